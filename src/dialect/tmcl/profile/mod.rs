//! Module profiles: the command, axis-parameter and global-parameter tables of a module, as data.
//!
//! One table serves the validator, completion, hints, `params`, the simulator and the docs. Every
//! file of `data/profiles/` is built in ([`catalogue`]: by name, alias or module number); the
//! TMCM-142's is the default and holds the TMCL command table the others start from;
//! `--profile FILE.toml` loads another module's table with the same schema, so a new module needs
//! no new release. A module without a profile gets the generic one ([`catalogue::generic`]).

pub mod catalogue;
mod check;
pub mod commands;
pub mod decode;
pub mod family;
pub(crate) mod load;
mod range_when;
pub mod sim_roles;
pub mod version;

use std::path::{Path, PathBuf};
use std::sync::{Arc, OnceLock};

use crate::suggest;
use commands::CommandTable;
use family::{Identity, IoPort, RangeWhen};
use load::{ParamRow, ProfileFile, SimulationRow};

pub use crate::commission::{Access, SnapshotRole, SnapshotRules};

/// The default profile's source text (TMCM-142), kept in the repository as the single source of
/// truth for it and for the TMCL command table.
pub const BUILTIN_TOML: &str = include_str!("../../../../data/profiles/tmcm-142.toml");

/// Axis parameters belong to a motor; global parameters to a bank.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ParamKind {
    /// SAP/GAP/STAP/RSAP parameter.
    Axis,
    /// SGP/GGP/STGP/RSGP parameter in the given bank.
    Global {
        /// Bank number (0 module settings, 1 reserved, 2 user variables).
        bank: u8,
    },
}

/// One parameter of a module.
#[derive(Debug, Clone, PartialEq)]
pub struct Param {
    /// Axis or global (with bank).
    pub kind: ParamKind,
    /// Parameter number (the type byte of the command).
    pub number: u8,
    /// Name as printed in the manual.
    pub name: String,
    /// Identifier users type (`actual_position`).
    pub ident: String,
    /// Read/write/store rules.
    pub access: Access,
    /// Accepted value range, where the manual gives one.
    pub range: Option<(i64, i64)>,
    /// Unit as printed.
    pub unit: String,
    /// One-paragraph description.
    pub description: String,
    /// Power-up value the simulator uses.
    pub default: Option<i64>,
    /// Whether any field is best knowledge rather than confirmed by the manual.
    pub uncertain: bool,
    /// Ranges that apply instead of `range` while another parameter has a value.
    pub range_when: Vec<RangeWhen>,
    /// What its values mean (enumerations, bits), where the profile says.
    pub decoding: decode::Decoding,
}

impl Param {
    /// Bank of a global parameter, 0 for axis parameters.
    pub fn bank(&self) -> u8 {
        match self.kind {
            ParamKind::Axis => 0,
            ParamKind::Global { bank } => bank,
        }
    }

    /// Whether `value` lies in the documented range (no range means any 32-bit value).
    pub fn accepts(&self, value: i64) -> bool {
        self.range.is_none_or(|(lo, hi)| (lo..=hi).contains(&value))
    }

    /// "0 … 15" style range text, or empty.
    pub fn range_text(&self) -> String {
        self.range
            .map(|(lo, hi)| format!("{lo}..{hi}"))
            .unwrap_or_default()
    }
}

/// How long a TMCL module's UART waits in quiet before it drops a partial binary frame: Trinamic's
/// open firmware for its modules and evaluation boards sets a receive timeout of 10 ticks of
/// 0.5 ms (`UART_TIMEOUT_VALUE 10 // timeout value in 0.5ms`, TMC-EvalSystem `hal/.../UART.c`).
/// A profile may say otherwise (`[simulation] frame_timeout_ms`); the session keeps the line quiet
/// for longer than this before a frame that follows other bytes.
pub const UART_TIMEOUT_MS: u32 = 10 / 2;

