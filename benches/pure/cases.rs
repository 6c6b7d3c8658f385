//! The pure parts, timed in-process: what every command costs before and after the wire.
//!
//! Each case runs in batches sized to take about 5 ms; the result is the median time per
//! operation over the batches, so a batch disturbed by another process on the machine does not
//! move it. Inputs and outputs pass through `black_box`, so the work cannot be optimised away.

use std::hint::black_box;
use std::time::{Duration, Instant};

use tmclsh::dialect::smd4::protocol::{self as smd4, Expectation, Smd4Spec, check_reply};
use tmclsh::dialect::tmcl::profile::Profile;
use tmclsh::dialect::tmcl::protocol::{
    CommandFrame, FrameDecoder, Instruction, ReplyFrame, Status, format_line, parse, parse_reply,
};
use tmclsh::escape::escape_control;

/// One timed case.
pub struct Case {
    pub name: &'static str,
    /// Median nanoseconds per operation.
    pub ns: f64,
}

const BATCH: Duration = Duration::from_millis(5);
const BATCHES: usize = 31;

/// Times `op` and returns the median nanoseconds per call.
fn time(mut op: impl FnMut()) -> f64 {
    // Warm up and size a batch.
    let mut n: u64 = 1;
    loop {
        let start = Instant::now();
        for _ in 0..n {
            op();
        }
        if start.elapsed() >= BATCH / 4 {
            break;
        }
        n *= 2;
    }
    n *= 4;
    let mut per_op: Vec<f64> = (0..BATCHES)
        .map(|_| {
            let start = Instant::now();
            for _ in 0..n {
                op();
            }
            start.elapsed().as_nanos() as f64 / n as f64
        })
        .collect();
    per_op.sort_by(f64::total_cmp);
    per_op[BATCHES / 2]
}

/// Runs every case.
pub fn run() -> Vec<Case> {
    let profile = Profile::builtin();
    let command = CommandFrame {
        address: 1,
        instruction: Instruction::new(6, 1, 0, 0),
    };
    let reply = ReplyFrame {
        host: 2,
        module: 1,
        status: Status::Ok,
        command: 6.into(),
        value: -5000,
    }
    .encode();
    let smd4 = Smd4Spec::builtin();
    let pact = Expectation::for_command(smd4.commands.get("MOTOR:PACT").expect("MOTOR:PACT"));
    let vmax = Expectation::for_command(smd4.commands.get("MOTOR:VMAX").expect("MOTOR:VMAX"));
    // One decoder for the whole run, as a receiver keeps one.
    let mut decoder = FrameDecoder::new();
    let case = |name, ns| Case { name, ns };
    vec![
        case(
            "TMCL frame encode (9 bytes)",
            time(|| {
                black_box(black_box(&command).encode());
            }),
        ),
        case(
            "TMCL frame decode, byte by byte (9 bytes)",
            time(|| {
                for &byte in black_box(&reply) {
                    decoder.push(&[byte]);
                }
                let frame = decoder.next_frame().expect("a frame").expect("checksum");
                black_box(ReplyFrame::decode(&frame).expect("valid"));
            }),
        ),
        case(
            "TMCL line parse + resolve + format (`GAP actual_position, 0`)",
            time(|| {
                let line = parse(black_box("GAP actual_position, 0"), &profile).expect("ok");
                black_box(format_line(&line, 1, &profile));
            }),
        ),
        case(
            "TMCL reply parse (`BA 100 -5000`)",
            time(|| {
                black_box(parse_reply(black_box("BA 100 -5000")));
            }),
        ),
        case(
            "SMD4 response parse (`0x0000,0x0000,1000.00`)",
            time(|| {
                black_box(smd4::parse_reply(black_box("0x0000,0x0000,1000.00"), &pact).ok());
            }),
        ),
        case(
            "SMD4 reply check (`0x0888,0x0000,1.0000E+03,1.0000E+03`, parsed)",
            {
                let line = "0x0888,0x0000,1.0000E+03,1.0000E+03";
                let reply = smd4::parse_reply(line, &vmax).expect("a reply");
                time(|| {
                    black_box(check_reply(black_box(&reply), &vmax, None).is_ok());
                })
            },
        ),
        case(
            "escape for the terminal, nothing to escape (36 chars)",
            time(|| {
                black_box(escape_control(black_box(
                    "0x0888,0x0000,1.0000E+03,1.0000E+03",
                )));
            }),
        ),
    ]
}
