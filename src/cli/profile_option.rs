//! `--profile`, declared by each command that reads module tables (the shell, the commands that
//! open a session, `params`, `asm`, `disasm`, `transcript`, `sim`) and by no other, so that the
//! help of `ports`, `completions`, `man` and `profiles` does not offer it. Its value is read from
//! the innermost command's matches (`cli::parse_with`).

use std::path::PathBuf;

use clap::{Arg, ArgMatches, Args, Command, FromArgMatches};

/// The argument id, shared with the configuration file's key.
pub(super) const ID: &str = "profile";

/// Adds `--profile` to the command it is flattened into; holds nothing.
#[derive(Debug, Clone)]
pub struct ProfileOption;

impl FromArgMatches for ProfileOption {
    fn from_arg_matches(_: &ArgMatches) -> Result<Self, clap::Error> {
        Ok(ProfileOption)
    }

    fn update_from_arg_matches(&mut self, _: &ArgMatches) -> Result<(), clap::Error> {
        Ok(())
    }
}

impl Args for ProfileOption {
    fn augment_args(cmd: Command) -> Command {
        cmd.arg(
            Arg::new(ID)
                .long("profile")
                .value_name("NAME|FILE")
                .env("TMCLSH_PROFILE")
                .value_parser(clap::value_parser!(PathBuf))
                .help(
                    "Module profile instead of the TMCM-142's: a built-in name, alias or module \
                     number (`tmclsh profiles` lists them: tmcm-6110, pd-1141, 6110, generic …) \
                     or a TOML file (schema in docs/profiles.md)",
                ),
        )
    }

    fn augment_args_for_update(cmd: Command) -> Command {
        Self::augment_args(cmd)
    }
}

/// The profile given to the innermost command of `matches` (command line, environment or a
/// configuration file's default), if it takes one.
pub(super) fn given(leaf: &ArgMatches) -> Option<PathBuf> {
    leaf.try_get_one::<PathBuf>(ID).ok().flatten().cloned()
}
