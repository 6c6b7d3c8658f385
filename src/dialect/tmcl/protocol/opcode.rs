//! TMCL command numbers (manual §6.4–§6.7) by name, for the code's own references: the
//! simulator's dispatch, the session's mode changes, program download and control, scripts. The
//! command *table* — mnemonics, operands, keywords, where each command is accepted — stays data in
//! the profile; a test holds every name here to the built-in table's number and mnemonic.

use std::hash::{Hash, Hasher};

/// Declares [`Opcode`] from one list: variant, number, mnemonic (empty for the control
/// functions, which have none), so the conversions both ways cannot disagree.
macro_rules! opcodes {
    ($( $(#[doc = $doc:literal])* $name:ident = $number:literal $mnemonic:literal, )*) => {
        /// A TMCL command number. [`From<u8>`] gives the named variant for every number that has
        /// one, so `Other` holds only numbers without; `==` and hashing compare numbers, so even
        /// an `Other` built by hand equals the variant of its number.
        #[derive(Debug, Clone, Copy)]
        pub enum Opcode {
            $( $(#[doc = $doc])* $name, )*
            /// A number no variant names (another module's command, or noise).
            Other(u8),
        }

        impl From<u8> for Opcode {
            fn from(number: u8) -> Opcode {
                match number {
                    $( $number => Opcode::$name, )*
                    other => Opcode::Other(other),
                }
            }
        }

        impl From<Opcode> for u8 {
            fn from(opcode: Opcode) -> u8 {
                match opcode {
                    $( Opcode::$name => $number, )*
                    Opcode::Other(number) => number,
                }
            }
        }

        /// Every named opcode with its number and mnemonic, to check them against the table.
        #[cfg(test)]
        const NAMED: &[(Opcode, u8, &str)] = &[ $( (Opcode::$name, $number, $mnemonic), )* ];
    };
}

opcodes! {
    /// 1 ROR: rotate right at the given velocity.
    Ror = 1 "ROR",
    /// 2 ROL: rotate left at the given velocity.
    Rol = 2 "ROL",
    /// 3 MST: motor stop.
    Mst = 3 "MST",
    /// 4 MVP: move to a position (absolute, relative or a coordinate).
    Mvp = 4 "MVP",
    /// 5 SAP: set an axis parameter.
    Sap = 5 "SAP",
    /// 6 GAP: get an axis parameter.
    Gap = 6 "GAP",
    /// 7 STAP: store an axis parameter in EEPROM.
    Stap = 7 "STAP",
    /// 8 RSAP: restore an axis parameter from EEPROM.
    Rsap = 8 "RSAP",
    /// 9 SGP: set a global parameter.
    Sgp = 9 "SGP",
    /// 10 GGP: get a global parameter.
    Ggp = 10 "GGP",
    /// 11 STGP: store a global parameter in EEPROM.
    Stgp = 11 "STGP",
    /// 12 RSGP: restore a global parameter from EEPROM.
    Rsgp = 12 "RSGP",
    /// 13 RFS: reference search (start, stop, status).
    Rfs = 13 "RFS",
    /// 14 SIO: set an output.
    Sio = 14 "SIO",
    /// 15 GIO: get an input or output.
    Gio = 15 "GIO",
    /// 19 CALC: arithmetic on the accumulator with a value.
    Calc = 19 "CALC",
    /// 20 COMP: compare the accumulator with a value (programs).
    Comp = 20 "COMP",
    /// 21 JC: jump on a condition (programs).
    Jc = 21 "JC",
    /// 22 JA: jump always (programs).
    Ja = 22 "JA",
    /// 23 CSUB: call a subroutine (programs).
    Csub = 23 "CSUB",
    /// 24 RSUB: return from a subroutine (programs).
    Rsub = 24 "RSUB",
    /// 27 WAIT: wait for an event (programs).
    Wait = 27 "WAIT",
    /// 28 STOP: end of program.
    Stop = 28 "STOP",
    /// 29 SAC: SPI bus access.
    Sac = 29 "SAC",
    /// 30 SCO: set a coordinate.
    Sco = 30 "SCO",
    /// 31 GCO: get a coordinate.
    Gco = 31 "GCO",
    /// 32 CCO: capture the current position as a coordinate.
    Cco = 32 "CCO",
    /// 33 CALCX: arithmetic on the accumulator with the X register.
    Calcx = 33 "CALCX",
    /// 34 AAP: accumulator to axis parameter.
    Aap = 34 "AAP",
    /// 35 AGP: accumulator to global parameter.
    Agp = 35 "AGP",
    /// 36 CLE: clear error flags (programs).
    Cle = 36 "CLE",
    /// 39 ACO: accumulator to coordinate.
    Aco = 39 "ACO",
    /// 64 UF0: user function 0.
    Uf0 = 64 "UF0",
    /// 65 UF1: user function 1.
    Uf1 = 65 "UF1",
    /// 66 UF2: user function 2.
    Uf2 = 66 "UF2",
    /// 67 UF3: user function 3.
    Uf3 = 67 "UF3",
    /// 68 UF4: user function 4.
    Uf4 = 68 "UF4",
    /// 69 UF5: user function 5.
    Uf5 = 69 "UF5",
    /// 70 UF6: user function 6.
    Uf6 = 70 "UF6",
    /// 71 UF7: user function 7.
    Uf7 = 71 "UF7",
    /// 128: stop the stored program.
    StopApplication = 128 "",
    /// 129: run the stored program (type 1: from the address in the value).
    RunApplication = 129 "",
    /// 130: execute one instruction of the stored program.
    StepApplication = 130 "",
    /// 131: reset the program counter to the start of the program.
    ResetApplication = 131 "",
    /// 132: enter download mode: the following instructions are stored, not executed.
    StartDownload = 132 "",
    /// 133: leave download mode.
    QuitDownload = 133 "",
    /// 134: read the program memory at the address in the value (type 0: the instruction's
    /// value; type 1: its command, type and motor, as the simulator answers).
    ReadMemory = 134 "",
    /// 135: the program's status (stopped, running, stepping, reset).
    ApplicationStatus = 135 "",
    /// 136: the firmware version (type 0: a string reply without checksum; type 1: binary).
    FirmwareVersion = 136 "",
    /// 137: restore factory settings (value 1234; no reply is sent).
    FactoryDefaults = 137 "",
    /// 138: request a second, delayed reply (status 128) when the target position is reached.
    PositionEvent = 138 "",
    /// 139: switch to ASCII mode.
    EnterAscii = 139 "",
}

impl Opcode {
    /// The command number.
    pub fn number(self) -> u8 {
        self.into()
    }

    /// Whether this is a control function (128 and above, manual §6.5): it acts on the module
    /// and its program, and is executed even in download mode rather than stored.
    pub fn is_control(self) -> bool {
        self.number() >= 128
    }
}

impl PartialEq for Opcode {
    fn eq(&self, other: &Opcode) -> bool {
        self.number() == other.number()
    }
}

impl Eq for Opcode {}

impl Hash for Opcode {
    fn hash<H: Hasher>(&self, state: &mut H) {
        self.number().hash(state);
    }
}

#[cfg(test)]
mod tests {
    use std::collections::HashSet;

    use crate::dialect::tmcl::profile::Profile;

    use super::*;

    #[test]
    fn every_name_agrees_with_the_builtin_command_table() {
        let profile = Profile::builtin();
        for &(opcode, number, mnemonic) in NAMED {
            let spec = profile
                .commands
                .by_number(number)
                .unwrap_or_else(|| panic!("{opcode:?}: no command {number} in the table"));
            assert_eq!(spec.mnemonic, mnemonic, "{opcode:?}");
            assert_eq!(opcode.number(), number, "{opcode:?}");
            assert_eq!(Opcode::from(number), opcode, "{opcode:?}");
        }
        for spec in profile.commands.iter() {
            let opcode = Opcode::from(spec.number);
            assert!(
                !matches!(opcode, Opcode::Other(_)),
                "command {} ({}) has no name",
                spec.number,
                spec.name
            );
        }
        let numbers: HashSet<u8> = NAMED.iter().map(|&(_, n, _)| n).collect();
        assert_eq!(numbers.len(), NAMED.len(), "a number named twice");
    }

    #[test]
    fn every_number_round_trips_and_only_unnamed_ones_are_other() {
        for number in 0..=u8::MAX {
            let opcode = Opcode::from(number);
            assert_eq!(u8::from(opcode), number);
            let named = NAMED.iter().any(|&(_, n, _)| n == number);
            assert_eq!(matches!(opcode, Opcode::Other(_)), !named, "{number}");
        }
    }

    #[test]
    fn an_other_built_by_hand_equals_the_variant_of_its_number() {
        assert_eq!(Opcode::Other(6), Opcode::Gap);
        assert_ne!(Opcode::Other(7), Opcode::Gap);
        let set: HashSet<Opcode> = [Opcode::Other(139), Opcode::EnterAscii].into();
        assert_eq!(set.len(), 1);
    }
}
