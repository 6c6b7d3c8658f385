//! The motor axis: velocity mode, positioning, stop, limit switches and reference search, on top
//! of the analytic plans of [`super::ramp`]. Time is seconds since power-up; positions here are
//! physical microsteps (where the switches are), and the position counter the host sees is the
//! physical position plus an offset that SAP 1 and reference search redefine.
//!
//! Choices the manual leaves open: a limit switch stops the motor at once, exactly at the switch
//! position; reference search brakes with the acceleration after hitting a switch, then finds the
//! switch edge at the reference switch speed and stops there, which becomes position 0.

use super::ramp::{Plan, State};

/// What the motor of a module is doing, for tests and the console.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MotorState {
    /// Position counter (AP 1).
    pub position: i32,
    /// Target position (AP 0).
    pub target: i32,
    /// Velocity in microsteps per second.
    pub velocity: f64,
    /// Target position reached (AP 8).
    pub target_reached: bool,
    /// Reference search in progress.
    pub searching: bool,
}

/// Where the virtual switches are, in physical microsteps (`None`: not connected).
///
/// The left limit switch is active at and left of its position, the right one at and right of
/// its position; the reference (home) switch is a cam, active at and right of its position.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Switches {
    /// Left limit switch (REF L).
    pub left: Option<i64>,
    /// Right limit switch (REF R).
    pub right: Option<i64>,
    /// Reference (home) switch.
    pub home: Option<i64>,
}

/// One of the three switches.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Switch {
    /// Left limit switch.
    Left,
    /// Right limit switch.
    Right,
    /// Reference (home) switch.
    Home,
}

impl Switches {
    /// The position of a switch.
    pub fn get(&self, which: Switch) -> Option<i64> {
        match which {
            Switch::Left => self.left,
            Switch::Right => self.right,
            Switch::Home => self.home,
        }
    }

    /// Moves (or disconnects) a switch.
    pub fn set(&mut self, which: Switch, position: Option<i64>) {
        match which {
            Switch::Left => self.left = position,
            Switch::Right => self.right = position,
            Switch::Home => self.home = position,
        }
    }
}

/// Which limit switches stop the motor (AP12/AP13 clear).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Limits {
    pub left: bool,
    pub right: bool,
}

/// Something that happened to the axis at an event time.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Happened {
    /// A positioning move reached its target.
    Arrived,
    /// A limit switch stopped the motor.
    LimitStop,
    /// Reference search went on to its next leg.
    SearchLeg,
    /// Reference search finished; position 0 is the switch edge.
    SearchDone,
}

/// One leg of a reference search: drive towards a switch level until it is reached.
#[derive(Debug, Clone, Copy)]
struct Leg {
    dir: f64,
    switch: Switch,
    fast: bool,
}

/// The highest search mode the simulator runs (AP193 1…4).
pub(super) const SEARCH_MODES: i64 = 4;

/// The legs of the reference search modes of AP193. Mode 4 (the TMC429 modules' "left switch,
/// from both sides") ends on the left switch like mode 1.
fn legs(mode: u8) -> &'static [Leg] {
    const fn leg(dir: f64, switch: Switch, fast: bool) -> Leg {
        Leg { dir, switch, fast }
    }
    const MODE1: [Leg; 2] = [leg(-1.0, Switch::Left, true), leg(1.0, Switch::Left, false)];
    const MODE2: [Leg; 3] = [
        leg(1.0, Switch::Right, true),
        leg(-1.0, Switch::Left, true),
        leg(1.0, Switch::Left, false),
    ];
    const MODE3: [Leg; 3] = [
        leg(1.0, Switch::Right, true),
        leg(-1.0, Switch::Home, true),
        leg(1.0, Switch::Home, false),
    ];
    match mode {
        2 => &MODE2,
        3 => &MODE3,
        _ => &MODE1,
    }
}

#[derive(Debug, Clone, Copy)]
struct Search {
    mode: u8,
    leg: usize,
    braking: bool,
    fast: f64,
    slow: f64,
    accel: f64,
    right_hit: Option<f64>,
}

