//! The `tmclsh sim --protocol smd4` flags: each quirk of the SMD4 document behind a switch, so
//! clients can be tested against every reading of it.

use std::path::Path;

use clap::{ArgMatches, Args, Command, FromArgMatches};

use crate::dialect::SimFlags;
use crate::dialect::smd4::protocol::{ErrorSpelling, FlagCase, FloatStyle, PrefixStyle, Smd4Spec};
use crate::sim::Device;
use crate::sim::error::SimStartError;

use super::{PositionFormat, PrefixAcceptance, Smd4Sim, Smd4SimOptions};

/// Quirk switches of the simulated SMD4.
#[derive(Debug, Clone, clap::Args)]
#[command(next_help_heading = "SMD4 quirks (with --protocol smd4)")]
pub struct QuirkFlags {
    /// Hex case of the flag words: upper (0x088E, the text) or lower (0x088e, many examples).
    #[arg(long, value_name = "CASE", default_value = "upper", value_parser = ["upper", "lower"])]
    pub flag_case: String,
    /// Decimals of FLOAT replies: 4 (every example) or 5 (the type table).
    #[arg(long, value_name = "N", default_value_t = 4, value_parser = clap::value_parser!(u8).range(4..=5))]
    pub float_decimals: u8,
    /// Leave the E out of floats (1.0000+01), as two examples do.
    #[arg(long)]
    pub float_missing_e: bool,
    /// Spelling of error items: paren (-103 (Invalid Mnemonic)), comma (-103,Invalid Mnemonic)
    /// or bare (-103).
    #[arg(long, value_name = "HOW", default_value = "paren", value_parser = ["paren", "comma", "bare"])]
    pub error_spelling: String,
    /// Echo currents unrounded, as the examples do (the text rounds to 1.044/31 A steps).
    #[arg(long)]
    pub no_current_rounding: bool,
    /// Accept only one form of the address prefix: attached (@3MOTOR:STOP) or comma (@3,MOTOR:STOP).
    #[arg(long, value_name = "FORM", value_parser = ["attached", "comma"])]
    pub prefix_only: Option<String>,
    /// Send replies to addressed packets without the @N, prefix.
    #[arg(long)]
    pub no_reply_prefix: bool,
    /// Report PACT/PREL in scientific notation like other FLOATs (examples: 1000.00).
    #[arg(long)]
    pub scientific_positions: bool,
    /// Report MOTOR:TZW in milliseconds, as its example does (its argument is in seconds).
    #[arg(long)]
    pub tzw_reply_ms: bool,
    /// Put the real value of user/real pairs (VMAX, AMAX, VSTART …) on a grid of STEP Hz or Hz/s
    /// (the conversion is undocumented; 0.0027939677238464355 = 12 MHz/2^24/256 reproduces the
    /// VSTOP example). Without it the real value echoes the user value. At most 1, so each pair
    /// stays within the 0.5 the reply check allows ([user_real] in data/smd4.toml).
    #[arg(long, value_name = "STEP", value_parser = grid_step)]
    pub real_value_grid: Option<f64>,
    /// Answer SYS:FLAGS without the trailing item `1` only its example shows (the document
    /// declares no return for it).
    #[arg(long)]
    pub flags_without_item: bool,
}

fn positive(text: &str) -> Result<f64, SimStartError> {
    text.parse::<f64>()
        .ok()
        .filter(|x| x.is_finite() && *x > 0.0)
        .ok_or_else(|| SimStartError::NotPositive(text.to_string()))
}

/// A grid step whose real values the reply check admits: half a step off at most, so at most
/// twice the data's absolute user/real tolerance.
fn grid_step(text: &str) -> Result<f64, SimStartError> {
    let step = positive(text)?;
    let widest = Smd4Spec::builtin()
        .commands
        .iter()
        .find_map(|c| c.real_tolerance)
        .map_or(f64::INFINITY, |t| 2.0 * t.absolute);
    if step > widest {
        return Err(SimStartError::GridTooCoarse { step, widest });
    }
    Ok(step)
}

impl QuirkFlags {
    /// The options these switches select; `state` keeps STORE'd settings across restarts.
    pub fn options(&self, state: Option<&Path>) -> Smd4SimOptions {
        Smd4SimOptions {
            flag_case: if self.flag_case == "lower" {
                FlagCase::Lower
            } else {
                FlagCase::Upper
            },
            float_style: FloatStyle {
                decimals: self.float_decimals,
                missing_e: self.float_missing_e,
            },
            error_spelling: match self.error_spelling.as_str() {
                "comma" => ErrorSpelling::Comma,
                "bare" => ErrorSpelling::Bare,
                _ => ErrorSpelling::Parenthesised,
            },
            current_rounding: !self.no_current_rounding,
            prefix: match self.prefix_only.as_deref() {
                Some("attached") => PrefixAcceptance::Only(PrefixStyle::Attached),
                Some("comma") => PrefixAcceptance::Only(PrefixStyle::Comma),
                _ => PrefixAcceptance::Either,
            },
            reply_prefix: !self.no_reply_prefix,
            position_format: if self.scientific_positions {
                PositionFormat::Scientific
            } else {
                PositionFormat::Fixed
            },
            tzw_reply_ms: self.tzw_reply_ms,
            real_value_grid: self.real_value_grid,
            omit_optional_item: self.flags_without_item,
            state_file: state.map(Path::to_path_buf),
        }
    }

    /// The simulated drive; `verbose` logs its traffic to stderr.
    pub fn device(&self, state: Option<&Path>, verbose: bool) -> Box<dyn Device> {
        let sim = Smd4Sim::new(self.options(state));
        if verbose {
            Box::new(sim.with_log(Box::new(|line: &str| eprintln!("sim {line}"))))
        } else {
            Box::new(sim)
        }
    }
}

/// Adds the flags of `group` to `tmclsh sim`.
pub fn add(group: SimFlags, cmd: Command) -> Command {
    match group {
        SimFlags::Quirks => QuirkFlags::augment_args(cmd),
        SimFlags::Bus | SimFlags::Module => cmd,
    }
}

/// The quirk switches are not refused with another simulator: each has a default, and none
/// changes what another simulator does.
pub fn given(_: &ArgMatches) -> Option<&'static str> {
    None
}

/// The simulated drive the quirk switches describe.
pub fn served(
    matches: &ArgMatches,
    state: Option<&Path>,
    verbose: bool,
) -> Result<Box<dyn Device>, SimStartError> {
    let flags = QuirkFlags::from_arg_matches(matches)?;
    Ok(flags.device(state, verbose))
}
