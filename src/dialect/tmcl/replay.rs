//! Transcripts that replay: a `--log` transcript turned into a Rhai script that sends the same
//! commands and checks the values that came back, so a manual commissioning session becomes a
//! regression test (`tmclsh transcript to-rhai LOG`).
//!
//! What the session did on its own is left out: identifying the module on connect (136 and the
//! note after it), entering ASCII mode (139 and the CR after it), the
//! echo probe (`GGP 67, 0` followed by the session's "in ASCII mode, echo …" note), BIN, and
//! resynchronising CRs. Commands sent as binary frames are replayed as ASCII lines (the script's
//! session is in ASCII mode); the firmware version (136) becomes `firmware_version()`.
//!
//! Values are checked exactly (`assert_eq`) except live ones — reads of live or read-only
//! parameters, inputs and the reference search status — which depend on when they were read:
//! those are checked with `wait_until` only where the transcript read the same value twice in a
//! row with nothing sent in between (a settled value), and kept as comments otherwise.

use std::fmt::Write as _;

use crate::dialect::tmcl::profile::{Profile, SnapshotRole, catalogue};
use crate::dialect::tmcl::protocol::frame::{
    CommandFrame, FRAME_LEN, ReplyFrame, decode_version_string,
};
use crate::dialect::tmcl::protocol::line::{self, Op, address_char, format_instruction};
use crate::dialect::tmcl::protocol::reply::parse_reply;
use crate::dialect::tmcl::protocol::{AsciiWord, Instruction, ModuleName, Opcode, Status};

use crate::dialect::replay::parse::{Entry, Record};
use crate::dialect::replay::{ReplayError, comment, reply_after, rhai_string};
use crate::session::transcript::Header;

/// The Rhai script replaying a TMCL transcript with the modules of `profile`; refused when the
/// transcript's header names another module, or when no exchange in it replays.
pub fn script(
    entries: &[Entry],
    header: Option<&Header>,
    profile: &Profile,
    name: &str,
    wait_ms: u64,
) -> Result<String, ReplayError> {
    refuse_mixed_bus(entries)?;
    if let Some(header) = header {
        let (module, origin) = match identified_profile(entries) {
            Some(used) => (used.module.clone(), used.name.clone()),
            None => (
                header.module.clone(),
                header.profile.clone().unwrap_or_else(|| "unknown".into()),
            ),
        };
        if module != profile.module {
            return Err(ReplayError::OtherModule(format!(
                "a transcript of a {module} (profile {origin}), but the profile in use is the \
                 {}'s; give --profile",
                profile.module
            )));
        }
    }
    let steps = steps(entries, profile);
    if !replays_something(&steps) {
        return Err(ReplayError::Nothing { dialect: "TMCL" });
    }
    Ok(to_rhai(&steps, profile, name, wait_ms))
}

/// Whether any step is an exchange to replay (a transcript of only failed or unreadable
/// commands replays nothing).
pub fn replays_something(steps: &[Step]) -> bool {
    steps
        .iter()
        .any(|s| matches!(s, Step::Exchange { .. } | Step::Version { .. }))
}

/// One thing the script does.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Step {
    /// A command line and the reply it got.
    Exchange {
        /// The line as sent, with its address character (`AGAP 1, 0`).
        line: String,
        /// The module addressed.
        module: u8,
        /// The command, where the line resolves (RUN/STOP do not).
        instruction: Option<Instruction>,
        /// Status and value of the reply.
        status: Status,
        /// The value.
        value: i32,
    },
    /// The firmware version a module told (command 136).
    Version {
        /// The module.
        module: u8,
        /// Its version string.
        text: String,
    },
    /// Something kept as a comment: a command that got no reply, a binary-only command.
    Comment(String),
}

/// The session's note after its echo probe (see `session::tmcl::mode`).
const PROBE_NOTE: &str = "in ASCII mode, echo";

/// The session's note after asking for the firmware version on connect (see
/// `session::tmcl::identify`): "identified: …" or "not identified: …".
const IDENTIFIED_NOTE: &str = "identified: ";

/// What each identification note says: (the module and its type, the profile label).
fn identifications(entries: &[Entry]) -> Vec<(&str, &str)> {
    entries
        .iter()
        .filter_map(|e| match &e.record {
            Record::Note(note) => note
                .strip_prefix(IDENTIFIED_NOTE)?
                .rsplit_once(", profile "),
            _ => None,
        })
        .collect()
}

/// A session on a bus of different modules checked each module's lines with its own profile; a
/// replay script has one profile for all of them, so it would check module 2's lines against
/// module 1's tables. Refused, naming the modules.
fn refuse_mixed_bus(entries: &[Entry]) -> Result<(), ReplayError> {
    let found = identifications(entries);
    let Some((_, first)) = found.first() else {
        return Ok(());
    };
    if found.iter().all(|(_, label)| label == first) {
        return Ok(());
    }
    let mut modules: Vec<String> = found
        .iter()
        .map(|(module, label)| format!("{module} ({label})"))
        .collect();
    modules.sort();
    modules.dedup();
    Err(ReplayError::Mixed(format!(
        "a transcript of a bus of different modules: {}; a replay checks every line against one \
         profile, so it cannot replay this one (log one session per module, or give the \
         same --profile to every session)",
        modules.join("; ")
    )))
}

