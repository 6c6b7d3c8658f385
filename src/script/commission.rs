//! The commissioning functions of scripts: `snapshot_save`, `snapshot_diff`, `snapshot_restore`
//! (TOML files) and `record_csv` (CSV files), each reaching files only through the script's
//! [`Sandbox`]. The same functions serve TMCL modules and SMD4 drives; values come back as
//! integers, real numbers or strings as the module has them.

use std::cell::RefCell;
use std::rc::Rc;
use std::time::Duration;

use rhai::{Array, Dynamic, Engine, INT, Map};

use crate::clock::SystemClock;
use crate::commission::actions::{self, RestoreOptions};
use crate::commission::diff::{self, Side};
use crate::commission::record::{self, CsvFile};
use crate::commission::{ParamDevice, ParamValue, Snapshot};

use super::common::duration;
use super::failure::{Fallible, device, refused, thrown};
use super::sandbox::{Kind, READ_LIMIT, Sandbox};

/// Registers the commissioning functions over `session` (any dialect whose session is a
/// [`ParamDevice`]), reaching files through `sandbox`.
pub fn register<S: ParamDevice + 'static>(
    engine: &mut Engine,
    session: &Rc<RefCell<S>>,
    sandbox: &Rc<Sandbox>,
) {
    let (s, b) = (session.clone(), sandbox.clone());
    volatile!(engine, "snapshot_save", move |path: &str| snapshot_save(
        &s, &b, path
    ));
    let (s, b) = (session.clone(), sandbox.clone());
    volatile!(engine, "snapshot_diff", move |path: &str| snapshot_diff(
        &s, &b, path
    ));
    let (s, b) = (session.clone(), sandbox.clone());
    volatile!(engine, "snapshot_restore", move |path: &str| restore(
        &s, &b, path, false, false
    ));
    let (s, b) = (session.clone(), sandbox.clone());
    volatile!(
        engine,
        "snapshot_restore",
        move |path: &str, store: bool| restore(&s, &b, path, store, false)
    );
    let (s, b) = (session.clone(), sandbox.clone());
    volatile!(
        engine,
        "snapshot_restore",
        move |path: &str, store: bool, force: bool| restore(&s, &b, path, store, force)
    );
    let (s, b) = (session.clone(), sandbox.clone());
    volatile!(
        engine,
        "record_csv",
        move |path: &str, params: Dynamic, interval_ms: INT, duration_ms: INT| {
            record_csv(&s, &b, path, &params, interval_ms, duration_ms)
        }
    );
}

/// `snapshot_save(path)`: every readable parameter to a new snapshot file; how many were saved.
fn snapshot_save<S: ParamDevice>(
    session: &Rc<RefCell<S>>,
    sandbox: &Sandbox,
    path: &str,
) -> Fallible<INT> {
    // Checked before the module is read, so a refused path costs no time.
    sandbox
        .check_writable(path, Kind::Snapshot)
        .map_err(|r| thrown(r.into()))?;
    let mut session = session.borrow_mut();
    let mut write = |snapshot: &Snapshot| {
        let mut file = sandbox
            .create(path, Kind::Snapshot)
            .map_err(|r| crate::session::SessionError::Usage(r.to_string()))?;
        std::io::Write::write_all(&mut file, snapshot.to_toml().as_bytes())?;
        Ok(())
    };
    let snapshot = device(actions::save_with(
        &mut *session,
        path,
        &mut write,
        &mut std::io::sink(),
    ))?;
    Ok(snapshot.entries.len() as INT)
}

/// `snapshot_diff(path)`: the differences between the file and the module, one map each.
fn snapshot_diff<S: ParamDevice>(
    session: &Rc<RefCell<S>>,
    sandbox: &Sandbox,
    path: &str,
) -> Fallible<Array> {
    let file = load(sandbox, path)?;
    let mut session = session.borrow_mut();
    let comparison = device(diff::with_device(&file, &mut *session))?;
    Ok(comparison
        .differences
        .iter()
        .map(|d| {
            let mut map = Map::new();
            map.insert("name".into(), d.name.clone().into());
            map.insert("place".into(), d.place.clone().into());
            map.insert("file".into(), side(&d.left));
            map.insert("current".into(), side(&d.right));
            map.insert("unit".into(), d.unit.clone().into());
            Dynamic::from_map(map)
        })
        .collect())
}

