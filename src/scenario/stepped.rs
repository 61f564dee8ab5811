//! A scenario's controller alone, for any loop to step: the position law, the force law,
//! the selection and contact switching, the sensor model, tool compensation and the
//! supervisor, with the scenario's reference and desired force, but no plant. The simulator
//! is one loop that steps it; a Python loop over MuJoCo is another; a robot's driver at its
//! period would be a third.
//!
//! ```text
//! reset(t0, q, qd)                     the scenario's time starts at t0
//! step(t, q, qd, wrench) -> tau        setpoint = reference(t - t0); tau = C(setpoint, q, qd, sensor(wrench))
//! report() -> StepOutcome              mode, force error, trips, the command before saturation
//! ```
//!
//! `wrench` is the true wrench the tool exerts on the environment (base frame, N and N m):
//! the scenario's sensor model (bias, noise, filter, a tool's weight) and its sensor faults
//! act on it inside, as in the simulator. `step` never allocates.
//!
//! ```no_run
//! use armdyn::model::Ur5;
//! use armdyn::scenario::{Scenario, SteppedController};
//! use armdyn::nalgebra::SVector;
//! let scenario = Scenario::load("scenarios/ur5-press-table.toml".as_ref())?;
//! let mut c = SteppedController::new(&scenario, Ur5)?; // SteppedController<6, Ur5>
//! let (q, qd) = (c.start(), SVector::zeros());
//! c.reset(0.0, &q, &qd);
//! let tau = c.step(0.0, &q, &qd, &SVector::zeros()); // N m, within the effort limits
//! println!("{:?}", c.report().mode);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use nalgebra::Vector3;

use super::error::ScenarioError;
use super::outcome::Recorded;
use super::prepare::{prepare_for, PreparedRun};
use super::robot::ScenarioRobot;
use super::runner::RunOutput;
use super::spec::Scenario;
use crate::control::safety::TripCause;
use crate::control::{ControllerInput, StepReport};
use crate::model::{JointVector, Wrench};
use crate::sim::{RunStats, Sample};
use crate::target::{orientation, Setpoint};

/// What the controller did at a step.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    /// Position control (before the force switch, or a position-only scenario).
    Position,
    /// Force control along the contact normal, position in the other task directions.
    Force,
    /// The supervisor has tripped and holds its reaction (hold, retract or compliant).
    Tripped,
}

impl Mode {
    /// The mode's name, as the CSV and Python reports write it.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Position => "position",
            Self::Force => "force",
            Self::Tripped => "tripped",
        }
    }
}

/// The report of one step of a [`SteppedController`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StepOutcome<const N: usize> {
    /// The loop's time of the step, s.
    pub t: f64,
    /// Position, force or tripped.
    pub mode: Mode,
    /// The desired force of the tool on the environment, base frame, N.
    pub force_ref: Vector3<f64>,
    /// The force the controller measured (the sensor's reading of `wrench`), base frame, N.
    pub force_measured: Vector3<f64>,
    /// `|f_ref| - f_measured . f_ref / |f_ref|`, N: how much force is missing along the
    /// desired one (negative: too much); 0 without a desired force.
    pub force_error_n: f64,
    /// The supervisor's trips so far (0 without a supervisor).
    pub trips: usize,
    /// The cause of the first trip, if any.
    pub first_trip: Option<TripCause>,
    /// The controller's torque before saturation, N m or N.
    pub command: JointVector<N>,
    /// The joints whose command was clipped to its effort limit.
    pub saturated: [bool; N],
    /// Everything the controller's wrappers reported ([`StepReport`]).
    pub detail: StepReport<N>,
}

/// A scenario's controller with its reference, for robot `R`, for any loop: `reset(t0, q,
/// qd)`, then `step(t, q, qd, wrench) -> tau` at [`Self::period_s`] and [`Self::report`]
/// (the simulator's torques, bit for bit, for the same samples).
pub struct SteppedController<const N: usize, R: ScenarioRobot<N>> {
    run: PreparedRun<N, R>,
    t0: f64,
    last: StepOutcome<N>,
    /// The steps recorded for the run's metrics and files ([`Self::record`]).
    recorded: Option<RunOutput<N>>,
}

