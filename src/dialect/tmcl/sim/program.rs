//! Program memory (the module's TMCL EEPROM) and download mode (132/133/134): instructions sent
//! between 132 and 133 are stored at consecutive addresses instead of being executed.

use crate::dialect::tmcl::protocol::{Instruction, Status};

/// The stored program of one module.
#[derive(Debug, Clone)]
pub(crate) struct Program {
    memory: Vec<Instruction>,
    /// Addresses below this have been written at some time.
    used: usize,
    /// The next address while download mode is on.
    download: Option<usize>,
    /// Memory changed since the last save.
    changed: bool,
}

impl Program {
    /// Empty memory of `size` instructions (all zero: command 0 is no valid instruction).
    pub(super) fn new(size: u16) -> Program {
        Program {
            memory: vec![Instruction::default(); size.into()],
            used: 0,
            download: None,
            changed: false,
        }
    }

    /// Number of instructions the memory holds.
    pub(super) fn size(&self) -> usize {
        self.memory.len()
    }

    /// 132: stores the following instructions from `address` on.
    pub(super) fn start_download(&mut self, address: i32) -> Result<(), Status> {
        let address = usize::try_from(address)
            .ok()
            .filter(|a| *a < self.memory.len())
            .ok_or(Status::InvalidValue)?;
        self.download = Some(address);
        Ok(())
    }

    /// 133: back to executing; returns whether memory changed and should be saved.
    pub(super) fn quit_download(&mut self) -> bool {
        self.download = None;
        std::mem::take(&mut self.changed)
    }

    /// Whether no instruction was ever stored.
    pub(super) fn is_empty(&self) -> bool {
        self.used == 0
    }

    /// Whether download mode is on (GP 129).
    pub(super) fn downloading(&self) -> bool {
        self.download.is_some()
    }

    /// Stores one instruction in download mode; memory full answers invalid value.
    pub(super) fn store(&mut self, instruction: Instruction) -> Result<(), Status> {
        let address = self.download.ok_or(Status::InvalidCommand)?;
        let slot = self.memory.get_mut(address).ok_or(Status::InvalidValue)?;
        if *slot != instruction {
            *slot = instruction;
            self.changed = true;
        }
        self.used = self.used.max(address + 1);
        self.download = Some(address + 1);
        Ok(())
    }

    /// The instruction at `address`, if the address exists.
    pub(super) fn get(&self, address: i32) -> Option<Instruction> {
        usize::try_from(address)
            .ok()
            .and_then(|a| self.memory.get(a))
            .copied()
    }

    /// The used part of memory, for the state file.
    pub(super) fn image(&self) -> Vec<(u8, u8, u8, i32)> {
        self.memory[..self.used]
            .iter()
            .map(|i| (i.command.number(), i.type_, i.motor, i.value))
            .collect()
    }

    /// Loads memory from the state file (excess instructions are dropped).
    pub(super) fn load(&mut self, image: &[(u8, u8, u8, i32)]) {
        self.erase();
        for (slot, &(c, t, m, v)) in self.memory.iter_mut().zip(image) {
            *slot = Instruction::new(c, t, m, v);
        }
        self.used = image.len().min(self.memory.len());
    }

    /// Clears memory; returns whether anything was there.
    pub(super) fn erase(&mut self) -> bool {
        let had = self.used > 0;
        self.memory.fill(Instruction::default());
        self.used = 0;
        had
    }
}

/// The reply value of 134 (read memory), a convention of this simulator because the manual does
/// not document one: type 0 gives the stored value, type 1 the command, type and motor/bank
/// packed big-endian into the low three bytes. Other types answer wrong type.
pub(crate) fn read_reply(instruction: Instruction, type_: u8) -> Result<i32, Status> {
    match type_ {
        0 => Ok(instruction.value),
        1 => Ok(i32::from(instruction.command.number()) << 16
            | i32::from(instruction.type_) << 8
            | i32::from(instruction.motor)),
        _ => Err(Status::WrongType),
    }
}
