//! Interrupts of the program runner (EI 25, DI 26, VECT 37, RETI 38), on the vectors of the
//! module's profile (`[[interrupt]]`). What the TMCL manuals say (TMCM-1690 §3.5.6): VECT sets an
//! interrupt's handler, EI and DI switch one interrupt or, with 255, all of them; an enabled
//! interrupt with a vector interrupts the program, whose context (accumulator, X register,
//! comparison flags) is saved and restored by RETI; handlers do not nest. A timer's period is its
//! bank-3 global parameter, in milliseconds of simulated time.
//!
//! Choices the manuals leave open: an event of an interrupt that is not enabled is dropped; one
//! that comes while a handler runs, or while interrupts are off globally, waits, and several of
//! one interrupt count once; a WAIT the program was in goes on after RETI; timers and their events
//! count only while the program runs. An input interrupt's bank-3 parameter is its trigger
//! (1 rising, 2 falling, 3 both edges, 0 off: inferred from the parameters' names, "trigger
//! transition"); inputs change on the simulator's console. A stop switch interrupt raises when a
//! limit switch stops its motor (reaching the switch taken as the rising edge); a switch passed
//! with its limit disabled, or left again, raises nothing.

use crate::dialect::tmcl::profile::family::{ALL_INTERRUPTS, InterruptKind};
use crate::dialect::tmcl::protocol::Instruction;
use crate::sim::error::ConsoleError;

use super::machine::Machine;
use super::motion::Switch;
use super::params::Slot;
use super::vm::{Context, ProgramError, jump_target};

/// The global parameter bank of the interrupt configuration.
const CONFIG_BANK: u8 = 3;

impl Machine {
    /// EI, DI, VECT, RETI in a program; `next_pc` is where the program would go on.
    pub(super) fn interrupt_instruction(
        &mut self,
        i: &Instruction,
        next_pc: &mut i32,
    ) -> Result<(), ProgramError> {
        let known = |n: u8| self.profile.interrupts.iter().any(|v| v.number == n);
        match u8::from(i.command) {
            25 | 26 => {
                let on = u8::from(i.command) == 25;
                match i.type_ {
                    ALL_INTERRUPTS => self.vm.interrupts.global = on,
                    n if known(n) => {
                        let n = usize::from(n);
                        self.vm.interrupts.enabled[n] = on;
                        if !on {
                            self.vm.interrupts.pending[n] = false;
                        }
                    }
                    _ => return Err(ProgramError::InvalidInstruction),
                }
            }
            37 => {
                if !known(i.type_) {
                    return Err(ProgramError::InvalidInstruction);
                }
                let target = jump_target(&self.program, i.value)?;
                self.vm.interrupts.vectors[usize::from(i.type_)] = Some(target);
            }
            _ => {
                // RETI: back to the interrupted program; outside a handler it is an error.
                let saved = self
                    .vm
                    .interrupts
                    .saved
                    .take()
                    .ok_or(ProgramError::StackUnderflow)?;
                *next_pc = saved.pc;
                self.vm.acc = saved.acc;
                self.vm.x = saved.x;
                self.vm.compared = saved.compared;
                self.vm.timeout_flag = saved.timeout_flag;
                self.vm.wait = saved.wait;
            }
        }
        Ok(())
    }

    /// SGP of a bank-3 parameter at `t`: a timer whose period it is starts over.
    pub(super) fn configure_interrupt(&mut self, t: f64, number: u8, value: i32) {
        let timers: Vec<u8> = self
            .profile
            .interrupts
            .iter()
            .filter(|v| v.kind == InterruptKind::Timer && v.config == Some(number))
            .map(|v| v.number)
            .collect();
        for timer in timers {
            let ticks = &mut self.vm.interrupts.timers;
            ticks.retain(|&(n, _)| n != timer);
            if value > 0 {
                ticks.push((timer, t + f64::from(value) / 1000.0));
            }
        }
    }

    /// A timer's period in seconds, from its bank-3 parameter.
    fn period(&self, timer: u8) -> Option<f64> {
        let config = self
            .profile
            .interrupts
            .iter()
            .find(|v| v.number == timer)?
            .config?;
        let ms = self.params.get(Slot::Global(CONFIG_BANK, config));
        (ms > 0).then(|| f64::from(ms) / 1000.0)
    }

