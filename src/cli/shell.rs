//! `tmclsh [CONNECTION] [-c LINE]...`: the shell — the REPL on a terminal, otherwise the `-c`
//! lines or stdin lines.

use std::io::IsTerminal;

use crate::dialect::{Configured, Purpose};
use crate::exit::Exit;
use crate::session::interrupt;
use crate::shell::Shell;
use crate::shell::batch::{self, Lines};

use super::Failure;
use super::connection::{Audience, ModuleArgs};

/// Flags of the shell itself.
#[derive(Debug, Clone, clap::Args)]
pub struct ShellArgs {
    /// Execute LINE and exit (repeatable; executed in order). Without -c, lines are read from
    /// stdin when it is not a terminal.
    #[arg(short = 'c', value_name = "LINE")]
    pub commands: Vec<String>,
    /// Which module, and how to talk to it.
    #[command(flatten)]
    pub module: ModuleArgs,
}

/// Runs the shell: the REPL on a terminal, otherwise the `-c` lines or stdin lines.
pub fn run(args: ShellArgs, configs: &Configured) -> Result<Exit, Failure> {
    interrupt::install();
    let interactive = args.commands.is_empty() && std::io::stdin().is_terminal();
    let audience = if interactive {
        Audience::Interactive
    } else {
        Audience::Batch
    };
    let session = args.module.open(configs, audience, Purpose::Talk)?;
    let mut shell = Shell::new(session);
    if interactive {
        let banner = banner(&args.module, &shell, configs);
        return Ok(crate::repl::run(&mut shell, &banner));
    }
    let lines = if args.commands.is_empty() {
        Lines::stdin()
    } else {
        Lines::Given(args.commands.into_iter())
    };
    let mut out = std::io::stdout().lock();
    let mut err = std::io::stderr().lock();
    Ok(batch::run(&mut shell, lines, &mut out, &mut err))
}

fn banner(module: &ModuleArgs, shell: &Shell, configs: &Configured) -> String {
    let version = env!("CARGO_PKG_VERSION");
    if module.connection.is_builtin() {
        let module = configs.of(module.protocol()).simulated_module();
        format!("tmclsh {version} — simulated {module} (built-in) — use --port to talk to hardware")
    } else {
        let module = shell.session_ref().banner();
        format!(
            "tmclsh {version} — {module} on {}",
            shell.session_ref().describe()
        )
    }
}