/// Constants the simulator needs that are not parameters.
#[derive(Debug, Clone, PartialEq)]
pub struct SimConstants {
    /// Microsteps per second per internal velocity unit (AP255 = 0).
    pub velocity_pps_per_unit: f64,
    /// Microsteps per second² per internal acceleration unit (AP255 = 0).
    pub acceleration_pps2_per_unit: f64,
    /// The eight-character string of command 136 type 0.
    pub version_string: String,
    /// The value of command 136 type 1.
    pub version_binary: u32,
    /// Length of a WAIT tick in milliseconds.
    pub tick_ms: u32,
    /// GIO bank 1 ports.
    pub analog_inputs: Vec<u8>,
    /// GIO bank 0 ports.
    pub digital_inputs: Vec<u8>,
    /// SIO / GIO bank 2 ports.
    pub outputs: Vec<u8>,
    /// Full-scale ADC reading.
    pub adc_max: i32,
    /// A partial binary frame followed by this much quiet is discarded, so the receiver
    /// resynchronises after line noise or a half-sent frame ([`UART_TIMEOUT_MS`] unless the
    /// profile says otherwise).
    pub frame_timeout_ms: u32,
    /// Characters kept per ASCII command line; further characters are dropped.
    pub ascii_line_max: usize,
    /// Microsteps per count of the simulated encoder.
    pub encoder_usteps_per_count: f64,
    /// Execution time of one stand-alone program instruction, in microseconds.
    pub instruction_us: u32,
    /// Which axis parameter plays which part in the simulated motion (empty: not given).
    pub axis_roles: sim_roles::AxisRoles,
}

/// A module's tables.
#[derive(Debug, Clone)]
pub struct Profile {
    /// Module name ("TMCM-142").
    pub module: String,
    /// Number of motors (valid motor numbers are `0..axes`).
    pub axes: u8,
    /// Program memory size in instructions.
    pub program_memory: u16,
    /// Number of coordinates (valid numbers `0..coordinates`).
    pub coordinates: u8,
    /// Subroutine stack depth of stand-alone programs.
    pub stack_depth: u8,
    /// Commands, keywords and operand layouts.
    pub commands: CommandTable,
    /// Axis parameters, sorted by number.
    pub axis: Vec<Param>,
    /// Global parameters, sorted by bank and number.
    pub global: Vec<Param>,
    /// Simulation constants.
    pub sim: SimConstants,
    /// How parameter snapshots treat each parameter.
    pub snapshot: SnapshotRules,
    /// The file it was loaded from; `None` for a built-in profile.
    pub source: Option<PathBuf>,
    /// The built-in name (`tmcm-6110`, `generic`), or the file's stem.
    pub name: String,
    /// Who the module is and what the profile rests on.
    pub identity: Identity,
    /// The GIO/SIO addresses of the module, by bank and port (empty: not mapped, not checked).
    pub io_ports: Vec<IoPort>,
    /// No parameter tables: parameters are known by number only (the generic profile).
    pub generic: bool,
    /// The interrupt vectors of its program runner (empty: the module has none).
    pub interrupts: Vec<family::Interrupt>,
}

/// Why a profile could not be loaded.
#[derive(Debug, thiserror::Error)]
pub enum ProfileError {
    /// The file could not be read.
    #[error("cannot read profile {0}")]
    Read(crate::file::FileError),
    /// The file is not valid TOML, does not follow the schema, or has rows that cannot be right.
    #[error(
        "profile {path} refused (schema in docs/profiles.md):\n  {}",
        problems.join("\n  ")
    )]
    Schema {
        /// The file.
        path: String,
        /// What is wrong, one `line N: …` each.
        problems: Vec<String>,
    },
    /// `--profile` names neither a built-in profile nor a file.
    #[error(
        "no built-in profile or file '{name}' (`tmclsh profiles` lists the built-in ones){}",
        suggest::did_you_mean(suggestion)
    )]
    Unknown {
        /// What was given.
        name: String,
        /// The nearest built-in name.
        suggestion: Option<String>,
    },
}

/// Tables that cannot be had are refused before anything is sent.
impl crate::exit::ExitStatus for ProfileError {
    fn exit(&self) -> crate::exit::Exit {
        crate::exit::Exit::Refused
    }
}

