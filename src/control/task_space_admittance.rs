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

use nalgebra::Vector3;

use super::admittance::{AdmittanceGains, NormalAdmittance};
use super::normal_law::{NormalCommand, NormalLaw, NormalSample};
use super::selection::{ramped_force, Decision, ModeSelector, SelectionPolicy};
use super::task_frame::TaskFrame;
use super::task_space_hybrid::ToolOrientation;
use super::{Controller, ControllerInput};
use crate::model::{JointVector, RobotModel, Wrench};

/// Admittance around a task-space position law `P` (see the [module documentation](self)).
#[derive(Clone, Debug)]
pub struct TaskSpaceAdmittance<const N: usize, R, P> {
    robot: R,
    position: P,
    law: NormalAdmittance,
    frame: TaskFrame,
    tool: ToolOrientation,
    selector: ModeSelector,
    offset_m: f64,
    rate_m_s: f64,
    force_active: bool,
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
            law: NormalAdmittance::new(gains),
            frame,
            tool,
            selector: ModeSelector::new(selection),
            offset_m: 0.0,
            rate_m_s: 0.0,
            force_active: false,
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
        self.selector.reset();
        self.law.reset();
        self.offset_m = 0.0;
        self.rate_m_s = 0.0;
        self.force_active = false;
    }

    fn report(&self) -> super::StepReport<N> {
        super::StepReport {
            force_controlled: self.force_active,
            ..super::StepReport::default()
        }
    }

    fn step(&mut self, input: &ControllerInput<'_, N>, dt: f64) -> JointVector<N> {
        let pose = self.robot.end_effector_pose(input.q);
        let p = pose.fixed_view::<3, 1>(0, 3).into_owned();
        let n = self.frame.normal_at(&p);
        let w: &Wrench = input.wrench;
        let f_n = n.dot(&Vector3::new(w[0], w[1], w[2]));
        let contact_mode = matches!(self.selector.policy(), SelectionPolicy::Contact(_));
        let c = input.cartesian;
        let ref_gap = self.frame.signed_distance(&c.position);
        let tool_gap = self.frame.signed_distance(&p);
        let (ref_seen, tool_seen) = if contact_mode {
            (ref_gap, tool_gap)
        } else {
            (None, None)
        };
        let mut target = *c;
        match self
            .selector
            .step(input.t, dt, -f_n, f_n, ref_seen, tool_seen)
        {
            Decision::Position {
                offset_m,
                offset_rate_m_s,
            } => {
                self.force_active = false;
                self.offset_m = -offset_m;
                self.rate_m_s = -offset_rate_m_s;
                target.position += n * self.offset_m;
                target.velocity += n * self.rate_m_s;
            }
            Decision::Force {
                just_switched,
                ramp,
                from_n,
            } => {
                self.force_active = true;
                let wr = input.wrench_ref;
                let target_n = n.dot(&Vector3::new(wr[0], wr[1], wr[2]));
                let twist: Wrench = self.robot.jacobian(input.q) * input.qd;
                let sample = NormalSample {
                    f_d: ramped_force(from_n, target_n, ramp),
                    f: f_n,
                    v: n.dot(&Vector3::new(twist[0], twist[1], twist[2])),
                    height_m: tool_gap.unwrap_or(0.0),
                };
                let h_ref = ref_gap.unwrap_or(0.0);
                let v_ref_n = n.dot(&c.velocity);
                if just_switched {
                    // Continue from the target's height above the surface, at its rate.
                    self.law
                        .start(&sample, self.offset_m + h_ref, self.rate_m_s + v_ref_n);
                }
                if let NormalCommand::Height { height_m, rate_m_s } = self.law.step(&sample, dt) {
                    target.position += n * (height_m - h_ref);
                    target.velocity += n * (rate_m_s - v_ref_n);
                    target.acceleration -= n * n.dot(&c.acceleration);
                }
            }
        }
        target.orientation = self
            .tool
            .target_at(&c.orientation, &n, ref_gap, self.force_active);
        self.position.step(
            &ControllerInput {
                cartesian: &target,
                ..*input
            },
            dt,
        )
    }
}
