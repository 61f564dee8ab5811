//! The sampled closed loop linearised about a state of a run: plant with its zero-order
//! hold, controller and contact, as one discrete-time map over a control period.
//!
//! ```text
//! s_k = [q_k; qd_k; z_(k-1)]       joint state at sample k, controller state before its step
//! tau_k, z_k = C(z_(k-1), q_k, qd_k, w(q_k, qd_k))     the controller's step (saturated)
//! [q; qd]_(k+1) = P(q_k, qd_k, tau_k)                 the plant over one period, tau held
//! s_(k+1) = Phi(s_k),   A = d Phi / d s = [P_x + P_u C_x, P_u C_z; Z_x, Z_z]
//! ```
//!
//! `P_x`, `P_u` come from the generated derivatives ([`plant::plant_period`]). The
//! controller's Jacobian (`C_x`, `C_z`, `Z_x`, `Z_z`) is differenced numerically: central
//! differences of one step from its restored state ([`Controller::read_state`]), steps
//! [`CONTROLLER_JOINT_STEP`] and [`CONTROLLER_STATE_STEP`] (relative); the laws are
//! piecewise smooth compositions of the model's functions, and a step is cheap. The contact
//! wrench the controller reads is the environment's at the perturbed state, so the sensor's
//! path is in `C_x`. A saturated joint's torque does not move with the state (its rows of
//! `C` are zero).
//!
//! Before differencing, the step is evaluated twice from the same restored state: if the two
//! torques differ, a stage holds state it does not expose (sensor noise, a law without
//! [`Controller::state_len`]), and the linearisation is refused rather than wrong.

pub mod equilibrium;
pub mod modes;
pub mod plant;

use nalgebra::DMatrix;

use crate::contact::Environment;
use crate::control::{Controller, ControllerInput};
use crate::model::{DynamicsDerivatives, JointVector, Wrench};
use crate::sim::{ReferenceSource, SimConfig, SimError};
use crate::target::{CartesianTarget, JointTarget};

pub use equilibrium::Equilibrium;
pub use modes::{Mode, Modes};

/// Central-difference step of the joint state in the controller, rad or m (rad/s, m/s).
pub const CONTROLLER_JOINT_STEP: f64 = 1e-7;
/// The window before the sample over which the run's changes of mode are counted, s.
pub const MODE_WINDOW_S: f64 = 1.0;
/// Central-difference step of the controller's own state, relative to `max(1, |z_i|)`.
pub const CONTROLLER_STATE_STEP: f64 = 1e-7;

/// Why a closed loop could not be linearised.
#[derive(Debug, thiserror::Error)]
pub enum LinearizeError {
    /// The run to the linearisation time failed.
    #[error("the run to the linearisation time failed: {0}")]
    Run(#[from] SimError),
    /// The model could not be evaluated at the state.
    #[error("the model at t = {t} s: {error}")]
    Model {
        /// Time, s.
        t: f64,
        /// What the model said.
        error: crate::model::ModelError,
    },
    /// The time is not within the run.
    #[error("time {0} s is not within the run (0 to its duration)")]
    Time(f64),
    /// The loop cannot be linearised as configured (the message says why).
    #[error("{0}")]
    Unsupported(String),
    /// The controller's output depends on state it does not expose.
    #[error(
        "controller `{0}` gives two different torques for the same step from the same state: a \
         stage holds state it does not expose for linearisation (sensor noise, or a law without \
         `state_len`), so its Jacobian cannot be taken"
    )]
    HiddenState(&'static str),
}

