//! `exit()` in a script: with a value other than 0 it fails the script (exit 1, the value shown,
//! no `catch` stopping it) and the motor the script started is stopped; `exit()` and `exit(0)`
//! end it as its last line would.

use super::script;
use crate::sim::Sim;
use crate::util::{code, run, stderr, stdout};

#[test]
fn exit_with_a_value_fails_the_script_and_stops_its_motor() {
    for (value, shown) in [
        ("7", "exit(7)"),
        ("-1", "exit(-1)"),
        ("\"homing failed\"", "exit(\"homing failed\")"),
        ("true", "exit(true)"),
    ] {
        let mut sim = Sim::start(&["--pty", "--manual-clock"]);
        let source = format!(
            "ror(0, 100000);\ntry {{ exit({value}); }} catch {{ print(\"caught\"); }}\nprint(\"after\");\n"
        );
        let path = script("exit.rhai", &source);
        let out = run(&["run", &path, "--port", &sim.first]);
        let err = stderr(&out);
        assert_eq!(code(&out), 1, "{value}: {err}");
        assert!(
            err.contains(&format!(
                "exit.rhai:2:7: the script called {shown}: it fails"
            )),
            "{value}: {err}"
        );
        assert!(
            err.contains("stopped motor 0 of module 1 (A) with MST"),
            "{value}: {err}"
        );
        assert_eq!(stdout(&out), "", "nothing after exit runs");
        sim.console("advance 10s");
        assert!(sim.console("motor").contains("velocity 0"), "{value}");
    }
}

#[test]
fn exit_and_exit_0_end_the_script_as_its_last_line_would() {
    for call in ["exit()", "exit(0)", "exit(())"] {
        let path = script(
            "done.rhai",
            &format!("print(\"before\");\n{call};\nprint(\"after\");\n"),
        );
        let out = run(&["--sim", "run", &path]);
        assert_eq!(code(&out), 0, "{call}: {}", stderr(&out));
        assert_eq!(stdout(&out), "before\n", "{call}");
    }
}

#[test]
fn exit_inside_a_closure_a_built_in_function_runs_ends_the_script_too() {
    let path = script(
        "map.rhai",
        "[1, 2].map(|x| exit(x + 1));\nprint(\"after\");\n",
    );
    let out = run(&["--sim", "run", &path]);
    assert_eq!(code(&out), 1, "{}", stderr(&out));
    assert!(
        stderr(&out).contains("the script called exit(2): it fails"),
        "{}",
        stderr(&out)
    );
    let path = script("map0.rhai", "[1, 2].map(|x| exit(0));\nprint(\"after\");\n");
    let out = run(&["--sim", "run", &path]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert_eq!(stdout(&out), "");
}
