//! The run, the last stage: a prepared run simulated, its samples turned into an
//! [`Outcome`].

use super::desired_force::DesiredForce;
use super::planned::PlannedReference;
use super::prepare::{Prepared, PreparedRun};
use super::robot::ScenarioRobot;
use super::runner::{run, RunOutput};
use super::spec::Scenario;
use crate::control::selection::SelectionPolicy;
use crate::metrics::{AlignmentMetrics, ContactMetrics, ForceMetrics, PostureMetrics};
use crate::metrics::{PoseMetrics, TrackingMetrics};
use crate::model::Wrench;
use crate::sim::{ReferenceSource, Setpoint, SimError};

use super::outcome::{
    BiasReport, JointTracking, Outcome, Recorded, RunCounts, SETTLED_AFTER_SWITCH_S,
    SWITCH_WINDOW_SAMPLES, TRACKING_AFTER_S,
};
use super::prepare::ErasedRun;

impl<const N: usize, R: ScenarioRobot<N>> ErasedRun for PreparedRun<N, R> {
    fn execute(
        self: Box<Self>,
        scenario: &Scenario,
        progress: &mut dyn FnMut(f64),
    ) -> Result<Outcome, SimError> {
        (*self).execute(scenario, progress).map(|r| r.outcome)
    }

    fn controller_name(&self) -> &'static str {
        self.controller.name()
    }

    fn linearize(
        self: Box<Self>,
        at_s: f64,
        at_equilibrium: bool,
    ) -> Result<crate::sim::linearize::Linearization, crate::sim::linearize::LinearizeError> {
        (*self).linearize(at_s, at_equilibrium)
    }
}

/// The planned reference with the desired force: the setpoints of the run.
pub(super) struct RunReference<'a, const N: usize> {
    pub(super) planned: &'a mut dyn PlannedReference<N>,
    pub(super) force: Option<&'a DesiredForce>,
}

impl<const N: usize> ReferenceSource<N> for RunReference<'_, N> {
    fn at(&mut self, t: f64) -> Setpoint<N> {
        let mut s = self.planned.at(t);
        s.wrench = self
            .force
            .map_or_else(Wrench::zeros, |f| f.wrench(t, &s.cartesian.position));
        s
    }
}

impl<const N: usize, R: ScenarioRobot<N>> PreparedRun<N, R> {
    /// Runs it; `progress` gets the simulated time about every 0.5 s. The result keeps every
    /// sample with the metrics.
    ///
    /// # Errors
    ///
    /// [`SimError`] if the simulation breaks down.
    #[allow(clippy::result_large_err)]
    pub fn execute(
        mut self,
        scenario: &Scenario,
        progress: impl FnMut(f64),
    ) -> Result<Recorded<N>, SimError> {
        let out = self.run(progress)?;
        Ok(self.outcome(scenario, out))
    }

    /// Runs it and keeps the typed samples.
    ///
    /// # Errors
    ///
    /// [`SimError`] if the simulation breaks down.
    #[allow(clippy::result_large_err)]
    pub fn run(&mut self, progress: impl FnMut(f64)) -> Result<RunOutput<N>, SimError> {
        let mut reference = RunReference {
            planned: self.reference.as_mut(),
            force: self.force.as_ref(),
        };
        match &self.plant {
            None => run(
                &self.robot,
                self.controller.as_mut(),
                &mut reference,
                &self.environment,
                &self.config,
                progress,
            ),
            Some(plant) => run(
                plant,
                self.controller.as_mut(),
                &mut reference,
                &self.environment,
                &self.config,
                progress,
            ),
        }
    }

