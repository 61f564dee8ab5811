//! The SCARA's hybrid force/position step over a scalar `T` (`f32` or `f64`): the thesis's
//! law with a fixed task normal and a switch at a time, allocation-free, for deployment.

use nalgebra::{Matrix4, SMatrix, Vector3, Vector4};

use super::super::TASK_ROWS as SCARA_TASK_ROWS;
use super::error::DeployError;
use super::scalar::ScaraScalar;
use crate::control::force::ForcePi;
use crate::control::jacobian_factor::JacobianFactor;
use crate::control::pid_fl::PidFeedbackLinearization;
use crate::control::selection::SelectionPolicy;
use crate::control::task_frame::TaskFrame;
use crate::model::Scara;

/// What the step reads at one sample, in its scalar `T`. Forces are those the tool exerts on
/// the environment, base frame (negative along an outward normal = pressing).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HybridInput<T> {
    /// Time, s.
    pub t: T,
    /// Measured joint positions, rad or m.
    pub q: [T; 4],
    /// Measured joint velocities, rad/s or m/s.
    pub qd: [T; 4],
    /// Joint position reference, rad or m.
    pub q_ref: [T; 4],
    /// Joint velocity reference, rad/s or m/s.
    pub qd_ref: [T; 4],
    /// Cartesian position reference of the tool, m.
    pub position_ref: [T; 3],
    /// Cartesian velocity reference of the tool, m/s.
    pub velocity_ref: [T; 3],
    /// Measured force, N.
    pub force: [T; 3],
    /// Desired force, N.
    pub force_ref: [T; 3],
}

/// Hybrid force/position control of the SCARA (thesis eq. 5.4) in a scalar `T`:
///
/// ```text
/// before switch_s:  tau = PID-FL(q_ref, qd_ref)
/// from switch_s:    tau = J_r^T f_cmd,  f_cmd = (I - n n^T) J_r^-T tau_p + n f_f  (linear rows)
///                   tau_p = PID-FL(q_ref + J_r^-1 n (n.(p - p_ref)), qd_ref + ...)
///                   f_f = f_d + Kfp (f_d - f) + Kfi int(f_d - f) dt - Kvd n.v
/// PID-FL(x) = u + (M(q) - M_linear) M_linear^-1 u + c(q, qd) + g(q),  u = PID(x - q)
/// ```
///
/// the law of [`HybridForcePosition`](crate::control::hybrid::HybridForcePosition) with
/// [`PidFeedbackLinearization`] and [`ForcePi`], a fixed normal `n`
/// ([`TaskFrame::Fixed`]), the switch at a time ([`SelectionPolicy::Time`]), rows `vx vy vz
/// wz`, and no gravity or friction feedforward; the same Jacobian solve
/// ([`JacobianFactor`], generic over the scalar), singularity rule and damping. Gains are
/// designed in `f64` by the existing design code and rounded to `T`. No allocation, no failure in [`Self::step`].
///
/// ```
/// use armdyn::robots::scara::deploy::{HybridInput, ScaraHybrid};
/// let mut c = ScaraHybrid::<f32>::thesis().unwrap();
/// let x = HybridInput {
///     t: 3.0,
///     q: [0.3, 0.8, 0.2, 0.1],
///     qd: [0.0; 4],
///     q_ref: [0.3, 0.8, 0.2, 0.1],
///     qd_ref: [0.0; 4],
///     position_ref: [0.45, -0.1, 0.13],
///     velocity_ref: [0.0; 3],
///     force: [0.0, 0.0, -190.0],
///     force_ref: [0.0, 0.0, -200.0],
/// };
/// let tau: [f32; 4] = c.step(&x, 1e-3);
/// assert!(tau.iter().all(|t| t.is_finite()));
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct ScaraHybrid<T: ScaraScalar> {
    kp: Vector4<T>,
    ki: Vector4<T>,
    kd: Vector4<T>,
    m_linear: Matrix4<T>,
    m_linear_inv: Matrix4<T>,
    kfp: T,
    kfi: T,
    kvd: T,
    normal: Vector3<T>,
    switch_s: T,
    pid_integral: Vector4<T>,
    force_integral: T,
    force_active: bool,
    tool: Option<(Vector3<T>, Vector3<T>)>,
}

