//! Reading a transcript header back: the inverse of [`Header::to_text`], which also checks that
//! the dialect it names is one of [`crate::dialect::all`].

use crate::dialect::by_name;
use crate::session::transcript::{HEADER_TITLE, Header, split_quoted, unescape};

impl Header {
    /// Reads a header's text back (the inverse of [`Header::to_text`]); fields it does not know
    /// are skipped, so later versions may add some.
    pub fn parse(text: &str) -> Result<Header, String> {
        let mut rest = text
            .strip_prefix(HEADER_TITLE)
            .ok_or_else(|| format!("a header that does not start with '{HEADER_TITLE}'"))?;
        let (mut dialect, mut module, mut profile, mut profiles, mut version) =
            (None, None, None, None, None);
        loop {
            rest = rest.trim_start_matches([' ', ',']);
            if rest.is_empty() {
                break;
            }
            let (key, after) = rest
                .split_once(' ')
                .ok_or_else(|| format!("a header field without a value: {rest}"))?;
            let (quoted, after) = split_quoted(after)
                .ok_or_else(|| format!("the header field {key} has no quoted value"))?;
            let value = unescape(quoted)
                .and_then(|b| String::from_utf8(b).ok())
                .ok_or_else(|| format!("the header field {key} is not text"))?;
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
            Some(other) => return Err(format!("a header naming the unknown dialect '{other}'")),
            None => return Err("a header without a dialect".into()),
        };
        Ok(Header {
            dialect,
            module: module.ok_or("a header without a module")?,
            profile,
            profiles,
            version: version.unwrap_or_default(),
        })
    }
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
