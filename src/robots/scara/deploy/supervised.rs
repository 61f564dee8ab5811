//! The deployable hybrid step inside the safety supervisor, both in the step's scalar `T`:
//! what a microcontroller runs when it must stay safe on its own (`no_std`, no allocation).

use nalgebra::{Matrix4, SMatrix, Vector3, Vector4, Vector6};

use super::hybrid::{HybridInput, ScaraHybrid};
use super::scalar::ScaraScalar;
use crate::control::safety::reaction::ModelAt;
use crate::control::safety::{Observation, SafetyLimits, SafetyMonitor};

/// [`ScaraHybrid`] inside a [`SafetyMonitor`], each period (the order of
/// [`Supervised`](crate::control::safety::Supervised), so the `f64` instance gives the same
/// torques to the last bit):
///
/// 1. the force reading's health (`force_age_s` old) and the spike filter; the step reads the
///    last accepted reading;
/// 2. the step, while nothing has tripped;
/// 3. the state checks: force, its rate, oscillation and loss, tool speed and box, joints;
/// 4. after a trip, the latched reaction (hold, retract along the step's normal, compliant)
///    from the generated `M`, `c + g` and Jacobian in `T`;
/// 5. the output stage: a non-finite torque replaced by gravity compensation, the torque
///    rate slewed.
///
/// ```
/// use armdyn::control::safety::SafetyLimits;
/// use armdyn::model::{RobotModel, Scara};
/// use armdyn::robots::scara::deploy::{HybridInput, ScaraHybrid, SupervisedHybrid};
/// let limits = SafetyLimits::defaults(
///     Scara.lower_limits(), Scara.upper_limits(), Scara.effort_limits(), Some(200.0), 0.0,
/// );
/// let mut c = SupervisedHybrid::new(ScaraHybrid::<f32>::thesis().unwrap(), &limits);
/// let mut x = HybridInput {
///     t: 3.0,
///     q: [0.3, 0.8, 0.2, 0.1],
///     qd: [0.0; 4],
///     q_ref: [0.3, 0.8, 0.2, 0.1],
///     qd_ref: [0.0; 4],
///     position_ref: [0.45, -0.1, 0.13],
///     velocity_ref: [0.0; 3],
///     force: [0.0, 0.0, f32::NAN],
///     force_ref: [0.0, 0.0, -200.0],
/// };
/// let tau = c.step(&x, 0.0, 1e-3);
/// assert!(tau.iter().all(|t| t.is_finite()));
/// assert_eq!(c.monitor().trips().first().unwrap().cause.name(), "sensor-non-finite");
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct SupervisedHybrid<T: ScaraScalar> {
    step: ScaraHybrid<T>,
    monitor: SafetyMonitor<T, 4>,
}

impl<T: ScaraScalar> SupervisedHybrid<T> {
    /// `step` checked against `limits` (stated in `f64`, rounded to `T`).
    #[must_use]
    pub fn new(step: ScaraHybrid<T>, limits: &SafetyLimits<f64, 4>) -> Self {
        Self {
            step,
            monitor: SafetyMonitor::new(limits.cast()),
        }
    }

    /// The step inside.
    #[must_use]
    pub fn inner(&self) -> &ScaraHybrid<T> {
        &self.step
    }

    /// The monitor: its limits, trips, counts and peaks.
    #[must_use]
    pub fn monitor(&self) -> &SafetyMonitor<T, 4> {
        &self.monitor
    }

    /// Clears the step and the monitor for a new run.
    pub fn reset(&mut self) {
        self.step.reset();
        self.monitor.reset();
    }

    /// Whether the last step controlled force (never after a trip).
    #[must_use]
    pub fn force_controlled(&self) -> bool {
        !self.monitor.tripped() && self.step.force_controlled()
    }

    /// One control period of `dt` s with a force reading `force_age_s` s old (0: fresh): the
    /// joint torques (N m, N m, N, N m), always finite.
    pub fn step(&mut self, x: &HybridInput<T>, force_age_s: T, dt: T) -> [T; 4] {
        let reading = Vector6::new(
            x.force[0],
            x.force[1],
            x.force[2],
            T::zero(),
            T::zero(),
            T::zero(),
        );
        let accepted = self.monitor.sensor(x.t, &reading, force_age_s, dt);
        let mut tau = Vector4::zeros();
        if !self.monitor.tripped() {
            let seen = HybridInput {
                force: [accepted[0], accepted[1], accepted[2]],
                ..*x
            };
            tau = Vector4::from(self.step.step(&seen, dt));
        }
        let (q, qd) = (Vector4::from(x.q), Vector4::from(x.qd));
        // The tool's state as the step computed it (under force control), else from the
        // generated Jacobian; the translational rows and the position in one call.
        let kinematics = || {
            let jp = T::jacobian_and_position(&x.q);
            let j = SMatrix::<T, 3, 4>::from_fn(|r, c| jp[r][c]);
            (j, Vector3::new(jp[0][4], jp[1][4], jp[2][4]))
        };
        let tool = (!self.monitor.tripped())
            .then(|| self.step.tool_state())
            .flatten();
        let (position, velocity) = tool.unwrap_or_else(|| {
            let (j, p) = kinematics();
            (p, j * qd)
        });
        self.monitor.state(
            &Observation {
                t: x.t,
                q: &q,
                qd: &qd,
                position: &position,
                velocity: &velocity,
                force_ref_n: Vector3::from(x.force_ref).norm(),
                force_controlled: self.step.force_controlled() && !self.monitor.tripped(),
            },
            &accepted,
            dt,
        );
        // The controller's torque, found finite here, is not checked again at the output.
        let finite = !self.monitor.tripped() && self.monitor.torque(x.t, &tau);
        if self.monitor.tripped() {
            let mb = T::mass_matrix_and_bias(&x.q, &x.qd);
            let mass = Matrix4::<T>::from_fn(|r, c| mb[r][c]);
            let bias = Vector4::new(mb[0][4], mb[1][4], mb[2][4], mb[3][4]);
            let (jp, _) = kinematics();
            let model = ModelAt {
                mass: &mass,
                bias: &bias,
                jp: &jp,
                position: &position,
            };
            let away = self.step.normal();
            if let Some(r) = self
                .monitor
                .reaction_torque(x.t, dt, &q, &qd, &away, &model)
            {
                tau = r;
            }
        }
        let gravity = || {
            let g = T::mass_matrix_and_bias(&x.q, &[T::zero(); 4]);
            Vector4::new(g[0][4], g[1][4], g[2][4], g[3][4])
        };
        if finite {
            return self.monitor.output_of_finite(&tau, dt).into();
        }
        self.monitor.output(&tau, gravity, dt).into()
    }
}
