//! Task-space inverse dynamics (operational-space computed torque, Khatib), with a
//! null-space posture for a redundant arm.
//!
//! With `J` the task's rows of the geometric Jacobian (the other rows zero), `e` the pose
//! error in the task's directions ([`Task::pose_error`]: position, then the SO(3) logarithm
//! or the yaw difference) and `e' = v_d - J qd` the twist error:
//!
//! ```text
//! a*      = a_d + Kd e' + Kp e + Ki int(e) dt - Jdot qd  (task rows)
//! Lambda  = (J M^-1 J^T)^-1                              (the task-space inertia)
//! F       = Lambda a*
//! tau_0   = M (Kp0 (q_d - q) + Kd0 (qd_d - qd))           (the joint reference, joint space)
//! tau     = J^T F + (I - J^T Lambda J M^-1) tau_0 + c + g
//! ```
//!
//! With a correct model the task error obeys `e''' + Kd e'' + Kp e' + Ki e = 0` in each task
//! direction (to first order in the orientation error; `Ki = 0` without integral action, the
//! classical computed torque); the integral takes up what the model gets wrong at rest (a
//! payload's weight). `tau_0` acts only in the dynamically
//! consistent null space of the task: it moves the redundant joints without disturbing the
//! tool. Its target is the reference's joint setpoint, the inverse kinematics of the pose
//! nearest the scenario's posture, so the arm's self-motion follows the solution the
//! reference chose. For a robot with as many joints as task directions the null-space
//! projector is zero.
//!
//! Near a singularity of the task rows, `J M^-1 J^T` is damped by `lambda^2 I`, `lambda` as
//! in [`crate::kinematics::joint_rates`] (zero away from it). Gains are stated per task
//! direction.
//!
//! Every matrix is fixed-size; the step never allocates.

use nalgebra::{Cholesky, Matrix4, SMatrix, UnitQuaternion, Vector3, Vector6, U6};

use super::{Controller, ControllerInput};
use crate::model::{JointMatrix, JointVector, RobotModel};
use crate::target::{orientation, CartesianTarget, JointTarget, Task};

/// Below this normalised determinant of `J M^-1 J^T` (over the product of its diagonal) the
/// task-space inertia is damped.
pub const SINGULARITY_THRESHOLD: f64 = 1e-4;
/// The damping added to `J M^-1 J^T` at a singularity, relative to its mean diagonal.
pub const MAX_DAMPING: f64 = 1e-3;

/// Gains of [`TaskSpaceInverseDynamics`]: per Jacobian row (`vx vy vz wx wy wz`; rows outside
/// the task unused), and of the null-space posture.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TaskSpaceGains {
    /// Stiffness per task row, 1/s^2.
    pub kp: Vector6<f64>,
    /// Damping per task row, 1/s.
    pub kd: Vector6<f64>,
    /// Integral gain per task row, 1/s^3 (0: none).
    pub ki: Vector6<f64>,
    /// Posture stiffness, 1/s^2.
    pub posture_kp: f64,
    /// Posture damping, 1/s.
    pub posture_kd: f64,
}

impl TaskSpaceGains {
    /// Gains placing each of robot `R`'s task directions' error poles (`omega` in rad/s, one
    /// per direction, in the task's order): without integral action the pair
    /// `s^2 + 2 zeta omega s + omega^2` (`Kp = omega^2`, `Kd = 2 zeta omega`), with it that pair
    /// and a real pole at `-omega`, `(s^2 + 2 zeta omega s + omega^2)(s + omega)`
    /// (`Kd = (2 zeta + 1) omega`, `Kp = (1 + 2 zeta) omega^2`, `Ki = omega^3`); and a
    /// critically damped posture at `posture_omega` rad/s.
    ///
    /// ```
    /// use armdyn::control::task_space::TaskSpaceGains;
    /// use armdyn::model::Scara;
    /// let g = TaskSpaceGains::critically_damped::<4, Scara>(&[10.0, 10.0, 20.0, 5.0], 1.0, 8.0, false);
    /// assert_eq!((g.kp[2], g.kd[2], g.kp[5], g.kp[3], g.ki[2]), (400.0, 40.0, 25.0, 0.0, 0.0));
    /// let g = TaskSpaceGains::critically_damped::<4, Scara>(&[10.0; 4], 1.0, 8.0, true);
    /// assert_eq!((g.kp[0], g.kd[0], g.ki[0]), (300.0, 30.0, 1000.0));
    /// ```
    #[must_use]
    pub fn critically_damped<const N: usize, R: RobotModel<N>>(
        omega: &[f64],
        damping_ratio: f64,
        posture_omega: f64,
        integral: bool,
    ) -> Self {
        let mut kp = Vector6::zeros();
        let mut kd = Vector6::zeros();
        let mut ki = Vector6::zeros();
        for (w, r) in omega.iter().zip(R::TASK.rows()) {
            let z2 = 2.0 * damping_ratio;
            if integral {
                kd[r] = (z2 + 1.0) * w;
                kp[r] = (1.0 + z2) * w * w;
                ki[r] = w * w * w;
            } else {
                kp[r] = w * w;
                kd[r] = z2 * w;
            }
        }
        Self {
            kp,
            kd,
            ki,
            posture_kp: posture_omega * posture_omega,
            posture_kd: 2.0 * posture_omega,
        }
    }
}

