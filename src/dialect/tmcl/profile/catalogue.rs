//! The built-in profiles: every file of `data/profiles/`, built into the binary and found by name
//! (`tmcm-6110`), by alias (`pd-1141`) or by module number (`6110`), and the generic profile for a
//! module none of them describes.
//!
//! # For identification on connect
//!
//! A session that has read the module's 136 type-0 answer hands it to [`identify`]: a firmware
//! answer gives the profile of its module number ([`Identified::Known`]) or the generic one
//! ([`Identified::Unknown`], with [`GENERIC_NOTICE`] to show for each unknown module); a boot-loader answer
//! ([`Identified::BootLoader`]) means nothing else may be sent. [`Identified::banner`] is the line
//! the banner and `-v` print (`TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in)`). An
//! explicit `--profile` is [`resolve`]d instead and wins over what the module says. The pieces are
//! public on their own: [`version::FirmwareVersion::parse`](super::version::FirmwareVersion::parse),
//! [`by_module_number`], [`by_name`], [`generic`].
//!
//! Each profile is parsed once per process, when first asked for.

use std::path::Path;
use std::sync::{Arc, OnceLock};

use super::version::{FirmwareVersion, VersionError};
use super::{Profile, ProfileError};
use crate::suggest;

/// The profile used when none is asked for.
pub const DEFAULT: &str = "tmcm-142";

/// The name of the generic profile.
pub const GENERIC: &str = "generic";

/// The one line a session with the generic profile shows.
pub const GENERIC_NOTICE: &str = "generic TMCL profile: commands and motors 0..5 are checked, \
    parameters by number only (0..255, no names, values unchecked); `tmclsh profiles` lists the \
    modules with tables";

/// One built-in profile file.
#[derive(Debug, Clone, Copy)]
pub struct Builtin {
    /// The name users give (the file's stem): `tmcm-6110`.
    pub name: &'static str,
    /// Its path in the source repository.
    pub file: &'static str,
    text: &'static str,
}

macro_rules! builtin {
    ($name:literal) => {
        Builtin {
            name: $name,
            file: concat!("data/profiles/", $name, ".toml"),
            text: include_str!(concat!("../../../../data/profiles/", $name, ".toml")),
        }
    };
}

/// Every file of `data/profiles/` (a test holds this list to the folder), the default first.
pub const BUILTINS: &[Builtin] = &[
    builtin!("tmcm-142"),
    builtin!("tmcm-1021"),
    builtin!("tmcm-1140"),
    builtin!("tmcm-1141"),
    builtin!("tmcm-1160"),
    builtin!("tmcm-1260"),
    builtin!("tmcm-3110"),
    builtin!("tmcm-6110"),
    builtin!("tmcm-6214"),
];

/// The generic profile's file: the built-in command table, no parameters.
const GENERIC_TOML: &str = include_str!("../../../../data/generic.toml");

/// Every built-in profile, parsed (in [`BUILTINS`] order).
pub fn all() -> &'static [Arc<Profile>] {
    static ALL: OnceLock<Vec<Arc<Profile>>> = OnceLock::new();
    ALL.get_or_init(|| BUILTINS.iter().map(Builtin::profile).collect())
}

impl Builtin {
    /// The profile, parsed the first time it is asked for (alone: identifying a module on
    /// connect parses the one profile its number names, not all of them).
    pub fn profile(&self) -> Arc<Profile> {
        static PARSED: [OnceLock<Arc<Profile>>; BUILTINS.len()] =
            [const { OnceLock::new() }; BUILTINS.len()];
        let index = BUILTINS
            .iter()
            .position(|b| b.name == self.name)
            .expect("a listed built-in profile");
        PARSED[index]
            .get_or_init(|| {
                if self.name == DEFAULT {
                    return Profile::builtin();
                }
                let mut profile = Profile::from_text(self.text, self.file)
                    .unwrap_or_else(|e| panic!("the built-in profile {} is valid: {e}", self.file));
                profile.name = self.name.to_string();
                Arc::new(profile)
            })
            .clone()
    }

    /// The module number its file declares (`[meta] module_number`, the first such line),
    /// read without parsing the file; a test holds it to the parsed profile's.
    pub fn declared_number(&self) -> Option<u32> {
        self.text.lines().find_map(|line| {
            let value = line.trim_start().strip_prefix("module_number")?;
            value.trim_start().strip_prefix('=')?.trim().parse().ok()
        })
    }
}

/// The generic TMCL profile: the standard commands, motors 0..5, parameters by number only.
pub fn generic() -> Arc<Profile> {
    static GENERIC_PROFILE: OnceLock<Arc<Profile>> = OnceLock::new();
    GENERIC_PROFILE
        .get_or_init(|| {
            let mut profile = Profile::from_text(GENERIC_TOML, "data/generic.toml")
                .unwrap_or_else(|e| panic!("the generic profile data/generic.toml is valid: {e}"));
            profile.name = GENERIC.to_string();
            Arc::new(profile)
        })
        .clone()
}