impl<const N: usize, R: ScenarioRobot<N>> SteppedController<N, R> {
    /// The controller of `scenario` on `robot`, built by the same stages as a run of it
    /// ([`prepare_for`]); the plant, its surfaces and its faults are not stepped.
    ///
    /// # Errors
    ///
    /// [`ScenarioError`] naming the key at fault, as [`prepare_for`].
    pub fn new(scenario: &Scenario, robot: R) -> Result<Self, ScenarioError> {
        Ok(Self::from_prepared(prepare_for(scenario, robot)?))
    }

    /// The controller of a prepared run (its plant is not stepped).
    #[must_use]
    pub fn from_prepared(run: PreparedRun<N, R>) -> Self {
        Self {
            run,
            t0: 0.0,
            last: StepOutcome {
                t: 0.0,
                mode: Mode::Position,
                force_ref: Vector3::zeros(),
                force_measured: Vector3::zeros(),
                force_error_n: 0.0,
                trips: 0,
                first_trip: None,
                command: JointVector::<N>::zeros(),
                saturated: [false; N],
                detail: StepReport::default(),
            },
            recorded: None,
        }
    }

    /// The controller's name (`task-space-hybrid-pi-ff-vd`, ...).
    #[must_use]
    pub fn name(&self) -> &'static str {
        self.run.controller.name()
    }

    /// The control period the gains were designed for and the controller expects, s.
    #[must_use]
    pub fn period_s(&self) -> f64 {
        self.run.config.control_dt
    }

    /// The joints the scenario's run starts from (its `q0`, or the reference's first point
    /// with `start_on_reference`), rad or m.
    #[must_use]
    pub fn start(&self) -> JointVector<N> {
        self.run.config.q0
    }

    /// The effort limits the command is clipped to, N m or N.
    #[must_use]
    pub fn effort_limits(&self) -> &JointVector<N> {
        &self.run.config.effort_limits
    }

    /// The prepared run the controller was taken from: its plant's settings, surfaces and
    /// faults, for a loop that simulates them itself.
    #[must_use]
    pub fn prepared(&self) -> &PreparedRun<N, R> {
        &self.run
    }

    /// Keeps every step from now on as a sample of the run (the tool's pose by the robot's
    /// forward kinematics; this allocates), for [`Self::outcome`].
    pub fn record(&mut self) {
        self.recorded = Some(RunOutput {
            samples: Vec::new(),
            stats: RunStats {
                samples: 0,
                first_limit_violation: [None; N],
                saturated_samples: [0; N],
                end_stop_samples: [0; N],
            },
        });
    }

    /// A new run from the arm's state `q`, `qd` at the loop's time `t0`: the scenario's
    /// time is `t - t0` from now on, and the controller's integrators, filters, sensor tare
    /// and supervisor start afresh (recorded steps are dropped).
    pub fn reset(&mut self, t0: f64, q: &JointVector<N>, qd: &JointVector<N>) {
        let _ = (q, qd);
        self.t0 = t0;
        self.run.controller.reset();
        self.last.t = t0;
        if self.recorded.is_some() {
            self.record();
        }
    }

    /// One control period at the loop's time `t` with the arm at `q`, `qd` and the tool
    /// exerting `wrench` on the environment (base frame, N and N m): the joint torques to
    /// hold until the next step, clipped to the effort limits. Never allocates (unless
    /// recording).
    pub fn step(
        &mut self,
        t: f64,
        q: &JointVector<N>,
        qd: &JointVector<N>,
        wrench: &Wrench,
    ) -> JointVector<N> {
        let s = t - self.t0;
        let setpoint = self.setpoint(s);
        let input = ControllerInput {
            t: s,
            q,
            qd,
            target: &setpoint.joint,
            cartesian: &setpoint.cartesian,
            wrench,
            wrench_ref: &setpoint.wrench,
            wrench_age_s: 0.0,
        };
        let command = self.run.controller.step(&input, self.run.config.control_dt);
        let limits = &self.run.config.effort_limits;
        let tau = JointVector::<N>::from_fn(|i, _| command[i].clamp(-limits[i], limits[i]));
        let detail = self.run.controller.report();
        let measured = detail.measured_wrench.unwrap_or(*wrench);
        let force_ref: Vector3<f64> = setpoint.wrench.fixed_rows::<3>(0).into_owned();
        let force_measured: Vector3<f64> = measured.fixed_rows::<3>(0).into_owned();
        let force_error_n = match force_ref.try_normalize(1e-12) {
            Some(u) => force_ref.norm() - force_measured.dot(&u),
            None => 0.0,
        };
        let (trips, first_trip) = detail.safety.map_or((0, None), |r| {
            (r.trips.len(), r.trips.iter().next().map(|t| t.cause))
        });
        let mode = if trips > 0 {
            Mode::Tripped
        } else if detail.force_controlled {
            Mode::Force
        } else {
            Mode::Position
        };
        self.last = StepOutcome {
            t,
            mode,
            force_ref,
            force_measured,
            force_error_n,
            trips,
            first_trip,
            command,
            saturated: core::array::from_fn(|i| tau[i] != command[i]),
            detail,
        };
        if self.recorded.is_some() {
            self.keep(s, q, qd, &tau, setpoint, wrench, measured);
        }
        tau
    }

    /// What the last step did.
    #[must_use]
    pub fn report(&self) -> &StepOutcome<N> {
        &self.last
    }

    /// The metrics of the steps recorded since [`Self::record`] (or the last reset), as a
    /// simulated run of the scenario has them, with the samples: what
    /// [`write_outputs_for`](super::write_outputs_for) writes as `armdyn run scenario` does.
    /// `None` if nothing was recorded.
    #[must_use]
    pub fn outcome(self, scenario: &Scenario) -> Option<Recorded<N>> {
        let out = self.recorded?;
        if out.samples.is_empty() {
            return None;
        }
        Some(self.run.outcome(scenario, out))
    }

    /// Records a step as a sample.
    #[allow(clippy::too_many_arguments)]
    fn keep(
        &mut self,
        s: f64,
        q: &JointVector<N>,
        qd: &JointVector<N>,
        tau: &JointVector<N>,
        setpoint: Setpoint<N>,
        wrench: &Wrench,
        measured: Wrench,
    ) {
        let pose = self.run.robot.end_effector_pose(q);
        let (lower, upper) = (self.run.robot.lower_limits(), self.run.robot.upper_limits());
        let Some(out) = self.recorded.as_mut() else {
            return;
        };
        let stats = &mut out.stats;
        stats.samples += 1;
        for i in 0..N {
            if self.last.saturated[i] {
                stats.saturated_samples[i] += 1;
            }
            if stats.first_limit_violation[i].is_none() && !(lower[i] <= q[i] && q[i] <= upper[i]) {
                stats.first_limit_violation[i] = Some(s);
            }
            if self.run.config.end_stops.is_some_and(|e| e.engaged(q, i)) {
                stats.end_stop_samples[i] += 1;
            }
        }
        out.samples.push(Sample {
            t: s,
            q: *q,
            qd: *qd,
            tau_command: self.last.command,
            tau: *tau,
            setpoint,
            position: Vector3::new(pose[(0, 3)], pose[(1, 3)], pose[(2, 3)]),
            orientation: orientation::of_pose(&pose),
            wrench: *wrench,
            measured_wrench: measured,
            force_controlled: self.last.detail.force_controlled,
        });
    }

    /// The setpoint at the scenario's time `s`: the planned reference with the desired force.
    fn setpoint(&mut self, s: f64) -> Setpoint<N> {
        let mut setpoint = self.run.reference.at(s);
        setpoint.wrench = self
            .run
            .force
            .as_ref()
            .map_or_else(Wrench::zeros, |f| f.wrench(s, &setpoint.cartesian.position));
        setpoint
    }
}
