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