/// The built-in profile the session took from the module's answer on connect, where its note
/// names one (`identified: TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in)`): the
/// header, written before the module was asked, names the profile it started with.
fn identified_profile(entries: &[Entry]) -> Option<std::sync::Arc<Profile>> {
    entries.iter().find_map(|e| {
        let Record::Note(note) = &e.record else {
            return None;
        };
        let (_, profile) = note
            .strip_prefix(IDENTIFIED_NOTE)?
            .rsplit_once(", profile ")?;
        catalogue::by_name(profile.strip_suffix(" (built in)")?)
    })
}

/// Pairs what was sent with what came back, leaving out what the session did on its own.
pub fn steps(entries: &[Entry], profile: &Profile) -> Vec<Step> {
    let mut steps = Vec::new();
    for (i, entry) in entries.iter().enumerate() {
        let Record::Sent(bytes) = &entry.record else {
            continue;
        };
        let reply = reply_after(&entries[i + 1..]);
        if let Some(text) = ascii_line(bytes) {
            if let Some(step) = ascii_step(text, reply, profile) {
                if !is_echo_probe(&step, &entries[i + 1..]) {
                    steps.push(step);
                }
            }
        } else if let Ok(frame) = <[u8; FRAME_LEN]>::try_from(bytes.as_slice()) {
            if !is_identification(&entries[i + 1..]) {
                steps.extend(binary_step(&frame, reply, profile));
            }
        }
    }
    steps
}

/// The text of an ASCII command line (printable, ending in CR), without the CR.
fn ascii_line(bytes: &[u8]) -> Option<&str> {
    let body = bytes.strip_suffix(b"\r")?;
    body.iter()
        .all(|b| (0x20..=0x7E).contains(b))
        .then(|| std::str::from_utf8(body).ok())
        .flatten()
}

fn ascii_step(text: &str, reply: Option<&[u8]>, profile: &Profile) -> Option<Step> {
    if text.trim().is_empty() {
        return None; // a CR that ends partial lines
    }
    let Ok(parsed) = line::parse(text, profile) else {
        return Some(Step::Comment(format!(
            "not replayed (not a valid line): {text}"
        )));
    };
    let module = parsed.address?;
    let instruction = match parsed.op {
        Op::Ascii(AsciiWord::Bin) => return None, // a mode switch, the session's business
        Op::Ascii(_) => None,
        Op::Command(i) => Some(i),
    };
    let Some(bytes) = reply else {
        return Some(Step::Comment(format!("no reply to {text}")));
    };
    let c = address_char(module)?;
    let text_reply = String::from_utf8_lossy(bytes);
    let Some(reply) = text_reply
        .split(['\r', '\n'])
        .filter_map(parse_reply)
        .find(|r| r.module == c)
    else {
        return Some(Step::Comment(format!("no usable reply to {text}")));
    };
    Some(Step::Exchange {
        line: text.to_string(),
        module,
        instruction,
        status: reply.status,
        value: reply.value,
    })
}

fn binary_step(frame: &[u8; FRAME_LEN], reply: Option<&[u8]>, profile: &Profile) -> Option<Step> {
    let command = CommandFrame::decode(frame).ok()?;
    let i = command.instruction;
    if i.command == Opcode::EnterAscii {
        return None; // entering ASCII mode
    }
    let sent = format_instruction(&i, profile);
    let reply: Option<[u8; FRAME_LEN]> = reply.and_then(|r| r.try_into().ok());
    let Some(reply) = reply else {
        return Some(Step::Comment(format!("no reply to {sent} (binary)")));
    };
    if i.command == Opcode::FirmwareVersion && i.type_ == 0 {
        let (_, text) = decode_version_string(&reply);
        return Some(Step::Version {
            module: command.address,
            text: text.trim().to_string(),
        });
    }
    let ascii = profile
        .commands
        .by_number(i.command)
        .is_some_and(|s| s.ascii_allowed);
    let (Some(c), true) = (address_char(command.address), ascii) else {
        return Some(Step::Comment(format!(
            "not replayed (binary direct mode only): {sent} to {}",
            ModuleName(command.address)
        )));
    };
    let reply = ReplyFrame::decode(&reply).ok()?;
    Some(Step::Exchange {
        line: format!("{c}{sent}"),
        module: command.address,
        instruction: Some(i),
        status: reply.status,
        value: reply.value,
    })
}

/// Whether the frame just sent was the session's identification on connect: its note follows.
fn is_identification(rest: &[Entry]) -> bool {
    rest.iter()
        .take_while(|e| !matches!(e.record, Record::Sent(_)))
        .any(|e| matches!(&e.record, Record::Note(n) if n.contains(IDENTIFIED_NOTE)))
}

