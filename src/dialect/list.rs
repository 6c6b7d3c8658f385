//! The list of dialects: the built-in ones, then any a program embedding the library registers
//! before it first asks for the list. The list is fixed at that first use, because everything
//! built from it (clap's `--protocol` values and flags, help tables, the configured dialects)
//! would otherwise disagree with it; a registration after that is refused, never ignored.

use std::sync::{Mutex, OnceLock, PoisonError};

use super::{BUILT_IN, Dialect};

/// The list, fixed at its first use.
static FIXED: OnceLock<&'static [&'static Dialect]> = OnceLock::new();

/// Dialects registered so far, and whether the list has been fixed: one lock, so a
/// registration racing the first use is either in the list or refused.
static REGISTERED: Mutex<Registry> = Mutex::new(Registry {
    extra: Vec::new(),
    fixed: false,
});

/// Why a dialect could not be registered.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum RegisterError {
    /// The list was already used, and what was built from it would not know the dialect.
    #[error(
        "the dialect {0} was registered after the list of dialects was first used; register \
         every dialect before anything reads the list (dialect::all)"
    )]
    TooLate(&'static str),
    /// Another dialect of the list has its name, which `--protocol` and transcripts go by.
    #[error("the dialect {0} is already in the list of dialects")]
    NameTaken(&'static str),
}

/// The registrations before the list is fixed.
#[derive(Debug)]
struct Registry {
    extra: Vec<&'static Dialect>,
    fixed: bool,
}

impl Registry {
    /// Adds `dialect` unless the list is fixed or has its name.
    fn register(&mut self, dialect: &'static Dialect) -> Result<(), RegisterError> {
        if self.fixed {
            return Err(RegisterError::TooLate(dialect.name));
        }
        if BUILT_IN
            .iter()
            .chain(&self.extra)
            .any(|d| d.name == dialect.name)
        {
            return Err(RegisterError::NameTaken(dialect.name));
        }
        self.extra.push(dialect);
        Ok(())
    }

    /// Fixes the list: the built-in dialects, then the registered ones in order.
    fn fix(&mut self) -> Vec<&'static Dialect> {
        self.fixed = true;
        BUILT_IN
            .iter()
            .copied()
            .chain(self.extra.drain(..))
            .collect()
    }
}

/// Adds `dialect` to the list, after the built-in ones: a program embedding the library calls
/// this before anything reads the list ([`all`]).
pub fn register(dialect: &'static Dialect) -> Result<(), RegisterError> {
    let mut registry = REGISTERED.lock().unwrap_or_else(PoisonError::into_inner);
    registry.register(dialect)
}

/// Every dialect, the default first: the built-in ones, then those registered. The first call
/// fixes the list.
pub fn all() -> &'static [&'static Dialect] {
    FIXED.get_or_init(|| {
        let mut registry = REGISTERED.lock().unwrap_or_else(PoisonError::into_inner);
        registry.fix().leak()
    })
}

/// The dialect named `name` (as `--protocol` and transcript headers write it).
pub fn by_name(name: &str) -> Option<&'static Dialect> {
    all().iter().copied().find(|d| d.name == name)
}

/// The default dialect (the first in the list).
pub fn default_dialect() -> &'static Dialect {
    all()[0]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dialect::{smd4, tmcl};

    /// A dialect of another name, for a registry of this test's own (the crate's list is shared
    /// by every test of the binary, and stays as built).
    fn other(name: &'static str) -> &'static Dialect {
        Box::leak(Box::new(Dialect {
            name,
            ..smd4::DIALECT
        }))
    }

    #[test]
    fn registered_dialects_follow_the_built_in_ones_until_the_list_is_fixed() {
        let mut registry = Registry {
            extra: Vec::new(),
            fixed: false,
        };
        let echo = other("echo");
        assert_eq!(registry.register(echo), Ok(()));
        assert_eq!(
            registry.register(other("smd4")),
            Err(RegisterError::NameTaken("smd4"))
        );
        assert_eq!(
            registry.register(other("echo")),
            Err(RegisterError::NameTaken("echo"))
        );
        let names: Vec<&str> = registry.fix().iter().map(|d| d.name).collect();
        assert_eq!(names, ["tmcl", "smd4", "echo"]);
        let late = registry.register(other("late")).unwrap_err();
        assert_eq!(late, RegisterError::TooLate("late"));
        assert!(late.to_string().contains("before anything reads the list"));
    }

    #[test]
    fn a_registration_after_the_first_use_is_refused() {
        assert_eq!(default_dialect(), &tmcl::DIALECT);
        assert_eq!(register(other("late")), Err(RegisterError::TooLate("late")));
        assert!(by_name("late").is_none());
        assert_eq!(by_name("smd4"), Some(&smd4::DIALECT));
    }
}
