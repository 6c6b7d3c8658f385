//! The TMCL device functions of scripts. Every call becomes the same request a typed line would,
//! through the same session (validation, echo, timeout, transcript). Names and argument order are
//! a contract (TMCL order: parameter, motor/bank, value).

use std::cell::RefCell;
use std::rc::Rc;

use rhai::{Dynamic, Engine, INT, Map};

use crate::dialect::tmcl::asm::{self, LoadError};
use crate::dialect::tmcl::profile::Profile;
use crate::dialect::tmcl::protocol::line::address_of;
use crate::dialect::tmcl::protocol::{Instruction, Status};
use crate::dialect::tmcl::session::{TmclExchange, TmclReply, TmclSession};

use crate::script::common::duration;
use crate::script::failure::{Fallible, device, refused};
use crate::script::sandbox::{READ_LIMIT, Sandbox};
use crate::script::volatile;
use crate::script::waiting;

/// The session a script talks through.
pub type Shared = Rc<RefCell<TmclSession>>;

/// Registers the TMCL functions over `session`.
pub fn register(engine: &mut Engine, session: &Shared, sandbox: &Rc<Sandbox>) {
    let s = session.clone();
    volatile!(engine, "send", move |line: &str| value_of(checked(
        s.borrow_mut().exchange_line(line)
    )?));
    let s = session.clone();
    volatile!(engine, "reply", move |line: &str| device(
        s.borrow_mut().exchange_line(line)
    )
    .map(reply_map));

    let s = session.clone();
    volatile!(engine, "gap", move |param: Dynamic, motor: INT| {
        let p = axis(&s, &param)?;
        request(&s, 6, p, byte("motor", motor)?, 0)
    });
    let s = session.clone();
    volatile!(
        engine,
        "sap",
        move |param: Dynamic, motor: INT, value: INT| {
            let p = axis(&s, &param)?;
            request(&s, 5, p, byte("motor", motor)?, word("value", value)?).map(|_| ())
        }
    );
    let s = session.clone();
    volatile!(engine, "stap", move |param: Dynamic, motor: INT| {
        let p = axis(&s, &param)?;
        request(&s, 7, p, byte("motor", motor)?, 0).map(|_| ())
    });
    let s = session.clone();
    volatile!(engine, "rsap", move |param: Dynamic, motor: INT| {
        let p = axis(&s, &param)?;
        request(&s, 8, p, byte("motor", motor)?, 0).map(|_| ())
    });
    let s = session.clone();
    volatile!(engine, "ggp", move |param: Dynamic, bank: INT| {
        let p = global(&s, &param, bank)?;
        request(&s, 10, p, byte("bank", bank)?, 0)
    });
    let s = session.clone();
    volatile!(
        engine,
        "sgp",
        move |param: Dynamic, bank: INT, value: INT| {
            let p = global(&s, &param, bank)?;
            request(&s, 9, p, byte("bank", bank)?, word("value", value)?).map(|_| ())
        }
    );
    let s = session.clone();
    volatile!(engine, "stgp", move |param: Dynamic, bank: INT| {
        let p = global(&s, &param, bank)?;
        request(&s, 11, p, byte("bank", bank)?, 0).map(|_| ())
    });
    let s = session.clone();
    volatile!(engine, "rsgp", move |param: Dynamic, bank: INT| {
        let p = global(&s, &param, bank)?;
        request(&s, 12, p, byte("bank", bank)?, 0).map(|_| ())
    });

    // Motion: (name, command, type).
    for (name, command, type_) in [
        ("mvp_abs", 4, 0),
        ("mvp_rel", 4, 1),
        ("mvp_coord", 4, 2),
        ("ror", 1, 0),
        ("rol", 2, 0),
    ] {
        let s = session.clone();
        volatile!(engine, name, move |motor: INT, value: INT| {
            request(
                &s,
                command,
                type_,
                byte("motor", motor)?,
                word("value", value)?,
            )
            .map(|_| ())
        });
    }
    let s = session.clone();
    volatile!(engine, "mst", move |motor: INT| request(
        &s,
        3,
        0,
        byte("motor", motor)?,
        0
    )
    .map(|_| ()));
    for (name, type_) in [("rfs_start", 0), ("rfs_stop", 1)] {
        let s = session.clone();
        volatile!(engine, name, move |motor: INT| request(
            &s,
            13,
            type_,
            byte("motor", motor)?,
            0
        )
        .map(|_| ()));
    }
    let s = session.clone();
    volatile!(engine, "rfs_status", move |motor: INT| request(
        &s,
        13,
        2,
        byte("motor", motor)?,
        0
    ));

    let s = session.clone();
    volatile!(engine, "sio", move |port: INT, bank: INT, value: INT| {
        request(
            &s,
            14,
            byte("port", port)?,
            byte("bank", bank)?,
            word("value", value)?,
        )
        .map(|_| ())
    });
    let s = session.clone();
    volatile!(engine, "gio", move |port: INT, bank: INT| request(
        &s,
        15,
        byte("port", port)?,
        byte("bank", bank)?,
        0
    ));
    let s = session.clone();
    volatile!(engine, "sco", move |n: INT, motor: INT, position: INT| {
        request(
            &s,
            30,
            byte("coordinate", n)?,
            byte("motor", motor)?,
            word("position", position)?,
        )
        .map(|_| ())
    });
    let s = session.clone();
    volatile!(engine, "gco", move |n: INT, motor: INT| request(
        &s,
        31,
        byte("coordinate", n)?,
        byte("motor", motor)?,
        0
    ));

    let s = session.clone();
    volatile!(engine, "wait_pos", move |motor: INT, timeout_ms: INT| {
        let motor = byte("motor", motor)?;
        let what = format!("motor {motor} to reach its target position");
        waiting::until(&what, duration(timeout_ms)?, || {
            Ok(request(&s, 6, 8, motor, 0)? == 1)
        })
    });

    let s = session.clone();
    volatile!(engine, "target", move |address: Dynamic| {
        let module = module_address(&address)?;
        device(s.borrow_mut().set_target(module))
    });
    let s = session.clone();
    volatile!(engine, "firmware_version", move || -> Fallible<String> {
        // Command 136 exists only in binary mode: switch there and back transparently.
        let target = s.borrow().target();
        let mut session = s.borrow_mut();
        let exchange = checked(session.in_binary(target, |x| {
            x.request(target, Instruction::new(136, 0, 0, 0))
        }))?;
        Ok(match exchange.reply {
            TmclReply::Version(text) => text,
            _ => exchange.raw,
        })
    });
    let s = session.clone();
    let files = sandbox.clone();
    volatile!(engine, "download", move |path: &str| -> Fallible<INT> {
        let instructions = program(&files, path, &s.borrow().profile().clone())?;
        let mut session = s.borrow_mut();
        let target = session.target();
        device(crate::dialect::tmcl::program::download(
            &mut session,
            target,
            &instructions,
            |_, _| {},
        ))?;
        Ok(instructions.len() as INT)
    });
    let s = session.clone();
    volatile!(engine, "program_status", move || -> Fallible<INT> {
        let mut session = s.borrow_mut();
        let target = session.target();
        device(crate::dialect::tmcl::program::status(&mut session, target)).map(INT::from)
    });
    let s = session.clone();
    volatile!(engine, "run_program", move || {
        let target = s.borrow().target();
        checked(s.borrow_mut().run_program(target, None)).map(|_| ())
    });
    let s = session.clone();
    volatile!(engine, "stop_program", move || {
        let target = s.borrow().target();
        checked(s.borrow_mut().stop_program(target)).map(|_| ())
    });
}

