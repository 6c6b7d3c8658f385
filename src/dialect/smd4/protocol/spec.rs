//! The SMD4 dialect as loaded from `data/smd4.toml`: commands, flag words, error codes and the
//! simulator's constants. Parsed once; everything else borrows it.

use std::net::Ipv4Addr;
use std::sync::OnceLock;
use std::time::Duration;

use super::commands::Smd4CommandTable;
use super::errors::ErrorInfo;
use super::flags::FlagTable;
use super::load::Smd4File;
use super::tolerance::RealTolerance;
use crate::commission::SnapshotRules;

/// The data file, kept in the repository as the single source of truth and built into the binary.
pub const BUILTIN_TOML: &str = include_str!("../../../../data/smd4.toml");

/// Constants a simulated SMD4 needs that are not per command.
#[derive(Debug, Clone, PartialEq)]
pub struct SimConstants {
    /// How long the line must stay quiet before a multi-line reply counts as complete.
    pub quiet_gap: Duration,
    /// IP address a DHCP server assigned.
    pub dhcp_ip: Ipv4Addr,
    /// Net mask a DHCP server assigned.
    pub dhcp_netmask: Ipv4Addr,
    /// Gateway a DHCP server assigned.
    pub dhcp_gateway: Ipv4Addr,
    /// External enable input at power-up.
    pub external_enable_input: bool,
    /// MOTOR:SSTOP ramps to standstill in this many seconds.
    pub sstop_seconds: f64,
}

/// How parameter snapshots treat the drive's values (the `[snapshot]` section).
#[derive(Debug, Clone, PartialEq)]
pub struct SnapshotSpec {
    /// Live, first, last and manual lists, by canonical mnemonic.
    pub rules: SnapshotRules,
    /// A restore starts only while the drive reports standby.
    pub needs_standby: bool,
    /// Significant digits FLOAT replies carry: real values are compared to this precision.
    pub float_digits: u32,
}

/// Everything the data file says about the SMD4.
#[derive(Debug, Clone)]
pub struct Smd4Spec {
    /// The commands.
    pub commands: Smd4CommandTable,
    /// SFLAGS bits.
    pub sflags: FlagTable,
    /// EFLAGS bits.
    pub eflags: FlagTable,
    /// Error codes.
    pub errors: Vec<ErrorInfo>,
    /// Simulator constants.
    pub sim: SimConstants,
    /// Snapshot rules.
    pub snapshot: SnapshotSpec,
}

