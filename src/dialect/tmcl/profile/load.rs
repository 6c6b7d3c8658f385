//! Reading a module profile from its TOML file (the schema of `data/profiles/tmcm-142.toml`, the
//! family fields in `data/profiles/README.md`).
//!
//! The file is written for people first: it carries pages and uncertainty notes that tmclsh
//! ignores. Only the fields below are read; unknown fields are allowed so that a profile can be
//! annotated freely.

use serde::Deserialize;

#[derive(Debug, Deserialize)]
pub(crate) struct ProfileFile {
    pub meta: Meta,
    #[serde(default)]
    pub command: Vec<CommandRow>,
    #[serde(default)]
    pub axis_parameter: Vec<ParamRow>,
    #[serde(default)]
    pub global_parameter: Vec<ParamRow>,
    pub ascii: Option<AsciiSection>,
    pub simulation: Option<SimulationRow>,
    #[serde(default)]
    pub snapshot: super::SnapshotRules,
    /// What a profile without `[[command]]` rows changes in the built-in command table.
    pub commands: Option<CommandsSection>,
    /// Commands the built-in table lacks, in the `[[command]]` schema.
    #[serde(default)]
    pub extra_command: Vec<CommandRow>,
    /// The module's own value range of a command of the built-in table (ROR/ROL speeds).
    #[serde(default)]
    pub command_range: Vec<CommandRangeRow>,
    #[serde(default)]
    pub io_port: Vec<IoPortRow>,
    /// The interrupt vectors of the program runner (EI, DI, VECT, RETI).
    #[serde(default)]
    pub interrupt: Vec<InterruptRow>,
    #[serde(default)]
    pub source_doc: Vec<SourceDocRow>,
}

#[derive(Debug, Deserialize)]
pub(crate) struct Meta {
    pub module: String,
    #[serde(default = "one")]
    pub axes: u8,
    #[serde(default = "program_memory")]
    pub tmcl_program_memory_commands: u16,
    #[serde(default = "coordinates")]
    pub coordinates: u8,
    #[serde(default = "stack_depth")]
    pub stack_depth: u8,
    pub module_number: Option<u32>,
    pub version_prefix: Option<String>,
    pub version_format: Option<String>,
    pub bootloader_format: Option<String>,
    #[serde(default)]
    pub aliases: Vec<String>,
    pub ascii_interface: Option<String>,
    pub parameter_generation: Option<String>,
    /// The generic profile: no parameter tables, numbers sent unchecked.
    #[serde(default)]
    pub generic: bool,
    #[serde(default)]
    pub manual: String,
    #[serde(default)]
    pub manual_url: String,
    #[serde(default)]
    pub motion_controller: String,
    /// Field name → source, for the `[meta]` fields.
    #[serde(default)]
    pub sources: std::collections::BTreeMap<String, String>,
    /// Field name → why it is uncertain.
    #[serde(default)]
    pub uncertain_facts: std::collections::BTreeMap<String, String>,
}

fn one() -> u8 {
    1
}
fn program_memory() -> u16 {
    2048
}
fn coordinates() -> u8 {
    21
}
fn stack_depth() -> u8 {
    8
}

#[derive(Debug, Deserialize)]
pub(crate) struct CommandRow {
    pub number: u8,
    pub mnemonic: String,
    pub name: String,
    #[serde(default)]
    pub ascii_allowed: bool,
    #[serde(default)]
    pub direct_mode: bool,
    #[serde(default)]
    pub standalone: bool,
    #[serde(default)]
    pub operands: Vec<String>,
    #[serde(default)]
    pub types: Vec<KeywordRow>,
    pub value_range: Option<[i64; 2]>,
    pub param_use: Option<String>,
    #[serde(default)]
    pub starts_motion: bool,
    #[serde(default)]
    pub uncertain: bool,
    /// The banks a global-parameter command accepts (STGP/RSGP: user variables only).
    pub banks: Option<Vec<u8>>,
    #[serde(default)]
    pub banks_note: String,
    #[serde(default)]
    pub range_when: Vec<RangeWhenRow>,
    /// The manual makes the type byte "don't care".
    #[serde(default)]
    pub type_ignored: bool,
    /// What the manual says the motor/bank byte is (`"don't care"` for 128–139).
    #[serde(default)]
    pub motor_bank: String,
}

/// A command of the built-in table whose value range the module's own manual gives differently
/// (the TMCM-142's ROR 0…2147483647 is 0…2047 on a TMC429 module and signed on later ones).
#[derive(Debug, Deserialize)]
pub(crate) struct CommandRangeRow {
    pub number: u8,
    pub mnemonic: String,
    pub value_range: [i64; 2],
}

