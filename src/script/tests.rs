use std::sync::Arc;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Instant;

use crate::clock::ManualClock;
use crate::dialect::tmcl::profile::Profile;
use crate::dialect::tmcl::sim::{Bus, BusOptions};
use crate::link::{Link, LinkError};
use crate::session::SessionOptions;
use crate::sim::inprocess::SimLink;

use super::*;
use crate::dialect::tmcl::session::TmclSession;
use crate::shell::run_source;

/// A link that counts what is sent through it.
struct Counting {
    inner: SimLink,
    sent: Arc<AtomicUsize>,
}

impl Link for Counting {
    fn send(&mut self, bytes: &[u8]) -> Result<(), LinkError> {
        self.sent.fetch_add(1, Ordering::SeqCst);
        self.inner.send(bytes)
    }
    fn recv(&mut self, buf: &mut [u8], deadline: Instant) -> Result<usize, LinkError> {
        self.inner.recv(buf, deadline)
    }
    fn describe(&self) -> String {
        self.inner.describe()
    }
}

fn session() -> (TmclSession, Arc<AtomicUsize>) {
    let profile = Profile::builtin();
    let bus = Bus::new(profile.clone(), BusOptions::default());
    let link = SimLink::new(Box::new(bus), Arc::new(ManualClock::new()));
    let sent = Arc::new(AtomicUsize::new(0));
    let counting = Counting {
        inner: link,
        sent: sent.clone(),
    };
    let session =
        TmclSession::open(Box::new(counting), profile, SessionOptions::default(), None).unwrap();
    (session, sent)
}

#[test]
fn device_functions_never_run_while_compiling_even_at_full_optimisation() {
    let (session, sent) = session();
    let shared = Rc::new(RefCell::new(session));
    let mut engine = base_engine(
        &Limits::default(),
        None,
        Arc::default(),
        &(Rc::new(print_to_stdout) as PrintSink),
        never(),
    );
    let sandbox = Rc::new(Sandbox::new([std::path::Path::new(".")], false));
    crate::dialect::tmcl::script::register(&mut engine, &shared, &sandbox);
    engine.set_optimization_level(OptimizationLevel::Full);
    let before = sent.load(Ordering::SeqCst);
    let ast = engine
        .compile("const X = gap(4, 0); let y = sap(6, 0, 3); if false { mst(0) } X + gap(6, 0)")
        .unwrap();
    assert_eq!(
        sent.load(Ordering::SeqCst),
        before,
        "nothing sent while compiling"
    );
    let value: rhai::INT = engine.eval_ast(&ast).unwrap();
    assert_eq!(value, 1_000_003);
    assert!(
        sent.load(Ordering::SeqCst) >= before + 3,
        "the calls run when the script runs"
    );
}

#[test]
fn run_source_gives_the_session_back_and_reports_positions() {
    let (session, _) = session();
    let (session, result) = run_source(
        "t.rhai",
        "sap(6, 0, 4);\nassert_eq(gap(6, 0), 5);",
        &[],
        Box::new(session),
        Limits::default(),
    );
    let report = result.unwrap_err();
    assert_eq!(report.exit, Exit::DeviceError);
    assert_eq!(
        report.message,
        "t.rhai:2:1: assert_eq failed: left = 4, right = 5"
    );
    let Ok(mut session) = session.into_any().downcast::<TmclSession>() else {
        panic!("TMCL session back")
    };
    assert_eq!(
        session.exchange_line("GAP 6, 0").unwrap().value(),
        Some(4),
        "the session still works"
    );
}

#[test]
fn errors_inside_script_functions_keep_their_exit_code() {
    let (session, _) = session();
    let source = "fn check(v) { assert_eq(v, 2); }\ncheck(1);";
    let (_, result) = run_source("f.rhai", source, &[], Box::new(session), Limits::default());
    let report = result.unwrap_err();
    assert_eq!(report.exit, Exit::DeviceError);
    assert!(
        report
            .message
            .contains("assert_eq failed: left = 1, right = 2"),
        "{}",
        report.message
    );
    assert!(
        report.message.contains("(in function check)"),
        "{}",
        report.message
    );
}

#[test]
fn print_goes_to_the_sink_given_escaped_like_all_output() {
    let (session, _) = session();
    let printed = Rc::new(RefCell::new(Vec::<String>::new()));
    let lines = printed.clone();
    let script = Script::from_source(
        "p.rhai",
        "print(\"pos \" + gap(1, 0));\nprint(\"a\\x1b]0;owned\\x07b\\rc\\nd\");",
        &[],
        Limits::default(),
    )
    .print_to(Rc::new(move |line: &str| {
        lines.borrow_mut().push(line.to_string())
    }));
    let (_, result) = crate::dialect::DialectSession::run_script(Box::new(session), &script);
    result.unwrap();
    assert_eq!(
        *printed.borrow(),
        ["pos 0", "a\\x1B]0;owned\\x07b\\rc\nd"],
        "captured, nothing on stdout, device-like text escaped and a line feed kept"
    );
}

