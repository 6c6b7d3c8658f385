//! The ASCII command-line grammar (manual §6.6.1), in nom.
//!
//! `[address char][spaces]MNEMONIC [arg][, arg]…[CR|LF]` — mnemonic case-insensitive, arguments
//! separated by commas and/or spaces, numbers in decimal (signed) or hex (`0x…`, `$…`), words for
//! keywords and parameter names. A line starting with a number is a command given by number
//! (`136 1`), for the control functions that have no mnemonic.
//!
//! The address character is ambiguous with the first letter of a mnemonic: `RSAP` is restore-axis-
//! parameter, not `SAP` to module R. A whole mnemonic wins; `R SAP …` with a space addresses R.
//! This layer only knows the shape of a line; meaning comes from the command table (`line.rs`,
//! and `operands.rs` for the operands).

use nom::branch::alt;
use nom::bytes::complete::{tag_no_case, take_while, take_while1};
use nom::character::complete::{char, digit1, one_of, satisfy, space0, space1};
use nom::combinator::{opt, recognize};
use nom::{IResult, Parser};

/// A command line split into its parts, before any table lookup.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct RawLine {
    /// The address character, upper-cased, if the line has one.
    pub address: Option<char>,
    /// The command word.
    pub word: Word,
    /// Arguments in order.
    pub args: Vec<Arg>,
}

/// The command part of a line.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Word {
    /// A mnemonic or other word, upper-cased.
    Name(String),
    /// A command number (`136 1`).
    Number(u8),
}

/// One argument.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Arg {
    /// A number; `hex` numbers may use the full unsigned 32-bit range.
    Number {
        /// The value as written.
        value: i64,
        /// Written in hex (`0x…`/`$…`).
        hex: bool,
    },
    /// A keyword or parameter name, as typed.
    Name(String),
}

/// Where and why a line does not parse.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("column {column}: {message}")]
pub struct SyntaxError {
    /// 1-based column of the problem.
    pub column: usize,
    /// What is wrong.
    pub message: String,
}

/// Parses one line. `is_word` tells whether a word is a known mnemonic (or ASCII-only word), which
/// settles whether a leading letter is an address character.
pub fn parse_line(line: &str, is_word: impl Fn(&str) -> bool) -> Result<RawLine, SyntaxError> {
    let text = line.trim_end_matches(['\r', '\n']);
    let at = |rest: &str| text.len() - rest.len() + 1;
    let (rest, _) = space0::<_, nom::error::Error<&str>>(text).expect("space0 cannot fail");
    if rest.is_empty() {
        return Err(SyntaxError {
            column: 1,
            message: "empty line".into(),
        });
    }
    let (rest, address, word) =
        head(rest, &is_word).map_err(|(column_at, message)| SyntaxError {
            column: at(column_at),
            message,
        })?;
    let mut args = Vec::new();
    let mut rest = rest;
    loop {
        let (after, sep) = separator(rest).unwrap_or((rest, ""));
        let error = |at_text: &str, message: String| SyntaxError {
            column: at(at_text),
            message,
        };
        if after.is_empty() {
            if sep.contains(',') {
                return Err(error(after, "argument missing after ','".into()));
            }
            break;
        }
        if sep.is_empty() || (args.is_empty() && sep.contains(',')) {
            return Err(error(
                rest,
                format!("unexpected '{}'", first_char(rest.trim_start())),
            ));
        }
        if let Some((second_comma, _)) = sep.match_indices(',').nth(1) {
            return Err(error(
                &rest[second_comma..],
                "empty argument between commas".into(),
            ));
        }
        let Ok((next, arg)) = argument(after) else {
            let token: String = after
                .chars()
                .take_while(|c| !matches!(c, ',' | ' ' | '\t'))
                .collect();
            let message = if token.starts_with(|c: char| c.is_ascii_digit() || c == '-')
                && token.contains('.')
            {
                format!("'{token}' is not a whole number; TMCL values are integers")
            } else {
                format!("expected a number or a name, found '{token}'")
            };
            return Err(error(after, message));
        };
        args.push(arg);
        rest = next;
    }
    Ok(RawLine {
        address,
        word,
        args,
    })
}

