//! Closed-loop simulation: fixed-step RK4 plant integration with the controller sampled at
//! its own period and its torque held in between (zero-order hold), actuator saturation,
//! contact through `J^T f_ext`, joint-limit reporting and non-finite detection.
//!
//! ```text
//! every control period:  measure (q, qd, f_ext) -> reference -> controller -> saturate -> tau
//! every plant step:      RK4 on qdd = M^-1 (tau - c - g - J^T f_ext(q, qd))     (eq. 3.70, erratum 3)
//! ```
//!
//! [`simulate`] never allocates; what happens to each sample is up to the caller's observer.

// `SimError` carries a copy of the state (136 bytes) so that a failure names it; without
// an allocator it cannot be boxed, so the large `Err` is deliberate.
#![allow(clippy::result_large_err)]

pub mod end_stops;
pub mod faults;
pub mod friction;
#[cfg(feature = "std")]
pub mod linearize;
pub mod open_loop;
pub mod rk4;
mod schedule;
mod steps;
#[cfg(feature = "std")]
pub mod torque_history;

pub use end_stops::EndStops;
pub use friction::JointFriction;

use crate::contact::Environment;
use crate::control::{Controller, ControllerInput};
use crate::model::{forward_dynamics, JointVector, ModelError, RobotModel, Wrench};
use crate::target::orientation;
pub use crate::target::Setpoint;
use nalgebra::{UnitQuaternion, Vector3};

/// Timing, initial state and actuator limits of a run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SimConfig<const N: usize> {
    /// Length of the run, s.
    pub duration: f64,
    /// RK4 step of the plant, s (default 1 ms).
    pub plant_dt: f64,
    /// Controller sample period, s, a whole multiple of `plant_dt` (default 1 ms).
    pub control_dt: f64,
    /// Initial joint positions, rad or m (default: the home configuration q = 0, as the
    /// thesis's Simulink integrators start).
    pub q0: JointVector<N>,
    /// Initial joint velocities.
    pub qd0: JointVector<N>,
    /// Actuator limits, N m or N per joint: `|tau_i|` is clamped to them.
    pub effort_limits: JointVector<N>,
    /// Joint end stops in the plant (`None`: none, as the thesis's model).
    pub end_stops: Option<EndStops<N>>,
    /// Joint friction in the plant (`None`: none, as the thesis's model).
    pub friction: Option<JointFriction<N>>,
    /// Faults of the actuators and of the control timing (none by default).
    pub faults: faults::PlantFaults,
}

impl<const N: usize> SimConfig<N> {
    /// A run of `robot`: 10 s, 1 ms plant and controller steps, start at q = 0 at rest, the
    /// robot's effort limits; no end stops, joint friction or faults (the thesis trials'
    /// settings, which a scenario overrides).
    #[must_use]
    pub fn new<R: RobotModel<N>>(robot: &R) -> Self {
        Self {
            duration: 10.0,
            plant_dt: 1e-3,
            control_dt: 1e-3,
            q0: JointVector::zeros(),
            qd0: JointVector::zeros(),
            effort_limits: robot.effort_limits(),
            end_stops: None,
            friction: None,
            faults: faults::PlantFaults::default(),
        }
    }
}

/// Why a run stopped or could not start.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum SimError {
    /// A timing or limit parameter is unusable.
    #[error("simulation settings: {0}")]
    Config(&'static str),
    /// The state became NaN or infinite (during the integration step starting at `t`).
    #[error("non-finite state at t = {t:.6} s; state at the start of that step: {state}")]
    NonFinite {
        /// Start of the step in which the state stopped being finite, s.
        t: f64,
        /// Joint positions and velocities at the start of that step.
        state: StateSnapshot,
    },
    /// The model could not be evaluated (`M` not positive definite).
    #[error("model error at t = {t:.6} s: {error}")]
    Model {
        /// Time, s.
        t: f64,
        /// What the model said.
        error: ModelError,
    },
}

/// A copy of the joint state for error messages (up to 8 joints, no allocation).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StateSnapshot {
    n: usize,
    q: [f64; 8],
    qd: [f64; 8],
}

