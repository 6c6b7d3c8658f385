//! What a transcript is of: the dialect and module its headers name, checked alike across the
//! sessions appended to one file; a file from before headers gets a reasoned guess and a notice.

use crate::dialect::{Dialect, all, by_name, default_dialect};
use crate::session::transcript::Header;

use super::parse::{Entry, Record};

/// What a transcript is of, as read from it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Recognised {
    /// The dialect of its sessions.
    pub dialect: &'static Dialect,
    /// The header of its first session; `None` for a file from before headers.
    pub header: Option<Header>,
    /// Something the reader should know about how the file was read.
    pub notice: Option<String>,
}

/// What `entries` are a transcript of: the dialect and module its headers name, all sessions
/// alike. A file written before transcripts had headers is read as the dialect whose session note
/// ([`Dialect::legacy_note`]) it has, as the default dialect otherwise, with a notice saying so.
pub fn recognise(entries: &[Entry]) -> Result<Recognised, String> {
    let headers: Vec<(usize, &Header)> = entries
        .iter()
        .filter_map(|e| match &e.record {
            Record::Header(h) => Some((e.line, h)),
            _ => None,
        })
        .collect();
    let Some(&(first_line, first)) = headers.first() else {
        return Ok(without_header(entries));
    };
    let dialect = by_name(&first.dialect).expect("headers are read with the dialects listed");
    for &(line, header) in &headers[1..] {
        if header.dialect != first.dialect || header.module != first.module {
            return Err(format!(
                "it holds sessions with different modules: {} {} (line {first_line}) and {} {} \
                 (line {line}); split it",
                first.dialect.to_uppercase(),
                first.module,
                header.dialect.to_uppercase(),
                header.module
            ));
        }
    }
    let unheaded = entries
        .iter()
        .take_while(|e| e.line < first_line)
        .any(|e| matches!(e.record, Record::Sent(_)));
    Ok(Recognised {
        dialect,
        header: Some(first.clone()),
        notice: unheaded.then(|| {
            format!(
                "lines before line {first_line} have no header (written by an older tmclsh): \
                 read as {} like the rest",
                first.dialect.to_uppercase()
            )
        }),
    })
}

/// A transcript from before headers: the dialect whose session note it has, or the default.
fn without_header(entries: &[Entry]) -> Recognised {
    let noted = |note: &str| {
        entries
            .iter()
            .any(|e| matches!(&e.record, Record::Note(n) if n.starts_with(note)))
    };
    let found = all().iter().find(|d| d.legacy_note.is_some_and(&noted));
    let (dialect, why) = match found {
        Some(d) => (*d, format!("its {} session note", d.name.to_uppercase())),
        None => {
            let noting: Vec<String> = all()
                .iter()
                .filter(|d| d.legacy_note.is_some())
                .map(|d| d.name.to_uppercase())
                .collect();
            let why = format!("no {} session note", noting.join(" or "));
            (default_dialect(), why)
        }
    };
    Recognised {
        dialect,
        header: None,
        notice: Some(format!(
            "no header (a transcript from an older tmclsh): read as {} because of {why}",
            dialect.name.to_uppercase()
        )),
    }
}