/// The linearised closed loop at one sample.
#[derive(Clone, Debug)]
pub struct Linearization {
    /// The sample's time, s.
    pub t: f64,
    /// The control period, s.
    pub dt: f64,
    /// One name per state: `q <joint>`, `qd <joint>`, `controller[k]` (the controller's
    /// [`Controller::write_state`] order).
    pub labels: Vec<String>,
    /// `A = d s_(k+1) / d s_k`, the discrete closed-loop matrix.
    pub a: DMatrix<f64>,
    /// Joint positions at the sample.
    pub q: Vec<f64>,
    /// Joint velocities at the sample.
    pub qd: Vec<f64>,
    /// The torque the controller commanded at the sample (before saturation), N m or N.
    pub tau: Vec<f64>,
    /// `[q; qd]` one period later by this module's plant, against the run's own next sample
    /// (the largest difference, rad or rad/s): a check that the linearised map is the run's.
    pub next_state_mismatch: f64,
    /// Where the state is not the run's own but the equilibrium found from it
    /// ([`LinearizeAt::Equilibrium`]): how it was found.
    pub equilibrium: Option<Equilibrium>,
    /// How often the run left the sample's mode (force or position control: the contact
    /// selection's switch, the supervisor) in the [`MODE_WINDOW_S`] up to the sample. The map
    /// is linearised in the sample's mode; a run that keeps leaving it is in a cycle through
    /// the switch, which the linearisation of one mode does not describe (its verdict is then
    /// of that mode alone, and the run does not settle). Entering it once, as at the first
    /// contact, is not counted.
    pub mode_exits: usize,
    /// Whether the sample's step controlled force (else position).
    pub force_controlled: bool,
}

impl Linearization {
    /// Whether the run settles by this analysis: the linearised loop is stable and the run
    /// did not leave the sample's mode over the [`MODE_WINDOW_S`] up to it.
    #[must_use]
    pub fn settles(&self) -> bool {
        Modes::of(&self.a, self.dt, &self.labels).stable() && self.mode_exits == 0
    }
}

/// The controller's view at the probed sample: everything of its input, owned.
#[derive(Clone, Copy)]
struct Probed<const N: usize> {
    t: f64,
    target: JointTarget<N>,
    cartesian: CartesianTarget,
    wrench_ref: Wrench,
    q: JointVector<N>,
    qd: JointVector<N>,
}

/// Wraps the run's controller to copy its state and input at the first sample at or after
/// `at` (and at the sample after, for the check of the plant).
struct Probe<'a, const N: usize> {
    inner: &'a mut dyn Controller<N>,
    at: f64,
    state: Vec<f64>,
    probed: Option<Probed<N>>,
    next: Option<(JointVector<N>, JointVector<N>)>,
    /// Whether the last step controlled force, and the times the answer changed (with the
    /// new answer).
    force_controlled: bool,
    switch_times: Vec<(f64, bool)>,
}

impl<const N: usize> Controller<N> for Probe<'_, N> {
    fn name(&self) -> &'static str {
        self.inner.name()
    }
    fn reset(&mut self) {
        self.inner.reset();
    }
    fn step(&mut self, input: &ControllerInput<'_, N>, dt: f64) -> JointVector<N> {
        let first = self.probed.is_none() && input.t >= self.at - 1e-9 * dt;
        if first {
            self.state = vec![0.0; self.inner.state_len()];
            self.inner.write_state(&mut self.state);
        } else if self.probed.is_some() && self.next.is_none() {
            self.next = Some((*input.q, *input.qd));
        }
        let tau = self.inner.step(input, dt);
        if self.probed.is_none() || first {
            let force_controlled = self.inner.report().force_controlled;
            if force_controlled != self.force_controlled {
                self.switch_times.push((input.t, force_controlled));
                self.force_controlled = force_controlled;
            }
        }
        if first {
            self.probed = Some(Probed {
                t: input.t,
                target: *input.target,
                cartesian: *input.cartesian,
                wrench_ref: *input.wrench_ref,
                q: *input.q,
                qd: *input.qd,
            });
        }
        tau
    }
    fn report(&self) -> crate::control::StepReport<N> {
        self.inner.report()
    }
}

