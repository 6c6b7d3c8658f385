//! SMD4 transcripts that replay: each line sent becomes a `send`/`reply` call of an SMD4 script,
//! and the values the drive answered are checked — real numbers to the significant digits the
//! drive reports (a drive that prints 4 or 5 decimals replays alike), the rest exactly. Flag words
//! are not checked: standby, limit and boost bits follow the moment, not the commands.
//!
//! Settings (read or written) and the firmware version are checked; other queries and live
//! values (positions, speeds, temperatures, flags) are awaited with `wait_until` where the
//! transcript read the same value twice in a row with only reads between, and left unchecked
//! otherwise. Error codes are checked as codes. Multi-line listings are sent, not checked.

use std::fmt::Write as _;

use crate::commission::SnapshotRole;
use crate::dialect::smd4::commission::spec_params;
use crate::dialect::smd4::protocol::{
    Expectation, ReplyShape, Request, Smd4Reply, Smd4Spec, Value, parse_reply,
};

use crate::dialect::replay::parse::{Entry, Record};
use crate::dialect::replay::{ReplayError, comment, reply_after, rhai_string};

/// The session's first note in an SMD4 transcript, which tells one written before transcripts
/// had headers.
pub const OPENED: &str = "SMD4 session opened";

/// One thing the script does.
#[derive(Debug, Clone, PartialEq)]
pub enum Step {
    /// A line sent and the reply it got (`None`: the drive answers nothing, e.g. a broadcast).
    Exchange {
        /// The line as sent, with its address prefix.
        line: String,
        /// The request it parses to.
        request: Request,
        /// The reply.
        response: Option<Smd4Reply>,
    },
    /// Kept as a comment.
    Comment(String),
}

/// The Rhai script replaying an SMD4 transcript; refused when no exchange in it replays.
pub fn script(entries: &[Entry], name: &str, wait_ms: u64) -> Result<String, ReplayError> {
    let spec = Smd4Spec::builtin();
    let steps = steps(entries, spec);
    if !steps.iter().any(|s| matches!(s, Step::Exchange { .. })) {
        return Err(ReplayError::Nothing { dialect: "SMD4" });
    }
    Ok(to_rhai(&steps, spec, name, wait_ms))
}

/// Pairs what was sent with what came back.
pub fn steps(entries: &[Entry], spec: &Smd4Spec) -> Vec<Step> {
    let mut steps = Vec::new();
    for (i, entry) in entries.iter().enumerate() {
        let Record::Sent(bytes) = &entry.record else {
            continue;
        };
        let text = String::from_utf8_lossy(bytes);
        let line = text.trim_end_matches(['\r', '\n']).to_string();
        let Ok(request) = Request::parse(&line) else {
            steps.push(Step::Comment(format!(
                "not replayed (not a request): {line}"
            )));
            continue;
        };
        let command = spec.commands.get(&request.mnemonic);
        let silent = request.is_broadcast() || command.is_some_and(|c| c.no_response);
        let response = match reply_after(&entries[i + 1..]) {
            _ if silent => None,
            None => {
                steps.push(Step::Comment(format!("no reply to {line}")));
                continue;
            }
            Some(bytes) => match reply_to(bytes, &request, spec) {
                Some(response) => Some(response),
                None => {
                    steps.push(Step::Comment(format!("no usable reply to {line}")));
                    continue;
                }
            },
        };
        steps.push(Step::Exchange {
            line,
            request,
            response,
        });
    }
    steps
}

/// The reply to `request` among the received lines (a reply from another drive is skipped).
fn reply_to(bytes: &[u8], request: &Request, spec: &Smd4Spec) -> Option<Smd4Reply> {
    let expect = Expectation::for_request(&spec.commands, request);
    String::from_utf8_lossy(bytes)
        .split(['\r', '\n'])
        .filter_map(|l| parse_reply(l, &expect).ok())
        .find(|r| match (r.address, request.address) {
            (Some(got), Some(wanted)) => got == wanted,
            _ => true,
        })
}

