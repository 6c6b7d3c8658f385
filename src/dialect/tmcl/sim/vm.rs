//! The stand-alone program runner's registers: a TMCL virtual machine over program memory, with
//! accumulator and X register, comparison flags, a bounded subroutine stack, the wait it is in,
//! and its interrupts' vectors and switches. What runs on them is [`super::runner`]'s; this file
//! knows no module, so the module's state ([`super::machine`]) can hold it.

use std::cmp::Ordering;

use crate::dialect::tmcl::protocol::{Instruction, Opcode, Status};

use super::program::Program;

/// Application status as 135 and GP 128 report it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum AppStatus {
    Stop = 0,
    Run = 1,
    Step = 2,
    Reset = 3,
}

/// Why a program stopped on its own (135 type 1).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum ProgramError {
    /// No error.
    None = 0,
    /// An instruction the module cannot execute (unknown command, control function, bad type).
    InvalidInstruction = 1,
    /// A jump or call to an address outside program memory.
    BadJump = 2,
    /// CSUB beyond the stack depth.
    StackOverflow = 3,
    /// RSUB without CSUB.
    StackUnderflow = 4,
    /// The program ran past the end of memory.
    EndOfMemory = 5,
    /// CALC/CALCX DIV or MOD by zero.
    DivisionByZero = 6,
}

/// What a WAIT waits for (its type byte).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Until {
    Ticks,
    Position,
    ReferenceSwitch,
    LimitSwitch,
    ReferenceSearch,
}

#[derive(Debug, Clone, Copy)]
pub(super) struct Wait {
    pub(super) until: Until,
    /// The motor waited for.
    pub(super) motor: u8,
    /// End of the wait (TICKS) or its time-out.
    pub(super) deadline: Option<f64>,
}

/// Program runner state.
#[derive(Debug, Clone)]
pub(crate) struct Vm {
    /// The accumulator (AAP, AGP, ACO read it).
    pub acc: i32,
    /// The X register.
    pub x: i32,
    pub(super) status: AppStatus,
    pub(super) pc: i32,
    pub(super) stack: Vec<i32>,
    pub(super) compared: Option<Ordering>,
    pub(super) timeout_flag: bool,
    error: ProgramError,
    /// When the next instruction (or the next look at a wait) is due.
    pub(super) next_at: f64,
    pub(super) wait: Option<Wait>,
    /// Vectors, switches and pending interrupts ([`super::interrupts`]).
    pub(super) interrupts: Interrupts,
    /// In step mode: one instruction still to run.
    step_pending: bool,
}

impl Vm {
    /// Stopped at address 0.
    pub(super) fn new() -> Vm {
        Vm {
            acc: 0,
            x: 0,
            status: AppStatus::Stop,
            pc: 0,
            stack: Vec::new(),
            compared: None,
            timeout_flag: false,
            error: ProgramError::None,
            next_at: 0.0,
            wait: None,
            step_pending: false,
            interrupts: Interrupts::new(),
        }
    }

    /// Whether instructions are due to run.
    pub(super) fn running(&self) -> bool {
        self.status == AppStatus::Run || (self.status == AppStatus::Step && self.step_pending)
    }

    /// 129 type 0: run (or continue) from the current address.
    pub(super) fn resume(&mut self, t: f64, _program: &Program) -> Result<(), Status> {
        self.status = AppStatus::Run;
        self.error = ProgramError::None;
        self.next_at = t;
        Ok(())
    }

    /// 129 type 1: run from `address`.
    pub(super) fn run_from(
        &mut self,
        t: f64,
        program: &Program,
        address: i32,
    ) -> Result<(), Status> {
        if !(0..program.size() as i64).contains(&i64::from(address)) {
            return Err(Status::InvalidValue);
        }
        self.pc = address;
        self.stack.clear();
        self.wait = None;
        self.interrupts.saved = None;
        self.resume(t, program)
    }

    /// Auto-start (GP 77) at power-up.
    pub(super) fn start(&mut self, t: f64, address: i32) {
        self.pc = address;
        self.status = AppStatus::Run;
        self.next_at = t;
    }

    /// 130: run the next instruction, then pause in step mode.
    pub(super) fn step(&mut self, t: f64, _program: &Program) -> Result<(), Status> {
        self.status = AppStatus::Step;
        self.step_pending = true;
        self.error = ProgramError::None;
        self.next_at = t;
        Ok(())
    }

