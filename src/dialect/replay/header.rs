//! Reading a transcript header back: the inverse of [`Header::to_text`], which also checks that
//! the dialect it names is one of [`crate::dialect::all`].

use crate::dialect::by_name;
use crate::session::transcript::{HEADER_TITLE, Header, split_quoted, unescape};

impl Header {
    /// Reads a header's text back (the inverse of [`Header::to_text`]); fields it does not know
    /// are skipped, so later versions may add some.
    pub fn parse(text: &str) -> Result<Header, HeaderError> {
        let mut rest = text
            .strip_prefix(HEADER_TITLE)
            .ok_or(HeaderError::NoTitle)?;
        let (mut dialect, mut module, mut profile, mut profiles, mut version) =
            (None, None, None, None, None);
        loop {
            rest = rest.trim_start_matches([' ', ',']);
            if rest.is_empty() {
                break;
            }
            let (key, after) = rest
                .split_once(' ')
                .ok_or_else(|| HeaderError::NoValue(rest.to_string()))?;
            let (quoted, after) =
                split_quoted(after).ok_or_else(|| HeaderError::Unquoted(key.to_string()))?;
            let value = unescape(quoted)
                .and_then(|b| String::from_utf8(b).ok())
                .ok_or_else(|| HeaderError::NotText(key.to_string()))?;
            match key {
                "dialect" => dialect = Some(value),
                "module" => module = Some(value),
                "profile" => profile = Some(value),
                "profiles" => profiles = Some(value),
                "version" => version = Some(value),
                _ => {}
            }
            rest = after;
        }
        let dialect = match dialect {
            Some(name) if by_name(&name).is_some() => name,
            Some(other) => return Err(HeaderError::UnknownDialect(other)),
            None => return Err(HeaderError::NoDialect),
        };
        Ok(Header {
            dialect,
            module: module.ok_or(HeaderError::NoModule)?,
            profile,
            profiles,
            version: version.unwrap_or_default(),
        })
    }
}

/// Why a header line cannot be read back.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum HeaderError {
    /// Not a header this program wrote.
    #[error("a header that does not start with '{HEADER_TITLE}'")]
    NoTitle,
    /// A field name with nothing after it (the rest of the header).
    #[error("a header field without a value: {0}")]
    NoValue(String),
    /// A field whose value is not in quotes.
    #[error("the header field {0} has no quoted value")]
    Unquoted(String),
    /// A field whose value is not UTF-8.
    #[error("the header field {0} is not text")]
    NotText(String),
    /// A dialect no list has.
    #[error("a header naming the unknown dialect '{0}'")]
    UnknownDialect(String),
    /// No dialect field.
    #[error("a header without a dialect")]
    NoDialect,
    /// No module field.
    #[error("a header without a module")]
    NoModule,
}

#[cfg(test)]
mod tests {
    use std::path::PathBuf;

    use super::*;
    use crate::dialect::smd4::config::header as smd4_header;
    use crate::dialect::tmcl::config::{PER_MODULE, header as tmcl_header, session_header};
    use crate::dialect::tmcl::profile::Profile;

    #[test]
    fn headers_read_back_what_they_say() {
        let mut profile = Profile::clone(&Profile::builtin());
        profile.module = "TMCM-\"odd\", name".into();
        profile.source = Some(PathBuf::from("dir with space/p.toml"));
        let per_module = session_header(&profile, false);
        assert_eq!(per_module.profiles.as_deref(), Some(PER_MODULE));
        assert_eq!(session_header(&profile, true), tmcl_header(&profile));
        for header in [tmcl_header(&profile), per_module, smd4_header()] {
            assert_eq!(Header::parse(&header.to_text()), Ok(header));
        }
        let later = "tmclsh transcript: dialect \"smd4\", firmware \"1.2\", module \"SMD4\"";
        assert_eq!(Header::parse(later).unwrap().dialect, "smd4");
        for bad in [
            "tmclsh transcript: module \"X\"",
            "tmclsh transcript: dialect \"canopen\", module \"X\"",
            "tmclsh transcript: dialect \"tmcl\"",
            "tmclsh transcript: dialect tmcl",
            "something else",
        ] {
            assert!(Header::parse(bad).is_err(), "{bad}");
        }
    }
}