impl StateSnapshot {
    /// Copies `q` and `qd` (the first 8 joints).
    #[must_use]
    pub fn new<const N: usize>(q: &JointVector<N>, qd: &JointVector<N>) -> Self {
        let mut s = Self {
            n: N.min(8),
            q: [0.0; 8],
            qd: [0.0; 8],
        };
        for i in 0..s.n {
            s.q[i] = q[i];
            s.qd[i] = qd[i];
        }
        s
    }

    /// Joint positions.
    #[must_use]
    pub fn q(&self) -> &[f64] {
        &self.q[..self.n]
    }

    /// Joint velocities.
    #[must_use]
    pub fn qd(&self) -> &[f64] {
        &self.qd[..self.n]
    }
}

impl core::fmt::Display for StateSnapshot {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(f, "q = {:?}, qd = {:?}", self.q(), self.qd())
    }
}

/// Maps a model failure inside a step to the simulator's error: a non-finite input means
/// the state blew up during the step.
pub(crate) fn step_error<const N: usize>(
    t: f64,
    q: &JointVector<N>,
    qd: &JointVector<N>,
    error: ModelError,
) -> SimError {
    match error {
        ModelError::NonFinite { .. } => SimError::NonFinite {
            t,
            state: StateSnapshot::new(q, qd),
        },
        error => SimError::Model { t, error },
    }
}

/// Where the setpoints come from: called once per control sample, in time order.
pub trait ReferenceSource<const N: usize> {
    /// The setpoint at time `t`, s.
    fn at(&mut self, t: f64) -> Setpoint<N>;
}

/// Everything recorded at one control sample.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sample<const N: usize> {
    /// Time, s.
    pub t: f64,
    /// Joint positions, rad or m.
    pub q: JointVector<N>,
    /// Joint velocities.
    pub qd: JointVector<N>,
    /// Controller output before saturation, N m or N.
    pub tau_command: JointVector<N>,
    /// Applied torque after saturation, held until the next sample.
    pub tau: JointVector<N>,
    /// The setpoint used.
    pub setpoint: Setpoint<N>,
    /// End-effector position, m, base frame.
    pub position: Vector3<f64>,
    /// End-effector orientation, base frame.
    pub orientation: UnitQuaternion<f64>,
    /// Wrench of the tool on the environment (the true one; a sensor model inside the
    /// controller may see it otherwise).
    pub wrench: Wrench,
    /// The force-sensor reading the controller received, base frame (the true wrench for a
    /// controller without a sensor model; [`StepReport::measured_wrench`](crate::control::StepReport)).
    pub measured_wrench: Wrench,
    /// Whether the controller was in force control at this sample
    /// ([`StepReport::force_controlled`](crate::control::StepReport)).
    pub force_controlled: bool,
}

impl<const N: usize> Sample<N> {
    /// The end-effector yaw about base z, rad in `(-pi, pi]`
    /// ([`crate::target::orientation::yaw`]).
    #[must_use]
    pub fn yaw(&self) -> f64 {
        orientation::yaw(&self.orientation)
    }
}

/// Summary of a finished run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RunStats<const N: usize> {
    /// Control samples taken.
    pub samples: usize,
    /// Per joint, the first sample time at which the position was outside its limits.
    pub first_limit_violation: [Option<f64>; N],
    /// Per joint, how many samples had the torque clamped by saturation.
    pub saturated_samples: [usize; N],
    /// Per joint, how many samples found it past an end stop (with end stops in the plant).
    pub end_stop_samples: [usize; N],
}

