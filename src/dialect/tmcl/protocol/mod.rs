//! The TMCL protocol of Trinamic modules: binary frames, the ASCII interface's line and reply
//! grammar, the command table and validation. Pure code: bytes and text in, values out.

pub mod commands;
pub mod error;
pub mod frame;
pub mod instruction;
pub mod line;
pub mod reply;
pub mod status;
pub mod syntax;
pub mod validate;

pub use commands::{AsciiWord, CommandSpec, CommandTable};
pub use error::{InputError, Warning};
pub use frame::{CommandFrame, FrameDecoder, ReplyFrame};
pub use instruction::Instruction;
pub use line::{Line, Op, address_char, address_of, format_instruction, format_line, parse};
pub use reply::{AsciiReply, host_char, parse_reply, parse_reply_bytes};
pub use status::Status;
pub use validate::{Mode, validate};
