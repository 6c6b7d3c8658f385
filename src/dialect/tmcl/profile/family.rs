//! What the TMCL family adds to a module's tables (schema in `data/profiles/README.md`): how the
//! module identifies itself, whether it has the ASCII interface, its I/O map, ranges that depend on
//! another parameter, and how its command set differs from the built-in table.

use super::ParamKind;
use super::commands::{CommandRowError, CommandTable};
use super::load::ProfileFile;
pub use super::range_when::{Condition, RangeWhen};

/// Whether a module has the ASCII interface (manual: "ASCII interface", command 139).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AsciiInterface {
    /// The manual documents it.
    Yes,
    /// Binary-only: sessions send binary frames.
    No,
    /// Not confirmed by a manual page: binary unless the module answers 139.
    Unconfirmed,
}

impl AsciiInterface {
    /// The word of the profile file (`yes`, `no`, `unconfirmed`).
    pub fn parse(word: &str) -> Option<AsciiInterface> {
        match word {
            "yes" => Some(AsciiInterface::Yes),
            "no" => Some(AsciiInterface::No),
            "unconfirmed" => Some(AsciiInterface::Unconfirmed),
            _ => None,
        }
    }

    /// The word as written in a profile.
    pub fn as_str(self) -> &'static str {
        match self {
            AsciiInterface::Yes => "yes",
            AsciiInterface::No => "no",
            AsciiInterface::Unconfirmed => "unconfirmed",
        }
    }
}

/// The parameter numberings of the family (`parameter_generation`): one number means different
/// things in different generations.
pub const GENERATIONS: &[&str] = &["TMCM-142", "A", "B"];

/// Who the module is, and what its profile rests on.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Identity {
    /// The module number (`142`, `6110`): what command 136 names.
    pub module_number: Option<u32>,
    /// The digits that open the 136 type-0 answer.
    pub version_prefix: Option<String>,
    /// The 8-character 136 string: `NNNVa.bc` or `NNNNVabc`.
    pub version_format: Option<String>,
    /// The same with `B` for `V`: the boot loader answering.
    pub bootloader_format: Option<String>,
    /// Other product names with the same firmware (`PD-1141`).
    pub aliases: Vec<String>,
    /// Whether the module has the ASCII interface.
    pub ascii: Option<AsciiInterface>,
    /// Which parameter numbering it follows (one of [`GENERATIONS`]).
    pub generation: Option<String>,
    /// The manual the tables come from.
    pub manual: String,
    /// Where it was read.
    pub manual_url: String,
    /// The motion controller chip, as the profile names it.
    pub motion_controller: String,
    /// The documents the profile's facts cite (`[[source_doc]]`).
    pub sources: Vec<SourceDoc>,
    /// `[meta]` fields with the source each rests on.
    pub fact_sources: Vec<(String, String)>,
    /// `[meta]` fields that are best knowledge, with the reason.
    pub uncertain_facts: Vec<(String, String)>,
}

impl Identity {
    /// The ASCII interface as the session treats it: a profile that does not say has it (the
    /// schema before the family fields, and custom profiles written for it).
    pub fn ascii_interface(&self) -> AsciiInterface {
        self.ascii.unwrap_or(AsciiInterface::Yes)
    }
}

/// One document a profile cites.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SourceDoc {
    /// The id facts name in their `source`.
    pub id: String,
    /// What it is.
    pub what: String,
    /// Where it is (URL or repository path).
    pub at: String,
}

/// One GIO/SIO address of the module's I/O map.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct IoPort {
    /// 0 digital inputs, 1 analog inputs, 2 output states (the family's numbering).
    pub bank: u8,
    /// The port number (type byte of GIO/SIO).
    pub port: u8,
    /// The signal's name (`IN0`, `AIN4`, `OUT7`).
    pub name: String,
    /// What it is.
    pub kind: String,
    /// The values GIO reads there.
    pub range: Option<(i64, i64)>,
    /// Their unit.
    pub unit: String,
    /// The connector pin, as the manual prints it.
    pub pin: Option<String>,
    /// Whether the row is best knowledge rather than confirmed by the module's manual.
    pub uncertain: bool,
}

/// The bank SIO writes: the output states.
pub const OUTPUT_BANK: u8 = 2;

impl IoPort {
    /// Whether SIO sets it (GIO reads every port).
    pub fn is_output(&self) -> bool {
        self.bank == OUTPUT_BANK
    }
}

/// "0..2, 4, 8" from sorted port numbers.
pub fn spans(ports: &[u8]) -> String {
    let mut out: Vec<String> = Vec::new();
    let mut i = 0;
    while i < ports.len() {
        let mut j = i;
        while j + 1 < ports.len() && ports[j].checked_add(1) == Some(ports[j + 1]) {
            j += 1;
        }
        out.push(if j > i + 1 {
            format!("{}..{}", ports[i], ports[j])
        } else if j == i + 1 {
            format!("{}, {}", ports[i], ports[j])
        } else {
            ports[i].to_string()
        });
        i = j + 1;
    }
    out.join(", ")
}

/// The I/O map of a file: the rows with a bank and a port (the others document signals only).
pub(crate) fn io_ports(file: &ProfileFile) -> Vec<IoPort> {
    let mut ports: Vec<IoPort> = file
        .io_port
        .iter()
        .filter_map(|row| {
            Some(IoPort {
                bank: row.bank?,
                port: row.port?,
                name: row
                    .name
                    .clone()
                    .or_else(|| row.signal.clone())
                    .unwrap_or_default(),
                kind: row.kind.clone(),
                range: row.range.map(|[lo, hi]| (lo, hi)),
                unit: row.unit.clone(),
                pin: row.pin.as_ref().map(|pin| pin.text()),
                uncertain: row.uncertain,
            })
        })
        .collect();
    ports.sort_by_key(|p| (p.bank, p.port));
    ports
}

