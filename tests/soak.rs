//! The fast fault soak (the full one, 20,000 reads per cell, is a row of BENCHMARKS.md): in each
//! configuration, reads of known values at 1 % dropped, corrupted, delayed past the timeout, and
//! all three, through `tmclsh run` over a pty to `tmclsh sim`. A read returns the truth or fails
//! with a reported error; a different value returned normally is a silent wrong value, and there
//! must be none. The seed makes each cell replay: `tmclsh sim --seed N` or the console's `seed N`.

pub(crate) mod harness;

use harness::{
    Counts, Fault, Plan, Target, one_character_changed, one_digit_changed, run_cell,
    script_reading, tally_output,
};

use crate::sim::Sim;
use crate::util::{bin, run, stdout};

/// Reads per cell: 20 cells, 6,000 reads in all.
const READS: u64 = 300;

fn plan() -> Plan {
    Plan {
        reads: READS,
        rate: 0.01,
        timeout_ms: 100,
        delay_ms: 150,
        seed: 12,
    }
}

/// Runs the four fault cells of `target` and checks each.
fn soak(target: Target) {
    let plan = plan();
    let mut total = Counts::default();
    let mut report = Vec::new();
    for fault in Fault::ALL {
        let counts = run_cell(&bin(), target, fault, &plan);
        report.push(format!(
            "{} / {}: {} {:?}",
            target.name(),
            fault.name(),
            counts.summary(),
            counts.examples
        ));
        assert_eq!(counts.reads, plan.reads);
        assert_eq!(
            counts.ok + counts.failures() + counts.silent_wrong + counts.undetectable,
            counts.reads,
            "every read is counted once"
        );
        total.add(&counts);
    }
    let report = report.join("\n");
    println!("{report}");
    let injected = total.injected;
    assert!(
        injected.dropped > 0 && injected.corrupted > 0 && injected.delayed > 0,
        "the soak injected every kind of fault:\n{report}"
    );
    assert_eq!(
        total.silent_wrong, 0,
        "values returned without an error that are not the truth:\n{report}"
    );
    // The module never refuses these reads (the set-up read every value back), so each device
    // error would be line noise taken for a status the module did not send.
    assert_eq!(
        total.device, 0,
        "damaged replies taken for a refusal by the module:\n{report}"
    );
    assert_eq!(
        total.other, 0,
        "failures with an exit code other than 3 (link) or 1 (device):\n{report}"
    );
}

#[test]
fn soak_tmcl_char_echo() {
    soak(Target::TmclChar);
}

#[test]
fn soak_tmcl_line_echo() {
    soak(Target::TmclLine);
}

// With echo off nothing ties a reply to its request: a reply delayed past the timeout must be
// drained by the resynchronisation after the timeout, not taken as the next request's answer.
#[test]
fn soak_tmcl_no_echo() {
    soak(Target::TmclNone);
}

// Every SMD4 exchange is like TMCL with echo off: late replies must be drained, and garbled
// digits or truncated UUIDs refused by the check of the reply against the command's items.
#[test]
fn soak_smd4() {
    soak(Target::Smd4);
}

// The same with the drive in addressing mode: a reply must carry our `@7,` prefix.
#[test]
fn soak_smd4_addressed() {
    soak(Target::Smd4Addressed);
}

// Binary direct mode: a reply frame names its module and command, and carries a checksum.
#[test]
fn soak_tmcl_binary() {
    soak(Target::TmclBinary);
}

/// Reads per late-reply cell.
const LATE_READS: u64 = 2000;

/// Replies dropped and replies held back 250 ms, 2 % each: past the timeout (100 ms) and the
/// quiet wait after it (as long), so a late reply comes while the next request's answer is
/// awaited — the case a quiet line cannot rule out, which the barrier after a failure must.
fn late_plan() -> Plan {
    Plan {
        reads: LATE_READS,
        rate: 0.02,
        timeout_ms: 100,
        delay_ms: 250,
        seed: 12,
    }
}

/// Runs `target`'s late-reply cell: every read the truth or a reported failure.
fn late_replies(target: Target) {
    let plan = late_plan();
    let counts = run_cell(&bin(), target, Fault::DropDelay, &plan);
    let report = format!(
        "{} / {}: {} {:?}",
        target.name(),
        Fault::DropDelay.name(),
        counts.summary(),
        counts.examples
    );
    println!("{report}");
    assert_eq!(counts.reads, plan.reads);
    assert!(
        counts.injected.dropped > 0 && counts.injected.delayed > 10,
        "the cell injected late replies: {report}"
    );
    assert_eq!(
        counts.silent_wrong, 0,
        "late replies taken for the answer to a later request: {report}"
    );
    assert_eq!(
        (counts.device, counts.other),
        (0, 0),
        "a barrier's refusal (or a late one) taken for the module's: {report}"
    );
}

// A late frame names the same module and command as the next request's answer when the request is
// a read of another type or bank: the barrier after a failure keeps it out.
#[test]
fn late_replies_tmcl_binary() {
    late_replies(Target::TmclBinary);
}

#[test]
fn late_replies_tmcl_no_echo() {
    late_replies(Target::TmclNone);
}

#[test]
fn late_replies_smd4() {
    late_replies(Target::Smd4);
}