/// How a step's reply is checked.
enum Check {
    /// The error code.
    Error(i32),
    /// Sent; nothing to check.
    Send(&'static str),
    /// The data items as strings (a command the table does not know).
    Strings(Vec<String>),
    /// The decoded values.
    Values,
    /// The decoded values, where they were settled.
    Live,
}

fn check_of(request: &Request, response: &Smd4Reply, spec: &Smd4Spec) -> Check {
    if let Some(error) = &response.error {
        return Check::Error(error.code.code());
    }
    let Some(command) = spec.commands.get(&request.mnemonic) else {
        return Check::Strings(response.data_strings());
    };
    match &command.reply {
        ReplyShape::MultiLine => return Check::Send("a listing, not checked"),
        ReplyShape::None | ReplyShape::Literal(_) => return Check::Send(""),
        _ if response.data.is_empty() => return Check::Send(""),
        _ => {}
    }
    if !request.args.is_empty() || command.mnemonic == "SYS:FW" {
        return Check::Values;
    }
    let setting = spec_params(spec)
        .into_iter()
        .find(|p| p.name == command.mnemonic)
        .is_some_and(|p| matches!(p.role, SnapshotRole::Setting | SnapshotRole::Manual));
    if setting { Check::Values } else { Check::Live }
}

/// The Rhai script for `steps`; live values are awaited for at most `wait_ms`.
pub fn to_rhai(steps: &[Step], spec: &Smd4Spec, source: &str, wait_ms: u64) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "// Replay of the SMD4 transcript {source}, written by `tmclsh transcript to-rhai`."
    );
    out.push_str(
        "// Each line is sent again and the values the drive answered are checked: real numbers to\n\
         // the digits the drive reports, the rest exactly; flag words are not checked. Live values\n\
         // (positions, speeds, temperatures) are awaited with wait_until where the transcript read\n\
         // the same value twice in a row; values read while they were changing are not checked.\n\
         // Run it with: tmclsh run THIS_FILE.rhai --protocol smd4 [--port PATH | --tcp HOST:PORT]\n\n",
    );
    let tolerance = 0.5 * 10f64.powi(1 - spec.snapshot.float_digits.max(1) as i32);
    out.push_str(&CHECK.replace("TOLERANCE", &rhai_float(tolerance)));
    for (k, step) in steps.iter().enumerate() {
        let (line, request, response) = match step {
            Step::Comment(text) => {
                let _ = writeln!(out, "// {}", comment(text));
                continue;
            }
            Step::Exchange {
                line,
                request,
                response,
            } => (line, request, response),
        };
        let sent = rhai_string(line);
        let Some(response) = response else {
            let _ = writeln!(out, "send({sent});  // no reply expected");
            continue;
        };
        let want = values(response);
        match check_of(request, response, spec) {
            Check::Error(code) => {
                let _ = writeln!(out, "assert_eq(reply({sent}).error, {code});");
            }
            Check::Send("") => {
                let _ = writeln!(out, "send({sent});");
            }
            Check::Send(note) => {
                let _ = writeln!(out, "send({sent});  // {note}");
            }
            Check::Strings(items) => {
                let items: Vec<String> = items.iter().map(|s| rhai_string(s)).collect();
                let _ = writeln!(out, "assert_eq(send({sent}), [{}]);", items.join(", "));
            }
            Check::Values => {
                let _ = writeln!(out, "assert_eq(check({sent}, {want}), \"\");");
            }
            Check::Live if settled(steps, k) => {
                let _ = writeln!(
                    out,
                    "wait_until(|| check({sent}, {want}) == \"\", {wait_ms});"
                );
            }
            Check::Live => {
                let _ = writeln!(
                    out,
                    "send({sent});  // read {want}, not checked (it may have been changing)"
                );
            }
        }
    }
    out
}