/// A range that applies instead of the usual one while a parameter has a value.
#[derive(Debug, Deserialize)]
pub(crate) struct RangeWhenRow {
    pub axis_parameter: Option<u8>,
    pub global_parameter: Option<u8>,
    #[serde(default)]
    pub bank: u8,
    pub equals: i64,
    pub range: [i64; 2],
    #[serde(default)]
    pub unit: String,
}

#[derive(Debug, Deserialize)]
pub(crate) struct KeywordRow {
    pub value: u8,
    pub name: String,
    #[serde(default)]
    pub meaning: String,
}

#[derive(Debug, Deserialize)]
pub(crate) struct ParamRow {
    #[serde(default)]
    pub bank: u8,
    pub number: i64,
    pub number_last: Option<i64>,
    pub name: String,
    pub ident: String,
    #[serde(default)]
    pub access: String,
    pub range: Option<[i64; 2]>,
    #[serde(default)]
    pub unit: String,
    #[serde(default)]
    pub description: String,
    pub default: Option<i64>,
    #[serde(default)]
    pub uncertain: bool,
    #[serde(default)]
    pub range_when: Vec<RangeWhenRow>,
    /// What its values mean (`values`, `bits`, `fields`).
    #[serde(flatten)]
    pub decoding: super::decode::DecodeRows,
}

#[derive(Debug, Deserialize)]
pub(crate) struct AsciiSection {
    #[serde(default)]
    pub ascii_only_commands: Vec<String>,
    /// The module's ASCII allow-list; replaces the `ascii_allowed` flags of the command rows.
    pub allowed_commands: Option<Vec<String>>,
}

#[derive(Debug, Deserialize)]
pub(crate) struct CommandsSection {
    pub base: Option<String>,
    /// Commands of the built-in table the module does not have.
    #[serde(default)]
    pub absent: Vec<u8>,
    #[serde(default)]
    pub absent_reason: String,
}

/// One interrupt vector: its number (the type byte of EI, DI, VECT), what raises it, and the
/// bank-3 global parameter that configures it (a timer's period in ms, a trigger condition).
#[derive(Debug, Deserialize)]
pub(crate) struct InterruptRow {
    pub number: u8,
    pub name: String,
    /// `timer`, `stop_left`, `stop_right`, `input` or `position_reached`.
    pub kind: String,
    #[serde(default)]
    pub motor: u8,
    #[serde(default)]
    pub port: u8,
    /// The bank-3 global parameter that configures it.
    pub config: Option<u8>,
}

/// One GIO/SIO address, or (without bank and port) a signal documented only.
#[derive(Debug, Deserialize)]
pub(crate) struct IoPortRow {
    pub bank: Option<u8>,
    pub port: Option<u8>,
    pub name: Option<String>,
    pub signal: Option<String>,
    #[serde(default)]
    pub kind: String,
    pub range: Option<[i64; 2]>,
    #[serde(default)]
    pub unit: String,
    /// The connector pin, as a number or as printed (`"X3.4"`).
    pub pin: Option<PinRow>,
    #[serde(default)]
    pub uncertain: bool,
}

/// A connector pin: manuals number some and name others.
#[derive(Debug, Deserialize)]
#[serde(untagged)]
pub(crate) enum PinRow {
    /// `pin = 11`.
    Number(i64),
    /// `pin = "X3.4"`.
    Text(String),
}

impl PinRow {
    /// The pin as printed.
    pub(crate) fn text(&self) -> String {
        match self {
            PinRow::Number(n) => n.to_string(),
            PinRow::Text(t) => t.clone(),
        }
    }
}

#[derive(Debug, Deserialize)]
pub(crate) struct SourceDocRow {
    #[serde(default)]
    pub id: String,
    #[serde(default)]
    pub what: String,
    #[serde(default, rename = "where")]
    pub at: String,
}

#[derive(Debug, Deserialize)]
pub(crate) struct SimulationRow {
    pub velocity_pps_per_unit: Option<f64>,
    pub acceleration_pps2_per_unit: Option<f64>,
    pub version_string: Option<String>,
    pub version_binary: Option<u32>,
    pub tick_ms: Option<u32>,
    #[serde(default)]
    pub analog_inputs: Vec<u8>,
    #[serde(default)]
    pub digital_inputs: Vec<u8>,
    #[serde(default)]
    pub outputs: Vec<u8>,
    pub adc_max: Option<i32>,
    pub frame_timeout_ms: Option<u32>,
    pub ascii_line_max: Option<usize>,
    pub encoder_usteps_per_count: Option<f64>,
    pub instruction_us: Option<u32>,
    /// Which axis parameter plays which part in the simulated motion.
    pub axis_roles: Option<super::sim_roles::AxisRoles>,
}

impl ProfileFile {
    pub(crate) fn parse(text: &str) -> Result<Self, toml::de::Error> {
        toml::from_str(text)
    }
}
