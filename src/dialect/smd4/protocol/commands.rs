//! The SMD4 command table, built from `data/smd4.toml`: what each mnemonic reads and writes, its
//! argument, its reply shape and the rules around it. Nothing here lists commands by hand.

use super::load::{CommandRow, Scalar};
use super::tolerance::RealTolerance;
use super::types::{ArgValue, ItemType, parse_arg};

/// What kind of command a mnemonic is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// A value that can be read and (usually) written.
    Setting,
    /// A read-only value.
    Query,
    /// Does something, no value.
    Action,
    /// Starts motion.
    Motion,
}

/// The data part of a successful reply.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum ReplyShape {
    /// Flags only.
    None,
    /// One item of the command's value type.
    Value,
    /// Two FLOATs: the value asked for and the value the drive produces.
    UserReal,
    /// `<n> (<label>)` (SYS:MODE).
    Named,
    /// Fixed text, as the document's examples show (`1` for MOTOR:RUNR and SYS:FLAGS).
    Literal(String),
    /// The flags line with an empty item, then text lines without an end marker.
    MultiLine,
}

/// One accepted value of an argument, with its meaning.
#[derive(Debug, Clone, PartialEq)]
pub struct Choice {
    /// As typed (`+`, `256`, `0`).
    pub value: String,
    /// What it means (`Remote`), or empty.
    pub label: String,
}

/// The argument a command takes when written.
#[derive(Debug, Clone, PartialEq)]
pub struct ArgSpec {
    /// Its type.
    pub ty: ItemType,
    /// Lowest value, for numbers.
    pub min: Option<f64>,
    /// Highest value, for numbers.
    pub max: Option<f64>,
    /// The only values accepted (enum options or an `allowed` list); empty = any in range.
    pub choices: Vec<Choice>,
    /// FLOAT values are rounded to the nearest `k * max / levels`.
    pub levels: Option<u32>,
}

/// Why an argument is refused.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ArgProblem {
    /// Not of the argument's type (the drive answers −101).
    Type,
    /// Not one of the accepted values (−2).
    NotAllowed,
    /// Outside min..max (−2).
    OutOfRange,
}

impl ArgSpec {
    /// Parses and checks `text`.
    pub fn check(&self, text: &str) -> Result<ArgValue, ArgProblem> {
        let value = parse_arg(self.ty, text).ok_or(ArgProblem::Type)?;
        if !self.choices.is_empty() && !self.choices.iter().any(|c| same(&c.value, &value)) {
            return Err(ArgProblem::NotAllowed);
        }
        if let Some(x) = value.as_f64() {
            let below = self.min.is_some_and(|min| x < min);
            let above = self.max.is_some_and(|max| x > max);
            if below || above {
                return Err(ArgProblem::OutOfRange);
            }
        }
        Ok(value)
    }

    /// `1..15000`, or empty when there is no range.
    pub fn range_text(&self) -> String {
        match (self.min, self.max) {
            (Some(lo), Some(hi)) => format!("{}..{}", trim_number(lo), trim_number(hi)),
            (Some(lo), None) => format!(">= {}", trim_number(lo)),
            (None, Some(hi)) => format!("<= {}", trim_number(hi)),
            (None, None) => String::new(),
        }
    }

    /// The accepted values, comma separated.
    pub fn choices_text(&self) -> String {
        let values: Vec<&str> = self.choices.iter().map(|c| c.value.as_str()).collect();
        values.join(", ")
    }
}

fn same(choice: &str, value: &ArgValue) -> bool {
    match value.as_f64() {
        Some(x) => choice.parse::<f64>().is_ok_and(|c| c == x),
        None => choice == value.canonical(),
    }
}

/// A number without a needless `.0`.
pub fn trim_number(x: f64) -> String {
    if x.fract() == 0.0 && x.abs() < 1e15 {
        format!("{}", x as i64)
    } else {
        format!("{x}")
    }
}

/// One line of the document's examples.
#[derive(Debug, Clone, PartialEq)]
pub struct Example {
    /// The request as printed.
    pub tx: String,
    /// The reply as printed (none for SYS:PROG and SYS:RESET).
    pub rx: Option<String>,
    /// Continuation lines of a multi-line reply.
    pub rx_more: Vec<String>,
    /// Why the example is odd, if it is.
    pub note: String,
    /// The example contradicts the document's own text.
    pub suspect: bool,
}