impl<T: ScaraScalar> ScaraHybrid<T> {
    /// The thesis's controller (the one `embedded/src/cases.rs` builds in `f64`): PID with
    /// feedback linearization on the constant part of `M` with the thesis's rounding,
    /// PI + feedforward + velocity damping, force along base z from 2 s.
    ///
    /// # Errors
    ///
    /// [`DeployError::SingularLinearPart`] if the gain design fails (not for the committed
    /// robot).
    pub fn thesis() -> Result<Self, DeployError> {
        use crate::control::mass_split::SplitKind;
        use crate::robots::scara::thesis_setup::{thesis_force_law, thesis_position_loop};
        let position =
            thesis_position_loop(SplitKind::ConstantPart).ok_or(DeployError::SingularLinearPart)?;
        Self::new(
            &position,
            &thesis_force_law(true),
            &TaskFrame::along_z(),
            &crate::robots::scara::thesis_setup::THESIS_SELECTION,
        )
    }

    /// From an `f64` design: the position loop's gains and `M_linear`, the force law's gains,
    /// the task frame and the selection, each rounded to `T`.
    ///
    /// # Errors
    ///
    /// [`DeployError`] if the frame follows a surface or its normal is not a unit vector, if
    /// the selection switches on contact, or if `M_linear` is singular.
    pub fn new(
        position: &PidFeedbackLinearization<4, Scara>,
        force: &ForcePi,
        frame: &TaskFrame,
        selection: &SelectionPolicy,
    ) -> Result<Self, DeployError> {
        let TaskFrame::Fixed(normal) = frame else {
            return Err(DeployError::SurfaceFrame);
        };
        if !normal.iter().all(|x| x.is_finite()) || (normal.norm() - 1.0).abs() > 1e-9 {
            return Err(DeployError::Normal);
        }
        let SelectionPolicy::Time { switch_s } = *selection else {
            return Err(DeployError::ContactSelection);
        };
        let m_linear = *position.m_linear();
        let m_linear_inv = m_linear
            .try_inverse()
            .ok_or(DeployError::SingularLinearPart)?;
        let gains = position.gains();
        Ok(Self {
            kp: gains.kp.map(T::round_from),
            ki: gains.ki.map(T::round_from),
            kd: gains.kd.map(T::round_from),
            m_linear: m_linear.map(T::round_from),
            m_linear_inv: m_linear_inv.map(T::round_from),
            kfp: T::round_from(force.kfp()),
            kfi: T::round_from(force.kfi()),
            kvd: T::round_from(force.kvd()),
            normal: normal.map(T::round_from),
            switch_s: T::round_from(switch_s),
            pid_integral: Vector4::zeros(),
            force_integral: T::zero(),
            force_active: false,
            tool: None,
        })
    }

    /// Clears both integrators for a new run.
    pub fn reset(&mut self) {
        self.pid_integral = Vector4::zeros();
        self.force_integral = T::zero();
        self.force_active = false;
        self.tool = None;
    }

    /// Whether the force law damps the tool's velocity along the normal (`Kvd != 0`).
    #[must_use]
    pub fn velocity_damping(&self) -> bool {
        self.kvd != T::zero()
    }

    /// The task normal the force is controlled along (unit, base frame).
    #[must_use]
    pub fn normal(&self) -> Vector3<T> {
        self.normal
    }

    /// The tool's position (m) and linear velocity (m/s) at the last step's state, if that
    /// step computed them (under force control); `None` otherwise.
    #[must_use]
    pub fn tool_state(&self) -> Option<(Vector3<T>, Vector3<T>)> {
        self.tool
    }