/// Whether `step` is the session's echo probe: `GGP 67, 0` followed by its note.
fn is_echo_probe(step: &Step, rest: &[Entry]) -> bool {
    let Step::Exchange {
        instruction: Some(i),
        ..
    } = step
    else {
        return false;
    };
    if (i.command, i.type_, i.motor) != (Opcode::Ggp, 67, 0) {
        return false;
    }
    rest.iter()
        .take_while(|e| !matches!(e.record, Record::Sent(_)))
        .any(|e| matches!(&e.record, Record::Note(n) if n.contains(PROBE_NOTE)))
}

/// Whether the value of `i` depends on when it was read.
pub fn is_live(i: &Instruction, profile: &Profile) -> bool {
    let role = |p: Option<&crate::dialect::tmcl::profile::Param>| {
        p.is_none_or(|p| {
            matches!(
                profile.snapshot.role_of(&p.ident, p.access.write),
                SnapshotRole::Live | SnapshotRole::ReadOnly
            )
        })
    };
    match i.command {
        Opcode::Gap => role(profile.axis_param(i.type_)),
        Opcode::Ggp => role(profile.global_param(i.motor, i.type_)),
        Opcode::Gio => true,
        Opcode::Rfs => i.type_ == 2,
        _ => false,
    }
}

/// Whether the step only reads (so two reads with nothing else between see the same state).
fn only_reads(step: &Step) -> bool {
    match step {
        Step::Exchange {
            instruction: Some(i),
            ..
        } => i.reads_value(),
        Step::Exchange { .. } => false,
        Step::Version { .. } | Step::Comment(_) => true,
    }
}

/// The Rhai script for `steps`. `source` names the transcript in the header; live values are
/// awaited for at most `wait_ms`.
pub fn to_rhai(steps: &[Step], profile: &Profile, source: &str, wait_ms: u64) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "// Replay of the transcript {source}, written by `tmclsh transcript to-rhai`."
    );
    out.push_str(
        "// Each command is sent again and the value it returned is checked. Live values (positions,\n\
         // speeds, switches, inputs) are awaited with wait_until where the transcript read the same\n\
         // value twice in a row; values read while they were changing are left as comments.\n\
         // Run it with: tmclsh run THIS_FILE.rhai [--port PATH | --tcp HOST:PORT]\n\n",
    );
    let mut target: Option<u8> = None;
    for (k, step) in steps.iter().enumerate() {
        match step {
            Step::Comment(text) => {
                let _ = writeln!(out, "// {}", comment(text));
            }
            Step::Version { module, text } => {
                if target != Some(*module) {
                    let _ = writeln!(out, "target({module});");
                    target = Some(*module);
                }
                let _ = writeln!(out, "assert_eq(firmware_version(), {});", rhai_string(text));
            }
            Step::Exchange {
                line,
                instruction,
                status,
                value,
                ..
            } => {
                let note = instruction
                    .and_then(|i| param_name(&i, profile))
                    .map(|n| format!("  // {n}"))
                    .unwrap_or_default();
                let sent = rhai_string(line);
                if !status.is_success() {
                    let _ = writeln!(
                        out,
                        "assert_eq(reply({sent}).status, {});{note}",
                        status.code()
                    );
                } else if instruction.is_some_and(|i| is_live(&i, profile)) {
                    if settled(steps, k) {
                        let _ = writeln!(
                            out,
                            "wait_until(|| send({sent}) == {value}, {wait_ms});{note}"
                        );
                    } else {
                        let _ = writeln!(
                            out,
                            "send({sent});  // read {value}, not checked (it may have been changing){}",
                            note.replace("  //", ",")
                        );
                    }
                } else {
                    let _ = writeln!(out, "assert_eq(send({sent}), {value});{note}");
                }
            }
        }
    }
    out
}

/// Whether the live read at `k` repeats the value of the same read just before it, with only
/// reads in between.
fn settled(steps: &[Step], k: usize) -> bool {
    let Step::Exchange { line, value, .. } = &steps[k] else {
        return false;
    };
    for earlier in steps[..k].iter().rev() {
        if let Step::Exchange {
            line: l, value: v, ..
        } = earlier
        {
            if l == line {
                return v == value;
            }
        }
        if !only_reads(earlier) {
            return false;
        }
    }
    false
}

fn param_name(i: &Instruction, profile: &Profile) -> Option<String> {
    let p = match i.command {
        Opcode::Sap | Opcode::Gap | Opcode::Stap | Opcode::Rsap => profile.axis_param(i.type_),
        Opcode::Sgp | Opcode::Ggp | Opcode::Stgp | Opcode::Rsgp => {
            profile.global_param(i.motor, i.type_)
        }
        _ => None,
    }?;
    Some(p.ident.clone())
}

#[cfg(test)]
mod tests;
