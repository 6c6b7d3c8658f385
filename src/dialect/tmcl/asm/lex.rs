//! Source text to tokens, line by line. Comments (`//` to the end of the line, `/* … */` across
//! lines) are blanked out first, keeping every other character in its line and column, so all
//! later positions point into the text as the user wrote it.

use super::error::{Diagnostics, Position, Problem};

/// One token of a source line.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(super) enum Tok {
    /// A name: mnemonic, keyword, label, constant or parameter.
    Ident(String),
    /// A number literal; `hex` literals may use the full unsigned 32-bit range.
    Number {
        /// Its value.
        value: i64,
        /// Written as `0x…` or `$…`.
        hex: bool,
    },
    /// One of `, : = + - * / % ( ) #`.
    Punct(char),
    /// A double-quoted string (only so that `#include "file"` gets a clear message).
    Text(String),
}

/// A token and the column it starts at.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(super) struct Token {
    pub tok: Tok,
    pub column: usize,
}

impl Token {
    pub(super) fn is(&self, c: char) -> bool {
        self.tok == Tok::Punct(c)
    }

    /// How the token reads in a message.
    pub(super) fn text(&self) -> String {
        match &self.tok {
            Tok::Ident(name) => name.clone(),
            Tok::Number { value, .. } => value.to_string(),
            Tok::Punct(c) => c.to_string(),
            Tok::Text(text) => format!("\"{text}\""),
        }
    }
}

/// The tokens of each line that has any, with its 1-based line number. Lexical errors are
/// reported to `diags`; the rest of such a line is dropped.
pub(super) fn tokenize(source: &str, diags: &mut Diagnostics) -> Vec<(usize, Vec<Token>)> {
    let code = blank_comments(source, diags);
    let mut lines = Vec::new();
    for (index, text) in code.lines().enumerate() {
        let line = index + 1;
        match tokens(text) {
            Ok(tokens) if tokens.is_empty() => {}
            Ok(tokens) => lines.push((line, tokens)),
            Err((column, message)) => {
                diags.error(Position { line, column }, Problem::Syntax(message))
            }
        }
    }
    lines
}

/// The source with comment characters replaced by spaces (line breaks kept).
fn blank_comments(source: &str, diags: &mut Diagnostics) -> String {
    let mut out = String::with_capacity(source.len());
    let mut chars = source.chars().peekable();
    let (mut line, mut column) = (1, 1);
    let mut block_start: Option<Position> = None;
    let mut in_line_comment = false;
    while let Some(c) = chars.next() {
        let next = chars.peek().copied();
        let here = Position { line, column };
        if c == '\n' {
            (line, column) = (line + 1, 1);
            in_line_comment = false;
            out.push('\n');
            continue;
        }
        column += 1;
        if in_line_comment {
            out.push(' ');
        } else if block_start.is_some() {
            if c == '*' && next == Some('/') {
                chars.next();
                column += 1;
                block_start = None;
                out.push_str("  ");
            } else {
                out.push(if c == '\r' { '\r' } else { ' ' });
            }
        } else if c == '/' && next == Some('/') {
            in_line_comment = true;
            out.push(' ');
        } else if c == '/' && next == Some('*') {
            chars.next();
            column += 1;
            block_start = Some(here);
            out.push_str("  ");
        } else {
            out.push(c);
        }
    }
    if let Some(at) = block_start {
        diags.error(
            at,
            Problem::Syntax("'/*' comment is never closed with '*/'".into()),
        );
    }
    out
}

type LexError = (usize, String);

