//! Transcript to script, on transcripts written the way the session writes them.

use super::*;
use crate::dialect::replay::parse;
use crate::dialect::replay::{Recognised, ReplayError, recognise};
use crate::dialect::smd4::config::header as smd4_header;
use crate::dialect::tmcl::config::header as tmcl_header;
use crate::dialect::tmcl::protocol::frame::encode_version_string;
use crate::session::transcript::{Header, escape_into};

/// Builds transcript text line by line.
#[derive(Default)]
struct Log(String);

impl Log {
    fn bytes(&mut self, tag: &str, bytes: &[u8], meaning: &str) -> &mut Self {
        self.0.push_str("2026-01-01T00:00:00.000Z ");
        self.0.push_str(tag);
        self.0.push(' ');
        escape_into(bytes, &mut self.0);
        if !meaning.is_empty() {
            self.0.push_str(" ; ");
            self.0.push_str(meaning);
        }
        self.0.push('\n');
        self
    }
    fn tx(&mut self, line: &str) -> &mut Self {
        self.bytes("tx", format!("{line}\r").as_bytes(), "to module A")
    }
    /// A reply with line echo, as the session logs it.
    fn rx(&mut self, sent: &str, status: u8, value: i32) -> &mut Self {
        let module = sent.chars().next().unwrap();
        let bytes = format!("{sent}\rB{module} {status} {value}\r");
        self.bytes(
            "rx",
            bytes.as_bytes(),
            &format!("{module}: {status}, value {value}"),
        )
    }
    fn exchange(&mut self, sent: &str, status: u8, value: i32) -> &mut Self {
        self.tx(sent).rx(sent, status, value)
    }
    fn note(&mut self, text: &str) -> &mut Self {
        self.0.push_str("2026-01-01T00:00:00.000Z -- ");
        self.0.push_str(text);
        self.0.push('\n');
        self
    }
    /// What the session writes when it first contacts module A.
    fn contact(&mut self) -> &mut Self {
        let enter = CommandFrame {
            address: 1,
            instruction: Instruction::new(139, 0, 0, 0),
        }
        .encode();
        let reply = ReplyFrame {
            host: 2,
            module: 1,
            status: Status::Ok,
            command: 139.into(),
            value: 0,
        }
        .encode();
        self.bytes("tx", &enter, "enter ASCII mode (139) to module 1")
            .bytes("rx", &reply, "binary reply to 139: status 100")
            .bytes("tx", b"\r", "end of line, clears any partial line")
            .exchange("AGGP 67, 0", 100, 17)
            .note("module A in ASCII mode, echo line, found in binary mode")
    }
    fn steps(&self) -> Vec<Step> {
        let entries = parse::parse(&self.0).unwrap();
        steps(&entries, &Profile::builtin())
    }
    fn script(&self) -> String {
        to_rhai(&self.steps(), &Profile::builtin(), "t.log", 5000)
    }
}

/// The script's lines after its header comment.
fn body(script: &str) -> Vec<&str> {
    let start = script.find("\n\n").unwrap() + 2;
    script[start..].lines().filter(|l| !l.is_empty()).collect()
}

#[test]
fn the_session_s_own_traffic_is_left_out() {
    let mut log = Log::default();
    log.note("session opened on simulator").contact();
    log.exchange("AGAP 6, 0", 100, 128);
    log.bytes("tx", b"\r", "resynchronise after timeout");
    let steps = log.steps();
    assert_eq!(steps.len(), 1, "{steps:?}");
    assert!(matches!(&steps[0], Step::Exchange { line, value: 128, .. } if line == "AGAP 6, 0"));
}

#[test]
fn a_user_s_own_read_of_the_echo_setting_is_kept() {
    let mut log = Log::default();
    log.contact().exchange("AGGP 67, 0", 100, 17);
    assert_eq!(log.steps().len(), 1);
}

