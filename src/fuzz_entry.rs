//! Entry points of the fuzz targets (`fuzz/`, run with `cargo +nightly fuzz run NAME`): one
//! function per parser or byte-driven state machine, taking arbitrary bytes. Each must return
//! for every input — no panic, no hang, no unbounded growth — and checks what must hold for any
//! input it accepts (a formatted value parses back to itself, a disassembly reassembles to the
//! same program, a transcript's free text never becomes script code). They live in the library so
//! that `cargo test` on stable replays the committed corpus (`fuzz/corpus/NAME/`) through the
//! same code as the fuzzer.

use std::time::Duration;

use crate::commission::Snapshot;
use crate::dialect::replay::parse::parse as parse_transcript;
use crate::dialect::replay::recognise;
use crate::dialect::smd4::protocol::{
    self as smd4, CollectorState, Expectation, PrefixStyle, ReplyCollector, Request, Smd4Spec,
    check_reply,
};
use crate::dialect::smd4::replay as smd4_replay;
use crate::dialect::smd4::sim::{Smd4Sim, Smd4SimOptions};
use crate::dialect::tmcl::asm::{self, disassemble};
use crate::dialect::tmcl::profile::Profile;
use crate::dialect::tmcl::protocol::frame::{
    FRAME_LEN, decode_version_string, encode_version_string,
};
use crate::dialect::tmcl::protocol::line::format_raw;
use crate::dialect::tmcl::protocol::syntax::parse_line;
use crate::dialect::tmcl::protocol::validate::validate_instruction;
use crate::dialect::tmcl::protocol::{
    CommandFrame, FrameDecoder, Instruction, Mode, ReplyFrame, address_of, format_line, parse,
    parse_reply, validate,
};
use crate::dialect::tmcl::replay as tmcl_replay;
use crate::dialect::tmcl::sim::Bus;
use crate::link::can::slcan;
use crate::sim::Device;
use crate::sim::fault::{Faults, Faulty};

/// A fuzz target: its name (the directory under `fuzz/corpus/`) and its entry point.
pub type Target = (&'static str, fn(&[u8]));

/// Every target, by name.
pub const TARGETS: &[Target] = &[
    ("tmcl_line", tmcl_line),
    ("tmcl_reply", tmcl_reply),
    ("tmcl_frame", tmcl_frame),
    ("slcan", slcan),
    ("smd4_request", smd4_request),
    ("smd4_response", smd4_response),
    ("asm", asm),
    ("disasm", disasm),
    ("profile_toml", profile_toml),
    ("snapshot_toml", snapshot_toml),
    ("transcript", transcript),
    ("sim_tmcl", sim_tmcl),
    ("sim_smd4", sim_smd4),
];

fn text(data: &[u8]) -> std::borrow::Cow<'_, str> {
    String::from_utf8_lossy(data)
}

/// A typed TMCL line: grammar, resolution against the built-in profile, validation in every
/// mode. A line that resolves is formatted to the line that is sent: its address character,
/// then a command that must resolve to the same one (the module reads the first character as
/// the address, so `R` + `SAP` is not `RSAP`).
pub fn tmcl_line(data: &[u8]) {
    let profile = Profile::builtin();
    for line in text(data).lines() {
        if let Ok(raw) = parse_line(line, |w| profile.commands.is_word(w)) {
            let _ = format_raw(&raw, 1);
        }
        let Ok(parsed) = parse(line, &profile) else {
            continue;
        };
        for mode in [Mode::Ascii, Mode::Binary, Mode::Program] {
            let _ = validate(&parsed, &profile, mode);
        }
        let canonical = format_line(&parsed, 1, &profile);
        let mut chars = canonical.chars();
        let address = chars.next().and_then(address_of);
        assert_eq!(address, Some(parsed.address.unwrap_or(1)), "{canonical}");
        let command = chars.as_str();
        let again = parse(command, &profile)
            .unwrap_or_else(|e| panic!("'{line}' is sent as '{canonical}', which fails: {e}"));
        assert_eq!(again.op, parsed.op, "'{line}' is sent as '{canonical}'");
        assert_eq!(again.address, None, "'{line}' is sent as '{canonical}'");
    }
}

