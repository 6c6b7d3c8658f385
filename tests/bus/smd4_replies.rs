//! SMD4 replies the document leaves open: SYS:FLAGS declares no return and only its example shows
//! a trailing `1`; a drive that leaves the item out is answered, not called line noise, so
//! `wait_standby` works on it (the simulator's `--flags-without-item`). A user/real pair may lie
//! apart only as far as a drive's resolution: the simulator's grid stays within that.

use crate::smd4::{Drive, Via, assert_exit, lines};
use crate::util::{code, run, stderr, tempdir};

#[test]
fn sys_flags_with_or_without_the_example_s_item_is_the_answer_and_wait_standby_works() {
    let dir = tempdir();
    let script = dir.join("standby.rhai");
    std::fs::write(
        &script,
        "send(\"MOTOR:RUNV,+\");\nsend(\"MOTOR:STOP\");\nwait_standby(10000);\nprint(\"standing by\");\n",
    )
    .unwrap();
    for sim in [&[][..], &["--flags-without-item"][..]] {
        let drive = Drive::start(Via::Pty, sim);
        let out = drive.run(&["-c", "SYS:FLAGS"]);
        assert_exit(&out, 0);
        let shown = lines(&out);
        let expected_items = if sim.is_empty() { 3 } else { 2 };
        assert_eq!(
            shown[0].split(',').count(),
            expected_items,
            "{sim:?}: {shown:?}"
        );
        let out = drive.script(&script, &[]);
        assert_exit(&out, 0);
        assert_eq!(lines(&out), ["standing by"], "{sim:?}");
    }
}

#[test]
fn a_real_value_grid_coarser_than_the_reply_check_admits_is_refused() {
    let out = run(&["sim", "--protocol", "smd4", "--real-value-grid", "5"]);
    assert_eq!(code(&out), 2, "{}", stderr(&out));
    assert!(stderr(&out).contains("at most 1"), "{}", stderr(&out));
}

#[test]
fn real_values_on_the_coarsest_grid_pass_the_reply_check() {
    let drive = Drive::start(Via::Pty, &["--real-value-grid", "1"]);
    let out = drive.run(&["-c", "MOTOR:VSTART,1.5", "-c", "MOTOR:VSTART"]);
    assert_exit(&out, 0);
    assert_eq!(lines(&out)[1], "0x0888,0x0000,1.5000E+00,2.0000E+00");
}