#[test]
fn settings_are_checked_exactly_and_errors_by_status() {
    let mut log = Log::default();
    log.contact()
        .exchange("ASAP 6, 0, 100", 100, 100)
        .exchange("AGAP 6, 0", 100, 100)
        .exchange("ASAP 6, 0, 99", 4, 99);
    assert_eq!(
        body(&log.script()),
        [
            "assert_eq(send(\"ASAP 6, 0, 100\"), 100);  // max_current",
            "assert_eq(send(\"AGAP 6, 0\"), 100);  // max_current",
            "assert_eq(reply(\"ASAP 6, 0, 99\").status, 4);  // max_current",
        ]
    );
}

#[test]
fn live_values_are_awaited_only_where_they_had_settled() {
    let mut log = Log::default();
    log.contact()
        .exchange("AMVP ABS, 0, 1000", 100, 1000)
        .exchange("AGAP 1, 0", 100, 400)
        .exchange("AGAP 1, 0", 100, 1000)
        .exchange("AGAP 8, 0", 100, 1)
        .exchange("AGAP 1, 0", 100, 1000)
        .exchange("AMVP ABS, 0, 0", 100, 0)
        .exchange("AGAP 1, 0", 100, 1000);
    assert_eq!(
        body(&log.script()),
        [
            "assert_eq(send(\"AMVP ABS, 0, 1000\"), 1000);",
            "send(\"AGAP 1, 0\");  // read 400, not checked (it may have been changing), actual_position",
            "send(\"AGAP 1, 0\");  // read 1000, not checked (it may have been changing), actual_position",
            "send(\"AGAP 8, 0\");  // read 1, not checked (it may have been changing), target_position_reached",
            "wait_until(|| send(\"AGAP 1, 0\") == 1000, 5000);  // actual_position",
            "assert_eq(send(\"AMVP ABS, 0, 0\"), 0);",
            "send(\"AGAP 1, 0\");  // read 1000, not checked (it may have been changing), actual_position",
        ]
    );
}

#[test]
fn binary_mode_commands_replay_as_lines_and_the_version_as_firmware_version() {
    let mut log = Log::default();
    log.contact().exchange("ABIN", 100, 0);
    let gap = CommandFrame {
        address: 1,
        instruction: Instruction::new(6, 4, 0, 0),
    }
    .encode();
    let gap_reply = ReplyFrame {
        host: 2,
        module: 1,
        status: Status::Ok,
        command: 6.into(),
        value: 2047,
    }
    .encode();
    let version = CommandFrame {
        address: 2,
        instruction: Instruction::new(136, 0, 0, 0),
    }
    .encode();
    let stop_app = CommandFrame {
        address: 1,
        instruction: Instruction::new(128, 0, 0, 0),
    }
    .encode();
    log.bytes("tx", &gap, "GAP 4, 0 to module 1 (A) in binary")
        .bytes("rx", &gap_reply, "from module 1: 100, value 2047")
        .bytes("tx", &version, "136 to module 2 (binary)")
        .bytes(
            "rx",
            &encode_version_string(2, "142V1.07"),
            "version 142V1.07",
        )
        .bytes("tx", &stop_app, "128 to module 1 (binary)")
        .bytes("rx", &gap_reply, "from module 1: 100");
    assert_eq!(
        body(&log.script()),
        [
            "assert_eq(send(\"AGAP 4, 0\"), 2047);  // max_positioning_speed",
            "target(2);",
            "assert_eq(firmware_version(), \"142V1.07\");",
            "// not replayed (binary direct mode only): 128 to module 1 (A)",
        ]
    );
}

