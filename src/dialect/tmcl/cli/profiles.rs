//! `tmclsh profiles [NAME|FILE]`: the built-in TMCL module profiles with their sources, or one
//! profile in full (identification, ASCII interface, command set, I/O map, every source).

use std::io::{self, Write};
use std::path::PathBuf;
use std::sync::Arc;

use crate::dialect::tmcl::profile::catalogue::{self, GENERIC};
use crate::dialect::tmcl::profile::family::Identity;
use crate::dialect::tmcl::profile::{Param, Profile};
use crate::escape::escape_control;
use crate::exit::Exit;
use crate::json::{Value, json};

use crate::exit::Failure;

/// Arguments of `profiles`.
#[derive(Debug, clap::Args)]
pub struct ProfilesArgs {
    /// Show this profile in full: a built-in name, alias or module number, or a profile file.
    #[arg(value_name = "NAME|FILE")]
    pub name: Option<PathBuf>,
    /// Print one JSON document instead (fields in docs/machine-output.md).
    #[arg(long)]
    pub json: bool,
}

/// Lists the built-in profiles, or shows one.
pub fn run(args: &ProfilesArgs, out: &mut dyn Write) -> Result<Exit, Failure> {
    let result = match (&args.name, args.json) {
        (None, false) => list(out),
        (None, true) => {
            let all: Vec<Value> = listed().iter().map(|p| summary_json(p)).collect();
            crate::json::write(&json!({ "profiles": all }), out)
        }
        (Some(arg), json) => {
            let profile = catalogue::resolve(arg)?;
            if json {
                crate::json::write(&json!({ "profile": detail_json(&profile) }), out)
            } else {
                detail(&profile, out)
            }
        }
    };
    result.map(|()| Exit::Success).map_err(Failure::from)
}

/// One row of the list.
struct Row {
    name: String,
    module: String,
    aliases: String,
    number: String,
    axes: String,
    ascii: String,
    generation: String,
    parameters: String,
}

fn row(p: &Profile) -> Row {
    let id = &p.identity;
    Row {
        name: p.name.clone(),
        module: if p.generic {
            "any other".into()
        } else {
            p.module.clone()
        },
        aliases: dash(id.aliases.join(", ")),
        number: id
            .module_number
            .map_or_else(|| "-".to_string(), |n| n.to_string()),
        axes: p.axes.to_string(),
        ascii: id.ascii_interface().as_str().to_string(),
        generation: dash(id.generation.clone().unwrap_or_default()),
        parameters: if p.generic {
            "by number only".into()
        } else {
            parameter_count(p)
        },
    }
}

fn dash(text: String) -> String {
    if text.is_empty() { "-".into() } else { text }
}

/// "85 (62 uncertain)".
fn parameter_count(p: &Profile) -> String {
    let all: Vec<&Param> = p.axis.iter().chain(&p.global).collect();
    let uncertain = all.iter().filter(|p| p.uncertain).count();
    format!("{} ({uncertain} uncertain)", all.len())
}

/// The built-in profiles and the generic one, in the order the list shows them.
fn listed() -> Vec<Arc<Profile>> {
    let mut profiles: Vec<Arc<Profile>> = catalogue::all().to_vec();
    profiles.push(catalogue::generic());
    profiles
}

/// A profile's row of the list as JSON (`profiles --json`).
fn summary_json(p: &Profile) -> Value {
    let id = &p.identity;
    json!({
        "name": p.name,
        "module": p.module,
        "generic": p.generic,
        "aliases": id.aliases,
        "module_number": id.module_number,
        "axes": p.axes,
        "ascii": id.ascii_interface().as_str(),
        "generation": id.generation,
        "axis_parameters": p.axis.len(),
        "global_parameters": p.global.len(),
        "uncertain_parameters": p.axis.iter().chain(&p.global).filter(|p| p.uncertain).count(),
        "manual": id.manual,
        "manual_url": id.manual_url,
        "origin": origin(p),
    })
}

