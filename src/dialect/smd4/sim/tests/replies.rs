//! Every reply the simulated drive writes, in every combination of its spelling switches, passes
//! the client's reply check ([`Bench::reply`] runs it): reads and writes of every command, values
//! of every size and sign while a motor moves, error replies, and addressed replies.

use super::Bench;
use crate::dialect::smd4::protocol::{ErrorSpelling, FlagCase, FloatStyle, Smd4Spec};
use crate::dialect::smd4::sim::{PositionFormat, Smd4SimOptions};

/// Every combination of the switches that change how replies are spelled.
fn every_spelling() -> Vec<Smd4SimOptions> {
    let mut all = vec![Smd4SimOptions::default()];
    let mut vary = |change: &dyn Fn(&mut Smd4SimOptions, usize), ways: usize| {
        all = all
            .iter()
            .flat_map(|o| {
                (0..ways).map(move |i| {
                    let mut o = o.clone();
                    change(&mut o, i);
                    o
                })
            })
            .collect();
    };
    vary(
        &|o, i| o.flag_case = [FlagCase::Upper, FlagCase::Lower][i],
        2,
    );
    // What `tmclsh sim --float-decimals` accepts: the examples' 4 and the type table's 5.
    let decimals = [4, 5];
    vary(
        &|o, i| {
            o.float_style = FloatStyle {
                decimals: decimals[i / 2],
                missing_e: i % 2 == 1,
            }
        },
        decimals.len() * 2,
    );
    let spellings = [
        ErrorSpelling::Parenthesised,
        ErrorSpelling::Comma,
        ErrorSpelling::Bare,
    ];
    vary(&|o, i| o.error_spelling = spellings[i], 3);
    let positions = [PositionFormat::Fixed, PositionFormat::Scientific];
    vary(&|o, i| o.position_format = positions[i], 2);
    vary(&|o, i| o.reply_prefix = i == 0, 2);
    // The switches that change values rather than spellings, all on or all off.
    vary(
        &|o, i| {
            o.tzw_reply_ms = i == 1;
            o.current_rounding = i == 0;
            o.real_value_grid = [None, Some(0.0447)][i];
        },
        2,
    );
    all
}

#[test]
fn every_reply_in_every_spelling_passes_the_check() {
    let spec = Smd4Spec::builtin();
    let spellings = every_spelling();
    assert_eq!(spellings.len(), 2 * 4 * 3 * 2 * 2 * 2);
    for options in spellings {
        let mut bench = Bench::with(options);
        for command in spec.commands.iter() {
            if command.readable {
                bench.reply(&command.mnemonic);
            }
            if let (true, Some(arg), false) =
                (command.writable, &command.arg, command.starts_motion)
            {
                let value = command
                    .default
                    .clone()
                    .or_else(|| arg.choices.first().map(|c| c.value.clone()))
                    .or_else(|| arg.max.map(|m| m.to_string()))
                    .unwrap_or_else(|| "1".into());
                bench.reply(&format!("{},{value}", command.mnemonic));
            }
        }
        // Positions, velocities and temperatures of every sign and size while moving.
        for (i, distance) in [123_456, -7_654_321, 3].into_iter().enumerate() {
            bench.reply(&format!("MOTOR:RUNR,{distance}"));
            bench.at(0.37 + i as f64);
            for read in [
                "MOTOR:PACT",
                "MOTOR:PREL",
                "MOTOR:VACT",
                "SYS:UPTIME",
                "MOTOR:T",
            ] {
                bench.reply(read);
            }
            bench.reply("MOTOR:STOP");
        }
        // Refusals in the chosen error spelling.
        for refused in ["MOTOR:NOPE", "MOTOR:RES,7", "MOTOR:RUNV", "BAKE:RUN"] {
            assert!(!bench.reply(refused).is_ok(), "{refused}");
        }
        // Addressed replies, with or without the prefix.
        for read in ["@1SYS:FW", "@1MOTOR:VMAX", "@1SYS:FLAGSV", "@1MOTOR:NOPE"] {
            bench.reply(read);
        }
    }
}
