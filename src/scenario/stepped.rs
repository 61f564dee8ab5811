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
//! let mut c = SteppedController::new(&scenario, Ur5)?;
//! let (q, qd) = (c.start(), SVector::zeros());
//! c.reset(0.0, &q, &qd);
//! let tau = c.step(0.0, &q, &qd, &SVector::zeros()); // N m, within the effort limits
//! println!("{:?}", c.report().mode);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use nalgebra::Vector3;

use super::desired_force::DesiredForce;
use super::error::ScenarioError;
use super::planned::PlannedReference;
use super::prepare::{prepare_for, PreparedRun};
use super::robot::ScenarioRobot;
use super::spec::Scenario;
use crate::control::safety::TripCause;
use crate::control::{Controller, ControllerInput, StepReport};
use crate::model::{JointVector, Wrench};
use crate::target::Setpoint;

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

/// A scenario's controller with its reference, for any loop (see the
/// [module documentation](self)).
pub struct SteppedController<const N: usize> {
    name: &'static str,
    controller: Box<dyn Controller<N>>,
    reference: Box<dyn PlannedReference<N>>,
    force: Option<DesiredForce>,
    period_s: f64,
    effort_limits: JointVector<N>,
    start: JointVector<N>,
    t0: f64,
    last: StepOutcome<N>,
}

impl<const N: usize> SteppedController<N> {
    /// The controller of `scenario` on `robot`, built by the same stages as a run of it
    /// ([`prepare_for`]); the plant, its surfaces and its faults are left out.
    ///
    /// # Errors
    ///
    /// [`ScenarioError`] naming the key at fault, as [`prepare_for`].
    pub fn new<R: ScenarioRobot<N>>(scenario: &Scenario, robot: R) -> Result<Self, ScenarioError> {
        Ok(Self::from_prepared(prepare_for(scenario, robot)?))
    }

    /// The controller of a prepared run (its plant left out).
    #[must_use]
    pub fn from_prepared<R: ScenarioRobot<N>>(run: PreparedRun<N, R>) -> Self {
        let effort_limits = run.config.effort_limits;
        Self {
            name: run.controller.name(),
            controller: run.controller,
            start: run.config.q0,
            reference: run.reference,
            force: run.force,
            period_s: run.config.control_dt,
            effort_limits,
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
        }
    }

    /// The controller's name (`task-space-hybrid-pi-ff-vd`, ...).
    #[must_use]
    pub fn name(&self) -> &'static str {
        self.name
    }

    /// The control period the gains were designed for and the controller expects, s.
    #[must_use]
    pub fn period_s(&self) -> f64 {
        self.period_s
    }

    /// The joints the scenario's run starts from (its `q0`, or the reference's first point
    /// with `start_on_reference`), rad or m.
    #[must_use]
    pub fn start(&self) -> JointVector<N> {
        self.start
    }

    /// The effort limits the command is clipped to, N m or N.
    #[must_use]
    pub fn effort_limits(&self) -> &JointVector<N> {
        &self.effort_limits
    }

    /// A new run from the arm's state `q`, `qd` at the loop's time `t0`: the scenario's
    /// time is `t - t0` from now on, and the controller's integrators, filters, sensor tare
    /// and supervisor start afresh.
    pub fn reset(&mut self, t0: f64, q: &JointVector<N>, qd: &JointVector<N>) {
        let _ = (q, qd);
        self.t0 = t0;
        self.controller.reset();
        self.last.t = t0;
    }

    /// One control period at the loop's time `t` with the arm at `q`, `qd` and the tool
    /// exerting `wrench` on the environment (base frame, N and N m): the joint torques to
    /// hold until the next step, clipped to the effort limits. Never allocates.
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
        let command = self.controller.step(&input, self.period_s);
        let limits = &self.effort_limits;
        let tau = JointVector::<N>::from_fn(|i, _| command[i].clamp(-limits[i], limits[i]));
        let detail = self.controller.report();
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
        tau
    }

    /// What the last step did.
    #[must_use]
    pub fn report(&self) -> &StepOutcome<N> {
        &self.last
    }

    /// The setpoint at the scenario's time `s`: the planned reference with the desired force.
    fn setpoint(&mut self, s: f64) -> Setpoint<N> {
        let mut setpoint = self.reference.at(s);
        setpoint.wrench = self
            .force
            .as_ref()
            .map_or_else(Wrench::zeros, |f| f.wrench(s, &setpoint.cartesian.position));
        setpoint
    }
}