/// Runs a closed loop from `config.q0` for `config.duration` seconds.
///
/// At each control sample `k` (time `k * control_dt`, `k = 0 ..= duration / control_dt`) the
/// controller sees the exact state and the environment's wrench, its torque is saturated
/// and held for `control_dt / plant_dt` RK4 steps; end stops and joint friction, if
/// configured, act in the plant like the contact
/// (`M qdd = tau - c - g - J^T f_ext + tau_stop - tau_friction`). `observer`
/// receives every sample.
///
/// # Errors
///
/// [`SimError::Config`] for unusable timing; [`SimError::NonFinite`] or
/// [`SimError::Model`] when the state or the model breaks down (naming the time and state).
pub fn simulate<const N: usize, R, C, E, S>(
    robot: &R,
    controller: &mut C,
    reference: &mut S,
    environment: &E,
    config: &SimConfig<N>,
    mut observer: impl FnMut(&Sample<N>),
) -> Result<RunStats<N>, SimError>
where
    R: RobotModel<N>,
    C: Controller<N> + ?Sized,
    E: Environment + ?Sized,
    S: ReferenceSource<N> + ?Sized,
{
    let (steps, substeps) = timing(config)?;
    let h = config.control_dt / substeps as f64;
    let total = steps * substeps;
    let mut q = config.q0;
    let mut qd = config.qd0;
    check_state(0.0, &q, &qd)?;
    controller.reset();
    let mut stats = RunStats {
        samples: 0,
        first_limit_violation: [None; N],
        saturated_samples: [0; N],
        end_stop_samples: [0; N],
    };
    let lower = robot.lower_limits();
    let upper = robot.upper_limits();
    let mut schedule = schedule::Schedule::new(config, steps, substeps, h);
    let mut pending = schedule::Pending::<N>::default();
    let mut tau = JointVector::<N>::zeros();
    // `J^T f_ext` at the last control sample, and the plant step it was taken at.
    let mut contact_here: Option<(usize, JointVector<N>)> = None;
    // Plant step `i` starts at `k control_dt + s h` (`k = i / substeps`, `s = i % substeps`);
    // control sample `k` is taken at plant step `schedule.at(k)` (`k substeps` without
    // jitter), and its torque reaches the plant `delay` plant steps later.
    for i in 0..=total {
        let t = (i / substeps) as f64 * config.control_dt + (i % substeps) as f64 * h;
        while schedule.due(i) {
            let pose = robot.end_effector_pose(&q);
            let position = Vector3::new(pose[(0, 3)], pose[(1, 3)], pose[(2, 3)]);
            let jac = robot.jacobian(&q);
            let velocity = (jac * qd).fixed_rows::<3>(0).into_owned();
            let wrench = environment.wrench_at(t, &position, &velocity);
            // The first RK4 stage of this plant step is at this very state and time.
            contact_here = Some((i, joint_torque_of(&jac, &wrench)));
            let setpoint = reference.at(t);
            let input = ControllerInput {
                t,
                q: &q,
                qd: &qd,
                target: &setpoint.joint,
                cartesian: &setpoint.cartesian,
                wrench: &wrench,
                wrench_ref: &setpoint.wrench,
                wrench_age_s: 0.0,
            };
            let tau_command = controller.step(&input, config.control_dt);
            let report = controller.report();
            let saturated = JointVector::<N>::from_fn(|i, _| {
                let limit = config.effort_limits[i];
                tau_command[i].clamp(-limit, limit)
            });
            for i in 0..N {
                if saturated[i] != tau_command[i] {
                    stats.saturated_samples[i] += 1;
                }
                if stats.first_limit_violation[i].is_none()
                    && !(lower[i] <= q[i] && q[i] <= upper[i])
                {
                    stats.first_limit_violation[i] = Some(t);
                }
                if config.end_stops.is_some_and(|e| e.engaged(&q, i)) {
                    stats.end_stop_samples[i] += 1;
                }
            }
            observer(&Sample {
                t,
                q,
                qd,
                tau_command,
                tau: saturated,
                setpoint,
                position,
                orientation: orientation::of_pose(&pose),
                wrench,
                measured_wrench: report.measured_wrench.unwrap_or(wrench),
                force_controlled: report.force_controlled,
            });
            stats.samples += 1;
            let delivered = if config.faults.actuator.is_some() {
                JointVector::<N>::from_fn(|j, _| saturated[j] * config.faults.actuator_scale(t, j))
            } else {
                saturated
            };
            pending.push(i + config.faults.delay_steps(t), delivered);
        }
        if let Some(next) = pending.take(i) {
            tau = next;
        }
        if i == total {
            break;
        }
        let mut first_stage = contact_here.filter(|(at, _)| *at == i).map(|(_, c)| c);
        let (qn, qdn) = rk4::rk4_step(&q, &qd, h, |q, qd| {
            let mut tau_ext = match first_stage.take() {
                Some(contact) => contact,
                None => contact_torque(robot, environment, t, q, qd),
            };
            if let Some(stops) = &config.end_stops {
                tau_ext -= stops.torque(q, qd);
            }
            if let Some(friction) = &config.friction {
                tau_ext += friction.torque(qd);
            }
            forward_dynamics(robot, q, qd, &tau, &tau_ext)
        })
        .map_err(|e| step_error(t, &q, &qd, e))?;
        q = qn;
        qd = qdn;
        check_state(t + h, &q, &qd)?;
    }
    Ok(stats)
}

