//! Admittance control in the full task frame for any arm: the normal force error moves the
//! Cartesian reference along the surface's normal through a virtual mass and damper, the
//! orientation target holds the tool to the normal, and a task-space position law (the
//! operational-space law of [`TaskSpaceInverseDynamics`](super::task_space), with its
//! null-space posture on a redundant arm) tracks the moved pose.
//!
//! ```text
//! M_a d'' + D_a d' = f_d - f          d: the target's height above the expected surface, m
//! p_t = p_ref + n (d - h_ref)         h_ref: the reference's height above it
//! v_t = v_ref - n (n . v_ref) + n d'
//! R_t = Rot(R_ref a -> -n) R_ref      (ToolOrientation)
//! ```
//!
//! As for the SCARA's [`Admittance`](super::admittance): at rest `f = f_d` whatever the
//! surface's height or stiffness; during the approach the target is the selector's (the
//! reference moved along `-n`), and the mass-damper starts from the target's height and rate
//! at the switch. The reference's normal acceleration is dropped under force control.
//!
//! The step adds to the position law's no allocation.

use super::admittance::{AdmittanceGains, AdmittanceState, TargetShift};
use super::normal_reading::{linear, NormalSelector};
use super::selection::SelectionPolicy;
use super::task_frame::TaskFrame;
use super::tool_orientation::ToolOrientation;
use super::{Controller, ControllerInput};
use crate::model::{JointVector, RobotModel, Wrench};

/// Admittance around a task-space position law `P` (see the [module documentation](self)).
#[derive(Clone, Debug)]
pub struct TaskSpaceAdmittance<const N: usize, R, P> {
    robot: R,
    position: P,
    state: AdmittanceState,
    tool: ToolOrientation,
    switch: NormalSelector,
}

impl<const N: usize, R: RobotModel<N>, P: Controller<N>> TaskSpaceAdmittance<N, R, P> {
    /// The admittance with `gains` around `position` (a law that tracks the Cartesian
    /// reference), the orientation rule `tool`, switching by `selection`.
    #[must_use]
    pub fn new(
        robot: R,
        position: P,
        gains: AdmittanceGains,
        frame: TaskFrame,
        tool: ToolOrientation,
        selection: SelectionPolicy,
    ) -> Self {
        Self {
            robot,
            position,
            state: AdmittanceState::new(gains),
            tool,
            switch: NormalSelector::new(frame, selection),
        }
    }
}

impl<const N: usize, R: RobotModel<N>, P: Controller<N>> Controller<N>
    for TaskSpaceAdmittance<N, R, P>
{
    fn name(&self) -> &'static str {
        "task-space-admittance"
    }

    fn reset(&mut self) {
        self.position.reset();
        self.switch.reset();
        self.state.reset();
    }

    fn report(&self) -> super::StepReport<N> {
        self.switch.report(None)
    }

    fn step(&mut self, input: &ControllerInput<'_, N>, dt: f64) -> JointVector<N> {
        let pose = self.robot.end_effector_pose(input.q);
        let p = pose.fixed_view::<3, 1>(0, 3).into_owned();
        let reading = self.switch.read(input, &p, dt);
        let n = reading.n;
        let c = input.cartesian;
        let v_n = if reading.forcing() {
            let twist: Wrench = self.robot.jacobian(input.q) * input.qd;
            n.dot(&linear(&twist))
        } else {
            0.0
        };
        let reference_rate_n = n.dot(&c.velocity);
        let mut target = *c;
        match self.state.step(&reading, v_n, reference_rate_n, dt) {
            TargetShift::FromReference { offset_m, rate_m_s } => {
                target.position += n * offset_m;
                target.velocity += n * rate_m_s;
            }
            TargetShift::AboveSurface { height_m, rate_m_s } => {
                let h_ref = reading.reference_gap.unwrap_or(0.0);
                target.position += n * (height_m - h_ref);
                target.velocity += n * (rate_m_s - reference_rate_n);
                target.acceleration -= n * n.dot(&c.acceleration);
            }
        }
        target.orientation =
            self.tool
                .target_at(&c.orientation, &n, reading.reference_gap, reading.forcing());
        self.position.step(
            &ControllerInput {
                cartesian: &target,
                ..*input
            },
            dt,
        )
    }
}
