//! Bus addresses as users write them for a scan (`1-26`, `A-Z`, `A,C,30-40`) and as a scan
//! report shows them: what every dialect's scan shares.

use std::time::Duration;

/// How long a scan waits for each reply unless `--timeout` says otherwise: a module answers a
/// probe at once, so this is the wire time of a short exchange at 9600 baud over a USB adapter
/// (about 40 ms) with a margin; a scan of 26 empty TMCL addresses then takes about 5 s, not 50.
pub const SCAN_WAIT: Duration = Duration::from_millis(100);

/// The wait per reply of a scan in a session whose reply timeout is `timeout`: [`SCAN_WAIT`]
/// while it is the built-in default (the session's long default is for slow commands), the
/// timeout itself when one was set.
pub fn scan_wait(timeout: Duration) -> Duration {
    if timeout == crate::session::SessionOptions::default().timeout {
        SCAN_WAIT
    } else {
        timeout
    }
}

/// Parses an address list: numbers 1..`max` and letters A..Z, single or as ranges, comma
/// separated (`1-26`, `A-Z`, `A,C,30-40`).
pub fn parse_addresses(text: &str, max: u8) -> Result<Vec<u8>, AddressError> {
    let one = |word: &str| -> Result<u8, AddressError> {
        let word = word.trim();
        if let Ok(n) = word.parse::<u8>() {
            if (1..=max).contains(&n) {
                return Ok(n);
            }
        }
        let mut chars = word.chars();
        match (chars.next().and_then(letter), chars.next()) {
            (Some(a), None) => Ok(a),
            _ => Err(AddressError::NotAnAddress {
                word: word.to_string(),
                max,
            }),
        }
    };
    let mut addresses = Vec::new();
    for part in text.split(',') {
        let (lo, hi) = match part.split_once('-') {
            Some((lo, hi)) => (one(lo)?, one(hi)?),
            None => {
                let a = one(part)?;
                (a, a)
            }
        };
        if lo > hi {
            return Err(AddressError::Backwards(part.trim().to_string()));
        }
        for a in lo..=hi {
            if !addresses.contains(&a) {
                addresses.push(a);
            }
        }
    }
    addresses.sort_unstable();
    Ok(addresses)
}

/// Why an address list is refused.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum AddressError {
    /// A word that is neither a number in range nor a letter.
    #[error("'{word}' is not a bus address (1..{max} or A..Z)")]
    NotAnAddress {
        /// The word as written.
        word: String,
        /// The highest address of the dialect.
        max: u8,
    },
    /// A range whose end comes before its start (`5-2`).
    #[error("the range '{0}' runs backwards")]
    Backwards(String),
}

/// A letter as an address: A is 1 … Z is 26 (TMCL's address characters; any dialect may take
/// them).
fn letter(c: char) -> Option<u8> {
    let upper = c.to_ascii_uppercase();
    upper.is_ascii_uppercase().then(|| upper as u8 - b'A' + 1)
}

/// The addresses as a short text (`1-26`, `1-3, 7`).
pub fn describe_addresses(addresses: &[u8]) -> String {
    let mut parts: Vec<String> = Vec::new();
    let mut i = 0;
    while i < addresses.len() {
        let start = addresses[i];
        let mut end = start;
        while i + 1 < addresses.len() && addresses[i + 1] == end + 1 {
            i += 1;
            end = addresses[i];
        }
        parts.push(if start == end {
            start.to_string()
        } else {
            format!("{start}-{end}")
        });
        i += 1;
    }
    parts.join(", ")
}

/// A scan's summary line: how many of `noun` answered where, and how long each reply was
/// awaited (`3 modules answered at 1-26 (at most 200 ms per reply)`, `no drive answered at …`).
pub fn scan_summary(found: usize, noun: &str, scanned: &[u8], per_reply: Duration) -> String {
    let who = match found {
        0 => format!("no {noun} answered"),
        n => format!("{} answered", crate::count::counted(n, noun)),
    };
    format!(
        "{who} at {} (at most {} ms per reply)",
        describe_addresses(scanned),
        per_reply.as_millis()
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn address_lists_take_numbers_letters_and_ranges() {
        assert_eq!(
            parse_addresses("1-26", 255).unwrap(),
            (1..=26).collect::<Vec<u8>>()
        );
        assert_eq!(
            parse_addresses("A-Z", 255).unwrap(),
            (1..=26).collect::<Vec<u8>>()
        );
        assert_eq!(
            parse_addresses("c, a,30-32", 255).unwrap(),
            [1, 3, 30, 31, 32]
        );
        assert_eq!(parse_addresses("255", 255).unwrap(), [255]);
        assert!(
            parse_addresses("0", 255)
                .unwrap_err()
                .to_string()
                .contains("'0' is not a bus address")
        );
        assert!(
            parse_addresses("5-2", 255)
                .unwrap_err()
                .to_string()
                .contains("runs backwards")
        );
        assert!(parse_addresses("AA", 255).is_err());
        assert!(parse_addresses("256", 255).is_err());
        assert!(
            parse_addresses("248", 247)
                .unwrap_err()
                .to_string()
                .contains("'248' is not a bus address (1..247 or A..Z)")
        );
    }

    #[test]
    fn addresses_are_described_as_ranges() {
        assert_eq!(describe_addresses(&[1, 2, 3, 7, 9, 10]), "1-3, 7, 9-10");
        assert_eq!(describe_addresses(&(1..=26).collect::<Vec<u8>>()), "1-26");
    }
}
