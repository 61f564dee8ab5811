//! Hybrid force/position control (thesis Section 5.2, eq. 5.4), written once for every arm,
//! motion loop and force law:
//!
//! ```text
//! tau = J^T ( S J^-T tau_p  +  (I - S) f_f )
//! ```
//!
//! `S` selects motion control in the tangent directions of a task frame and force control
//! along its outward normal `n` ([`TaskFrame`]), from a time or from detected contact on
//! ([`SelectionPolicy`], read with the forces and heights along `n` by [`NormalSelector`]).
//! The motion directions are a [`MotionLoop`]'s: the thesis's joint-space position loop
//! through the square task rows ([`JointLoop`]; the SCARA's `x y z yaw` is its four-row case)
//! or task-space inverse dynamics in the full task frame ([`TaskFrameLoop`]). Along `n` a
//! [`NormalLaw`] commands either
//!
//! - a force ([`NormalCommand::Force`]; the thesis's PI + feedforward (+ velocity damping),
//!   [`ForcePi`]): the loop's target follows the tool along `n` and the normal row of its
//!   wrench is replaced,
//!
//!   ```text
//!   F = F_m - n (n . F_m) + n (f_f + g_n) + f_friction,     tau = J^T F (+ the loop's terms)
//!   ```
//!
//!   with `g_n` the model's gravity along `n` (optional, off in the thesis's law) and
//!   `f_friction = mu |f_n| t_d` the optional friction feedforward along the reference's
//!   tangential direction `t_d`; or
//! - a height above the expected surface ([`NormalCommand::Height`]; the admittance's
//!   virtual mass-damper, [`NormalAdmittance`](super::admittance::NormalAdmittance)): the
//!   loop's target is moved there along `n` and the loop's wrench is used as it is.
//!
//! With contact switching the switch is bumpless: the force command starts at the loop's last
//! normal force and the difference fades out over the force reference's ramp; a height law
//! starts from the target's height and rate at the switch.

use super::force::ForcePi;
pub use super::jacobian_factor::{
    reduced_transpose_solve, JacobianFactor, JacobianSolve, MAX_DAMPING, SINGULARITY_THRESHOLD,
};
use super::joint_loop::JointLoop;
use super::motion_loop::{Motion, MotionLoop, NormalTarget};
use super::normal_law::{NormalCommand, NormalLaw, NormalSample, Windup};
use super::normal_reading::NormalSelector;
use super::selection::{Decision, ModeSelector, SelectionPolicy};
use super::task_frame::TaskFrame;
use super::task_frame_loop::TaskFrameLoop;
use super::task_space::TaskSpaceGains;
use super::tool_orientation::ToolOrientation;
use super::{Controller, ControllerInput, ToolState};
use crate::model::{JointVector, RobotModel};
use crate::surface::sliding_friction;

/// Hybrid force/motion control with the motion loop `M` and the force law `L` along the
/// normal (see the [module documentation](self)).
#[derive(Clone, Debug)]
pub struct HybridForcePosition<const N: usize, R, M, L = ForcePi> {
    robot: R,
    motion: M,
    law: L,
    switch: NormalSelector,
    friction_feedforward: f64,
    normal_gravity: bool,
    anti_windup: bool,
    reference_stiffness: Option<f64>,
    last_f_ref: Option<f64>,
    last_normal_command: f64,
    transfer_offset: f64,
    approach: (f64, f64),
    tool: Option<ToolState>,
}

/// The hybrid law on the thesis's motion loop: a joint-space position controller `P` through
/// the task rows.
pub type JointHybrid<const N: usize, R, P, L = ForcePi> =
    HybridForcePosition<N, R, JointLoop<N, P>, L>;

/// The hybrid law in the full task frame.
pub type TaskSpaceHybrid<const N: usize, R, L = ForcePi> =
    HybridForcePosition<N, R, TaskFrameLoop, L>;

