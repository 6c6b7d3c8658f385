//! Telling an AML SMD4 drive on a line where a TMCL module was expected: a drive ends its lines
//! with LF and ignores TMCL's CR-ended lines and binary frames, so a TMCL session hears nothing.
//! After a silent start the session sends [`SMD4_PROBE`] — a line end (which makes a drive answer
//! whatever TMCL bytes it was holding with a packet error) and a harmless SMD4 query — and looks
//! for a reply of the drive's shape: `[@N,]SFLAGS,EFLAGS[,…]`, each flag word four hex digits,
//! usually `0x`-prefixed (`0x0000,0x0000,-101 (Packet Error)`). Pure: bytes in, a verdict out.

/// What the session sends to find out whether an SMD4 drive is listening: CR LF ends whatever the
/// drive holds, then the firmware query, read-only. Ten bytes, so never one binary frame of nine.
pub const SMD4_PROBE: &[u8] = b"\r\nSYS:FW\r\n";

/// The first line in `heard` with the shape of an SMD4 reply, if any.
pub fn smd4_reply(heard: &[u8]) -> Option<String> {
    heard
        .split(|&b| b == b'\n' || b == b'\r')
        .filter_map(|line| std::str::from_utf8(line).ok())
        .find(|line| smd4_shaped(line))
        .map(str::to_string)
}

/// `[@N[,]]FLAGS,FLAGS[,…]`: the status and error words of an SMD4 reply, then its items.
fn smd4_shaped(line: &str) -> bool {
    let mut rest = line.trim();
    if let Some(after) = rest.strip_prefix('@') {
        let digits = after.chars().take_while(char::is_ascii_digit).count();
        if digits == 0 {
            return false;
        }
        rest = after[digits..].trim_start_matches(',').trim_start();
    }
    let mut words = rest.splitn(3, ',');
    let flags = |word: Option<&str>| {
        word.map(|w| w.trim())
            .map(|w| w.strip_prefix("0x").or(w.strip_prefix("0X")).unwrap_or(w))
            .is_some_and(|w| w.len() == 4 && w.chars().all(|c| c.is_ascii_hexdigit()))
    };
    flags(words.next()) && flags(words.next())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_drive_s_replies_are_told() {
        for reply in [
            "0x0000,0x0000,-101 (Packet Error)",
            "0x0001,0x0000,24044.12",
            "@3,0x0000,0x0000",
            "@3 0x0000,0x00a0,1",
            "0000,0000",
        ] {
            assert!(smd4_shaped(reply), "{reply}");
        }
        let heard = b"\x02\x01\x64\x88\r\n0x0000,0x0000,-101 (Packet Error)\r\n";
        assert_eq!(
            smd4_reply(heard).as_deref(),
            Some("0x0000,0x0000,-101 (Packet Error)")
        );
    }

    #[test]
    fn tmcl_replies_and_noise_are_not_a_drive() {
        for line in [
            "BA 100 5000",
            "BA 2 0",
            "",
            "0x00,0x00",
            "@,0x0000,0x0000",
            "0x0000",
        ] {
            assert!(!smd4_shaped(line), "{line}");
        }
        assert_eq!(smd4_reply(b"\x02\x01\x64\x88\x00\x00\x00\x00\xef"), None);
    }

    #[test]
    fn the_probe_is_no_binary_frame() {
        assert_ne!(SMD4_PROBE.len(), 9);
        assert!(SMD4_PROBE.ends_with(b"\r\n"));
    }
}