    /// Whether the last step controlled force.
    #[must_use]
    pub fn force_controlled(&self) -> bool {
        self.force_active
    }

    /// One control period of `dt` s: the joint torques (N m, N m, N, N m).
    ///
    /// The same operations, in the same order, as `HybridForcePosition::step` in this
    /// configuration, so the `f64` instance equals it to the last bit where the Jacobian solve
    /// is exact.
    pub fn step(&mut self, x: &HybridInput<T>, dt: T) -> [T; 4] {
        if x.t < self.switch_s {
            self.force_active = false;
            self.force_integral = T::zero();
            self.tool = None;
            let tau = self.position(x, &Vector4::from(x.q_ref), &Vector4::from(x.qd_ref), dt);
            return tau.into();
        }
        self.force_active = true;
        // J (6 x 4) and the tool position p (m) in one call.
        let jp = T::jacobian_and_position(&x.q);
        let j = SMatrix::<T, 6, 4>::from_fn(|r, c| jp[r][c]);
        let p = Vector3::new(jp[0][4], jp[1][4], jp[2][4]);
        let v: Vector3<T> = j.fixed_rows::<3>(0) * Vector4::from(x.qd);
        self.tool = Some((p, v));
        let n = self.normal;
        let f_n = n.dot(&Vector3::from(x.force));
        let v_n = n.dot(&v);
        let factor = JacobianFactor::from_rows(&j, &SCARA_TASK_ROWS);
        // The joint motion per metre along n; the position loop sees only tangential errors:
        // its target moves along n onto the tool.
        let along_n = factor.solve(&Vector4::new(n[0], n[1], n[2], T::zero()));
        let mut q_target = Vector4::from(x.q_ref);
        q_target += along_n * n.dot(&(p - Vector3::from(x.position_ref)));
        let mut qd_target = Vector4::from(x.qd_ref);
        qd_target += along_n * n.dot(&(v - Vector3::from(x.velocity_ref)));
        let tau_p = self.position(x, &q_target, &qd_target, dt);
        // The position loop's force along n, n . J_r^-T tau_p, as (J_r^-1 n) . tau_p.
        let f_p_n = along_n.dot(&tau_p);
        let f_d = n.dot(&Vector3::from(x.force_ref));
        let e = f_d - f_n;
        self.force_integral += e * dt;
        let f_f = f_d + self.kfp * e + self.kfi * self.force_integral - self.kvd * v_n;
        // tau = J_r^T f_cmd, f_cmd the position loop's wrench with its normal component
        // replaced by f_f: tau_p (unless damped) plus the linear rows of J times the change.
        let df = n * (f_f - f_p_n);
        let mut tau = factor.wrench_torque(&tau_p);
        for k in 0..3 {
            tau += j.row(k).transpose() * df[k];
        }
        tau.into()
    }

    /// PID with feedback linearization towards `(q_target, qd_target)`.
    fn position(
        &mut self,
        x: &HybridInput<T>,
        q_target: &Vector4<T>,
        qd_target: &Vector4<T>,
        dt: T,
    ) -> Vector4<T> {
        let e = q_target - Vector4::from(x.q);
        let e_dot = qd_target - Vector4::from(x.qd);
        self.pid_integral += e * dt;
        let u = self.kp.component_mul(&e)
            + self.ki.component_mul(&self.pid_integral)
            + self.kd.component_mul(&e_dot);
        let qdd_cmd = self.m_linear_inv * u;
        // M and c + g in one call.
        let mb = T::mass_matrix_and_bias(&x.q, &x.qd);
        let m = Matrix4::<T>::from_fn(|i, j| mb[i][j]);
        let bias = Vector4::new(mb[0][4], mb[1][4], mb[2][4], mb[3][4]);
        u + (m - self.m_linear) * qdd_cmd + bias
    }
}
