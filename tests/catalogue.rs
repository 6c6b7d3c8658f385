//! The built-in module profiles through the real binary: `tmclsh profiles`, `--profile NAME`
//! (names, aliases, module numbers, files, refusals), `params` of each, the generic profile, and
//! the validation each profile drives — motors, I/O ports and banks, the ASCII allow-list,
//! conditional ranges — with the built-in simulator and with `tmclsh sim` over a pty.

use std::collections::BTreeSet;

use crate::sim::Sim;
use crate::util::{code, repo, run, stderr, stdout, tempdir};

/// The built-in names: the stems of `data/profiles/*.toml`.
fn names() -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(repo().join("data/profiles"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .map(|p| p.file_stem().unwrap().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

/// `args`, which must succeed; its stdout.
fn ok(args: &[&str]) -> String {
    let out = run(args);
    assert_eq!(code(&out), 0, "{args:?}: {}", stderr(&out));
    stdout(&out)
}

/// `args`, which must be refused before anything is sent; its stderr.
fn refused(args: &[&str]) -> String {
    let out = run(args);
    assert_eq!(code(&out), 2, "{args:?}: {}{}", stdout(&out), stderr(&out));
    assert!(
        stdout(&out).is_empty(),
        "{args:?}: nothing sent: {}",
        stdout(&out)
    );
    stderr(&out)
}

#[test]
fn profiles_lists_every_built_in_module_with_its_sources() {
    let out = ok(&["profiles"]);
    let (table, sources) = out.split_once("\n\n").expect("a table, then the sources");
    let mut rows = table.lines();
    let header: Vec<&str> = rows.next().unwrap().split_whitespace().collect();
    assert_eq!(
        header,
        [
            "profile",
            "module",
            "aliases",
            "number",
            "axes",
            "ascii",
            "generation",
            "parameters"
        ]
    );
    let mut listed = BTreeSet::new();
    for row in rows {
        let cells: Vec<&str> = row.split_whitespace().collect();
        listed.insert(cells[0].to_string());
        if cells[0] == "generic" {
            assert!(row.contains("by number only"), "{row}");
            continue;
        }
        let text = std::fs::read_to_string(repo().join(format!("data/profiles/{}.toml", cells[0])))
            .unwrap();
        let file: toml::Table = text.parse().unwrap();
        let meta = file["meta"].as_table().unwrap();
        assert_eq!(cells[1], meta["module"].as_str().unwrap(), "{row}");
        assert_eq!(
            cells[3],
            meta["module_number"].as_integer().unwrap().to_string()
        );
        assert_eq!(cells[4], meta["axes"].as_integer().unwrap().to_string());
        assert_eq!(cells[5], meta["ascii_interface"].as_str().unwrap(), "{row}");
    }
    let mut expected: BTreeSet<String> = names().into_iter().collect();
    expected.insert("generic".into());
    assert_eq!(listed, expected);
    for name in names() {
        let line = sources
            .lines()
            .find(|l| l.starts_with(&format!("{name} ")))
            .unwrap_or_else(|| panic!("sources of {name}: {sources}"));
        assert!(
            line.contains("Manual") && line.ends_with(" documents"),
            "{line}"
        );
    }
}

#[test]
fn profiles_shows_one_in_full_by_name_alias_or_file() {
    let by_alias = ok(&["profiles", "pd-1141"]);
    assert!(by_alias.starts_with("tmcm-1141: TMCM-1141 (built in, data/profiles/tmcm-1141.toml)"));
    for needle in [
        "aliases         PD-1141",
        "module number   1141 (136 answers NNNNVabc; the boot loader NNNNBabc)",
        "commands absent 29 SAC (",
        "commands added  25 EI, 26 DI, 37 VECT, 38 RETI",
        "I/O (bank/port) 0/0 IN0",
        "documents",
        "    tmcm1141:p20: TMCM-1141 TMCL Firmware V1.19 manual p20",
    ] {
        assert!(by_alias.contains(needle), "{needle} in\n{by_alias}");
    }
    let file = repo().join("data/profiles/tmcm-1141.toml");
    let by_file = ok(&["profiles", file.to_str().unwrap()]);
    assert_eq!(
        by_file.lines().skip(1).collect::<Vec<_>>(),
        by_alias.lines().skip(1).collect::<Vec<_>>()
    );
    assert!(ok(&["profiles", "6214"]).contains("ASCII interface no"));
    assert!(ok(&["profiles", "generic"]).contains("I/O (bank/port) none: no port map"));
    let said = refused(&["profiles", "tmcm-611"]);
    assert!(said.contains("did you mean tmcm-6110?"), "{said}");
    let said = refused(&["--profile", "tmcm-6110", "profiles"]);
    assert!(
        said.contains("does not apply to `tmclsh profiles`"),
        "{said}"
    );
    let said = refused(&["profiles", "--profile", "tmcm-6110"]);
    assert!(said.contains("'--profile'"), "{said}");
}

#[test]
fn params_of_each_built_in_profile_by_name_are_those_of_its_file() {
    for name in names() {
        let file = repo().join(format!("data/profiles/{name}.toml"));
        let by_file = ok(&["params", "--profile", file.to_str().unwrap()]);
        let by_name = ok(&["params", "--profile", &name]);
        assert_eq!(by_name, by_file, "{name}");
        // A filter: the identifier of the first row.
        let ident = by_name
            .lines()
            .nth(1)
            .unwrap()
            .split_whitespace()
            .nth(2)
            .unwrap();
        let filtered = ok(&["params", "--profile", &name, ident]);
        assert!(filtered.lines().count() >= 2, "{name} {ident}");
        assert!(
            filtered.lines().skip(1).all(|l| l.contains(ident)),
            "{name} {ident}: {filtered}"
        );
    }
    // Before the subcommand, from the environment, by number.
    let six = ok(&["--profile", "tmcm-6110", "params", "max_current"]);
    assert_eq!(six, ok(&["params", "--profile", "6110", "max_current"]));
    let out = std::process::Command::new(crate::util::bin())
        .args(["params", "max_current"])
        .env("TMCLSH_PROFILE", "TMCM-6110")
        .output()
        .unwrap();
    assert_eq!(stdout(&out), six);
    // The generic profile has none to print.
    let out = run(&["params", "--profile", "generic"]);
    assert_eq!(code(&out), 1);
    assert!(stderr(&out).contains("by number only"), "{}", stderr(&out));
}

#[test]
fn an_unknown_profile_name_is_refused_with_the_nearest() {
    let said = refused(&["--sim", "--profile", "pd-1114", "-c", "GAP 1, 0"]);
    assert!(
        said.contains("no built-in profile or file 'pd-1114'"),
        "{said}"
    );
    assert!(said.contains("did you mean pd-1141?"), "{said}");
    let said = refused(&["--profile", "profiles/nothing.toml", "params"]);
    assert!(
        said.contains("cannot read profile profiles/nothing.toml"),
        "{said}"
    );
}

#[test]
fn an_alias_drives_its_module() {
    let out = run(&["--sim", "--profile", "pd-1141", "-c", "GAP 1, 0"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert_eq!(stdout(&out), "BA 100 0\n");
    assert!(
        stderr(&out).contains("simulated TMCM-1141"),
        "{}",
        stderr(&out)
    );
}

#[test]
fn motor_numbers_are_the_modules_own() {
    ok(&["--sim", "--profile", "tmcm-6110", "-c", "GAP 4, 5"]);
    let said = refused(&["--sim", "--profile", "tmcm-6110", "-c", "GAP 4, 6"]);
    assert!(
        said.contains("motor 6 does not exist: the TMCM-6110 has 6 motors (0..5)"),
        "{said}"
    );
    ok(&["--sim", "--profile", "tmcm-3110", "-c", "ROR 2, 0"]);
    let said = refused(&["--sim", "--profile", "tmcm-1141", "-c", "MVP ABS, 1, 100"]);
    assert!(said.contains("the TMCM-1141 has one motor"), "{said}");
}

#[test]
fn io_ports_and_banks_come_from_the_profile() {
    ok(&[
        "--sim",
        "--profile",
        "tmcm-6110",
        "-c",
        "SIO 7, 2, 1",
        "-c",
        "GIO 8, 1",
    ]);
    let said = refused(&["--sim", "--profile", "tmcm-6110", "-c", "SIO 8, 2, 1"]);
    assert!(
        said.contains("the TMCM-6110 has no I/O port 8 in bank 2; it has bank 2 ports 0..7"),
        "{said}"
    );
    let said = refused(&["--sim", "-c", "SIO 3, 0, 1"]);
    assert!(said.contains("port 3 of bank 0 is IN3, an input"), "{said}");
    let said = refused(&["--sim", "-c", "GIO 0, 0"]);
    assert!(said.contains("bank 0 ports 3..8"), "{said}");
    // STGP and RSGP store user variables (bank 2) only; bank-0 settings are SGP's.
    ok(&[
        "--sim",
        "-c",
        "SGP 0, 2, 7",
        "-c",
        "STGP 0, 2",
        "-c",
        "RSGP 0, 2",
    ]);
    let said = refused(&["--sim", "-c", "STGP 67, 0"]);
    assert!(
        said.contains("STGP accepts bank 2 only on the TMCM-142, not bank 0"),
        "{said}"
    );
}

#[test]
fn the_ascii_allow_list_is_the_modules() {
    let said = refused(&["--sim", "--profile", "tmcm-1140", "-c", "SAC 0, 0, 0"]);
    assert!(
        said.contains("SAC (29) is not a command of the TMCM-1140"),
        "{said}"
    );
    let said = refused(&["--sim", "--profile", "tmcm-1140", "-c", "CALC ADD, 1"]);
    assert!(
        said.contains("the TMCM-1140's ASCII command list lacks it") && said.contains(":bin"),
        "{said}"
    );
    ok(&[
        "--sim",
        "--profile",
        "tmcm-1140",
        "-c",
        ":bin",
        "-c",
        "CALC ADD, 1",
    ]);
    // A profile file's own list: SIO left out is refused in ASCII mode, sent in binary.
    let dir = tempdir();
    let file = dir.join("no-sio.toml");
    std::fs::write(
        &file,
        "[meta]\nmodule = \"TMCM-9\"\n[ascii]\nallowed_commands = [\"GAP\", \"SAP\", \"GGP\"]\n\
         [simulation]\noutputs = [0]\n",
    )
    .unwrap();
    let file = file.to_str().unwrap();
    let said = refused(&["--sim", "--profile", file, "-c", "SIO 0, 2, 1"]);
    assert!(
        said.contains("the TMCM-9's ASCII command list lacks it"),
        "{said}"
    );
    ok(&[
        "--sim",
        "--profile",
        file,
        "-c",
        ":bin",
        "-c",
        "SIO 0, 2, 1",
    ]);
}

#[test]
fn a_conditional_range_sends_with_a_notice() {
    let out = run(&["--sim", "-c", "SAP max_positioning_speed, 0, 40000000"]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert_eq!(stdout(&out), "BA 100 40000000\n");
    assert!(
        stderr(&out)
            .contains("40000000 is outside 0..31999999 usteps/s when axis parameter 255 = 1"),
        "{}",
        stderr(&out)
    );
    let out = run(&["--sim", "-c", "SAP max_positioning_speed, 0, 4000"]);
    assert!(!stderr(&out).contains("outside"), "{}", stderr(&out));
    refused(&["--sim", "-c", "ROR 0, -1"]);
}

#[test]
fn the_generic_profile_checks_commands_and_sends_parameter_numbers() {
    let out = run(&[
        "--sim",
        "--profile",
        "generic",
        "-c",
        "GAP 4, 0",
        "-c",
        "SAP 200, 0, 5",
        "-c",
        "GAP 4, 0",
    ]);
    // Both parameter numbers go out; the simulated TMCM-142 has no parameter 200, and the run
    // stops at its error.
    assert_eq!(code(&out), 1, "{}", stderr(&out));
    assert_eq!(stdout(&out), "BA 100 1000000\nBA 3 5\n");
    let said = stderr(&out);
    assert_eq!(
        said.matches("generic TMCL profile: commands and motors 0..5 are checked")
            .count(),
        1,
        "one notice: {said}"
    );
    assert!(
        said.contains("refused 'ASAP 200, 0, 5': status 3"),
        "{said}"
    );
    let said = refused(&[
        "--sim",
        "--profile",
        "generic",
        "-c",
        "GAP max_positioning_speed, 0",
    ]);
    assert!(
        said.contains("the generic TMCL module profile has no parameter names"),
        "{said}"
    );
    let said = refused(&["--sim", "--profile", "generic", "-c", "GAP 4, 6"]);
    assert!(said.contains("motor 6 does not exist"), "{said}");
}

#[test]
fn a_served_module_of_a_profile_is_that_module() {
    let sim = Sim::start(&["--pty", "--profile", "tmcm-6110"]);
    let out = run(&[
        "--profile",
        "tmcm-6110",
        "--port",
        &sim.first,
        "-c",
        ":bin",
        "-c",
        "136",
    ]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert_eq!(
        stdout(&out).lines().last(),
        Some("6110V131"),
        "{}",
        stdout(&out)
    );
    let out = run(&[
        "--profile",
        "tmcm-6110",
        "--port",
        &sim.first,
        "-c",
        "GAP 4, 5",
    ]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    sim.quit();
}

#[test]
fn a_binary_only_module_is_talked_to_in_binary_frames() {
    let sim = Sim::start(&["--pty", "--profile", "tmcm-1260"]);
    let dir = tempdir();
    let log = dir.join("session.log");
    let out = run(&[
        "--profile",
        "tmcm-1260",
        "--port",
        &sim.first,
        "--log",
        log.to_str().unwrap(),
        "-c",
        "SAP 4, 0, 1234",
        "-c",
        "GAP 4, 0",
    ]);
    assert_eq!(code(&out), 0, "{}", stderr(&out));
    assert_eq!(stdout(&out).lines().last(), Some("BA 100 1234"));
    let transcript = std::fs::read_to_string(&log).unwrap();
    assert!(
        transcript.contains("binary direct mode: the TMCM-1260 has no ASCII interface"),
        "{transcript}"
    );
    assert!(
        !transcript.contains("(139)"),
        "139 was not sent: {transcript}"
    );
    let said = refused(&[
        "--profile",
        "tmcm-1260",
        "--port",
        &sim.first,
        "-c",
        ":ascii",
    ]);
    assert!(said.contains("has no ASCII interface"), "{said}");
    sim.quit();
}

#[test]
fn help_on_ascii_mode_names_the_modules_own_list() {
    let help = |profile: &str| ok(&["--sim", "--profile", profile, "-c", ":help ascii"]);
    let own = help("tmcm-142");
    assert!(
        own.contains("The TMCM-142 takes only ROR ROL") && own.contains(" SAC "),
        "{own}"
    );
    let family = help("tmcm-1140");
    assert!(
        family.contains("The TMCM-1140 takes only") && !family.contains("SAC"),
        "{family}"
    );
    assert!(help("tmcm-6214").contains("The TMCM-6214 has no ASCII interface."));
}