/// One command of the SMD4.
#[derive(Debug, Clone, PartialEq)]
pub struct Smd4Command {
    /// Canonical mnemonic, upper case (`MOTOR:VMAX`).
    pub mnemonic: String,
    /// Other spellings the drive may accept (`SYS:STORE`).
    pub aliases: Vec<String>,
    /// Section of the document (`Profile`).
    pub group: String,
    /// Setting, query, action or motion.
    pub kind: Kind,
    /// One sentence.
    pub description: String,
    /// Sending it without arguments reads it.
    pub readable: bool,
    /// Sending it with an argument writes it (or, without an argument, runs an action).
    pub writable: bool,
    /// The argument of a write; `None` when the command takes none.
    pub arg: Option<ArgSpec>,
    /// Type of the value item in replies, for [`ReplyShape::Value`].
    pub value_type: Option<ItemType>,
    /// Value reported in fixed point with 2 decimals (PACT, PREL).
    pub fixed_point: bool,
    /// Reply shape.
    pub reply: ReplyShape,
    /// The reply's data item may be missing: the document declares no return, only an example
    /// shows one (SYS:FLAGS).
    pub reply_optional: bool,
    /// Unit as printed (`Hz`, `A rms`).
    pub unit: String,
    /// Factory default, as text.
    pub default: Option<String>,
    /// Options of an enumerated value, with labels (also used for `n (Name)` replies).
    pub labels: Vec<Choice>,
    /// A write needs the standby flag (−1 otherwise).
    pub requires_standby: bool,
    /// The command starts motion (−7 while an error flag is set).
    pub starts_motion: bool,
    /// SYS:MODE values in which it may run (empty = any); −6 otherwise.
    pub modes: Vec<u8>,
    /// The drive sends no reply (SYS:PROG, SYS:RESET).
    pub no_response: bool,
    /// Part of the stored configuration.
    pub persistent: bool,
    /// Fixed value a simulated unit reports.
    pub sim_value: Option<String>,
    /// The document's examples.
    pub examples: Vec<Example>,
    /// Whether anything about the command is best knowledge.
    pub uncertain: bool,
    /// Why.
    pub uncertain_reason: String,
    /// How far the two values of a [`ReplyShape::UserReal`] reply may disagree (`[user_real]`).
    pub real_tolerance: Option<RealTolerance>,
}

impl Smd4Command {
    /// The type of the reply's value item.
    pub fn value_item_type(&self) -> Option<ItemType> {
        self.value_type.or(self.arg.as_ref().map(|a| a.ty))
    }

    /// Whether a reply carries several lines.
    pub fn multi_line(&self) -> bool {
        self.reply == ReplyShape::MultiLine
    }

    /// Whether `name` (any case) names this command.
    pub fn answers_to(&self, name: &str) -> bool {
        self.mnemonic.eq_ignore_ascii_case(name)
            || self.aliases.iter().any(|a| a.eq_ignore_ascii_case(name))
    }

    /// The label of an enumerated value (`1` → `Remote`).
    pub fn label_of(&self, value: &str) -> Option<&str> {
        self.labels
            .iter()
            .find(|c| c.value == value)
            .map(|c| c.label.as_str())
    }

    pub(crate) fn from_row(row: &CommandRow) -> Result<Smd4Command, String> {
        let name = &row.mnemonic;
        let kind = kind(row)?;
        let reply = reply_shape(row)?;
        let labels = labels(row)?;
        let arg = arg_spec(row, &labels)?;
        let value_type = match &row.value_type {
            Some(ty) => Some(
                ItemType::from_name(ty)
                    .ok_or_else(|| format!("{name}: unknown value_type '{ty}'"))?,
            ),
            None => None,
        };
        if reply == ReplyShape::Value && value_type.is_none() && arg.is_none() {
            return Err(format!(
                "{name}: a value reply needs value_type or arg_type"
            ));
        }
        Ok(Smd4Command {
            mnemonic: name.to_ascii_uppercase(),
            aliases: row.aliases.iter().map(|a| a.to_ascii_uppercase()).collect(),
            group: row.group.clone(),
            kind,
            description: row.description.clone(),
            readable: row.readable,
            writable: row.writable,
            arg,
            value_type,
            fixed_point: row.value_format.as_deref() == Some("fixed"),
            reply,
            reply_optional: row.reply_optional,
            unit: row.unit.clone(),
            default: row.default.as_ref().map(Scalar::text),
            labels,
            requires_standby: row.requires_standby,
            starts_motion: row.starts_motion,
            modes: row.modes.clone(),
            no_response: row.no_response,
            persistent: row.persistent && kind == Kind::Setting && row.writable && row.readable,
            sim_value: row.sim_value.clone(),
            examples: examples(row),
            uncertain: row.uncertain,
            uncertain_reason: row.uncertain_reason.clone(),
            real_tolerance: None,
        })
    }
}

/// The row's `kind`.
fn kind(row: &CommandRow) -> Result<Kind, String> {
    match row.kind.as_str() {
        "setting" => Ok(Kind::Setting),
        "query" => Ok(Kind::Query),
        "action" => Ok(Kind::Action),
        "motion" => Ok(Kind::Motion),
        other => Err(format!("{}: unknown kind '{other}'", row.mnemonic)),
    }
}

