//! The header line that starts each session's part of a transcript: what it is a transcript of
//! (dialect, module type, profile, tmclsh version), as `key "value"` fields that later versions
//! may add to. Each dialect writes its own header; reading one back checks its dialect against
//! the list of dialects, so it lives with the transcript reading (`dialect::replay`).

use super::escape_into;

/// The tag of header lines.
pub const HEADER_TAG: &str = "##";
/// What a header line says before its fields.
pub const HEADER_TITLE: &str = "tmclsh transcript:";

/// What a transcript is of: the dialect and the module type, with the profile of a TMCL module.
/// A TMCL session that takes each module's profile from its answer says so in `profiles`: its
/// `module` and `profile` are then those of a module that does not name itself, and the
/// identification notes that follow name each module's own.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Header {
    /// The protocol of the session, by the name `--protocol` takes (`tmcl`).
    pub dialect: String,
    /// The module type ("TMCM-142", "SMD4").
    pub module: String,
    /// The profile of a TMCL session: "built-in" or the file given with `--profile`.
    pub profile: Option<String>,
    /// How modules get their profile when it is not one for all ("per module, see the
    /// identification notes").
    pub profiles: Option<String>,
    /// The tmclsh version that wrote the transcript.
    pub version: String,
}

impl Header {
    /// The header's text after its tag: `tmclsh transcript: dialect "tmcl", module "…", …`.
    pub fn to_text(&self) -> String {
        let mut text = String::from(HEADER_TITLE);
        let fields = [
            ("dialect", Some(self.dialect.as_str())),
            ("module", Some(self.module.as_str())),
            ("profile", self.profile.as_deref()),
            ("profiles", self.profiles.as_deref()),
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