/// An ASCII reply line: a reply that parses formats back to a line that parses to itself.
pub fn tmcl_reply(data: &[u8]) {
    for line in text(data).split_inclusive(['\r', '\n']) {
        if let Some(reply) = parse_reply(line) {
            assert_eq!(parse_reply(&reply.format()), Some(reply), "{line:?}");
        }
    }
}

/// Binary frames arriving in pieces: every complete frame with a good checksum decodes as command
/// and reply frame and encodes back to the same nine bytes; version strings decode from anything.
pub fn tmcl_frame(data: &[u8]) {
    let mut decoder = FrameDecoder::new();
    let mut rest = data;
    while let Some((&split, tail)) = rest.split_first() {
        let take = usize::from(split % 16).min(tail.len());
        decoder.push(&tail[..take]);
        rest = &tail[take..];
        while let Some(frame) = decoder.next_frame() {
            let (host, version) = decode_version_string(&frame.unwrap_or_else(|e| e.bytes));
            assert_eq!(version.len(), FRAME_LEN - 1);
            assert_eq!(
                decode_version_string(&encode_version_string(host, &version)),
                (host, version)
            );
            let Ok(frame) = frame else { continue };
            let command = CommandFrame::decode(&frame).expect("the checksum was verified");
            assert_eq!(command.encode(), frame);
            let reply = ReplyFrame::decode(&frame).expect("the checksum was verified");
            assert_eq!(reply.encode(), frame);
        }
        assert!(decoder.pending() < FRAME_LEN);
    }
}

/// slcan text from an adapter (or a host), in pieces: the events do not depend on where the
/// bytes were cut, no partial line outgrows the longest slcan line, and every frame read encodes
/// back to a line that reads as the same frame.
pub fn slcan(data: &[u8]) {
    let (mut whole, mut pieces) = (Vec::new(), Vec::new());
    slcan::Decoder::default().push(data, &mut whole);
    let mut decoder = slcan::Decoder::default();
    let mut rest = data;
    while let Some((&split, tail)) = rest.split_first() {
        let take = usize::from(split % 16).min(tail.len());
        decoder.push(&tail[..take], &mut pieces);
        rest = &tail[take..];
    }
    for event in &whole {
        if let slcan::Event::Frame(frame) = event {
            let line = slcan::encode(frame);
            let mut again = Vec::new();
            slcan::Decoder::default().push(line.as_bytes(), &mut again);
            assert_eq!(again, vec![event.clone()], "{line:?}");
        }
    }
    let mut cut = Vec::new();
    let mut decoder = slcan::Decoder::default();
    for chunk in data.chunks(7) {
        decoder.push(chunk, &mut cut);
    }
    assert_eq!(cut, whole, "events depend on where the bytes were cut");
}

/// A typed SMD4 request: parse, validate against the built-in table, and format back to a line
/// that parses to the same request.
pub fn smd4_request(data: &[u8]) {
    let table = &Smd4Spec::builtin().commands;
    for line in text(data).lines() {
        let Ok((request, style)) = Request::parse_styled(line) else {
            continue;
        };
        let _ = smd4::validate(&request, table);
        let _ = Expectation::for_request(table, &request);
        let style = style.unwrap_or(PrefixStyle::Attached);
        let again = Request::parse_styled(&request.format(style))
            .unwrap_or_else(|e| panic!("'{line}' formats to a line that fails: {e}"));
        assert_eq!(again.0, request, "{line:?}");
    }
}

/// SMD4 reply lines against every command's expectation (the first byte picks the command), and
/// through the multi-line collector.
pub fn smd4_response(data: &[u8]) {
    let Some((&pick, rest)) = data.split_first() else {
        return;
    };
    let table = &Smd4Spec::builtin().commands;
    let specs: Vec<_> = table.iter().collect();
    let expect = match specs.get(usize::from(pick)) {
        Some(spec) => Expectation::for_command(spec),
        None => Expectation::unknown(),
    };
    let text = text(rest);
    let mut collector = ReplyCollector::new(expect.clone());
    let mut complete = false;
    for line in text.split_inclusive('\n') {
        if let Ok(reply) = smd4::parse_reply(line, &expect) {
            let _ = reply.data_strings();
            let _ = reply.user_real();
            for to in [None, Some(0), Some(5)] {
                let _ = check_reply(&reply, &expect, to);
            }
            let _ = reply.into_result();
        }
        if !complete {
            complete = matches!(collector.push_line(line), Ok(CollectorState::Complete(_)));
        }
    }
    if !complete {
        let _ = collector.finish_quiet();
    }
}

