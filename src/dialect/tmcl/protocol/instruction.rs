//! The 7-byte TMCL instruction: what every command line, frame and stored program word carries.

use std::fmt;

use super::opcode::Opcode;

/// Command number, type, motor/bank and value — the binary representation of one command
/// (manual §6.1), without the serial address and checksum.
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
pub struct Instruction {
    /// Command number (1 ROR … 139 enter ASCII mode).
    pub command: Opcode,
    /// Type byte (parameter number, keyword value, port …).
    pub type_: u8,
    /// Motor or bank byte.
    pub motor: u8,
    /// Value, sent big-endian.
    pub value: i32,
}

impl Instruction {
    /// A new instruction.
    pub fn new(command: impl Into<Opcode>, type_: u8, motor: u8, value: i32) -> Self {
        Instruction {
            command: command.into(),
            type_,
            motor,
            value,
        }
    }

    /// The seven bytes in wire order (command, type, motor, value MSB first).
    pub fn to_bytes(self) -> [u8; 7] {
        let v = self.value.to_be_bytes();
        [
            self.command.into(),
            self.type_,
            self.motor,
            v[0],
            v[1],
            v[2],
            v[3],
        ]
    }

    /// Whether the instruction asks for a value and changes nothing: GAP, GGP, GIO, GCO and the
    /// status of a reference search (a program gets the value in its accumulator).
    pub fn reads_value(&self) -> bool {
        matches!(
            self.command,
            Opcode::Gap | Opcode::Ggp | Opcode::Gio | Opcode::Gco
        ) || (self.command == Opcode::Rfs && self.type_ == 2)
    }

    /// The instruction from its seven bytes.
    pub fn from_bytes(b: [u8; 7]) -> Self {
        Instruction {
            command: b[0].into(),
            type_: b[1],
            motor: b[2],
            value: i32::from_be_bytes([b[3], b[4], b[5], b[6]]),
        }
    }
}

/// All seven bytes zero: command 0, which no module has — what erased program memory holds.
impl Default for Instruction {
    fn default() -> Self {
        Instruction::from_bytes([0; 7])
    }
}

/// The fields as numbers, as they are on the wire (messages such as a failed download
/// verification show them).
impl fmt::Debug for Instruction {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Instruction")
            .field("command", &self.command.number())
            .field("type_", &self.type_)
            .field("motor", &self.motor)
            .field("value", &self.value)
            .finish()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #[test]
        fn bytes_round_trip(c: u8, t: u8, m: u8, v: i32) {
            let i = Instruction::new(c, t, m, v);
            prop_assert_eq!(Instruction::from_bytes(i.to_bytes()), i);
        }
    }

    #[test]
    fn value_is_big_endian() {
        let i = Instruction::new(4, 0, 0, 1000);
        assert_eq!(i.to_bytes(), [4, 0, 0, 0, 0, 0x03, 0xE8]);
        assert_eq!(
            Instruction::new(1, 0, 0, -2).to_bytes()[3..],
            [0xFF, 0xFF, 0xFF, 0xFE]
        );
    }
}
