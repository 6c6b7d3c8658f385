//! Finding the modules on a bus, in three rounds so binary-mode modules never see a frame out
//! of step:
//!
//! 1. Binary frames only: command 136 type 1 (checksummed, answered by the addressed module
//!    alone) to every address finds the modules in binary mode, then 136 type 0 reads their
//!    version string. Modules in ASCII mode take these bytes as lines for other modules.
//! 2. ASCII: every address 1..26 (A..Z) that did not answer is asked for its echo setting (global
//!    parameter 67) in an ASCII line, which finds the modules already in ASCII mode (no 139: a
//!    module in binary mode answered round 1); their version comes from 136 in binary mode, there
//!    and back.
//! 3. The echo setting of the binary-mode modules (global parameter 67 over a binary frame), after
//!    the line has been quiet long enough for their receivers to drop what the ASCII lines left
//!    in them (the firmware's frame timeout). Skipped when a module in ASCII mode answers to C:
//!    the frame's bytes 10, 67 ("LF", "C") would start a line for it.
//!
//! Each reply is awaited at most the given time; the session puts every module it switched back
//! in its mode when it closes, and modules only probed with binary frames are never switched.
//! Each module found is named from its version string by the built-in profiles
//! (`TMCM-6110`); a boot loader is named as one and asked nothing more.

use std::collections::BTreeMap;
use std::io::{self, Write};
use std::time::Duration;

use crate::dialect::tmcl::profile::catalogue::{self, Identified};
use crate::dialect::tmcl::profile::family::AsciiInterface;
use crate::dialect::tmcl::protocol::host_clash;
use crate::dialect::tmcl::protocol::line::address_char;
use crate::dialect::tmcl::protocol::{Instruction, Opcode};
use crate::dialect::tmcl::session::{Echo, TmclExchange, TmclReply, TmclSession, WireMode};
use crate::json::{Value, json};
use crate::session::SessionError;

use crate::commission::scan::scan_summary;
use crate::dialect::session::{BusScan, DialectSession};
use crate::progress::Progress;

/// A module that answered.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct FoundModule {
    /// Its bus address.
    pub address: u8,
    /// The mode it was in when found.
    pub mode: WireMode,
    /// Its firmware version (command 136), where it told it.
    pub firmware: Option<String>,
    /// Its echo setting (global parameter 67), where it could be read.
    pub echo: Option<Echo>,
    /// The host address its replies start with (global parameter 76), where its profile has
    /// the parameter and it could be read.
    pub host: Option<u8>,
}

impl FoundModule {
    /// What its version string names: `TMCM-6110`, `TMCM-9999 (no profile)`, `TMCM-142 (boot
    /// loader)`, or `?` without a version string.
    pub fn module(&self) -> String {
        let Some(firmware) = &self.firmware else {
            return "?".into();
        };
        match catalogue::identify(firmware) {
            Ok(Identified::Known { profile, .. }) => profile.module.clone(),
            Ok(Identified::Unknown { version, .. }) => {
                format!("TMCM-{} (no profile)", version.module)
            }
            Ok(Identified::BootLoader { version, profile }) => format!(
                "{} (boot loader)",
                profile.map_or_else(|| format!("TMCM-{}", version.module), |p| p.module.clone())
            ),
            Err(_) => "?".into(),
        }
    }

    /// The module as a JSON object (`scan --json`).
    pub fn json(&self) -> Value {
        json!({
            "address": self.address,
            "char": address_char(self.address).map(String::from),
            "mode": match self.mode {
                WireMode::Ascii => "ascii",
                WireMode::Binary => "binary",
            },
            "firmware": self.firmware,
            "echo": self.echo.map(Echo::name),
            "host_address": self.host,
            "module": self.firmware.as_ref().map(|_| self.module()),
            "boot_loader": self.in_boot_loader(),
        })
    }

    /// Whether the profile its version string names has no ASCII interface: it has no echo
    /// setting (global parameter 67 is not its own) and is shown as `binary`.
    pub fn binary_only(&self) -> bool {
        let Some(firmware) = &self.firmware else {
            return false;
        };
        matches!(
            catalogue::identify(firmware),
            Ok(Identified::Known { profile, .. })
                if profile.identity.ascii_interface() == AsciiInterface::No
        )
    }

