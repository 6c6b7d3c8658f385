//! The TMCL command table: numbers, mnemonics, operand layouts, keywords and where each command
//! may be used. Built from the profile data; nothing here lists commands by hand.

use super::load::{CommandRow, KeywordRow};
use super::range_when::{Condition, RangeWhen};

/// What an operand in mnemonic form means, and so which instruction field it fills.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum OperandKind {
    /// A keyword of the command (`ABS`, `START`, `ADD`, `TICKS` …) → type byte.
    Keyword,
    /// Axis parameter number or name → type byte.
    AxisParam,
    /// Global parameter number or name → type byte.
    GlobalParam,
    /// I/O port number → type byte.
    Port,
    /// Coordinate number → type byte.
    Coord,
    /// Raw type byte → type byte.
    Type,
    /// Motor number → motor/bank byte.
    Motor,
    /// Global parameter bank → motor/bank byte.
    Bank,
    /// I/O bank → motor/bank byte.
    IoBank,
    /// Value → value.
    Value,
    /// Program address (a label in programs) → value.
    Address,
}

/// Which part of the instruction an operand fills.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Field {
    /// The type byte.
    Type,
    /// The motor/bank byte.
    Motor,
    /// The 32-bit value.
    Value,
}

impl OperandKind {
    pub(crate) fn parse(word: &str) -> Option<OperandKind> {
        Some(match word {
            "keyword" => OperandKind::Keyword,
            "axis_param" => OperandKind::AxisParam,
            "global_param" => OperandKind::GlobalParam,
            "port" => OperandKind::Port,
            "coord" => OperandKind::Coord,
            "type" => OperandKind::Type,
            "motor" => OperandKind::Motor,
            "bank" => OperandKind::Bank,
            "io_bank" => OperandKind::IoBank,
            "value" => OperandKind::Value,
            "address" => OperandKind::Address,
            _ => return None,
        })
    }

    /// The instruction field this operand fills.
    pub fn field(self) -> Field {
        match self {
            OperandKind::Keyword
            | OperandKind::AxisParam
            | OperandKind::GlobalParam
            | OperandKind::Port
            | OperandKind::Coord
            | OperandKind::Type => Field::Type,
            OperandKind::Motor | OperandKind::Bank | OperandKind::IoBank => Field::Motor,
            OperandKind::Value | OperandKind::Address => Field::Value,
        }
    }

    /// How a sentence names the operand (`the motor`), where a usage line shows `<motor>`.
    pub fn noun(self) -> String {
        let word = self.placeholder().trim_start_matches('<');
        format!("the {}", word.trim_end_matches('>'))
    }

    /// How the operand is shown in usage lines (`<motor>`).
    pub fn placeholder(self) -> &'static str {
        match self {
            OperandKind::Keyword => "<keyword>",
            OperandKind::AxisParam => "<parameter>",
            OperandKind::GlobalParam => "<parameter>",
            OperandKind::Port => "<port>",
            OperandKind::Coord => "<coordinate>",
            OperandKind::Type => "<type>",
            OperandKind::Motor => "<motor>",
            OperandKind::Bank => "<bank>",
            OperandKind::IoBank => "<bank>",
            OperandKind::Value => "<value>",
            OperandKind::Address => "<address>",
        }
    }
}

/// One operand of a command's mnemonic form.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Operand {
    /// What it means.
    pub kind: OperandKind,
    /// Whether it may be left out (it is then 0).
    pub optional: bool,
}

/// A named value of a command's type byte.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Keyword {
    /// The type byte.
    pub value: u8,
    /// The keyword as written (`ABS`).
    pub name: String,
    /// What it selects.
    pub meaning: String,
}

/// What a command does with the parameter it names.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ParamUse {
    /// GAP, GGP: needs read access.
    Read,
    /// SAP, SGP, AAP, AGP: needs write access and a value in range.
    Write,
    /// STAP, RSAP, STGP, RSGP: needs an EEPROM-backed parameter.
    Store,
}