#[derive(Debug, Clone, Copy)]
enum Mode {
    /// Ramping to (or turning at) a velocity; 0 means stopping or standing.
    Velocity { target: f64, accel: f64 },
    /// Positioning to a counter value.
    Position {
        target: i32,
        vmax: f64,
        accel: f64,
        arrived: bool,
    },
    /// Reference search.
    Search(Search),
}

/// The simulated motor.
#[derive(Debug, Clone)]
pub(crate) struct Axis {
    plan: Plan,
    mode: Mode,
    /// Events before this time have been handled.
    since: f64,
    offset: i64,
    /// Switch positions.
    pub switches: Switches,
    end_distance: i32,
}

const EPS: f64 = 1e-9;

impl Axis {
    /// A motor standing at 0.
    pub(super) fn new(switches: Switches) -> Axis {
        Axis {
            plan: Plan::hold(0.0, 0.0),
            mode: Mode::Velocity {
                target: 0.0,
                accel: 0.0,
            },
            since: 0.0,
            offset: 0,
            switches,
            end_distance: 0,
        }
    }

    /// Power-up at `t`: the motor stops where it is (the switches stay where they are) and the
    /// counter starts at 0.
    pub(super) fn power_up(&mut self, t: f64) {
        let x = self.state(t).x.round();
        self.replace(t, Plan::hold(t, x), stopped());
        self.offset = -(x as i64);
        self.end_distance = 0;
    }

    /// Declares every event before `t` handled.
    pub(super) fn settle(&mut self, t: f64) {
        self.since = self.since.max(t);
    }

    /// Position, velocity and acceleration at `t`.
    pub(super) fn state(&self, t: f64) -> State {
        self.plan.at(t)
    }

    /// The position counter (AP1) at `t`, wrapping like the 32-bit register.
    pub(super) fn counter(&self, t: f64) -> i32 {
        (self.state(t).x.round() as i64).wrapping_add(self.offset) as i32
    }

    fn physical(&self, counter: i32, t: f64) -> f64 {
        let here = self.state(t).x.round();
        here + f64::from(counter.wrapping_sub(self.counter(t)))
    }

    /// Redefines the position counter without moving (SAP 1).
    pub(super) fn set_counter(&mut self, t: f64, value: i32) {
        let here = self.state(t).x.round() as i64;
        self.offset = i64::from(value) - here;
        if let Mode::Position {
            target,
            vmax,
            accel,
            arrived: false,
        } = self.mode
        {
            self.move_to(t, target, vmax, accel);
        }
    }

    fn replace(&mut self, t: f64, plan: Plan, mode: Mode) {
        self.plan = plan;
        self.mode = mode;
        self.since = t;
    }

    /// Velocity mode: ramp to `v` pps with `accel` (ROR, ROL, MST, SAP 2).
    pub(super) fn rotate(&mut self, t: f64, v: f64, accel: f64) {
        let now = self.state(t);
        let plan = Plan::velocity(t, now.x, now.v, v, accel);
        self.replace(t, plan, Mode::Velocity { target: v, accel });
    }

    /// Sets the actual velocity at once (SAP 3), keeping the current goal.
    pub(super) fn set_velocity(&mut self, t: f64, v: f64) {
        let x = self.state(t).x;
        self.plan = Plan::velocity(t, x, v, v, 0.0);
        self.since = t;
        self.replan(t);
    }

    /// Positioning to counter value `target` (MVP, SAP 0), the shorter way round.
    pub(super) fn move_to(&mut self, t: f64, target: i32, vmax: f64, accel: f64) {
        let now = self.state(t);
        let goal = self.physical(target, t);
        let plan = Plan::position(t, now.x, now.v, goal, vmax, accel);
        let mode = Mode::Position {
            target,
            vmax,
            accel,
            arrived: false,
        };
        self.replace(t, plan, mode);
    }

