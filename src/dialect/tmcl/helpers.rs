//! The helper commands of TMCL modules: targets, echo, program control, download, modes.

use std::io::Write;
use std::path::Path;

use crate::dialect::helper::{ArgKind, Helper, Section, helper};
use crate::dialect::session::DialectSession;
use crate::dialect::tmcl::params::write_table;
use crate::dialect::tmcl::program::{self, download};
use crate::dialect::tmcl::protocol::Instruction;
use crate::dialect::tmcl::protocol::line::{address_char, address_of};
use crate::dialect::tmcl::session::{Echo, TmclExchange, TmclSession};
use crate::session::SessionError;

/// The helpers only TMCL modules have.
pub const HELPERS: &[Helper] = &[
    helper(
        "echo",
        ":echo char|line|none",
        "set the module's echo (global parameter 67 bits 4/5, keeping bit 0)",
        ArgKind::Echo,
        Section::Session,
    ),
    helper(
        "run",
        ":run [address]",
        "start the module's stored TMCL program (ASCII RUN, or command 129)",
        ArgKind::Address,
        Section::Module,
    ),
    helper(
        "stop",
        ":stop",
        "stop the module's TMCL program (ASCII STOP, or command 128)",
        ArgKind::None,
        Section::Module,
    ),
    helper(
        "step",
        ":step",
        "execute the program's next instruction (command 130)",
        ArgKind::None,
        Section::Module,
    ),
    helper(
        "reset",
        ":reset",
        "program counter to 0, program stopped (command 131)",
        ArgKind::None,
        Section::Module,
    ),
    helper(
        "status",
        ":status",
        "application status (135): stopped, running, stepping or reset",
        ArgKind::None,
        Section::Module,
    ),
    helper(
        "download",
        ":download FILE [--run]",
        "store a program (.tmc source or .bin) in the module, verify it, optionally run it",
        ArgKind::File,
        Section::Module,
    ),
    helper(
        "bin",
        ":bin",
        "leave ASCII mode; lines are then sent as binary frames (direct mode)",
        ArgKind::None,
        Section::Module,
    ),
    helper(
        "ascii",
        ":ascii",
        "enter ASCII mode again (command 139)",
        ArgKind::None,
        Section::Module,
    ),
];

/// Runs one TMCL helper.
pub fn run(
    session: &mut TmclSession,
    helper: &Helper,
    arg: &str,
    out: &mut dyn Write,
) -> Result<(), SessionError> {
    let target = session.target();
    let c = address_char(target).unwrap_or('?');
    match helper.name {
        "params" => {
            let profile = session.profile().clone();
            let rows: Vec<_> = profile.matching(arg).collect();
            if rows.is_empty() {
                writeln!(out, "no parameter matches '{arg}'")?;
            } else {
                write_table(&rows, out)?;
            }
        }
        "target" => {
            let module = parse_module(arg)?;
            session.set_target(module)?;
            writeln!(
                out,
                "target: module {} ({})",
                module,
                address_char(module).unwrap_or('?')
            )?;
        }
        "echo" => {
            let echo = Echo::parse(arg)
                .ok_or_else(|| SessionError::Usage(format!("usage: {}", helper.usage)))?;
            let echo = session.set_echo(target, echo)?;
            writeln!(out, "echo: {}", echo.name())?;
        }
        "run" => {
            let exchange = session
                .run_program(target, parse_address(arg)?)?
                .checked()?;
            report_program(session, &exchange, "started", out)?;
        }
        "stop" => {
            let exchange = session.stop_program(target)?.checked()?;
            report_program(session, &exchange, "stopped", out)?;
            for warning in program::still_turning(session, target) {
                session.notify(format!("warning: {warning}"));
            }
        }
        "step" | "reset" | "status" => {
            let command = match helper.name {
                "step" => 130,
                "reset" => 131,
                _ => 135,
            };
            let exchange = program::control(session, target, Instruction::new(command, 0, 0, 0))?;
            let mode = program::mode_text(session, target);
            match helper.name {
                "status" => {
                    let value = exchange.value().unwrap_or(0);
                    let name = program::status_name(value);
                    writeln!(
                        out,
                        "program on module {c}: {name} ({value}); the module is in {mode} mode"
                    )?
                }
                name => writeln!(
                    out,
                    "program {name} done on module {c}; the module is in {mode} mode"
                )?,
            }
        }
        "download" => {
            let (path, run) = match arg.strip_suffix("--run") {
                Some(path) => (path.trim(), true),
                None => (arg, false),
            };
            if path.is_empty() {
                return Err(SessionError::Usage(format!("usage: {}", helper.usage)));
            }
            let profile = session.profile().clone();
            let instructions = download::load(Path::new(path), &profile)?;
            let text = download::download_and_run(session, &instructions, run)?;
            writeln!(out, "{text}")?;
        }
        "bin" => {
            session.leave_ascii(target)?;
            writeln!(
                out,
                "module {c} is in binary direct mode: lines go out as binary frames (:ascii returns)"
            )?;
        }
        "ascii" => {
            session.enter_ascii(target)?;
            writeln!(out, "module {c} is in ASCII mode")?;
        }
        other => unreachable!("helper table and TMCL dispatch disagree on :{other}"),
    }
    Ok(())
}

fn report_program(
    session: &TmclSession,
    exchange: &TmclExchange,
    verb: &str,
    out: &mut dyn Write,
) -> std::io::Result<()> {
    let module = exchange.module;
    let mode = program::mode_text(session, module);
    writeln!(
        out,
        "program {verb} on module {}; the module is in {mode} mode",
        address_char(module).unwrap_or('?')
    )
}

fn parse_module(arg: &str) -> Result<u8, SessionError> {
    let usage = || {
        SessionError::Usage(format!(
            "usage: :target N|CHAR (1..26 or A..Z), not '{arg}'"
        ))
    };
    if let Ok(n) = arg.parse::<u8>() {
        return (1..=26).contains(&n).then_some(n).ok_or_else(usage);
    }
    let mut chars = arg.chars();
    match (chars.next(), chars.next()) {
        (Some(c), None) => address_of(c).ok_or_else(usage),
        _ => Err(usage()),
    }
}

fn parse_address(arg: &str) -> Result<Option<i32>, SessionError> {
    if arg.is_empty() {
        return Ok(None);
    }
    arg.parse::<i32>()
        .ok()
        .filter(|a| *a >= 0)
        .map(Some)
        .ok_or_else(|| {
            SessionError::Usage(format!(
                "usage: :run [address], address a number, not '{arg}'"
            ))
        })
}
