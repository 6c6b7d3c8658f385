//! `--profile` files checked at the door: each class of bad row refused with its line (exit 2,
//! nothing sent), and a good custom profile served by the built-in simulator.

use crate::util::{code, run, stderr, stdout, tempdir};

/// A valid profile of two axis parameters (lines 1-13); `extra` follows from line 14.
fn profile(extra: &str) -> String {
    format!(
        "[meta]\n\
         module = \"TMCM-9\"\n\
         axes = 2\n\
         [[axis_parameter]]\n\
         number = 4\n\
         name = \"Max speed\"\n\
         ident = \"max_speed\"\n\
         access = \"RWE\"\n\
         range = [0, 100]\n\
         default = 10\n\
         [[axis_parameter]]\n\
         number = 1\n\
         name = \"Position\"\n\
         ident = \"position\"\n\
         access = \"RW\"\n\
         {extra}"
    )
}

fn write(text: &str) -> std::path::PathBuf {
    let path = tempdir().join("profile.toml");
    std::fs::write(&path, text).unwrap();
    path
}

#[test]
fn each_bad_profile_class_is_refused_with_its_line() {
    let row = |body: &str| profile(&format!("[[axis_parameter]]\n{body}"));
    let cases = [
        (
            "reversed range",
            row("number = 6\nname = \"a\"\nident = \"a\"\nrange = [100, 0]\n"),
            "line 20: range [100, 0] is reversed",
        ),
        (
            "zero axes",
            profile("").replace("axes = 2", "axes = 0"),
            "line 3: axes must be at least 1",
        ),
        (
            "unknown access letter",
            row("number = 6\nname = \"a\"\nident = \"a\"\naccess = \"RWX\"\n"),
            "line 20: access \"RWX\" has the unknown letter 'X'",
        ),
        (
            "empty identifier",
            row("number = 6\nname = \"a\"\nident = \"\"\n"),
            "line 19: ident must not be empty",
        ),
        (
            "spaced identifier",
            row("number = 6\nname = \"a\"\nident = \"max accel\"\n"),
            "line 19: ident \"max accel\" must be letters, digits and _ (no spaces)",
        ),
        (
            "duplicate identifier",
            row("number = 6\nname = \"a\"\nident = \"max_speed\"\n"),
            "line 19: axis parameter identifier 'max_speed' is defined twice (first on line 7)",
        ),
        (
            "duplicate number",
            row("number = 4\nname = \"a\"\nident = \"a\"\n"),
            "line 17: axis parameter 4 is defined twice (first on line 5)",
        ),
        (
            "default outside its range",
            profile("").replace("default = 10", "default = 101"),
            "line 10: default 101 lies outside the range 0..100",
        ),
        (
            "not the schema",
            profile("").replace("axes = 2", "axes = \"two\""),
            "line 3: invalid type: string \"two\", expected u8",
        ),
    ];
    for (class, text, expected) in cases {
        let path = write(&text);
        let path = path.to_str().unwrap();
        let out = run(&["--sim", "--profile", path, "-c", "GAP 4, 0"]);
        assert_eq!(code(&out), 2, "{class}: {}", stderr(&out));
        assert!(stdout(&out).is_empty(), "{class}: nothing is sent");
        assert!(
            stderr(&out).contains(&format!("tmclsh: profile {path} refused")),
            "{class}: {}",
            stderr(&out)
        );
        assert!(
            stderr(&out).contains(&format!("\n  {expected}")),
            "{class}: {}",
            stderr(&out)
        );
        // Every subcommand loads the profile the same way.
        let out = run(&["--profile", path, "params"]);
        assert_eq!(code(&out), 2, "{class}: params");
    }
}

#[test]
fn every_problem_of_a_file_is_listed() {
    let text = profile("[[axis_parameter]]\nnumber = 300\nname = \"\"\nident = \"9lives\"\n")
        .replace("axes = 2", "axes = 0");
    let path = write(&text);
    let out = run(&["--profile", path.to_str().unwrap(), "params"]);
    assert_eq!(code(&out), 2);
    let lines: Vec<String> = stderr(&out)
        .lines()
        .skip(1)
        .map(|l| l.trim().split(':').next().unwrap().to_string())
        .collect();
    assert_eq!(
        lines,
        ["line 3", "line 17", "line 18", "line 19"],
        "{}",
        stderr(&out)
    );
}

#[test]
fn the_built_in_simulator_serves_a_custom_profile() {
    let path = write(&profile(""));
    let path = path.to_str().unwrap();
    let out = run(&[
        "--sim",
        "--profile",
        path,
        "-c",
        "GAP max_speed, 0",
        "-c",
        "SAP max_speed, 0, 55",
        "-c",
        "GAP max_speed, 0",
        "-c",
        "STAP max_speed, 0",
    ]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert_eq!(
        stdout(&out).lines().collect::<Vec<_>>(),
        ["BA 100 10", "BA 100 55", "BA 100 55", "BA 100 0"],
        "the power-up value is the profile's default"
    );
    // The profile's table is the one checked: its range, its parameters.
    let out = run(&["--sim", "--profile", path, "-c", "SAP max_speed, 0, 101"]);
    assert_eq!(code(&out), 2);
    assert!(stderr(&out).contains("allowed 0..100"), "{}", stderr(&out));
    let out = run(&["--sim", "--profile", path, "-c", "GAP max_current, 0"]);
    assert_eq!(code(&out), 2, "{}", stderr(&out));
    // And the same from a script.
    let script = tempdir().join("p.rhai");
    std::fs::write(&script, "assert_eq(gap(\"max_speed\", 0), 10);\n").unwrap();
    let out = run(&["--sim", "--profile", path, "run", script.to_str().unwrap()]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
}
