//! Reading a module profile from its TOML file (the schema of `data/profiles/tmcm-142.toml`).
//!
//! The file is written for people first: it carries sources, pages and uncertainty notes that
//! tmclsh ignores. Only the fields below are read; unknown fields are allowed so that a profile can
//! be annotated freely.

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
}

#[derive(Debug, Deserialize)]
pub(crate) struct AsciiSection {
    #[serde(default)]
    pub ascii_only_commands: Vec<String>,
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
}

impl ProfileFile {
    pub fn parse(text: &str) -> Result<Self, toml::de::Error> {
        toml::from_str(text)
    }
}
