//! The commissioning helper commands of the shell: `:snapshot`, `:scan`, `:watch`, `:record` and
//! `:plot`. The REPL and `-c`/stdin lines share them; the ones that need keys (`:watch`, and
//! `:record` without a duration) need a terminal.

use std::cell::Cell;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::time::Duration;

use crate::clock::SystemClock;
use crate::commission::actions::{self, RestoreOptions};
use crate::commission::device::{ParamDevice, ParamRef};
use crate::commission::plot;
use crate::commission::record::{self, CsvFile, Recording};
use crate::commission::scan::parse_addresses;
use crate::commission::watch::{self, Key, Screen};
use crate::dialect::DialectSession;
use crate::session::SessionError;

use super::helpers::HelperError;
use super::terminal::{TerminalScreen, interactive, width};

/// What the helpers remember between commands.
#[derive(Debug, Default)]
pub struct State {
    /// The last recording made with `:record`, for `:plot`.
    pub last_recording: Option<(PathBuf, Recording)>,
}

/// Runs `:NAME ARG` for the commissioning helpers.
pub fn helper(
    session: &mut dyn DialectSession,
    state: &mut State,
    name: &str,
    arg: &str,
    out: &mut dyn Write,
) -> Result<(), SessionError> {
    match name {
        "snapshot" => snapshot(session.param_device(), arg, out),
        "scan" => scan(session, arg, out),
        "watch" => {
            let example = session.dialect().param_example;
            watch(session.param_device(), arg, example, out)
        }
        "record" => {
            let example = session.dialect().param_example;
            let (path, recording) = record(session.param_device(), arg, example, out)?;
            state.last_recording = Some((path, recording));
            Ok(())
        }
        "plot" => plot(state, arg, out),
        other => Err(SessionError::Usage(format!(
            "no commissioning helper :{other}"
        ))),
    }
}

fn usage(text: &str) -> SessionError {
    SessionError::Usage(format!("usage: {text}"))
}

fn snapshot(
    session: &mut dyn ParamDevice,
    arg: &str,
    out: &mut dyn Write,
) -> Result<(), SessionError> {
    const USAGE: &str = ":snapshot save FILE [--force] | diff FILE [FILE2] | restore FILE [--dry-run] [--force] [--store --yes]";
    let words: Vec<&str> = arg.split_whitespace().collect();
    let flags: Vec<&str> = words
        .iter()
        .copied()
        .filter(|w| w.starts_with("--"))
        .collect();
    let files: Vec<&str> = words
        .iter()
        .copied()
        .filter(|w| !w.starts_with("--"))
        .collect();
    let flag = |f: &str| flags.contains(&f);
    if let Some(unknown) = flags
        .iter()
        .find(|f| !["--dry-run", "--store", "--yes", "--force"].contains(f))
    {
        return Err(SessionError::Usage(format!(
            "unknown option {unknown}; {USAGE}"
        )));
    }
    match files.as_slice() {
        ["save", file] if flags.iter().all(|f| *f == "--force") => {
            actions::save_new(session, Path::new(file), flag("--force"), out).map(|_| ())
        }
        ["diff", file] if flags.is_empty() => {
            actions::diff(session, Path::new(file), out).map(|_| ())
        }
        ["diff", file, other] if flags.is_empty() => {
            let params = session.params();
            actions::diff_files(Path::new(file), Path::new(other), &params, out).map(|_| ())
        }
        ["restore", file] => {
            let options = RestoreOptions {
                store: flag("--store"),
                dry_run: flag("--dry-run"),
                force: flag("--force"),
                redact: false,
            };
            if options.store && !options.dry_run && !flag("--yes") {
                return Err(SessionError::Usage(
                    "storing to EEPROM needs confirming: add --yes (:snapshot restore FILE --store --yes)"
                        .into(),
                ));
            }
            let mut confirmed = |_: &str| Ok(true);
            actions::restore(session, Path::new(file), options, &mut confirmed, out).map(|_| ())
        }
        _ => Err(usage(USAGE)),
    }
}

