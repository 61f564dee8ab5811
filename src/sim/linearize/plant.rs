//! One control period of the plant and its Jacobian, from the generated derivatives.
//!
//! ```text
//! x = [q; qd],   x' = f(x, tau) = [qd; a(q, qd, tau)],   a = FD(q, qd, tau - e(q, qd))
//! e(q, qd) = J(q)^T w(p(q), v(q, qd)) - tau_stop(q, qd) + tau_friction(qd)
//! d a/d q  = FD_q - M^-1 d e/d q,   d a/d qd = FD_qd - M^-1 d e/d qd,   d a/d tau = M^-1
//! d e/d q  = W(q, w) + J^T (w_p J_v + w_v V),   V[:, k] = (d J_v/d q_k) qd,   d e/d qd = J^T w_v J_v
//! ```
//!
//! `FD_q`, `FD_qd`, `M^-1` and `d J/d q_k` (for `W` and `V`) are the generated functions
//! ([`DynamicsDerivatives`]). The environment's wrench `w(p, v)` is differenced numerically
//! (central differences of [`Environment::wrench_at`] in the tool's position and velocity,
//! steps [`POSITION_STEP_M`] and [`VELOCITY_STEP_M_S`]: contact models are piecewise
//! smooth and give no derivatives of their own), and so are the end stops and the joint
//! friction (per joint, steps [`JOINT_STEP`]). The period is `substeps` RK4 steps of `h` with
//! `tau` held (zero-order hold), as in [`crate::sim::simulate`]; its Jacobian is the chain
//! rule through the four stages of each step.

use nalgebra::{DMatrix, Matrix6x3, Vector3};

use crate::contact::Environment;
use crate::model::{
    wrench_torque_derivative, DynamicsDerivatives, JointMatrix, JointVector, ModelError,
};
use crate::sim::SimConfig;

/// Central-difference step of the tool position in the contact model, m.
pub const POSITION_STEP_M: f64 = 1e-7;
/// Central-difference step of the tool velocity in the contact model, m/s.
pub const VELOCITY_STEP_M_S: f64 = 1e-7;
/// Central-difference step of the joint position and velocity in the end stops and the
/// friction, rad or m (rad/s or m/s).
pub const JOINT_STEP: f64 = 1e-7;

/// The state after one period and its derivatives: `dx` (2N x 2N) with respect to
/// `[q; qd]` at the start, `du` (2N x N) with respect to the held torque.
pub struct PlantPeriod<const N: usize> {
    /// Joint positions at the end of the period.
    pub q: JointVector<N>,
    /// Joint velocities at the end of the period.
    pub qd: JointVector<N>,
    /// `d [q'; qd'] / d [q; qd]`.
    pub dx: DMatrix<f64>,
    /// `d [q'; qd'] / d tau`.
    pub du: DMatrix<f64>,
}

/// What a period integrates: the robot, its environment and the run's plant settings (end
/// stops, friction).
struct Plant<'a, const N: usize, R, E: ?Sized> {
    robot: &'a R,
    environment: &'a E,
    config: &'a SimConfig<N>,
}

