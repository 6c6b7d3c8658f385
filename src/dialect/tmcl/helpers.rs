//! The helper commands of TMCL modules: targets, echo, program control, download and upload,
//! modes.

use std::io::Write;
use std::path::Path;

use crate::dialect::helper::{ArgKind, Helper, Section, helper};
use crate::dialect::session::DialectSession;
use crate::dialect::tmcl::params::write_table;
use crate::dialect::tmcl::program::{self, download, upload};
use crate::dialect::tmcl::protocol::line::address_of;
use crate::dialect::tmcl::protocol::{Instruction, ModuleName, Opcode};
use crate::dialect::tmcl::session::{Echo, TmclExchange, TmclSession};
use crate::session::SessionError;

/// The helpers only TMCL modules have.
pub const HELPERS: &[Helper] = &[
    helper(
        ":echo char|line|none",
        "set the module's echo (global parameter 67 bits 4/5, keeping bit 0)",
        ArgKind::Echo,
        Section::Session,
    ),
    helper(
        ":run [address]",
        "start the module's stored TMCL program (ASCII RUN, or command 129)",
        ArgKind::Address,
        Section::Module,
    ),
    helper(
        ":stop",
        "stop the module's TMCL program (ASCII STOP, or command 128)",
        ArgKind::None,
        Section::Module,
    ),
    helper(
        ":step",
        "execute the program's next instruction (command 130)",
        ArgKind::None,
        Section::Module,
    ),
    helper(
        ":reset",
        "program counter to 0, program stopped (command 131)",
        ArgKind::None,
        Section::Module,
    ),
    helper(
        ":status",
        "application status (135): stopped, running, stepping or reset",
        ArgKind::None,
        Section::Module,
    ),
    helper(
        ":download FILE [--run]",
        "store a program (.tmc source or .bin) in the module, verify it, optionally run it",
        ArgKind::File,
        Section::Module,
    ),
    helper(
        ":upload [FILE.tmc|FILE.bin]",
        "read the stored program back (command 134): print it as source, or write it",
        ArgKind::File,
        Section::Module,
    ),
    helper(
        ":bin",
        "leave ASCII mode; lines are then sent as binary frames (direct mode)",
        ArgKind::None,
        Section::Module,
    ),
    helper(
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
    let usage = || SessionError::Usage(format!("usage: {}", helper.usage));
    match helper.name() {
        "params" => params(session, arg, out),
        "target" => target(session, arg, out),
        "echo" => {
            let echo = Echo::parse(arg).ok_or_else(usage)?;
            let target = session.target();
            let echo = session.set_echo(target, echo)?;
            writeln!(out, "echo: {}", echo.name())?;
            Ok(())
        }
        "run" => run_program(session, arg, out),
        "stop" => stop_program(session, out),
        "step" => control_program(session, Opcode::StepApplication, out),
        "reset" => control_program(session, Opcode::ResetApplication, out),
        "status" => program_status(session, out),
        "download" => {
            let (path, run) = match arg.strip_suffix("--run") {
                Some(path) => (path.trim(), true),
                None => (arg, false),
            };
            if path.is_empty() {
                return Err(usage());
            }
            download_file(session, path, run, out)
        }
        "upload" => {
            let path = Path::new(arg);
            let output = if arg.is_empty() {
                upload::Output::Print
            } else {
                upload::Output::for_file(path)?
            };
            let text = upload::upload_to(session, output, None)?;
            write!(out, "{text}")?;
            Ok(())
        }
        "bin" | "ascii" => switch_mode(session, helper.name() == "ascii", out),
        other => unreachable!("helper table and TMCL dispatch disagree on :{other}"),
    }
}

/// `:params [FILTER]`: the profile's parameters matching the filter.
fn params(session: &TmclSession, arg: &str, out: &mut dyn Write) -> Result<(), SessionError> {
    let rows: Vec<_> = session.profile().matching(arg).collect();
    if rows.is_empty() {
        writeln!(out, "no parameter matches '{arg}'")?;
    } else {
        write_table(&rows, out)?;
    }
    Ok(())
}

/// `:target [N|CHAR]`: the module lines without an address character go to (alone: shows it).
fn target(session: &mut TmclSession, arg: &str, out: &mut dyn Write) -> Result<(), SessionError> {
    if !arg.trim().is_empty() {
        session.set_target(parse_module(arg)?)?;
    }
    let which = session.identity_line();
    writeln!(out, "target: {}, {which}", ModuleName(session.target()))?;
    Ok(())
}

/// `:run [ADDRESS]`: starts the stored program.
fn run_program(
    session: &mut TmclSession,
    arg: &str,
    out: &mut dyn Write,
) -> Result<(), SessionError> {
    let target = session.target();
    let exchange = session
        .run_program(target, parse_address(arg)?)?
        .checked()?;
    report_program(session, &exchange, "started", out)?;
    Ok(())
}

/// `:stop`: stops the program, and warns of motion it leaves going.
fn stop_program(session: &mut TmclSession, out: &mut dyn Write) -> Result<(), SessionError> {
    let target = session.target();
    let exchange = session.stop_program(target)?.checked()?;
    report_program(session, &exchange, "stopped", out)?;
    for warning in program::still_turning(session, target) {
        session.notify(format!("warning: {warning}"));
    }
    Ok(())
}

/// `:step` (130) and `:reset` (131).
fn control_program(
    session: &mut TmclSession,
    command: Opcode,
    out: &mut dyn Write,
) -> Result<(), SessionError> {
    let target = session.target();
    program::control(session, target, Instruction::new(command, 0, 0, 0))?;
    let name = if command == Opcode::StepApplication {
        "step"
    } else {
        "reset"
    };
    let mode = program::mode_text(session, target);
    writeln!(
        out,
        "program {name} done on {}; the module is in {mode} mode",
        ModuleName(target)
    )?;
    Ok(())
}

/// `:status`: the application status (135).
fn program_status(session: &mut TmclSession, out: &mut dyn Write) -> Result<(), SessionError> {
    let target = session.target();
    let exchange = program::control(
        session,
        target,
        Instruction::new(Opcode::ApplicationStatus, 0, 0, 0),
    )?;
    let value = exchange.value().unwrap_or(0);
    let name = program::status_name(value);
    let mode = program::mode_text(session, target);
    writeln!(
        out,
        "program on {}: {name} ({value}); the module is in {mode} mode",
        ModuleName(target)
    )?;
    Ok(())
}

/// `:download FILE [--run]`: loads or assembles the file, stores it, verifies it, maybe runs it.
fn download_file(
    session: &mut TmclSession,
    path: &str,
    run: bool,
    out: &mut dyn Write,
) -> Result<(), SessionError> {
    let profile = session.profile().clone();
    let instructions = download::load(Path::new(path), &profile)?;
    let text = download::download_and_run(session, &instructions, run)?;
    writeln!(out, "{text}")?;
    Ok(())
}

/// `:bin` and `:ascii`: leaves or enters ASCII mode.
fn switch_mode(
    session: &mut TmclSession,
    ascii: bool,
    out: &mut dyn Write,
) -> Result<(), SessionError> {
    let target = session.target();
    let name = ModuleName(target);
    if ascii {
        session.enter_ascii(target)?;
        writeln!(out, "{name} is in ASCII mode")?;
    } else {
        session.leave_ascii(target)?;
        writeln!(
            out,
            "{name} is in binary direct mode: lines go out as binary frames; :ascii returns"
        )?;
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
        "program {verb} on {}; the module is in {mode} mode",
        ModuleName(module)
    )
}

fn parse_module(arg: &str) -> Result<u8, SessionError> {
    let usage = || {
        let not = match arg {
            "" => String::new(),
            arg => format!(", not '{arg}'"),
        };
        SessionError::Usage(format!("usage: :target N|CHAR (1..26 or A..Z){not}"))
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