/// The run's controller and input at the probed sample, after running to it.
struct RunToSample<'a, const N: usize> {
    controller: &'a mut dyn Controller<N>,
    probed: Probed<N>,
    /// The controller's state before its step at the sample.
    z0: Vec<f64>,
    /// The run's own `[q; qd]` one period later.
    next: (JointVector<N>, JointVector<N>),
    /// How often the run left the sample's mode in the [`MODE_WINDOW_S`] up to the sample.
    mode_exits: usize,
    /// Whether the sample's step controlled force.
    force_controlled: bool,
}

/// Runs the closed loop to `at_s` and one period past it, keeping the controller's state and
/// input at the first sample at or after `at_s`.
fn run_to_sample<'a, const N: usize, R, E>(
    robot: &R,
    controller: &'a mut dyn Controller<N>,
    reference: &mut dyn ReferenceSource<N>,
    environment: &E,
    config: &SimConfig<N>,
    at_s: f64,
) -> Result<RunToSample<'a, N>, LinearizeError>
where
    R: DynamicsDerivatives<N>,
    E: Environment + ?Sized,
{
    if !(at_s.is_finite() && at_s >= 0.0 && at_s <= config.duration) {
        return Err(LinearizeError::Time(at_s));
    }
    let dt = config.control_dt;
    let mut run_config = *config;
    run_config.duration = (libm::ceil(at_s / dt - 1e-9) + 1.0) * dt;
    run_config.faults = crate::sim::faults::PlantFaults::default();
    let mut probe = Probe {
        inner: controller,
        at: at_s,
        state: Vec::new(),
        probed: None,
        next: None,
        force_controlled: false,
        switch_times: Vec::new(),
    };
    crate::sim::simulate(
        robot,
        &mut probe,
        reference,
        environment,
        &run_config,
        |_| {},
    )?;
    match (probe.probed, probe.next) {
        (Some(probed), Some(next)) => Ok(RunToSample {
            mode_exits: probe
                .switch_times
                .iter()
                .filter(|&&(t, to)| t > probed.t - MODE_WINDOW_S && to != probe.force_controlled)
                .count(),
            force_controlled: probe.force_controlled,
            controller: probe.inner,
            probed,
            z0: probe.state,
            next,
        }),
        _ => Err(LinearizeError::Time(at_s)),
    }
}

/// The closed loop with its time and its controller's inputs other than the joint state
/// (reference, force reference) frozen at one sample: the map `s -> Phi(s)` of the module
/// documentation, at any state `s = [q; qd; z]`.
struct FrozenLoop<'a, 'b, const N: usize, R, E: ?Sized> {
    robot: &'b R,
    controller: &'b mut (dyn Controller<N> + 'a),
    environment: &'b E,
    config: &'b SimConfig<N>,
    probed: Probed<N>,
}

/// `Phi` and its Jacobian at one state.
struct MapAt<const N: usize> {
    /// `A = d Phi / d s`.
    a: DMatrix<f64>,
    /// `Phi(s)`: `[q; qd]` one period later and the controller's state after its step.
    next: Vec<f64>,
    /// The commanded torque (before saturation).
    tau: JointVector<N>,
}