/// The built-in profile with this name or alias (case-insensitive), or `generic`.
pub fn by_name(name: &str) -> Option<Arc<Profile>> {
    if name.eq_ignore_ascii_case(GENERIC) {
        return Some(generic());
    }
    all()
        .iter()
        .find(|p| {
            p.name.eq_ignore_ascii_case(name)
                || p.module.eq_ignore_ascii_case(name)
                || p.identity
                    .aliases
                    .iter()
                    .any(|a| a.eq_ignore_ascii_case(name))
        })
        .cloned()
}

/// The built-in profile of the module with this number (what command 136 names).
pub fn by_module_number(number: u32) -> Option<Arc<Profile>> {
    BUILTINS
        .iter()
        .find(|b| b.declared_number() == Some(number))
        .map(Builtin::profile)
}

/// Every name `--profile` takes for a built-in profile: names, then aliases, then `generic`.
pub fn names() -> Vec<String> {
    let mut names: Vec<String> = all().iter().map(|p| p.name.clone()).collect();
    names.extend(
        all()
            .iter()
            .flat_map(|p| p.identity.aliases.iter().map(|a| a.to_ascii_lowercase())),
    );
    names.push(GENERIC.to_string());
    names
}

/// What `--profile NAME|FILE` names: a built-in profile by name, alias or module number first,
/// then a file (anything at the path, so a directory or a FIFO is refused as what it is). A
/// value that is neither is refused with the nearest name.
pub fn resolve(arg: &Path) -> Result<Arc<Profile>, ProfileError> {
    let text = arg.to_string_lossy();
    if let Some(profile) = by_name(&text) {
        return Ok(profile);
    }
    if let Some(profile) = text.parse::<u32>().ok().and_then(by_module_number) {
        return Ok(profile);
    }
    if arg.symlink_metadata().is_ok() || looks_like_a_path(&text) {
        return Profile::from_file(arg).map(Arc::new);
    }
    let suggestion = suggest::nearest(
        &text.to_ascii_lowercase(),
        names().iter().map(String::as_str),
    );
    Err(ProfileError::Unknown {
        name: text.into_owned(),
        suggestion,
    })
}

/// Whether a `--profile` value is meant as a file: it has a directory part or a `.toml` ending.
pub fn looks_like_a_path(text: &str) -> bool {
    text.contains(std::path::MAIN_SEPARATOR) || text.contains('/') || text.ends_with(".toml")
}

/// What a module's 136 answer tells about it.
#[derive(Debug, Clone)]
pub enum Identified {
    /// Its firmware answered and a built-in profile describes it.
    Known {
        /// The answer.
        version: FirmwareVersion,
        /// Its profile.
        profile: Arc<Profile>,
    },
    /// Its firmware answered; no built-in profile describes it: the generic profile, with
    /// [`GENERIC_NOTICE`].
    Unknown {
        /// The answer.
        version: FirmwareVersion,
        /// The generic profile.
        profile: Arc<Profile>,
    },
    /// The boot loader answered (`B` for `V`): nothing else may be sent.
    BootLoader {
        /// The answer.
        version: FirmwareVersion,
        /// The profile of its module number, if there is one (for the message only).
        profile: Option<Arc<Profile>>,
    },
}

impl Identified {
    /// The profile to talk to the module with; `None` for a boot loader.
    pub fn profile(&self) -> Option<&Arc<Profile>> {
        match self {
            Identified::Known { profile, .. } | Identified::Unknown { profile, .. } => {
                Some(profile)
            }
            Identified::BootLoader { .. } => None,
        }
    }

    /// The banner line: `TMCM-6110, firmware 6110V131, profile tmcm-6110 (built in)`.
    pub fn banner(&self) -> String {
        match self {
            Identified::Known { version, profile } => format!(
                "{}, firmware {}, profile {} (built in)",
                profile.module, version.text, profile.name
            ),
            Identified::Unknown { version, .. } => format!(
                "TMCM-{}, firmware {}, profile {GENERIC} (built in): no profile for the TMCM-{}",
                version.module, version.text, version.module
            ),
            Identified::BootLoader { version, profile } => format!(
                "{} in its boot loader ({}): no firmware is running; nothing else was sent",
                profile
                    .as_ref()
                    .map_or_else(|| format!("TMCM-{}", version.module), |p| p.module.clone()),
                version.text
            ),
        }
    }
}

/// Identifies a module from its 136 type-0 answer (eight characters, `6110V131`).
pub fn identify(answer: &str) -> Result<Identified, VersionError> {
    let version = FirmwareVersion::parse(answer)?;
    let profile = by_module_number(version.module);
    Ok(match (version.bootloader, profile) {
        (true, profile) => Identified::BootLoader { version, profile },
        (false, Some(profile)) => Identified::Known { version, profile },
        (false, None) => Identified::Unknown {
            version,
            profile: generic(),
        },
    })
}

#[cfg(test)]
mod tests;
