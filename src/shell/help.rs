//! `:help` for either dialect: the helper list, a command's usage, the ASCII interface, SMD4
//! addressing, exit codes.

use std::io::{self, Write};

use crate::protocol::Dialect;
use crate::protocol::smd4::{ADDRESSING_HELP, hints};
use crate::session::Session;

use super::helpers;

/// Writes the help on `topic` (empty: the overview).
pub fn write_help(topic: &str, session: &Session, out: &mut dyn Write) -> io::Result<()> {
    let topic = topic.trim().trim_start_matches(':');
    let dialect = session.dialect();
    if topic.is_empty() {
        match dialect {
            Dialect::Tmcl => {
                writeln!(
                    out,
                    "Type TMCL commands as in the TMCL-IDE, e.g. GAP actual_position, 0 or MVP ABS, 0, 1000."
                )?;
                writeln!(
                    out,
                    "Parameter names work in place of numbers; Tab completes, hints show units and ranges."
                )?;
                writeln!(
                    out,
                    "A leading address character reaches another module: CGAP 4, 0.\n"
                )?;
            }
            Dialect::Smd4 => {
                writeln!(
                    out,
                    "Type SMD4 requests, e.g. MOTOR:VMAX (read) or MOTOR:VMAX,2000 (write); @N addresses a drive."
                )?;
                writeln!(
                    out,
                    "Tab completes the hierarchical mnemonics (MOTOR:, SYS:, LIMIT:, BAKE:, BOOST:, COMS:NET:, COMS:SERIAL:).\n"
                )?;
            }
        }
        writeln!(out, "Helper commands:")?;
        for h in helpers::available(dialect) {
            writeln!(out, "  {:<30} {}", h.usage, h.summary)?;
        }
        let more = match dialect {
            Dialect::Tmcl => ":help COMMAND, :help params, :help exit, :help ascii",
            Dialect::Smd4 => ":help MNEMONIC, :help addressing, :help exit",
        };
        return writeln!(out, "\nMore: {more}");
    }
    match (topic.to_ascii_lowercase().as_str(), session) {
        ("exit", _) => {
            writeln!(
                out,
                "Leave with :quit (or quit, exit) or Ctrl-D; the modules go back to the mode they were found in."
            )?;
            writeln!(
                out,
                "Ctrl-C stops a command and the motor; at the prompt it stops the motors this session set moving."
            )?;
            writeln!(
                out,
                "Exit codes: 0 success, 1 device error or failed assertion, 2 refused before sending, 3 connection/timeout/lost link, 130 Ctrl-C."
            )
        }
        ("params", Session::Tmcl(_)) => {
            writeln!(
                out,
                "Parameters are listed by :params [filter]; use their names in SAP/GAP/SGP/GGP lines."
            )
        }
        ("ascii", Session::Tmcl(_)) => {
            writeln!(
                out,
                "ASCII mode (manual 6.6): lines are <address char><command>, replies <host char><module char> <status> <value>."
            )?;
            writeln!(
                out,
                "Only ROL ROR MST MVP SAP GAP STAP RSAP SGP GGP STGP RSGP RFS SIO GIO SAC SCO GCO CCO UF0-UF7, plus BIN RUN STOP."
            )?;
            writeln!(
                out,
                "Echo (GP 67 bits 4/5): char, line or none (:echo). :bin switches to binary frames for the rest."
            )
        }
        ("addressing", Session::Smd4(_)) => writeln!(out, "{ADDRESSING_HELP}"),
        (word, Session::Tmcl(s)) => {
            let profile = s.profile();
            let spec = profile.commands.by_mnemonic(word).or_else(|| {
                word.parse()
                    .ok()
                    .and_then(|n| profile.commands.by_number(n))
            });
            if let Ok(h) = helpers::find(word, dialect) {
                writeln!(out, "{:<30} {}", h.usage, h.summary)
            } else if let Some(spec) = spec {
                writeln!(
                    out,
                    "{} — {} (command {})",
                    spec.usage(),
                    spec.name,
                    spec.number
                )?;
                for k in &spec.keywords {
                    writeln!(out, "  {:<8} {}", k.name, k.meaning)?;
                }
                let place = match (spec.ascii_allowed, spec.direct_mode) {
                    (true, _) => "ASCII and binary direct mode",
                    (false, true) => "binary direct mode only (:bin)",
                    (false, false) => "stand-alone programs only",
                };
                writeln!(out, "  usable in: {place}")
            } else {
                writeln!(out, "no help on '{topic}'; :help lists topics")
            }
        }
        (word, Session::Smd4(s)) => {
            if let Ok(h) = helpers::find(word, dialect) {
                writeln!(out, "{:<30} {}", h.usage, h.summary)
            } else if let Some(spec) = s.spec().commands.get(word) {
                let usage = hints::usage(spec);
                let hint = hints::hint(spec);
                writeln!(out, "{usage}")?;
                writeln!(
                    out,
                    "  {}",
                    hint.strip_prefix(&usage).unwrap_or(&hint).trim_start()
                )?;
                if spec.uncertain && !spec.uncertain_reason.is_empty() {
                    writeln!(out, "  uncertain: {}", spec.uncertain_reason)?;
                }
                Ok(())
            } else {
                writeln!(out, "no help on '{topic}'; :help lists topics")
            }
        }
    }
}
