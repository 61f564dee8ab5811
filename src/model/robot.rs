//! The [`RobotModel`] trait: what controllers and the simulator may ask of a robot.

use super::joint::JointKind;
use crate::target::Task;
use nalgebra::{Vector3, Vector6};

use super::types::{Jacobian, JointMatrix, JointVector, Pose};

/// A serial robot arm with `N` joints, its kinematics and rigid-body dynamics.
///
/// Conventions (thesis Section 3.3, and `docs/thesis.md` section 2):
///
/// ```text
/// tau = M(q) qdd + c(q, qd) + g(q) + J(q)^T f_ext          (eq. 3.67, 3.68)
/// c(q, qd) = C(q, qd) qd                                     (Christoffel form)
/// ```
///
/// - `q`: joint positions, rad (revolute) or m (prismatic), in DH order base to tip.
/// - `qd`, `qdd`: their first and second time derivatives.
/// - `tau`: joint torques (N m) or forces (N).
/// - Frames are the link frames of the robot description, frame `i` attached to link `i`: the
///   Denavit–Hartenberg frames of a DH table (`A_i = Rz(theta_i) Tz(d_i) Tx(a_i) Rx(alpha_i)`),
///   or the child links of the moving joints of a URDF.
///
/// Implementors are expected to be cheap, allocation-free and panic-free for any finite
/// input; the generated robots ([`Scara`](super::Scara), [`Puma560`](super::Puma560),
/// [`Ur5`](super::Ur5), [`Panda`](super::Panda), ...) are zero-sized. Inputs are not checked: a NaN in gives NaN
/// out.
///
/// # Example
///
/// ```
/// use armdyn::model::{RobotModel, Scara};
/// use nalgebra::SVector;
///
/// let q = SVector::<f64, 4>::zeros();
/// let pose = Scara.end_effector_pose(&q);
/// // Thesis check: at q = 0 the tool is at (0.8, 0, 0.35) m, pointing down.
/// assert!((pose[(0, 3)] - 0.8).abs() < 1e-12);
/// assert!((pose[(2, 3)] - 0.35).abs() < 1e-12);
/// assert_eq!(Scara::DOF, 4);
/// ```
pub trait RobotModel<const N: usize> {
    /// The robot's name, as in its description file (`robots/<name>.toml`).
    const NAME: &'static str;
    /// Degrees of freedom, `N`.
    const DOF: usize = N;
    /// Joint names, base to tip.
    const JOINT_NAMES: [&'static str; N];
    /// Joint kinds, base to tip.
    const JOINT_KINDS: [JointKind; N];
    /// Joint position limits `[lower, upper]`, rad or m.
    const JOINT_LIMITS: [[f64; 2]; N];
    /// Actuator limits, N m or N, symmetric: `|tau_i| <= EFFORT_LIMITS[i]`.
    const EFFORT_LIMITS: [f64; N];
    /// Gravity acceleration in the base frame, m/s^2.
    const GRAVITY: [f64; 3];
    /// The task-space directions its end effector is controlled in (the description's
    /// `task`, [`Task`]): the SCARA's `x, y, z, rz`, all six for a 6- or 7-joint arm.
    const TASK: Task;
    /// SHA-256 of the robot description the model was generated from (hex).
    const SOURCE_SHA256: &'static str;
    /// Operation counts of the generated functions: `(function, flops, trig)`.
    const OPERATION_COUNTS: &'static [(&'static str, u32, u32)];

    /// Pose of every link frame `1..=N` in the base frame.
    ///
    /// Entry `i` (from 0) is `T_0^{i+1} = A_1 ... A_{i+1}`; translations in m.
    fn frame_poses(&self, q: &JointVector<N>) -> [Pose; N];

    /// Pose of the end effector (DH frame `N`, or a URDF's tip link) in the base frame;
    /// translation in m.
    fn end_effector_pose(&self, q: &JointVector<N>) -> Pose;

    /// Geometric Jacobian `J(q)`, 6 x N, base frame, at the end-effector origin.
    ///
    /// `[v; w] = J(q) qd` with `v` the linear velocity (m/s) of the end-effector origin and
    /// `w` the angular velocity (rad/s) of link `N`, both in the base frame.
    fn jacobian(&self, q: &JointVector<N>) -> Jacobian<N>;

    /// Jacobian and tool position together, `(J(q), p(q))`: the geometric Jacobian of
    /// [`Self::jacobian`] and the end-effector origin (m, base frame), the translation of
    /// [`Self::end_effector_pose`] — what a Cartesian controller needs at each step.
    ///
    /// The default calls [`Self::jacobian`] and [`Self::end_effector_pose`]; the generated
    /// robots use their `jacobian_and_position` function, one graph in which `J` and `p` share
    /// sin/cos and subexpressions and the pose's rotation is not computed, which is cheaper
    /// than the two calls.
    ///
    /// ```
    /// use armdyn::model::{Puma560, RobotModel};
    /// use nalgebra::SVector;
    ///
    /// let q = SVector::from([0.1, -0.4, 0.3, 0.2, -0.5, 0.7]);
    /// let (j, p) = Puma560.jacobian_and_position(&q);
    /// let pose = Puma560.end_effector_pose(&q);
    /// assert!((j - Puma560.jacobian(&q)).amax() < 1e-12);
    /// assert!((p - pose.fixed_view::<3, 1>(0, 3)).amax() < 1e-12);
    /// ```
    fn jacobian_and_position(&self, q: &JointVector<N>) -> (Jacobian<N>, Vector3<f64>) {
        let pose = self.end_effector_pose(q);
        (
            self.jacobian(q),
            Vector3::new(pose[(0, 3)], pose[(1, 3)], pose[(2, 3)]),
        )
    }

    /// Acceleration bias of the end effector, `Jdot(q, qd) qd`, base frame: m/s^2 (rows 0–2)
    /// and rad/s^2 (rows 3–5), so that `d/dt (J qd) = J qdd + Jdot qd`.
    fn jdot_qd(&self, q: &JointVector<N>, qd: &JointVector<N>) -> Vector6<f64>;

    /// Joint-space mass (inertia) matrix `M(q)`, symmetric positive definite
    /// (kg m^2, kg m or kg by entry). Thesis eq. 3.67 for the SCARA.
    fn mass_matrix(&self, q: &JointVector<N>) -> JointMatrix<N>;

    /// Coriolis/centrifugal matrix `C(q, qd)` in Christoffel form:
    /// `C_kj = sum_i 1/2 (dM_kj/dq_i + dM_ki/dq_j - dM_ij/dq_k) qd_i`,
    /// so that `Mdot - 2C` is skew-symmetric.
    fn coriolis_matrix(&self, q: &JointVector<N>, qd: &JointVector<N>) -> JointMatrix<N>;

    /// Velocity term `c(q, qd) = C(q, qd) qd` (N m or N). For the SCARA
    /// `c1 = -h s2 (2 qd1 qd2 + qd2^2)`, `c2 = h s2 qd1^2`, `c3 = c4 = 0`
    /// (`docs/thesis.md` section 2; the thesis's printed eq. 3.61–3.64 are wrong).
    fn coriolis(&self, q: &JointVector<N>, qd: &JointVector<N>) -> JointVector<N>;

    /// Gravity term `g(q) = dU/dq` (N m or N), `U` the potential energy. Thesis eq. 3.68
    /// for the SCARA: `g = [0, 0, -9.8 (m3 + m4), 0]`.
    fn gravity(&self, q: &JointVector<N>) -> JointVector<N>;

    /// Mass matrix and bias together, `(M(q), c(q, qd) + g(q))`: the two terms of
    /// `tau = M qdd + (c + g)` that a model-based controller needs (what Pinocchio's `crba`
    /// and `nonLinearEffects` compute), units as in [`Self::mass_matrix`] and
    /// [`Self::coriolis`].
    ///
    /// The default assembles them from [`Self::mass_matrix`], [`Self::coriolis`] and
    /// [`Self::gravity`]; the generated robots use their `mass_matrix_and_bias` function, one
    /// graph in which `M` and the bias share sin/cos and subexpressions, which is cheaper than
    /// the three calls.
    ///
    /// ```
    /// use armdyn::model::{Puma560, RobotModel};
    /// use nalgebra::SVector;
    ///
    /// let (q, qd) = (SVector::from([0.1, -0.4, 0.3, 0.2, -0.5, 0.7]), SVector::repeat(0.5));
    /// let (m, bias) = Puma560.mass_matrix_and_bias(&q, &qd);
    /// assert!((m - Puma560.mass_matrix(&q)).amax() < 1e-12);
    /// assert!((bias - Puma560.coriolis(&q, &qd) - Puma560.gravity(&q)).amax() < 1e-12);
    /// ```
    fn mass_matrix_and_bias(
        &self,
        q: &JointVector<N>,
        qd: &JointVector<N>,
    ) -> (JointMatrix<N>, JointVector<N>) {
        (self.mass_matrix(q), self.coriolis(q, qd) + self.gravity(q))
    }

    /// Inverse dynamics in free motion, `tau = M(q) qdd + c(q, qd) + g(q)` (N m or N).
    ///
    /// The default assembles it from [`Self::mass_matrix`], [`Self::coriolis`] and
    /// [`Self::gravity`]; the generated robots use their recursive Newton–Euler function,
    /// which is cheaper. For the contact term see [`inverse_dynamics`](super::inverse_dynamics).
    fn inverse_dynamics(
        &self,
        q: &JointVector<N>,
        qd: &JointVector<N>,
        qdd: &JointVector<N>,
    ) -> JointVector<N> {
        self.mass_matrix(q) * qdd + self.coriolis(q, qd) + self.gravity(q)
    }

    /// Forward dynamics in free motion, `qdd = M(q)^-1 (tau - c(q, qd) - g(q))` (rad/s^2 or
    /// m/s^2); for a contact wrench pass `tau - J^T f_ext`, as
    /// [`forward_dynamics`](super::forward_dynamics) does.
    ///
    /// The default factorises `M` by a fixed-size Cholesky decomposition
    /// ([`forward_dynamics_cholesky`](super::forward_dynamics_cholesky)); the generated
    /// robots use their generated function (an unrolled sparse `L^T D L` factorisation of
    /// `M` sharing sin/cos with `c` and `g`), which is cheaper. Inputs are not checked.
    ///
    /// # Errors
    ///
    /// [`ModelError::NotPositiveDefinite`](super::ModelError::NotPositiveDefinite) if `M(q)`
    /// is not positive definite (default), [`ModelError::NonFinite`](super::ModelError::NonFinite)
    /// naming `"qdd"` if the result is not finite (generated robots).
    fn forward_dynamics(
        &self,
        q: &JointVector<N>,
        qd: &JointVector<N>,
        tau: &JointVector<N>,
    ) -> Result<JointVector<N>, super::ModelError>
    where
        Self: Sized,
    {
        self.forward_dynamics_by_cholesky(q, qd, tau)
    }

    /// `M(q)^-1 (tau - c(q, qd) - g(q))` (rad/s^2 or m/s^2) by a fixed-size Cholesky solve of
    /// the mass matrix: the reference the generated forward dynamics is tested against.
    /// Inputs are not checked.
    ///
    /// # Errors
    ///
    /// [`ModelError::NotPositiveDefinite`](super::ModelError::NotPositiveDefinite) if `M(q)`
    /// is not positive definite.
    fn forward_dynamics_by_cholesky(
        &self,
        q: &JointVector<N>,
        qd: &JointVector<N>,
        tau: &JointVector<N>,
    ) -> Result<JointVector<N>, super::ModelError>
    where
        Self: Sized,
    {
        let m = self.mass_matrix(q);
        let rhs = tau - self.coriolis(q, qd) - self.gravity(q);
        Ok(super::cholesky::Cholesky::new(&m)?.solve(&rhs))
    }

    /// The robot's name (same as [`Self::NAME`]).
    fn name(&self) -> &'static str {
        Self::NAME
    }

    /// Lower joint limits as a vector, rad or m.
    fn lower_limits(&self) -> JointVector<N> {
        JointVector::<N>::from_fn(|i, _| Self::JOINT_LIMITS[i][0])
    }

    /// Upper joint limits as a vector, rad or m.
    fn upper_limits(&self) -> JointVector<N> {
        JointVector::<N>::from_fn(|i, _| Self::JOINT_LIMITS[i][1])
    }

    /// The middle of each joint's range, `(lower + upper) / 2` (rad or m), 0 for a joint
    /// without two finite limits.
    ///
    /// ```
    /// use armdyn::model::{Puma560, RobotModel};
    /// let mid = Puma560.middle_of_limits();
    /// assert_eq!(mid[0], 0.0); // [-160 deg, 160 deg]
    /// assert!((mid[1] - core::f64::consts::FRAC_PI_2).abs() < 1e-15); // [-45 deg, 225 deg]
    /// ```
    fn middle_of_limits(&self) -> JointVector<N> {
        JointVector::<N>::from_fn(|i, _| {
            let [lower, upper] = Self::JOINT_LIMITS[i];
            if lower.is_finite() && upper.is_finite() {
                0.5 * (lower + upper)
            } else {
                0.0
            }
        })
    }

    /// Actuator limits as a vector, N m or N.
    fn effort_limits(&self) -> JointVector<N> {
        JointVector::<N>::from_fn(|i, _| Self::EFFORT_LIMITS[i])
    }

    /// Whether every joint position is within its limits (inclusive). NaN is outside.
    fn within_joint_limits(&self, q: &JointVector<N>) -> bool {
        q.iter()
            .zip(Self::JOINT_LIMITS.iter())
            .all(|(&qi, &[lo, hi])| lo <= qi && qi <= hi)
    }

    /// `tau` with each entry clamped to `[-EFFORT_LIMITS[i], EFFORT_LIMITS[i]]` (actuator
    /// saturation). NaN entries stay NaN.
    fn saturate_effort(&self, tau: &JointVector<N>) -> JointVector<N> {
        JointVector::<N>::from_fn(|i, _| {
            let limit = Self::EFFORT_LIMITS[i];
            tau[i].clamp(-limit, limit)
        })
    }
}
