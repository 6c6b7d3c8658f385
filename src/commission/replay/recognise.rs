//! What a transcript is of: the dialect and module its headers name, checked alike across the
//! sessions appended to one file; a file from before headers gets a reasoned guess and a notice.

use crate::dialect::Dialect;
use crate::session::transcript::{Header, dialect_name};

use super::parse::{Entry, Record};
use crate::dialect::smd4::replay as smd4;

/// What a transcript is of, as read from it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Recognised {
    /// The dialect of its sessions.
    pub dialect: Dialect,
    /// The header of its first session; `None` for a file from before headers.
    pub header: Option<Header>,
    /// Something the reader should know about how the file was read.
    pub notice: Option<String>,
}

/// What `entries` are a transcript of: the dialect and module its headers name, all sessions
/// alike. A file written before transcripts had headers is read as SMD4 when it has the SMD4
/// session's opening note and as TMCL otherwise, with a notice saying so.
pub fn recognise(entries: &[Entry]) -> Result<Recognised, String> {
    let headers: Vec<(usize, &Header)> = entries
        .iter()
        .filter_map(|e| match &e.record {
            Record::Header(h) => Some((e.line, h)),
            _ => None,
        })
        .collect();
    let Some(&(first_line, first)) = headers.first() else {
        let dialect = if smd4::is_smd4(entries) {
            Dialect::Smd4
        } else {
            Dialect::Tmcl
        };
        let why = match dialect {
            Dialect::Smd4 => "its SMD4 session note",
            Dialect::Tmcl => "no SMD4 session note",
        };
        return Ok(Recognised {
            dialect,
            header: None,
            notice: Some(format!(
                "no header (a transcript from an older tmclsh): read as {} because of {why}",
                dialect_name(dialect).to_uppercase()
            )),
        });
    };
    for &(line, header) in &headers[1..] {
        if header.dialect != first.dialect || header.module != first.module {
            return Err(format!(
                "it holds sessions with different modules: {} {} (line {first_line}) and {} {} \
                 (line {line}); split it",
                dialect_name(first.dialect).to_uppercase(),
                first.module,
                dialect_name(header.dialect).to_uppercase(),
                header.module
            ));
        }
    }
    let unheaded = entries
        .iter()
        .take_while(|e| e.line < first_line)
        .any(|e| matches!(e.record, Record::Sent(_)));
    Ok(Recognised {
        dialect: first.dialect,
        header: Some(first.clone()),
        notice: unheaded.then(|| {
            format!(
                "lines before line {first_line} have no header (written by an older tmclsh): \
                 read as {} like the rest",
                dialect_name(first.dialect).to_uppercase()
            )
        }),
    })
}