/// Why a parameter name did not resolve.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum LookupError {
    /// No parameter has this name or prefix.
    #[error(
        "unknown {kind} parameter '{name}'{}",
        suggest::did_you_mean(suggestion)
    )]
    Unknown {
        /// "axis" or "global".
        kind: &'static str,
        /// What was typed.
        name: String,
        /// The nearest identifier, if one is close.
        suggestion: Option<String>,
    },
    /// The prefix matches several parameters.
    #[error("'{name}' is ambiguous: {}", candidates.join(", "))]
    Ambiguous {
        /// What was typed.
        name: String,
        /// The identifiers it could mean.
        candidates: Vec<String>,
    },
    /// A name where the profile has none (the generic profile).
    #[error(
        "the {module} profile has no parameter names: give the {kind} parameter's number \
         (0..255) for '{name}', or the module's profile with --profile (tmclsh profiles lists them)"
    )]
    NumbersOnly {
        /// "axis" or "global".
        kind: &'static str,
        /// What was typed.
        name: String,
        /// The profile's module name.
        module: String,
    },
}

/// A name that fits no parameter is refused before anything is sent.
impl crate::exit::ExitStatus for LookupError {
    fn exit(&self) -> crate::exit::Exit {
        crate::exit::Exit::Refused
    }
}

impl Profile {
    /// The default built-in profile, the TMCM-142's (parsed once per process).
    pub fn builtin() -> Arc<Profile> {
        static BUILTIN: OnceLock<Arc<Profile>> = OnceLock::new();
        BUILTIN
            .get_or_init(|| {
                let mut profile = Profile::from_toml(BUILTIN_TOML, None)
                    .expect("the built-in profile data/profiles/tmcm-142.toml is valid");
                profile.name = catalogue::DEFAULT.to_string();
                Arc::new(profile)
            })
            .clone()
    }

    /// Loads a profile file; a file without `[[command]]` rows uses the built-in command table.
    pub fn from_file(path: &Path) -> Result<Profile, ProfileError> {
        let text =
            crate::file::read_text(path, crate::file::READ_LIMIT).map_err(ProfileError::Read)?;
        let mut profile = Profile::from_text(&text, &path.display().to_string())?;
        profile.source = Some(path.to_path_buf());
        profile.name = path
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default();
        Ok(profile)
    }

    /// A profile from its text, over the built-in command table; `path` names it in errors.
    pub(crate) fn from_text(text: &str, path: &str) -> Result<Profile, ProfileError> {
        let builtin = Profile::builtin();
        Profile::from_toml(text, Some(&builtin.commands)).map_err(|message| ProfileError::Schema {
            path: path.to_string(),
            problems: message.lines().map(String::from).collect(),
        })
    }

    /// Builds a profile from TOML text; `fallback_commands` fills in a missing command table.
    /// Every problem of the file is reported, one `line N: …` per line of the error.
    pub fn from_toml(
        text: &str,
        fallback_commands: Option<&CommandTable>,
    ) -> Result<Profile, String> {
        let file = ProfileFile::parse(text).map_err(|e| check::render_toml_error(text, &e))?;
        let base = if file.command.is_empty() {
            fallback_commands
        } else {
            None
        };
        let problems = check::check(&file, base);
        if !problems.is_empty() {
            return Err(check::render(text, &problems).join("\n"));
        }
        let at = |place: Vec<check::Step>, message: &dyn std::fmt::Display| {
            check::render(text, &[check::Problem::at(place, message.to_string())]).join("\n")
        };
        let mut commands = command_table(&file, fallback_commands, at)?;
        family::apply_ascii(&mut commands, &file);
        let (axis, global) = parameters(&file);
        file.snapshot
            .check_names(|ident| axis.iter().chain(&global).any(|p| p.ident == ident))
            .map_err(|e| at(vec![check::Step::Key("snapshot")], &e))?;
        Ok(Profile {
            module: file.meta.module.clone(),
            axes: file.meta.axes,
            program_memory: file.meta.tmcl_program_memory_commands,
            coordinates: file.meta.coordinates,
            stack_depth: file.meta.stack_depth,
            commands,
            axis,
            global,
            sim: SimConstants::from_section(file.simulation.as_ref()),
            snapshot: file.snapshot.clone(),
            source: None,
            name: String::new(),
            identity: family::identity(&file),
            io_ports: family::io_ports(&file),
            generic: file.meta.generic,
            interrupts: family::interrupts(&file),
        })
    }