/// Sends one instruction to the target module; returns the reply value, throwing on errors.
fn request(session: &Shared, command: u8, type_: u8, motor: u8, value: i32) -> Fallible<INT> {
    let target = session.borrow().target();
    let instruction = Instruction::new(command, type_, motor, value);
    value_of(checked(session.borrow_mut().request(target, instruction))?)
}

fn checked(result: Result<TmclExchange, crate::session::SessionError>) -> Fallible<TmclExchange> {
    device(result.and_then(TmclExchange::checked))
}

fn value_of(exchange: TmclExchange) -> Fallible<INT> {
    match exchange.reply {
        TmclReply::Status { value, .. } => Ok(value.into()),
        _ => Ok(0),
    }
}

fn reply_map(exchange: TmclExchange) -> Map {
    let (status, value) = match &exchange.reply {
        TmclReply::Status { status, value } => (*status, *value),
        _ => (Status::Ok, 0),
    };
    let mut map = Map::new();
    map.insert("status".into(), INT::from(status.code()).into());
    map.insert("value".into(), INT::from(value).into());
    map.insert("ok".into(), exchange.ok().into());
    let raw = match &exchange.reply {
        TmclReply::Version(text) => text.clone(),
        _ => exchange.raw.clone(),
    };
    map.insert("raw".into(), raw.into());
    map
}