/// The names of the functions `register` adds to an engine, beyond those every script has.
fn registered(register: impl FnOnce(&mut Engine)) -> Vec<String> {
    let print = Rc::new(print_to_stdout) as PrintSink;
    let base = function_names(&base_engine(
        &Limits::default(),
        None,
        Arc::default(),
        &print,
        never(),
    ));
    let mut engine = base_engine(&Limits::default(), None, Arc::default(), &print, never());
    register(&mut engine);
    let mut added: Vec<String> = function_names(&engine)
        .into_iter()
        .filter(|name| !base.contains(name))
        .collect();
    added.sort();
    added
}

fn sorted(functions: &[registry::ScriptFn]) -> Vec<String> {
    let mut names: Vec<String> = functions.iter().map(|f| f.name().to_string()).collect();
    names.sort();
    names
}

#[test]
fn each_dialect_lists_the_functions_it_registers() {
    use crate::dialect::{Opening, Purpose, smd4, tmcl};
    let (session, _) = session();
    let shared = Rc::new(RefCell::new(session));
    let sandbox = Rc::new(Sandbox::new([std::path::Path::new(".")], false));
    let tmcl_names = registered(|engine| tmcl::script::register(engine, &shared, &sandbox));
    assert_eq!(tmcl_names, sorted(tmcl::script::FUNCTIONS));
    let config = (smd4::DIALECT.configure)(None).unwrap();
    let link = SimLink::new(config.simulator(), Arc::new(ManualClock::new()));
    let opened = config
        .open(Opening {
            link: Box::new(link),
            options: SessionOptions::default(),
            transcript: None,
            flags: None,
            purpose: Purpose::Scan,
        })
        .unwrap();
    let session = *opened
        .into_any()
        .downcast::<smd4::session::Smd4Session>()
        .unwrap();
    let shared = Rc::new(RefCell::new(session));
    let smd4_names = registered(|engine| smd4::script::register(engine, &shared));
    assert_eq!(smd4_names, sorted(smd4::script::FUNCTIONS));
}

#[test]
fn a_caught_failure_tells_its_exit_code() {
    let (session, _) = session();
    let printed = Rc::new(RefCell::new(Vec::<String>::new()));
    let lines = printed.clone();
    let source = r#"
        try { send("GAP 200, 0") } catch (e) { print(`${e.exit} ${e}`) }
        try { gap(1, 300) } catch (e) { print(`${e.exit}`) }
    "#;
    let script = Script::from_source("c.rhai", source, &[], Limits::default()).print_to(Rc::new(
        move |line: &str| lines.borrow_mut().push(line.to_string()),
    ));
    let (_, result) = crate::dialect::DialectSession::run_script(Box::new(session), &script);
    result.unwrap();
    let printed = printed.borrow();
    assert_eq!(printed.len(), 2, "{printed:?}");
    assert!(
        printed[0].starts_with("1 ") && printed[0].contains("status 3"),
        "a device error status: {printed:?}"
    );
    assert_eq!(printed[1], "2", "refused before sending");
}

#[test]
fn the_registry_lists_every_function_every_script_has_and_no_other() {
    let (session, _) = session();
    let shared = Rc::new(RefCell::new(session));
    let sandbox = Rc::new(Sandbox::new([std::path::Path::new(".")], false));
    let print = Rc::new(print_to_stdout) as PrintSink;
    let mut engine = base_engine(&Limits::default(), None, Arc::default(), &print, never());
    common::register(&mut engine, Rc::from(""), |_| {});
    blocks::register(&mut engine, blocks::Record::default(), Rc::new(|| {}));
    commission::register(&mut engine, &shared, &sandbox);
    // Registered into the engine itself, not Rhai's standard packages (documented by Rhai);
    // `to_string` is Rhai's own conversion, given to a caught `Failure` too.
    let mut added: Vec<String> = engine
        .gen_fn_signatures(false)
        .iter()
        .filter_map(|signature| signature.split('(').next())
        .map(str::trim)
        .filter(|name| name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_'))
        .filter(|name| *name != "to_string")
        .map(str::to_string)
        .collect();
    added.sort();
    added.dedup();
    assert_eq!(added, sorted(registry::SHARED));
}
