//! Reading `data/smd4.toml`, the SMD4 dialect's single source of truth (schema in its header).
//!
//! The file is written for people first: it keeps the document's uncertainty notes, quick-reference
//! marks and sources, which tmclsh ignores. Only the fields below are read; unknown fields are
//! allowed so the file can be annotated freely.

use serde::Deserialize;

#[derive(Debug, Deserialize)]
pub(crate) struct Smd4File {
    #[serde(default)]
    pub simulation: SimulationRow,
    #[serde(default)]
    pub snapshot: SnapshotRow,
    #[serde(default)]
    pub user_real: UserRealRow,
    #[serde(default)]
    pub error_code: Vec<ErrorCodeRow>,
    #[serde(default)]
    pub sflag: Vec<FlagRow>,
    #[serde(default)]
    pub eflag: Vec<FlagRow>,
    #[serde(default)]
    pub command: Vec<CommandRow>,
}

#[derive(Debug, Default, Deserialize)]
pub(crate) struct SimulationRow {
    pub multi_line_quiet_gap_ms: Option<u64>,
    pub dhcp_ip: Option<String>,
    pub dhcp_netmask: Option<String>,
    pub dhcp_gateway: Option<String>,
    pub external_enable_input: Option<bool>,
    pub sstop_seconds: Option<f64>,
}

/// The `[snapshot]` section: the lists every profile has, and the SMD4's own rules.
#[derive(Debug, Default, Deserialize)]
pub(crate) struct SnapshotRow {
    #[serde(flatten)]
    pub rules: crate::commission::SnapshotRules,
    #[serde(default)]
    pub needs_standby: bool,
    pub float_digits: Option<u32>,
}

/// The `[user_real]` section: how far a user/real pair may disagree.
#[derive(Debug, Default, Deserialize)]
pub(crate) struct UserRealRow {
    pub relative_tolerance: Option<f64>,
    pub absolute_tolerance: Option<f64>,
}

#[derive(Debug, Deserialize)]
pub(crate) struct ErrorCodeRow {
    pub code: i32,
    pub name: String,
    #[serde(default)]
    pub meaning: String,
}

#[derive(Debug, Deserialize)]
pub(crate) struct FlagRow {
    pub bit: u8,
    pub name: String,
    #[serde(default)]
    pub flagsv_label: String,
    #[serde(default)]
    pub meaning: String,
    #[serde(default)]
    pub uncertain: bool,
}

/// A number or a word, as TOML allows in `default`, `allowed` and enum values.
#[derive(Debug, Clone, Deserialize)]
#[serde(untagged)]
pub(crate) enum Scalar {
    Int(i64),
    Float(f64),
    Text(String),
}

impl Scalar {
    pub(crate) fn as_f64(&self) -> Option<f64> {
        match self {
            Scalar::Int(i) => Some(*i as f64),
            Scalar::Float(f) => Some(*f),
            Scalar::Text(_) => None,
        }
    }

    pub(crate) fn text(&self) -> String {
        match self {
            Scalar::Int(i) => i.to_string(),
            Scalar::Float(f) => f.to_string(),
            Scalar::Text(t) => t.clone(),
        }
    }
}

#[derive(Debug, Deserialize)]
pub(crate) struct EnumRow {
    pub value: Scalar,
    #[serde(default)]
    pub label: String,
}

#[derive(Debug, Deserialize)]
pub(crate) struct ExampleRow {
    pub tx: String,
    pub rx: Option<String>,
    #[serde(default)]
    pub rx_more: Vec<String>,
    #[serde(default)]
    pub note: String,
    #[serde(default)]
    pub suspect: bool,
}

#[derive(Debug, Deserialize)]
pub(crate) struct CommandRow {
    pub mnemonic: String,
    #[serde(default)]
    pub group: String,
    #[serde(default)]
    pub kind: String,
    #[serde(default)]
    pub description: String,
    #[serde(default)]
    pub readable: bool,
    #[serde(default)]
    pub writable: bool,
    #[serde(default = "none_type")]
    pub arg_type: String,
    pub value_type: Option<String>,
    pub value_format: Option<String>,
    pub min: Option<Scalar>,
    pub max: Option<Scalar>,
    pub default: Option<Scalar>,
    #[serde(default, rename = "enum")]
    pub enum_: Vec<EnumRow>,
    #[serde(default)]
    pub allowed: Vec<Scalar>,
    pub levels: Option<u32>,
    #[serde(default)]
    pub unit: String,
    pub reply: String,
    pub reply_literal: Option<String>,
    #[serde(default)]
    pub reply_optional: bool,
    #[serde(default)]
    pub requires_standby: bool,
    #[serde(default)]
    pub starts_motion: bool,
    #[serde(default)]
    pub modes: Vec<u8>,
    #[serde(default)]
    pub no_response: bool,
    #[serde(default = "yes")]
    pub persistent: bool,
    #[serde(default)]
    pub aliases: Vec<String>,
    pub sim_value: Option<String>,
    #[serde(default)]
    pub examples: Vec<ExampleRow>,
    #[serde(default)]
    pub uncertain: bool,
    #[serde(default)]
    pub uncertain_reason: String,
}

fn none_type() -> String {
    "none".into()
}

fn yes() -> bool {
    true
}

impl Smd4File {
    pub(crate) fn parse(text: &str) -> Result<Self, toml::de::Error> {
        toml::from_str(text)
    }
}
