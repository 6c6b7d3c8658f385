//! An assembled program: the instructions in memory order, where each came from, its labels, and
//! the listing that shows them side by side with the source.

use std::fmt::Write as _;

use crate::dialect::tmcl::protocol::Instruction;

use super::error::AsmWarning;

/// A label and the address it stands for.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Label {
    /// The name as written where it was defined.
    pub name: String,
    /// Program address (instruction index).
    pub address: usize,
}

/// The result of [`assemble`](super::assemble).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Program {
    /// The instructions; instruction `i` is stored at program address `i`.
    pub instructions: Vec<Instruction>,
    /// For each instruction, the 1-based source line it came from.
    pub lines: Vec<usize>,
    /// The labels, by address.
    pub labels: Vec<Label>,
    /// Warnings about lines that still assembled.
    pub warnings: Vec<AsmWarning>,
}

impl Program {
    /// Size in program memory, in bytes (7 per instruction).
    pub fn byte_len(&self) -> usize {
        self.instructions.len() * 7
    }

    /// The listing: every source line, preceded by the address and the 7 bytes (hex) of the
    /// instruction it produced, if it produced one.
    ///
    /// ```text
    /// addr  command type motor value  line  source
    /// 0008  04 00 00 00 0F 42 40        17  Loop: MVP ABS, 0, 1000000 //Move to Position 10000
    /// ```
    pub fn listing(&self, source: &str) -> String {
        let mut by_line = vec![None; source.lines().count() + 1];
        for (address, &line) in self.lines.iter().enumerate() {
            if let Some(slot) = by_line.get_mut(line) {
                *slot = Some(address);
            }
        }
        let number_width = source.lines().count().to_string().len().max(4);
        let mut out = String::new();
        let _ = writeln!(
            out,
            "addr  {:<20}  {:>number_width$}  source",
            "bytes", "line"
        );
        for (index, text) in source.lines().enumerate() {
            let line = index + 1;
            let code = match by_line[line] {
                Some(address) => {
                    let bytes = self.instructions[address].to_bytes();
                    let hex: Vec<String> = bytes.iter().map(|b| format!("{b:02X}")).collect();
                    format!("{address:04}  {}", hex.join(" "))
                }
                None => String::new(),
            };
            let row = format!("{code:<26}  {line:>number_width$}  {text}");
            let _ = writeln!(out, "{}", row.trim_end());
        }
        out
    }
}
