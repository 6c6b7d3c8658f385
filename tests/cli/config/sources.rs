//! Values from every source are checked alike before anything is opened: a bit rate of 0 or
//! nonsense from the command line, the environment, the project or the user file is exit 2 with
//! its source named; an empty environment variable counts as unset.

use super::{Place, shown};
use crate::util::{code, stderr, stdout};

/// Environment variables set for a run.
type Env<'a> = Vec<(&'a str, &'a str)>;

#[test]
fn a_bit_rate_of_0_or_nonsense_is_refused_from_every_source_before_anything_opens() {
    for bad in ["0", "-1", "7", "99999999999", "fast"] {
        let place = Place::new();
        let port = ["--port", "/nonexistent/ttyUSB9"];
        let given = format!("--baud={bad}");
        let cases: [(&str, Vec<&str>, Env); 2] = [
            ("command line", vec![&given, "-c", "GAP 4, 0"], vec![]),
            (
                "environment",
                vec!["-c", "GAP 4, 0"],
                vec![("TMCLSH_BAUD", bad)],
            ),
        ];
        for (source, mut args, env) in cases {
            args.extend(port);
            let out = place.run(&args, &env);
            let err = stderr(&out);
            assert_eq!(code(&out), 2, "{source} {bad}: {err}");
            assert!(
                err.contains("a bit rate is a whole number"),
                "{source} {bad}: {err}"
            );
            assert!(
                !err.contains("cannot open"),
                "{source} {bad}: opened: {err}"
            );
            if source == "environment" {
                assert!(err.contains("environment variable TMCLSH_BAUD"), "{err}");
            }
        }
        let value = if bad.parse::<i64>().is_ok() {
            bad.to_string()
        } else {
            format!("\"{bad}\"")
        };
        for (source, file) in [
            ("project", place.project_file(&format!("baud = {value}\n"))),
            ("user", place.user_file(&format!("baud = {value}\n"))),
        ] {
            let out = place.run(&["-c", "GAP 4, 0", "--port", "/nonexistent/ttyUSB9"], &[]);
            let err = stderr(&out);
            assert_eq!(code(&out), 2, "{source} {bad}: {err}");
            assert!(
                err.contains(&format!("{}:1", file.display())),
                "{source} {bad}: {err}"
            );
            assert!(
                !err.contains("cannot open"),
                "{source} {bad}: opened: {err}"
            );
            std::fs::remove_file(file).unwrap();
        }
    }
}

#[test]
fn an_empty_environment_variable_counts_as_unset_and_a_bad_one_is_named() {
    let place = Place::new();
    for (name, key) in [
        ("TMCLSH_PORT", "port"),
        ("TMCLSH_BAUD", "baud"),
        ("TMCLSH_PROTOCOL", "protocol"),
        ("TMCLSH_PROFILE", "profile"),
        ("TMCLSH_MODULE", "module"),
        ("TMCLSH_TIMEOUT", "timeout"),
    ] {
        let out = place.run(&["config"], &[(name, "")]);
        assert_eq!(code(&out), 0, "{name}: {}", stderr(&out));
        let line = shown(&stdout(&out), key).to_string();
        assert!(
            line.contains("built-in") || line.contains("is not set"),
            "{name}: {line}"
        );
        let out = place.run(&["--sim", "-c", "GAP 4, 0"], &[(name, "")]);
        assert_eq!(code(&out), 0, "{name}: {}", stderr(&out));
    }
    for (name, value) in [
        ("TMCLSH_TIMEOUT", "soon"),
        ("TMCLSH_MODULE", "0"),
        ("TMCLSH_PROTOCOL", "modbus"),
        ("TMCLSH_LOCAL_ECHO", "maybe"),
    ] {
        let out = place.run(&["--sim", "-c", "GAP 4, 0"], &[(name, value)]);
        let err = stderr(&out);
        assert_eq!(code(&out), 2, "{name}: {err}");
        assert!(
            err.contains(&format!("environment variable {name}")),
            "{err}"
        );
    }
}

#[test]
fn a_port_or_profile_refused_later_still_names_where_it_came_from() {
    let place = Place::new();
    let out = place.run(&["-c", "GAP 4, 0"], &[("TMCLSH_PORT", "usb:zz")]);
    assert_eq!(code(&out), 2, "{}", stderr(&out));
    assert!(
        stderr(&out).contains("environment variable TMCLSH_PORT: `usb:zz`"),
        "{}",
        stderr(&out)
    );
    let out = place.run(
        &["--sim", "-c", "GAP 4, 0"],
        &[("TMCLSH_PROFILE", "nosuch")],
    );
    assert_eq!(code(&out), 2, "{}", stderr(&out));
    assert!(
        stderr(&out).contains("environment TMCLSH_PROFILE: no built-in profile or file 'nosuch'"),
        "{}",
        stderr(&out)
    );
    let file = place.project_file("profile = \"nosuch\"\n");
    let out = place.run(&["--sim", "-c", "GAP 4, 0"], &[]);
    assert_eq!(code(&out), 2, "{}", stderr(&out));
    assert!(
        stderr(&out).contains(&format!(
            "project {}:1: no built-in profile",
            file.display()
        )),
        "{}",
        stderr(&out)
    );
    // From the command line, the option itself is the origin.
    let out = place.run(&["--sim", "--profile", "nosuch", "-c", "GAP 4, 0"], &[]);
    assert!(
        stderr(&out).contains("tmclsh: no built-in profile"),
        "{}",
        stderr(&out)
    );
}