/// The motion part of the task-space laws: the gains, the robot's task and the integral of
/// the task error, turned into the wrench `F = Lambda a*` toward a target and into torque
/// (see the [module documentation](self)). Shared by [`TaskSpaceInverseDynamics`] and the
/// force laws' [`TaskFrameLoop`](super::task_frame_loop::TaskFrameLoop).
#[derive(Clone, Debug)]
pub struct TaskMotion {
    gains: TaskSpaceGains,
    task: Task,
    integral: Vector6<f64>,
}

/// The kinematics of one sample of a task-space law: the tool pose, the task rows `J` of the
/// Jacobian (the others zero) and the tool twist `J qd`.
#[derive(Clone, Copy, Debug)]
pub struct TaskSample<const N: usize> {
    /// The tool pose, homogeneous 4 x 4, base frame.
    pub pose: Matrix4<f64>,
    /// The tool position, m.
    pub position: Vector3<f64>,
    /// The task rows of the Jacobian, the others zero.
    pub j: SMatrix<f64, 6, N>,
    /// `J qd` on the task rows, m/s and rad/s (the task controls all three translations or
    /// none of its linear rows is used: its first three are the tool's velocity).
    pub twist: Vector6<f64>,
}

impl TaskMotion {
    /// Robot `R`'s task ([`RobotModel::TASK`]) with `gains`.
    #[must_use]
    pub fn new<const N: usize, R: RobotModel<N>>(gains: TaskSpaceGains) -> Self {
        Self {
            gains,
            task: R::TASK,
            integral: Vector6::zeros(),
        }
    }

    /// The gains.
    #[must_use]
    pub fn gains(&self) -> &TaskSpaceGains {
        &self.gains
    }

    /// The robot's task.
    #[must_use]
    pub fn task(&self) -> &Task {
        &self.task
    }

    /// The kinematics at `(q, qd)`.
    #[must_use]
    #[inline(always)]
    pub fn sample<const N: usize, R: RobotModel<N>>(
        &self,
        robot: &R,
        q: &JointVector<N>,
        qd: &JointVector<N>,
    ) -> TaskSample<N> {
        let pose = robot.end_effector_pose(q);
        let j = task_rows(&self.task, robot.jacobian(q));
        TaskSample {
            pose,
            position: pose.fixed_view::<3, 1>(0, 3).into_owned(),
            j,
            twist: j * qd,
        }
    }

