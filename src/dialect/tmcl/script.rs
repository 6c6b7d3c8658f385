//! The TMCL device functions of scripts. Every call becomes the same request a typed line would,
//! through the same session (validation, echo, timeout, transcript). Names and argument order are
//! a contract (TMCL order: parameter, motor/bank, value).

use std::cell::RefCell;
use std::rc::Rc;

use rhai::{Dynamic, Engine, INT, Map};

use crate::dialect::tmcl::asm::{self, LoadError};
use crate::dialect::tmcl::profile::Profile;
use crate::dialect::tmcl::protocol::line::address_of;
use crate::dialect::tmcl::protocol::{Instruction, Opcode, Status};
use crate::dialect::tmcl::session::{TmclExchange, TmclReply, TmclSession};

use crate::script::common::duration;
use crate::script::failure::{Fallible, device, refused, thrown};
use crate::script::registry::ScriptFn;
use crate::script::sandbox::{READ_LIMIT, Sandbox};
use crate::script::volatile;
use crate::script::waiting;

/// The functions [`register`] adds, with signature and help (a test checks the list against
/// the engine).
pub const FUNCTIONS: &[ScriptFn] = &[
    ScriptFn {
        signature: "send(line) -> int",
        help: "sends a line as typed in the shell; returns the reply's value, throws on an error status",
    },
    ScriptFn {
        signature: "reply(line) -> #{status, value, ok, raw}",
        help: "sends a line as typed; returns the whole reply, never throws on a device status",
    },
    ScriptFn {
        signature: "gap(param, motor) -> int",
        help: "reads an axis parameter (GAP), given by number or name",
    },
    ScriptFn {
        signature: "sap(param, motor, value)",
        help: "sets an axis parameter (SAP)",
    },
    ScriptFn {
        signature: "stap(param, motor)",
        help: "stores an axis parameter in EEPROM (STAP)",
    },
    ScriptFn {
        signature: "rsap(param, motor)",
        help: "restores an axis parameter from EEPROM (RSAP)",
    },
    ScriptFn {
        signature: "ggp(param, bank) -> int",
        help: "reads a global parameter (GGP), given by number or name",
    },
    ScriptFn {
        signature: "sgp(param, bank, value)",
        help: "sets a global parameter (SGP)",
    },
    ScriptFn {
        signature: "stgp(param, bank)",
        help: "stores a global parameter in EEPROM (STGP)",
    },
    ScriptFn {
        signature: "rsgp(param, bank)",
        help: "restores a global parameter from EEPROM (RSGP)",
    },
    ScriptFn {
        signature: "mvp_abs(motor, position)",
        help: "moves to an absolute position (MVP ABS)",
    },
    ScriptFn {
        signature: "mvp_rel(motor, offset)",
        help: "moves by an offset from the target position (MVP REL)",
    },
    ScriptFn {
        signature: "mvp_coord(motor, n)",
        help: "moves to stored coordinate n (MVP COORD)",
    },
    ScriptFn {
        signature: "ror(motor, velocity)",
        help: "rotates right at a velocity (ROR)",
    },
    ScriptFn {
        signature: "rol(motor, velocity)",
        help: "rotates left at a velocity (ROL)",
    },
    ScriptFn {
        signature: "mst(motor)",
        help: "stops the motor (MST)",
    },
    ScriptFn {
        signature: "rfs_start(motor)",
        help: "starts the reference search (RFS START)",
    },
    ScriptFn {
        signature: "rfs_stop(motor)",
        help: "stops the reference search (RFS STOP)",
    },
    ScriptFn {
        signature: "rfs_status(motor) -> int",
        help: "the reference search's status: 0 when it has ended (RFS STATUS)",
    },
    ScriptFn {
        signature: "wait_pos(motor, timeout_ms)",
        help: "waits until the motor reaches its target position; a timeout is exit 3",
    },
    ScriptFn {
        signature: "sio(port, bank, value)",
        help: "sets an output (SIO)",
    },
    ScriptFn {
        signature: "gio(port, bank) -> int",
        help: "reads an input or output (GIO)",
    },
    ScriptFn {
        signature: "sco(n, motor, position)",
        help: "stores coordinate n (SCO)",
    },
    ScriptFn {
        signature: "gco(n, motor) -> int",
        help: "reads coordinate n (GCO)",
    },
    ScriptFn {
        signature: "target(address)",
        help: "addresses another module on the bus: 1..26 or a letter (\"B\")",
    },
    ScriptFn {
        signature: "firmware_version() -> string",
        help: "the firmware version string (command 136, in binary mode and back)",
    },
    ScriptFn {
        signature: "download(path) -> int",
        help: "stores a program (source or program file) in the module, verified; returns how many instructions",
    },
    ScriptFn {
        signature: "program_status() -> int",
        help: "the stand-alone program's status (135): 0 stopped, 1 running, 2 stepping, 3 reset",
    },
    ScriptFn {
        signature: "run_program()",
        help: "starts the stored program",
    },
    ScriptFn {
        signature: "stop_program()",
        help: "stops the stored program",
    },
];