impl<const N: usize, R, E> FrozenLoop<'_, '_, N, R, E>
where
    R: DynamicsDerivatives<N>,
    E: Environment + ?Sized,
{
    /// The controller as a function of `(q, qd, z)`: torque (before saturation) and next state.
    fn evaluate(
        &mut self,
        q: &JointVector<N>,
        qd: &JointVector<N>,
        z: &[f64],
    ) -> (JointVector<N>, Vec<f64>) {
        let p = &self.probed;
        self.controller.read_state(z);
        let (j, x) = self.robot.jacobian_and_position(q);
        let v = j.fixed_rows::<3>(0) * qd;
        let wrench = self.environment.wrench_at(p.t, &x, &v.into_owned());
        let input = ControllerInput {
            t: p.t,
            q,
            qd,
            target: &p.target,
            cartesian: &p.cartesian,
            wrench: &wrench,
            wrench_ref: &p.wrench_ref,
            wrench_age_s: 0.0,
        };
        let tau = self.controller.step(&input, self.config.control_dt);
        let mut z_next = vec![0.0; self.controller.state_len()];
        self.controller.write_state(&mut z_next);
        (tau, z_next)
    }

    /// `Phi(s)` and `A` at `s = [q; qd; z]`; the controller is left at `z`.
    fn map(
        &mut self,
        q: &JointVector<N>,
        qd: &JointVector<N>,
        z0: &[f64],
    ) -> Result<MapAt<N>, LinearizeError> {
        let config = self.config;
        let dt = config.control_dt;
        let substeps = libm::round(dt / config.plant_dt).max(1.0) as usize;
        let h = dt / substeps as f64;
        let nz = z0.len();
        let t = self.probed.t;
        let (tau0, z1) = self.evaluate(q, qd, z0);
        let (tau_again, z_again) = self.evaluate(q, qd, z0);
        if tau_again != tau0 || z_again != z1 {
            return Err(LinearizeError::HiddenState(self.controller.name()));
        }
        let limits = config.effort_limits;
        let saturated: [bool; N] = core::array::from_fn(|i| tau0[i].abs() > limits[i]);
        let tau_held = JointVector::<N>::from_fn(|i, _| tau0[i].clamp(-limits[i], limits[i]));

        // Columns of the controller's Jacobian: d [tau; z'] / d [q; qd; z].
        let ns = 2 * N + nz;
        let mut c = DMatrix::<f64>::zeros(N + nz, ns);
        for col in 0..ns {
            let (mut qa, mut qda, mut za) = (*q, *qd, z0.to_vec());
            let (mut qb, mut qdb, mut zb) = (*q, *qd, z0.to_vec());
            let step = if col < N {
                qa[col] += CONTROLLER_JOINT_STEP;
                qb[col] -= CONTROLLER_JOINT_STEP;
                CONTROLLER_JOINT_STEP
            } else if col < 2 * N {
                qda[col - N] += CONTROLLER_JOINT_STEP;
                qdb[col - N] -= CONTROLLER_JOINT_STEP;
                CONTROLLER_JOINT_STEP
            } else {
                let k = col - 2 * N;
                let s = CONTROLLER_STATE_STEP * z0[k].abs().max(1.0);
                za[k] += s;
                zb[k] -= s;
                s
            };
            let (ta, ya) = self.evaluate(&qa, &qda, &za);
            let (tb, yb) = self.evaluate(&qb, &qdb, &zb);
            for i in 0..N {
                c[(i, col)] = if saturated[i] {
                    0.0
                } else {
                    (ta[i] - tb[i]) / (2.0 * step)
                };
            }
            for k in 0..nz {
                c[(N + k, col)] = (ya[k] - yb[k]) / (2.0 * step);
            }
        }
        self.controller.read_state(z0);

        let period = plant::plant_period(
            self.robot,
            self.environment,
            config,
            t,
            q,
            qd,
            &tau_held,
            substeps,
            h,
        )
        .map_err(|error| LinearizeError::Model { t, error })?;

        // A = [P_x + P_u C_x, P_u C_z; Z_x, Z_z].
        let mut a = DMatrix::<f64>::zeros(ns, ns);
        let pu_c = &period.du * c.rows(0, N);
        a.view_mut((0, 0), (2 * N, ns)).copy_from(&pu_c);
        {
            let mut top = a.view_mut((0, 0), (2 * N, 2 * N));
            top += &period.dx;
        }
        a.view_mut((2 * N, 0), (nz, ns)).copy_from(&c.rows(N, nz));
        let mut next = Vec::with_capacity(ns);
        next.extend(period.q.iter());
        next.extend(period.qd.iter());
        next.extend(z1);
        Ok(MapAt { a, next, tau: tau0 })
    }
}

