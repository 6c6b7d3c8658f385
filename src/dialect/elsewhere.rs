//! Lines and scripts written for another dialect than the session's. A line the session refuses
//! is read by every other dialect of the list with its own grammar and built-in tables
//! ([`Dialect::recognises`]); when one of them knows it and the session's own dialect does not,
//! the refusal says which `--protocol` it belongs to instead of where the session's grammar gave
//! up (`column 6: unexpected ':'`). Scripts likewise, by the device functions each dialect
//! registers ([`Dialect::script_functions`]).

use crate::exit::{Exit, ExitStatus};
use crate::session::SessionError;

use super::{Dialect, all};

/// The dialect other than `this` whose command `line` is, if `this` does not know it.
pub fn line_dialect(this: &Dialect, line: &str) -> Option<&'static Dialect> {
    let line = line.trim();
    if line.is_empty() || (this.recognises)(line) {
        return None;
    }
    all()
        .iter()
        .copied()
        .find(|d| *d != this && (d.recognises)(line))
}

/// What to say about a line of `other`'s: "this looks like an SMD4 command — add `--protocol
/// smd4`".
pub fn line_message(other: &Dialect) -> String {
    format!(
        "this looks like {} command — add `--protocol {}`",
        other.indefinite(),
        other.name
    )
}

/// A refusal of `line` by a session of `this`, explained when the line is another dialect's;
/// every other outcome unchanged.
pub fn explain(this: &Dialect, line: &str, error: SessionError) -> SessionError {
    if error.exit() != Exit::Refused {
        return error;
    }
    match line_dialect(this, line) {
        Some(other) => SessionError::Refused(line_message(other)),
        None => error,
    }
}

/// The dialect other than `this` whose scripts call the function `name`, if `this` has no
/// function of that name.
pub fn script_dialect(this: &Dialect, name: &str) -> Option<&'static Dialect> {
    if this.script_functions.iter().any(|f| f.name() == name) {
        return None;
    }
    all()
        .iter()
        .copied()
        .find(|d| *d != this && d.script_functions.iter().any(|f| f.name() == name))
}

/// What to say about a script of `other`'s: "this looks like a TMCL script — add `--protocol
/// tmcl`".
pub fn script_message(other: &Dialect) -> String {
    format!(
        "this looks like {} script — add `--protocol {}`",
        other.indefinite(),
        other.name
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dialect::smd4::DIALECT as SMD4;
    use crate::dialect::tmcl::DIALECT as TMCL;

    #[test]
    fn each_dialect_knows_its_own_lines_by_its_tables() {
        for line in [
            "GAP 1, 0",
            "gap 1 0",
            "AGAP 1, 0",
            "MVP ABS, 0, 1000",
            "136 1",
            "MST",
            "SAP 4",
        ] {
            assert!((TMCL.recognises)(line), "{line}");
            assert!(!(SMD4.recognises)(line), "{line}");
        }
        for line in [
            "MOTOR:VMAX",
            "motor:vmax,2000",
            "MOTOR:VMAX 2000",
            "@3MOTOR:STOP",
            "@3,SYS:FW",
            "STORE",
            "SYS:FLAGS?",
        ] {
            assert!((SMD4.recognises)(line), "{line}");
            assert!(!(TMCL.recognises)(line), "{line}");
        }
        for neither in ["FOO 1", "MOTOR:FOO", "", "12345", "GAPP 1, 0", ":help"] {
            assert!(!(TMCL.recognises)(neither), "{neither}");
            assert!(!(SMD4.recognises)(neither), "{neither}");
        }
    }

    #[test]
    fn a_refused_line_of_the_other_dialect_names_it() {
        let refused = || SessionError::Refused("column 6: unexpected ':'".into());
        let explained = explain(&TMCL, "MOTOR:VMAX", refused());
        assert_eq!(
            explained.to_string(),
            "this looks like an SMD4 command — add `--protocol smd4`"
        );
        assert_eq!(explained.exit(), Exit::Refused);
        let explained = explain(&SMD4, "GAP 1, 0", refused());
        assert_eq!(
            explained.to_string(),
            "this looks like a TMCL command — add `--protocol tmcl`"
        );
        // Its own lines, lines of no dialect and failures after sending keep their message.
        for (dialect, line) in [(&TMCL, "GAP 1, 0, 7, 9"), (&TMCL, "FOO"), (&SMD4, "XYZ")] {
            let kept = explain(dialect, line, refused()).to_string();
            assert_eq!(kept, refused().to_string(), "{line}");
        }
        let lost = explain(&TMCL, "MOTOR:VMAX", SessionError::Lost("gone".into()));
        assert_eq!(lost.to_string(), "link lost: gone");
    }

    #[test]
    fn scripts_are_told_by_the_functions_only_one_dialect_has() {
        assert_eq!(script_dialect(&SMD4, "gap"), Some(&TMCL));
        assert_eq!(script_dialect(&TMCL, "wait_standby"), Some(&SMD4));
        // Both have send: it says nothing about the script.
        assert_eq!(script_dialect(&TMCL, "send"), None);
        assert_eq!(script_dialect(&TMCL, "no_such_function"), None);
    }
}
