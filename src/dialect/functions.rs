//! The script functions of every dialect, from the one registry ([`crate::script::registry`]):
//! the tables `:help`, `tmclsh run --help`, completion and docs/script-functions.md show.

use crate::script::registry::{SHARED, ScriptFn};

use super::{Dialect, all};

/// Every script's functions, then each dialect's, each table with its title.
pub fn tables() -> Vec<(String, &'static [ScriptFn])> {
    let mut tables = vec![("Every script".to_string(), SHARED)];
    for dialect in all() {
        tables.push((
            format!(
                "{} scripts (--protocol {})",
                dialect.name.to_uppercase(),
                dialect.name
            ),
            dialect.script_functions,
        ));
    }
    tables
}

/// The function `name` a script run in a session of `dialect` can call.
pub fn find(dialect: &Dialect, name: &str) -> Option<&'static ScriptFn> {
    crate::script::registry::find(&[SHARED, dialect.script_functions], name)
}

/// The names of the functions a script of `dialect` can call.
pub fn names(dialect: &Dialect) -> impl Iterator<Item = &'static str> {
    SHARED
        .iter()
        .chain(dialect.script_functions)
        .map(ScriptFn::name)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// docs/script-functions.md is generated from the registry; `TMCLSH_REGENERATE=1`
    /// rewrites it.
    #[test]
    fn the_script_function_reference_is_generated_from_the_registry() {
        let path =
            std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/script-functions.md");
        let generated = crate::script::registry::markdown(&tables());
        if std::env::var_os("TMCLSH_REGENERATE").is_some() {
            std::fs::write(&path, &generated).unwrap();
        }
        let committed = std::fs::read_to_string(&path).unwrap_or_default();
        assert!(
            committed == generated,
            "docs/script-functions.md is stale; regenerate it with \
             TMCLSH_REGENERATE=1 cargo test --lib dialect::functions"
        );
    }

    #[test]
    fn each_function_is_listed_once_per_table() {
        for (title, table) in tables() {
            let mut names: Vec<&str> = table.iter().map(ScriptFn::name).collect();
            names.sort_unstable();
            let all = names.len();
            names.dedup();
            assert_eq!(names.len(), all, "{title}");
            for f in table {
                let name = f.name();
                assert!(f.signature.contains('('), "{f:?}");
                assert!(
                    !name.is_empty() && name.chars().all(|c| c == '_' || c.is_ascii_alphanumeric()),
                    "{f:?}"
                );
                assert!(!f.help.is_empty() && !f.help.contains('\n'), "{f:?}");
            }
        }
    }
}