/// One TMCL command.
#[derive(Debug, Clone, PartialEq)]
pub struct CommandSpec {
    /// Command number.
    pub number: u8,
    /// Mnemonic (empty for the control functions 128–139, which have none).
    pub mnemonic: String,
    /// What it does.
    pub name: String,
    /// Accepted in ASCII mode (manual §6.6.3).
    pub ascii_allowed: bool,
    /// Accepted in binary direct mode.
    pub direct_mode: bool,
    /// Usable inside stand-alone programs.
    pub standalone: bool,
    /// Operands in mnemonic order.
    pub operands: Vec<Operand>,
    /// Keywords of the type byte, if it selects a sub-function.
    pub keywords: Vec<Keyword>,
    /// Documented range of the value operand.
    pub value_range: Option<(i64, i64)>,
    /// What the command does with its parameter, for commands that name one.
    pub param_use: Option<ParamUse>,
    /// Whether the command can set the motor moving (an aborted run stops such modules).
    pub starts_motion: bool,
    /// Whether the entry is best knowledge rather than confirmed.
    pub uncertain: bool,
    /// The banks a global-parameter command accepts (STGP/RSGP: bank 2); `None`: every bank.
    pub banks: Option<Vec<u8>>,
    /// Why, as the profile says (shown when another bank is refused).
    pub banks_note: String,
    /// Ranges of the value that apply while another parameter has a value.
    pub range_when: Vec<RangeWhen>,
    /// The manual makes the type byte "don't care" (134, 135).
    pub type_ignored: bool,
    /// The manual makes the motor/bank byte "don't care" (128–139): any value is taken, whatever
    /// the module's axes.
    pub motor_ignored: bool,
}

impl CommandSpec {
    /// The keyword with this name (case-insensitive).
    pub fn keyword(&self, name: &str) -> Option<&Keyword> {
        self.keywords
            .iter()
            .find(|k| k.name.eq_ignore_ascii_case(name))
    }

    /// The keyword with this type byte.
    pub fn keyword_for(&self, value: u8) -> Option<&Keyword> {
        self.keywords.iter().find(|k| k.value == value)
    }

    /// The operand that fills `field`, if the command has one.
    pub fn operand_for(&self, field: Field) -> Option<&Operand> {
        self.operands.iter().find(|o| o.kind.field() == field)
    }

    /// Whether `field` holds an operand of `kind`.
    pub fn field_is(&self, field: Field, kind: OperandKind) -> bool {
        self.operand_for(field).is_some_and(|o| o.kind == kind)
    }

    /// The name users type: the mnemonic, or the number for control functions.
    pub fn display_name(&self) -> String {
        if self.mnemonic.is_empty() {
            self.number.to_string()
        } else {
            self.mnemonic.clone()
        }
    }

    /// Usage line: `MVP ABS|REL|COORD, <motor>, <value>`.
    pub fn usage(&self) -> String {
        let parts: Vec<String> = self
            .operands
            .iter()
            .map(|o| {
                let text = if o.kind == OperandKind::Keyword && !self.keywords.is_empty() {
                    self.keywords
                        .iter()
                        .map(|k| k.name.as_str())
                        .collect::<Vec<_>>()
                        .join("|")
                } else {
                    o.kind.placeholder().to_string()
                };
                if o.optional {
                    format!("[{text}]")
                } else {
                    text
                }
            })
            .collect();
        if parts.is_empty() {
            self.display_name()
        } else {
            format!("{} {}", self.display_name(), parts.join(", "))
        }
    }

    /// Number of operands that must be given.
    pub fn required_operands(&self) -> usize {
        self.operands.iter().filter(|o| !o.optional).count()
    }
}

/// Words that exist only in ASCII mode (manual §6.6.3).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum AsciiWord {
    /// Leave ASCII mode, back to binary.
    Bin,
    /// Start the TMCL program in memory.
    Run,
    /// Stop the running TMCL program.
    Stop,
}

impl AsciiWord {
    /// The word from its spelling (case-insensitive).
    pub fn parse(word: &str) -> Option<AsciiWord> {
        match word.to_ascii_uppercase().as_str() {
            "BIN" => Some(AsciiWord::Bin),
            "RUN" => Some(AsciiWord::Run),
            "STOP" => Some(AsciiWord::Stop),
            _ => None,
        }
    }

    /// The word as sent.
    pub fn as_str(self) -> &'static str {
        match self {
            AsciiWord::Bin => "BIN",
            AsciiWord::Run => "RUN",
            AsciiWord::Stop => "STOP",
        }
    }
}

/// A command row whose words name nothing the table knows.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub(crate) enum CommandRowError {
    /// An operand kind that is not one.
    #[error("command {number}: unknown operand kind '{kind}'")]
    Operand {
        /// The command's number.
        number: u8,
        /// The kind as written (with its `?`).
        kind: String,
    },
    /// A `param_use` other than read, write or store.
    #[error("command {number}: unknown param_use '{word}'")]
    ParamUse {
        /// The command's number.
        number: u8,
        /// The word as written.
        word: String,
    },
}

impl CommandRowError {
    /// The number of the command whose row it is.
    pub(crate) fn number(&self) -> u8 {
        match self {
            CommandRowError::Operand { number, .. } | CommandRowError::ParamUse { number, .. } => {
                *number
            }
        }
    }
}

/// All commands of a profile.
#[derive(Debug, Clone, PartialEq)]
pub struct CommandTable {
    commands: Vec<CommandSpec>,
    ascii_words: Vec<String>,
    /// Commands of the built-in table this module does not have, with the profile's reason.
    absent: Vec<(CommandSpec, String)>,
}

