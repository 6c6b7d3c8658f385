//! Machine-readable output: each `--json` document parsed as JSON with the field names
//! docs/machine-output.md promises, against the built-in simulator (`--sim`).

use std::path::Path;
use std::process::{Command, Output, Stdio};

use serde_json::Value;

use crate::util::{bin, code, run, stderr, stdout, tempdir};

/// The one JSON document on stdout: a single line that parses.
fn document(out: &Output) -> Value {
    let text = stdout(out);
    assert_eq!(text.lines().count(), 1, "one line: {text}");
    assert!(text.is_ascii(), "ASCII only: {text}");
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("{e}: {text}"))
}

/// Runs `tmclsh ARGS` in `dir` with `env`, stdin empty.
fn run_in(dir: &Path, args: &[&str], env: &[(&str, &str)]) -> Output {
    Command::new(bin())
        .args(args)
        .current_dir(dir)
        .envs(env.iter().copied())
        .stdin(Stdio::null())
        .output()
        .expect("tmclsh runs")
}

#[test]
fn params_json_lists_each_parameter_with_its_fields() {
    let out = run(&["params", "--json", "max"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let doc = document(&out);
    assert_eq!(doc["protocol"], "tmcl");
    let params = doc["parameters"].as_array().unwrap();
    let names: Vec<&str> = params.iter().map(|p| p["name"].as_str().unwrap()).collect();
    assert!(names.contains(&"max_current"), "{names:?}");
    let current = params.iter().find(|p| p["name"] == "max_current").unwrap();
    assert_eq!(current["kind"], "axis");
    assert_eq!(current["number"], 6);
    assert_eq!(current["access"], "RWE");
    assert!(current["range"].is_array(), "{current}");
    for key in ["bank", "manual_name", "unit", "uncertain", "description"] {
        assert!(current.get(key).is_some(), "{key} in {current}");
    }
    // Nothing matches: no document, the reason on stderr, exit 1 as without --json.
    let out = run(&["params", "--json", "no_such_thing"]);
    assert_eq!(code(&out), 1);
    assert!(stdout(&out).is_empty());
    assert!(stderr(&out).contains("no TMCM-142 parameter matches"));
    let out = run(&["--protocol", "smd4", "params", "--json", "MOTOR:VMAX"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let doc = document(&out);
    assert_eq!(doc["protocol"], "smd4");
    let vmax = &doc["parameters"][0];
    assert_eq!(vmax["mnemonic"], "MOTOR:VMAX");
    assert_eq!(vmax["readable"], true);
    assert_eq!(vmax["unit"], "Hz");
}

#[test]
fn profiles_json_lists_the_catalogue_and_shows_one_in_full() {
    let out = run(&["profiles", "--json"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let doc = document(&out);
    let profiles = doc["profiles"].as_array().unwrap();
    let p6110 = profiles.iter().find(|p| p["name"] == "tmcm-6110").unwrap();
    assert_eq!(p6110["module"], "TMCM-6110");
    assert_eq!(p6110["module_number"], 6110);
    assert_eq!(p6110["axes"], 6);
    assert!(profiles.iter().any(|p| p["generic"] == true));
    let out = run(&["profiles", "6110", "--json"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let one = &document(&out)["profile"];
    assert_eq!(one["name"], "tmcm-6110");
    assert!(!one["parameters"].as_array().unwrap().is_empty());
    assert!(one["io_ports"].is_array() && one["documents"].is_array());
}

#[test]
fn scan_json_names_each_module_and_is_printed_when_nothing_answers() {
    let out = run(&["scan", "--sim", "--json"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let doc = document(&out);
    assert_eq!(doc["protocol"], "tmcl");
    assert_eq!(doc["found"], 1);
    let module = &doc["modules"][0];
    assert_eq!(module["address"], 1);
    assert_eq!(module["char"], "A");
    assert_eq!(module["module"], "TMCM-142");
    assert_eq!(module["boot_loader"], false);
    assert!(module["firmware"].as_str().unwrap().starts_with("142V"));
    // Nobody at 5: the document says so, and the exit code is still 3.
    let out = run(&["scan", "--sim", "--json", "--addresses", "5"]);
    assert_eq!(code(&out), 3);
    let doc = document(&out);
    assert_eq!(doc["found"], 0);
    assert_eq!(doc["modules"], serde_json::json!([]));
    let out = run(&[
        "--protocol",
        "smd4",
        "scan",
        "--sim",
        "--json",
        "--addresses",
        "1-2",
    ]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let doc = document(&out);
    assert_eq!(doc["protocol"], "smd4");
    assert_eq!(doc["modules"][0]["address"], 1);
    assert!(doc["modules"][0]["serial"].is_string());
}

#[test]
fn snapshot_diff_json_shows_both_sides_and_exits_1_when_they_differ() {
    let dir = tempdir();
    let out = run_in(&dir, &["snapshot", "save", "--sim", "a.toml"], &[]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let text = std::fs::read_to_string(dir.join("a.toml")).unwrap();
    let changed: String = text
        .lines()
        .map(|l| {
            if l.starts_with("max_current = {") {
                let (head, rest) = l.split_once("value = ").unwrap();
                let (_, tail) = rest.split_once(',').unwrap();
                format!("{head}value = 3,{tail}\n")
            } else {
                format!("{l}\n")
            }
        })
        .collect();
    assert_ne!(changed, text, "max_current changed");
    std::fs::write(dir.join("b.toml"), changed).unwrap();
    let out = run_in(
        &dir,
        &["snapshot", "diff", "a.toml", "b.toml", "--json"],
        &[],
    );
    assert_eq!(code(&out), 1, "{}", stderr(&out));
    let doc = document(&out);
    assert_eq!(doc["left"], "a.toml");
    assert_eq!(doc["right"], "b.toml");
    assert_eq!(doc["differ"], 1);
    assert!(doc["compared"].as_u64().unwrap() > 1);
    let d = &doc["differences"][0];
    assert_eq!(d["name"], "max_current");
    assert_eq!(d["section"], "axis.0");
    assert_eq!(d["left"]["state"], "value");
    assert_eq!(d["right"]["value"], 3);
    // Against the module: the right side is the module.
    let out = run_in(
        &dir,
        &["snapshot", "diff", "a.toml", "--sim", "--json"],
        &[],
    );
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let doc = document(&out);
    assert_eq!(doc["differ"], 0);
    assert_eq!(doc["right"], "module 1 (A)");
}

#[test]
fn config_json_gives_each_setting_its_value_and_origin() {
    let dir = tempdir();
    let home = dir.join("home");
    std::fs::create_dir_all(&home).unwrap();
    let out = run_in(
        &dir,
        &["config", "--json", "--port", "/dev/ttyUSB9"],
        &[
            ("TMCLSH_BAUD", "19200"),
            ("HOME", home.to_str().unwrap()),
            ("XDG_CONFIG_HOME", home.to_str().unwrap()),
        ],
    );
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let doc = document(&out);
    let setting = |key: &str| {
        doc["settings"]
            .as_array()
            .unwrap()
            .iter()
            .find(|s| s["key"] == key)
            .unwrap_or_else(|| panic!("{key} in {doc}"))
            .clone()
    };
    assert_eq!(setting("port")["value"], "/dev/ttyUSB9");
    assert_eq!(setting("port")["origin"], "command line");
    assert_eq!(setting("baud")["value"], 19200);
    assert!(
        setting("baud")["origin"]
            .as_str()
            .unwrap()
            .contains("TMCLSH_BAUD")
    );
    assert!(setting("log_dir")["value"].is_null());
    assert!(setting("log_dir")["unset"].is_string());
    assert!(doc["project_file"].is_null());
}

#[cfg(target_os = "linux")]
#[test]
fn ports_json_describes_a_usb_adapter() {
    use std::os::unix::fs::symlink;
    let root = tempdir();
    for dir in ["sys/class/tty", "sys/bus/usb", "sys/bus/usb-serial", "dev"] {
        std::fs::create_dir_all(root.join(dir)).unwrap();
    }
    let usb = root.join("sys/devices/usb1/ttyUSB0");
    let interface = usb.join("1-0:1.0");
    let port = interface.join("ttyUSB0");
    std::fs::create_dir_all(&port).unwrap();
    for (file, text) in [
        ("idVendor", "0403"),
        ("idProduct", "6001"),
        ("serial", "A1\u{1b}[2J"),
        ("product", "FT232R USB UART"),
        ("manufacturer", "FTDI"),
    ] {
        std::fs::write(usb.join(file), format!("{text}\n")).unwrap();
    }
    symlink(root.join("sys/bus/usb"), interface.join("subsystem")).unwrap();
    symlink(root.join("sys/bus/usb-serial"), port.join("subsystem")).unwrap();
    let class = root.join("sys/class/tty/ttyUSB0");
    std::fs::create_dir_all(&class).unwrap();
    symlink(&port, class.join("device")).unwrap();
    std::fs::write(root.join("dev/ttyUSB0"), "").unwrap();
    let out = run_in(
        &root,
        &["ports", "--json"],
        &[("TMCLSH_TEST_SYSFS", root.to_str().unwrap())],
    );
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let doc = document(&out);
    let port = &doc["ports"][0];
    assert!(
        port["path"].as_str().unwrap().ends_with("dev/ttyUSB0"),
        "{doc}"
    );
    assert_eq!(port["type"], "usb");
    assert_eq!(port["vid"], "0403");
    assert_eq!(port["pid"], "6001");
    // The escape sequence in the serial number comes back exactly, escaped on the wire.
    assert_eq!(port["serial"], "A1\u{1b}[2J");
    assert!(stdout(&out).contains("\\u001b[2J"));
    assert_eq!(port["product"], "FT232R USB UART");
    assert!(
        port["usb_name"]
            .as_str()
            .unwrap()
            .starts_with("usb:0403:6001")
    );
    assert!(doc.get("probes").is_none());
}

/// The JUnit report at `path`, checked against the schema's required elements and attributes:
/// `testsuites` holding `testsuite` elements with name, tests, failures and errors that add up,
/// each `testcase` with name and classname. Returns (case name, failure or error element name,
/// its message) for each case.
fn junit_cases(path: &Path) -> Vec<(String, Option<(String, String)>)> {
    let text = std::fs::read_to_string(path).expect("the JUnit file is written");
    let doc = roxmltree::Document::parse(&text).unwrap_or_else(|e| panic!("{e}: {text}"));
    let root = doc.root_element();
    assert_eq!(root.tag_name().name(), "testsuites", "{text}");
    let number = |node: roxmltree::Node, attribute: &str| -> usize {
        node.attribute(attribute)
            .unwrap_or_else(|| panic!("{attribute} on {}", node.tag_name().name()))
            .parse()
            .unwrap()
    };
    let suites: Vec<_> = root.children().filter(|n| n.is_element()).collect();
    assert_eq!(suites.len(), 1, "{text}");
    let suite = suites[0];
    assert_eq!(suite.tag_name().name(), "testsuite");
    assert!(!suite.attribute("name").unwrap_or_default().is_empty());
    let mut cases = Vec::new();
    let (mut failures, mut errors) = (0, 0);
    for case in suite.children().filter(|n| n.is_element()) {
        assert_eq!(case.tag_name().name(), "testcase");
        let name = case.attribute("name").expect("testcase name").to_string();
        assert!(!case.attribute("classname").expect("classname").is_empty());
        let problem = case.children().find(|n| n.is_element()).map(|n| {
            let kind = n.tag_name().name().to_string();
            match kind.as_str() {
                "failure" => failures += 1,
                "error" => errors += 1,
                other => panic!("unexpected <{other}>"),
            }
            (kind, n.attribute("message").expect("message").to_string())
        });
        cases.push((name, problem));
    }
    for node in [root, suite] {
        assert_eq!(number(node, "tests"), cases.len(), "{text}");
        assert_eq!(number(node, "failures"), failures, "{text}");
        assert_eq!(number(node, "errors"), errors, "{text}");
    }
    cases
}

#[test]
fn run_junit_reports_each_block_and_runs_every_block_after_a_failure() {
    let dir = tempdir();
    std::fs::write(
        dir.join("check.rhai"),
        r#"test("moves", || {
    mvp_abs(0, 1000);
    wait_pos(0, 5000);
    assert_eq(gap(1, 0), 1000);
});
test("speed <& \"quoted\">", || {
    ror(0, 500);
    assert(gap(1, 0) == 42, "never 42");
});
test("stopped after the failure", || {
    assert_eq(gap(3, 0), 0, "the motor the failed block started was stopped");
});
test("a refused call", || {
    gap(1, 300);
});
"#,
    )
    .unwrap();
    let out = run_in(
        &dir,
        &["run", "check.rhai", "--sim", "--junit", "report.xml"],
        &[],
    );
    assert_eq!(code(&out), 1, "{}", stderr(&out));
    let err = stderr(&out);
    assert!(err.contains("4 tests failed"), "{err}");
    let cases = junit_cases(&dir.join("report.xml"));
    let names: Vec<&str> = cases.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(
        names,
        [
            "moves",
            "speed <& \"quoted\">",
            "stopped after the failure",
            "a refused call"
        ]
    );
    assert_eq!(cases[0].1, None);
    let (kind, message) = cases[1].1.clone().unwrap();
    assert_eq!(kind, "failure");
    assert!(
        message.starts_with("check.rhai:8:5: assertion failed: never 42"),
        "{message}"
    );
    assert_eq!(cases[2].1, None, "the next block ran, its motor stopped");
    let (kind, message) = cases[3].1.clone().unwrap();
    assert_eq!(kind, "error", "a refusal (exit 2) is an error");
    assert!(message.starts_with("check.rhai:14:5:"), "{message}");
}

#[test]
fn run_junit_is_written_when_the_script_passes_or_does_not_compile() {
    let dir = tempdir();
    std::fs::write(dir.join("plain.rhai"), "assert_eq(gap(1, 0), 0);\n").unwrap();
    let out = run_in(
        &dir,
        &["run", "plain.rhai", "--sim", "--junit", "a.xml"],
        &[],
    );
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert_eq!(
        junit_cases(&dir.join("a.xml")),
        [("plain".to_string(), None)]
    );
    std::fs::write(dir.join("broken.rhai"), "test(\"x\", || { let = 1 });\n").unwrap();
    let out = run_in(
        &dir,
        &["run", "broken.rhai", "--sim", "--junit", "b.xml"],
        &[],
    );
    assert_eq!(code(&out), 2, "{}", stderr(&out));
    let cases = junit_cases(&dir.join("b.xml"));
    let (kind, message) = cases[0].1.clone().unwrap();
    assert_eq!(kind, "error");
    assert!(message.contains("does not compile"), "{message}");
}

#[test]
fn script_functions_have_help_from_the_registry() {
    let out = run(&["--sim", "-c", ":help wait_pos"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    let text = stdout(&out);
    assert!(
        text.starts_with("wait_pos(motor, timeout_ms) — waits until"),
        "{text}"
    );
    let out = run(&["--sim", "--protocol", "smd4", "-c", ":help wait_standby"]);
    assert!(
        stdout(&out).starts_with("wait_standby(timeout_ms) — "),
        "{}",
        stdout(&out)
    );
    let out = run(&["run", "--help"]);
    assert_eq!(code(&out), 0);
    let help = stdout(&out);
    for signature in [
        "test(name, || { … })",
        "wait_pos(motor, timeout_ms)",
        "wait_standby(timeout_ms)",
        "snapshot_save(path) -> int",
    ] {
        assert!(help.contains(signature), "{signature} in {help}");
    }
}
