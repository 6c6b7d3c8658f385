//! A module driven by time: motor events (arrivals, switches, searches) and the program runner's
//! steps handled in time order, and the second replies of 138 they make due.

use super::machine::Machine;
use super::motion::{Happened, Limits};

impl Machine {
    fn limits(&self, motor: u8) -> Limits {
        Limits {
            right: self.role(motor, self.roles.right_limit_disable) == 0,
            left: self.role(motor, self.roles.left_limit_disable) == 0,
        }
    }

    /// The motor whose next event comes first, and when.
    fn next_axis_event(&self) -> Option<(u8, f64)> {
        (0..self.axes.len() as u8)
            .filter_map(|m| Some((m, self.axes[m as usize].next_event(self.limits(m))?)))
            .min_by(|a, b| a.1.total_cmp(&b.1))
    }

    /// Runs motor events and the program up to `t`, in time order.
    pub(super) fn advance(&mut self, t: f64) {
        loop {
            let axis_next = self.next_axis_event();
            let vm_next = self.program_due();
            let next = match (axis_next.map(|(_, a)| a), vm_next) {
                (Some(a), Some(v)) => a.min(v),
                (a, v) => match a.or(v) {
                    Some(n) => n,
                    None => break,
                },
            };
            if next > t + 1e-9 {
                break;
            }
            let at = next.max(self.t);
            match axis_next {
                Some((motor, a)) if a <= next => {
                    let limits = self.limits(motor);
                    if let Some(happened) = self.axes[motor as usize].handle_event(at, limits) {
                        self.on_axis(motor, at, happened);
                    }
                }
                _ => {
                    self.t = at;
                    self.run_program(at);
                }
            }
            self.t = self.t.max(at);
        }
        self.t = self.t.max(t);
        // Everything up to now is handled: a switch or limit setting changed from now on must
        // not act in the past.
        for axis in &mut self.axes {
            axis.settle(self.t);
        }
    }

    fn on_axis(&mut self, motor: u8, at: f64, happened: Happened) {
        match happened {
            Happened::Arrived => {
                self.arrived(motor);
                let Some(request) = self.event else { return };
                let waiting = self.event_motors(request.mask);
                let others_moving = waiting
                    .into_iter()
                    .filter(|&m| m != motor)
                    .any(|m| self.axes[m as usize].is_positioning());
                if request.mask & (1 << motor) != 0 && !others_moving {
                    self.due_events.push((at, request.mask));
                    if !request.every_move {
                        self.event = None;
                    }
                }
            }
            Happened::SearchDone => self.set_role(motor, self.roles.target_position, 0),
            Happened::LimitStop => self.stopped_at_switch(motor, at),
            Happened::SearchLeg => {}
        }
    }

    /// The motors of a 138 mask that this module has.
    fn event_motors(&self, mask: i32) -> Vec<u8> {
        (0..self.axes.len() as u8)
            .filter(|m| mask & (1 << m) != 0)
            .collect()
    }

    /// When output (a 138 second reply) may next be due, as seconds.
    pub(super) fn next_output(&self) -> Option<f64> {
        let request = self.event?;
        let arrival = self
            .event_motors(request.mask)
            .into_iter()
            .filter_map(|m| self.axes[m as usize].arrival())
            .min_by(f64::total_cmp);
        match (arrival, self.program_due()) {
            (Some(a), Some(v)) => Some(a.min(v)),
            (a, v) => a.or(v),
        }
    }
}