/// Assembler source. A program that assembles survives the `.bin` format, and its disassembly
/// reassembles to the same instructions.
pub fn asm(data: &[u8]) {
    let profile = Profile::builtin();
    let source = text(data);
    let _ = asm::load_program(data, "fuzz.tmc", &profile);
    let Ok(program) = asm::assemble(&source, "fuzz.tmc", &profile) else {
        return;
    };
    let _ = program.listing(&source);
    let bytes = asm::write_binary(&program.instructions).expect("a program fits its file");
    assert_eq!(asm::read_binary(&bytes).as_ref(), Ok(&program.instructions));
    reassembles(&program.instructions, &profile);
}

/// Instructions as stored in program memory (7 bytes each) and `.bin` files: disassembly never
/// fails, and a program of instructions that are valid in a program reassembles to itself.
pub fn disasm(data: &[u8]) {
    let profile = Profile::builtin();
    if let Ok(instructions) = asm::read_binary(data) {
        let _ = disassemble(&instructions, &profile);
    }
    let instructions: Vec<Instruction> = data
        .chunks_exact(7)
        .map(|c| Instruction::from_bytes(c.try_into().expect("seven bytes")))
        .collect();
    let _ = disassemble(&instructions, &profile);
    let mut valid: Vec<Instruction> = instructions
        .into_iter()
        .filter(|i| validate_instruction(i, &profile, Mode::Program).is_ok())
        .collect();
    valid.truncate(usize::from(profile.program_memory));
    reassembles(&valid, &profile);
}

fn reassembles(instructions: &[Instruction], profile: &Profile) {
    if instructions.is_empty() {
        return;
    }
    let disassembly = disassemble(instructions, profile);
    if !disassembly.problems.is_empty() {
        return;
    }
    let again = asm::assemble(&disassembly.source, "disassembly", profile)
        .map(|p| p.instructions)
        .unwrap_or_else(|e| panic!("{}\n{e}", disassembly.source));
    assert_eq!(again, instructions, "{}", disassembly.source);
}

/// A module profile (`--profile FILE`): loading, then using it to parse, validate and format.
pub fn profile_toml(data: &[u8]) {
    let builtin = Profile::builtin();
    let Ok(profile) = Profile::from_toml(&text(data), Some(&builtin.commands)) else {
        return;
    };
    let _ = profile.find_axis("actual_position");
    let _ = profile.find_global("ascii_mode");
    let _ = profile.matching("speed").count();
    for line in [
        "GAP 1, 0",
        "SAP 4, 0, 1000",
        "GGP 67, 0",
        "MVP ABS, 0, 100",
        "BIN",
    ] {
        if let Ok(parsed) = parse(line, &profile) {
            let _ = validate(&parsed, &profile, Mode::Ascii);
            let _ = format_line(&parsed, 1, &profile);
        }
    }
}

/// A parameter snapshot file: what loads saves to text that loads to the same text.
pub fn snapshot_toml(data: &[u8]) {
    let Ok(snapshot) = Snapshot::parse(&text(data)) else {
        return;
    };
    let saved = snapshot.to_toml();
    let again = Snapshot::parse(&saved)
        .unwrap_or_else(|e| panic!("a saved snapshot does not load: {e}\n{saved}"));
    assert_eq!(again.to_toml(), saved);
}

