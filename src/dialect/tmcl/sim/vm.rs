//! The stand-alone program runner: a TMCL virtual machine over program memory, with accumulator
//! and X register, comparison flags, a bounded subroutine stack, waits with time-outs, and the
//! motion and parameter commands of [`super::exec`].
//!
//! Time: each instruction takes `instruction_us` of the profile's `[simulation]` constants, a
//! WAIT as long as it waits; the runner is driven by [`Machine::advance`], so direct-mode
//! commands interleave with the program at their arrival time (and leave the accumulator alone,
//! manual §6.4.5).
//!
//! Choices the manual leaves open: JC ZE/NZ test the accumulator, EQ..LE the last COMP; a command
//! that fails in a program (other than an invalid one) is skipped, as there is nobody to answer;
//! STOP ends the program with the program counter back at 0, so that 129 type 0 runs it again;
//! ASCII RUN starts at address 0. A program error stops the program with the program counter on
//! the faulty instruction; 135 type 1 (a simulator extension) tells which error it was.

use std::cmp::Ordering;

use crate::dialect::tmcl::protocol::{Instruction, Opcode, Status};

use super::interrupts::Interrupts;
use super::machine::Machine;
use super::motion::Switch;
use super::outcome::{Reply, Source};
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
enum Until {
    Ticks,
    Position,
    ReferenceSwitch,
    LimitSwitch,
    ReferenceSearch,
}

#[derive(Debug, Clone, Copy)]
pub(super) struct Wait {
    until: Until,
    /// The motor waited for.
    motor: u8,
    /// End of the wait (TICKS) or its time-out.
    deadline: Option<f64>,
}

/// Program runner state.
#[derive(Debug, Clone)]
pub(crate) struct Vm {
    /// The accumulator (AAP, AGP, ACO read it).
    pub acc: i32,
    /// The X register.
    pub x: i32,
    status: AppStatus,
    pub(super) pc: i32,
    stack: Vec<i32>,
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

    fn fail(&mut self, error: ProgramError) {
        self.error = error;
        self.stop();
    }

