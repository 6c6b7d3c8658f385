//! The TMCL protocol of Trinamic modules: binary frames, the ASCII interface's line and reply
//! grammar, the operand grammar typed lines and programs share, and validation against the
//! profile's tables ([`super::profile`], which holds the command table). Pure code: bytes and
//! text in, values out.

pub mod can;
pub mod error;
pub mod frame;
pub mod host_clash;
pub mod instruction;
pub mod line;
pub mod module_name;
pub mod opcode;
pub mod operands;
pub mod reply;
pub mod sniff;
pub mod status;
pub mod syntax;
pub mod validate;

pub use crate::dialect::tmcl::profile::commands::{AsciiWord, CommandSpec, CommandTable};
pub use error::{InputError, Warning};
pub use frame::{CommandFrame, FrameDecoder, ReplyFrame};
pub use instruction::Instruction;
pub use line::{Line, Op, address_char, address_of, format_instruction, format_line, parse};
pub use module_name::ModuleName;
pub use opcode::Opcode;
pub use reply::{AsciiReply, host_char, parse_reply, parse_reply_bytes};
pub use status::Status;
pub use validate::{Mode, validate};