    /// `F = Lambda a*` toward `target` (its position, velocity and acceleration) with the
    /// orientation `r_d`, after `dt` s; with `free = Some(n)` the linear errors along `n` are
    /// removed (the normal is a force law's). The operational-space quantities with it;
    /// `None` if `M` or `Lambda^-1` is not positive definite.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    pub(crate) fn wrench<const N: usize, R: RobotModel<N>>(
        &mut self,
        robot: &R,
        q: &JointVector<N>,
        qd: &JointVector<N>,
        s: &TaskSample<N>,
        target: &CartesianTarget,
        r_d: &UnitQuaternion<f64>,
        free: Option<&Vector3<f64>>,
        dt: f64,
    ) -> Option<(OperationalSpace<N>, Vector6<f64>)> {
        let mask = self.task.mask();
        let mut e = self.task.pose_error(
            &target.position,
            r_d,
            &s.position,
            &orientation::of_pose(&s.pose),
        );
        let mut ed = target.twist() - s.twist;
        if let Some(n) = free {
            // Only the motion directions: the normal component of the linear errors is the
            // force law's.
            let e_n = n.dot(&Vector3::new(e[0], e[1], e[2]));
            let ed_n = n.dot(&Vector3::new(ed[0], ed[1], ed[2]));
            for k in 0..3 {
                e[k] -= n[k] * e_n;
                ed[k] -= n[k] * ed_n;
            }
        }
        self.integral += e.component_mul(&mask) * dt;
        let bias_acc = robot.jdot_qd(q, qd);
        let a_d = target.acceleration_twist();
        let a_star = Vector6::from_fn(|r, _| {
            mask[r]
                * (a_d[r]
                    + self.gains.kd[r] * ed[r]
                    + self.gains.kp[r] * e[r]
                    + self.gains.ki[r] * self.integral[r]
                    - bias_acc[r])
        });
        let space = OperationalSpace::new(robot, q, qd, s.j, &mask, self.task.len())?;
        let f = space.task_force(&a_star);
        Some((space, f))
    }

    /// `tau = J^T F + c + g`, and on a redundant arm the posture toward `posture` in the null
    /// space.
    #[must_use]
    #[inline(always)]
    pub(crate) fn torque<const N: usize>(
        &self,
        space: &OperationalSpace<N>,
        f: &Vector6<f64>,
        q: &JointVector<N>,
        qd: &JointVector<N>,
        posture: &JointTarget<N>,
    ) -> JointVector<N> {
        let mut tau = space.j.transpose() * f + space.bias;
        if self.task.redundancy(N) > 0 {
            let acc0 =
                (posture.q - q) * self.gains.posture_kp + (posture.qd - qd) * self.gains.posture_kd;
            tau += space.null_space_torque(&acc0);
        }
        tau
    }

    /// Clears the integral.
    pub fn reset(&mut self) {
        self.integral = Vector6::zeros();
    }

    /// The state ([`Controller::state_len`]): the integral of the task error per task row
    /// (m s, rad s).
    #[must_use]
    pub fn state_len(&self) -> usize {
        6
    }

    /// Writes the integral into `out[..6]`.
    pub fn write_state(&self, out: &mut [f64]) {
        out[..6].copy_from_slice(self.integral.as_slice());
    }

    /// Sets the integral from `x[..6]`.
    pub fn read_state(&mut self, x: &[f64]) {
        self.integral = Vector6::from_column_slice(&x[..6]);
    }
}

/// Task-space inverse dynamics (see the [module documentation](self)).
#[derive(Clone, Debug)]
pub struct TaskSpaceInverseDynamics<const N: usize, R> {
    robot: R,
    motion: TaskMotion,
}

impl<const N: usize, R: RobotModel<N>> TaskSpaceInverseDynamics<N, R> {
    /// The law for `robot`'s task ([`RobotModel::TASK`]) with `gains`.
    #[must_use]
    pub fn new(robot: R, gains: TaskSpaceGains) -> Self {
        Self {
            robot,
            motion: TaskMotion::new::<N, R>(gains),
        }
    }

    /// The gains.
    #[must_use]
    pub fn gains(&self) -> &TaskSpaceGains {
        self.motion.gains()
    }
}

impl<const N: usize, R: RobotModel<N>> Controller<N> for TaskSpaceInverseDynamics<N, R> {
    fn name(&self) -> &'static str {
        "task-space"
    }

    fn reset(&mut self) {
        self.motion.reset();
    }

    // The integral of the task error per task row (m s, rad s).
    super::pass_on_state!(motion);

    fn step(&mut self, input: &ControllerInput<'_, N>, dt: f64) -> JointVector<N> {
        let (q, qd) = (input.q, input.qd);
        let c = input.cartesian;
        let s = self.motion.sample(&self.robot, q, qd);
        match self
            .motion
            .wrench(&self.robot, q, qd, &s, c, &c.orientation, None, dt)
        {
            Some((space, f)) => self.motion.torque(&space, &f, q, qd, input.target),
            None => self.robot.mass_matrix_and_bias(q, qd).1,
        }
    }
}

/// `j` with the rows outside `task` zeroed (unchanged, not copied, for a task of all six).
#[inline]
pub(crate) fn task_rows<const N: usize>(task: &Task, j: SMatrix<f64, 6, N>) -> SMatrix<f64, 6, N> {
    if task.len() == 6 {
        j
    } else {
        let mask = task.mask();
        SMatrix::<f64, 6, N>::from_fn(|r, k| j[(r, k)] * mask[r])
    }
}

