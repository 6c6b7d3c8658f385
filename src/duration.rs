//! Times typed by people — `:record`, `:watch` and `:scan` in the shell, `--max-time`, the
//! simulator console's `advance` — in one grammar, so the same text means the same time
//! everywhere: a number with a unit (`250ms`, `2s`, `1.5s`, `18.75ms`, `1m`; humantime's units,
//! decimals exact to the nanosecond), or a bare number, which is always milliseconds (`250` is
//! `250ms`; `1.5` is `1.5ms`). At most [`MAX`]: a bound keeps every deadline computed from a time
//! far inside what a clock can represent.

use std::time::Duration;

/// The longest time accepted: a week of recording or simulated time is plenty.
pub const MAX: Duration = Duration::from_secs(7 * 24 * 3600);

/// Why a text is not an accepted time: the text, and what is wrong with it, with examples.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum DurationError {
    /// Not written as a time at all.
    #[error("'{0}' is not a time (e.g. 100ms, 2s, or a number of milliseconds)")]
    NotATime(String),
    /// A time, but longer than [`MAX`].
    #[error(
        "'{0}' is longer than {days} days, the longest time allowed here",
        days = MAX.as_secs() / (24 * 3600)
    )]
    TooLong(String),
}

/// Whether `text` is written as a time, allowed or too long (so a time too long is refused as
/// such, not taken for a name).
pub fn is_duration(text: &str) -> bool {
    !matches!(parse(text), Err(DurationError::NotATime(_)))
}

/// Parses a time, telling a text that is no time from one that is too long.
pub fn parse(text: &str) -> Result<Duration, DurationError> {
    let bare = !text.is_empty()
        && text.bytes().any(|b| b.is_ascii_digit())
        && text.bytes().all(|b| b.is_ascii_digit() || b == b'.');
    let time = if bare {
        humantime::parse_duration(&format!("{text}ms"))
    } else {
        humantime::parse_duration(text)
    };
    let time = time.map_err(|e| match e {
        humantime::DurationError::NumberOverflow => DurationError::TooLong(text.to_string()),
        _ => DurationError::NotATime(text.to_string()),
    })?;
    if time > MAX {
        return Err(DurationError::TooLong(text.to_string()));
    }
    Ok(time)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_bare_number_is_milliseconds_and_a_unit_says_otherwise() {
        assert_eq!(parse("250"), Ok(Duration::from_millis(250)));
        assert_eq!(parse("1.5"), Ok(Duration::from_micros(1500)));
        assert_eq!(parse("2s"), Ok(Duration::from_secs(2)));
        assert_eq!(parse("100ms"), Ok(Duration::from_millis(100)));
        assert_eq!(parse("10us"), Ok(Duration::from_micros(10)));
        assert_eq!(parse("1m"), Ok(Duration::from_secs(60)));
        assert_eq!(parse("0"), Ok(Duration::ZERO));
    }

    #[test]
    fn decimals_are_exact_to_the_nanosecond() {
        assert_eq!(parse("1.5s"), Ok(Duration::from_millis(1500)));
        assert_eq!(parse("18.75ms"), Ok(Duration::from_micros(18_750)));
        assert_eq!(parse("5.24s"), Ok(Duration::from_millis(5240)));
        assert_eq!(parse("0.25s"), Ok(Duration::from_millis(250)));
        assert_eq!(parse("0.000000001s"), Ok(Duration::from_nanos(1)));
    }

    #[test]
    fn what_is_not_a_time_says_so_with_examples() {
        for text in [
            "soon",
            "-1s",
            "",
            ".",
            "1.",
            "1..5",
            "2 parsecs",
            "1e3",
            "+5",
        ] {
            assert_eq!(
                parse(text),
                Err(DurationError::NotATime(text.into())),
                "{text:?}"
            );
            assert!(!is_duration(text), "{text:?}");
        }
        assert_eq!(
            parse("soon").unwrap_err().to_string(),
            "'soon' is not a time (e.g. 100ms, 2s, or a number of milliseconds)"
        );
    }

    #[test]
    fn times_longer_than_a_week_are_refused_as_too_long() {
        assert_eq!(parse("7days"), Ok(MAX));
        assert_eq!(parse("604800000"), Ok(MAX));
        for text in [
            "8days",
            "604800001",
            "604800000.000001",
            "300000000000y",
            "18446744073709551615",
            "99999999999999999999999",
            "99999999999999999999999y",
        ] {
            assert_eq!(
                parse(text),
                Err(DurationError::TooLong(text.into())),
                "{text}"
            );
            assert!(is_duration(text), "{text}");
        }
        for text in [
            "300000000000y",
            "8days",
            "604800001",
            "18446744073709551615",
        ] {
            assert_eq!(
                parse(text).unwrap_err().to_string(),
                format!("'{text}' is longer than 7 days, the longest time allowed here"),
            );
        }
        assert!(is_duration("2s") && !is_duration("actual_position") && !is_duration("-1s"));
    }
}