    /// A digital input set from outside: an input interrupt on the port raises when the edge
    /// is one its trigger (bank-3 parameter) asks for.
    pub(super) fn set_input(&mut self, port: u8, high: bool) -> Result<(), ConsoleError> {
        let before = self.io.read(port, 0).map(|v| v != 0).unwrap_or(high);
        self.io.set_input(port, high)?;
        if before == high {
            return Ok(());
        }
        let edge = if high { 1 } else { 2 };
        let raised: Vec<u8> = self
            .profile
            .interrupts
            .iter()
            .filter(|v| v.kind == InterruptKind::Input && v.port == port)
            .filter(|v| {
                v.config
                    .is_some_and(|c| self.params.get(Slot::Global(CONFIG_BANK, c)) & edge != 0)
            })
            .map(|v| v.number)
            .collect();
        for number in raised {
            self.raise(number);
        }
        Ok(())
    }

    /// Motor `motor` reached its target: its position interrupt raises.
    pub(super) fn arrived(&mut self, motor: u8) {
        let raised: Vec<u8> = self
            .profile
            .interrupts
            .iter()
            .filter(|v| v.kind == InterruptKind::PositionReached && v.motor == motor)
            .map(|v| v.number)
            .collect();
        for number in raised {
            self.raise(number);
        }
    }

    /// A limit switch stopped motor `motor` at `t`: the stop switch interrupt of the switch it
    /// stands on raises, if its trigger (bank-3 parameter) takes a rising edge (reaching the
    /// switch).
    pub(super) fn stopped_at_switch(&mut self, motor: u8, t: f64) {
        let axis = &self.axes[usize::from(motor)];
        let left = axis.switch_active(t, Switch::Left);
        let right = axis.switch_active(t, Switch::Right);
        let raised: Vec<u8> = self
            .profile
            .interrupts
            .iter()
            .filter(|v| v.motor == motor)
            .filter(|v| match v.kind {
                InterruptKind::StopLeft => left,
                InterruptKind::StopRight => right,
                _ => false,
            })
            .filter(|v| {
                v.config
                    .is_some_and(|c| self.params.get(Slot::Global(CONFIG_BANK, c)) & 1 != 0)
            })
            .map(|v| v.number)
            .collect();
        for number in raised {
            self.raise(number);
        }
    }

    /// Raises interrupt `number` (dropped unless it is enabled).
    pub(super) fn raise(&mut self, number: u8) {
        let n = usize::from(number);
        if self.vm.interrupts.enabled[n] {
            self.vm.interrupts.pending[n] = true;
        }
    }

    /// The timers that ticked by `t` raise their interrupts and tick on.
    pub(super) fn tick_timers(&mut self, t: f64) {
        for k in 0..self.vm.interrupts.timers.len() {
            let (timer, at) = self.vm.interrupts.timers[k];
            if at > t + 1e-9 {
                continue;
            }
            let Some(period) = self.period(timer) else {
                continue;
            };
            let mut next = at;
            while next <= t + 1e-9 {
                next += period;
            }
            self.vm.interrupts.timers[k].1 = next;
            self.raise(timer);
        }
    }

    /// Takes a pending interrupt, if one can be taken at `t`: the program's context is saved
    /// and it goes on at the vector. Whether it did.
    pub(super) fn take_interrupt(&mut self, t: f64) -> bool {
        let Some(number) = self.vm.interrupts.ready() else {
            return false;
        };
        let n = usize::from(number);
        self.vm.interrupts.pending[n] = false;
        let Some(vector) = self.vm.interrupts.vectors[n] else {
            return false;
        };
        self.vm.interrupts.saved = Some(Context {
            pc: self.vm.pc,
            acc: self.vm.acc,
            x: self.vm.x,
            compared: self.vm.compared,
            timeout_flag: self.vm.timeout_flag,
            wait: self.vm.wait.take(),
        });
        self.vm.pc = vector;
        self.vm.next_at = t;
        true
    }
}
