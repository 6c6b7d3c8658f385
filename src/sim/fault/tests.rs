use super::*;
use crate::dialect::tmcl::protocol::{CommandFrame, Instruction, ReplyFrame};
use crate::dialect::tmcl::sim::Bus;

fn gap4() -> [u8; 9] {
    CommandFrame {
        address: 1,
        instruction: Instruction::new(6, 4, 0, 0),
    }
    .encode()
}

/// Sends GAP 4 at `t` and returns what is sent by then.
fn ask(device: &mut Faulty<Bus>, t: Duration) -> Vec<u8> {
    device.receive(t, &gap4());
    let mut out = Vec::new();
    device.poll_output(t, &mut out);
    out
}

fn faulty(faults: Faults) -> Faulty<Bus> {
    Faulty::new(Bus::builtin(), faults)
}

#[test]
fn without_faults_every_reply_passes_unchanged() {
    let mut device = faulty(Faults::default());
    for i in 0..20 {
        let out = ask(&mut device, Duration::from_millis(i));
        assert!(ReplyFrame::decode(out[..].try_into().unwrap()).is_ok());
    }
}

#[test]
fn drops_follow_the_rate_and_the_seed() {
    let pattern = |seed| {
        let mut device = faulty(Faults {
            drop_rate: 0.5,
            seed,
            ..Faults::default()
        });
        (0..200)
            .map(|i| ask(&mut device, Duration::from_millis(i)).is_empty())
            .collect::<Vec<bool>>()
    };
    let a = pattern(7);
    assert_eq!(a, pattern(7), "same seed, same faults");
    assert_ne!(a, pattern(8));
    let dropped = a.iter().filter(|d| **d).count();
    assert!(
        (60..140).contains(&dropped),
        "{dropped} of 200 dropped at rate 0.5"
    );
    let mut all = faulty(Faults {
        drop_rate: 1.0,
        ..Faults::default()
    });
    assert!(ask(&mut all, Duration::ZERO).is_empty());
}

#[test]
fn corrupted_replies_fail_their_checksum() {
    let mut device = faulty(Faults {
        corrupt_rate: 1.0,
        ..Faults::default()
    });
    for i in 0..50 {
        let out = ask(&mut device, Duration::from_millis(i));
        assert_eq!(out.len(), 9);
        assert!(ReplyFrame::decode(out[..].try_into().unwrap()).is_err());
    }
}

#[test]
fn delayed_replies_arrive_late_and_in_order() {
    let mut device = faulty(Faults {
        delay_rate: 1.0,
        delay: Duration::from_millis(100),
        ..Faults::default()
    });
    assert!(ask(&mut device, Duration::ZERO).is_empty());
    assert_eq!(
        device.next_due(Duration::ZERO),
        Some(Duration::from_millis(100))
    );
    let mut out = Vec::new();
    device.poll_output(Duration::from_millis(99), &mut out);
    assert!(out.is_empty());
    device.poll_output(Duration::from_millis(100), &mut out);
    assert_eq!(out.len(), 9);
}

#[test]
fn a_silent_device_still_executes() {
    let mut device = faulty(Faults {
        silent_after: Some(2),
        ..Faults::default()
    });
    assert_eq!(ask(&mut device, Duration::ZERO).len(), 9);
    assert_eq!(ask(&mut device, Duration::ZERO).len(), 9);
    let mvp = CommandFrame {
        address: 1,
        instruction: Instruction::new(4, 0, 0, 1000),
    };
    device.receive(Duration::ZERO, &mvp.encode());
    let mut out = Vec::new();
    device.poll_output(Duration::ZERO, &mut out);
    assert!(out.is_empty());
    let motor = device.inner.motor(Duration::ZERO, 1).unwrap();
    assert_eq!(motor.target, 1000, "the silent module moved anyway");
}

#[test]
fn hanging_up_after_n_replies_and_reconnecting() {
    let mut device = faulty(Faults {
        hangup_after: Some(3),
        ..Faults::default()
    });
    for _ in 0..3 {
        assert!(!device.hung_up());
        assert_eq!(ask(&mut device, Duration::ZERO).len(), 9);
    }
    assert!(device.hung_up());
    assert!(ask(&mut device, Duration::ZERO).is_empty());
    device.reconnect();
    assert!(!device.hung_up());
    assert_eq!(ask(&mut device, Duration::ZERO).len(), 9);
}