/// `:scan [ADDRESSES] [TIME PER REPLY]`: the dialect's scan of the bus, its table printed.
fn scan(
    session: &mut dyn DialectSession,
    arg: &str,
    out: &mut dyn Write,
) -> Result<(), SessionError> {
    let dialect = session.dialect();
    let usage_text = format!(
        ":scan [ADDRESSES] [TIME PER REPLY] (e.g. :scan {})",
        dialect.scan_example
    );
    let words: Vec<&str> = arg.split_whitespace().collect();
    let list = words.first().copied().unwrap_or(dialect.scan_addresses);
    let addresses = parse_addresses(list, dialect.max_address)
        .map_err(|e| usage(&format!("{usage_text}; {e}")))?;
    let per_reply = match words.get(1) {
        Some(t) => crate::duration::parse(t).map_err(|e| usage(&format!("{usage_text}; {e}")))?,
        // As `tmclsh scan`: a short wait per reply unless --timeout was set.
        None => crate::commission::scan::scan_wait(session.options().timeout),
    };
    if words.len() > 2 {
        return Err(usage(&usage_text));
    }
    let scan = session.scan_bus(&addresses, per_reply)?;
    out.write_all(scan.report.as_bytes())?;
    Ok(())
}

/// Splits `PARAM[,PARAM…] [TIME] [TIME]`: parameter names, then up to `times` trailing times.
fn params_and_times(
    device: &dyn ParamDevice,
    words: &[&str],
    times: usize,
) -> Result<(Vec<ParamRef>, Vec<Duration>), HelperError> {
    let mut split = words.len();
    while split > 1 && words.len() - split < times && crate::duration::is_duration(words[split - 1])
    {
        split -= 1;
    }
    let durations = words[split..]
        .iter()
        .map(|w| crate::duration::parse(w))
        .collect::<Result<Vec<_>, _>>()?;
    let joined = words[..split].join(",");
    let names: Vec<&str> = joined.split(',').filter(|n| !n.is_empty()).collect();
    if names.is_empty() {
        return Err(HelperError::NoParameter);
    }
    let params = names
        .iter()
        .map(|n| device.find(n))
        .collect::<Result<Vec<_>, _>>()?;
    if let Some(p) = params.iter().find(|p| !p.access.read) {
        return Err(HelperError::Unreadable(p.name.clone()));
    }
    if durations.iter().any(Duration::is_zero) {
        return Err(HelperError::ZeroTime);
    }
    Ok((params, durations))
}

/// `:watch PARAM[,PARAM…] [INTERVAL]`; `example` names parameters of the session's dialect.
fn watch(
    session: &mut dyn ParamDevice,
    arg: &str,
    example: &str,
    out: &mut dyn Write,
) -> Result<(), SessionError> {
    let usage_text = format!(":watch PARAM[,PARAM…] [INTERVAL] (e.g. :watch {example} 200ms)");
    let words: Vec<&str> = arg.split_whitespace().collect();
    let (params, times) =
        params_and_times(session, &words, 1).map_err(|e| usage(&format!("{usage_text}; {e}")))?;
    if !interactive() {
        return Err(SessionError::Usage(
            ":watch needs a terminal; without one, :record FILE.csv PARAMS INTERVAL DURATION samples to a file"
                .into(),
        ));
    }
    let interval = times.first().copied().unwrap_or(Duration::from_millis(250));
    let mut screen = TerminalScreen::new(out)?;
    watch::watch(session, &params, interval, &mut screen).map(|_| ())
}

