//! Inputs and outputs (SIO/GIO): digital inputs (GIO bank 0) and analog inputs (bank 1) that a
//! test or the console sets, outputs (SIO bank 2) that read back. The port lists and the ADC
//! range come from the profile.

use crate::dialect::tmcl::profile::SimConstants;
use crate::dialect::tmcl::protocol::Status;
use crate::sim::error::ConsoleError;

/// GIO/SIO bank numbers.
const DIGITAL: u8 = 0;
const ANALOG: u8 = 1;
const OUTPUTS: u8 = 2;

/// The I/O ports of one module.
#[derive(Debug, Clone)]
pub(crate) struct Io {
    digital: Vec<(u8, bool)>,
    analog: Vec<(u8, i32)>,
    outputs: Vec<(u8, bool)>,
    adc_max: i32,
}

fn find<T: Copy>(ports: &[(u8, T)], port: u8) -> Option<T> {
    ports.iter().find(|(p, _)| *p == port).map(|(_, v)| *v)
}

fn find_mut<T>(ports: &mut [(u8, T)], port: u8) -> Option<&mut T> {
    ports.iter_mut().find(|(p, _)| *p == port).map(|(_, v)| v)
}

/// Sets input `port` of `inputs` (of a `kind`), or says which inputs there are.
fn set_input<T>(
    inputs: &mut [(u8, T)],
    port: u8,
    value: T,
    kind: &'static str,
) -> Result<(), ConsoleError> {
    let ports = inputs.iter().map(|(p, _)| *p).collect();
    let input = find_mut(inputs, port).ok_or(ConsoleError::NoInput { kind, port, ports })?;
    *input = value;
    Ok(())
}

impl Io {
    /// All inputs low, analog inputs at 0, outputs off.
    pub(super) fn new(sim: &SimConstants) -> Io {
        Io {
            digital: sim.digital_inputs.iter().map(|&p| (p, false)).collect(),
            analog: sim.analog_inputs.iter().map(|&p| (p, 0)).collect(),
            outputs: sim.outputs.iter().map(|&p| (p, false)).collect(),
            adc_max: sim.adc_max,
        }
    }

    /// GIO: a digital input, an analog input or an output state. Unknown ports answer wrong
    /// type (the port is the type byte), unknown banks invalid value.
    pub(super) fn read(&self, port: u8, bank: u8) -> Result<i32, Status> {
        let value = match bank {
            DIGITAL => find(&self.digital, port).map(i32::from),
            ANALOG => find(&self.analog, port),
            OUTPUTS => find(&self.outputs, port).map(i32::from),
            _ => return Err(Status::InvalidValue),
        };
        value.ok_or(Status::WrongType)
    }

    /// SIO: sets an output (bank 2 only).
    pub(super) fn write(&mut self, port: u8, bank: u8, on: bool) -> Result<(), Status> {
        if bank != OUTPUTS {
            return Err(Status::InvalidValue);
        }
        *find_mut(&mut self.outputs, port).ok_or(Status::WrongType)? = on;
        Ok(())
    }

    /// Sets a digital input.
    pub(super) fn set_input(&mut self, port: u8, high: bool) -> Result<(), ConsoleError> {
        set_input(&mut self.digital, port, high, "digital")
    }

    /// Sets an analog input (0..adc_max).
    pub(super) fn set_analog(&mut self, port: u8, value: i32) -> Result<(), ConsoleError> {
        if !(0..=self.adc_max).contains(&value) {
            return Err(ConsoleError::OutOfRange {
                what: "analog value",
                value,
                max: self.adc_max,
            });
        }
        set_input(&mut self.analog, port, value, "analog")
    }

    /// An output's state.
    pub(super) fn output(&self, port: u8) -> Option<bool> {
        find(&self.outputs, port)
    }

    /// Switches every output off (power-up).
    pub(super) fn reset_outputs(&mut self) {
        for (_, on) in &mut self.outputs {
            *on = false;
        }
    }
}
