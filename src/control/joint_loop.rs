//! The motion loop of the thesis's hybrid law: a joint-space position controller `P` (PID
//! with feedback linearization in the thesis) acting through the robot's N task rows of the
//! Jacobian ([`TaskRows`]; `vx vy vz wz` for the SCARA), square, so that `J_r^-1` moves its
//! target along the normal and `J_r^-T` reads its torque as a wrench:
//!
//! ```text
//! a       = J_r^-1 n                       the joint motion per metre along n (one solve)
//! q_t     = q_d + a h,  qd_t = qd_d + a h'  the target moved h along n
//! n . F_m = n . J_r^-T tau_p = a . tau_p    the position loop's force along n
//! tau     = J_r^T J_r^-T tau_p + J_v^T df   (= tau_p + J_v^T df unless the solve is damped)
//! ```
//!
//! Under force control the target is moved onto the tool, `h = n . (p - p_d)`, so the
//! position loop sees only the tangential errors. Singularities are handled explicitly
//! ([`JacobianFactor`]).

use nalgebra::{SMatrix, Vector3};

use super::jacobian_factor::{JacobianFactor, JacobianSolve};
use super::motion_loop::{Motion, MotionLoop, NormalTarget};
use super::normal_reading::NormalReading;
use super::task_rows::TaskRows;
use super::{Controller, ControllerInput, ToolState};
use crate::model::{Jacobian, JointVector, RobotModel};

/// A joint-space position controller `P` through the task rows (see the [module
/// documentation](self)).
#[derive(Clone, Debug)]
pub struct JointLoop<const N: usize, P> {
    position: P,
    rows: TaskRows<N>,
    last_solve: JacobianSolve,
}

/// A [`JointLoop`]'s command: the position loop's torque and the factor it is read through.
#[derive(Clone, Copy, Debug)]
pub struct JointCommand<const N: usize> {
    tau_p: JointVector<N>,
    factor: JacobianFactor<f64, N>,
    along_n: JointVector<N>,
}

impl<const N: usize, P: Controller<N>> JointLoop<N, P> {
    /// `position` through `rows`: the task rows of the 6 x N Jacobian kept (each in 0..6,
    /// distinct, including 0, 1 and 2), e.g. `[0, 1, 2, 5]` for a SCARA. `None` if `rows`
    /// repeats a row, names one outside 0..6 or lacks a linear row.
    #[must_use]
    pub fn new(position: P, rows: [usize; N]) -> Option<Self> {
        Some(Self {
            position,
            rows: TaskRows::new(rows)?,
            last_solve: JacobianSolve::NotNeeded,
        })
    }

    /// How `J_r^-T` was obtained at the last step under force control
    /// ([`JacobianSolve::NotNeeded`] under position control).
    #[must_use]
    pub fn last_solve(&self) -> JacobianSolve {
        self.last_solve
    }

    /// The position controller.
    #[must_use]
    pub fn position(&self) -> &P {
        &self.position
    }
}

impl<const N: usize, P: Controller<N>> MotionLoop<N> for JointLoop<N, P> {
    type Sample = Jacobian<N>;
    type Command = JointCommand<N>;
    const FULL_FRAME: bool = false;

    #[inline(always)]
    fn sample<R: RobotModel<N>>(
        &self,
        robot: &R,
        input: &ControllerInput<'_, N>,
    ) -> (ToolState, Jacobian<N>) {
        // J and the tool position p (m) in one call: the generated robots share sin/cos.
        let (j, p) = robot.jacobian_and_position(input.q);
        let tool = ToolState {
            position: p,
            // The tool's linear velocity (rows vx vy vz of J qd), m/s.
            velocity: j.fixed_rows::<3>(0) * input.qd,
        };
        (tool, j)
    }

    #[inline(always)]
    fn command<R: RobotModel<N>>(
        &mut self,
        _robot: &R,
        input: &ControllerInput<'_, N>,
        j: &Jacobian<N>,
        tool: &ToolState,
        reading: &NormalReading,
        target: NormalTarget,
        dt: f64,
    ) -> Motion<JointCommand<N>, N> {
        self.last_solve = JacobianSolve::NotNeeded;
        let (offset_m, rate_m_s) = match target {
            NormalTarget::Reference => return Motion::Torque(self.position.step(input, dt)),
            NormalTarget::Moved {
                offset_m, rate_m_s, ..
            } => (offset_m, rate_m_s),
            NormalTarget::Free => {
                let (n, c) = (&reading.n, input.cartesian);
                (
                    n.dot(&(tool.position - c.position)),
                    n.dot(&(tool.velocity - c.velocity)),
                )
            }
        };
        let factor = self.rows.factor(j);
        // The joint motion per metre along the normal (one solve serves q and qd).
        let along_n = factor.solve(&self.rows.lift(&reading.n));
        let mut moved = *input.target;
        moved.q += along_n * offset_m;
        moved.qd += along_n * rate_m_s;
        let tau_p = self.position.step(
            &ControllerInput {
                target: &moved,
                ..*input
            },
            dt,
        );
        if target == NormalTarget::Free {
            self.last_solve = factor.how();
        }
        Motion::Command {
            command: JointCommand {
                tau_p,
                factor,
                along_n,
            },
            // n . J^-T tau_p as (J^-1 n) . tau_p (damped alike: P^T and P).
            normal_n: along_n.dot(&tau_p),
        }
    }

    #[inline(always)]
    fn torque<R: RobotModel<N>>(
        &self,
        _robot: &R,
        _input: &ControllerInput<'_, N>,
        j: &Jacobian<N>,
        command: JointCommand<N>,
        df: Option<&Vector3<f64>>,
    ) -> JointVector<N> {
        let Some(df) = df else {
            return command.tau_p;
        };
        // tau = J^T f_cmd = J^T f_p + J^T df, with J^T f_p = tau_p unless damped. The linear
        // rows of J_r are rows 0, 1, 2 of J.
        let mut tau = command.factor.wrench_torque(&command.tau_p);
        for k in 0..3 {
            tau += j.row(k).transpose() * df[k];
        }
        tau
    }

    #[inline(always)]
    fn gravity_along_normal<R: RobotModel<N>>(
        &self,
        robot: &R,
        input: &ControllerInput<'_, N>,
        command: &JointCommand<N>,
    ) -> f64 {
        // n . J^-T g as (J^-1 n) . g.
        command.along_n.dot(&robot.gravity(input.q))
    }

    #[inline(always)]
    fn linear_jacobian(&self, j: &Jacobian<N>) -> SMatrix<f64, 3, N> {
        j.fixed_rows::<3>(0).into_owned()
    }

    fn reset(&mut self) {
        self.position.reset();
        self.last_solve = JacobianSolve::NotNeeded;
    }

    // The position controller's state.
    super::pass_on_state!(position);
}