/// The operational-space quantities of one step: the task rows `J` of the Jacobian (the
/// other rows zero), `M` (factored as `L L^T` on the way), `c + g`, and the Cholesky factor of
/// `Lambda^-1 = J M^-1 J^T = Y^T Y`, `Y = L^-1 J^T` (an identity on the rows outside the task;
/// damped near a singularity, see the [module documentation](self)). Shared by the task-space
/// laws.
pub(crate) struct OperationalSpace<const N: usize> {
    /// The task rows of the geometric Jacobian, the others zero.
    pub(crate) j: SMatrix<f64, 6, N>,
    /// `M(q)`.
    pub(crate) m: JointMatrix<N>,
    /// `c(q, qd) + g(q)`, N m or N.
    pub(crate) bias: JointVector<N>,
    l_chol: Cholesky<f64, U6>,
    mask: Vector6<f64>,
}

impl<const N: usize> OperationalSpace<N> {
    /// The quantities at `(q, qd)` for the task rows `j` (`mask[r]` 1 on a task row, 0
    /// elsewhere; `task_len` task directions). `None` if `M` or `Lambda^-1` is not positive
    /// definite.
    #[inline(always)]
    pub(crate) fn new<R: RobotModel<N>>(
        robot: &R,
        q: &JointVector<N>,
        qd: &JointVector<N>,
        j: SMatrix<f64, 6, N>,
        mask: &Vector6<f64>,
        task_len: usize,
    ) -> Option<Self> {
        let (m, bias) = robot.mass_matrix_and_bias(q, qd);
        let m_chol = m.cholesky()?;
        // Y = L^-1 J^T (N x 6), one forward substitution; J M^-1 J^T = Y^T Y, with an identity
        // on the rows outside the task.
        let y: SMatrix<f64, N, 6> = m_chol
            .l_dirty()
            .solve_lower_triangular_unchecked(&j.transpose());
        let mut inv_lambda = y.tr_mul(&y);
        let mut diag = 1.0;
        let mut trace = 0.0;
        for r in 0..6 {
            if mask[r] == 1.0 {
                diag *= inv_lambda[(r, r)];
                trace += inv_lambda[(r, r)];
            } else {
                inv_lambda[(r, r)] = 1.0;
            }
        }
        // The determinant from the factor itself (the product of its squared diagonal); a
        // factor that fails, or a normalised determinant below the threshold, is damped.
        let measure_of = |c: &Cholesky<f64, U6>| {
            let l = c.l_dirty();
            let det: f64 = (0..6).map(|r| l[(r, r)] * l[(r, r)]).product();
            if diag > 0.0 {
                det / diag
            } else {
                0.0
            }
        };
        let l_chol = match inv_lambda.cholesky() {
            Some(c) if measure_of(&c) >= SINGULARITY_THRESHOLD => c,
            first => {
                let measure = first.as_ref().map_or(0.0, measure_of);
                let scale = trace / task_len as f64;
                let damping =
                    MAX_DAMPING * scale * (1.0 - measure.max(0.0) / SINGULARITY_THRESHOLD);
                for r in 0..6 {
                    if mask[r] == 1.0 {
                        inv_lambda[(r, r)] += damping;
                    }
                }
                inv_lambda.cholesky()?
            }
        };
        Some(Self {
            j,
            m,
            bias,
            l_chol,
            mask: *mask,
        })
    }

    /// `Lambda a` on the task rows (zero elsewhere): the wrench that gives the tool the task
    /// acceleration `a` (m/s^2, rad/s^2) in free space, N and N m.
    pub(crate) fn task_force(&self, a: &Vector6<f64>) -> Vector6<f64> {
        self.l_chol.solve(a).component_mul(&self.mask)
    }

    /// `(I - J^T Lambda J M^-1) M a0`: the joint torque that would give the joints the
    /// acceleration `a0` (rad/s^2 or m/s^2), the part of it in the dynamically consistent null
    /// space of the task (zero for a square task). `J M^-1 (M a0) = J a0`: no solve with `M`.
    pub(crate) fn null_space_torque(&self, a0: &JointVector<N>) -> JointVector<N> {
        let tau0 = self.m * a0;
        let through = self.l_chol.solve(&(self.j * a0)).component_mul(&self.mask);
        tau0 - self.j.transpose() * through
    }
}
