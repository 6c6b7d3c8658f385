//! Telling a Trinamic TMCL module on a line where an SMD4 drive was expected: a TMCL module in
//! binary mode takes the drive's text lines for broken frames and drops them, so an SMD4 session
//! hears nothing. After a silent start the session sends [`TMCL_FRAME_PROBE`] (command 136 to
//! address 1, the firmware version, read-only), then [`TMCL_ASCII_PROBE`] for a module in ASCII
//! mode, and looks for what a TMCL module sends back: a nine-byte reply frame whose checksum
//! holds, or an ASCII reply line `BA 100 1`. The frames are built here, byte by byte, since the
//! dialects share no code. Pure: bytes in, a verdict out.

/// Command 136 (get firmware version), type 1 (as a number), to module 1, with its checksum.
pub const TMCL_FRAME_PROBE: [u8; 9] = [1, 136, 1, 0, 0, 0, 0, 0, 138];

/// A read of global parameter 67 (the echo setting) from module 1 in the ASCII interface, after
/// a CR that ends whatever the module holds.
pub const TMCL_ASCII_PROBE: &[u8] = b"\rAGGP 67, 0\r";

/// What was heard of a TMCL module in `heard`: `binary reply to 136 (status 100)` or the
/// ASCII reply line, if any.
pub fn tmcl_reply(heard: &[u8]) -> Option<String> {
    if let Some(status) = heard.windows(9).find_map(reply_frame) {
        return Some(format!("a binary reply frame to 136 (status {status})"));
    }
    heard
        .split(|&b| b == b'\n' || b == b'\r')
        .filter_map(|line| std::str::from_utf8(line).ok())
        .find(|line| ascii_reply(line))
        .map(|line| format!("the ASCII reply `{}`", line.trim()))
}

/// The status of a reply frame to 136 with a sound checksum.
fn reply_frame(frame: &[u8]) -> Option<u8> {
    let sum = frame[..8].iter().fold(0u8, |a, b| a.wrapping_add(*b));
    let status = frame[2];
    let known = matches!(status, 1..=6 | 100 | 101);
    (sum == frame[8] && frame[3] == 136 && known).then_some(status)
}

/// `<host><module> <status> <value>`: a host character, a module letter, a status code a module
/// sends, a whole number.
fn ascii_reply(line: &str) -> bool {
    let mut chars = line.trim().chars();
    let (Some(_host), Some(module)) = (chars.next(), chars.next()) else {
        return false;
    };
    let rest: Vec<&str> = chars.as_str().split_whitespace().collect();
    let status_ok = |s: &str| matches!(s.parse::<u8>(), Ok(1..=6 | 100 | 101));
    let number = |s: &str| {
        s.strip_prefix('-')
            .unwrap_or(s)
            .chars()
            .all(|c| c.is_ascii_digit())
    };
    module.is_ascii_uppercase()
        && matches!(rest.as_slice(), [status, value] if status_ok(status) && !value.is_empty() && number(value))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_probe_frame_checks_out() {
        assert!(
            TMCL_FRAME_PROBE[..8]
                .iter()
                .map(|&b| u32::from(b))
                .sum::<u32>()
                % 256
                == 138
        );
        assert!(
            !TMCL_ASCII_PROBE.contains(&b'\n'),
            "no line end a drive would act on"
        );
    }

    #[test]
    fn a_module_s_replies_are_told() {
        let frame = [2, 1, 100, 136, 0, 0, 0x01, 0x06, 0];
        let sum = frame[..8].iter().fold(0u8, |a, b| a.wrapping_add(*b));
        let mut frame = frame;
        frame[8] = sum;
        let mut heard = b"junk".to_vec();
        heard.extend(frame);
        assert_eq!(
            tmcl_reply(&heard).as_deref(),
            Some("a binary reply frame to 136 (status 100)")
        );
        assert_eq!(
            tmcl_reply(b"BA 100 0\r\n").as_deref(),
            Some("the ASCII reply `BA 100 0`")
        );
    }

    #[test]
    fn drive_replies_and_noise_are_not_a_module() {
        assert_eq!(tmcl_reply(b"0x0000,0x0000,-101 (Packet Error)\r\n"), None);
        assert_eq!(tmcl_reply(b"BA 7 0\r\n"), None);
        let mut frame = [2, 1, 100, 136, 0, 0, 1, 6, 0];
        frame[8] = 1; // a wrong checksum
        assert_eq!(tmcl_reply(&frame), None);
    }
}
