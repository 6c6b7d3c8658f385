//! Integration tests: the real `tmclsh` binary, over pseudo-terminals and loopback TCP, against
//! the simulator. One test binary keeps link times low (see TESTING.md).

mod util;

mod asm;
mod binary_session;
mod bus;
mod can;
mod catalogue;
mod cli;
mod commission;
mod dialect_echo;
mod fuzz_corpus;
#[cfg(feature = "hardware")]
mod hardware;
mod hostile;
mod hot_path;
mod identify;
mod inputs;
mod layers;
mod lost;
mod mixed_bus;
mod module_reset;
mod options;
mod profiles;
mod program;
mod repl;
#[cfg(unix)]
mod reply_noise;
mod safety;
mod script;
mod shared_line;
mod shell;
mod sim;
mod smd4;
mod soak;
mod typeahead;