#[test]
fn faults_change_at_run_time_through_control_commands() {
    let mut device = faulty(Faults::default());
    let now = Duration::ZERO;
    assert!(device.control(now, "drop 1").unwrap().is_ok());
    assert!(ask(&mut device, now).is_empty());
    device.control(now, "drop 0").unwrap().unwrap();
    device.control(now, "silent on").unwrap().unwrap();
    assert!(ask(&mut device, now).is_empty());
    device.control(now, "silent off").unwrap().unwrap();
    assert_eq!(ask(&mut device, now).len(), 9);
    assert!(device.control(now, "drop 2").unwrap().is_err());
    // Commands of the wrapped bus pass through.
    assert!(device.control(now, "input 3 1").unwrap().is_ok());
    assert!(device.control(now, "nonsense").is_none());
    device.control(now, "hangup").unwrap().unwrap();
    assert!(device.hung_up());
}

/// The replies to `n` GAP 4 requests, from `t` on, one millisecond apart.
fn replies(device: &mut Faulty<Bus>, n: u64) -> Vec<Vec<u8>> {
    (0..n)
        .map(|i| ask(device, Duration::from_millis(i)))
        .collect()
}

#[test]
fn reseeding_replays_the_same_faults_and_restarts_the_counts() {
    let mut device = faulty(Faults {
        drop_rate: 0.2,
        corrupt_rate: 0.2,
        ..Faults::default()
    });
    let before = replies(&mut device, 50);
    assert_eq!(device.injected().replies, 50);
    assert_eq!(
        device.control(Duration::ZERO, "seed 42"),
        Some(Ok("seed 42".to_string()))
    );
    assert_eq!(device.injected(), Injected::default(), "counts restart");
    let first = replies(&mut device, 300);
    let counts = device.injected();
    device.reseed(42);
    assert_eq!(replies(&mut device, 300), first, "same seed, same faults");
    assert_eq!(device.injected(), counts);
    device.reseed(43);
    assert_ne!(
        replies(&mut device, 300),
        first,
        "another seed, other faults"
    );
    assert_ne!(before, first[..50], "the seed was really changed");

    // The counts are what happened to the replies.
    let dropped = first.iter().filter(|r| r.is_empty()).count() as u64;
    let corrupted = first
        .iter()
        .filter(|r| !r.is_empty() && ReplyFrame::decode(r[..].try_into().unwrap()).is_err())
        .count() as u64;
    assert_eq!(counts.replies, 300);
    assert_eq!(counts.dropped, dropped);
    assert_eq!(counts.corrupted, corrupted);
    assert!(dropped > 20 && corrupted > 20, "{counts:?}");
    assert_eq!(counts.delayed, 0);
}

#[test]
fn the_console_shows_the_seed_and_the_injected_faults() {
    let mut device = faulty(Faults {
        delay_rate: 1.0,
        delay: Duration::from_millis(5),
        seed: 9,
        ..Faults::default()
    });
    let now = Duration::ZERO;
    replies(&mut device, 3);
    assert_eq!(
        device.control(now, "faults"),
        Some(Ok(
            "seed 9 replies 3 dropped 0 corrupted 0 delayed 3".to_string()
        ))
    );
    device.control(now, "seed 10").unwrap().unwrap();
    assert_eq!(
        device.control(now, "faults"),
        Some(Ok(
            "seed 10 replies 0 dropped 0 corrupted 0 delayed 0".to_string()
        ))
    );
    assert!(device.control(now, "seed -1").unwrap().is_err());
    let refused = device.control(now, "seed many").unwrap().unwrap_err();
    assert_eq!(
        refused.to_string(),
        format!("'many' is not a seed (0..{})", u64::MAX)
    );
}

#[test]
fn silence_is_not_counted_as_dropped_replies() {
    let mut device = faulty(Faults::default());
    device.set_silent(true);
    assert!(replies(&mut device, 4).iter().all(Vec::is_empty));
    let counts = device.injected();
    assert_eq!((counts.replies, counts.dropped), (4, 0));
}

#[test]
fn neighbouring_seeds_make_different_decisions() {
    let first_draws = |seed| {
        let mut rng = Rng::new(seed);
        (0..4).map(|_| rng.next()).collect::<Vec<u64>>()
    };
    let all: Vec<Vec<u64>> = (0..64).map(first_draws).collect();
    for (i, a) in all.iter().enumerate() {
        for b in &all[i + 1..] {
            assert_ne!(a, b, "two of seeds 0..64 start the same sequence");
        }
    }
}