impl Smd4Spec {
    /// The built-in dialect (`data/smd4.toml`).
    pub fn builtin() -> &'static Smd4Spec {
        static BUILTIN: OnceLock<Smd4Spec> = OnceLock::new();
        BUILTIN.get_or_init(|| {
            Smd4Spec::from_toml(BUILTIN_TOML).expect("the built-in data/smd4.toml is valid")
        })
    }

    /// Reads a dialect from TOML text with the schema of `data/smd4.toml`.
    pub fn from_toml(text: &str) -> Result<Smd4Spec, String> {
        let file = Smd4File::parse(text).map_err(|e| e.to_string())?;
        let sim = &file.simulation;
        let ip = |text: &Option<String>, fallback: Ipv4Addr| {
            text.as_deref()
                .map(|t| t.parse().map_err(|_| format!("bad IPv4 address '{t}'")))
                .unwrap_or(Ok(fallback))
        };
        let mut commands = Smd4CommandTable::from_rows(&file.command)?;
        let float_digits = file.snapshot.float_digits.unwrap_or(5);
        commands.set_real_tolerance(RealTolerance::from_data(
            file.user_real.relative_tolerance,
            file.user_real.absolute_tolerance,
            float_digits,
        )?);
        let rules = file.snapshot.rules.clone();
        rules.check_names(|name| commands.get(name).is_some_and(|c| c.mnemonic == name))?;
        Ok(Smd4Spec {
            snapshot: SnapshotSpec {
                rules,
                needs_standby: file.snapshot.needs_standby,
                float_digits,
            },
            commands,
            sflags: FlagTable::from_rows("sflag", &file.sflag)?,
            eflags: FlagTable::from_rows("eflag", &file.eflag)?,
            errors: file
                .error_code
                .iter()
                .map(|e| ErrorInfo {
                    code: e.code,
                    name: e.name.clone(),
                    meaning: e.meaning.clone(),
                })
                .collect(),
            sim: SimConstants {
                quiet_gap: Duration::from_millis(sim.multi_line_quiet_gap_ms.unwrap_or(100)),
                dhcp_ip: ip(&sim.dhcp_ip, Ipv4Addr::new(10, 0, 97, 70))?,
                dhcp_netmask: ip(&sim.dhcp_netmask, Ipv4Addr::new(255, 255, 248, 0))?,
                dhcp_gateway: ip(&sim.dhcp_gateway, Ipv4Addr::new(10, 0, 96, 1))?,
                external_enable_input: sim.external_enable_input.unwrap_or(true),
                sstop_seconds: sim.sstop_seconds.unwrap_or(1.0),
            },
        })
    }

    /// The row of the error table for `code`.
    pub fn error_info(&self, code: i32) -> Option<&ErrorInfo> {
        self.errors.iter().find(|e| e.code == code)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dialect::smd4::protocol::{ItemType, Kind, ReplyShape};

    #[test]
    fn builtin_table_loads_every_command() {
        let spec = Smd4Spec::builtin();
        assert_eq!(spec.commands.iter().count(), 71);
        assert_eq!(spec.errors.len(), 10);
        assert_eq!(spec.sflags.bits().len(), 16);
        assert_eq!(spec.eflags.bits().len(), 16);
        assert_eq!(spec.sim.quiet_gap, Duration::from_millis(100));
    }

    #[test]
    fn lookup_is_case_insensitive_and_knows_aliases() {
        let table = &Smd4Spec::builtin().commands;
        let vmax = table.get("motor:vmax").unwrap();
        assert_eq!(vmax.mnemonic, "MOTOR:VMAX");
        assert_eq!(vmax.reply, ReplyShape::UserReal);
        assert_eq!(vmax.arg.as_ref().unwrap().range_text(), "1..15000");
        assert_eq!(table.get("sys:store").unwrap().mnemonic, "STORE");
        assert!(table.get("MOTOR:NOPE").is_none());
    }

    #[test]
    fn data_driven_facts_reach_the_table() {
        let table = &Smd4Spec::builtin().commands;
        let res = table.get("MOTOR:RES").unwrap();
        assert!(res.requires_standby);
        assert_eq!(
            res.arg.as_ref().unwrap().choices_text(),
            "8, 16, 32, 64, 128, 256"
        );
        let runv = table.get("MOTOR:RUNV").unwrap();
        assert_eq!(runv.kind, Kind::Motion);
        assert!(!runv.readable);
        assert_eq!(runv.arg.as_ref().unwrap().choices_text(), "+, -");
        assert_eq!(
            table.get("MOTOR:IR").unwrap().arg.as_ref().unwrap().levels,
            Some(31)
        );
        assert_eq!(
            table.get("SYS:UUID").unwrap().value_item_type(),
            Some(ItemType::Uuid)
        );
        assert!(table.get("MOTOR:PACT").unwrap().fixed_point);
        assert!(!table.get("MOTOR:PACT").unwrap().persistent);
        assert!(table.get("MOTOR:VMAX").unwrap().persistent);
        assert!(table.get("SYS:RESET").unwrap().no_response);
        assert_eq!(table.get("SYS:MODE").unwrap().label_of("1"), Some("Remote"));
    }

    #[test]
    fn broken_data_is_reported_not_panicked() {
        let bad = "[[command]]\nmnemonic = \"X\"\nkind = \"weird\"\nreply = \"none\"\n";
        assert!(
            Smd4Spec::from_toml(bad)
                .unwrap_err()
                .contains("unknown kind")
        );
        let bad = "[[command]]\nmnemonic = \"X\"\nkind = \"query\"\nreply = \"value\"\n";
        assert!(Smd4Spec::from_toml(bad).unwrap_err().contains("value_type"));
        assert!(Smd4Spec::from_toml("not toml [").is_err());
        let bad = "[snapshot]\nfirst = [\"MOTOR:NOPE\"]\n";
        assert!(
            Smd4Spec::from_toml(bad)
                .unwrap_err()
                .contains("[snapshot] first names 'MOTOR:NOPE'")
        );
    }

    #[test]
    fn each_field_of_a_command_row_is_checked_by_name() {
        let refused = |fields: &str| {
            Smd4Spec::from_toml(&format!("[[command]]\nmnemonic = \"X:Y\"\n{fields}")).unwrap_err()
        };
        assert_eq!(
            refused("kind = \"query\"\nreply = \"loud\"\n"),
            "X:Y: unknown reply 'loud'"
        );
        assert_eq!(
            refused("kind = \"query\"\nreply = \"literal\"\n"),
            "X:Y: reply = \"literal\" needs reply_literal"
        );
        assert_eq!(
            refused("kind = \"setting\"\nreply = \"none\"\narg_type = \"BYTE\"\n"),
            "X:Y: unknown arg_type 'BYTE'"
        );
        assert_eq!(
            refused("kind = \"query\"\nreply = \"value\"\nvalue_type = \"WORD\"\n"),
            "X:Y: unknown value_type 'WORD'"
        );
        assert_eq!(
            refused("kind = \"query\"\nreply = \"value\"\n"),
            "X:Y: a value reply needs value_type or arg_type"
        );
    }

    #[test]
    fn a_flag_or_enumerated_value_that_would_read_two_ways_is_refused() {
        let refused = |text: &str| Smd4Spec::from_toml(text).unwrap_err();
        let flags = "[[sflag]]\nbit = 3\nname = \"A\"\n[[sflag]]\nbit = 3\nname = \"B\"\n";
        assert_eq!(refused(flags), "sflag bit 3 is given twice");
        let flags = "[[eflag]]\nbit = 16\nname = \"A\"\n";
        assert_eq!(
            refused(flags),
            "eflag bit 16 is beyond bit 15 of a flag word"
        );
        let flags = "[[eflag]]\nbit = 2\nname = \" \"\n";
        assert_eq!(refused(flags), "eflag bit 2 has no name");
        let command = |labels: &str| {
            format!(
                "[[command]]\nmnemonic = \"X:Y\"\nkind = \"setting\"\nreply = \"value\"\n\
                 arg_type = \"UINT\"\nenum = [{labels}]\n"
            )
        };
        assert_eq!(
            refused(&command(
                r#"{ value = 0, label = "Off" }, { value = 0, label = "On" }"#
            )),
            "X:Y: enum value 0 is given twice"
        );
        assert_eq!(
            refused(&command(r#"{ value = 1, label = "" }"#)),
            "X:Y: enum value 1 has no label"
        );
        Smd4Spec::from_toml(&command(
            r#"{ value = 0, label = "Off" }, { value = 1, label = "On" }"#,
        ))
        .unwrap();
    }
}
