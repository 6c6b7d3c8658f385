//! The SMD4 device functions of scripts: `send` returns the data items as strings (throwing on
//! an error code), `reply` the whole reply as a map (with the items also decoded, `values`, and
//! the following lines of a multi-line reply, `lines`),
//! `flags()`, `wait_standby(timeout_ms)`, `target(address)`, and `parse_number(item)`, which reads
//! a number in every spelling drives use (`1.0000E+03`, `1.0000+03`, `1000.00`, `0x0888`). Ctrl-C or a failure while the motor runs sends MOTOR:STOP (the session
//! tracks what the script set moving).

use std::cell::RefCell;
use std::rc::Rc;

use rhai::{Array, Dynamic, Engine, INT, Map};

use crate::dialect::smd4::protocol::{DataItem, MAX_ADDRESS, Smd4Reply, Value, items};
use crate::dialect::smd4::session::{Smd4Exchange, Smd4Session};

use crate::script::common::duration;
use crate::script::failure::{Fallible, device, refused, runtime};
use crate::script::registry::ScriptFn;
use crate::script::volatile;
use crate::script::waiting;

/// The functions [`register`] adds, with signature and help (a test checks the list against
/// the engine).
pub const FUNCTIONS: &[ScriptFn] = &[
    ScriptFn {
        signature: "send(line) -> [string]",
        help: "sends a line as typed; returns the data items, throws on an error code",
    },
    ScriptFn {
        signature: "reply(line) -> #{sflags, eflags, data, error, ok, raw}",
        help: "sends a line as typed; returns the whole reply, never throws on an error code",
    },
    ScriptFn {
        signature: "flags() -> #{sflags, eflags, standby, status, errors}",
        help: "reads SYS:FLAGS with each flag named",
    },
    ScriptFn {
        signature: "wait_standby(timeout_ms)",
        help: "waits until the motor stands still (standby flag); a timeout is exit 3",
    },
    ScriptFn {
        signature: "parse_number(item) -> float",
        help: "a reply's data item as a number",
    },
    ScriptFn {
        signature: "target(address)",
        help: "addresses another drive on the bus (0..247)",
    },
];

/// The session a script talks through.
pub type Shared = Rc<RefCell<Smd4Session>>;

/// Registers the SMD4 functions over `session`.
pub fn register(engine: &mut Engine, session: &Shared) {
    let s = session.clone();
    volatile!(engine, "send", move |line: &str| -> Fallible<Array> {
        let exchange = device(
            s.borrow_mut()
                .exchange_line(line)
                .and_then(Smd4Exchange::checked),
        )?;
        Ok(exchange
            .reply
            .map(|r| r.data_strings().into_iter().map(Dynamic::from).collect())
            .unwrap_or_default())
    });
    let s = session.clone();
    volatile!(engine, "reply", move |line: &str| -> Fallible<Map> {
        let exchange = device(s.borrow_mut().exchange_line(line))?;
        Ok(reply_map(&exchange))
    });
    let s = session.clone();
    volatile!(engine, "flags", move || -> Fallible<Map> {
        let response = read_flags(&s)?;
        let spec = s.borrow().spec();
        let names = |table: &crate::dialect::smd4::protocol::FlagTable, word: u16| -> Array {
            table
                .decode(word)
                .into_iter()
                .map(|b| Dynamic::from(b.name))
                .collect()
        };
        let mut map = Map::new();
        map.insert("sflags".into(), INT::from(response.sflags.0).into());
        map.insert("eflags".into(), INT::from(response.eflags.0).into());
        map.insert("standby".into(), response.sflags.standby().into());
        map.insert(
            "status".into(),
            names(&spec.sflags, response.sflags.0).into(),
        );
        map.insert(
            "errors".into(),
            names(&spec.eflags, response.eflags.0).into(),
        );
        Ok(map)
    });
    let s = session.clone();
    volatile!(engine, "wait_standby", move |timeout_ms: INT| {
        waiting::until(
            "the motor to stand still (standby flag)",
            duration(timeout_ms)?,
            || Ok(read_flags(&s)?.sflags.standby()),
        )
    });
    volatile!(
        engine,
        "parse_number",
        |item: &str| -> Fallible<rhai::FLOAT> {
            items::guess(item.trim())
                .as_f64()
                .ok_or_else(|| runtime(format!("'{item}' is not a number")))
        }
    );
    let s = session.clone();
    volatile!(engine, "target", move |address: INT| -> Fallible<()> {
        let address = u32::try_from(address)
            .ok()
            .filter(|a| *a <= MAX_ADDRESS)
            .ok_or_else(|| refused(format!("SMD4 address {address} is not in 0..{MAX_ADDRESS}")))?;
        s.borrow_mut().set_address(Some(address));
        Ok(())
    });
}

/// A fresh reply carrying the flags (SYS:FLAGS).
fn read_flags(session: &Shared) -> Fallible<Smd4Reply> {
    let exchange = device(
        session
            .borrow_mut()
            .exchange_line("SYS:FLAGS")
            .and_then(Smd4Exchange::checked),
    )?;
    exchange.reply.ok_or_else(|| {
        refused("SYS:FLAGS got no reply (a broadcast address is set; use target(N))")
    })
}

fn reply_map(exchange: &Smd4Exchange) -> Map {
    let mut map = Map::new();
    let response = exchange.reply.as_ref();
    map.insert(
        "sflags".into(),
        INT::from(response.map_or(0, |r| r.sflags.0)).into(),
    );
    map.insert(
        "eflags".into(),
        INT::from(response.map_or(0, |r| r.eflags.0)).into(),
    );
    let data: Array = response
        .map(|r| r.data_strings().into_iter().map(Dynamic::from).collect())
        .unwrap_or_default();
    map.insert("data".into(), data.into());
    let values: Array = response
        .map(|r| r.data.iter().map(value).collect())
        .unwrap_or_default();
    map.insert("values".into(), values.into());
    let lines: Array = response
        .map(|r| r.lines.iter().cloned().map(Dynamic::from).collect())
        .unwrap_or_default();
    map.insert("lines".into(), lines.into());
    let error = response
        .and_then(|r| r.error.as_ref())
        .map_or(Dynamic::UNIT, |e| INT::from(e.code.code()).into());
    map.insert("error".into(), error);
    map.insert("ok".into(), exchange.ok().into());
    map.insert("raw".into(), exchange.raw().into());
    map
}

/// A data item as its decoded value: numbers as numbers (`1.0000+03` is 1000.0), `0`/`1` of BOOL
/// items as booleans, named values (`1 (Remote)`) as their number, anything else as received.
fn value(item: &DataItem) -> Dynamic {
    match &item.value {
        Value::Int(i) => Dynamic::from(*i as INT),
        Value::Uint(u) => INT::try_from(*u).map_or_else(|_| item.raw.clone().into(), Dynamic::from),
        Value::Float(f) => Dynamic::from(*f as rhai::FLOAT),
        Value::Bool(b) => Dynamic::from(*b),
        Value::Named { number, .. } => Dynamic::from(*number as INT),
        _ => item.raw.clone().into(),
    }
}