/// `J(q)^T f_ext` for the environment's wrench at the current state (thesis eq. 3.66).
/// `J` and the tool position come from one generated call that shares sin/cos
/// ([`RobotModel::jacobian_and_position`]; bit for bit `jacobian` and `end_effector_pose`).
fn contact_torque<const N: usize, R: RobotModel<N>, E: Environment + ?Sized>(
    robot: &R,
    environment: &E,
    t: f64,
    q: &JointVector<N>,
    qd: &JointVector<N>,
) -> JointVector<N> {
    let (jac, position) = robot.jacobian_and_position(q);
    let velocity = (jac * qd).fixed_rows::<3>(0).into_owned();
    joint_torque_of(&jac, &environment.wrench_at(t, &position, &velocity))
}

/// `J^T w` (N m or N), exactly zero without contact.
fn joint_torque_of<const N: usize>(jac: &crate::model::Jacobian<N>, w: &Wrench) -> JointVector<N> {
    if *w == Wrench::zeros() {
        return JointVector::zeros();
    }
    jac.transpose() * w
}

/// The run's control samples and plant substeps per sample, as floats (before any cap): the
/// one place their checks and rounding live ([`timing`] and [`SimConfig::plant_steps`]).
pub(crate) fn sample_counts<const N: usize>(c: &SimConfig<N>) -> Result<(f64, f64), SimError> {
    if !(c.duration.is_finite() && c.duration >= 0.0) {
        return Err(SimError::Config("duration must be finite and >= 0 s"));
    }
    if !(c.plant_dt.is_finite() && c.plant_dt > 0.0) {
        return Err(SimError::Config("plant step must be finite and > 0 s"));
    }
    if !(c.control_dt.is_finite() && c.control_dt > 0.0) {
        return Err(SimError::Config("control period must be finite and > 0 s"));
    }
    let ratio = c.control_dt / c.plant_dt;
    let substeps = libm::round(ratio);
    if substeps < 1.0 || (ratio - substeps).abs() > 1e-9 * ratio {
        return Err(SimError::Config(
            "control period must be a whole multiple of the plant step",
        ));
    }
    Ok((libm::round(c.duration / c.control_dt), substeps))
}

fn timing<const N: usize>(c: &SimConfig<N>) -> Result<(usize, usize), SimError> {
    let (steps, substeps) = sample_counts(c)?;
    if steps > 1e9 {
        return Err(SimError::Config("too many control samples (> 1e9)"));
    }
    if c.effort_limits.iter().any(|l| l.is_nan() || *l <= 0.0) {
        return Err(SimError::Config(
            "actuator limits must be > 0 (use f64::INFINITY for none)",
        ));
    }
    if c.q0.iter().chain(c.qd0.iter()).any(|x| !x.is_finite()) {
        return Err(SimError::Config("initial state must be finite"));
    }
    Ok((steps as usize, substeps as usize))
}

pub(crate) fn check_state<const N: usize>(
    t: f64,
    q: &JointVector<N>,
    qd: &JointVector<N>,
) -> Result<(), SimError> {
    if q.iter().chain(qd.iter()).all(|x| x.is_finite()) {
        return Ok(());
    }
    Err(SimError::NonFinite {
        t,
        state: StateSnapshot::new(q, qd),
    })
}