impl<const N: usize, R: RobotModel<N>, P: Controller<N>, L: NormalLaw + Clone>
    HybridForcePosition<N, R, JointLoop<N, P>, L>
{
    /// The law with the joint-space position controller `position` acting through `rows`,
    /// the task rows of the 6 x N Jacobian kept (each in 0..6, distinct, including 0, 1 and
    /// 2), e.g. `[0, 1, 2, 5]` for a SCARA ([`TaskRows`](super::task_rows::TaskRows)).
    ///
    /// Returns `None` if `rows` repeats a row, names one outside 0..6 or lacks a linear row.
    #[must_use]
    pub fn new(
        robot: R,
        position: P,
        law: L,
        frame: TaskFrame,
        selection: SelectionPolicy,
        rows: [usize; N],
    ) -> Option<Self> {
        Some(Self::with_loop(
            robot,
            JointLoop::new(position, rows)?,
            law,
            frame,
            selection,
        ))
    }

    /// How `J^-T` was obtained at the last step.
    #[must_use]
    pub fn last_solve(&self) -> JacobianSolve {
        self.motion.last_solve()
    }
}

impl<const N: usize, R: RobotModel<N>, L: NormalLaw + Clone>
    HybridForcePosition<N, R, TaskFrameLoop, L>
{
    /// The law in the full task frame for `robot`'s task ([`RobotModel::TASK`], which must
    /// control all three translations) with the motion `gains` and the orientation rule
    /// `tool`. Returns `None` if the robot's task lacks a translation.
    #[must_use]
    pub fn in_task_frame(
        robot: R,
        gains: TaskSpaceGains,
        law: L,
        frame: TaskFrame,
        tool: ToolOrientation,
        selection: SelectionPolicy,
    ) -> Option<Self> {
        Some(Self::with_loop(
            robot,
            TaskFrameLoop::new::<N, R>(gains, tool)?,
            law,
            frame,
            selection,
        ))
    }
}

impl<const N: usize, R: RobotModel<N>, M: MotionLoop<N>, L: NormalLaw + Clone>
    HybridForcePosition<N, R, M, L>
{
    /// The law with the motion loop `motion`, the force law `law` along the normal of
    /// `frame`, switching by `selection`.
    #[must_use]
    pub fn with_loop(
        robot: R,
        motion: M,
        law: L,
        frame: TaskFrame,
        selection: SelectionPolicy,
    ) -> Self {
        Self {
            robot,
            motion,
            law,
            switch: NormalSelector::new(frame, selection),
            friction_feedforward: 0.0,
            normal_gravity: false,
            anti_windup: false,
            reference_stiffness: None,
            last_f_ref: None,
            last_normal_command: 0.0,
            transfer_offset: 0.0,
            approach: (0.0, 0.0),
            tool: None,
        }
    }

    /// Adds the friction feedforward with nominal Coulomb coefficient `mu` (0: none).
    #[must_use]
    pub fn with_friction_feedforward(mut self, mu: f64) -> Self {
        self.friction_feedforward = mu;
        self
    }

    /// Keeps the model's gravity along the normal in the force command (`g_n`): the thesis's
    /// law drops it with the position loop's normal row, and the force integral has to take it
    /// up slowly (the 48 N of d3's weight decaying with `(1 + Kfp) / Kfi = 4.2 s`). A loop that
    /// compensates gravity in joint space has none to keep.
    #[must_use]
    pub fn with_normal_gravity_compensation(mut self, on: bool) -> Self {
        self.normal_gravity = on;
        self
    }

    /// Conditional integration of the force law's integral (anti-windup,
    /// [`NormalLaw::limit_windup`]): a period whose integral increment would drive an
    /// actuator further past its limit (`RobotModel::EFFORT_LIMITS`) is not integrated, and
    /// its increment is taken out of that period's command. Off in the thesis's law.
    #[must_use]
    pub fn with_anti_windup(mut self, on: bool) -> Self {
        self.anti_windup = on;
        self
    }

    /// Velocity damping against the force reference's own motion: with the contact's
    /// stiffness `k` (N/m, the controller's belief), the tool must move along `n` at
    /// `v_ref = (d f_ref / dt) / k` for the force to follow the reference `f_ref` (a ramp or a
    /// profile of the scenario's; the switching ramp from the measured force stays damped),
    /// and the force law sees `v_n - v_ref` instead of `v_n`, so a moving force reference does
    /// not lag. `None` (the default): `v_n`, the thesis's law.
    #[must_use]
    pub fn with_reference_motion(mut self, stiffness: Option<f64>) -> Self {
        self.reference_stiffness = stiffness.filter(|k| k.is_finite() && *k > 0.0);
        self
    }

    /// The force law.
    #[must_use]
    pub fn force_law(&self) -> &L {
        &self.law
    }

    /// The motion loop.
    #[must_use]
    pub fn motion_loop(&self) -> &M {
        &self.motion
    }

    /// The switching state machine.
    #[must_use]
    pub fn selector(&self) -> &ModeSelector {
        self.switch.selector()
    }

    /// The torque of the motion loop's command, or the torque it settled on.
    #[inline(always)]
    fn torque_of(
        &self,
        input: &ControllerInput<'_, N>,
        sample: &M::Sample,
        motion: Motion<M::Command, N>,
    ) -> JointVector<N> {
        match motion {
            Motion::Torque(tau) => tau,
            Motion::Command { command, .. } => {
                self.motion
                    .torque(&self.robot, input, sample, command, None)
            }
        }
    }
}