    /// Plans the current goal again from the present state (after the counter, speed or
    /// acceleration changed).
    pub(super) fn replan(&mut self, t: f64) {
        match self.mode {
            Mode::Velocity { target, accel } => self.rotate(t, target, accel),
            Mode::Position {
                target,
                vmax,
                accel,
                arrived: false,
            } => self.move_to(t, target, vmax, accel),
            Mode::Position { .. } | Mode::Search(_) => {}
        }
    }

    /// Changes maximum speed and acceleration of a move in progress (SAP 4, SAP 5).
    pub(super) fn retune(&mut self, t: f64, vmax: f64, accel: f64) {
        match &mut self.mode {
            Mode::Position {
                vmax: v,
                accel: a,
                arrived: false,
                ..
            } => {
                (*v, *a) = (vmax, accel);
                self.replan(t);
            }
            Mode::Velocity { accel: a, .. } => {
                *a = accel;
                self.replan(t);
            }
            _ => {}
        }
    }

    /// Scales the speed a rotation turns at by `factor` (the unit of the speed it was given in
    /// changed); a move, a search and a motor stopping are left alone.
    pub(super) fn rescale_rotation(&mut self, t: f64, factor: f64) {
        if let Mode::Velocity { target, accel } = self.mode {
            if target != 0.0 && factor != 1.0 {
                self.rotate(t, target * factor, accel);
            }
        }
    }

    /// Starts a reference search (RFS START) in `mode` (AP193) with the search and switch
    /// speeds.
    pub(super) fn start_search(&mut self, t: f64, mode: u8, fast: f64, slow: f64, accel: f64) {
        let search = Search {
            mode,
            leg: 0,
            braking: false,
            fast,
            slow,
            accel,
            right_hit: None,
        };
        self.start_leg(t, search);
    }

    fn start_leg(&mut self, t: f64, search: Search) {
        let leg = legs(search.mode)[search.leg];
        let speed = if leg.fast { search.fast } else { search.slow };
        let now = self.state(t);
        let plan = Plan::velocity(t, now.x, now.v, leg.dir * speed, search.accel);
        self.replace(t, plan, Mode::Search(search));
    }

    /// Aborts a reference search (RFS STOP): the motor brakes.
    pub(super) fn stop_search(&mut self, t: f64) {
        if let Mode::Search(search) = self.mode {
            self.rotate(t, 0.0, search.accel);
        }
    }

    /// RFS STATUS: 0 when no search runs, else the number of the leg in progress.
    pub(super) fn search_status(&self) -> i32 {
        match self.mode {
            Mode::Search(s) => s.leg as i32 + 1,
            _ => 0,
        }
    }

    /// Distance between the switches found by the last mode 2 or 3 search (AP196).
    pub(super) fn end_distance(&self) -> i32 {
        self.end_distance
    }

    /// Whether a switch is active at `t`: judged on the whole microstep the counter shows, so a
    /// host that reads the switch's position from the counter also reads the switch active.
    pub(super) fn switch_active(&self, t: f64, which: Switch) -> bool {
        let x = self.state(t).x.round();
        match (which, self.switches.get(which)) {
            (_, None) => false,
            (Switch::Left, Some(p)) => x <= p as f64,
            (Switch::Right | Switch::Home, Some(p)) => x >= p as f64,
        }
    }

    /// Whether a positioning move is on its way.
    pub(super) fn is_positioning(&self) -> bool {
        matches!(self.mode, Mode::Position { arrived: false, .. })
    }

    /// When the move in progress arrives, if nothing interferes.
    pub(super) fn arrival(&self) -> Option<f64> {
        self.is_positioning().then(|| self.plan.settles_at())
    }

    fn level(&self, switch: Switch) -> Option<f64> {
        self.switches.get(switch).map(|p| p as f64)
    }

    /// The next event (switch reached, move arrived, search leg over) at or after the last one.
    pub(super) fn next_event(&self, limits: Limits) -> Option<f64> {
        self.next(limits).map(|(t, _)| t)
    }

