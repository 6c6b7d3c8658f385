//! `tmclsh completions SHELL --install` and `tmclsh man --install`: the completion script or the
//! manual page written where the user's shell and `man` look for them without root, following
//! the XDG base directories (docs/install.md lists the places, and the system-wide ones). The
//! file is written by the project's file policy (`crate::file`): a symlink, a directory or a
//! device in its place is refused, never followed or replaced.

use std::io::Write;
use std::path::{Path, PathBuf};

use clap_complete::Shell;

use crate::exit::{Exit, ExitStatus, Failure};
use crate::file::{self, FileError, Follow, Mode};

/// Arguments of `man`.
#[derive(Debug, clap::Args)]
pub(super) struct ManArgs {
    /// Write the page to $XDG_DATA_HOME/man/man1/tmclsh.1 (~/.local/share/man/man1) instead of
    /// printing it, and say where.
    #[arg(long)]
    pub install: bool,
}

/// Why nothing was installed.
#[derive(Debug, thiserror::Error)]
pub(super) enum InstallError {
    #[error("no home directory to install into: set HOME (or XDG_DATA_HOME, XDG_CONFIG_HOME)")]
    NoHome,
    #[error(
        "{0} has no standard place for completion scripts; print the script with `tmclsh \
         completions {0}` and load it from your {0} configuration"
    )]
    NoPlace(Shell),
    #[error("cannot create the directory {}: {reason}", .dir.display())]
    Directory { dir: PathBuf, reason: String },
    #[error("cannot install {0}")]
    File(#[from] FileError),
}

impl ExitStatus for InstallError {
    fn exit(&self) -> Exit {
        Exit::Refused
    }
}

/// What is installed where, and what the user may need to know to have it loaded.
struct Place {
    path: PathBuf,
    note: &'static str,
}

/// The environment the places are found from (the process's, or a test's).
pub(super) trait Env {
    fn var(&self, name: &str) -> Option<String>;
}

/// The process environment.
pub(super) struct ProcessEnv;

impl Env for ProcessEnv {
    fn var(&self, name: &str) -> Option<String> {
        std::env::var(name).ok()
    }
}

/// `$NAME` when it is an absolute path (the XDG rule: a relative or empty one is ignored), else
/// `$HOME/default`.
fn base(env: &dyn Env, name: &str, default: &str) -> Result<PathBuf, InstallError> {
    if let Some(dir) = env.var(name).filter(|d| Path::new(d).is_absolute()) {
        return Ok(PathBuf::from(dir));
    }
    match env.var("HOME").filter(|h| Path::new(h).is_absolute()) {
        Some(home) => Ok(Path::new(&home).join(default)),
        None => Err(InstallError::NoHome),
    }
}

fn data_home(env: &dyn Env) -> Result<PathBuf, InstallError> {
    base(env, "XDG_DATA_HOME", ".local/share")
}

/// Where `shell` loads a user's completion script from.
fn completion_place(shell: Shell, env: &dyn Env) -> Result<Place, InstallError> {
    Ok(match shell {
        Shell::Bash => Place {
            path: data_home(env)?.join("bash-completion/completions/tmclsh"),
            note: "the bash-completion package loads it in new shells (bash alone has no \
                   completion loader)",
        },
        Shell::Zsh => Place {
            path: data_home(env)?.join("zsh/site-functions/_tmclsh"),
            note: "zsh loads it when its directory is in fpath before compinit: add \
                   fpath=(~/.local/share/zsh/site-functions $fpath) to ~/.zshrc \
                   ($ZDOTDIR/.zshrc if you set ZDOTDIR)",
        },
        Shell::Fish => Place {
            path: base(env, "XDG_CONFIG_HOME", ".config")?.join("fish/completions/tmclsh.fish"),
            note: "fish loads it in new shells",
        },
        other => return Err(InstallError::NoPlace(other)),
    })
}

/// Where `man` finds a user's page.
fn man_place(env: &dyn Env) -> Result<Place, InstallError> {
    Ok(Place {
        path: data_home(env)?.join("man/man1/tmclsh.1"),
        note: "`man tmclsh` finds it where ~/.local/bin is on PATH; otherwise export \
               MANPATH=\"$HOME/.local/share/man:\"",
    })
}

