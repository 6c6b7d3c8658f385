//! SMD4 replies the document leaves open: SYS:FLAGS declares no return and only its example shows
//! a trailing `1`; a drive that leaves the item out is answered, not called line noise, so
//! `wait_standby` works on it (the simulator's `--flags-without-item`).

use crate::smd4::{Drive, Via, assert_exit, lines};
use crate::util::tempdir;

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
