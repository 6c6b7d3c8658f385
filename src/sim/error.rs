//! Why a simulator refuses: a console command it cannot run ([`ConsoleError`], the text after
//! `error: ` on the console's answer line), or flags it cannot start from ([`SimStartError`],
//! exit 2 before anything is served). Both simulators share them, so the same mistake reads the
//! same on each.

use super::store::StoreError;
use crate::exit::{Exit, ExitStatus};

/// Why a console command was refused.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum ConsoleError {
    /// No console knows the command (its first word).
    #[error("unknown command '{0}'; try help")]
    Unknown(String),
    /// The command works only when the simulator is served another way.
    #[error("{command} needs {what}")]
    Needs {
        /// The command (`advance`).
        command: &'static str,
        /// What it needs, with the way out where there is one (`--manual-clock`).
        what: &'static str,
    },
    /// A word the command cannot read, and what it takes: `'x' is not a level; use 0 or 1`.
    #[error("'{word}' is not {expected}")]
    BadArgument {
        /// The word as typed.
        word: String,
        /// What the command takes there, with a hint how to write it.
        expected: &'static str,
    },
    /// A time `advance` cannot read (the duration grammar's own message).
    #[error(transparent)]
    Time(#[from] crate::duration::DurationError),
    /// A value beyond what the device takes: `analog value 5000 is out of range 0..4095`.
    #[error("{what} {value} is out of range 0..{max}")]
    OutOfRange {
        /// What the value is (`analog value`).
        what: &'static str,
        /// The value given.
        value: i32,
        /// The largest the device takes.
        max: i32,
    },
    /// No module at that factory address on the bus.
    #[error("no module {slot} on the bus (modules: {on_bus:?})")]
    NoModule {
        /// The address asked for.
        slot: u8,
        /// The addresses there are.
        on_bus: Vec<u8>,
    },
    /// The module has fewer motors.
    #[error("the {module} has no motor {motor} (motors 0..{})", .motors - 1)]
    NoMotor {
        /// The module's name (`TMCM-142`).
        module: String,
        /// The motor asked for.
        motor: u8,
        /// How many motors it has.
        motors: usize,
    },
    /// No module at that address with that motor (what `motor [M]` asked about).
    #[error("no module {slot} with a motor {motor}")]
    NoModuleMotor {
        /// The module's factory address.
        slot: u8,
        /// The motor.
        motor: u8,
    },
    /// The module has no such output.
    #[error("no output {0}")]
    NoOutput(u8),
    /// The module has no such input, and the ones it has.
    #[error("no {kind} input {port}; inputs are {}", list(.ports))]
    NoInput {
        /// `digital` or `analog`.
        kind: &'static str,
        /// The port asked for.
        port: u8,
        /// The inputs of that kind there are.
        ports: Vec<u8>,
    },
    /// The drive has no such setting.
    #[error("no setting {0}")]
    NoSetting(String),
    /// The drive has no error flag of that name, and the ones it has.
    #[error("no error flag '{name}'; use one of {}", .known.join(", "))]
    NoFlag {
        /// The name as typed.
        name: String,
        /// The flags there are, each `BIT LABEL`.
        known: Vec<String>,
    },
    /// An error flag bit past the 16 of EFLAGS.
    #[error("EFLAGS has bits 0..15, not {0}")]
    NoBit(u8),
}

impl ConsoleError {
    /// `word` is not what the command takes there (`expected`, with its hint).
    pub fn bad(word: &str, expected: &'static str) -> Self {
        ConsoleError::BadArgument {
            word: word.to_string(),
            expected,
        }
    }
}

/// Ports as a list in a message: `0, 1, 2`.
fn list(ports: &[u8]) -> String {
    let ports: Vec<String> = ports.iter().map(u8::to_string).collect();
    ports.join(", ")
}

/// Why `tmclsh sim` cannot start the simulator its flags describe.
#[derive(Debug, thiserror::Error)]
pub enum SimStartError {
    /// The flags did not read back from the parsed command line (clap's own message).
    #[cfg(feature = "cli")]
    #[error(transparent)]
    Flags(#[from] clap::Error),
    /// A module address out of 1..255 (`--modules`).
    #[error("module address {0} is out of range 1..255")]
    AddressRange(i64),
    /// A word that is no module address (`--modules`).
    #[error("'{0}' is not a module address (1..255)")]
    NotAnAddress(String),
    /// `N:` with nothing after the colon (`--modules`).
    #[error("'{0}' names no profile after the ':'")]
    NoProfile(String),
    /// The profile named with a module cannot be had (the dialect's own error).
    #[error("{0}")]
    Profile(Box<dyn std::error::Error + Send + Sync>),
    /// A word of `--boot-loader=LIST` that is no module address.
    #[error("'{word}' is not a module address (1..255) in --boot-loader={list}")]
    BootLoaderAddress {
        /// The word as written.
        word: String,
        /// The whole list.
        list: String,
    },
    /// A switch flag's motor that is no motor number.
    #[error("'{word}' is not a motor number (0..255) in '{spec}'")]
    NotAMotor {
        /// The word as written.
        word: String,
        /// The whole `MOTOR:POS`.
        spec: String,
    },
    /// A switch position that is no whole number of microsteps.
    #[error("'{0}' is not a position in microsteps")]
    NotAPosition(String),
    /// A value that must be a positive number.
    #[error("'{0}' is not a positive number")]
    NotPositive(String),
    /// A real-value grid coarser than the reply check admits.
    #[error(
        "a step of {step} puts real values further from the user value than a drive's \
         resolution (at most {widest})"
    )]
    GridTooCoarse {
        /// The step given.
        step: f64,
        /// The widest step the check admits.
        widest: f64,
    },
    /// `--modules` names an address twice.
    #[error("module address {0} is given twice in --modules")]
    Twice(u8),
    /// `--boot-loader=N` names a module `--modules` does not put on the bus.
    #[error("--boot-loader names module {0}, which is not on the bus (--modules)")]
    BootLoaderOffBus(u8),
    /// A switch flag names a motor no module on the bus has.
    #[error(
        "{flag} {motor}:{position}: no module on the bus has a motor {motor} (motors 0..{})",
        .motors - 1
    )]
    NoMotor {
        /// The flag (`--left-switch`).
        flag: &'static str,
        /// The motor it names.
        motor: u8,
        /// The switch position given with it.
        position: i64,
        /// The most motors a module on the bus has.
        motors: u8,
    },
    /// The `--state` file cannot be read.
    #[error(transparent)]
    Store(#[from] StoreError),
    /// The `--state` file is not one the simulator wrote.
    #[error("state file {path} is damaged ({message}); delete it to start from factory settings")]
    Damaged {
        /// The file.
        path: String,
        /// What is wrong.
        message: String,
    },
}

/// Every start-up error is a refusal: nothing was served yet.
impl ExitStatus for SimStartError {
    fn exit(&self) -> Exit {
        Exit::Refused
    }
}
