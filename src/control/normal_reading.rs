//! What every force law reads along the contact normal at one sample, and the switching
//! state that decides from it whether force or position is controlled: the outward normal
//! `n` of the task frame at the tool, the measured and desired forces along it, the tool's and
//! the reference's heights above the expected surface, and the selector's [`Decision`].
//!
//! ```text
//! n     = frame.normal_at(p)                 f_n = n . f_meas    f_ref = n . f_desired
//! h     = frame.signed_distance(p)           h_ref = frame.signed_distance(p_ref)
//! f_d   = f_from + (f_ref - f_from) ramp     (the force reference along a switch's ramp)
//! ```

use nalgebra::Vector3;

use super::selection::{ramped_force, Decision, ModeSelector, SelectionPolicy};
use super::task_frame::TaskFrame;
use super::ControllerInput;
use crate::model::Wrench;

/// The linear part `[fx fy fz]` of a wrench, N.
#[must_use]
#[inline(always)]
pub fn linear(w: &Wrench) -> Vector3<f64> {
    Vector3::new(w[0], w[1], w[2])
}

/// One sample's values along the contact normal ([module documentation](self)).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NormalReading {
    /// The outward unit normal of the task frame at the tool, base frame.
    pub n: Vector3<f64>,
    /// Measured force of the tool on the environment along `n`, N (negative: pressing).
    pub f_n: f64,
    /// The reference's force along `n`, N.
    pub reference_n: f64,
    /// The force reference along `n`, N: under force control the reference's along the
    /// switch's ramp from the force measured at the switch ([`ramped_force`]), else the
    /// reference's.
    pub f_d: f64,
    /// The tool's signed height above the expected surface, m (`None`: a fixed frame, which
    /// knows no surface, or the tool off the surface's extent).
    pub tool_gap: Option<f64>,
    /// The reference position's signed height above the expected surface, m (`None` as for
    /// `tool_gap`).
    pub reference_gap: Option<f64>,
    /// What the selector decided.
    pub decision: Decision,
}

impl NormalReading {
    /// Whether force is controlled at this sample.
    #[must_use]
    pub fn forcing(&self) -> bool {
        matches!(self.decision, Decision::Force { .. })
    }
}

/// The task frame and the switching state machine of a force law, read together at each
/// sample ([`Self::read`]); it remembers whether the last sample controlled force.
#[derive(Clone, Copy, Debug)]
pub struct NormalSelector {
    frame: TaskFrame,
    selector: ModeSelector,
    force_active: bool,
}

impl NormalSelector {
    /// Force along the normal of `frame`, when `selection` says.
    #[must_use]
    pub fn new(frame: TaskFrame, selection: SelectionPolicy) -> Self {
        Self {
            frame,
            selector: ModeSelector::new(selection),
            force_active: false,
        }
    }

    /// The sample with the tool at `p` (m, base frame): the normal, the forces and heights
    /// along it, and the selector's decision after `dt` s (contact switching sees the
    /// heights; a time switch does not).
    #[inline(always)]
    pub fn read<const N: usize>(
        &mut self,
        input: &ControllerInput<'_, N>,
        p: &Vector3<f64>,
        dt: f64,
    ) -> NormalReading {
        let n = self.frame.normal_at(p);
        let f_n = n.dot(&linear(input.wrench));
        let tool_gap = self.frame.signed_distance(p);
        let reference_gap = self.frame.signed_distance(&input.cartesian.position);
        let (reference_seen, tool_seen) = if self.contact_switching() {
            (reference_gap, tool_gap)
        } else {
            (None, None)
        };
        let decision = self
            .selector
            .step(input.t, dt, -f_n, f_n, reference_seen, tool_seen);
        self.force_active = matches!(decision, Decision::Force { .. });
        let reference_n = n.dot(&linear(input.wrench_ref));
        NormalReading {
            n,
            f_n,
            reference_n,
            f_d: match decision {
                Decision::Force { ramp, from_n, .. } => ramped_force(from_n, reference_n, ramp),
                Decision::Position { .. } => reference_n,
            },
            tool_gap,
            reference_gap,
            decision,
        }
    }

