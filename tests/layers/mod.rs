//! The layers of ARCHITECTURE.md's diagram are true of the code: every module of the library
//! uses only modules of lower layers, the dialect folders never use each other, and outside them
//! only the list of dialects and the subcommands of one dialect name one.

mod circles;
mod paths;

use std::collections::BTreeMap;

use crate::util::repo;

use paths::{Source, sources, used_paths};

/// Files outside the dialect folders that may name one: the list of dialects, the command line,
/// which dispatches to the subcommands in TMCL's `cli/` folder, and the fuzz targets' entry
/// points, one per parser of either dialect.
const NAMING_A_DIALECT: &[&str] = &["src/dialect/mod.rs", "src/cli/mod.rs", "src/fuzz_entry.rs"];

/// The layer a module path is in: its top module's, but a dialect's `cli/` folder (the
/// subcommands only it has) is in the `cli` layer.
fn layer_name(path: &[String]) -> &str {
    match path {
        [dialect, _, cli, ..] if dialect == "dialect" && cli == "cli" => "cli",
        [top, ..] => top,
        [] => "",
    }
}

/// The layers of the diagram, top first: the module names on each line of the fenced block that
/// follows the `<!-- layers -->` marker in ARCHITECTURE.md. Names on one line are peers.
fn layers() -> Vec<Vec<String>> {
    let text = std::fs::read_to_string(repo().join("ARCHITECTURE.md")).expect("ARCHITECTURE.md");
    let after = text
        .split_once("<!-- layers -->")
        .expect("ARCHITECTURE.md marks its layer diagram with <!-- layers -->")
        .1;
    let block = after
        .split("```")
        .nth(1)
        .expect("a fenced block after the marker");
    block
        .lines()
        .skip(1)
        .map(|line| line.split('(').next().unwrap_or(""))
        .map(|line| {
            line.split('·')
                .map(|name| name.trim().to_string())
                .filter(|name| {
                    !name.is_empty() && name.chars().all(|c| c.is_alphanumeric() || c == '_')
                })
                .collect::<Vec<_>>()
        })
        .filter(|names| !names.is_empty())
        .collect()
}

/// Each module's layer, 0 at the top.
fn layer_of() -> BTreeMap<String, usize> {
    let mut map = BTreeMap::new();
    for (depth, names) in layers().into_iter().enumerate() {
        for name in names {
            assert!(
                map.insert(name.clone(), depth).is_none(),
                "{name} is in two layers"
            );
        }
    }
    map
}

fn library() -> Vec<Source> {
    sources(repo())
        .into_iter()
        .filter(|s| !s.module.is_empty())
        .collect()
}

#[test]
fn the_diagram_names_every_module_of_the_library() {
    let layers = layer_of();
    for source in library() {
        let top = &source.module[0];
        assert!(
            layers.contains_key(top),
            "{} is in module {top}, which ARCHITECTURE.md's diagram does not place",
            source.file.display()
        );
    }
}

#[test]
fn every_module_uses_only_the_layers_below_it() {
    let wrong = upward_uses(&library(), &layer_of());
    assert!(
        wrong.is_empty(),
        "upward or sideways uses:\n{}",
        wrong.join("\n")
    );
}

/// The uses in `sources` of a module on the same layer or above.
fn upward_uses(sources: &[Source], layers: &BTreeMap<String, usize>) -> Vec<String> {
    let mut wrong = Vec::new();
    for source in sources.iter().filter(|s| !s.test_only) {
        let top = layer_name(&source.module);
        let own = layers[top];
        for path in used_paths(source) {
            let used = layer_name(&path);
            if used == top {
                continue;
            }
            if layers.get(used).is_some_and(|&layer| layer <= own) {
                wrong.push(format!(
                    "{} ({top}) uses {} (not a layer below)",
                    source.file.display(),
                    path.join("::")
                ));
            }
        }
    }
    wrong
}

#[test]
fn dialect_folders_never_use_each_other() {
    let wrong = crossings(&library(), &dialect_folders());
    assert!(
        wrong.is_empty(),
        "dialects using each other:\n{}",
        wrong.join("\n")
    );
}

/// The uses in `sources` of one dialect folder by another.
fn crossings(sources: &[Source], folders: &[String]) -> Vec<String> {
    let mut wrong = Vec::new();
    for source in sources.iter().filter(|s| !s.test_only) {
        let own = folder_of(&source.module, folders);
        for path in used_paths(source) {
            if let Some(used) = folder_of(&path, folders) {
                if own.is_some_and(|own| own != used) {
                    wrong.push(format!(
                        "{} uses {}",
                        source.file.display(),
                        path.join("::")
                    ));
                }
            }
        }
    }
    wrong
}