// The soak's count of device errors can see one: the same loop, its reads replaced by a request
// the module refuses (there is no parameter type 200: status 3), run on the built-in simulator.
#[test]
fn a_refusal_the_module_sends_is_counted_as_a_device_error() {
    let dir = std::env::temp_dir().join(format!("tmclsh-soak-refusal-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let script = dir.join("refused.rhai");
    let reader = "let names = [];\nfn read(names, i) { send(\"GAP 200, 0\") }\n";
    std::fs::write(&script, script_reading(reader, 1)).unwrap();
    let out = run(&["--sim", "run", script.to_str().unwrap(), "--", "7", "1"]);
    let _ = std::fs::remove_dir_all(&dir);
    let mut counts = Counts::default();
    let truth = ["0".to_string()];
    tally_output(&mut counts, &stdout(&out), &truth, Target::TmclChar, false);
    assert_eq!(
        (counts.reads, counts.device, counts.failures()),
        (7, 7, 7),
        "{}\n{}",
        counts.summary(),
        stdout(&out)
    );
}

#[test]
fn the_same_seed_replays_the_same_run() {
    // Drops and corruption; the "delay" of 0 ms holds nothing back. A real delay races the
    // client's timeout on the real clock, so its outcome may vary with the machine's load.
    let plan = Plan {
        reads: 150,
        rate: 0.04,
        timeout_ms: 300,
        delay_ms: 0,
        seed: 77,
    };
    let run = |plan: &Plan| {
        let mut counts = run_cell(&bin(), Target::TmclLine, Fault::All, plan);
        counts.examples.clear();
        counts
    };
    let first = run(&plan);
    assert!(
        first.injected.dropped > 0 && first.injected.corrupted > 0 && first.failures() > 0,
        "{}",
        first.summary()
    );
    let again = run(&plan);
    assert_eq!(first, again, "same seed, same run");
    let other = run(&Plan {
        seed: 78,
        ..plan.clone()
    });
    assert_ne!(first.digest, other.digest, "another seed, another run");
}

#[test]
fn the_seed_is_a_flag_and_a_console_command() {
    let mut sim = Sim::start(&["--pty", "--seed", "5", "--drop-rate", "0.5"]);
    assert_eq!(
        sim.console("faults"),
        "ok seed 5 replies 0 dropped 0 corrupted 0 delayed 0"
    );
    assert_eq!(sim.console("seed 6"), "ok seed 6");
    assert!(sim.console("faults").starts_with("ok seed 6 "));
    assert!(
        sim.console("seed six")
            .starts_with("error: 'six' is not a seed")
    );
    let mut old = Sim::start(&["--pty", "--fault-seed", "9"]);
    assert!(
        old.console("faults").starts_with("ok seed 9 "),
        "--fault-seed still works"
    );
    let mut drive = Sim::start(&["--pty", "--protocol", "smd4", "--seed", "4"]);
    assert!(
        drive.console("faults").starts_with("ok seed 4 "),
        "the SMD4 drive's faults take the seed too"
    );
}

#[test]
fn only_a_well_formed_one_character_change_counts_as_undetectable() {
    let undetectable = [
        ("-8695", "-8795"),
        ("844502454", "-44502454"),
        ("-4502454", "44502454"),
        (
            "[\"1.3058E+04\", \"1.3058E+04\"]",
            "[\"1.3058E+04\", \"1.3068E+04\"]",
        ),
        ("[\"-3705418.00\"]", "[\"83705418.00\"]"),
        ("[\"6.5000E-01\"]", "[\"6.5000E-11\"]"),
        (
            "[\"f4562fb1-d002-11ee-b3e5-44b7d0c71675\"]",
            "[\"f4562fb1-d002-11ee-b3e5-44b7d0c7167a\"]",
        ),
    ];
    for (truth, got) in undetectable {
        assert!(one_digit_changed(got, truth), "{got} for {truth}");
    }
    let refusable = [
        ("-8695", "-8"),
        ("40163803", "-163803"),
        ("173", "073"),
        ("173", "17V"),
        (
            "[\"1.3058E+04\", \"1.3058E+04\"]",
            "[\"1.3058E<04\", \"1.3058E+04\"]",
        ),
        ("[\"6.5000E-01\"]", "[\"6.5000E801\"]"),
        ("173", "73"),
        (
            "[\"f4562fb1-d002-11ee-b3e5-44b7d0c71675\"]",
            "[\"f4562fb14d002-11ee-b3e5-44b7d0c71675\"]",
        ),
        ("1234", "1234"),
        ("1234", "1243"),
    ];
    for (truth, got) in refusable {
        assert!(!one_digit_changed(got, truth), "{got} for {truth}");
    }
}

#[test]
fn in_a_text_item_only_one_printable_character_changed_counts_as_undetectable() {
    for (truth, got) in [
        ("[\"24044.12\"]", "[\"240A4.12\"]"),
        ("[\"24044.12\"]", "[\"24044=12\"]"),
        ("[\"24044.12\"]", "[\"!4044.12\"]"),
        // A byte corrupted into a backslash, which the script prints escaped.
        ("[\"24044.12\"]", "[\"24044.\\\\2\"]"),
        ("[\"24044.12\"]", "[\"24044.\\\"2\"]"),
    ] {
        assert!(one_character_changed(got, truth), "{got} for {truth}");
    }
    for (truth, got) in [
        ("[\"24044.12\"]", "[\"24044.1\"]"),
        ("[\"24044.12\"]", "[\"24044.122\"]"),
        ("[\"24044.12\"]", "[\"24A44.1b\"]"),
        ("[\"24044.12\"]", "[\"2404\u{5}.12\"]"),
        ("[\"24044.12\"]", "[\"24044.12\"]"),
    ] {
        assert!(!one_character_changed(got, truth), "{got} for {truth}");
    }
}