    /// Whether force control starts on detected contact (rather than at a time).
    #[must_use]
    pub fn contact_switching(&self) -> bool {
        matches!(self.selector.policy(), SelectionPolicy::Contact(_))
    }

    /// Whether the last sample controlled force.
    #[must_use]
    pub fn force_active(&self) -> bool {
        self.force_active
    }

    /// The switching state machine.
    #[must_use]
    pub fn selector(&self) -> &ModeSelector {
        &self.selector
    }

    /// The task frame.
    #[must_use]
    pub fn frame(&self) -> &TaskFrame {
        &self.frame
    }

    /// Back to the initial phase, force not controlled.
    pub fn reset(&mut self) {
        self.selector.reset();
        self.force_active = false;
    }

    /// A force law's step report: whether force was controlled, and the tool's state if the
    /// step computed it.
    #[must_use]
    pub fn report<const N: usize>(&self, tool: Option<super::ToolState>) -> super::StepReport<N> {
        super::StepReport {
            force_controlled: self.force_active,
            tool,
            ..super::StepReport::default()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::control::selection::ContactSwitch;
    use crate::model::JointVector;
    use crate::surface::SurfaceGeometry;
    use crate::target::{CartesianTarget, JointTarget};
    use nalgebra::{UnitQuaternion, Vector6};

    fn reading(selection: SelectionPolicy, t: f64, f_z: f64, tool_z: f64) -> NormalReading {
        let frame = TaskFrame::Surface(SurfaceGeometry::plane(
            Vector3::zeros(),
            Vector3::z(),
            [1.0, 1.0],
        ));
        let mut s = NormalSelector::new(frame, selection);
        let q = JointVector::<1>::zeros();
        let target = JointTarget::at_rest(q);
        let c = CartesianTarget::at_rest(Vector3::new(0.0, 0.0, -0.01), UnitQuaternion::identity());
        let w = Vector6::new(0.0, 0.0, f_z, 0.0, 0.0, 0.0);
        let w_ref = Vector6::new(0.0, 0.0, -50.0, 0.0, 0.0, 0.0);
        let input = ControllerInput {
            t,
            q: &q,
            qd: &q,
            target: &target,
            cartesian: &c,
            wrench: &w,
            wrench_ref: &w_ref,
            wrench_age_s: 0.0,
        };
        let r = s.read(&input, &Vector3::new(0.0, 0.0, tool_z), 1e-3);
        assert_eq!(s.force_active(), r.forcing());
        r
    }

    #[test]
    fn the_reading_names_the_forces_and_heights_along_the_normal() {
        let r = reading(SelectionPolicy::Time { switch_s: 1.0 }, 2.0, -20.0, 0.003);
        assert_eq!((r.n, r.f_n, r.reference_n), (Vector3::z(), -20.0, -50.0));
        assert!((r.tool_gap.unwrap() - 0.003).abs() < 1e-15);
        assert!((r.reference_gap.unwrap() + 0.01).abs() < 1e-15);
        assert_eq!(r.f_d, -50.0);
        let before = reading(SelectionPolicy::Time { switch_s: 1.0 }, 0.5, -20.0, 0.003);
        assert!(!before.forcing());
    }

    #[test]
    fn contact_switching_starts_the_ramp_from_the_measured_force() {
        let mut c = ContactSwitch::for_sensor(0.0, 0.0);
        c.debounce_s = 1e-3; // one period
        let r = reading(SelectionPolicy::Contact(c), 0.0, -20.0, -0.001);
        assert!(r.forcing());
        // At the switch the force reference is the measured force; it ramps to -50 N.
        assert_eq!(r.f_d, -20.0);
        // Without a push, position control (approaching: the reference is below the surface).
        let r = reading(SelectionPolicy::Contact(c), 0.0, 0.0, 0.002);
        assert!(matches!(r.decision, Decision::Position { .. }));
    }
}
