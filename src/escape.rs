//! Text from a device or from input made safe for a terminal.
//!
//! A reply, a discarded line or an error message that quotes one may carry bytes a terminal acts
//! on: ESC starts sequences that retitle the window, clear the screen or remap keys, BEL rings,
//! CR and BS overwrite what was printed before, and the bidirectional overrides of Unicode reorder
//! it. Every place that writes such text to stdout or stderr passes it through
//! [`escape_control`] first.
//!
//! The escapes are visible and plain ASCII (`\x1B`, `\r`, `\u{202e}`), and a backslash is left
//! alone, so escaping is idempotent: text that is already escaped (a transcript line, a notice
//! built with the session's own quoting) comes out unchanged, and applying it at every boundary
//! never doubles a backslash. The line feed is kept: it separates the lines of a multi-line
//! reply or message that tmclsh itself built, and device text never carries one, since sessions
//! split what they receive into lines at CR and LF.

use std::borrow::Cow;
use std::fmt::Write;

/// `text` with every control character except the line feed — C0, DEL, C1 — and every Unicode
/// bidirectional formatting character replaced by a visible escape. Borrows when there is
/// nothing to replace.
pub fn escape_control(text: &str) -> Cow<'_, str> {
    if !text.chars().any(needs_escape) {
        return Cow::Borrowed(text);
    }
    let mut out = String::with_capacity(text.len() + 8);
    for c in text.chars() {
        match c {
            _ if !needs_escape(c) => out.push(c),
            '\r' => out.push_str("\\r"),
            '\t' => out.push_str("\\t"),
            '\0'..='\x7f' => {
                let _ = write!(out, "\\x{:02X}", c as u32);
            }
            _ => {
                let _ = write!(out, "\\u{{{:x}}}", c as u32);
            }
        }
    }
    Cow::Owned(out)
}

/// Whether a character must not reach a terminal as it is.
fn needs_escape(c: char) -> bool {
    (c.is_control() && c != '\n') || is_bidi_format(c)
}

/// The characters that change the display order of text (LRM, RLM, the embeddings, overrides and
/// isolates): a device could make `-5000` read as `0005-`.
fn is_bidi_format(c: char) -> bool {
    matches!(c, '\u{200e}' | '\u{200f}' | '\u{202a}'..='\u{202e}' | '\u{2066}'..='\u{2069}')
}

#[cfg(test)]
mod tests {
    use proptest::prelude::*;

    use super::*;

    #[test]
    fn terminal_controls_become_visible() {
        assert_eq!(
            escape_control("\x1b]0;owned\x07\x1b[2J"),
            "\\x1B]0;owned\\x07\\x1B[2J"
        );
        assert_eq!(
            escape_control("a\0b\rc\td\x08\x7f"),
            "a\\x00b\\rc\\td\\x08\\x7F"
        );
        assert_eq!(escape_control("\u{9b}31m"), "\\u{9b}31m");
        assert_eq!(escape_control("pos \u{202e}0005-"), "pos \\u{202e}0005-");
    }

    #[test]
    fn plain_text_line_feeds_and_backslashes_are_kept() {
        for text in [
            "BA 100 -5000",
            "two\nlines",
            "already \\x1B escaped \\r",
            "rx \"AGAP 1, 0\\r\"",
            "µ-steps ⠿ …",
        ] {
            assert!(matches!(escape_control(text), Cow::Borrowed(t) if t == text));
        }
    }

    proptest! {
        #[test]
        fn escaping_is_idempotent_and_leaves_no_control(text in "\\PC*|[\\x00-\\x1f\\x7f-\\u{a0}\\u{2066}\\\\a]{0,40}") {
            let once = escape_control(&text).into_owned();
            let twice = escape_control(&once);
            prop_assert_eq!(twice.as_ref(), once.as_str());
            prop_assert!(!once.chars().any(needs_escape));
        }

        #[test]
        fn text_without_controls_is_unchanged(text in "[^\\p{Cc}\\u{200e}\\u{200f}\\u{202a}-\\u{202e}\\u{2066}-\\u{2069}]*") {
            let escaped = escape_control(&text);
            prop_assert_eq!(escaped.as_ref(), text.as_str());
        }
    }
}