/// A `--log` transcript turned into a Rhai script (TMCL and SMD4): the script compiles, and the
/// free text the transcript carries into comments never changes the script's code.
pub fn transcript(data: &[u8]) {
    let Ok(entries) = parse_transcript(&text(data)) else {
        return;
    };
    let _ = recognise(&entries);
    let profile = Profile::builtin();
    let steps = tmcl_replay::steps(&entries, &profile);
    let script = tmcl_replay::to_rhai(&steps, &profile, "fuzz.log", 1000);
    let blanked: Vec<tmcl_replay::Step> = steps
        .iter()
        .map(|s| match s {
            tmcl_replay::Step::Comment(_) => tmcl_replay::Step::Comment(String::new()),
            s => s.clone(),
        })
        .collect();
    same_code(
        &script,
        &tmcl_replay::to_rhai(&blanked, &profile, "fuzz.log", 1000),
    );
    let spec = Smd4Spec::builtin();
    let steps = smd4_replay::steps(&entries, spec);
    let script = smd4_replay::to_rhai(&steps, spec, "fuzz.log", 1000);
    let blanked: Vec<smd4_replay::Step> = steps
        .iter()
        .map(|s| match s {
            smd4_replay::Step::Comment(_) => smd4_replay::Step::Comment(String::new()),
            s => s.clone(),
        })
        .collect();
    same_code(
        &script,
        &smd4_replay::to_rhai(&blanked, spec, "fuzz.log", 1000),
    );
}

/// `script` compiles and has the same code, comments aside, as `blanked`.
fn same_code(script: &str, blanked: &str) {
    let mut engine = rhai::Engine::new();
    engine.set_max_expr_depths(0, 0);
    if let Err(e) = engine.compile(script) {
        panic!("the replay script does not compile: {e}\n{script}");
    }
    assert_eq!(
        code_of(script),
        code_of(blanked),
        "comment text changed the code:\n{script}"
    );
}

/// The script without its `//` comments (string literals, where `//` is text, are kept).
fn code_of(script: &str) -> Vec<String> {
    let mut lines = Vec::new();
    for line in script.split(['\n', '\r']) {
        let mut code = String::new();
        let mut in_string = false;
        let mut escaped = false;
        let mut chars = line.chars().peekable();
        while let Some(c) = chars.next() {
            if in_string {
                match (escaped, c) {
                    (false, '\\') => escaped = true,
                    (false, '"') => in_string = false,
                    _ => escaped = false,
                }
            } else if c == '"' {
                in_string = true;
            } else if c == '/' && chars.peek() == Some(&'/') {
                break;
            }
            code.push(c);
        }
        let code = code.trim_end().to_string();
        if !code.is_empty() {
            lines.push(code);
        }
    }
    lines
}

/// The simulated TMCM-142 bus fed arbitrary bytes, console commands and the passing of time,
/// up to 2^28 µs (4.5 minutes): a stored program runs one instruction per 100 µs of simulated
/// time, each costing real time, so an hour of a looping program is a minute of work.
pub fn sim_tmcl(data: &[u8]) {
    let limit = Duration::from_micros(1 << 28);
    drive(Faulty::new(Bus::builtin(), Faults::default()), data, limit);
}

/// The simulated SMD4 drive (factory settings in memory) fed the same, for as long as the
/// console's `advance` can reach (its motion is analytic, so time costs nothing).
pub fn sim_smd4(data: &[u8]) {
    let sim = Smd4Sim::new(Smd4SimOptions::default());
    let limit = Duration::from_nanos(u64::MAX / 2);
    drive(Faulty::new(sim, Faults::default()), data, limit);
}

/// Plays `data` to `device` as a script of steps, each a header byte and what follows: bytes
/// from the host (header % 4 == 0 or 1: the next 1..=64 bytes), a console command line (2: the
/// next 1..=64 bytes as text), or time passing (3: 2^(header / 4) microseconds, then the output
/// is collected). Time never goes backwards and stops at `limit`.
fn drive(mut device: impl Device, data: &[u8], limit: Duration) {
    let mut now = Duration::ZERO;
    let mut out = Vec::new();
    let mut rest = data;
    while let Some((&header, tail)) = rest.split_first() {
        let len = (usize::from(header >> 2) + 1).min(tail.len());
        let (chunk, after) = tail.split_at(len);
        match header % 4 {
            0 | 1 => {
                device.receive(now, chunk);
                rest = after;
            }
            2 => {
                let _ = device.control(now, &String::from_utf8_lossy(chunk));
                rest = after;
            }
            _ => {
                let step = Duration::from_micros(1u64 << (header >> 2).min(40));
                now = (now + step).min(limit);
                rest = tail;
            }
        }
        device.poll_output(now, &mut out);
        let _ = device.next_due(now);
        if device.hung_up() {
            device.reconnect();
        }
        out.clear();
    }
}