    /// Whether its boot loader answered: it is asked nothing more.
    pub fn in_boot_loader(&self) -> bool {
        self.firmware
            .as_deref()
            .is_some_and(|f| matches!(catalogue::identify(f), Ok(Identified::BootLoader { .. })))
    }
}

/// What a scan found.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct TmclScan {
    /// The addresses tried.
    pub scanned: Vec<u8>,
    /// The modules that answered, by address.
    pub found: Vec<FoundModule>,
    /// How long each reply was awaited.
    pub per_reply: Duration,
}

/// Tries every address in `addresses`, waiting at most `per_reply` for each reply; `quiet` is how
/// long binary-mode receivers need to drop a partial frame. Ctrl-C and a lost link end the scan;
/// silence or garbage at an address means nobody is there.
pub fn scan(
    session: &mut TmclSession,
    addresses: &[u8],
    per_reply: Duration,
    quiet: Duration,
) -> Result<TmclScan, SessionError> {
    let original = session.target();
    let mut addresses = addresses.to_vec();
    addresses.sort_unstable();
    addresses.dedup();
    session.align_frames()?;
    let progress = Progress::steps(addresses.len(), 2, "scanning (binary)");
    let mut found: BTreeMap<u8, FoundModule> = BTreeMap::new();
    for &address in &addresses {
        progress.step(&address.to_string());
        if let Some(module) = session.with_timeout(per_reply, |s| probe_binary(s, address))? {
            found.insert(address, module);
        }
    }
    // Round 2: the addresses with a character that did not answer binary frames.
    let candidates: Vec<u8> = addresses
        .iter()
        .copied()
        .filter(|a| !found.contains_key(a) && address_char(*a).is_some())
        .filter(|_| !session.frames_only())
        .collect();
    let in_step = candidates.is_empty();
    if !in_step {
        session.end_partial_line()?;
    }
    drop(progress);
    let progress = Progress::steps(candidates.len(), 2, "scanning (ASCII)");
    for &address in &candidates {
        progress.step(&address.to_string());
        if let Some(module) = session.with_timeout(per_reply, |s| probe_ascii(s, address))? {
            found.insert(address, module);
        }
    }
    // Round 3: the echo setting of the modules found in binary mode.
    let in_ascii =
        |m: &FoundModule| m.mode == WireMode::Ascii || session.module_state(m.address).is_some();
    let c_in_ascii = found.get(&3).is_some_and(in_ascii);
    let ascii_modules = found.values().any(in_ascii);
    let binary: Vec<u8> = found
        .values()
        .filter(|m| !in_ascii(m) && !m.in_boot_loader())
        .map(|m| m.address)
        .collect();
    if !binary.is_empty() && !c_in_ascii {
        if !in_step {
            session.quiet(quiet)?;
        }
        for address in binary {
            // GP 67 is not a binary-only module's own: not asked.
            let echo = if found.get(&address).is_some_and(FoundModule::binary_only) {
                None
            } else {
                session.with_timeout(per_reply, |s| read_echo_binary(s, address))?
            };
            let firmware = found.get(&address).and_then(|m| m.firmware.clone());
            let host = if has_host_address(session, address, firmware.as_deref()) {
                session.with_timeout(per_reply, |s| read_host_binary(s, address))?
            } else {
                None
            };
            if let Some(m) = found.get_mut(&address) {
                m.echo = echo;
                m.host = host;
            }
        }
        if ascii_modules {
            session.end_partial_line()?;
        }
    }
    if session.module_state(original).is_some() && session.target() != original {
        session.set_target(original)?;
    }
    let hosts: Vec<(u8, Option<u8>)> = found.values().map(|m| (m.address, m.host)).collect();
    // On CAN the reply ID, not the serial host address, tells replies from requests.
    let hosts = if session.frames_only() {
        Vec::new()
    } else {
        hosts
    };
    for warning in host_clash::warnings(&hosts) {
        session.notice(warning);
    }
    Ok(TmclScan {
        scanned: addresses,
        found: found.into_values().collect(),
        per_reply,
    })
}