/// The largest difference between `[q; qd]` one period later by the map (`phi`, the first
/// `2N` entries) and by the run (`run_next`), rad or rad/s: the check that the map is the
/// run's.
fn plant_mismatch<const N: usize>(phi: &[f64], run_next: &(JointVector<N>, JointVector<N>)) -> f64 {
    (0..N)
        .map(|i| {
            (phi[i] - run_next.0[i])
                .abs()
                .max((phi[N + i] - run_next.1[i]).abs())
        })
        .fold(0.0f64, f64::max)
}

/// One name per state: `q <joint>`, `qd <joint>`, `controller[k]`.
fn state_labels<const N: usize, R: DynamicsDerivatives<N>>(nz: usize) -> Vec<String> {
    let mut labels = Vec::with_capacity(2 * N + nz);
    labels.extend(R::JOINT_NAMES.iter().map(|j| format!("q {j}")));
    labels.extend(R::JOINT_NAMES.iter().map(|j| format!("qd {j}")));
    labels.extend((0..nz).map(|k| format!("controller[{k}]")));
    labels
}

/// Where [`linearize_closed_loop`] linearises the loop.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LinearizeAt {
    /// At the run's own state at the first sample at or after the time.
    Sample,
    /// At the loop's equilibrium nearest that state, the reference held there (see
    /// [`equilibrium`]): the point the run would come to rest at.
    Equilibrium,
}

/// Runs the closed loop to `at_s` (and one period past it), then linearises it at the first
/// sample at or after `at_s`, or at its equilibrium nearest that sample's state (`at`; see
/// the [module documentation](self)).
///
/// `config` is the run's (its duration is replaced); the plant is `robot` itself, without
/// actuator or timing faults (the linearisation is of the nominal loop).
///
/// # Errors
///
/// [`LinearizeError`]: the run fails, `at_s` is outside `[0, config.duration]`, the model
/// fails at the state, or the controller hides state; at the equilibrium,
/// [`LinearizeError::Unsupported`] when the reference moves at the sample (a moving loop
/// has no rest point) or Newton's method finds no equilibrium from the run's state (the
/// message gives the residual it stopped at).
#[allow(clippy::result_large_err)] // see `crate::sim`
pub fn linearize_closed_loop<const N: usize, R, E>(
    robot: &R,
    controller: &mut dyn Controller<N>,
    reference: &mut dyn ReferenceSource<N>,
    environment: &E,
    config: &SimConfig<N>,
    at_s: f64,
    at: LinearizeAt,
) -> Result<Linearization, LinearizeError>
where
    R: DynamicsDerivatives<N>,
    E: Environment + ?Sized,
{
    let run = run_to_sample(robot, controller, reference, environment, config, at_s)?;
    let (probed, z0, next, mode_exits) = (run.probed, run.z0, run.next, run.mode_exits);
    if at == LinearizeAt::Equilibrium {
        equilibrium::check_at_rest(&probed)?;
    }
    let run_force_controlled = run.force_controlled;
    let mut frozen = FrozenLoop {
        robot,
        controller: run.controller,
        environment,
        config,
        probed,
    };
    let map = frozen.map(&probed.q, &probed.qd, &z0)?;
    let next_state_mismatch = plant_mismatch(&map.next, &next);
    let (q, qd, map, equilibrium) = match at {
        LinearizeAt::Sample => (probed.q, probed.qd, map, None),
        LinearizeAt::Equilibrium => {
            let (q, qd, map, found) = equilibrium::newton(&mut frozen, &z0, map)?;
            (q, qd, map, Some(found))
        }
    };
    // Leave the controller at the state linearised at (the run's: after the probed step).
    frozen.controller.read_state(&map.next[2 * N..]);
    Ok(Linearization {
        t: probed.t,
        dt: config.control_dt,
        labels: state_labels::<N, R>(z0.len()),
        a: map.a,
        q: q.iter().copied().collect(),
        qd: qd.iter().copied().collect(),
        tau: map.tau.iter().copied().collect(),
        next_state_mismatch,
        equilibrium,
        mode_exits,
        force_controlled: run_force_controlled,
    })
}