/// `record_csv(path, params, interval_ms, duration_ms)`: samples to a new CSV file; how many.
fn record_csv<S: ParamDevice>(
    session: &Rc<RefCell<S>>,
    sandbox: &Sandbox,
    path: &str,
    params: &Dynamic,
    interval_ms: INT,
    duration_ms: INT,
) -> Fallible<INT> {
    let interval = positive(interval_ms, "interval")?;
    let length = duration(duration_ms)?;
    let mut session = session.borrow_mut();
    let params = names(params)?
        .iter()
        .map(|n| session.find(n).map_err(|e| thrown(e.into())))
        .collect::<Fallible<Vec<_>>>()?;
    let plan = record::Plan {
        params,
        interval,
        duration: Some(length),
    };
    let columns: Vec<String> = plan.params.iter().map(|p| p.name.clone()).collect();
    let file = sandbox
        .create(path, Kind::Recording)
        .map_err(|r| thrown(r.into()))?;
    let mut csv = device(CsvFile::start(file, &columns))?;
    let recording = device(record::record(
        &mut *session,
        &plan,
        &SystemClock::new(),
        &mut || false,
        &mut |sample| csv.append(sample),
    ))?;
    Ok(recording.samples.len() as INT)
}

/// Reads and parses the snapshot at `path` through the sandbox; errors never quote the file.
fn load(sandbox: &Sandbox, path: &str) -> Fallible<Snapshot> {
    let bytes = sandbox
        .read(path, READ_LIMIT)
        .map_err(|r| thrown(r.into()))?;
    let text = std::str::from_utf8(&bytes).map_err(|_| {
        refused(format!(
            "{path} is not a tmclsh snapshot: it is not UTF-8 text"
        ))
    })?;
    Snapshot::parse(text).map_err(|e| {
        refused(format!(
            "{path} is not a tmclsh snapshot ({}; `tmclsh snapshot diff {path} {path}` shows it)",
            e.redacted()
        ))
    })
}

/// Writes the snapshot back (verifying each value), storing when `store`, despite the problems
/// that allow it when `force`; returns how many parameters were written and verified.
fn restore<S: ParamDevice>(
    session: &RefCell<S>,
    sandbox: &Sandbox,
    path: &str,
    store: bool,
    force: bool,
) -> Fallible<INT> {
    let snapshot = load(sandbox, path)?;
    let options = RestoreOptions {
        store,
        dry_run: false,
        force,
        redact: true,
    };
    let mut session = session.borrow_mut();
    let outcome = device(actions::restore_snapshot(
        &mut *session,
        &snapshot,
        path,
        options,
        &mut |_: &str| Ok(true),
        &mut std::io::sink(),
    ))?;
    Ok(outcome.verified.len() as INT)
}

fn positive(ms: INT, what: &str) -> Fallible<Duration> {
    let d = duration(ms)?;
    if d.is_zero() {
        return Err(refused(format!("the {what} must be at least 1 ms")));
    }
    Ok(d)
}

/// Parameter names from an array of strings or a comma-separated string.
fn names(value: &Dynamic) -> Fallible<Vec<String>> {
    if let Some(array) = value.clone().try_cast::<Array>() {
        return array
            .into_iter()
            .map(|v| {
                v.into_immutable_string()
                    .map(|s| s.trim().to_string())
                    .map_err(|t| {
                        refused(format!(
                            "a parameter name is a string, not {}",
                            crate::article::with_article(t)
                        ))
                    })
            })
            .collect();
    }
    let text = value.clone().into_immutable_string().map_err(|t| {
        refused(format!(
            "parameters are names (an array or \"a,b\"), not {}",
            crate::article::with_article(t)
        ))
    })?;
    let list: Vec<String> = text
        .split(',')
        .map(str::trim)
        .filter(|n| !n.is_empty())
        .map(String::from)
        .collect();
    if list.is_empty() {
        return Err(refused("name at least one parameter"));
    }
    Ok(list)
}

fn side(side: &Side) -> Dynamic {
    match side.value() {
        Some(ParamValue::Int(i)) => (*i as INT).into(),
        Some(ParamValue::Float(f)) => (*f as rhai::FLOAT).into(),
        Some(ParamValue::Text(t)) => t.clone().into(),
        None => Dynamic::UNIT,
    }
}