/// [`scan`] with the quiet time of the session's profile, its report ready to print.
pub fn bus_scan(
    session: &mut TmclSession,
    addresses: &[u8],
    per_reply: Duration,
) -> Result<BusScan, SessionError> {
    let quiet = quiet_time(session.profile());
    let report = scan(session, addresses, per_reply, quiet)?;
    let mut text = Vec::new();
    write_report(&report, &mut text).expect("writing to memory cannot fail");
    Ok(BusScan {
        found: report.found.len(),
        summary: summary(&report),
        report: String::from_utf8_lossy(&text).into_owned(),
        modules: report.found.iter().map(FoundModule::json).collect(),
    })
}

/// How long the line stays quiet before binary frames follow ASCII lines, so that the module's
/// receiver drops a partial frame (best knowledge, in the profile).
pub fn quiet_time(profile: &crate::dialect::tmcl::profile::Profile) -> Duration {
    profile.sim.quiet_before_frame()
}

/// Whether an error means "nobody (usable) at this address" rather than "stop scanning".
fn absent(error: &SessionError) -> bool {
    !error.is_echo_mismatch()
        && matches!(
            error,
            SessionError::Timeout { .. }
                | SessionError::Link(_)
                | SessionError::Noise { .. }
                | SessionError::Device { .. }
        )
}

/// The exchange, `None` when its error means nobody (usable) answered, or the error that ends
/// the scan.
fn present(
    result: Result<TmclExchange, SessionError>,
) -> Result<Option<TmclExchange>, SessionError> {
    match result {
        Ok(x) => Ok(Some(x)),
        Err(e) if absent(&e) => Ok(None),
        Err(e) => Err(e),
    }
}

/// The value of an answer with a good status.
fn ok_value(answer: Option<TmclExchange>) -> Option<i32> {
    answer.filter(TmclExchange::ok).and_then(|x| x.value())
}

/// Round 1: a module in binary mode answers 136 type 1; then its version string.
fn probe_binary(
    session: &mut TmclSession,
    address: u8,
) -> Result<Option<FoundModule>, SessionError> {
    if session.module_state(address).is_some() {
        return Ok(None); // already reached by this session: round 2 reports it
    }
    let binary = Instruction::new(Opcode::FirmwareVersion, 1, 0, 0);
    let answer = present(session.probe_binary(address, binary))?;
    if answer.and_then(|x| x.value()).is_none() {
        return Ok(None);
    }
    let text = Instruction::new(Opcode::FirmwareVersion, 0, 0, 0);
    let firmware = present(session.probe_binary(address, text))?.and_then(version_text);
    Ok(Some(FoundModule {
        address,
        mode: WireMode::Binary,
        firmware,
        echo: None,
        host: None,
    }))
}

/// Round 2: a module in ASCII mode (or one this session already reached) answers in ASCII.
fn probe_ascii(
    session: &mut TmclSession,
    address: u8,
) -> Result<Option<FoundModule>, SessionError> {
    let known = session.found_in(address);
    match session.reach_in_ascii(address) {
        Ok(()) => {}
        Err(e) if absent(&e) => return Ok(None),
        Err(e) => return Err(e),
    }
    // It did not answer binary frames, so it was in ASCII mode unless this session put it there.
    let mode = known.unwrap_or(WireMode::Ascii);
    session.set_found_in(address, mode);
    let echo = session.module_state(address).map(|(_, echo)| echo);
    let version = session.in_binary(address, |s| {
        s.request(address, Instruction::new(Opcode::FirmwareVersion, 0, 0, 0))
    });
    let firmware = present(version)?.and_then(version_text);
    let host = if has_host_address(session, address, firmware.as_deref()) {
        let answer = present(session.request(address, host_request()))?;
        ok_value(answer).and_then(|v| u8::try_from(v).ok())
    } else {
        None
    };
    Ok(Some(FoundModule {
        address,
        mode,
        firmware,
        echo,
        host,
    }))
}

/// Round 3: global parameter 67 over a binary frame.
fn read_echo_binary(session: &mut TmclSession, address: u8) -> Result<Option<Echo>, SessionError> {
    let request = Instruction::new(Opcode::Ggp, 67, 0, 0);
    let answer = present(session.probe_binary(address, request))?;
    Ok(ok_value(answer).map(Echo::from_gp67))
}

/// Round 3: global parameter 76 over a binary frame.
fn read_host_binary(session: &mut TmclSession, address: u8) -> Result<Option<u8>, SessionError> {
    let answer = present(session.probe_binary(address, host_request()))?;
    Ok(ok_value(answer).and_then(|v| u8::try_from(v).ok()))
}