    /// 128: stop where the program is.
    pub(super) fn stop(&mut self) {
        self.status = AppStatus::Stop;
        self.wait = None;
        self.step_pending = false;
    }

    /// 131: program counter to 0, registers and stack cleared, stopped.
    pub(super) fn reset(&mut self) {
        *self = Vm::new();
        self.status = AppStatus::Reset;
    }

    /// 135 / GP 128.
    pub(super) fn status_code(&self) -> i32 {
        self.status as i32
    }

    /// 135 type 1: the error that stopped the program last (0 none).
    pub(super) fn error_code(&self) -> i32 {
        self.error as i32
    }

    /// GP 130.
    pub(super) fn pc(&self) -> i32 {
        self.pc
    }

    pub(super) fn fail(&mut self, error: ProgramError) {
        self.error = error;
        self.stop();
    }

    /// One instruction (or a whole wait) is done: on to the next.
    pub(super) fn done(&mut self, next_pc: i32, at: f64) {
        self.pc = next_pc;
        if self.status == AppStatus::Step {
            self.step_pending = false;
        }
        self.next_at = at;
    }
}

fn calc(op: u8, a: i32, b: i32) -> Result<i32, ProgramError> {
    Ok(match op {
        0 => a.wrapping_add(b),
        1 => a.wrapping_sub(b),
        2 => a.wrapping_mul(b),
        3 | 4 if b == 0 => return Err(ProgramError::DivisionByZero),
        3 => a.wrapping_div(b),
        4 => a.wrapping_rem(b),
        5 => a & b,
        6 => a | b,
        7 => a ^ b,
        8 => !a,
        9 => b,
        _ => return Err(ProgramError::InvalidInstruction),
    })
}

/// Where a jump or call to `address` goes, if program memory has it.
pub(super) fn jump_target(program: &Program, address: i32) -> Result<i32, ProgramError> {
    if (0..program.size() as i64).contains(&i64::from(address)) {
        Ok(address)
    } else {
        Err(ProgramError::BadJump)
    }
}

impl Vm {
    /// CALC and CALCX on the one accumulator and X register, from a program or in direct mode
    /// (manual 6.4.5: calculation commands may be used in both).
    pub(super) fn calculate(&mut self, i: &Instruction) -> Result<(), ProgramError> {
        match (i.command, i.type_) {
            (Opcode::Calc, op) => self.acc = calc(op, self.acc, i.value)?,
            (_, 9) => self.x = self.acc,
            (_, 10) => std::mem::swap(&mut self.acc, &mut self.x),
            (_, op) => self.acc = calc(op, self.acc, self.x)?,
        }
        Ok(())
    }
}

/// The program's state an interrupt saves and RETI restores.
#[derive(Debug, Clone)]
pub(super) struct Context {
    /// Where the program goes on.
    pub(super) pc: i32,
    pub(super) acc: i32,
    pub(super) x: i32,
    pub(super) compared: Option<Ordering>,
    pub(super) timeout_flag: bool,
    pub(super) wait: Option<Wait>,
}

/// Vectors, switches and what is pending.
#[derive(Debug, Clone)]
pub(super) struct Interrupts {
    pub(super) vectors: Box<[Option<i32>; 256]>,
    pub(super) enabled: Box<[bool; 256]>,
    pub(super) global: bool,
    pub(super) pending: Box<[bool; 256]>,
    /// The next tick of each timer, by interrupt number, while its period is set.
    pub(super) timers: Vec<(u8, f64)>,
    /// The interrupted program, while a handler runs.
    pub(super) saved: Option<Context>,
}

impl Interrupts {
    /// No vectors, all off (power-up, program reset).
    pub(super) fn new() -> Interrupts {
        Interrupts {
            vectors: Box::new([None; 256]),
            enabled: Box::new([false; 256]),
            global: false,
            pending: Box::new([false; 256]),
            timers: Vec::new(),
            saved: None,
        }
    }

    /// When the next timer ticks.
    pub(super) fn next_tick(&self) -> Option<f64> {
        self.timers.iter().map(|&(_, at)| at).min_by(f64::total_cmp)
    }

    pub(super) fn ready(&self) -> Option<u8> {
        if !self.global || self.saved.is_some() {
            return None;
        }
        (0..=u8::MAX)
            .find(|&n| self.pending[usize::from(n)] && self.vectors[usize::from(n)].is_some())
    }
}
