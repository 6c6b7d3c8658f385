//! The commissioning functions of scripts — the only file access a script has, and only to the
//! path it names: `snapshot_save`, `snapshot_diff`, `snapshot_restore` (TOML files) and
//! `record_csv` (CSV files). The extension is required, so a script cannot overwrite arbitrary
//! files with a snapshot or a recording. The same functions serve TMCL modules and SMD4 drives;
//! values come back as integers, real numbers or strings as the module has them.

use std::cell::RefCell;
use std::path::{Path, PathBuf};
use std::rc::Rc;
use std::time::Duration;

use rhai::{Array, Dynamic, Engine, INT, Map};

use crate::commission::actions::{self, RestoreOptions};
use crate::commission::diff::{self, Side};
use crate::commission::record::{self, CsvFile};
use crate::commission::{ParamDevice, ParamValue, Snapshot};
use crate::sim::clock::SystemClock;

use super::common::duration;
use super::failure::{Fallible, device, refused};

/// Registers the commissioning functions over `session` (any dialect whose session is a
/// [`ParamDevice`]).
pub fn register<S: ParamDevice + 'static>(engine: &mut Engine, session: &Rc<RefCell<S>>) {
    let s = session.clone();
    volatile!(
        engine,
        "snapshot_save",
        move |path: &str| -> Fallible<INT> {
            let path = allowed(path, "toml")?;
            let mut session = s.borrow_mut();
            let snapshot = device(actions::save(&mut *session, &path, &mut std::io::sink()))?;
            Ok(snapshot.entries.len() as INT)
        }
    );
    let s = session.clone();
    volatile!(
        engine,
        "snapshot_diff",
        move |path: &str| -> Fallible<Array> {
            let path = allowed(path, "toml")?;
            let file = device(Snapshot::load(&path))?;
            let mut session = s.borrow_mut();
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
    );
    let s = session.clone();
    volatile!(engine, "snapshot_restore", move |path: &str| restore(
        &s, path, false
    ));
    let s = session.clone();
    volatile!(
        engine,
        "snapshot_restore",
        move |path: &str, store: bool| { restore(&s, path, store) }
    );
    let s = session.clone();
    volatile!(engine, "record_csv", move |path: &str,
                                          params: Dynamic,
                                          interval_ms: INT,
                                          duration_ms: INT|
          -> Fallible<INT> {
        let path = allowed(path, "csv")?;
        let interval = positive(interval_ms, "interval")?;
        let length = duration(duration_ms)?;
        let mut session = s.borrow_mut();
        let params = names(&params)?
            .iter()
            .map(|n| session.find(n).map_err(refused))
            .collect::<Fallible<Vec<_>>>()?;
        let plan = record::Plan {
            params,
            interval,
            duration: Some(length),
        };
        let columns: Vec<String> = plan.params.iter().map(|p| p.name.clone()).collect();
        let mut csv = device(CsvFile::create(&path, &columns))?;
        let recording = device(record::record(
            &mut *session,
            &plan,
            &SystemClock::new(),
            &mut || false,
            &mut |sample| csv.append(sample),
        ))?;
        Ok(recording.samples.len() as INT)
    });
}

/// Writes the snapshot back (verifying each value), storing to EEPROM when `store`; returns how
/// many parameters were written and verified.
fn restore<S: ParamDevice>(session: &RefCell<S>, path: &str, store: bool) -> Fallible<INT> {
    let path = allowed(path, "toml")?;
    let options = RestoreOptions {
        store,
        dry_run: false,
    };
    let mut session = session.borrow_mut();
    let outcome = device(actions::restore(
        &mut *session,
        &path,
        options,
        &mut |_: &str| Ok(true),
        &mut std::io::sink(),
    ))?;
    Ok(outcome.verified as INT)
}

/// The path, when it ends in `.extension`; scripts touch no other files.
fn allowed(path: &str, extension: &str) -> Fallible<PathBuf> {
    let p = Path::new(path);
    let ok = p
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case(extension));
    if ok {
        Ok(p.to_path_buf())
    } else {
        Err(refused(format!(
            "'{path}' must be a .{extension} file (scripts may only write snapshots and recordings)"
        )))
    }
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
                    .map_err(|t| refused(format!("a parameter name is a string, not a {t}")))
            })
            .collect();
    }
    let text = value.clone().into_immutable_string().map_err(|t| {
        refused(format!(
            "parameters are names (an array or \"a,b\"), not a {t}"
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