    /// The I/O port at `bank` and `port`, if the profile maps it.
    pub fn io_port(&self, bank: u8, port: u8) -> Option<&IoPort> {
        self.io_ports
            .iter()
            .find(|p| p.bank == bank && p.port == port)
    }

    /// Where the profile comes from, for banners and transcripts: "built-in" or the file.
    pub fn origin(&self) -> String {
        self.source
            .as_ref()
            .map_or_else(|| "built-in".to_string(), |path| path.display().to_string())
    }

    /// The axis parameter with this number.
    pub fn axis_param(&self, number: u8) -> Option<&Param> {
        self.axis.iter().find(|p| p.number == number)
    }

    /// The global parameter with this bank and number.
    pub fn global_param(&self, bank: u8, number: u8) -> Option<&Param> {
        self.global
            .iter()
            .find(|p| p.bank() == bank && p.number == number)
    }

    /// Resolves an axis parameter identifier, name or unique identifier prefix.
    pub fn find_axis(&self, name: &str) -> Result<&Param, LookupError> {
        self.by_number_only("axis", name)?;
        find_by_name(&self.axis, name, "axis")
    }

    /// Resolves a global parameter identifier, name or unique identifier prefix (any bank).
    pub fn find_global(&self, name: &str) -> Result<&Param, LookupError> {
        self.by_number_only("global", name)?;
        find_by_name(&self.global, name, "global")
    }

    /// The refusal of a name where the profile knows parameters by number only.
    fn by_number_only(&self, kind: &'static str, name: &str) -> Result<(), LookupError> {
        if self.generic {
            return Err(LookupError::NumbersOnly {
                kind,
                name: name.to_string(),
                module: self.module.clone(),
            });
        }
        Ok(())
    }

    /// Parameters whose number, identifier, name or unit contains `filter` (case-insensitive).
    pub fn matching<'a>(&'a self, filter: &str) -> impl Iterator<Item = &'a Param> + 'a {
        let needle = filter.to_ascii_lowercase();
        self.axis.iter().chain(&self.global).filter(move |p| {
            needle.is_empty()
                || p.ident.contains(&needle)
                || p.name.to_ascii_lowercase().contains(&needle)
                || p.number.to_string() == needle
        })
    }
}

fn find_by_name<'a>(
    params: &'a [Param],
    name: &str,
    kind: &'static str,
) -> Result<&'a Param, LookupError> {
    let wanted = name.to_ascii_lowercase();
    if let Some(p) = params
        .iter()
        .find(|p| p.ident == wanted || p.name.eq_ignore_ascii_case(name))
    {
        return Ok(p);
    }
    let prefixed: Vec<&Param> = params
        .iter()
        .filter(|p| p.ident.starts_with(&wanted))
        .collect();
    match prefixed.as_slice() {
        [one] => Ok(one),
        [] => Err(LookupError::Unknown {
            kind,
            name: name.to_string(),
            suggestion: suggest::nearest(&wanted, params.iter().map(|p| p.ident.as_str())),
        }),
        many => Err(LookupError::Ambiguous {
            name: name.to_string(),
            candidates: many.iter().map(|p| p.ident.clone()).collect(),
        }),
    }
}

/// One row, or one per number for rows spanning `number..=number_last` (user variables). The
/// row has passed [`check`]: numbers lie in 0..255, -1 marks a placeholder.
fn expand(row: &ParamRow, kind: ParamKind) -> Vec<Param> {
    if row.number < 0 {
        return Vec::new(); // placeholder rows (e.g. bank 1, contents unknown)
    }
    let last = row.number_last.unwrap_or(row.number);
    let spans = row.number_last.is_some();
    (row.number..=last)
        .map(|number| Param {
            kind,
            number: number as u8,
            name: if spans {
                format!("{} {number}", row.ident.replace('_', " "))
            } else {
                row.name.clone()
            },
            ident: if spans {
                format!("{}_{number}", row.ident.to_ascii_lowercase())
            } else {
                row.ident.to_ascii_lowercase()
            },
            access: Access::from_letters(&row.access),
            range: row.range.map(|[lo, hi]| (lo, hi)),
            unit: row.unit.clone(),
            description: row.description.clone(),
            default: row.default,
            uncertain: row.uncertain,
            range_when: RangeWhen::from_rows(&row.range_when),
            decoding: decode::Decoding::from_rows(&row.decoding),
        })
        .collect()
}

