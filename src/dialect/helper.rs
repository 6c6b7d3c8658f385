//! Helper commands (lines starting with `:`) as data: each dialect lists its own in its
//! descriptor, the shell lists those every dialect has, and the two tables together drive
//! dispatch, `:help` and completion.

/// What a helper's argument is, for completion.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ArgKind {
    /// No argument.
    None,
    /// A file name.
    File,
    /// A parameter name or filter.
    Param,
    /// `char`, `line` or `none`.
    Echo,
    /// A module address or character.
    Module,
    /// A help topic.
    Topic,
    /// A program address.
    Address,
    /// `save`, `diff` or `restore`, then a snapshot file.
    Snapshot,
    /// A CSV file, then parameter names.
    Record,
}

/// Where a helper is listed (`:help`, completion, "ambiguous" messages): the shared helpers of a
/// section come first, then the dialect's own.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum Section {
    /// Help and what the session talks to.
    Session,
    /// How output is kept and shown.
    Output,
    /// What the module itself is told to do (programs, modes).
    Module,
    /// Scripts, commissioning tools, leaving.
    Tools,
}

/// One helper command.
#[derive(Debug, Clone, Copy)]
pub struct Helper {
    /// Usage line: the colon and the name, then the arguments.
    pub usage: &'static str,
    /// One-line description.
    pub summary: &'static str,
    /// What its argument is.
    pub arg: ArgKind,
    /// Where it is listed.
    pub section: Section,
}

/// A helper (for the tables).
pub const fn helper(
    usage: &'static str,
    summary: &'static str,
    arg: ArgKind,
    section: Section,
) -> Helper {
    Helper {
        usage,
        summary,
        arg,
        section,
    }
}

impl Helper {
    /// Its name without the colon: the usage line's first word.
    pub fn name(&self) -> &'static str {
        let word = self.usage.split(' ').next().unwrap_or_default();
        word.strip_prefix(':').unwrap_or(word)
    }
}
