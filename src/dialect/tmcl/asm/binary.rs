//! The `.bin` program file written by `tmclsh asm -o` and read by `disasm` and `download`.
//!
//! ```text
//! offset  size  content
//! 0       4     magic "TMCL" (54 4D 43 4C)
//! 4       1     format version, 1
//! 5       2     instruction count N, big-endian
//! 7       7*N   the instructions in address order, each command, type, motor/bank, value
//!               (i32 big-endian) — exactly the 7 bytes a download frame carries
//! ```
//!
//! Why a header rather than bare 7-byte records: the count and the magic let a reader refuse a
//! truncated file, a source file passed by mistake or any other file *before* anything is sent to
//! a module, and the version leaves room to grow. The header is itself 7 bytes long, so the
//! records stay aligned in a hex dump.

use crate::dialect::tmcl::protocol::Instruction;

/// The first four bytes of every program file.
pub const MAGIC: [u8; 4] = *b"TMCL";
/// The format version this code writes and reads.
pub const VERSION: u8 = 1;
/// Header length in bytes.
pub const HEADER_LEN: usize = 7;

/// Why bytes are not a program file.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum BinaryError {
    /// The magic is missing.
    #[error(
        "not a tmclsh program file (it does not start with \"TMCL\"); assemble a source with `tmclsh asm FILE.tmc -o FILE.bin`"
    )]
    NotAProgram,
    /// A version this build does not know.
    #[error(
        "program file format version {0} is not supported (this tmclsh reads version {VERSION})"
    )]
    Version(u8),
    /// The file ends inside the header.
    #[error("program file is damaged: it ends inside its {HEADER_LEN}-byte header")]
    Truncated,
    /// Length and count disagree.
    #[error("program file is damaged: the header announces {announced} instructions ({} bytes) but {actual} bytes follow it", announced * 7)]
    Length {
        /// Instructions announced by the header.
        announced: usize,
        /// Bytes after the header.
        actual: usize,
    },
    /// More instructions than the count field can hold.
    #[error("{0} instructions do not fit in a program file (at most 65535)")]
    TooMany(usize),
}

/// Instructions that make no program file are refused (exit 2).
impl crate::exit::ExitStatus for BinaryError {
    fn exit(&self) -> crate::exit::Exit {
        crate::exit::Exit::Refused
    }
}

/// Whether `bytes` start like a program file (as opposed to source text).
pub fn is_program_file(bytes: &[u8]) -> bool {
    bytes.starts_with(&MAGIC)
}

/// The file contents for `instructions`.
pub(super) fn write(instructions: &[Instruction]) -> Result<Vec<u8>, BinaryError> {
    let count =
        u16::try_from(instructions.len()).map_err(|_| BinaryError::TooMany(instructions.len()))?;
    let mut out = Vec::with_capacity(HEADER_LEN + 7 * instructions.len());
    out.extend_from_slice(&MAGIC);
    out.push(VERSION);
    out.extend_from_slice(&count.to_be_bytes());
    for instruction in instructions {
        out.extend_from_slice(&instruction.to_bytes());
    }
    Ok(out)
}

/// The instructions of a program file.
pub(super) fn read(bytes: &[u8]) -> Result<Vec<Instruction>, BinaryError> {
    if !is_program_file(bytes) {
        return Err(BinaryError::NotAProgram);
    }
    let header = bytes.get(..HEADER_LEN).ok_or(BinaryError::Truncated)?;
    if header[4] != VERSION {
        return Err(BinaryError::Version(header[4]));
    }
    let announced = usize::from(u16::from_be_bytes([header[5], header[6]]));
    let body = &bytes[HEADER_LEN..];
    if body.len() != announced * 7 {
        return Err(BinaryError::Length {
            announced,
            actual: body.len(),
        });
    }
    Ok(body
        .chunks_exact(7)
        .map(|chunk| Instruction::from_bytes(chunk.try_into().expect("chunks of 7")))
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #[test]
        fn files_round_trip(raw in proptest::collection::vec(any::<(u8, u8, u8, i32)>(), 0..50)) {
            let program: Vec<Instruction> =
                raw.iter().map(|&(c, t, m, v)| Instruction::new(c, t, m, v)).collect();
            let bytes = write(&program).unwrap();
            prop_assert_eq!(bytes.len(), 7 + 7 * program.len());
            prop_assert_eq!(read(&bytes).unwrap(), program);
        }
    }

    #[test]
    fn the_layout_is_header_then_big_endian_records() {
        let bytes = write(&[Instruction::new(22, 0, 0, 8), Instruction::new(4, 0, 0, -2)]).unwrap();
        assert_eq!(
            bytes,
            [
                b'T', b'M', b'C', b'L', 1, 0, 2, // header
                22, 0, 0, 0, 0, 0, 8, // JA 8
                4, 0, 0, 0xFF, 0xFF, 0xFF, 0xFE, // MVP ABS, 0, -2
            ]
        );
    }

    #[test]
    fn damaged_or_foreign_files_are_refused() {
        let good = write(&[Instruction::new(3, 0, 0, 0)]).unwrap();
        assert_eq!(read(b"ROL 0, 500\n"), Err(BinaryError::NotAProgram));
        assert_eq!(read(b"TMC"), Err(BinaryError::NotAProgram));
        assert_eq!(read(b"TMCL\x01\x00"), Err(BinaryError::Truncated));
        let mut future = good.clone();
        future[4] = 2;
        assert_eq!(read(&future), Err(BinaryError::Version(2)));
        assert_eq!(
            read(&good[..good.len() - 1]),
            Err(BinaryError::Length {
                announced: 1,
                actual: 6
            })
        );
        let mut long = good.clone();
        long.push(0);
        assert!(
            read(&long)
                .unwrap_err()
                .to_string()
                .contains("8 bytes follow")
        );
        assert!(is_program_file(&good) && !is_program_file(b"// TMCL source"));
    }
}