/// The session a script talks through.
pub type Shared = Rc<RefCell<TmclSession>>;

/// Registers the TMCL functions over `session`.
pub fn register(engine: &mut Engine, session: &Shared, sandbox: &Rc<Sandbox>) {
    register_lines(engine, session);
    register_parameters(engine, session, Table::Axis);
    register_parameters(engine, session, Table::Global);
    register_motion(engine, session);
    register_io(engine, session);
    register_module(engine, session);
    register_programs(engine, session, sandbox);
}

/// `send(line)` and `reply(line)`: a line as typed.
fn register_lines(engine: &mut Engine, session: &Shared) {
    let s = session.clone();
    volatile!(engine, "send", move |line: &str| value_of(checked(
        s.borrow_mut().exchange_line(line)
    )?));
    let s = session.clone();
    volatile!(engine, "reply", move |line: &str| device(
        s.borrow_mut().exchange_line(line)
    )
    .map(reply_map));
}

/// Which parameters a family of functions reaches.
#[derive(Debug, Clone, Copy)]
enum Table {
    /// Axis parameters, by motor: GAP, SAP, STAP, RSAP.
    Axis,
    /// Global parameters, by bank: GGP, SGP, STGP, RSGP.
    Global,
}

impl Table {
    /// The function names and commands of get, set, store and restore.
    fn functions(self) -> [(&'static str, Opcode); 4] {
        match self {
            Table::Axis => [
                ("gap", Opcode::Gap),
                ("sap", Opcode::Sap),
                ("stap", Opcode::Stap),
                ("rsap", Opcode::Rsap),
            ],
            Table::Global => [
                ("ggp", Opcode::Ggp),
                ("sgp", Opcode::Sgp),
                ("stgp", Opcode::Stgp),
                ("rsgp", Opcode::Rsgp),
            ],
        }
    }

    /// What the second argument is.
    fn index(self) -> &'static str {
        match self {
            Table::Axis => "motor",
            Table::Global => "bank",
        }
    }

    /// The number of a parameter given by number or name; a global parameter named must be in
    /// bank `index`.
    fn number(self, session: &Shared, param: &Dynamic, index: INT) -> Fallible<u8> {
        match self {
            Table::Axis => axis(session, param),
            Table::Global => global(session, param, index),
        }
    }
}

/// The get, set, store and restore functions of `table` (TMCL order: parameter, motor/bank,
/// value).
fn register_parameters(engine: &mut Engine, session: &Shared, table: Table) {
    let [(get, get_command), (set, set_command), store, restore] = table.functions();
    let what = table.index();
    let s = session.clone();
    volatile!(engine, get, move |param: Dynamic, index: INT| {
        let p = table.number(&s, &param, index)?;
        request(&s, get_command, p, byte(what, index)?, 0)
    });
    let s = session.clone();
    volatile!(engine, set, move |param: Dynamic,
                                 index: INT,
                                 value: INT| {
        let p = table.number(&s, &param, index)?;
        request(
            &s,
            set_command,
            p,
            byte(what, index)?,
            word("value", value)?,
        )
        .map(|_| ())
    });
    for (name, command) in [store, restore] {
        let s = session.clone();
        volatile!(engine, name, move |param: Dynamic, index: INT| {
            let p = table.number(&s, &param, index)?;
            request(&s, command, p, byte(what, index)?, 0).map(|_| ())
        });
    }
}

