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
use super::normal_reading::{linear, NormalReading, NormalSelector};
use super::selection::{Decision, SelectionPolicy};
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

    /// One period of `dt` s: `M_a d'' + D_a d' = f_d - f` with the error held (exact, stable
    /// for any period; `d'` relaxes towards `(f_d - f) / D_a`). Returns the height `d` (m)
    /// and its rate (m/s).
    pub fn advance(&mut self, s: &NormalSample, dt: f64) -> (f64, f64) {
        let g = &self.gains;
        let decay = libm::exp(-g.damping * dt / g.mass_kg);
        let goal = (s.f_d - s.f) / g.damping;
        self.height_m += goal * dt + (self.rate_m_s - goal) * (1.0 - decay) * g.mass_kg / g.damping;
        self.rate_m_s = goal + (self.rate_m_s - goal) * decay;
        (self.height_m, self.rate_m_s)
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
        let (height_m, rate_m_s) = self.advance(s, dt);
        NormalCommand::Height { height_m, rate_m_s }
    }
}

/// Where an admittance puts the position loop's target along the normal at one sample.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TargetShift {
    /// Before force control: the selector's approach, the target `offset_m` (m) from the
    /// reference along `n` at `rate_m_s` (m/s; both negative: into the surface).
    FromReference {
        /// m.
        offset_m: f64,
        /// m/s.
        rate_m_s: f64,
    },
    /// Under force control: the virtual mass-damper's height (m) above the expected surface
    /// and its rate (m/s).
    AboveSurface {
        /// m.
        height_m: f64,
        /// m/s.
        rate_m_s: f64,
    },
}

/// The state an admittance carries along the normal: the virtual mass-damper, and the
/// approach's displacement of the target from the reference, from which the mass-damper
/// starts at the switch (bumpless). Shared by the law in the task rows ([`Admittance`]) and
/// in the full task frame ([`TaskSpaceAdmittance`](super::task_space_admittance)).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AdmittanceState {
    law: NormalAdmittance,
    offset_m: f64,
    rate_m_s: f64,
}

impl AdmittanceState {
    /// At rest on the reference.
    #[must_use]
    pub fn new(gains: AdmittanceGains) -> Self {
        Self {
            law: NormalAdmittance::new(gains),
            offset_m: 0.0,
            rate_m_s: 0.0,
        }
    }

    /// Back to rest.
    pub fn reset(&mut self) {
        self.law.reset();
        self.offset_m = 0.0;
        self.rate_m_s = 0.0;
    }

    /// The approach's displacement of the target from the reference along `n`, m and m/s
    /// (before force control).
    #[must_use]
    pub fn offset(&self) -> (f64, f64) {
        (self.offset_m, self.rate_m_s)
    }

    /// One sample: `reading` as the force law read it, `v_n` the tool's velocity along `n`
    /// (m/s), `reference_rate_n` the reference's (m/s), after `dt` s.
    pub fn step(
        &mut self,
        reading: &NormalReading,
        v_n: f64,
        reference_rate_n: f64,
        dt: f64,
    ) -> TargetShift {
        match reading.decision {
            Decision::Position {
                offset_m,
                offset_rate_m_s,
            } => {
                self.offset_m = -offset_m;
                self.rate_m_s = -offset_rate_m_s;
                TargetShift::FromReference {
                    offset_m: self.offset_m,
                    rate_m_s: self.rate_m_s,
                }
            }
            Decision::Force { just_switched, .. } => {
                let sample = NormalSample {
                    f_d: reading.f_d,
                    f: reading.f_n,
                    v: v_n,
                    height_m: reading.tool_gap.unwrap_or(0.0),
                };
                if just_switched {
                    // Continue from the target's height above the surface, at its rate.
                    self.law.start(
                        &sample,
                        self.offset_m + reading.reference_gap.unwrap_or(0.0),
                        self.rate_m_s + reference_rate_n,
                    );
                }
                let (height_m, rate_m_s) = self.law.advance(&sample, dt);
                TargetShift::AboveSurface { height_m, rate_m_s }
            }
        }
    }
}

/// Admittance control around a position controller `P`, with the task frame and the
/// selection (time or contact, force ramp) of the hybrid law.
#[derive(Clone, Debug)]
pub struct Admittance<const N: usize, R, P> {
    robot: R,
    position: P,
    state: AdmittanceState,
    switch: NormalSelector,
    rows: TaskRows<N>,
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
            state: AdmittanceState::new(gains),
            switch: NormalSelector::new(frame, selection),
            rows: TaskRows::new(rows)?,
        })
    }

    /// The approach's displacement of the target from the reference along the normal, m
    /// and m/s (before force control).
    #[must_use]
    pub fn offset(&self) -> (f64, f64) {
        self.state.offset()
    }
}

impl<const N: usize, R: RobotModel<N>, P: Controller<N>> Controller<N> for Admittance<N, R, P> {
    fn name(&self) -> &'static str {
        "admittance"
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
        let j = self.robot.jacobian(input.q);
        let pose = self.robot.end_effector_pose(input.q);
        let p = Vector3::new(pose[(0, 3)], pose[(1, 3)], pose[(2, 3)]);
        let reading = self.switch.read(input, &p, dt);
        let n = reading.n;
        let c = input.cartesian;
        let v_n = if reading.forcing() {
            let twist: Wrench = j * input.qd;
            n.dot(&linear(&twist))
        } else {
            0.0
        };
        // The target's displacement along n from the reference: during the approach the
        // selector's; under force control the virtual mass-damper's position relative
        // to the expected surface under the tool (the reference's own normal motion is
        // dropped), or to the reference where the surface does not cover the tool.
        let reference_rate_n = n.dot(&c.velocity);
        let (shift, shift_rate) = match (
            self.state.step(&reading, v_n, reference_rate_n, dt),
            reading.reference_gap,
            reading.tool_gap,
        ) {
            (TargetShift::FromReference { offset_m, rate_m_s }, ..) => (offset_m, rate_m_s),
            // The target's height above the surface; the reference is at its gap.
            (TargetShift::AboveSurface { height_m, rate_m_s }, Some(r), Some(_)) => {
                (height_m - r, rate_m_s - reference_rate_n)
            }
            (TargetShift::AboveSurface { height_m, rate_m_s }, ..) => (height_m, rate_m_s),
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
