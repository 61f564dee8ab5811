//! A controller inside the safety monitor: [`Supervised`].

use super::monitor::{Observation, SafetyMonitor};
use super::reaction::ModelAt;
use super::SafetyLimits;
use crate::control::task_frame::TaskFrame;
use crate::control::{Controller, ControllerInput};
use crate::model::{JointVector, RobotModel};
use nalgebra::Vector3;

/// `inner` run inside a [`SafetyMonitor`] on the robot `model`, each period:
///
/// 1. the reading's health and the spike filter (a bad reading trips; the controller gets
///    the last accepted one);
/// 2. the controller's step, while nothing is tripped;
/// 3. the state checks (force, its rate, oscillation and loss, the tool's speed and box, the
///    joints' limits and speeds; tool pose and velocity from `model`), and the controller's
///    torque finite;
/// 4. once tripped, the latched reaction's torque instead (retreating along the outward
///    normal of `frame` at the tool);
/// 5. the output stage: a non-finite torque replaced by gravity compensation, a step above
///    the torque rate slewed.
///
/// While nothing trips and no step is slewed, the torque is the controller's, bit for bit.
#[derive(Clone, Debug)]
pub struct Supervised<C, M, const N: usize> {
    inner: C,
    model: M,
    frame: TaskFrame,
    monitor: SafetyMonitor<f64, N>,
    /// The accepted reading less the wrench the law read, at the last step the law ran.
    law_offset: crate::model::Wrench,
}

impl<C, M, const N: usize> Supervised<C, M, N> {
    /// `inner` on `model` checked against `limits`; a retraction goes along `frame`'s normal.
    #[must_use]
    pub fn new(inner: C, model: M, limits: SafetyLimits<f64, N>, frame: TaskFrame) -> Self {
        Self {
            inner,
            model,
            frame,
            monitor: SafetyMonitor::new(limits),
            law_offset: crate::model::Wrench::zeros(),
        }
    }

    /// The monitor.
    #[must_use]
    pub fn monitor(&self) -> &SafetyMonitor<f64, N> {
        &self.monitor
    }

    /// The supervised controller.
    #[must_use]
    pub fn inner(&self) -> &C {
        &self.inner
    }
}

impl<C: Controller<N>, M: RobotModel<N>, const N: usize> Controller<N> for Supervised<C, M, N> {
    // The monitors' filters only watch; until a trip the torque is the inner law's (the
    // slew limit acts only on a jump above its limit, not on a small perturbation).
    crate::control::pass_on_state!(inner);

    fn name(&self) -> &'static str {
        self.inner.name()
    }

    fn reset(&mut self) {
        self.inner.reset();
        self.monitor.reset();
        self.law_offset = crate::model::Wrench::zeros();
    }

    fn step(&mut self, input: &ControllerInput<'_, N>, dt: f64) -> JointVector<N> {
        let t = input.t;
        let accepted = self.monitor.sensor(t, input.wrench, input.wrench_age_s, dt);
        let mut tau = JointVector::<N>::zeros();
        if !self.monitor.tripped() {
            let seen = ControllerInput {
                wrench: &accepted,
                ..*input
            };
            tau = self.inner.step(&seen, dt);
        }
        // What the inner law's step reported (its last step's, if it was not stepped).
        let inner = self.inner.report();
        // The tool's state as the controller's step computed it, or else from the model.
        let tool = if self.monitor.tripped() {
            None
        } else {
            inner.tool
        };
        let (position, velocity) = match tool {
            Some(s) => (s.position, s.velocity),
            None => {
                let (jac, p) = self.model.jacobian_and_position(input.q);
                let v: Vector3<f64> = (jac * input.qd).fixed_rows::<3>(0).into_owned();
                (p, v)
            }
        };
        // The contact force as the law read it (a tool's weight and bias taken out by a
        // wrapper inside), else the accepted reading; after a trip the law is not stepped and
        // the accepted reading less the last difference between the two is judged.
        if !self.monitor.tripped() {
            self.law_offset = inner
                .law_wrench
                .map_or_else(crate::model::Wrench::zeros, |w| accepted - w);
        }
        let judged = accepted - self.law_offset;
        self.monitor.state(
            &Observation {
                t,
                q: input.q,
                qd: input.qd,
                position: &position,
                velocity: &velocity,
                force_ref_n: input.wrench_ref.fixed_rows::<3>(0).norm(),
                force_controlled: inner.force_controlled,
            },
            &judged,
            dt,
        );
        // The controller's torque, found finite here, is not checked again at the output.
        let finite = !self.monitor.tripped() && self.monitor.torque(t, &tau);
        if self.monitor.tripped() {
            let (mass, bias) = self.model.mass_matrix_and_bias(input.q, input.qd);
            let (jac, position) = self.model.jacobian_and_position(input.q);
            let jp = jac.fixed_rows::<3>(0).into_owned();
            let away = self.frame.normal_at(&position);
            let model = ModelAt {
                mass: &mass,
                bias: &bias,
                jp: &jp,
                position: &position,
            };
            if let Some(r) = self
                .monitor
                .reaction_torque(t, dt, input.q, input.qd, &away, &model)
            {
                tau = r;
            }
        }
        if finite {
            return self.monitor.output_of_finite(&tau, dt);
        }
        let model = &self.model;
        self.monitor.output(&tau, || model.gravity(input.q), dt)
    }

    fn report(&self) -> crate::control::StepReport<N> {
        let mut r = self.inner.report();
        r.force_controlled = !self.monitor.tripped() && r.force_controlled;
        r.safety = Some(self.monitor.report());
        r
    }
}