/// The tokens of one comment-free line.
fn tokens(text: &str) -> Result<Vec<Token>, LexError> {
    let chars: Vec<char> = text.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        let column = i + 1;
        if c.is_whitespace() || c == '\u{feff}' {
            // U+FEFF: the byte-order mark Windows editors put at the start of a file.
            i += 1;
            continue;
        }
        let word_end = |from: usize| {
            (from..chars.len())
                .find(|&j| {
                    !(chars[j].is_ascii_alphanumeric() || chars[j] == '_' || chars[j] == '.')
                })
                .unwrap_or(chars.len())
        };
        let tok = if c.is_ascii_alphabetic() || c == '_' {
            let end = (i..chars.len())
                .find(|&j| !(chars[j].is_ascii_alphanumeric() || chars[j] == '_'))
                .unwrap_or(chars.len());
            let word: String = chars[i..end].iter().collect();
            i = end;
            Tok::Ident(word)
        } else if c.is_ascii_digit() || c == '$' {
            let end = word_end(i + 1);
            let literal: String = chars[i..end].iter().collect();
            i = end;
            number(&literal).map_err(|message| (column, message))?
        } else if c == '"' {
            let close = (i + 1..chars.len())
                .find(|&j| chars[j] == '"')
                .ok_or((column, "'\"' is never closed".to_string()))?;
            let text: String = chars[i + 1..close].iter().collect();
            i = close + 1;
            Tok::Text(text)
        } else if ",:=+-*/%()#".contains(c) {
            i += 1;
            Tok::Punct(c)
        } else {
            return Err((column, format!("unexpected character '{c}'")));
        };
        out.push(Token { tok, column });
    }
    Ok(out)
}

/// A decimal, `0x` or `$` hex literal.
fn number(literal: &str) -> Result<Tok, String> {
    let hex_digits = literal
        .strip_prefix("0x")
        .or_else(|| literal.strip_prefix("0X"))
        .or_else(|| literal.strip_prefix('$'));
    let (digits, radix) = match hex_digits {
        Some(digits) => (digits, 16),
        None => (literal, 10),
    };
    let valid = !digits.is_empty() && digits.chars().all(|c| c.is_digit(radix));
    if !valid {
        return Err(if literal.contains('.') && radix == 10 {
            format!("'{literal}' is not a whole number; TMCL values are integers")
        } else {
            format!("'{literal}' is not a number")
        });
    }
    let value = i64::from_str_radix(digits, radix)
        .ok()
        .filter(|v| *v <= i64::from(u32::MAX))
        .ok_or_else(|| format!("{literal} does not fit in 32 bits"))?;
    Ok(Tok::Number {
        value,
        hex: radix == 16,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn lex(source: &str) -> (Vec<(usize, Vec<Token>)>, Vec<String>) {
        let mut diags = Diagnostics::new("t.tmc");
        let lines = tokenize(source, &mut diags);
        let errors = match diags.finish() {
            Ok(_) => Vec::new(),
            Err(e) => e.errors.iter().map(ToString::to_string).collect(),
        };
        (lines, errors)
    }

    fn texts(tokens: &[Token]) -> Vec<String> {
        tokens.iter().map(Token::text).collect()
    }

    #[test]
    fn comments_vanish_and_columns_stay_where_they_were() {
        let (lines, errors) =
            lex("// title\nLoop: MVP ABS, 0, 0x10 // go\n  /* a\n b */ JA Loop\n");
        assert!(errors.is_empty(), "{errors:?}");
        assert_eq!(lines.len(), 2);
        assert_eq!(lines[0].0, 2);
        assert_eq!(
            texts(&lines[0].1),
            ["Loop", ":", "MVP", "ABS", ",", "0", ",", "16"]
        );
        assert_eq!(lines[0].1[2].column, 7);
        assert_eq!(lines[1].0, 4);
        assert_eq!(lines[1].1[0].column, 7);
    }

    #[test]
    fn numbers_in_decimal_and_hex() {
        let (lines, _) = lex("X 10, $ff, 0XFFFFFFFF");
        let values: Vec<Tok> = lines[0].1.iter().map(|t| t.tok.clone()).collect();
        assert_eq!(
            values[1],
            Tok::Number {
                value: 10,
                hex: false
            }
        );
        assert_eq!(
            values[3],
            Tok::Number {
                value: 255,
                hex: true
            }
        );
        assert_eq!(
            values[5],
            Tok::Number {
                value: 0xFFFF_FFFF,
                hex: true
            }
        );
    }

    #[test]
    fn lexical_errors_name_line_and_column() {
        let (_, errors) = lex("ROL 0, 1.5\nROL 0, 0x\nROL 0, 99999999999\nROL @\n/* open");
        assert_eq!(
            errors,
            [
                "t.tmc:1:8: error: '1.5' is not a whole number; TMCL values are integers",
                "t.tmc:2:8: error: '0x' is not a number",
                "t.tmc:3:8: error: 99999999999 does not fit in 32 bits",
                "t.tmc:4:5: error: unexpected character '@'",
                "t.tmc:5:1: error: '/*' comment is never closed with '*/'",
            ]
        );
    }
}
