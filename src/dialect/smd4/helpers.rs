//! The helper commands of SMD4 drives: the address prefix, settings, flag tables.

use std::io::Write;

use crate::dialect::helper::{ArgKind, Helper, Section, helper};
use crate::dialect::smd4::protocol::{MAX_ADDRESS, hints};
use crate::dialect::smd4::session::{DriveName, Smd4Session};
use crate::session::SessionError;

/// The helpers only SMD4 drives have.
pub const HELPERS: &[Helper] = &[helper(
    ":flags",
    "the SFLAGS and EFLAGS bit tables with the drive's current flags",
    ArgKind::None,
    Section::Session,
)];

/// Runs one SMD4 helper.
pub fn run(
    session: &mut Smd4Session,
    helper: &Helper,
    arg: &str,
    out: &mut dyn Write,
) -> Result<(), SessionError> {
    match helper.name() {
        "params" => {
            let mut any = false;
            for spec in hints::matching(&session.spec().commands, arg) {
                super::params::write_row(spec, out)?;
                any = true;
            }
            if !any {
                writeln!(out, "no setting matches '{arg}'")?;
            }
        }
        // Alone: where requests go now.
        "target" if arg.trim().is_empty() => {
            writeln!(out, "requests go to {}", describe(session.address()))?;
        }
        "target" => {
            let address = parse_address(arg)?;
            session.set_address(address);
            writeln!(out, "requests go to {}", describe(address))?;
        }
        "flags" => {
            let reply = session.exchange_line("SYS:FLAGS")?.checked()?;
            let (sflags, eflags) = reply
                .reply
                .map(|r| (r.sflags.0, r.eflags.0))
                .unwrap_or((0, 0));
            let spec = session.spec();
            let words = [
                (format!("SFLAGS {sflags:#06X}"), sflags, &spec.sflags),
                (
                    format!(
                        "EFLAGS {eflags:#06X} (latching; SYS:CLR clears; any set bit disables the motor)"
                    ),
                    eflags,
                    &spec.eflags,
                ),
            ];
            for (title, word, table) in words {
                writeln!(out, "{title}")?;
                for bit in table.bits() {
                    writeln!(out, "  [{}] {:>2} {}", bit.mark(word), bit.bit, bit.name)?;
                }
            }
        }
        other => unreachable!("helper table and SMD4 dispatch disagree on :{other}"),
    }
    Ok(())
}

fn describe(address: Option<u32>) -> String {
    match address {
        None => "the drive without an address prefix".into(),
        Some(0) => "every drive (@0 broadcast: no replies)".into(),
        Some(_) => DriveName(address).to_string(),
    }
}

fn parse_address(arg: &str) -> Result<Option<u32>, SessionError> {
    let text = arg.trim().trim_start_matches('@');
    if text.eq_ignore_ascii_case("none") {
        return Ok(None);
    }
    text.parse::<u32>()
        .ok()
        .filter(|a| *a <= MAX_ADDRESS)
        .map(Some)
        .ok_or_else(|| {
            SessionError::Usage(format!(
                "usage: :target N (0..{MAX_ADDRESS}, 0 broadcasts) or :target none, not '{arg}'"
            ))
        })
}
