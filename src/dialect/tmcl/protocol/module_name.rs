//! How every message names a TMCL module: the number `--module` takes and, where the module has
//! one, the address letter its ASCII lines and the prompt show — `module 1 (A)`, `module 27`.

use std::fmt;

use super::line::{address_char, address_of};

/// A module address as messages show it: `module 1 (A)` for the addresses with an ASCII letter
/// (1..=26), `module 27` for the others.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ModuleName(pub u8);

impl ModuleName {
    /// The module an ASCII address letter names (`A`/`a` → `module 1 (A)`); a character that is
    /// no address letter names no module and shows as `module 0`.
    pub fn of_char(c: char) -> ModuleName {
        ModuleName(address_of(c).filter(|a| *a <= 26).unwrap_or(0))
    }
}

impl fmt::Display for ModuleName {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match address_char(self.0) {
            Some(c) => write!(f, "module {} ({c})", self.0),
            None => write!(f, "module {}", self.0),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::ModuleName;

    #[test]
    fn a_module_with_a_letter_shows_both() {
        assert_eq!(ModuleName(1).to_string(), "module 1 (A)");
        assert_eq!(ModuleName(26).to_string(), "module 26 (Z)");
        assert_eq!(ModuleName::of_char('c').to_string(), "module 3 (C)");
    }

    #[test]
    fn a_module_without_a_letter_shows_its_number() {
        assert_eq!(ModuleName(0).to_string(), "module 0");
        assert_eq!(ModuleName(27).to_string(), "module 27");
        assert_eq!(ModuleName(255).to_string(), "module 255");
        assert_eq!(ModuleName::of_char('@').to_string(), "module 0");
    }
}