impl CommandTable {
    pub(crate) fn from_rows(
        rows: &[CommandRow],
        ascii_words: Vec<String>,
    ) -> Result<Self, CommandRowError> {
        let mut commands = Vec::with_capacity(rows.len());
        for row in rows {
            let operands = row
                .operands
                .iter()
                .map(|text| {
                    let (word, optional) = match text.strip_suffix('?') {
                        Some(word) => (word, true),
                        None => (text.as_str(), false),
                    };
                    OperandKind::parse(word)
                        .map(|kind| Operand { kind, optional })
                        .ok_or_else(|| CommandRowError::Operand {
                            number: row.number,
                            kind: text.clone(),
                        })
                })
                .collect::<Result<Vec<_>, _>>()?;
            commands.push(CommandSpec {
                number: row.number,
                mnemonic: row.mnemonic.to_ascii_uppercase(),
                name: row.name.clone(),
                ascii_allowed: row.ascii_allowed,
                direct_mode: row.direct_mode,
                standalone: row.standalone,
                operands,
                keywords: row.types.iter().map(keyword).collect(),
                value_range: row.value_range.map(|[lo, hi]| (lo, hi)),
                param_use: match row.param_use.as_deref() {
                    None => None,
                    Some("read") => Some(ParamUse::Read),
                    Some("write") => Some(ParamUse::Write),
                    Some("store") => Some(ParamUse::Store),
                    Some(other) => {
                        return Err(CommandRowError::ParamUse {
                            number: row.number,
                            word: other.to_string(),
                        });
                    }
                },
                starts_motion: row.starts_motion,
                uncertain: row.uncertain,
                banks: row.banks.clone(),
                banks_note: row.banks_note.clone(),
                range_when: RangeWhen::from_rows(&row.range_when),
                type_ignored: row.type_ignored,
                motor_ignored: row.motor_bank.starts_with("don't care"),
            });
        }
        let ascii_words = ascii_words.iter().map(|w| w.to_ascii_uppercase()).collect();
        Ok(CommandTable {
            commands,
            ascii_words,
            absent: Vec::new(),
        })
    }

    /// Every command, in table order.
    pub fn iter(&self) -> impl Iterator<Item = &CommandSpec> {
        self.commands.iter()
    }

    /// The command with this mnemonic (case-insensitive).
    pub fn by_mnemonic(&self, mnemonic: &str) -> Option<&CommandSpec> {
        if mnemonic.is_empty() {
            return None;
        }
        self.commands
            .iter()
            .find(|c| c.mnemonic.eq_ignore_ascii_case(mnemonic))
    }

    /// The command with this number (a `u8` or an opcode).
    pub fn by_number(&self, number: impl Into<u8>) -> Option<&CommandSpec> {
        let number = number.into();
        self.commands.iter().find(|c| c.number == number)
    }

    /// Whether `word` is a mnemonic or an ASCII-only word.
    pub fn is_word(&self, word: &str) -> bool {
        self.by_mnemonic(word).is_some() || self.ascii_word(word).is_some()
    }

    /// The ASCII-only word, if `word` is one this profile lists.
    pub fn ascii_word(&self, word: &str) -> Option<AsciiWord> {
        let upper = word.to_ascii_uppercase();
        if self.ascii_words.contains(&upper) {
            AsciiWord::parse(&upper)
        } else {
            None
        }
    }

    /// Mnemonics and ASCII words, for completion and suggestions.
    pub fn words(&self) -> impl Iterator<Item = &str> {
        self.commands
            .iter()
            .map(|c| c.mnemonic.as_str())
            .filter(|m| !m.is_empty())
            .chain(self.ascii_words.iter().map(String::as_str))
    }
}

/// How a module's table differs from the built-in one (profile `[commands]`, `[[extra_command]]`,
/// `[ascii]`).
impl CommandTable {
    /// Takes out the commands numbered in `numbers`, remembering them with `reason`.
    pub(crate) fn remove(&mut self, numbers: &[u8], reason: &str) {
        let (gone, kept) = std::mem::take(&mut self.commands)
            .into_iter()
            .partition(|c| numbers.contains(&c.number));
        self.commands = kept;
        let gone: Vec<CommandSpec> = gone;
        self.absent
            .extend(gone.into_iter().map(|c| (c, reason.to_string())));
    }

    /// Adds the commands of `other`, in number order with the rest.
    pub(crate) fn extend(&mut self, other: CommandTable) {
        self.commands.extend(other.commands);
        self.commands.sort_by_key(|c| c.number);
    }

