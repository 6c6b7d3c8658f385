//! STORE, SYS:LOAD and SYS:LOADFD with a real state file, across re-created simulators.

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU32, Ordering};

use super::Bench;
use crate::dialect::smd4::protocol::Eflags;
use crate::dialect::smd4::sim::Smd4SimOptions;

/// A fresh directory for one test's state file.
fn scratch(name: &str) -> PathBuf {
    static COUNTER: AtomicU32 = AtomicU32::new(0);
    let n = COUNTER.fetch_add(1, Ordering::SeqCst);
    let dir = std::env::temp_dir().join(format!("tmclsh-smd4-{}-{name}-{n}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn drive(state: &Path) -> Bench {
    Bench::with(Smd4SimOptions {
        state_file: Some(state.to_path_buf()),
        ..Smd4SimOptions::default()
    })
}

#[test]
fn store_survives_a_new_simulator_and_load_and_loadfd_work() {
    let dir = scratch("store");
    let state = dir.join("smd4.toml");
    let mut first = drive(&state);
    first.send("MOTOR:VMAX,2500");
    first.send("SYS:IDENT,1");
    first.send("MOTOR:PACT,77");
    assert!(first.reply("STORE").is_ok());
    // Written at once: the file is there before the simulator goes away.
    let text = std::fs::read_to_string(&state).unwrap();
    assert!(text.contains("\"MOTOR:VMAX\" = 2500"), "{text}");
    assert!(
        !text.contains("SYS:IDENT") && !text.contains("MOTOR:PACT"),
        "{text}"
    );
    drop(first);

    let mut second = drive(&state);
    assert_eq!(
        second.reply("MOTOR:VMAX").user_real(),
        Some((2500.0, 2500.0))
    );
    assert_eq!(second.data("SYS:IDENT"), ["0"], "volatile");
    assert_eq!(
        second.data("MOTOR:PACT"),
        ["0.00"],
        "state, not configuration"
    );
    second.send("MOTOR:VMAX,3000");
    second.send("SYS:LOAD");
    assert_eq!(
        second.reply("MOTOR:VMAX").user_real(),
        Some((2500.0, 2500.0))
    );
    second.send("SYS:LOADFD");
    assert_eq!(
        second.reply("MOTOR:VMAX").user_real(),
        Some((1000.0, 1000.0))
    );
    drop(second);

    let mut third = drive(&state);
    assert_eq!(
        third.reply("MOTOR:VMAX").user_real(),
        Some((2500.0, 2500.0)),
        "LOADFD changes only the working set"
    );
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn a_damaged_state_file_latches_the_configuration_error() {
    let dir = scratch("damaged");
    let state = dir.join("smd4.toml");
    std::fs::write(
        &state,
        "format = 1\n[stored]\n\"MOTOR:VMAX\" = 99999.0\n\"MOTOR:AMAX\" = 250.0\n",
    )
    .unwrap();
    let mut b = drive(&state);
    let reply = b.reply("MOTOR:VMAX");
    assert!(reply.eflags.is_set(Eflags::CONFIG_ERROR));
    assert_eq!(
        reply.user_real(),
        Some((1000.0, 1000.0)),
        "bad value replaced by the default"
    );
    assert_eq!(
        b.reply("MOTOR:AMAX").user_real(),
        Some((250.0, 250.0)),
        "good values kept"
    );
    assert_eq!(b.error("MOTOR:RUNV,+"), -7, "the motor is disabled");
    b.send("STORE");
    b.send("SYS:CLR");
    drop(b);
    let mut again = drive(&state);
    assert_eq!(again.reply("SYS:FW").eflags.0, 0, "repaired by STORE");
    std::fs::write(&state, "not toml [").unwrap();
    assert!(
        drive(&state)
            .reply("SYS:FW")
            .eflags
            .is_set(Eflags::CONFIG_ERROR)
    );
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn store_fails_with_minus_5_when_it_cannot_write() {
    let dir = scratch("fail");
    let mut b = drive(&dir.join("missing-dir").join("smd4.toml"));
    assert_eq!(b.error("STORE"), -5);
    let mut worn = Bench::new();
    worn.sim.set_flash_failure(true);
    assert_eq!(worn.error("STORE"), -5);
    worn.sim.set_flash_failure(false);
    assert!(worn.reply("STORE").is_ok());
    std::fs::remove_dir_all(dir).unwrap();
}