/// GGP of the host address parameter.
fn host_request() -> Instruction {
    let (bank, number) = host_clash::HOST_ADDRESS;
    Instruction::new(Opcode::Ggp, number, bank, 0)
}

/// Whether the module's profile — the one its version string names, else the one the session
/// takes it for — has the host address parameter.
fn has_host_address(session: &TmclSession, address: u8, firmware: Option<&str>) -> bool {
    let named = firmware.and_then(|f| match catalogue::identify(f) {
        Ok(Identified::Known { profile, .. }) => Some(profile),
        _ => None,
    });
    let profile = named.unwrap_or_else(|| session.profile_of(address));
    let (bank, number) = host_clash::HOST_ADDRESS;
    profile.global_param(bank, number).is_some()
}

/// The version string of a 136 type 0 answer.
fn version_text(answer: TmclExchange) -> Option<String> {
    match &answer.reply {
        TmclReply::Version(text) if !text.trim().is_empty() => Some(text.trim().to_string()),
        _ => None,
    }
}

/// Prints the table of modules found and a summary line.
pub fn write_report(report: &TmclScan, out: &mut dyn Write) -> io::Result<()> {
    if !report.found.is_empty() {
        writeln!(out, "address  char  found in  firmware  echo    module")?;
    }
    for m in &report.found {
        let c = address_char(m.address).map_or("-".to_string(), String::from);
        let mode = match m.mode {
            WireMode::Ascii => "ASCII",
            WireMode::Binary => "binary",
        };
        let firmware = m.firmware.as_deref().unwrap_or("?");
        let echo = match m.echo {
            _ if m.binary_only() => "binary",
            Some(echo) => echo.name(),
            None => "?",
        };
        writeln!(
            out,
            "{:>7}  {c:<4}  {mode:<8}  {firmware:<8}  {echo:<6}  {}",
            m.address,
            m.module()
        )?;
    }
    writeln!(out, "{}", summary(report))
}

/// "3 modules answered at 1-26 (at most 200 ms per reply)".
pub fn summary(report: &TmclScan) -> String {
    scan_summary(
        report.found.len(),
        "module",
        &report.scanned,
        report.per_reply,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_table_lists_each_module_with_mode_firmware_and_echo() {
        let report = TmclScan {
            scanned: (1..=30).collect(),
            found: vec![
                FoundModule {
                    address: 1,
                    mode: WireMode::Binary,
                    firmware: Some("142V1.00".into()),
                    echo: Some(Echo::Character),
                    host: None,
                },
                FoundModule {
                    address: 3,
                    mode: WireMode::Ascii,
                    firmware: None,
                    echo: Some(Echo::None),
                    host: None,
                },
                FoundModule {
                    address: 30,
                    mode: WireMode::Binary,
                    firmware: Some("6110V131".into()),
                    echo: None,
                    host: None,
                },
            ],
            per_reply: Duration::from_millis(150),
        };
        let mut out = Vec::new();
        write_report(&report, &mut out).unwrap();
        let text = String::from_utf8(out).unwrap();
        let rows: Vec<Vec<&str>> = text
            .lines()
            .map(|l| l.split_whitespace().collect())
            .collect();
        assert_eq!(
            rows[0],
            [
                "address", "char", "found", "in", "firmware", "echo", "module"
            ]
        );
        assert_eq!(
            rows[1],
            ["1", "A", "binary", "142V1.00", "char", "TMCM-142"]
        );
        assert_eq!(rows[2], ["3", "C", "ASCII", "?", "none", "?"]);
        assert_eq!(rows[3], ["30", "-", "binary", "6110V131", "?", "TMCM-6110"]);
        let named = |firmware: &str| FoundModule {
            address: 1,
            mode: WireMode::Binary,
            firmware: Some(firmware.into()),
            echo: None,
            host: None,
        };
        assert_eq!(named("9999V100").module(), "TMCM-9999 (no profile)");
        assert_eq!(named("142B1.06").module(), "TMCM-142 (boot loader)");
        assert!(named("142B1.06").in_boot_loader());
        assert!(!named("142V1.06").in_boot_loader());
        assert_eq!(named("garbage").module(), "?");
        assert_eq!(
            text.lines().last().unwrap(),
            "3 modules answered at 1-30 (at most 150 ms per reply)"
        );
    }
}