impl<const N: usize, R, E> Plant<'_, N, R, E>
where
    R: DynamicsDerivatives<N>,
    E: Environment + ?Sized,
{
    /// `a(q, qd, tau)` at time `t` (s) and its derivative with respect to `[q; qd; tau]`
    /// (N x 3N).
    fn acceleration(
        &self,
        t: f64,
        q: &JointVector<N>,
        qd: &JointVector<N>,
        tau: &JointVector<N>,
    ) -> Result<(JointVector<N>, DMatrix<f64>), ModelError> {
        let (robot, environment, config) = (self.robot, self.environment, self.config);
        let (j, p) = robot.jacobian_and_position(q);
        let jv = j.fixed_rows::<3>(0).into_owned();
        let v: Vector3<f64> = jv * qd;
        let w = environment.wrench_at(t, &p, &v);
        // The contact model's derivatives, numerically.
        let mut w_p = Matrix6x3::zeros();
        let mut w_v = Matrix6x3::zeros();
        for k in 0..3 {
            let mut e = Vector3::zeros();
            e[k] = POSITION_STEP_M;
            let dp = (environment.wrench_at(t, &(p + e), &v)
                - environment.wrench_at(t, &(p - e), &v))
                / (2.0 * POSITION_STEP_M);
            w_p.set_column(k, &dp);
            e[k] = VELOCITY_STEP_M_S;
            let dv = (environment.wrench_at(t, &p, &(v + e))
                - environment.wrench_at(t, &p, &(v - e)))
                / (2.0 * VELOCITY_STEP_M_S);
            w_v.set_column(k, &dv);
        }
        let dj = robot.jacobian_derivatives(q);
        let vq = nalgebra::SMatrix::<f64, 3, N>::from_fn(|r, k| {
            (0..N).map(|i| dj[k][(r, i)] * qd[i]).sum()
        });
        let mut tau_ext = j.transpose() * w;
        let mut de_dq =
            wrench_torque_derivative(robot, q, &w) + j.transpose() * (w_p * jv + w_v * vq);
        let mut de_dqd = j.transpose() * w_v * jv;
        if let Some(stops) = &config.end_stops {
            tau_ext -= stops.torque(q, qd);
            de_dq -= joint_difference(q, |q| stops.torque(q, qd));
            de_dqd -= joint_difference(qd, |qd| stops.torque(q, qd));
        }
        if let Some(friction) = &config.friction {
            tau_ext += friction.torque(qd);
            de_dqd += joint_difference(qd, |qd| friction.torque(qd));
        }
        let tau_eff = tau - tau_ext;
        let qdd = robot.forward_dynamics(q, qd, &tau_eff)?;
        let d = robot.forward_dynamics_derivatives(q, qd, &tau_eff)?;
        let mut out = DMatrix::zeros(N, 3 * N);
        let a_q = d.dqdd_dq - d.mass_matrix_inverse * de_dq;
        let a_qd = d.dqdd_dqd - d.mass_matrix_inverse * de_dqd;
        out.view_mut((0, 0), (N, N)).copy_from(&a_q);
        out.view_mut((0, N), (N, N)).copy_from(&a_qd);
        out.view_mut((0, 2 * N), (N, N))
            .copy_from(&d.mass_matrix_inverse);
        Ok((qdd, out))
    }
}

/// `d f / d x` (N x N) by central differences of step [`JOINT_STEP`], column by column.
fn joint_difference<const N: usize>(
    x: &JointVector<N>,
    f: impl Fn(&JointVector<N>) -> JointVector<N>,
) -> JointMatrix<N> {
    let mut d = JointMatrix::<N>::zeros();
    for i in 0..N {
        let (mut a, mut b) = (*x, *x);
        a[i] += JOINT_STEP;
        b[i] -= JOINT_STEP;
        d.set_column(i, &((f(&a) - f(&b)) / (2.0 * JOINT_STEP)));
    }
    d
}