/// The command table of a checked file: its own `[[command]]` rows, or else `fallback` changed
/// by `[commands]` and `[[extra_command]]`. `at` renders an error at a place of the file.
fn command_table(
    file: &ProfileFile,
    fallback: Option<&CommandTable>,
    at: impl Fn(Vec<check::Step>, &dyn std::fmt::Display) -> String,
) -> Result<CommandTable, String> {
    if file.command.is_empty() {
        let base = fallback.ok_or_else(|| "no [[command]] rows".to_string())?;
        return family::compose(base, file)
            .map_err(|e| at(vec![check::Step::Key("extra_command")], &e));
    }
    let ascii_words = file.ascii.as_ref().map(|a| a.ascii_only_commands.clone());
    CommandTable::from_rows(&file.command, ascii_words.unwrap_or_default()).map_err(|e| {
        // The error names the command by number; numbers are unique by now.
        let row = file.command.iter().position(|r| r.number == e.number());
        let place = match row {
            Some(i) => vec![check::Step::Key("command"), check::Step::Row(i)],
            None => vec![check::Step::Key("command")],
        };
        at(place, &e)
    })
}

/// The axis and the global parameters of a checked file, one per number, sorted.
fn parameters(file: &ProfileFile) -> (Vec<Param>, Vec<Param>) {
    let mut axis = Vec::new();
    for row in &file.axis_parameter {
        axis.extend(expand(row, ParamKind::Axis));
    }
    let mut global = Vec::new();
    for row in &file.global_parameter {
        global.extend(expand(row, ParamKind::Global { bank: row.bank }));
    }
    axis.sort_by_key(|p| p.number);
    global.sort_by_key(|p| (p.bank(), p.number));
    (axis, global)
}

impl SimConstants {
    /// How long the host keeps the line quiet before a binary frame that follows other bytes, so
    /// that a module whose receiver holds a partial frame drops it: twice the frame time-out (the
    /// manuals' advice, 10 ms for Trinamic's firmware) and 50 ms for the operating system and a
    /// USB adapter, which may bunch bytes written some milliseconds apart, and for a receiver
    /// that is not scheduled at once on a loaded machine (it costs only where a frame follows
    /// ASCII lines or noise).
    pub fn quiet_before_frame(&self) -> std::time::Duration {
        std::time::Duration::from_millis(u64::from(self.frame_timeout_ms) * 2 + 50)
    }

    /// The simulator's constants from a file's `[simulation]`, each missing one at its default.
    fn from_section(sim: Option<&SimulationRow>) -> SimConstants {
        SimConstants {
            velocity_pps_per_unit: sim
                .and_then(|s| s.velocity_pps_per_unit)
                .unwrap_or(15625.0 / 1048576.0),
            acceleration_pps2_per_unit: sim
                .and_then(|s| s.acceleration_pps2_per_unit)
                .unwrap_or(1.0),
            version_string: sim
                .and_then(|s| s.version_string.clone())
                .unwrap_or_else(|| "000V1.00".into()),
            version_binary: sim.and_then(|s| s.version_binary).unwrap_or(0x0100),
            tick_ms: sim.and_then(|s| s.tick_ms).unwrap_or(10),
            analog_inputs: sim.map(|s| s.analog_inputs.clone()).unwrap_or_default(),
            digital_inputs: sim.map(|s| s.digital_inputs.clone()).unwrap_or_default(),
            outputs: sim.map(|s| s.outputs.clone()).unwrap_or_default(),
            adc_max: sim.and_then(|s| s.adc_max).unwrap_or(1023),
            frame_timeout_ms: sim
                .and_then(|s| s.frame_timeout_ms)
                .unwrap_or(UART_TIMEOUT_MS),
            ascii_line_max: sim.and_then(|s| s.ascii_line_max).unwrap_or(80),
            encoder_usteps_per_count: sim.and_then(|s| s.encoder_usteps_per_count).unwrap_or(1.0),
            instruction_us: sim.and_then(|s| s.instruction_us).unwrap_or(100),
            axis_roles: sim.and_then(|s| s.axis_roles.clone()).unwrap_or_default(),
        }
    }
}

#[cfg(test)]
mod tests;
