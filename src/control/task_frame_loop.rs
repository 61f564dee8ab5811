//! The motion loop in the full task frame, for any arm (operational space, Khatib's unified
//! motion and force control): task-space inverse dynamics ([`TaskMotion`]) toward the
//! reference moved along the normal, the orientation target holding the tool to the normal
//! ([`ToolOrientation`]), and a null-space posture on a redundant arm. With `s = [n; 0]` and
//! `P = I - s s^T`:
//!
//! ```text
//! e    = [p_t - p; log(R_d R^T)]            (P e under force control: the normal is the force law's)
//! a*   = a_t + Kd e' + Kp e + Ki int(e) - Jdot qd
//! F_m  = Lambda a*                           Lambda = (J M^-1 J^T)^-1
//! tau  = J^T (F_m + df) + (I - J^T Lambda J M^-1) M (Kp0 (q_d - q) + Kd0 (qd_d - qd)) + c + g
//! ```
//!
//! The gravity along the normal is compensated with the rest (`c + g` in joint space). Every
//! matrix is fixed-size; the step never allocates.

use nalgebra::{SMatrix, Vector3, Vector6};

use super::motion_loop::{Motion, MotionLoop, NormalTarget};
use super::normal_reading::NormalReading;
use super::task_space::{OperationalSpace, TaskMotion, TaskSample, TaskSpaceGains};
use super::tool_orientation::ToolOrientation;
use super::{ControllerInput, ToolState};
use crate::model::{JointVector, RobotModel};

/// Task-space inverse dynamics in the full task frame with the orientation rule `tool` (see
/// the [module documentation](self)).
#[derive(Clone, Debug)]
pub struct TaskFrameLoop {
    motion: TaskMotion,
    tool: ToolOrientation,
}

/// A [`TaskFrameLoop`]'s command: the wrench `F_m` and the operational-space quantities it
/// becomes torque through.
pub struct TaskCommand<const N: usize> {
    space: OperationalSpace<N>,
    f: Vector6<f64>,
}

impl TaskFrameLoop {
    /// Robot `R`'s task with the motion `gains` and the orientation rule `tool`; `None` if the
    /// task lacks a translation (the normal must be among its directions).
    #[must_use]
    pub fn new<const N: usize, R: RobotModel<N>>(
        gains: TaskSpaceGains,
        tool: ToolOrientation,
    ) -> Option<Self> {
        let mask = R::TASK.mask();
        if mask[0] != 1.0 || mask[1] != 1.0 || mask[2] != 1.0 {
            return None;
        }
        Some(Self {
            motion: TaskMotion::new::<N, R>(gains),
            tool,
        })
    }

    /// The orientation rule.
    #[must_use]
    pub fn tool(&self) -> ToolOrientation {
        self.tool
    }
}

impl<const N: usize> MotionLoop<N> for TaskFrameLoop {
    type Sample = TaskSample<N>;
    type Command = TaskCommand<N>;
    const FULL_FRAME: bool = true;

    #[inline(always)]
    fn sample<R: RobotModel<N>>(
        &self,
        robot: &R,
        input: &ControllerInput<'_, N>,
    ) -> (ToolState, TaskSample<N>) {
        let s = self.motion.sample(robot, input.q, input.qd);
        let tool = ToolState {
            position: s.position,
            // The task controls all three translations (`Self::new`).
            velocity: Vector3::new(s.twist[0], s.twist[1], s.twist[2]),
        };
        (tool, s)
    }

    #[inline(always)]
    fn command<R: RobotModel<N>>(
        &mut self,
        robot: &R,
        input: &ControllerInput<'_, N>,
        s: &TaskSample<N>,
        _tool: &ToolState,
        reading: &NormalReading,
        target: NormalTarget,
        dt: f64,
    ) -> Motion<TaskCommand<N>, N> {
        let (q, qd) = (input.q, input.qd);
        let (c, n) = (input.cartesian, reading.n);
        let mut moved = *c;
        if let NormalTarget::Moved {
            offset_m,
            rate_m_s,
            drop_normal_acceleration,
        } = target
        {
            moved.position += n * offset_m;
            moved.velocity += n * rate_m_s;
            if drop_normal_acceleration {
                moved.acceleration -= n * n.dot(&c.acceleration);
            }
        }
        let forcing = reading.forcing();
        let gap = if forcing { None } else { reading.reference_gap };
        let r_d = self.tool.target_at(&c.orientation, &n, gap, forcing);
        let free = (target == NormalTarget::Free).then_some(&n);
        match self.motion.wrench(robot, q, qd, s, &moved, &r_d, free, dt) {
            Some((space, f)) => Motion::Command {
                normal_n: n.dot(&Vector3::new(f[0], f[1], f[2])),
                command: TaskCommand { space, f },
            },
            None => Motion::Torque(robot.mass_matrix_and_bias(q, qd).1),
        }
    }

    #[inline(always)]
    fn torque<R: RobotModel<N>>(
        &self,
        _robot: &R,
        input: &ControllerInput<'_, N>,
        _s: &TaskSample<N>,
        command: TaskCommand<N>,
        df: Option<&Vector3<f64>>,
    ) -> JointVector<N> {
        let mut f = command.f;
        if let Some(df) = df {
            for k in 0..3 {
                f[k] += df[k];
            }
        }
        self.motion
            .torque(&command.space, &f, input.q, input.qd, input.target)
    }

    #[inline(always)]
    fn gravity_along_normal<R: RobotModel<N>>(
        &self,
        _robot: &R,
        _input: &ControllerInput<'_, N>,
        _command: &TaskCommand<N>,
    ) -> f64 {
        0.0
    }

    #[inline(always)]
    fn linear_jacobian(&self, s: &TaskSample<N>) -> SMatrix<f64, 3, N> {
        s.j.fixed_rows::<3>(0).into_owned()
    }

    fn reset(&mut self) {
        self.motion.reset();
    }

    // The integral of the task error per task row (m s, rad s).
    super::pass_on_state!(motion);
}
