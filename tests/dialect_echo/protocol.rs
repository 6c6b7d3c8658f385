//! The echo protocol, pure: a request is `ECHO text` (the word in any case), and the reply is the
//! text; a device answers anything else with `?`.

/// The one command.
pub const KEYWORD: &str = "ECHO";

/// What the device answers a line that is no echo request.
pub const UNKNOWN: &str = "?";

/// The text `line` asks back, or why it is no echo request (with what one looks like).
pub fn parse(line: &str) -> Result<&str, String> {
    let line = line.trim();
    let (word, text) = line.split_once(' ').unwrap_or((line, ""));
    if !word.eq_ignore_ascii_case(KEYWORD) {
        return Err(format!(
            "unknown command {word}: echo lines are `ECHO text`"
        ));
    }
    match text.trim() {
        "" => Err("ECHO needs the text to send back: `ECHO text`".to_string()),
        text => Ok(text),
    }
}

/// Whether `line` is meant as an echo request, right or not: how another dialect's session tells
/// a line typed in the wrong place.
pub fn recognises(line: &str) -> bool {
    let word = line.split_whitespace().next().unwrap_or_default();
    word.eq_ignore_ascii_case(KEYWORD)
}

/// The request that asks `text` back.
pub fn request(text: &str) -> String {
    format!("{KEYWORD} {text}")
}