/// The helper every replay script starts with.
const CHECK: &str = r#"// "" when LINE answers the values WANT (numbers to the drive's digits), else what differs.
fn check(line, want) {
    let r = reply(line);
    if r.error != () {
        return `${line}: error ${r.error}, the transcript had ${want}`;
    }
    let got = r.values;
    let differs = `${line}: got ${got}, the transcript had ${want}`;
    if got.len() != want.len() {
        return differs;
    }
    for i in 0..want.len() {
        let g = got[i];
        let w = want[i];
        if type_of(w) == "f64" && type_of(g) == "f64" {
            let scale = if w.abs() > g.abs() { w.abs() } else { g.abs() };
            if (g - w).abs() > scale * TOLERANCE {
                return differs;
            }
        } else if type_of(g) != type_of(w) || g != w {
            return differs;
        }
    }
    ""
}

"#;

/// Whether the read at `k` repeats the values of the same read just before it, with only reads
/// (lines without arguments) in between.
fn settled(steps: &[Step], k: usize) -> bool {
    let Step::Exchange {
        line,
        response: Some(response),
        ..
    } = &steps[k]
    else {
        return false;
    };
    for earlier in steps[..k].iter().rev() {
        let Step::Exchange {
            line: l,
            request,
            response: r,
        } = earlier
        else {
            continue;
        };
        if l == line {
            return r.as_ref().is_some_and(|r| values(r) == values(response));
        }
        if !request.args.is_empty() || r.is_none() {
            return false;
        }
    }
    false
}

/// The reply's values as a Rhai array literal, decoded as the script's `reply().values` decodes
/// them: integers, real numbers, booleans, named values as their number, the rest as strings.
fn values(response: &Smd4Reply) -> String {
    let items: Vec<String> = response
        .data
        .iter()
        .map(|item| match &item.value {
            Value::Int(i) => i.to_string(),
            Value::Uint(u) if i64::try_from(*u).is_ok() => u.to_string(),
            Value::Float(f) => rhai_float(*f),
            Value::Bool(b) => b.to_string(),
            Value::Named { number, .. } => number.to_string(),
            _ => rhai_string(&item.raw),
        })
        .collect();
    format!("[{}]", items.join(", "))
}