/// One control period from `(q, qd)` at time `t` with `tau` held: `substeps` RK4 steps of
/// `h` seconds, and the Jacobian of the result (see the [module documentation](self)).
///
/// # Errors
///
/// [`ModelError`] if the model cannot be evaluated on the way (a non-finite state).
#[allow(clippy::too_many_arguments)]
pub fn plant_period<const N: usize, R, E>(
    robot: &R,
    environment: &E,
    config: &SimConfig<N>,
    t: f64,
    q: &JointVector<N>,
    qd: &JointVector<N>,
    tau: &JointVector<N>,
    substeps: usize,
    h: f64,
) -> Result<PlantPeriod<N>, ModelError>
where
    R: DynamicsDerivatives<N>,
    E: Environment + ?Sized,
{
    let plant = Plant {
        robot,
        environment,
        config,
    };
    let n = N;
    // d [q; qd] / d [q0; qd0; tau], 2N x 3N, through the period.
    let mut total = DMatrix::<f64>::zeros(2 * n, 3 * n);
    total.view_mut((0, 0), (2 * n, 2 * n)).fill_with_identity();
    let (mut q, mut qd) = (*q, *qd);
    for s in 0..substeps {
        let ts = t + s as f64 * h;
        // Stage points (q_i, v_i) and their derivatives P_i (2N x 3N) with respect to
        // [q_s; qd_s; tau] of this step.
        let mut p1 = DMatrix::<f64>::zeros(2 * n, 3 * n);
        p1.view_mut((0, 0), (2 * n, 2 * n)).fill_with_identity();
        let stage = |qs: &JointVector<N>, vs: &JointVector<N>, ps: &DMatrix<f64>| {
            let (a, da) = plant.acceleration(ts, qs, vs, tau)?;
            // d a / d [x_s; tau] = da[:, ..2N] P + da[:, 2N..] on the tau columns.
            let mut dadx = da.columns(0, 2 * n) * ps;
            {
                let mut tail = dadx.columns_mut(2 * n, n);
                tail += da.columns(2 * n, n);
            }
            let dv = ps.rows(n, n).into_owned();
            Ok::<_, ModelError>((a, dv, dadx))
        };
        let k1v = qd;
        let (k1a, dk1v, dk1a) = stage(&q, &qd, &p1)?;
        let next = |h2: f64,
                    kv: &JointVector<N>,
                    ka: &JointVector<N>,
                    dkv: &DMatrix<f64>,
                    dka: &DMatrix<f64>| {
            let qs = q + kv * h2;
            let vs = qd + ka * h2;
            let mut ps = p1.clone();
            {
                let mut top = ps.rows_mut(0, n);
                top += dkv * h2;
            }
            {
                let mut bottom = ps.rows_mut(n, n);
                bottom += dka * h2;
            }
            (qs, vs, ps)
        };
        let (q2, v2, p2) = next(h / 2.0, &k1v, &k1a, &dk1v, &dk1a);
        let (k2a, dk2v, dk2a) = stage(&q2, &v2, &p2)?;
        let (q3, v3, p3) = next(h / 2.0, &v2, &k2a, &dk2v, &dk2a);
        let (k3a, dk3v, dk3a) = stage(&q3, &v3, &p3)?;
        let (q4, v4, p4) = next(h, &v3, &k3a, &dk3v, &dk3a);
        let (k4a, dk4v, dk4a) = stage(&q4, &v4, &p4)?;
        let q_next = q + (k1v + v2 * 2.0 + v3 * 2.0 + v4) * (h / 6.0);
        let qd_next = qd + (k1a + k2a * 2.0 + k3a * 2.0 + k4a) * (h / 6.0);
        let mut step = p1.clone();
        {
            let mut top = step.rows_mut(0, n);
            top += (&dk1v + &dk2v * 2.0 + &dk3v * 2.0 + &dk4v) * (h / 6.0);
        }
        {
            let mut bottom = step.rows_mut(n, n);
            bottom += (&dk1a + &dk2a * 2.0 + &dk3a * 2.0 + &dk4a) * (h / 6.0);
        }
        // Chain: [x_{s+1}] depends on x_s (itself on x0, tau) and on tau directly.
        let mut chained = step.columns(0, 2 * n) * &total;
        {
            let mut tail = chained.columns_mut(2 * n, n);
            tail += step.columns(2 * n, n);
        }
        total = chained;
        q = q_next;
        qd = qd_next;
    }
    Ok(PlantPeriod {
        q,
        qd,
        dx: total.columns(0, 2 * n).into_owned(),
        du: total.columns(2 * n, n).into_owned(),
    })
}