#[test]
fn outside_its_folder_a_dialect_is_named_only_by_the_list_and_the_command_line() {
    let folders = dialect_folders();
    let mut wrong = Vec::new();
    for source in library().iter().filter(|s| !s.test_only) {
        if folder_of(&source.module, &folders).is_some() {
            continue;
        }
        let file = source.file.to_string_lossy().replace('\\', "/");
        let names = used_paths(source)
            .iter()
            .any(|path| folder_of(path, &folders).is_some());
        if names && !NAMING_A_DIALECT.contains(&file.as_str()) {
            wrong.push(file);
        }
    }
    assert!(
        wrong.is_empty(),
        "shared files naming a dialect (use the descriptor or the trait):\n{}",
        wrong.join("\n")
    );
}

/// The dialect folders: the folders under `src/dialect/`.
fn dialect_folders() -> Vec<String> {
    let dir = repo().join("src").join("dialect");
    let mut folders: Vec<String> = std::fs::read_dir(dir)
        .expect("src/dialect")
        .filter_map(|e| e.ok())
        .filter(|e| e.path().is_dir() && e.path().join("mod.rs").exists())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|name| {
            std::fs::read_to_string(repo().join("src/dialect").join(name).join("mod.rs"))
                .is_ok_and(|text| text.contains("pub static DIALECT: Dialect"))
        })
        .collect();
    folders.sort();
    assert!(folders.len() >= 2, "dialect folders found: {folders:?}");
    folders
}

/// The dialect folder a module path is in (`dialect::tmcl::…` → `tmcl`).
fn folder_of<'a>(path: &[String], folders: &'a [String]) -> Option<&'a str> {
    match path {
        [dialect, folder, ..] if dialect == "dialect" => {
            folders.iter().find(|f| *f == folder).map(String::as_str)
        }
        _ => None,
    }
}

/// A source file made up for the checks' own tests.
fn made_up(file: &str, module: &[&str], code: &str) -> Source {
    Source {
        file: file.into(),
        module: module.iter().map(|m| m.to_string()).collect(),
        code: paths::strip(code),
        test_only: false,
    }
}

#[test]
fn the_checks_see_an_upward_use_and_a_dialect_crossing() {
    let layers = layer_of();
    let folders = dialect_folders();
    let session = made_up(
        "src/session/x.rs",
        &["session", "x"],
        "use crate::cli::Failure;\nuse super::super::dialect::DialectSession;\n// crate::repl\nlet s = \"crate::shell\";\nlet q = '\\'';\nlet r = r#\"crate::repl\"#;",
    );
    let wrong = upward_uses(&[session], &layers);
    assert_eq!(wrong.len(), 2, "{wrong:?}");
    assert!(wrong[0].contains("uses cli::Failure"), "{wrong:?}");
    assert!(
        wrong[1].contains("uses dialect::DialectSession"),
        "{wrong:?}"
    );
    let peer = made_up(
        "src/sim/x.rs",
        &["sim", "x"],
        "use crate::commission::Snapshot;",
    );
    assert_eq!(
        upward_uses(&[peer], &layers).len(),
        1,
        "peers do not use each other"
    );
    let down = made_up(
        "src/cli/x.rs",
        &["cli", "x"],
        "use crate::session::SessionError;",
    );
    assert!(upward_uses(&[down], &layers).is_empty());
    let (a, b) = (&folders[0], &folders[1]);
    let subcommand = made_up(
        "src/dialect/a/cli/x.rs",
        &["dialect", a, "cli", "x"],
        "use crate::cli::connection::ModuleArgs;\nuse crate::session::SessionError;",
    );
    assert!(upward_uses(&[subcommand], &layers).is_empty());
    let below = made_up(
        "src/dialect/a/session/x.rs",
        &["dialect", a, "session", "x"],
        &format!("use crate::dialect::{a}::cli::download;"),
    );
    assert_eq!(upward_uses(&[below], &layers).len(), 1);
    let crossing = made_up(
        "src/dialect/a/x.rs",
        &["dialect", a, "x"],
        &format!(
            "use crate::dialect::{b}::Thing;\nuse crate::dialect::{a}::Own;\nuse crate::dialect::all;"
        ),
    );
    let wrong = crossings(&[crossing], &folders);
    assert_eq!(wrong.len(), 1, "{wrong:?}");
}

