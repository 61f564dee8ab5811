//! A controller inside the safety monitor: [`Supervised`].

use super::monitor::{Observation, Peaks, SafetyMonitor};
use super::reaction::ModelAt;
use super::trip::TripLog;
use super::SafetyLimits;
use crate::control::task_frame::TaskFrame;
use crate::control::{Controller, ControllerInput};
use crate::model::{JointVector, RobotModel};
use nalgebra::Vector3;

/// What a run's supervisor saw.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SafetyReport<const N: usize> {
    /// The limits it checked.
    pub limits: SafetyLimits<f64, N>,
    /// Its trips; the first latched the reaction.
    pub trips: TripLog<f64>,
    /// Periods whose commanded torque was slewed.
    pub rate_limited_samples: u32,
    /// Periods whose torque was non-finite and replaced.
    pub replaced_samples: u32,
    /// Readings the spike filter held back.
    pub spikes_filtered: u32,
    /// How close the run came to each limit.
    pub peaks: Peaks<f64, N>,
    /// Largest force rate, N/s.
    pub peak_force_rate_n_s: f64,
    /// Largest oscillation RMS, N.
    pub peak_oscillation_rms_n: f64,
}

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
    fn name(&self) -> &'static str {
        self.inner.name()
    }

    fn reset(&mut self) {
        self.inner.reset();
        self.monitor.reset();
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
        // The tool's state as the controller's step computed it, or else from the model.
        let tool = (!self.monitor.tripped())
            .then(|| self.inner.tool_state())
            .flatten();
        let (position, velocity) = match tool {
            Some(s) => (s.position, s.velocity),
            None => {
                let (jac, p) = self.model.jacobian_and_position(input.q);
                let v: Vector3<f64> = (jac * input.qd).fixed_rows::<3>(0).into_owned();
                (p, v)
            }
        };
        self.monitor.state(
            &Observation {
                t,
                q: input.q,
                qd: input.qd,
                position: &position,
                velocity: &velocity,
                force_ref_n: input.wrench_ref.fixed_rows::<3>(0).norm(),
                force_controlled: self.inner.force_controlled(),
            },
            &accepted,
            dt,
        );
        if !self.monitor.tripped() {
            self.monitor.torque(t, &tau);
        }
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
        let model = &self.model;
        self.monitor.output(&tau, || model.gravity(input.q), dt)
    }

    fn force_controlled(&self) -> bool {
        !self.monitor.tripped() && self.inner.force_controlled()
    }

    fn sensor_bias_estimate(&self) -> Option<crate::model::Wrench> {
        self.inner.sensor_bias_estimate()
    }

    fn tool_state(&self) -> Option<crate::control::ToolState> {
        self.inner.tool_state()
    }

    fn safety(&self) -> Option<SafetyReport<N>> {
        let (rate, rms) = self.monitor.force_peaks();
        Some(SafetyReport {
            limits: *self.monitor.limits(),
            trips: *self.monitor.trips(),
            rate_limited_samples: self.monitor.rate_limited_samples(),
            replaced_samples: self.monitor.replaced_samples(),
            spikes_filtered: self.monitor.spikes_filtered(),
            peaks: self.monitor.peaks(),
            peak_force_rate_n_s: rate,
            peak_oscillation_rms_n: rms,
        })
    }
}
