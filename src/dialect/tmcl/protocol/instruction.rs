//! The 7-byte TMCL instruction: what every command line, frame and stored program word carries.

/// Command number, type, motor/bank and value — the binary representation of one command
/// (manual §6.1), without the serial address and checksum.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct Instruction {
    /// Command number (1 ROR … 139 enter ASCII mode).
    pub command: u8,
    /// Type byte (parameter number, keyword value, port …).
    pub type_: u8,
    /// Motor or bank byte.
    pub motor: u8,
    /// Value, sent big-endian.
    pub value: i32,
}

impl Instruction {
    /// A new instruction.
    pub fn new(command: u8, type_: u8, motor: u8, value: i32) -> Self {
        Instruction {
            command,
            type_,
            motor,
            value,
        }
    }

    /// The seven bytes in wire order (command, type, motor, value MSB first).
    pub fn to_bytes(self) -> [u8; 7] {
        let v = self.value.to_be_bytes();
        [self.command, self.type_, self.motor, v[0], v[1], v[2], v[3]]
    }

    /// The instruction from its seven bytes.
    pub fn from_bytes(b: [u8; 7]) -> Self {
        Instruction {
            command: b[0],
            type_: b[1],
            motor: b[2],
            value: i32::from_be_bytes([b[3], b[4], b[5], b[6]]),
        }
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