/// An axis parameter given by number or name.
fn axis(session: &Shared, param: &Dynamic) -> Fallible<u8> {
    if let Ok(n) = param.as_int() {
        return byte("parameter", n);
    }
    let name = name_of(param)?;
    let s = session.borrow();
    s.profile()
        .find_axis(&name)
        .map(|p| p.number)
        .map_err(|e| refused(e.to_string()))
}

/// A global parameter given by number or name (a name must be in `bank`).
fn global(session: &Shared, param: &Dynamic, bank: INT) -> Fallible<u8> {
    if let Ok(n) = param.as_int() {
        return byte("parameter", n);
    }
    let name = name_of(param)?;
    let s = session.borrow();
    let p = s
        .profile()
        .find_global(&name)
        .map_err(|e| refused(e.to_string()))?;
    if INT::from(p.bank()) != bank {
        return Err(refused(format!(
            "global parameter '{}' is in bank {}, not bank {bank}",
            p.ident,
            p.bank()
        )));
    }
    Ok(p.number)
}

fn name_of(param: &Dynamic) -> Fallible<String> {
    param
        .clone()
        .into_immutable_string()
        .map(|s| s.to_string())
        .map_err(|t| refused(format!("a parameter is a number or a name, not a {t}")))
}

fn module_address(address: &Dynamic) -> Fallible<u8> {
    if let Ok(n) = address.as_int() {
        return u8::try_from(n)
            .ok()
            .filter(|a| (1..=26).contains(a))
            .ok_or_else(|| refused(format!("module address {n} is not in 1..26")));
    }
    let text = name_of(address)?;
    let mut chars = text.chars();
    match (chars.next().and_then(address_of), chars.next()) {
        (Some(a), None) => Ok(a),
        _ => Err(refused(format!(
            "'{text}' is not a module address (1..26 or A..Z)"
        ))),
    }
}

fn byte(what: &str, n: INT) -> Fallible<u8> {
    u8::try_from(n).map_err(|_| refused(format!("{what} {n} does not fit in 0..255")))
}

fn word(what: &str, n: INT) -> Fallible<i32> {
    i32::try_from(n).map_err(|_| refused(format!("{what} {n} does not fit in a 32-bit value")))
}

/// The program at `path` (a program file or TMCL source), read through the sandbox. Errors say
/// where the first problem is, never what the file holds: the file may not be the script's.
fn program(sandbox: &Sandbox, path: &str, profile: &Profile) -> Fallible<Vec<Instruction>> {
    let bytes = sandbox
        .read(path, READ_LIMIT)
        .map_err(|r| refused(r.to_string()))?;
    asm::load_program(&bytes, path, profile).map_err(|e| {
        let place = match &e {
            LoadError::Source(errors) => errors.errors.first().map(|first| {
                format!(
                    " (the first problem is at line {}, column {})",
                    first.at.line, first.at.column
                )
            }),
            _ => None,
        };
        refused(format!(
            "{path} is not a program for the {}{}; `tmclsh asm {path}` shows why",
            profile.module,
            place.unwrap_or_default()
        ))
    })
}