/// A profile in full as JSON (`profiles NAME --json`): its row, its I/O ports, documents and
/// parameters.
fn detail_json(p: &Profile) -> Value {
    let mut object = match summary_json(p) {
        Value::Object(object) => object,
        _ => unreachable!("summary_json makes an object"),
    };
    let id = &p.identity;
    let ports: Vec<Value> = p
        .io_ports
        .iter()
        .map(|port| json!({ "bank": port.bank, "port": port.port, "name": port.name }))
        .collect();
    let documents: Vec<Value> = id
        .sources
        .iter()
        .map(|doc| json!({ "id": doc.id, "what": doc.what, "at": doc.at }))
        .collect();
    object.insert("ascii_commands".into(), json!(p.commands.ascii_mnemonics()));
    object.insert("io_ports".into(), json!(ports));
    object.insert("documents".into(), json!(documents));
    let parameters = crate::dialect::tmcl::params::params_json(p, "").unwrap_or_default();
    object.insert("parameters".into(), json!(parameters));
    Value::Object(object)
}

fn list(out: &mut dyn Write) -> io::Result<()> {
    let profiles = listed();
    let rows: Vec<Row> = profiles.iter().map(|p| row(p)).collect();
    let header = Row {
        name: "profile".into(),
        module: "module".into(),
        aliases: "aliases".into(),
        number: "number".into(),
        axes: "axes".into(),
        ascii: "ascii".into(),
        generation: "generation".into(),
        parameters: "parameters".into(),
    };
    let width = |f: fn(&Row) -> &str| {
        rows.iter()
            .chain([&header])
            .map(|r| f(r).len())
            .max()
            .unwrap_or(0)
    };
    let w = [
        width(|r| &r.name),
        width(|r| &r.module),
        width(|r| &r.aliases),
        width(|r| &r.number),
        width(|r| &r.axes),
        width(|r| &r.ascii),
        width(|r| &r.generation),
    ];
    for r in [&header].into_iter().chain(&rows) {
        writeln!(
            out,
            "{:<w0$}  {:<w1$}  {:<w2$}  {:<w3$}  {:<w4$}  {:<w5$}  {:<w6$}  {}",
            r.name,
            r.module,
            r.aliases,
            r.number,
            r.axes,
            r.ascii,
            r.generation,
            r.parameters,
            w0 = w[0],
            w1 = w[1],
            w2 = w[2],
            w3 = w[3],
            w4 = w[4],
            w5 = w[5],
            w6 = w[6],
        )?;
    }
    writeln!(out)?;
    writeln!(
        out,
        "sources (`tmclsh profiles NAME` shows each document; uncertain facts are marked in the files):"
    )?;
    for p in &profiles {
        let id = &p.identity;
        let what = if p.generic {
            "the built-in command table; no module's parameters".to_string()
        } else if id.manual.is_empty() {
            "no manual named".to_string()
        } else {
            id.manual.clone()
        };
        writeln!(
            out,
            "{:<w0$}  {what}; {} documents",
            p.name,
            id.sources.len(),
            w0 = w[0]
        )?;
    }
    Ok(())
}

fn detail(p: &Profile, out: &mut dyn Write) -> io::Result<()> {
    let id = &p.identity;
    let heading = format!("{}: {} ({})", p.name, p.module, origin(p));
    writeln!(out, "{}", escape_control(&heading))?;
    if let Some(number) = id.module_number {
        field(out, "module number", &module_number(number, id))?;
    }
    field(out, "aliases", &id.aliases.join(", "))?;
    field(out, "axes", &axes(p.axes))?;
    field(out, "ASCII interface", id.ascii_interface().as_str())?;
    field(out, "parameters", &parameters(p))?;
    field(out, "motion control", &id.motion_controller)?;
    field(out, "manual", &id.manual)?;
    field(out, "", &id.manual_url)?;
    field(out, "commands absent", &absent_commands(p))?;
    field(out, "commands added", &added_commands(p))?;
    let ascii: Vec<&str> = p.commands.ascii_mnemonics();
    field(out, "ASCII commands", &ascii.join(" "))?;
    field(out, "I/O (bank/port)", &io_ports(p))?;
    for (fact, source) in &id.fact_sources {
        field(out, "source of", &format!("{fact}: {source}"))?;
    }
    for (fact, why) in &id.uncertain_facts {
        field(out, "uncertain", &format!("{fact}: {why}"))?;
    }
    documents(id, out)
}

