//! A classic CAN data frame with a standard (11-bit) identifier: what TMCL over CAN uses (the
//! module manuals' §6.1/§6.2 name no extended identifiers).

use std::fmt;

/// The largest standard identifier.
pub const MAX_STANDARD_ID: u16 = 0x7FF;

/// At most eight data bytes in a classic CAN frame.
pub const MAX_DATA: usize = 8;

/// A standard data frame.
#[derive(Clone, Copy, PartialEq, Eq)]
pub struct CanFrame {
    id: u16,
    len: u8,
    data: [u8; MAX_DATA],
}

/// Why a frame cannot be built.
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
pub enum FrameError {
    /// The identifier needs more than 11 bits.
    #[error("CAN ID {0:#x} is not a standard 11-bit identifier (0..=0x7FF)")]
    Id(u32),
    /// More than eight data bytes.
    #[error("{0} data bytes do not fit a CAN frame (at most 8)")]
    Length(usize),
}

impl CanFrame {
    /// A frame with identifier `id` carrying `data`.
    pub fn new(id: u16, data: &[u8]) -> Result<CanFrame, FrameError> {
        if id > MAX_STANDARD_ID {
            return Err(FrameError::Id(u32::from(id)));
        }
        if data.len() > MAX_DATA {
            return Err(FrameError::Length(data.len()));
        }
        let mut bytes = [0u8; MAX_DATA];
        bytes[..data.len()].copy_from_slice(data);
        Ok(CanFrame {
            id,
            len: data.len() as u8,
            data: bytes,
        })
    }

    /// The identifier.
    pub fn id(&self) -> u16 {
        self.id
    }

    /// The data bytes.
    pub fn data(&self) -> &[u8] {
        &self.data[..usize::from(self.len)]
    }
}

/// `ID#DATA` in hex, as `candump` and `cansend` write frames.
impl fmt::Display for CanFrame {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{:03X}#", self.id)?;
        for b in self.data() {
            write!(f, "{b:02X}")?;
        }
        Ok(())
    }
}

impl fmt::Debug for CanFrame {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(self, f)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frames_keep_eleven_bits_and_eight_bytes() {
        let frame = CanFrame::new(0x7FF, &[1, 2, 3]).unwrap();
        assert_eq!(frame.id(), 0x7FF);
        assert_eq!(frame.data(), &[1, 2, 3]);
        assert_eq!(frame.to_string(), "7FF#010203");
        assert_eq!(CanFrame::new(0x800, &[]), Err(FrameError::Id(0x800)));
        assert_eq!(CanFrame::new(1, &[0; 9]), Err(FrameError::Length(9)));
        assert_eq!(CanFrame::new(1, &[]).unwrap().data(), &[] as &[u8]);
    }
}
