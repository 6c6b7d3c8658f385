//! The echo dialect's script function: `echo(text)` sends `ECHO text` and returns what came back.

use std::cell::RefCell;
use std::rc::Rc;

use rhai::{Engine, FuncRegistration};
use tmclsh::dialect::{DialectSession, Reply};
use tmclsh::script::failure::{Fallible, device};
use tmclsh::script::registry::ScriptFn;

use super::protocol::request;
use super::session::EchoSession;

/// The functions [`register`] adds, for `:help`, `run --help` and the other dialects' sessions.
pub const FUNCTIONS: &[ScriptFn] = &[ScriptFn {
    signature: "echo(text) -> string",
    help: "sends ECHO text; returns what came back",
}];

/// Registers `echo` over `session`, volatile so the optimiser never calls it while compiling.
pub fn register(engine: &mut Engine, session: &Rc<RefCell<EchoSession>>) {
    let s = session.clone();
    let echo = move |text: &str| -> Fallible<String> {
        let reply = s.borrow_mut().execute(&request(text));
        Ok(device(reply.and_then(Reply::checked))?.shown)
    };
    FuncRegistration::new("echo")
        .with_volatility(true)
        .register_into_engine(engine, echo);
}
