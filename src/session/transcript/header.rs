//! The header line that starts each session's part of a transcript: what it is a transcript of
//! (dialect, module type, profile, tmclsh version), as `key "value"` fields that later versions
//! may add to.

use crate::dialect::Dialect;
use crate::dialect::tmcl::profile::Profile;

use super::{escape_into, unescape};

/// The tag of header lines.
pub const HEADER_TAG: &str = "##";
/// What a header line says before its fields.
const HEADER_TITLE: &str = "tmclsh transcript:";

/// What a transcript is of: the dialect and the module type, with the profile of a TMCL module.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Header {
    /// The protocol of the session.
    pub dialect: Dialect,
    /// The module type ("TMCM-142", "SMD4").
    pub module: String,
    /// The profile of a TMCL session: "built-in" or the file given with `--profile`.
    pub profile: Option<String>,
    /// The tmclsh version that wrote the transcript.
    pub version: String,
}

impl Header {
    /// The header of a session in `dialect`; `profile` describes TMCL modules.
    pub fn new(dialect: Dialect, profile: &Profile) -> Self {
        match dialect {
            Dialect::Tmcl => Header::tmcl(profile),
            Dialect::Smd4 => Header::smd4(),
        }
    }

    /// The header of a TMCL session with modules of `profile`.
    pub fn tmcl(profile: &Profile) -> Self {
        let source = profile
            .source
            .as_ref()
            .map_or_else(|| "built-in".to_string(), |path| path.display().to_string());
        Header {
            dialect: Dialect::Tmcl,
            module: profile.module.clone(),
            profile: Some(source),
            version: env!("CARGO_PKG_VERSION").to_string(),
        }
    }

    /// The header of an SMD4 session.
    pub fn smd4() -> Self {
        Header {
            dialect: Dialect::Smd4,
            module: "SMD4".to_string(),
            profile: None,
            version: env!("CARGO_PKG_VERSION").to_string(),
        }
    }

    /// The header's text after its tag: `tmclsh transcript: dialect "tmcl", module "…", …`.
    pub fn to_text(&self) -> String {
        let mut text = String::from(HEADER_TITLE);
        let dialect = dialect_name(self.dialect);
        let fields = [
            ("dialect", Some(dialect)),
            ("module", Some(self.module.as_str())),
            ("profile", self.profile.as_deref()),
            ("version", Some(self.version.as_str())),
        ];
        for (i, (key, value)) in fields.iter().enumerate() {
            let Some(value) = value else { continue };
            text.push_str(if i == 0 { " " } else { ", " });
            text.push_str(key);
            text.push(' ');
            escape_into(value.as_bytes(), &mut text);
        }
        text
    }

    /// Reads a header's text back (the inverse of [`Header::to_text`]); fields it does not know
    /// are skipped, so later versions may add some.
    pub fn parse(text: &str) -> Result<Header, String> {
        let mut rest = text
            .strip_prefix(HEADER_TITLE)
            .ok_or_else(|| format!("a header that does not start with '{HEADER_TITLE}'"))?;
        let (mut dialect, mut module, mut profile, mut version) = (None, None, None, None);
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
                "version" => version = Some(value),
                _ => {}
            }
            rest = after;
        }
        let dialect = match dialect.as_deref() {
            Some("tmcl") => Dialect::Tmcl,
            Some("smd4") => Dialect::Smd4,
            Some(other) => return Err(format!("a header naming the unknown dialect '{other}'")),
            None => return Err("a header without a dialect".into()),
        };
        Ok(Header {
            dialect,
            module: module.ok_or("a header without a module")?,
            profile,
            version: version.unwrap_or_default(),
        })
    }
}

/// The dialect as headers and the `--protocol` option spell it.
pub fn dialect_name(dialect: Dialect) -> &'static str {
    match dialect {
        Dialect::Tmcl => "tmcl",
        Dialect::Smd4 => "smd4",
    }
}

/// Splits `"…" rest` into the quoted part (with its quotes) and the rest.
pub fn split_quoted(text: &str) -> Option<(&str, &str)> {
    let bytes = text.as_bytes();
    if bytes.first() != Some(&b'"') {
        return None;
    }
    let mut i = 1;
    while i < bytes.len() {
        match bytes[i] {
            b'\\' => i += 2,
            b'"' => return Some((&text[..=i], &text[i + 1..])),
            _ => i += 1,
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use std::path::PathBuf;

    use super::*;

    #[test]
    fn headers_read_back_what_they_say() {
        let mut profile = Profile::clone(&Profile::builtin());
        profile.module = "TMCM-\"odd\", name".into();
        profile.source = Some(PathBuf::from("dir with space/p.toml"));
        for header in [
            Header::new(Dialect::Tmcl, &profile),
            Header::new(Dialect::Smd4, &profile),
        ] {
            assert_eq!(Header::parse(&header.to_text()), Ok(header));
        }
        let later = "tmclsh transcript: dialect \"smd4\", firmware \"1.2\", module \"SMD4\"";
        assert_eq!(Header::parse(later).unwrap().dialect, Dialect::Smd4);
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