/// `:record FILE.csv PARAM[,PARAM…] [INTERVAL] [DURATION]`; `example` names parameters of the
/// session's dialect.
fn record(
    session: &mut dyn ParamDevice,
    arg: &str,
    example: &str,
    out: &mut dyn Write,
) -> Result<(PathBuf, Recording), SessionError> {
    let usage_text = format!(
        ":record FILE.csv PARAM[,PARAM…] [INTERVAL] [DURATION] (e.g. :record ramp.csv {example} 20ms 3s)"
    );
    let words: Vec<&str> = arg.split_whitespace().collect();
    let Some((file, rest)) = words.split_first() else {
        return Err(usage(&usage_text));
    };
    let (params, times) =
        params_and_times(session, rest, 2).map_err(|e| usage(&format!("{usage_text}; {e}")))?;
    let interval = times.first().copied().unwrap_or(Duration::from_millis(100));
    let duration = times.get(1).copied();
    let terminal = interactive();
    if duration.is_none() && !terminal {
        return Err(SessionError::Usage(format!(
            "without a terminal to stop it, :record needs a duration; {usage_text}"
        )));
    }
    let plan = record::Plan {
        params,
        interval,
        duration,
    };
    let path = PathBuf::from(file);
    let mut csv = CsvFile::create(
        &path,
        &plan
            .params
            .iter()
            .map(|p| p.name.clone())
            .collect::<Vec<_>>(),
    )?;
    let recording = if terminal {
        record_on_terminal(session, &plan, file, &mut csv, out)?
    } else {
        let mut sink = |s: &record::Sample| csv.append(s);
        record::record(
            session,
            &plan,
            &SystemClock::new(),
            &mut || false,
            &mut sink,
        )?
    };
    writeln!(
        out,
        "recorded {} of {} to {file}; :plot draws them",
        crate::count::counted(recording.samples.len(), "sample"),
        recording.columns.join(", ")
    )?;
    Ok((path, recording))
}

/// Records with a status line on the terminal, until the duration or a key (Ctrl-C as a key
/// ends the recording as an interrupt).
fn record_on_terminal(
    session: &mut dyn ParamDevice,
    plan: &record::Plan,
    file: &str,
    csv: &mut CsvFile,
    out: &mut dyn Write,
) -> Result<Recording, SessionError> {
    let count = Cell::new(0usize);
    let interrupted = Cell::new(false);
    let mut screen = TerminalScreen::new(out)?;
    let mut stop = || {
        let status = format!(
            "recording to {file}: {} — any key stops",
            crate::count::counted(count.get(), "sample")
        );
        let key = screen
            .draw(&[status])
            .and_then(|()| screen.key(Duration::ZERO));
        match key {
            Ok(Some(Key::Interrupt)) => {
                interrupted.set(true);
                true
            }
            Ok(Some(Key::Stop)) | Err(_) => true,
            Ok(None) => false,
        }
    };
    let mut sink = |s: &record::Sample| {
        count.set(count.get() + 1);
        csv.append(s)
    };
    let recording = record::record(session, plan, &SystemClock::new(), &mut stop, &mut sink)?;
    if interrupted.get() {
        return Err(SessionError::Interrupted);
    }
    Ok(recording)
}

fn plot(state: &State, arg: &str, out: &mut dyn Write) -> Result<(), SessionError> {
    let loaded;
    let recording = match arg.split_whitespace().collect::<Vec<_>>().as_slice() {
        [] => match &state.last_recording {
            Some((_, r)) => r,
            None => {
                return Err(SessionError::Usage(
                    "nothing recorded yet: :record FILE.csv PARAMS first, or :plot FILE.csv".into(),
                ));
            }
        },
        [file] => {
            let text = crate::file::read_text(Path::new(file), record::READ_LIMIT)
                .map_err(|e| SessionError::Usage(format!("cannot read recording {e}")))?;
            loaded = Recording::from_csv(&text).map_err(|e| {
                SessionError::Usage(format!("{file} is not a tmclsh recording: {e}"))
            })?;
            &loaded
        }
        _ => return Err(usage(":plot [FILE.csv]")),
    };
    plot::write_recording(recording, width().clamp(30, 200), out)?;
    Ok(())
}