type HeadResult<'a> = Result<(&'a str, Option<char>, Word), (&'a str, String)>;

/// The address character and command word at the start of a line.
fn head<'a>(input: &'a str, is_word: &impl Fn(&str) -> bool) -> HeadResult<'a> {
    if let Ok((rest, number)) = command_number(input) {
        return Ok((rest, None, Word::Number(number?)));
    }
    let Ok((rest, first)) = identifier(input) else {
        return Err((
            input,
            format!("expected a command, found '{}'", first_char(input)),
        ));
    };
    let upper = first.to_ascii_uppercase();
    let leading = upper.chars().next().expect("identifiers are not empty");
    if is_word(&upper) {
        return Ok((rest, None, Word::Name(upper)));
    }
    if !leading.is_ascii_alphabetic() {
        return Ok((rest, None, Word::Name(upper)));
    }
    let tail = &upper[1..];
    if tail.is_empty() {
        // A lone letter: the address character, then the command after optional spaces.
        let (after_space, _) =
            space0::<_, nom::error::Error<&str>>(rest).expect("space0 cannot fail");
        if after_space.is_empty() {
            return Err((
                after_space,
                format!("command missing after address character {leading}"),
            ));
        }
        if let Ok((rest, number)) = command_number(after_space) {
            return Ok((rest, Some(leading), Word::Number(number?)));
        }
        return match identifier(after_space) {
            Ok((rest, word)) => Ok((rest, Some(leading), Word::Name(word.to_ascii_uppercase()))),
            Err(_) => Err((
                after_space,
                format!("expected a command, found '{}'", first_char(after_space)),
            )),
        };
    }
    if is_word(tail) {
        return Ok((rest, Some(leading), Word::Name(tail.to_string())));
    }
    if tail.bytes().all(|b| b.is_ascii_digit()) {
        let number = tail.parse::<u8>().map_err(|_| {
            (
                &input[1..],
                format!("command number {tail} is not in 0..255"),
            )
        })?;
        return Ok((rest, Some(leading), Word::Number(number)));
    }
    Ok((rest, None, Word::Name(upper)))
}

type NumberResult<'a> = Result<u8, (&'a str, String)>;

fn command_number(input: &str) -> IResult<&str, NumberResult<'_>> {
    let (rest, digits) = digit1(input)?;
    if rest.starts_with(|c: char| c.is_ascii_alphanumeric() || c == '_') {
        return Err(nom::Err::Error(nom::error::Error::new(
            input,
            nom::error::ErrorKind::Digit,
        )));
    }
    let number = digits
        .parse::<u8>()
        .map_err(|_| (input, format!("command number {digits} is not in 0..255")));
    Ok((rest, number))
}

fn identifier(input: &str) -> IResult<&str, &str> {
    recognize((
        satisfy(|c| c.is_ascii_alphabetic() || c == '_'),
        take_while(|c: char| c.is_ascii_alphanumeric() || c == '_'),
    ))
    .parse(input)
}

/// Commas and/or spaces between arguments (the text matched).
fn separator(input: &str) -> IResult<&str, &str> {
    alt((
        recognize((space0, char(','), space0, opt((char(','), space0)))),
        space1,
    ))
    .parse(input)
}

fn argument(input: &str) -> IResult<&str, Arg> {
    let (rest, arg) = alt((hex_number, decimal_number, name)).parse(input)?;
    if rest.starts_with(|c: char| c.is_ascii_alphanumeric() || c == '_' || c == '.') {
        return Err(nom::Err::Error(nom::error::Error::new(
            input,
            nom::error::ErrorKind::Verify,
        )));
    }
    Ok((rest, arg))
}

fn hex_number(input: &str) -> IResult<&str, Arg> {
    let (rest, (sign, _, digits)) = (
        opt(one_of("+-")),
        alt((tag_no_case("0x"), tag_no_case("$"))),
        take_while1(|c: char| c.is_ascii_hexdigit()),
    )
        .parse(input)?;
    let magnitude = i64::from_str_radix(digits, 16).map_err(|_| {
        nom::Err::Error(nom::error::Error::new(
            input,
            nom::error::ErrorKind::HexDigit,
        ))
    })?;
    let value = if sign == Some('-') {
        -magnitude
    } else {
        magnitude
    };
    Ok((rest, Arg::Number { value, hex: true }))
}

fn decimal_number(input: &str) -> IResult<&str, Arg> {
    let (rest, text) = recognize((opt(one_of("+-")), digit1)).parse(input)?;
    let value = text.parse::<i64>().map_err(|_| {
        nom::Err::Error(nom::error::Error::new(input, nom::error::ErrorKind::Digit))
    })?;
    Ok((rest, Arg::Number { value, hex: false }))
}

fn name(input: &str) -> IResult<&str, Arg> {
    let (rest, word) = identifier(input)?;
    Ok((rest, Arg::Name(word.to_string())))
}

fn first_char(s: &str) -> char {
    s.chars().next().unwrap_or(' ')
}

#[cfg(test)]
mod tests;