/// Writes `bytes` to `place`, making its directories; a regular file there is replaced, anything
/// else (a symlink too) refused.
fn write(place: &Place, bytes: &[u8]) -> Result<(), InstallError> {
    if let Some(dir) = place.path.parent() {
        std::fs::create_dir_all(dir).map_err(|e| InstallError::Directory {
            dir: dir.to_path_buf(),
            reason: file::io_reason(&e),
        })?;
    }
    let mut out = file::open(&place.path, Mode::Write, Follow::No)?;
    let io = |e: std::io::Error| FileError::io(&place.path, "write", &e);
    out.set_len(0).map_err(io)?;
    out.write_all(bytes).map_err(io)?;
    Ok(())
}

fn install(
    place: Result<Place, InstallError>,
    bytes: &[u8],
    out: &mut dyn Write,
) -> Result<Exit, Failure> {
    let place = place?;
    write(&place, bytes)?;
    writeln!(out, "wrote {}; {}", place.path.display(), place.note)?;
    Ok(Exit::Success)
}

/// `tmclsh completions SHELL --install`.
pub(super) fn completions(shell: Shell, out: &mut dyn Write) -> Result<Exit, Failure> {
    let place = completion_place(shell, &ProcessEnv);
    install(place, &super::completions::generate(shell), out)
}

/// `tmclsh man`, printed or installed.
pub(super) fn man(args: &ManArgs, out: &mut dyn Write) -> Result<Exit, Failure> {
    let page = super::man::render()?;
    if args.install {
        install(man_place(&ProcessEnv), &page, out)
    } else {
        out.write_all(&page)?;
        Ok(Exit::Success)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::HashMap;

    struct Vars(HashMap<&'static str, &'static str>);

    impl Env for Vars {
        fn var(&self, name: &str) -> Option<String> {
            self.0.get(name).map(|v| v.to_string())
        }
    }

    fn env(vars: &[(&'static str, &'static str)]) -> Vars {
        Vars(vars.iter().copied().collect())
    }

    #[test]
    fn the_places_follow_xdg_and_fall_back_to_home() {
        let home = env(&[("HOME", "/h")]);
        let path = |shell| completion_place(shell, &home).unwrap().path;
        assert_eq!(
            path(Shell::Bash),
            Path::new("/h/.local/share/bash-completion/completions/tmclsh")
        );
        assert_eq!(
            path(Shell::Zsh),
            Path::new("/h/.local/share/zsh/site-functions/_tmclsh")
        );
        assert_eq!(
            path(Shell::Fish),
            Path::new("/h/.config/fish/completions/tmclsh.fish")
        );
        assert_eq!(
            man_place(&home).unwrap().path,
            Path::new("/h/.local/share/man/man1/tmclsh.1")
        );
        let xdg = env(&[
            ("HOME", "/h"),
            ("XDG_DATA_HOME", "/d"),
            ("XDG_CONFIG_HOME", "/c"),
        ]);
        assert_eq!(
            man_place(&xdg).unwrap().path,
            Path::new("/d/man/man1/tmclsh.1")
        );
        assert_eq!(
            completion_place(Shell::Fish, &xdg).unwrap().path,
            Path::new("/c/fish/completions/tmclsh.fish")
        );
    }

    #[test]
    fn a_relative_xdg_directory_is_ignored_and_no_home_is_an_error() {
        let relative = env(&[("HOME", "/h"), ("XDG_DATA_HOME", "rel")]);
        assert_eq!(
            man_place(&relative).unwrap().path,
            Path::new("/h/.local/share/man/man1/tmclsh.1")
        );
        assert!(matches!(man_place(&env(&[])), Err(InstallError::NoHome)));
    }

    #[test]
    fn shells_without_a_standard_place_are_refused_with_a_hint() {
        let error = completion_place(Shell::Elvish, &env(&[("HOME", "/h")]))
            .err()
            .unwrap();
        assert!(
            error.to_string().contains("tmclsh completions elvish"),
            "{error}"
        );
    }
}