/// Moves, stops and reference searches.
fn register_motion(engine: &mut Engine, session: &Shared) {
    // (name, command, type): MVP and the rotations take a motor and a value.
    for (name, command, type_) in [
        ("mvp_abs", Opcode::Mvp, 0),
        ("mvp_rel", Opcode::Mvp, 1),
        ("mvp_coord", Opcode::Mvp, 2),
        ("ror", Opcode::Ror, 0),
        ("rol", Opcode::Rol, 0),
    ] {
        let s = session.clone();
        volatile!(engine, name, move |motor: INT, value: INT| {
            let (motor, value) = (byte("motor", motor)?, word("value", value)?);
            request(&s, command, type_, motor, value).map(|_| ())
        });
    }
    // (name, command, type): these take a motor only.
    for (name, command, type_) in [
        ("mst", Opcode::Mst, 0),
        ("rfs_start", Opcode::Rfs, 0),
        ("rfs_stop", Opcode::Rfs, 1),
    ] {
        let s = session.clone();
        volatile!(engine, name, move |motor: INT| {
            request(&s, command, type_, byte("motor", motor)?, 0).map(|_| ())
        });
    }
    let s = session.clone();
    volatile!(engine, "rfs_status", move |motor: INT| request(
        &s,
        Opcode::Rfs,
        2,
        byte("motor", motor)?,
        0
    ));
    let s = session.clone();
    volatile!(engine, "wait_pos", move |motor: INT, timeout_ms: INT| {
        let motor = byte("motor", motor)?;
        let what = format!("motor {motor} to reach its target position");
        waiting::until(&what, duration(timeout_ms)?, || {
            Ok(request(&s, Opcode::Gap, 8, motor, 0)? == 1)
        })
    });
}

/// Inputs and outputs (SIO, GIO) and stored coordinates (SCO, GCO).
fn register_io(engine: &mut Engine, session: &Shared) {
    let s = session.clone();
    volatile!(engine, "sio", move |port: INT, bank: INT, value: INT| {
        let (port, bank) = (byte("port", port)?, byte("bank", bank)?);
        request(&s, Opcode::Sio, port, bank, word("value", value)?).map(|_| ())
    });
    let s = session.clone();
    volatile!(engine, "gio", move |port: INT, bank: INT| request(
        &s,
        Opcode::Gio,
        byte("port", port)?,
        byte("bank", bank)?,
        0
    ));
    let s = session.clone();
    volatile!(engine, "sco", move |n: INT, motor: INT, position: INT| {
        let (n, motor) = (byte("coordinate", n)?, byte("motor", motor)?);
        request(&s, Opcode::Sco, n, motor, word("position", position)?).map(|_| ())
    });
    let s = session.clone();
    volatile!(engine, "gco", move |n: INT, motor: INT| request(
        &s,
        Opcode::Gco,
        byte("coordinate", n)?,
        byte("motor", motor)?,
        0
    ));
}

/// Which module the functions talk to, and what it is.
fn register_module(engine: &mut Engine, session: &Shared) {
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
            x.request(target, Instruction::new(Opcode::FirmwareVersion, 0, 0, 0))
        }))?;
        Ok(match exchange.reply {
            TmclReply::Version(text) => text,
            _ => exchange.raw,
        })
    });
}

/// Programs in the module's memory: download (through the sandbox), status, run and stop.
fn register_programs(engine: &mut Engine, session: &Shared, sandbox: &Rc<Sandbox>) {
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
fn request(session: &Shared, command: Opcode, type_: u8, motor: u8, value: i32) -> Fallible<INT> {
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
        .map_err(|e| thrown(e.into()))
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
        .map_err(|e| thrown(e.into()))?;
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
        .map_err(|t| {
            refused(format!(
                "a parameter is a number or a name, not {}",
                crate::article::with_article(t)
            ))
        })
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
        .map_err(|r| thrown(r.into()))?;
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