#[test]
fn lines_without_reply_and_stale_bytes_are_comments_or_ignored() {
    let mut log = Log::default();
    log.contact()
        .bytes(
            "rx",
            b"BA 100 5\r",
            "arrived outside any exchange, discarded",
        )
        .tx("AGAP 6, 0")
        .bytes("rx", b"AGAP", "incomplete, no reply")
        .note("no reply from module 1 (A) within 1000 ms")
        .exchange("AGAP 7, 0", 100, 8);
    let steps = log.steps();
    assert_eq!(steps[0], Step::Comment("no reply to AGAP 6, 0".into()));
    assert!(matches!(&steps[1], Step::Exchange { value: 8, .. }));
}

#[test]
fn rhai_strings_escape_quotes_and_backslashes() {
    assert_eq!(rhai_string("a\"b\\c"), "\"a\\\"b\\\\c\"");
    assert_eq!(rhai_string("x\u{1}"), "\"x\\x01\"");
}

#[test]
fn comments_escape_control_characters_and_line_separators() {
    // Every comment goes through this; a line break in it would turn the rest into code.
    assert_eq!(comment("a\r\nb"), "a\\u{d}\\u{a}b");
    assert_eq!(comment("x\u{85}y\u{2029}"), "x\\u{85}y\\u{2029}");
    assert_eq!(comment("plain // text"), "plain // text");
}

impl Log {
    fn header(&mut self, header: &Header) -> &mut Self {
        self.0.push_str("2026-01-01T00:00:00.000Z ## ");
        self.0.push_str(&header.to_text());
        self.0.push('\n');
        self
    }
    fn recognised(&self) -> Result<Recognised, ReplayError> {
        recognise(&parse::parse(&self.0).unwrap())
    }
}

#[test]
fn the_header_says_what_a_transcript_is_of() {
    let mut log = Log::default();
    log.header(&smd4_header()).tx("MOTOR:STOP");
    let kind = log.recognised().unwrap();
    assert_eq!(
        (kind.dialect, kind.notice),
        (&crate::dialect::smd4::DIALECT, None)
    );
    // The same session again, appended: still one kind.
    log.header(&smd4_header()).tx("SYS:FW");
    assert_eq!(
        log.recognised().unwrap().dialect,
        &crate::dialect::smd4::DIALECT
    );
}

#[test]
fn sessions_of_different_modules_in_one_file_are_refused() {
    let mut log = Log::default();
    log.header(&tmcl_header(&Profile::builtin()))
        .exchange("AGAP 4, 0", 100, 5)
        .header(&smd4_header());
    let error = log.recognised().unwrap_err().to_string();
    assert!(
        error.contains("TMCL TMCM-142 (line 1) and SMD4 SMD4 (line 4)"),
        "{error}"
    );
}

#[test]
fn a_file_from_before_headers_is_read_with_a_notice() {
    let mut log = Log::default();
    log.note("SMD4 session opened on simulator")
        .tx("MOTOR:STOP");
    let kind = log.recognised().unwrap();
    assert_eq!(kind.dialect, &crate::dialect::smd4::DIALECT);
    assert!(kind.notice.unwrap().contains("read as SMD4"));
    let mut log = Log::default();
    log.exchange("AGAP 4, 0", 100, 5);
    assert_eq!(
        log.recognised().unwrap().dialect,
        &crate::dialect::tmcl::DIALECT
    );
    log.header(&tmcl_header(&Profile::builtin()));
    let kind = log.recognised().unwrap();
    assert!(
        kind.notice
            .unwrap()
            .contains("lines before line 3 have no header")
    );
}

#[test]
fn a_transcript_of_only_failures_replays_nothing() {
    let mut log = Log::default();
    log.contact()
        .tx("AGAP 6, 0")
        .note("no reply from module 1 (A) within 1000 ms");
    assert!(!replays_something(&log.steps()));
    log.exchange("AGAP 7, 0", 100, 8);
    assert!(replays_something(&log.steps()));
    // SMD4 lines read as TMCL: not lines a TMCM module understands.
    let mut log = Log::default();
    log.tx("MOTOR:STOP").tx("SYS:FW");
    assert!(!replays_something(&log.steps()));
}
