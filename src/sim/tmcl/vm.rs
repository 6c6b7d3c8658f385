//! The stand-alone program runner's state: application status (135, GP 128), program counter
//! (GP 130), accumulator and X register. Executing programs is not simulated yet: run and step
//! answer "command not available".

use crate::protocol::tmcl::Status;

use super::machine::Machine;
use super::program::Program;

/// Application status as 135 and GP 128 report it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum AppStatus {
    Stop = 0,
    Reset = 3,
}

/// Program runner state.
#[derive(Debug, Clone)]
pub(crate) struct Vm {
    /// The accumulator (AAP, AGP, ACO read it).
    pub acc: i32,
    status: AppStatus,
    pc: i32,
}

impl Vm {
    /// Stopped at address 0.
    pub fn new() -> Vm {
        Vm {
            acc: 0,
            status: AppStatus::Stop,
            pc: 0,
        }
    }

    /// 129 type 0.
    pub fn resume(&mut self, _t: f64, _program: &Program) -> Result<(), Status> {
        Err(Status::NotAvailable)
    }

    /// 129 type 1.
    pub fn run_from(&mut self, _t: f64, _program: &Program, _address: i32) -> Result<(), Status> {
        Err(Status::NotAvailable)
    }

    /// Auto-start (GP 77).
    pub fn start(&mut self, _address: i32) {}

    /// 130.
    pub fn step(&mut self, _t: f64, _program: &Program) -> Result<(), Status> {
        Err(Status::NotAvailable)
    }

    /// 128.
    pub fn stop(&mut self) {
        self.status = AppStatus::Stop;
    }

    /// 131: program counter to 0, stopped.
    pub fn reset(&mut self) {
        *self = Vm::new();
        self.status = AppStatus::Reset;
    }

    /// 135 / GP 128.
    pub fn status_code(&self) -> i32 {
        self.status as i32
    }

    /// 135 type 1: the last program error (0 none).
    pub fn error_code(&self) -> i32 {
        0
    }

    /// GP 130.
    pub fn pc(&self) -> i32 {
        self.pc
    }

    /// When the runner next has something to do.
    pub fn next_time(&self) -> Option<f64> {
        None
    }
}

impl Machine {
    /// Runs the program's next instruction at `t`.
    pub(crate) fn run_program(&mut self, _t: f64) {}
}