/// One `name value` line of the detail; nothing when the value is empty.
fn field(out: &mut dyn Write, name: &str, value: &str) -> io::Result<()> {
    if value.is_empty() {
        return Ok(());
    }
    // A profile file is anyone's text: its control characters are shown, not obeyed.
    writeln!(out, "  {name:<16}{}", escape_control(value))
}

/// Where the profile comes from: its file, or the data file it was built in from.
fn origin(p: &Profile) -> String {
    match (&p.source, p.name.as_str()) {
        (Some(path), _) => path.display().to_string(),
        (None, GENERIC) => "built in, data/generic.toml".to_string(),
        (None, name) => format!("built in, data/profiles/{name}.toml"),
    }
}

/// "1234 (136 answers NNNNVabc; the boot loader NNNNBabc)".
fn module_number(number: u32, id: &Identity) -> String {
    let formats = match (&id.version_format, &id.bootloader_format) {
        (Some(v), Some(b)) => format!(" (136 answers {v}; the boot loader {b})"),
        (Some(v), None) => format!(" (136 answers {v})"),
        _ => String::new(),
    };
    format!("{number}{formats}")
}

/// "2 (motors 0..1)".
fn axes(axes: u8) -> String {
    let motors = match axes {
        1 => "motor 0".to_string(),
        n => format!("motors 0..{}", n - 1),
    };
    format!("{axes} ({motors})")
}

/// How many parameters, of which generation; or that a generic profile knows none.
fn parameters(p: &Profile) -> String {
    if p.generic {
        return "by number only (0..255), no names, values unchecked".to_string();
    }
    let generation = p
        .identity
        .generation
        .as_ref()
        .map(|g| format!("generation {g}: "))
        .unwrap_or_default();
    format!(
        "{generation}{} axis, {} global; {}",
        p.axis.len(),
        p.global.len(),
        parameter_count(p)
    )
}

/// The built-in commands the module lacks, each with why.
fn absent_commands(p: &Profile) -> String {
    let absent: Vec<String> = p
        .commands
        .absent_commands()
        .map(|(c, reason)| format!("{} {} ({reason})", c.number, c.display_name()))
        .collect();
    absent.join("; ")
}

/// The commands the module has beyond the built-in table.
fn added_commands(p: &Profile) -> String {
    let builtin = Profile::builtin();
    let extra: Vec<String> = p
        .commands
        .iter()
        .filter(|c| builtin.commands.by_number(c.number).is_none())
        .map(|c| format!("{} {}", c.number, c.display_name()))
        .collect();
    extra.join(", ")
}

/// The port map as `bank/port name`, or what GIO and SIO do without one.
fn io_ports(p: &Profile) -> String {
    let ports: Vec<String> = p
        .io_ports
        .iter()
        .map(|port| format!("{}/{} {}", port.bank, port.port, port.name))
        .collect();
    if ports.is_empty() {
        "none: no port map, GIO and SIO send any port and bank".to_string()
    } else {
        ports.join(", ")
    }
}

/// The documents the profile's facts come from, each with where it is.
fn documents(id: &Identity, out: &mut dyn Write) -> io::Result<()> {
    if id.sources.is_empty() {
        return Ok(());
    }
    writeln!(out, "  documents")?;
    for doc in &id.sources {
        let what = format!("{}: {}", doc.id, doc.what);
        writeln!(out, "    {}", escape_control(&what))?;
        if !doc.at.is_empty() {
            writeln!(out, "      {}", escape_control(&doc.at))?;
        }
    }
    Ok(())
}