/// The row's `reply`, with the text of a literal one.
fn reply_shape(row: &CommandRow) -> Result<ReplyShape, String> {
    let name = &row.mnemonic;
    Ok(match row.reply.as_str() {
        "none" => ReplyShape::None,
        "value" => ReplyShape::Value,
        "user_real" => ReplyShape::UserReal,
        "named" => ReplyShape::Named,
        "multi_line" => ReplyShape::MultiLine,
        "literal" => ReplyShape::Literal(
            row.reply_literal
                .clone()
                .ok_or_else(|| format!("{name}: reply = \"literal\" needs reply_literal"))?,
        ),
        other => return Err(format!("{name}: unknown reply '{other}'")),
    })
}

/// The labels of an enumerated value, one per value: a reply's value must read one way.
fn labels(row: &CommandRow) -> Result<Vec<Choice>, String> {
    let name = &row.mnemonic;
    let labels: Vec<Choice> = row
        .enum_
        .iter()
        .map(|e| Choice {
            value: e.value.text(),
            label: e.label.clone(),
        })
        .collect();
    for (i, choice) in labels.iter().enumerate() {
        if choice.label.trim().is_empty() {
            return Err(format!("{name}: enum value {} has no label", choice.value));
        }
        if labels[..i].iter().any(|c| c.value == choice.value) {
            return Err(format!(
                "{name}: enum value {} is given twice",
                choice.value
            ));
        }
    }
    Ok(labels)
}

/// The argument of a write, if the command takes one: its type, limits and accepted values.
fn arg_spec(row: &CommandRow, labels: &[Choice]) -> Result<Option<ArgSpec>, String> {
    let ty = match row.arg_type.as_str() {
        "none" => return Ok(None),
        ty => ty,
    };
    Ok(Some(ArgSpec {
        ty: ItemType::from_name(ty)
            .ok_or_else(|| format!("{}: unknown arg_type '{ty}'", row.mnemonic))?,
        min: row.min.as_ref().and_then(Scalar::as_f64),
        max: row.max.as_ref().and_then(Scalar::as_f64),
        choices: choices(row, labels),
        levels: row.levels,
    }))
}

/// The document's examples of the command.
fn examples(row: &CommandRow) -> Vec<Example> {
    row.examples
        .iter()
        .map(|e| Example {
            tx: e.tx.clone(),
            rx: e.rx.clone(),
            rx_more: e.rx_more.clone(),
            note: e.note.clone(),
            suspect: e.suspect,
        })
        .collect()
}

/// Accepted values: the `allowed` list if there is one, else the enum options.
fn choices(row: &CommandRow, labels: &[Choice]) -> Vec<Choice> {
    if row.allowed.is_empty() {
        return labels.to_vec();
    }
    row.allowed
        .iter()
        .map(|a| {
            let value = a.text();
            let label = labels
                .iter()
                .find(|l| l.value == value)
                .map(|l| l.label.clone())
                .unwrap_or_default();
            Choice { value, label }
        })
        .collect()
}

/// All commands, looked up by mnemonic in any case.
#[derive(Debug, Clone)]
pub struct Smd4CommandTable {
    commands: Vec<Smd4Command>,
}

impl Smd4CommandTable {
    pub(crate) fn from_rows(rows: &[CommandRow]) -> Result<Smd4CommandTable, String> {
        let commands = rows
            .iter()
            .map(Smd4Command::from_row)
            .collect::<Result<Vec<_>, _>>()?;
        Ok(Smd4CommandTable { commands })
    }

    /// Gives every user/real command the data's tolerance.
    pub(crate) fn set_real_tolerance(&mut self, tolerance: Option<RealTolerance>) {
        for command in &mut self.commands {
            if command.reply == ReplyShape::UserReal {
                command.real_tolerance = tolerance;
            }
        }
    }

    /// Every command, in the document's order.
    pub fn iter(&self) -> impl Iterator<Item = &Smd4Command> {
        self.commands.iter()
    }

    /// The command `name` (any case, aliases included).
    pub fn get(&self, name: &str) -> Option<&Smd4Command> {
        self.commands.iter().find(|c| c.answers_to(name.trim()))
    }

    /// Canonical mnemonics.
    pub fn mnemonics(&self) -> impl Iterator<Item = &str> {
        self.commands.iter().map(|c| c.mnemonic.as_str())
    }

    /// The nearest mnemonic to a mistyped `word`: first a command whose last segment is `word`
    /// (`AMAX` → `MOTOR:AMAX`, the document itself drops prefixes), then the closest spelling,
    /// segment by segment (a shared `MOTOR:` makes no name near).
    pub fn suggest(&self, word: &str) -> Option<String> {
        let leaf = |m: &str| m.rsplit(':').next().map(str::to_string);
        let by_leaf: Vec<&str> = self
            .mnemonics()
            .filter(|m| leaf(m).is_some_and(|l| l.eq_ignore_ascii_case(word)))
            .collect();
        if let [only] = by_leaf.as_slice() {
            return Some(only.to_string());
        }
        crate::suggest::nearest_segmented(word, ':', self.mnemonics())
    }
}