/// A Rhai float literal (always with a decimal point).
fn rhai_float(x: f64) -> String {
    let text = format!("{x:?}");
    if text.contains('.') {
        return text;
    }
    match text.find('e') {
        Some(at) => format!("{}.0{}", &text[..at], &text[at..]),
        None => format!("{text}.0"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dialect::replay::parse::parse;
    use crate::dialect::replay::recognise;

    /// What recognising a transcript without headers takes it for: SMD4 by its session note.
    fn is_smd4(entries: &[Entry]) -> bool {
        recognise(entries).unwrap().dialect == &crate::dialect::smd4::DIALECT
    }

    const LOG: &str = r#"2026-01-01T00:00:00.000Z -- SMD4 session opened on simulated SMD4 (built-in)
2026-01-01T00:00:00.001Z tx "MOTOR:VMAX,2000\r\n" ; to SMD4
2026-01-01T00:00:00.002Z rx "0x0888,0x0000,2.0000E+03,2.0000E+03\r\n" ; sflags 0x0888
2026-01-01T00:00:00.003Z tx "SYS:MODE\r\n" ; to SMD4
2026-01-01T00:00:00.004Z rx "0x0888,0x0000,1 (Remote)\r\n" ; sflags 0x0888
2026-01-01T00:00:00.005Z tx "MOTOR:RES,7\r\n" ; to SMD4
2026-01-01T00:00:00.006Z rx "0x0888,0x0000,-2 (Argument validation)\r\n" ; error -2
2026-01-01T00:00:00.007Z tx "MOTOR:RUNR,300\r\n" ; to SMD4
2026-01-01T00:00:00.008Z rx "0x0808,0x0000,1\r\n" ; sflags 0x0808
2026-01-01T00:00:00.009Z tx "MOTOR:PACT\r\n" ; to SMD4
2026-01-01T00:00:00.010Z rx "0x0808,0x0000,120.50\r\n" ; sflags 0x0808
2026-01-01T00:00:01.009Z tx "MOTOR:PACT\r\n" ; to SMD4
2026-01-01T00:00:01.010Z rx "0x0888,0x0000,300.00\r\n" ; sflags 0x0888
2026-01-01T00:00:01.011Z tx "SYS:FLAGS\r\n" ; to SMD4
2026-01-01T00:00:01.012Z rx "0x0888,0x0000,1\r\n" ; sflags 0x0888
2026-01-01T00:00:01.013Z tx "MOTOR:PACT\r\n" ; to SMD4
2026-01-01T00:00:01.014Z rx "0x0888,0x0000,300.00\r\n" ; sflags 0x0888
2026-01-01T00:00:01.015Z tx "SYS:FW\r\n" ; to SMD4
2026-01-01T00:00:01.016Z rx "0x0888,0x0000,24044.12\r\n" ; sflags 0x0888
2026-01-01T00:00:01.017Z tx "@0MOTOR:STOP\r\n" ; to @0
2026-01-01T00:00:01.018Z tx "MOTOR:VACT\r\n" ; to SMD4
2026-01-01T00:00:02.018Z -- no reply from SMD4
2026-01-01T00:00:02.019Z -- session closed
"#;

    #[test]
    fn line_breaks_in_sent_bytes_stay_inside_comments() {
        let log = "2026-01-01T00:00:00.000Z -- SMD4 session opened on simulated SMD4 (built-in)\n\
                   2026-01-01T00:00:00.001Z tx \"@5MOTOR:STOP\\rsend(\\\"MOTOR:RUNR,900\\\");\\r\\n\" ; to @5\n";
        let entries = parse(log).unwrap();
        let spec = Smd4Spec::builtin();
        let script = to_rhai(&steps(&entries, spec), spec, "t.log", 5000);
        let lines: Vec<&str> = script.lines().filter(|l| l.contains("RUNR")).collect();
        assert_eq!(lines.len(), 1, "{script}");
        assert!(
            lines[0].starts_with("// not replayed (not a request): @5MOTOR:STOP\\u{d}send("),
            "{script}"
        );
    }

    #[test]
    fn an_smd4_transcript_becomes_checks_of_values_codes_and_settled_reads() {
        let entries = parse(LOG).unwrap();
        assert!(is_smd4(&entries));
        let spec = Smd4Spec::builtin();
        let script = to_rhai(&steps(&entries, spec), spec, "t.log", 5000);
        let body: Vec<&str> = script
            .lines()
            .skip_while(|l| l.trim() != "\"\"")
            .skip(3)
            .collect();
        assert_eq!(
            body,
            [
                "assert_eq(check(\"MOTOR:VMAX,2000\", [2000.0, 2000.0]), \"\");",
                "assert_eq(check(\"SYS:MODE\", [1]), \"\");",
                "assert_eq(reply(\"MOTOR:RES,7\").error, -2);",
                "send(\"MOTOR:RUNR,300\");",
                "send(\"MOTOR:PACT\");  // read [120.5], not checked (it may have been changing)",
                "send(\"MOTOR:PACT\");  // read [300.0], not checked (it may have been changing)",
                "send(\"SYS:FLAGS\");",
                "wait_until(|| check(\"MOTOR:PACT\", [300.0]) == \"\", 5000);",
                "assert_eq(check(\"SYS:FW\", [\"24044.12\"]), \"\");",
                "send(\"@0MOTOR:STOP\");  // no reply expected",
                "// no reply to MOTOR:VACT",
            ],
            "{script}"
        );
        assert!(script.contains("scale * 5.0e-5"), "{script}");
    }

    #[test]
    fn a_tmcl_transcript_is_not_taken_for_an_smd4_one() {
        let log =
            "2026-01-01T00:00:00.000Z -- session opened on simulated TMCM-142 bus (built-in)\n";
        assert!(!is_smd4(&parse(log).unwrap()));
    }

    #[test]
    fn float_literals_always_have_a_point() {
        assert_eq!(rhai_float(2000.0), "2000.0");
        assert_eq!(rhai_float(0.5), "0.5");
        assert_eq!(rhai_float(1e-7), "1.0e-7");
    }
}
