//! What a source file of the library uses: the `crate::…` and `super::…` paths in its code
//! (comments and string literals left out), resolved to module paths from the crate root.

use std::path::{Path, PathBuf};

/// A library source file: where it is, its module path, and whether it is test code.
pub struct Source {
    /// The file, relative to the repository.
    pub file: PathBuf,
    /// Its module path (`["dialect", "tmcl", "session"]` for `src/dialect/tmcl/session/mod.rs`).
    pub module: Vec<String>,
    /// Its code, without comments, string literals or inline test modules.
    pub code: String,
    /// Whether the whole file is test code (`tests.rs`, a `tests/` folder, a `#[cfg(test)]`
    /// module): tests may reach any layer, as a dev-dependency would.
    pub test_only: bool,
}

/// Every `.rs` file under `src/` except the binary's `main.rs`, in path order.
pub fn sources(repo: &Path) -> Vec<Source> {
    let src = repo.join("src");
    let mut files = Vec::new();
    walk(&src, &mut files);
    files.sort();
    files
        .into_iter()
        .filter(|f| f != &src.join("main.rs"))
        .map(|file| {
            let text = std::fs::read_to_string(&file).expect("a readable source file");
            let relative = file.strip_prefix(&src).expect("under src").to_path_buf();
            let module = module_path(&relative);
            let test_only = is_test_file(&relative) || declared_for_tests(&src, &relative);
            Source {
                file: Path::new("src").join(&relative),
                module,
                code: without_inline_tests(&strip(&text)),
                test_only,
            }
        })
        .collect()
}

fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).expect("a readable folder") {
        let path = entry.expect("a folder entry").path();
        if path.is_dir() {
            walk(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// `dialect/tmcl/session/mod.rs` → `dialect::tmcl::session`; `lib.rs` → the root.
fn module_path(relative: &Path) -> Vec<String> {
    let mut parts: Vec<String> = relative
        .iter()
        .map(|p| p.to_string_lossy().into_owned())
        .collect();
    let last = parts.pop().expect("a file name");
    let stem = last.trim_end_matches(".rs");
    if stem != "mod" && stem != "lib" {
        parts.push(stem.to_string());
    }
    parts
}

fn is_test_file(relative: &Path) -> bool {
    relative.file_name().is_some_and(|n| n == "tests.rs")
        || relative.iter().any(|part| part == "tests")
}

/// Whether the parent module declares this file's module under `#[cfg(test)]`.
fn declared_for_tests(src: &Path, relative: &Path) -> bool {
    let stem = relative.file_stem().expect("a file name").to_string_lossy();
    if stem == "mod" || stem == "lib" {
        return false;
    }
    let folder = relative.parent().unwrap_or(Path::new(""));
    let parent = if folder.as_os_str().is_empty() {
        src.join("lib.rs")
    } else if src.join(folder).join("mod.rs").exists() {
        src.join(folder).join("mod.rs")
    } else {
        src.join(folder.with_extension("rs"))
    };
    std::fs::read_to_string(parent)
        .is_ok_and(|text| text.contains(&format!("#[cfg(test)]\nmod {stem};")))
}

/// The code without comments and string, byte-string and char literals (their text names no
/// module).
pub fn strip(text: &str) -> String {
    let bytes = text.as_bytes();
    let mut out = String::with_capacity(text.len());
    let mut i = 0;
    while i < bytes.len() {
        let rest = &text[i..];
        if rest.starts_with("//") {
            i += rest.find('\n').unwrap_or(rest.len());
        } else if rest.starts_with("/*") {
            i += rest.find("*/").map_or(rest.len(), |j| j + 2);
        } else if let Some((opening, hashes)) = raw_string_start(rest).filter(|_| !in_word(text, i))
        {
            let close = format!("\"{}", "#".repeat(hashes));
            i += opening
                + rest[opening..]
                    .find(&close)
                    .map_or(rest.len() - opening, |j| j + close.len());
            out.push_str("\"\"");
        } else if bytes[i] == b'"' {
            i += 1;
            while i < bytes.len() && bytes[i] != b'"' {
                i += if bytes[i] == b'\\' { 2 } else { 1 };
            }
            i += 1;
            out.push_str("\"\"");
        } else if let Some(len) = char_literal(rest) {
            i += len;
        } else {
            let c = rest.chars().next().expect("not at the end");
            out.push(c);
            i += c.len_utf8();
        }
    }
    out
}

/// `r"…"`, `br#"…"#`: the length of the opening and the number of hashes, when `rest` starts a
/// raw string.
fn raw_string_start(rest: &str) -> Option<(usize, usize)> {
    let prefix = if rest.starts_with("br") { 2 } else { 1 };
    let after = rest.strip_prefix("br").or_else(|| rest.strip_prefix('r'))?;
    let hashes = after.len() - after.trim_start_matches('#').len();
    after[hashes..]
        .starts_with('"')
        .then_some((prefix + hashes + 1, hashes))
}

/// Whether the byte at `i` continues an identifier.
fn in_word(text: &str, i: usize) -> bool {
    text[..i].ends_with(|c: char| c.is_alphanumeric() || c == '_')
}

/// The length of a char literal at the start of `rest` (`'a'`, `'\n'`, `'\''`), not a lifetime.
fn char_literal(rest: &str) -> Option<usize> {
    let body = rest.strip_prefix('\'')?;
    let mut chars = body.char_indices();
    let (_, first) = chars.next()?;
    let end = if first == '\\' {
        // The escaped character may itself be a quote (`'\''`).
        body.get(2..)?.find('\'').map(|j| j + 2)?
    } else {
        let (j, c) = chars.next()?;
        (c == '\'').then_some(j)?
    };
    Some(end + 2)
}

/// The code before an inline `#[cfg(test)] mod tests { … }` (always last in a file).
fn without_inline_tests(code: &str) -> String {
    match code.find("#[cfg(test)]\nmod tests {") {
        Some(i) => code[..i].to_string(),
        None => code.to_string(),
    }
}

/// The module paths `source` uses, from the crate root (`["dialect", "tmcl", …]`).
pub fn used_paths(source: &Source) -> Vec<Vec<String>> {
    let code = &source.code;
    let mut paths = Vec::new();
    for (i, _) in code.match_indices("crate::") {
        if code[..i].ends_with('$') || in_word(code, i) {
            continue;
        }
        paths.push(segments(&code[i + "crate::".len()..]));
    }
    for (i, _) in code.match_indices("super::") {
        let before = &code[..i];
        if before.ends_with("super::") || in_word(code, i) {
            continue;
        }
        let mut rest = &code[i..];
        let mut base = source.module.clone();
        while let Some(after) = rest.strip_prefix("super::") {
            base.pop();
            rest = after;
        }
        base.extend(segments(rest));
        paths.push(base);
    }
    paths.retain(|p| !p.is_empty());
    paths
}

/// The identifiers of a path (`dialect::tmcl::{…}` → `["dialect", "tmcl"]`), up to the first
/// thing that is not one.
fn segments(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut rest = text;
    loop {
        let end = rest
            .find(|c: char| !(c.is_alphanumeric() || c == '_'))
            .unwrap_or(rest.len());
        if end == 0 {
            break;
        }
        out.push(rest[..end].to_string());
        match rest[end..].strip_prefix("::") {
            Some(after) => rest = after,
            None => break,
        }
    }
    out
}