    /// One instruction (or a whole wait) is done: on to the next.
    fn done(&mut self, next_pc: i32, at: f64) {
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

impl Machine {
    fn tick(&self) -> f64 {
        f64::from(self.profile.sim.tick_ms) / 1000.0
    }

    fn instruction_time(&self) -> f64 {
        f64::from(self.profile.sim.instruction_us) / 1e6
    }

    /// When the program runner next has something to do: its next instruction, a look at its
    /// wait, or a timer's tick.
    pub(crate) fn program_due(&self) -> Option<f64> {
        if !self.vm.running() {
            return None;
        }
        let Some(wait) = self.vm.wait else {
            return Some(self.vm.next_at);
        };
        let arrival = self.axes[usize::from(wait.motor)].arrival();
        let look = match (wait.until, arrival) {
            (Until::Position, Some(arrival)) => arrival,
            _ => self.vm.next_at,
        };
        let due = wait.deadline.map_or(look, |d| d.min(look));
        Some(match self.vm.interrupts.next_tick() {
            Some(tick) if self.vm.status == AppStatus::Run => due.min(tick),
            _ => due,
        })
    }

    /// Runs the program's next instruction, or looks at its wait, at `t`.
    pub(crate) fn run_program(&mut self, t: f64) {
        if !self.vm.running() {
            return;
        }
        if self.vm.status == AppStatus::Run {
            self.tick_timers(t);
            if self.take_interrupt(t) {
                return;
            }
        }
        if let Some(wait) = self.vm.wait {
            self.look_at_wait(t, wait);
            return;
        }
        let Some(i) = self.program.get(self.vm.pc) else {
            return self.vm.fail(ProgramError::EndOfMemory);
        };
        if let Err(error) = self.instruction(t, &i) {
            self.vm.fail(error);
        }
    }

    fn look_at_wait(&mut self, t: f64, wait: Wait) {
        let axis = &self.axes[usize::from(wait.motor)];
        let satisfied = match wait.until {
            Until::Ticks => false,
            Until::Position => !axis.is_positioning() && self.target_reached(wait.motor, t),
            Until::ReferenceSwitch => axis.switch_active(t, Switch::Home),
            Until::LimitSwitch => {
                axis.switch_active(t, Switch::Left) || axis.switch_active(t, Switch::Right)
            }
            Until::ReferenceSearch => axis.search_status() == 0,
        };
        let expired = wait.deadline.is_some_and(|d| t >= d - 1e-9);
        if satisfied || expired {
            if expired && !satisfied && wait.until != Until::Ticks {
                self.vm.timeout_flag = true;
            }
            self.vm.wait = None;
            let next = t + self.instruction_time();
            self.vm.done(self.vm.pc + 1, next);
        } else {
            self.vm.next_at = t + self.tick();
        }
    }

    pub(super) fn jump_target(&self, address: i32) -> Result<i32, ProgramError> {
        if (0..self.program.size() as i64).contains(&i64::from(address)) {
            Ok(address)
        } else {
            Err(ProgramError::BadJump)
        }
    }

    /// CALC and CALCX on the one accumulator and X register, from a program or in direct mode
    /// (manual 6.4.5: calculation commands may be used in both).
    pub(super) fn calculate(&mut self, i: &Instruction) -> Result<(), ProgramError> {
        match (i.command, i.type_) {
            (Opcode::Calc, op) => self.vm.acc = calc(op, self.vm.acc, i.value)?,
            (_, 9) => self.vm.x = self.vm.acc,
            (_, 10) => std::mem::swap(&mut self.vm.acc, &mut self.vm.x),
            (_, op) => self.vm.acc = calc(op, self.vm.acc, self.vm.x)?,
        }
        Ok(())
    }

    fn instruction(&mut self, t: f64, i: &Instruction) -> Result<(), ProgramError> {
        let next = t + self.instruction_time();
        let mut next_pc = self.vm.pc + 1;
        match i.command {
            Opcode::Calc | Opcode::Calcx => self.calculate(i)?,
            Opcode::Comp => self.vm.compared = Some(self.vm.acc.cmp(&i.value)),
            Opcode::Jc => {
                use Ordering::{Equal, Greater, Less};
                let c = self.vm.compared;
                let taken = match i.type_ {
                    0 => self.vm.acc == 0,
                    1 => self.vm.acc != 0,
                    2 => c == Some(Equal),
                    3 => matches!(c, Some(Less | Greater)),
                    4 => c == Some(Greater),
                    5 => matches!(c, Some(Greater | Equal)),
                    6 => c == Some(Less),
                    7 => matches!(c, Some(Less | Equal)),
                    8 => self.vm.timeout_flag,
                    9..=11 => false, // alarm, deviation and position errors do not occur
                    _ => return Err(ProgramError::InvalidInstruction),
                };
                if taken {
                    next_pc = self.jump_target(i.value)?;
                }
            }
            Opcode::Ja => next_pc = self.jump_target(i.value)?,
            Opcode::Csub => {
                let target = self.jump_target(i.value)?;
                if self.vm.stack.len() >= self.profile.stack_depth.into() {
                    return Err(ProgramError::StackOverflow);
                }
                self.vm.stack.push(next_pc);
                next_pc = target;
            }
            Opcode::Rsub => next_pc = self.vm.stack.pop().ok_or(ProgramError::StackUnderflow)?,
            Opcode::Cle => match i.type_ {
                0 | 1 => self.vm.timeout_flag = false,
                2..=4 => {}
                _ => return Err(ProgramError::InvalidInstruction),
            },
            Opcode::Stop => {
                self.vm.stop();
                self.vm.pc = 0;
                self.vm.stack.clear();
                return Ok(());
            }
            Opcode::Wait => return self.start_wait(t, i),
            // EI, DI, VECT, RETI on a module whose table has them.
            Opcode::Other(25 | 26 | 37 | 38)
                if self
                    .profile
                    .commands
                    .by_number(i.command)
                    .is_some_and(|spec| spec.standalone) =>
            {
                self.interrupt_instruction(i, &mut next_pc)?;
            }
            _ => {
                let outcome = self.execute(t, i, Source::Program);
                match outcome.reply {
                    Reply::Normal(Status::InvalidCommand, _) => {
                        return Err(ProgramError::InvalidInstruction);
                    }
                    Reply::Normal(Status::Ok, value) if i.reads_value() => self.vm.acc = value,
                    _ => {}
                }
            }
        }
        self.vm.done(next_pc, next);
        Ok(())
    }

    fn start_wait(&mut self, t: f64, i: &Instruction) -> Result<(), ProgramError> {
        let until = match i.type_ {
            0 => Until::Ticks,
            1 => Until::Position,
            2 => Until::ReferenceSwitch,
            3 => Until::LimitSwitch,
            4 => Until::ReferenceSearch,
            _ => return Err(ProgramError::InvalidInstruction),
        };
        if usize::from(i.motor) >= self.axes.len() {
            return Err(ProgramError::InvalidInstruction);
        }
        let ticks = f64::from(i.value.max(0)) * self.tick();
        let deadline = (until == Until::Ticks || i.value > 0).then_some(t + ticks);
        let wait = Wait {
            until,
            motor: i.motor,
            deadline,
        };
        self.vm.wait = Some(wait);
        // Look at once: a condition that already holds ends the wait now.
        self.look_at_wait(t, wait);
        Ok(())
    }
}
