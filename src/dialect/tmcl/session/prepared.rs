//! The last ASCII request checked and spelled, kept: a polling loop asks the same thing over and
//! over (`gap(1, 0)` in a script), and checking a line against the profile and spelling it are
//! pure functions of the line, the profile and the mode, so their answer for the same three is
//! the same. Only a line that passed without a warning is kept; one with warnings, or refused
//! (`--no-validate` sends it with a notice), is checked again each time, so its notices repeat.

use std::sync::Arc;

use crate::dialect::tmcl::profile::Profile;
use crate::dialect::tmcl::protocol::line::Line;
use crate::dialect::tmcl::protocol::validate::Mode;

/// A line that passed validation without warnings, with its spelling.
#[derive(Default)]
pub(super) struct Prepared {
    last: Option<Kept>,
}

struct Kept {
    line: Line,
    profile: Arc<Profile>,
    mode: Mode,
    text: String,
}

impl Prepared {
    /// The spelling of `line`, checked for `mode` against `profile` before, if it is the last
    /// line kept.
    pub(super) fn text(&self, line: &Line, profile: &Arc<Profile>, mode: Mode) -> Option<&str> {
        let kept = self.last.as_ref()?;
        let same = kept.line == *line && kept.mode == mode && Arc::ptr_eq(&kept.profile, profile);
        same.then_some(kept.text.as_str())
    }

    /// Keeps `text` as the spelling of `line`, which passed validation for `mode` against
    /// `profile` without a warning.
    pub(super) fn keep(&mut self, line: Line, profile: &Arc<Profile>, mode: Mode, text: &str) {
        match &mut self.last {
            Some(kept) => {
                kept.line = line;
                kept.mode = mode;
                if !Arc::ptr_eq(&kept.profile, profile) {
                    kept.profile = profile.clone();
                }
                kept.text.clear();
                kept.text.push_str(text);
            }
            None => {
                self.last = Some(Kept {
                    line,
                    profile: profile.clone(),
                    mode,
                    text: text.to_string(),
                })
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dialect::tmcl::protocol::line::{Op, format_line};
    use crate::dialect::tmcl::protocol::{Instruction, Opcode};

    fn gap(type_: u8) -> Line {
        Line {
            address: Some(1),
            op: Op::Command(Instruction::new(Opcode::Gap, type_, 0, 0)),
        }
    }

    #[test]
    fn only_the_same_line_profile_and_mode_find_the_spelling_kept() {
        let profile = Profile::builtin();
        let mut prepared = Prepared::default();
        assert_eq!(prepared.text(&gap(1), &profile, Mode::Ascii), None);
        let text = format_line(&gap(1), 1, &profile);
        prepared.keep(gap(1), &profile, Mode::Ascii, &text);
        assert_eq!(
            prepared.text(&gap(1), &profile, Mode::Ascii),
            Some("AGAP 1, 0")
        );
        assert_eq!(prepared.text(&gap(2), &profile, Mode::Ascii), None);
        assert_eq!(prepared.text(&gap(1), &profile, Mode::Binary), None);
        let other = Arc::new(Profile::clone(&profile));
        assert_eq!(prepared.text(&gap(1), &other, Mode::Ascii), None);
        prepared.keep(gap(2), &other, Mode::Ascii, "AGAP 2, 0");
        assert_eq!(prepared.text(&gap(1), &profile, Mode::Ascii), None);
        assert_eq!(
            prepared.text(&gap(2), &other, Mode::Ascii),
            Some("AGAP 2, 0")
        );
    }
}