    /// Gives command `number` the module's own value range: the built-in table's conditional
    /// ranges (the TMCM-142's unit mode) do not apply to it.
    pub(crate) fn set_value_range(&mut self, number: u8, range: (i64, i64)) {
        if let Some(command) = self.commands.iter_mut().find(|c| c.number == number) {
            command.value_range = Some(range);
            command.range_when.clear();
        }
    }

    /// Keeps the commands' conditional ranges whose condition `keep` accepts.
    pub(crate) fn keep_range_when(&mut self, keep: impl Fn(&Condition) -> bool) {
        for command in &mut self.commands {
            command.range_when.retain(|r| keep(&r.when));
        }
    }

    /// The words that exist only in ASCII mode.
    pub(crate) fn set_ascii_words(&mut self, words: &[String]) {
        self.ascii_words = words.iter().map(|w| w.to_ascii_uppercase()).collect();
    }

    /// The mnemonics of the commands accepted in ASCII mode, in table order.
    pub fn ascii_mnemonics(&self) -> Vec<&str> {
        self.commands
            .iter()
            .filter(|c| c.ascii_allowed)
            .map(|c| c.mnemonic.as_str())
            .collect()
    }

    /// Makes `mnemonics` (case-insensitive) the commands accepted in ASCII mode, and no others.
    pub(crate) fn set_ascii_allowed(&mut self, mnemonics: &[String]) {
        for command in &mut self.commands {
            command.ascii_allowed = !command.mnemonic.is_empty()
                && mnemonics
                    .iter()
                    .any(|m| m.eq_ignore_ascii_case(&command.mnemonic));
        }
    }

    /// A command of the built-in table this module does not have, by mnemonic, with the reason.
    pub fn absent(&self, mnemonic: &str) -> Option<(&CommandSpec, &str)> {
        self.absent
            .iter()
            .find(|(c, _)| !c.mnemonic.is_empty() && c.mnemonic.eq_ignore_ascii_case(mnemonic))
            .map(|(c, reason)| (c, reason.as_str()))
    }

    /// Every command of the built-in table this module does not have, with the reason.
    pub fn absent_commands(&self) -> impl Iterator<Item = (&CommandSpec, &str)> {
        self.absent.iter().map(|(c, reason)| (c, reason.as_str()))
    }
}

fn keyword(row: &KeywordRow) -> Keyword {
    Keyword {
        value: row.value,
        name: row.name.to_ascii_uppercase(),
        meaning: row.meaning.clone(),
    }
}

#[cfg(test)]
mod tests {
    use crate::dialect::tmcl::profile::Profile;

    use super::*;

    #[test]
    fn the_ascii_list_is_exactly_the_manual_list() {
        let profile = Profile::builtin();
        let mut ascii: Vec<&str> = profile.commands.ascii_mnemonics();
        ascii.sort();
        let mut manual = vec![
            "ROL", "ROR", "MST", "MVP", "SAP", "GAP", "STAP", "RSAP", "SGP", "GGP", "STGP", "RSGP",
            "RFS", "SIO", "GIO", "SAC", "SCO", "GCO", "CCO", "UF0", "UF1", "UF2", "UF3", "UF4",
            "UF5", "UF6", "UF7",
        ];
        manual.sort();
        assert_eq!(ascii, manual);
        for word in ["BIN", "RUN", "STOP", "bin"] {
            assert!(profile.commands.ascii_word(word).is_some(), "{word}");
        }
    }

    #[test]
    fn every_command_of_the_reference_is_present() {
        let profile = Profile::builtin();
        let numbers: Vec<u8> = profile.commands.iter().map(|c| c.number).collect();
        for n in (1..=15)
            .chain(19..=24)
            .chain(27..=36)
            .chain([39])
            .chain(64..=71)
            .chain(128..=139)
        {
            assert!(numbers.contains(&n), "command {n} missing");
        }
    }

    #[test]
    fn keywords_and_layouts_come_from_the_data() {
        let profile = Profile::builtin();
        let mvp = profile.commands.by_mnemonic("mvp").unwrap();
        assert_eq!(mvp.number, 4);
        assert_eq!(mvp.keyword("coord").unwrap().value, 2);
        assert_eq!(mvp.usage(), "MVP ABS|REL|COORD, <motor>, <value>");
        let wait = profile.commands.by_mnemonic("WAIT").unwrap();
        assert_eq!(wait.keyword("RFS").unwrap().value, 4);
        let calc = profile.commands.by_mnemonic("CALC").unwrap();
        assert_eq!(calc.required_operands(), 1);
        assert_eq!(
            profile.commands.by_number(136).unwrap().display_name(),
            "136"
        );
        assert_eq!(
            profile
                .commands
                .by_mnemonic("SAP")
                .unwrap()
                .operand_for(Field::Motor)
                .unwrap()
                .kind,
            OperandKind::Motor
        );
    }
}
