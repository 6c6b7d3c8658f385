//! The program runner on a module: the instructions of program memory on [`super::vm`]'s registers,
//! waits with time-outs, interrupts taken between instructions, and the motion and parameter
//! commands of [`super::exec`].
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

use super::machine::Machine;
use super::motion::Switch;
use super::outcome::{Reply, Source};
use super::vm::{AppStatus, ProgramError, Until, Wait, jump_target};

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

    fn instruction(&mut self, t: f64, i: &Instruction) -> Result<(), ProgramError> {
        let next = t + self.instruction_time();
        let mut next_pc = self.vm.pc + 1;
        match i.command {
            Opcode::Calc | Opcode::Calcx => self.vm.calculate(i)?,
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
                    next_pc = jump_target(&self.program, i.value)?;
                }
            }
            Opcode::Ja => next_pc = jump_target(&self.program, i.value)?,
            Opcode::Csub => {
                let target = jump_target(&self.program, i.value)?;
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