impl<const N: usize, R: RobotModel<N>, M: MotionLoop<N>, L: NormalLaw + Clone> Controller<N>
    for HybridForcePosition<N, R, M, L>
{
    fn name(&self) -> &'static str {
        let (through_rows, full_frame) = self.law.controller_names();
        if M::FULL_FRAME {
            full_frame
        } else {
            through_rows
        }
    }

    /// The motion loop's state, the force law's, then (with damping against the force
    /// reference's motion) the previous normal force reference (N) and whether there is one
    /// (1 or 0). The bumpless-transfer offset is set once at the switch and is a constant
    /// afterwards, not a state.
    fn state_len(&self) -> usize {
        self.motion.state_len()
            + self.law.state_len()
            + if self.reference_stiffness.is_some() {
                2
            } else {
                0
            }
    }

    fn write_state(&self, out: &mut [f64]) {
        let k = self.motion.state_len();
        self.motion.write_state(&mut out[..k]);
        let l = k + self.law.state_len();
        self.law.write_state(&mut out[k..l]);
        if self.reference_stiffness.is_some() {
            out[l] = self.last_f_ref.unwrap_or(0.0);
            out[l + 1] = if self.last_f_ref.is_some() { 1.0 } else { 0.0 };
        }
    }

    fn read_state(&mut self, x: &[f64]) {
        let k = self.motion.state_len();
        self.motion.read_state(&x[..k]);
        let l = k + self.law.state_len();
        self.law.read_state(&x[k..l]);
        if self.reference_stiffness.is_some() {
            self.last_f_ref = (x[l + 1] > 0.5).then_some(x[l]);
        }
    }

    fn reset(&mut self) {
        self.motion.reset();
        self.law.reset();
        self.switch.reset();
        self.last_f_ref = None;
        self.last_normal_command = 0.0;
        self.transfer_offset = 0.0;
        self.approach = (0.0, 0.0);
        self.tool = None;
    }

    fn report(&self) -> super::StepReport<N> {
        self.switch.report(self.tool)
    }

    fn step(&mut self, input: &ControllerInput<'_, N>, dt: f64) -> JointVector<N> {
        let (tool, sample) = self.motion.sample(&self.robot, input);
        self.tool = Some(tool);
        let reading = self.switch.read(input, &tool.position, dt);
        let (n, c) = (reading.n, input.cartesian);
        let (just_switched, ramp) = match reading.decision {
            Decision::Position {
                offset_m,
                offset_rate_m_s,
            } => {
                self.law.reset();
                self.last_f_ref = None;
                // The approach: the target moved `offset_m` into the surface along -n.
                self.approach = (-offset_m, -offset_rate_m_s);
                let target = if self.switch.contact_switching() {
                    NormalTarget::Moved {
                        offset_m: -offset_m,
                        rate_m_s: -offset_rate_m_s,
                        drop_normal_acceleration: false,
                    }
                } else {
                    NormalTarget::Reference
                };
                let motion =
                    self.motion
                        .command(&self.robot, input, &sample, &tool, &reading, target, dt);
                if let Motion::Command { normal_n, .. } = motion {
                    self.last_normal_command = normal_n;
                }
                return self.torque_of(input, &sample, motion);
            }
            Decision::Force {
                just_switched,
                ramp,
                ..
            } => (just_switched, ramp),
        };
        // The normal velocity the force reference itself asks for: from the motion of the
        // scenario's reference (a ramp, a profile), not from the switching ramp, which starts
        // at rest and must stay damped (zero at the switch and for a constant reference).
        let v_ref = match (self.reference_stiffness, self.last_f_ref) {
            (Some(k), Some(last)) if dt > 0.0 => (reading.reference_n - last) / dt / k,
            _ => 0.0,
        };
        self.last_f_ref = Some(reading.reference_n);
        let normal = NormalSample {
            f_d: reading.f_d,
            f: reading.f_n,
            v: n.dot(&tool.velocity) - v_ref,
            // The tool's height above the expected surface (or, for a frame that knows no
            // surface, above the reference along n).
            height_m: reading
                .tool_gap
                .unwrap_or_else(|| n.dot(&(tool.position - c.position))),
        };
        let reference_rate_n = n.dot(&c.velocity);
        if just_switched {
            // A law that moves the target continues from its height above the surface, at
            // its rate.
            self.law.start(
                &normal,
                self.approach.0 + reading.reference_gap.unwrap_or(0.0),
                self.approach.1 + reference_rate_n,
            );
        }
        let before = self.anti_windup.then(|| self.law.clone());
        let mut f_f = match self.law.step(&normal, dt) {
            NormalCommand::Force(f) => f,
            NormalCommand::Height { height_m, rate_m_s } => {
                // The target's height above the surface; the reference is at its own (or,
                // where the surface does not cover the tool, the height is the reference's).
                let (offset_m, rate_m_s) = match (reading.reference_gap, reading.tool_gap) {
                    (Some(r), Some(_)) => (height_m - r, rate_m_s - reference_rate_n),
                    _ => (height_m, rate_m_s),
                };
                let target = NormalTarget::Moved {
                    offset_m,
                    rate_m_s,
                    drop_normal_acceleration: true,
                };
                let motion =
                    self.motion
                        .command(&self.robot, input, &sample, &tool, &reading, target, dt);
                return self.torque_of(input, &sample, motion);
            }
        };
        let (command, normal_n) = match self.motion.command(
            &self.robot,
            input,
            &sample,
            &tool,
            &reading,
            NormalTarget::Free,
            dt,
        ) {
            Motion::Torque(tau) => return tau,
            Motion::Command { command, normal_n } => (command, normal_n),
        };
        let g_n = if self.normal_gravity {
            self.motion
                .gravity_along_normal(&self.robot, input, &command)
        } else {
            0.0
        };
        if just_switched {
            // Bumpless: the normal command starts where the motion loop left off; the
            // difference fades out over the force ramp.
            self.transfer_offset = self.last_normal_command - g_n - f_f;
        }
        if ramp < 1.0 {
            f_f += self.transfer_offset * (1.0 - ramp);
        }
        // F = F_m + df: the motion loop's wrench with its normal component replaced by the
        // force command (and the friction feedforward added).
        let mut df = n * (f_f + g_n - normal_n);
        if self.friction_feedforward > 0.0 {
            let vt = c.velocity - n * n.dot(&c.velocity);
            df += sliding_friction(self.friction_feedforward, (-reading.f_n).max(0.0), &vt);
        }
        let tau = self
            .motion
            .torque(&self.robot, input, &sample, command, Some(&df));
        match before {
            Some(before) => {
                let j_v = self.motion.linear_jacobian(&sample);
                let at = Windup {
                    tau,
                    j_v: &j_v,
                    n: &n,
                    effort_limits: &R::EFFORT_LIMITS,
                };
                self.law.limit_windup(&before, at)
            }
            None => tau,
        }
    }
}