    fn next(&self, limits: Limits) -> Option<(f64, Event)> {
        let from = self.since;
        match self.mode {
            Mode::Search(s) if s.braking => Some((self.plan.settles_at().max(from), Event::Braked)),
            Mode::Search(s) => {
                let leg = legs(s.mode)[s.leg];
                let level = self.level(leg.switch)?;
                let t = self.plan.reaches(from, level, leg.dir)?;
                Some((t, Event::LegDone(level)))
            }
            Mode::Velocity { .. } | Mode::Position { .. } => {
                let left = limits
                    .left
                    .then(|| self.level(Switch::Left))
                    .flatten()
                    .and_then(|l| Some((self.plan.reaches(from, l, -1.0)?, Event::Limit(l))));
                let right = limits
                    .right
                    .then(|| self.level(Switch::Right))
                    .flatten()
                    .and_then(|r| Some((self.plan.reaches(from, r, 1.0)?, Event::Limit(r))));
                let arrive = self.arrival().map(|t| (t.max(from), Event::Arrived));
                [left, right, arrive]
                    .into_iter()
                    .flatten()
                    .min_by(|a, b| a.0.total_cmp(&b.0))
            }
        }
    }

    /// Handles the next event if it is due by `t`.
    pub(super) fn handle_event(&mut self, t: f64, limits: Limits) -> Option<Happened> {
        let (at, event) = self.next(limits)?;
        if at > t + EPS {
            return None;
        }
        self.since = at;
        Some(match event {
            Event::Arrived => {
                if let Mode::Position { arrived, .. } = &mut self.mode {
                    *arrived = true;
                }
                Happened::Arrived
            }
            Event::Limit(level) => {
                // Stopped on crossing the switch, or at once when already beyond it.
                let x = self.state(at).x;
                let x = if (x - level).abs() < 0.5 { level } else { x };
                self.replace(at, Plan::hold(at, x), stopped());
                Happened::LimitStop
            }
            Event::Braked => {
                let Mode::Search(mut s) = self.mode else {
                    unreachable!("braking only happens in a search")
                };
                s.braking = false;
                s.leg += 1;
                self.start_leg(at, s);
                Happened::SearchLeg
            }
            Event::LegDone(level) => self.leg_done(at, level),
        })
    }

    fn leg_done(&mut self, at: f64, level: f64) -> Happened {
        let Mode::Search(mut s) = self.mode else {
            unreachable!("legs only end in a search")
        };
        let leg = legs(s.mode)[s.leg];
        if leg.switch == Switch::Right {
            s.right_hit = Some(level);
        }
        if s.leg + 1 < legs(s.mode).len() {
            s.braking = true;
            let now = self.state(at);
            let plan = Plan::velocity(at, now.x, now.v, 0.0, s.accel);
            self.replace(at, plan, Mode::Search(s));
            return Happened::SearchLeg;
        }
        // The edge: stop here, this is position 0.
        self.replace(at, Plan::hold(at, level), stopped());
        self.offset = -(level as i64);
        if let Some(right) = s.right_hit {
            self.end_distance = (right - level).abs().min(f64::from(i32::MAX)) as i32;
        }
        Happened::SearchDone
    }
}

fn stopped() -> Mode {
    Mode::Velocity {
        target: 0.0,
        accel: 0.0,
    }
}

#[derive(Debug, Clone, Copy)]
enum Event {
    Arrived,
    Limit(f64),
    Braked,
    LegDone(f64),
}

/// The encoder reading (AP41) of a motor at counter `counter`: counts of the simulated encoder
/// scaled by the encoder constant AP42 (binary /65536, or decimal when AP43 bit 13 is set).
pub(crate) fn encoder_position(
    counter: i32,
    constant: i32,
    mode: i32,
    usteps_per_count: f64,
) -> i32 {
    let factor = if mode & (1 << 13) != 0 {
        f64::from(constant >> 16) + f64::from(constant & 0xFFFF) / 10_000.0
    } else {
        f64::from(constant) / 65_536.0
    };
    let counts = f64::from(counter) / usteps_per_count;
    (counts * factor).round() as i64 as i32
}

#[cfg(test)]
mod tests;