    /// The metrics of a run `out` of this preparation.
    pub(super) fn outcome(self, scenario: &Scenario, out: RunOutput<N>) -> Recorded<N> {
        let mut tracking = TrackingMetrics::new(TRACKING_AFTER_S);
        out.samples.iter().for_each(|s| tracking.push(s));
        let tracking = tracking.summary();
        let mut after = TrackingMetrics::new(scenario.pose_metrics_after_s);
        out.samples.iter().for_each(|s| after.push(s));
        let after = after.summary();
        let mut pose = PoseMetrics::new(R::TASK, scenario.pose_metrics_after_s);
        out.samples.iter().for_each(|s| pose.push(s));
        let duration = self.config.duration;
        let switch_s = out.samples.iter().find(|s| s.force_controlled).map(|s| s.t);
        let force = scenario.force.as_ref().map(|f| {
            let mut m =
                ForceMetrics::new(switch_s.unwrap_or(duration), duration, 5.0, f.value_n, 0.05);
            out.samples.iter().for_each(|s| m.push(s));
            m.summary()
        });
        let contact = (!scenario.surfaces.is_empty()).then(|| {
            let value = scenario.force.as_ref().map_or(1.0, |f| f.value_n);
            let ramp_s = match scenario.selection {
                Some(SelectionPolicy::Contact(c)) => c.ramp_s,
                _ => 0.0,
            };
            let mut m = ContactMetrics::new(switch_s, value, duration).with_ramp(ramp_s);
            out.samples.iter().for_each(|s| m.push(s, &self.scene));
            m.summary()
        });
        let alignment = self.force.as_ref().and_then(|f| f.tool_axis).map(|axis| {
            let mut m = AlignmentMetrics::new(axis);
            out.samples.iter().for_each(|s| m.push(s, &self.scene));
            m.summary()
        });
        let posture = (R::TASK.redundancy(N) > 0).then(|| {
            let mut m = PostureMetrics::new(scenario.pose_metrics_after_s);
            out.samples.iter().for_each(|s| m.push(s));
            m.summary()
        });
        let sensor_bias = self.controller.report().sensor_bias_estimate.map(|b| {
            let estimate_n = [b[0], b[1], b[2]];
            let true_n = [0.0, 0.0, scenario.sensor.bias_n];
            let error_n = libm::sqrt(
                (0..3)
                    .map(|i| (estimate_n[i] - true_n[i]) * (estimate_n[i] - true_n[i]))
                    .sum(),
            );
            BiasReport {
                estimate_n,
                true_n,
                error_n,
            }
        });
        let switch_torque_step = out
            .samples
            .iter()
            .position(|s| s.force_controlled)
            .filter(|k| *k > 0)
            .map(|k| {
                let end = (k + SWITCH_WINDOW_SAMPLES).min(out.samples.len());
                (k..end)
                    .map(|i| (out.samples[i].tau_command - out.samples[i - 1].tau_command).amax())
                    .fold(0.0, f64::max)
            });
        let settled_torque_step = switch_s.map(|t0| {
            out.samples
                .windows(2)
                .filter(|w| w[0].t >= t0 + SETTLED_AFTER_SWITCH_S)
                .map(|w| (w[1].tau_command - w[0].tau_command).amax())
                .fold(0.0, f64::max)
        });
        let (lower, upper) = (self.robot.lower_limits(), self.robot.upper_limits());
        let joint_limit_violation_samples = out
            .samples
            .iter()
            .filter(|s| (0..N).any(|i| !(lower[i] <= s.q[i] && s.q[i] <= upper[i])))
            .count();
        let reference = self
            .reference
            .report(&out.samples, &self.config.effort_limits);
        let safety = super::safety_outcome::summary(
            self.controller.report().safety,
            &scenario.faults,
            &scenario.surfaces,
            &out.samples,
            self.config.control_dt,
        );
        let v = |x: &crate::model::JointVector<N>| x.iter().copied().collect::<Vec<f64>>();
        let outcome = Outcome {
            stats: RunCounts::from(&out.stats),
            robot: R::NAME,
            joint_names: R::JOINT_NAMES.to_vec(),
            joint_kinds: R::JOINT_KINDS.to_vec(),
            task: R::TASK,
            tracking: JointTracking {
                rms_joint_error: v(&tracking.rms_joint_error),
                rms_joint_error_after: v(&tracking.rms_joint_error_after),
                max_joint_error_after: v(&tracking.max_joint_error_after),
                max_abs_tau: v(&tracking.max_abs_tau),
            },
            tracking_after: JointTracking {
                rms_joint_error: v(&after.rms_joint_error),
                rms_joint_error_after: v(&after.rms_joint_error_after),
                max_joint_error_after: v(&after.max_joint_error_after),
                max_abs_tau: v(&after.max_abs_tau),
            },
            pose: pose.summary(),
            force,
            contact,
            alignment,
            posture,
            sensor_bias,
            switch_torque_step,
            settled_torque_step,
            controller_name: self.controller.name(),
            gains: self.gains,
            scene: self.scene,
            selection: scenario.selection.map(|s| match s {
                SelectionPolicy::Time { .. } => "time",
                SelectionPolicy::Contact(_) => "contact",
            }),
            joint_limit_violation_samples,
            safety,
            reference,
        };
        Recorded {
            outcome,
            samples: out.samples,
        }
    }
}

/// Runs a prepared scenario of any robot; `progress` gets the simulated time about every
/// 0.5 s. Its samples are not kept: [`PreparedRun::execute`] gives them with the metrics.
///
/// # Errors
///
/// [`SimError`] if the simulation breaks down.
#[allow(clippy::result_large_err)]
pub fn execute(
    scenario: &Scenario,
    p: Prepared,
    mut progress: impl FnMut(f64),
) -> Result<Outcome, SimError> {
    p.run.execute(scenario, &mut progress)
}