/// Who the module of a file is.
pub(crate) fn identity(file: &ProfileFile) -> Identity {
    let meta = &file.meta;
    Identity {
        module_number: meta.module_number,
        version_prefix: meta.version_prefix.clone(),
        version_format: meta.version_format.clone(),
        bootloader_format: meta.bootloader_format.clone(),
        aliases: meta.aliases.clone(),
        ascii: meta
            .ascii_interface
            .as_deref()
            .and_then(AsciiInterface::parse),
        generation: meta.parameter_generation.clone(),
        manual: meta.manual.clone(),
        manual_url: meta.manual_url.clone(),
        motion_controller: meta.motion_controller.clone(),
        sources: file
            .source_doc
            .iter()
            .map(|d| SourceDoc {
                id: d.id.clone(),
                what: d.what.clone(),
                at: d.at.clone(),
            })
            .collect(),
        fact_sources: meta
            .sources
            .iter()
            .map(|(k, v)| (k.clone(), v.clone()))
            .collect(),
        uncertain_facts: meta
            .uncertain_facts
            .iter()
            .map(|(k, v)| (k.clone(), v.clone()))
            .collect(),
    }
}

/// The command table of a file without `[[command]]` rows: the built-in one less `[commands]
/// absent`, plus `[[extra_command]]`, with the ranges of `[[command_range]]`. The checker has passed the numbers and mnemonics.
pub(crate) fn compose(
    base: &CommandTable,
    file: &ProfileFile,
) -> Result<CommandTable, CommandRowError> {
    let mut table = base.clone();
    // The built-in table's conditions name the TMCM-142's parameters: they hold for a module
    // whose profile has the parameter named.
    table.keep_range_when(|c| defines(file, c));
    if let Some(section) = &file.commands {
        table.remove(&section.absent, &section.absent_reason);
    }
    if !file.extra_command.is_empty() {
        let extra = CommandTable::from_rows(&file.extra_command, Vec::new())?;
        table.extend(extra);
    }
    for row in &file.command_range {
        table.set_value_range(row.number, (row.value_range[0], row.value_range[1]));
    }
    if let Some(words) = file.ascii.as_ref().map(|a| &a.ascii_only_commands) {
        if !words.is_empty() {
            table.set_ascii_words(words);
        }
    }
    Ok(table)
}

/// Whether the file has the parameter a condition names.
pub(crate) fn defines(file: &ProfileFile, condition: &Condition) -> bool {
    let covers = |row: &super::load::ParamRow| {
        let n = i64::from(condition.number);
        row.number >= 0 && (row.number..=row.number_last.unwrap_or(row.number)).contains(&n)
    };
    match condition.kind {
        ParamKind::Axis => file.axis_parameter.iter().any(covers),
        ParamKind::Global { bank } => file
            .global_parameter
            .iter()
            .any(|row| row.bank == bank && covers(row)),
    }
}

/// Applies the module's ASCII interface to its table: the `[ascii] allowed_commands` list where
/// there is one, nothing at all on a module without the interface.
pub(crate) fn apply_ascii(table: &mut CommandTable, file: &ProfileFile) {
    let ascii = file
        .meta
        .ascii_interface
        .as_deref()
        .and_then(AsciiInterface::parse);
    let allowed = file
        .ascii
        .as_ref()
        .and_then(|a| a.allowed_commands.as_ref());
    match (ascii, allowed) {
        (Some(AsciiInterface::No), _) => table.set_ascii_allowed(&[]),
        (_, Some(list)) => table.set_ascii_allowed(list),
        _ => {}
    }
}

/// What raises an interrupt of the program runner.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum InterruptKind {
    /// A timer whose period (ms) is its bank-3 parameter.
    Timer,
    /// The left stop switch of a motor.
    StopLeft,
    /// The right stop switch of a motor.
    StopRight,
    /// A change of a digital input.
    Input,
    /// A motor reached its target position.
    PositionReached,
}

impl InterruptKind {
    /// The kind a profile row names.
    pub fn parse(word: &str) -> Option<InterruptKind> {
        Some(match word {
            "timer" => InterruptKind::Timer,
            "stop_left" => InterruptKind::StopLeft,
            "stop_right" => InterruptKind::StopRight,
            "input" => InterruptKind::Input,
            "position_reached" => InterruptKind::PositionReached,
            _ => return None,
        })
    }
}

/// One interrupt vector of a module (`[[interrupt]]`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Interrupt {
    /// The interrupt number: the type byte of EI, DI and VECT.
    pub number: u8,
    /// As the manual names it (`Timer 0`).
    pub name: String,
    /// What raises it.
    pub kind: InterruptKind,
    /// The motor of a stop switch or position interrupt.
    pub motor: u8,
    /// The input port of an input interrupt.
    pub port: u8,
    /// The bank-3 global parameter that configures it (a timer's period in ms).
    pub config: Option<u8>,
}

/// The EI/DI number that switches every interrupt at once (TMCL reference: "EI 255").
pub const ALL_INTERRUPTS: u8 = 255;

/// The interrupt vectors of a file (rows of an unknown kind were refused by the checker).
pub(crate) fn interrupts(file: &ProfileFile) -> Vec<Interrupt> {
    file.interrupt
        .iter()
        .filter_map(|row| {
            Some(Interrupt {
                number: row.number,
                name: row.name.clone(),
                kind: InterruptKind::parse(&row.kind)?,
                motor: row.motor,
                port: row.port,
                config: row.config,
            })
        })
        .collect()
}
