//! Switches for each point where the SMD4 document contradicts itself or stays silent, so that a
//! client can be tested against every reading. The defaults follow the document's text where it
//! states a rule and its examples where they agree with each other.

use std::path::PathBuf;

use crate::dialect::smd4::protocol::{ErrorSpelling, FlagCase, FloatStyle, PrefixStyle};

/// Which request forms of the address prefix the simulated drive understands.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum PrefixAcceptance {
    /// `@3MOTOR:STOP` and `@3,MOTOR:STOP`.
    #[default]
    Either,
    /// Only this form; the other is a malformed packet.
    Only(PrefixStyle),
}

impl PrefixAcceptance {
    /// Whether a packet written in `style` is well formed.
    pub fn accepts(self, style: PrefixStyle) -> bool {
        match self {
            PrefixAcceptance::Either => true,
            PrefixAcceptance::Only(only) => only == style,
        }
    }
}

/// How PACT and PREL are reported.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum PositionFormat {
    /// `1000.00`, as the examples show.
    #[default]
    Fixed,
    /// Like every other FLOAT, as the type table says.
    Scientific,
}

/// Options of a simulated SMD4.
#[derive(Debug, Clone, PartialEq)]
pub struct Smd4SimOptions {
    /// Hex case of the flag words (text: upper; many examples: lower).
    pub flag_case: FlagCase,
    /// Decimals of FLOATs (examples: 4; type table: 5) and the `E`-less form of two examples.
    pub float_style: FloatStyle,
    /// Spelling of error items (undocumented).
    pub error_spelling: ErrorSpelling,
    /// Round IR/IA/IH to k·1.044/31 A as the text says (the examples echo unrounded values).
    pub current_rounding: bool,
    /// Request forms of the address prefix that are understood.
    pub prefix: PrefixAcceptance,
    /// Put `@N,` before replies to addressed packets, as the reply template shows (no example does).
    pub reply_prefix: bool,
    /// PACT/PREL number format.
    pub position_format: PositionFormat,
    /// Report MOTOR:TZW in milliseconds as its example does (its argument is in seconds).
    pub tzw_reply_ms: bool,
    /// Real values of user/real pairs on this grid (Hz or Hz/s); `None` echoes the user value,
    /// since the conversion is not documented.
    pub real_value_grid: Option<f64>,
    /// Leave out the data item the document declares no return for (SYS:FLAGS' `1`).
    pub omit_optional_item: bool,
    /// Where STORE saves the configuration and power-up reads it; `None` keeps it in memory.
    pub state_file: Option<PathBuf>,
}

impl Default for Smd4SimOptions {
    fn default() -> Self {
        Smd4SimOptions {
            flag_case: FlagCase::Upper,
            float_style: FloatStyle::default(),
            error_spelling: ErrorSpelling::Parenthesised,
            current_rounding: true,
            prefix: PrefixAcceptance::Either,
            reply_prefix: true,
            position_format: PositionFormat::Fixed,
            tzw_reply_ms: false,
            real_value_grid: None,
            omit_optional_item: false,
            state_file: None,
        }
    }
}