/// What a dialect's pure `protocol/` folder may not use: the crate's sessions, simulator and faces,
/// and its own dialect's session (where its faces live) and simulator. Tables it shares with
/// commissioning (`commission::SnapshotRules`) and a link's frame types (`link::can`) are data.
const ABOVE_PROTOCOL: &[&str] = &["cli", "repl", "shell", "script", "sim", "session"];
const ABOVE_PROTOCOL_IN_DIALECT: &[&str] = &["session", "sim", "faces"];

#[test]
fn pure_protocol_folders_use_no_session_simulator_or_face() {
    let wrong = protocol_reaching_up(&library(), &dialect_folders());
    assert!(
        wrong.is_empty(),
        "protocol code using what is above it:\n{}",
        wrong.join("\n")
    );
}

/// The uses in `sources`' `protocol/` folders of what is above them.
fn protocol_reaching_up(sources: &[Source], folders: &[String]) -> Vec<String> {
    let mut wrong = Vec::new();
    for source in sources.iter().filter(|s| !s.test_only) {
        let Some(folder) = folder_of(&source.module, folders) else {
            continue;
        };
        if source.module.get(2).map(String::as_str) != Some("protocol") {
            continue;
        }
        for path in used_paths(source) {
            let above = match path.as_slice() {
                [dialect, own, inner, ..] if dialect == "dialect" && own == folder => {
                    ABOVE_PROTOCOL_IN_DIALECT.contains(&inner.as_str())
                }
                [top, ..] => ABOVE_PROTOCOL.contains(&top.as_str()),
                [] => false,
            };
            if above {
                wrong.push(format!(
                    "{} uses {}",
                    source.file.display(),
                    path.join("::")
                ));
            }
        }
    }
    wrong
}

/// What asks the terminal: whether a stream is one, its size, the terminal library.
const ASKING_THE_TERMINAL: &[&str] = &[
    "is_terminal(",
    "terminal_width(",
    "crossterm::",
    "terminal::size(",
];

/// The layers that must not ask the terminal anything: the UI (`cli`, `repl`, `shell`) asks and
/// passes what it learnt down; `wrap` holds the one question, for the UI and the dialects' faces.
/// Below them the session, links, simulators, scripts and commissioning, and in each dialect its
/// `protocol/`, `session/` and `sim/` folders.
fn below_the_ui(source: &Source, folders: &[String]) -> bool {
    match source.module.as_slice() {
        [dialect, folder, inner, ..] if dialect == "dialect" && folders.contains(folder) => {
            ["protocol", "session", "sim"].contains(&inner.as_str())
        }
        [top, ..] => ["session", "link", "sim", "script", "commission"].contains(&top.as_str()),
        [] => false,
    }
}

#[test]
fn nothing_below_the_ui_asks_the_terminal() {
    let folders = dialect_folders();
    let wrong: Vec<String> = library()
        .iter()
        .filter(|s| !s.test_only && below_the_ui(s, &folders))
        .flat_map(|s| {
            ASKING_THE_TERMINAL
                .iter()
                .filter(|ask| s.code.contains(*ask))
                .map(move |ask| format!("{} asks the terminal ({ask}…)", s.file.display()))
        })
        .collect();
    assert!(
        wrong.is_empty(),
        "below the UI, pass what the terminal said in instead:\n{}",
        wrong.join("\n")
    );
}

#[test]
fn the_checks_see_a_protocol_reaching_up_and_a_question_to_the_terminal() {
    let folders = dialect_folders();
    let a = &folders[0];
    let protocol = made_up(
        "src/dialect/a/protocol/x.rs",
        &["dialect", a, "protocol", "x"],
        &format!(
            "use crate::dialect::{a}::session::faces::Faces;\nuse super::super::sim::Bus;\nuse crate::session::SessionError;\nuse super::table::Row;\nuse crate::escape::escape_control;"
        ),
    );
    let wrong = protocol_reaching_up(&[protocol], &folders);
    assert_eq!(wrong.len(), 3, "{wrong:?}");
    let asking = made_up(
        "src/dialect/a/protocol/y.rs",
        &["dialect", a, "protocol", "y"],
        "let w = crate::wrap::terminal_width();",
    );
    assert!(below_the_ui(&asking, &folders));
    assert!(asking.code.contains("terminal_width("));
    let face = made_up("src/shell/help.rs", &["shell", "help"], "");
    assert!(!below_the_ui(&face, &folders));
}
