//! Admittance control: an outer loop turns the normal force error into a motion of the
//! position reference through a virtual mass and damper, and the position loop (any
//! [`Controller`], the thesis's PID with feedback linearization in the scenarios) tracks
//! the moved reference.
//!
//! ```text
//! M_a d'' + D_a d' = f_d - f        (d: the target's height above the expected surface, m)
//! target = reference, its normal component replaced by the surface's + d (through J^-1)
//! ```
//!
//! `f`, `f_d` are normal forces of the tool on the surface (negative = pressing); a push
//! short of the target moves the reference further in. At rest `f = f_d` whatever the
//! surface's height or stiffness: the damper integrates the error.

use nalgebra::Vector3;

use super::normal_law::{NormalCommand, NormalLaw, NormalSample};
use super::selection::{ramped_force, Decision, ModeSelector, SelectionPolicy};
use super::task_frame::TaskFrame;
use super::task_rows::TaskRows;
use super::{Controller, ControllerInput};
use crate::model::{JointVector, RobotModel, Wrench};

/// The virtual mass-damper.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AdmittanceGains {
    /// Virtual mass, kg (> 0).
    pub mass_kg: f64,
    /// Virtual damping, N s/m (> 0).
    pub damping: f64,
}

/// The admittance's virtual mass-damper as a [`NormalLaw`]: its state is the position
/// loop's target height above the expected surface, driven by the force error.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NormalAdmittance {
    gains: AdmittanceGains,
    height_m: f64,
    rate_m_s: f64,
}

impl NormalAdmittance {
    /// At rest on the surface.
    #[must_use]
    pub fn new(gains: AdmittanceGains) -> Self {
        Self {
            gains,
            height_m: 0.0,
            rate_m_s: 0.0,
        }
    }
}

impl NormalLaw for NormalAdmittance {
    fn name(&self) -> &'static str {
        "admittance"
    }

    fn reset(&mut self) {
        self.height_m = 0.0;
        self.rate_m_s = 0.0;
    }

    fn start(&mut self, _sample: &NormalSample, height_m: f64, rate_m_s: f64) {
        self.height_m = height_m;
        self.rate_m_s = rate_m_s;
    }

    fn step(&mut self, s: &NormalSample, dt: f64) -> NormalCommand {
        // M_a d'' + D_a d' = f_d - f over one period with the error held: exact (stable
        // for any period), d' relaxing towards (f_d - f) / D_a.
        let g = &self.gains;
        let decay = libm::exp(-g.damping * dt / g.mass_kg);
        let goal = (s.f_d - s.f) / g.damping;
        self.height_m += goal * dt + (self.rate_m_s - goal) * (1.0 - decay) * g.mass_kg / g.damping;
        self.rate_m_s = goal + (self.rate_m_s - goal) * decay;
        NormalCommand::Height {
            height_m: self.height_m,
            rate_m_s: self.rate_m_s,
        }
    }
}

/// Admittance control around a position controller `P`, with the task frame and the
/// selection (time or contact, force ramp) of the hybrid law.
#[derive(Clone, Debug)]
pub struct Admittance<const N: usize, R, P> {
    robot: R,
    position: P,
    law: NormalAdmittance,
    frame: TaskFrame,
    selector: ModeSelector,
    rows: TaskRows<N>,
    offset_m: f64,
    rate_m_s: f64,
    force_active: bool,
}

impl<const N: usize, R: RobotModel<N>, P: Controller<N>> Admittance<N, R, P> {
    /// `rows` as for [`HybridForcePosition`](super::hybrid::HybridForcePosition); `None`
    /// if they are not a valid choice.
    #[must_use]
    pub fn new(
        robot: R,
        position: P,
        gains: AdmittanceGains,
        frame: TaskFrame,
        selection: SelectionPolicy,
        rows: [usize; N],
    ) -> Option<Self> {
        Some(Self {
            robot,
            position,
            law: NormalAdmittance::new(gains),
            frame,
            selector: ModeSelector::new(selection),
            rows: TaskRows::new(rows)?,
            offset_m: 0.0,
            rate_m_s: 0.0,
            force_active: false,
        })
    }

    /// The approach's displacement of the target from the reference along the normal, m
    /// and m/s (before force control).
    #[must_use]
    pub fn offset(&self) -> (f64, f64) {
        (self.offset_m, self.rate_m_s)
    }
}

impl<const N: usize, R: RobotModel<N>, P: Controller<N>> Controller<N> for Admittance<N, R, P> {
    fn name(&self) -> &'static str {
        "admittance"
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
        let j = self.robot.jacobian(input.q);
        let pose = self.robot.end_effector_pose(input.q);
        let p = Vector3::new(pose[(0, 3)], pose[(1, 3)], pose[(2, 3)]);
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
        // The target's displacement along n from the reference: during the approach the
        // selector's; under force control the virtual mass-damper's position relative
        // to the expected surface under the tool (the reference's own normal motion is
        // dropped), or to the reference where the surface does not cover the tool.
        let (shift, shift_rate) = match self
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
                (self.offset_m, self.rate_m_s)
            }
            Decision::Force {
                just_switched,
                ramp,
                from_n,
            } => {
                self.force_active = true;
                let wr = input.wrench_ref;
                let target_n = n.dot(&Vector3::new(wr[0], wr[1], wr[2]));
                let twist: Wrench = j * input.qd;
                let sample = NormalSample {
                    f_d: ramped_force(from_n, target_n, ramp),
                    f: f_n,
                    v: n.dot(&Vector3::new(twist[0], twist[1], twist[2])),
                    height_m: tool_gap.unwrap_or(0.0),
                };
                if just_switched {
                    // Continue from the target's height above the surface, at its rate.
                    self.law.start(
                        &sample,
                        self.offset_m + ref_gap.unwrap_or(0.0),
                        self.rate_m_s + n.dot(&c.velocity),
                    );
                }
                match (self.law.step(&sample, dt), ref_gap, tool_gap) {
                    // The target's height above the surface; the reference is at ref_gap.
                    (NormalCommand::Height { height_m, rate_m_s }, Some(r), Some(_)) => {
                        (height_m - r, rate_m_s - n.dot(&c.velocity))
                    }
                    (NormalCommand::Height { height_m, rate_m_s }, ..) => (height_m, rate_m_s),
                    (NormalCommand::Force(_), ..) => (self.offset_m, self.rate_m_s),
                }
            }
        };
        let factor = self.rows.factor(&j);
        let mut target = *input.target;
        target.q += factor.solve(&self.rows.lift(&(n * shift)));
        target.qd += factor.solve(&self.rows.lift(&(n * shift_rate)));
        self.position.step(
            &ControllerInput {
                target: &target,
                ..*input
            },
            dt,
        )
    }
}
