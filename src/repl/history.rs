//! History per dialect: a TMCL session recalls TMCL lines, an SMD4 session SMD4 lines. Each has
//! its file in the user's data directory (`tmclsh/history-tmcl`, `tmclsh/history-smd4`); the one
//! `history` file of earlier versions is split between them the first time a dialect has none.

use std::path::{Path, PathBuf};

use rustyline::Editor;
use rustyline::history::{DefaultHistory, History};

use crate::dialect::{Dialect, elsewhere};

use super::editor::ReplHelper;

/// The history file of `dialect`, in the user's data directory (`history-NAME`).
pub(super) fn path(dialect: &Dialect) -> Option<PathBuf> {
    let name = format!("history-{}", dialect.name);
    dirs::data_dir().map(|d| d.join("tmclsh").join(name))
}

/// Loads `dialect`'s history into the editor (from the shared file of earlier versions, keeping
/// this dialect's lines, when it has none yet). A missing or unreadable file is an empty history,
/// and so is one that is not a regular file (a FIFO would block the editor's open).
pub(super) fn load(editor: &mut Editor<ReplHelper, DefaultHistory>, dialect: &Dialect) {
    let Some(path) = path(dialect) else { return };
    if crate::file::check_writable(&path).is_err() {
        return;
    }
    if path.exists() {
        let _ = editor.load_history(&path);
        return;
    }
    let legacy = path.with_file_name("history");
    let mut shared = DefaultHistory::new();
    if crate::file::check_writable(&legacy).is_err() || shared.load(&legacy).is_err() {
        return;
    }
    for line in shared.iter().filter(|line| belongs(line, dialect)) {
        let _ = editor.add_history_entry(line.as_str());
    }
}

/// Saves the editor's history as `dialect`'s.
pub(super) fn save(editor: &mut Editor<ReplHelper, DefaultHistory>, dialect: &Dialect) {
    let Some(path) = path(dialect) else { return };
    if let Some(dir) = path.parent() {
        let _ = std::fs::create_dir_all(dir);
    }
    if crate::file::check_writable(&path).is_err() {
        return;
    }
    let _ = editor.save_history(Path::new(&path));
}

/// Whether a line of the shared history was typed in `dialect`: not one another dialect's
/// grammar knows and its own does not ([`elsewhere`]); helper lines (`:help`) belong to every
/// dialect.
fn belongs(line: &str, dialect: &Dialect) -> bool {
    let line = line.trim_start();
    line.starts_with(':') || elsewhere::line_dialect(dialect, line).is_none()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dialect::smd4::DIALECT as SMD4;
    use crate::dialect::tmcl::DIALECT as TMCL;

    #[test]
    fn lines_of_the_shared_history_go_to_their_dialect() {
        for line in ["GAP 1, 0", "AMVP ABS, 0, 5", "136 0", "C GAP 4, 0"] {
            assert!(belongs(line, &TMCL), "{line}");
            assert!(!belongs(line, &SMD4), "{line}");
        }
        for line in ["MOTOR:RUNA", "MOTOR:VMAX,2000", "@3SYS:FW", "@3,MOTOR:STOP"] {
            assert!(belongs(line, &SMD4), "{line}");
            assert!(!belongs(line, &TMCL), "{line}");
        }
        assert!(belongs(":help", &TMCL) && belongs(":help", &SMD4));
    }
}
