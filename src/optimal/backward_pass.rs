//! The iLQR backward pass on fixed-size `N x N` blocks.
//!
//! The state is `x = [q; qd]` (2N), so every matrix of the pass is a 2 x 2 array of joint
//! matrices (or a 1 x 2 row of them): `A = df/dx = [A_qq A_qv; A_vq A_vv]`,
//! `B = df/dv = [B_q; B_v]`, the value's Hessian `V_xx = [V_qq V_qv; V_vq V_vv]`, the
//! feedback gain `K = [K_q K_v]`. On the blocks the products are of the robot's own size,
//! unrolled and allocation-free, where `2N x 2N` dynamic matrices allocate at every product
//! (the Panda's plan spent a fifth of its time in them). Per knot, with `W = V_xx A`:
//!
//! ```text
//! Q_x  = A^T V_x,        Q_u  = 2 h v + B^T V_x
//! Q_xx = A^T W,          Q_ux = B^T W,           Q_uu = B^T V_xx B + (2 h + mu) I
//! k, K = box QP (Q_uu, Q_u; the torque box), K = -Q_uu,ff^-1 Q_ux,f on the free controls
//! V_x  = Q_x + K^T (Q_uu k + Q_u) + Q_ux^T k
//! V_xx = Q_xx + K^T Q_uu K + K^T Q_ux + Q_ux^T K
//! ```

use nalgebra::{DMatrix, DVector};

use super::box_qp;
use super::setup::{split, Multipliers, Setup, Trajectory, LIMIT_ROWS};
use crate::model::{DynamicsDerivatives, JointMatrix, JointVector};

/// A `2N x 2N` matrix as four `N x N` blocks: `[qq qv; vq vv]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Blocks<const N: usize> {
    pub(super) qq: JointMatrix<N>,
    pub(super) qv: JointMatrix<N>,
    pub(super) vq: JointMatrix<N>,
    pub(super) vv: JointMatrix<N>,
}

impl<const N: usize> Blocks<N> {
    /// `s I`.
    fn scaled_identity(s: f64) -> Self {
        let z = JointMatrix::<N>::zeros();
        Self {
            qq: JointMatrix::<N>::identity() * s,
            qv: z,
            vq: z,
            vv: JointMatrix::<N>::identity() * s,
        }
    }

    /// `self * a`.
    fn mul(&self, a: &Self) -> Self {
        Self {
            qq: self.qq * a.qq + self.qv * a.vq,
            qv: self.qq * a.qv + self.qv * a.vv,
            vq: self.vq * a.qq + self.vv * a.vq,
            vv: self.vq * a.qv + self.vv * a.vv,
        }
    }

    /// `self^T * w`.
    fn tr_mul(&self, w: &Self) -> Self {
        Self {
            qq: self.qq.tr_mul(&w.qq) + self.vq.tr_mul(&w.vq),
            qv: self.qq.tr_mul(&w.qv) + self.vq.tr_mul(&w.vv),
            vq: self.qv.tr_mul(&w.qq) + self.vv.tr_mul(&w.vq),
            vv: self.qv.tr_mul(&w.qv) + self.vv.tr_mul(&w.vv),
        }
    }

    /// `self^T * [x_q; x_v]`.
    fn tr_mul_vector(
        &self,
        x_q: &JointVector<N>,
        x_v: &JointVector<N>,
    ) -> (JointVector<N>, JointVector<N>) {
        (
            self.qq.tr_mul(x_q) + self.vq.tr_mul(x_v),
            self.qv.tr_mul(x_q) + self.vv.tr_mul(x_v),
        )
    }
}

/// `df/dx` and `df/dv` of one knot step.
#[derive(Clone, Copy, Debug)]
pub(super) struct KnotJacobian<const N: usize> {
    pub(super) a: Blocks<N>,
    /// `[B_q; B_v]`.
    pub(super) b: [JointMatrix<N>; 2],
}

/// One knot's feed-forward step `k` and feedback gain `K = [K_q K_v]`.
#[derive(Clone, Copy, Debug)]
pub(super) struct KnotGains<const N: usize> {
    pub(super) feedforward: JointVector<N>,
    pub(super) feedback: [JointMatrix<N>; 2],
}

impl<const N: usize> KnotGains<N> {
    /// The control change for the step `alpha` and the state deviation `[dq; dqd]`.
    pub(super) fn control(
        &self,
        alpha: f64,
        dq: &JointVector<N>,
        dqd: &JointVector<N>,
    ) -> JointVector<N> {
        self.feedforward * alpha + self.feedback[0] * dq + self.feedback[1] * dqd
    }
}

impl<const N: usize, R: DynamicsDerivatives<N>> Setup<'_, N, R> {
    /// One backward pass at `t`: per-knot gains and the expected reduction `(dV1, dV2)`
    /// (`dV(alpha) = alpha dV1 + alpha^2 dV2`); `None` if `Q_uu` is not positive definite
    /// with regularisation `mu` (see the [module documentation](self)).
    pub(super) fn backward(
        &self,
        t: &Trajectory,
        jac: &[KnotJacobian<N>],
        m: &Multipliers,
        mu: f64,
    ) -> Option<(Vec<KnotGains<N>>, f64, f64)> {
        let rho = m.penalty;
        // Terminal: the goal's augmented Lagrangian and the last knot's limits.
        let (goal_q, goal_v) = split::<N>(&(&m.goal + (&t.x[self.steps] - &self.goal) * rho));
        let (mut vx_q, mut vx_v) = (goal_q, goal_v);
        let mut vxx = Blocks::<N>::scaled_identity(rho);
        self.add_limit_terms(
            &t.x[self.steps],
            &m.limits[self.steps - 1],
            rho,
            (&mut vx_q, &mut vx_v),
            &mut vxx,
        );
        let none = KnotGains {
            feedforward: JointVector::<N>::zeros(),
            feedback: [JointMatrix::<N>::zeros(); 2],
        };
        let mut gains = vec![none; self.steps];
        let (mut dv1, mut dv2) = (0.0, 0.0);
        for k in (0..self.steps).rev() {
            let KnotJacobian { a, b } = &jac[k];
            let vk = JointVector::<N>::from_fn(|i, _| t.v[k][i]);
            let (qx_q, qx_v) = a.tr_mul_vector(&vx_q, &vx_v);
            let qu = vk * (2.0 * self.h) + b[0].tr_mul(&vx_q) + b[1].tr_mul(&vx_v);
            let w = vxx.mul(a);
            let qxx = a.tr_mul(&w);
            let qux = [
                b[0].tr_mul(&w.qq) + b[1].tr_mul(&w.vq),
                b[0].tr_mul(&w.qv) + b[1].tr_mul(&w.vv),
            ];
            let vb_q = vxx.qq * b[0] + vxx.qv * b[1];
            let vb_v = vxx.vq * b[0] + vxx.vv * b[1];
            let mut quu = b[0].tr_mul(&vb_q) + b[1].tr_mul(&vb_v);
            for i in 0..N {
                quu[(i, i)] += 2.0 * self.h + mu;
            }
            let quu = (quu + quu.transpose()) * 0.5;
            let lo = DVector::from_fn(N, |i, _| -self.share - vk[i]);
            let hi = DVector::from_fn(N, |i, _| self.share - vk[i]);
            let warm = if k + 1 < self.steps {
                gains[k + 1].feedforward
            } else {
                JointVector::<N>::zeros()
            };
            let qp = box_qp::solve(
                &DMatrix::from_column_slice(N, N, quu.as_slice()),
                &DVector::from_column_slice(qu.as_slice()),
                &lo,
                &hi,
                &DVector::from_column_slice(warm.as_slice()),
            )
            .ok()?;
            let kff = JointVector::<N>::from_fn(|i, _| qp.x[i]);
            let mut kfb = [JointMatrix::<N>::zeros(); 2];
            if let Some(factor) = &qp.free_factor {
                let idx: Vec<usize> = (0..N).filter(|&i| qp.free[i]).collect();
                let rhs =
                    DMatrix::from_fn(idx.len(), 2 * N, |r, col| qux[col / N][(idx[r], col % N)]);
                let sol = factor.solve(&rhs);
                for (r, &i) in idx.iter().enumerate() {
                    for col in 0..2 * N {
                        kfb[col / N][(i, col % N)] = -sol[(r, col)];
                    }
                }
            }
            let quu_k = quu * kff;
            dv1 += kff.dot(&qu);
            dv2 += 0.5 * kff.dot(&quu_k);
            let pull = quu_k + qu;
            vx_q = qx_q + kfb[0].tr_mul(&pull) + qux[0].tr_mul(&kff);
            vx_v = qx_v + kfb[1].tr_mul(&pull) + qux[1].tr_mul(&kff);
            let t_q = quu * kfb[0];
            let t_v = quu * kfb[1];
            let next = Blocks {
                qq: qxx.qq + kfb[0].tr_mul(&t_q) + kfb[0].tr_mul(&qux[0]) + qux[0].tr_mul(&kfb[0]),
                qv: qxx.qv + kfb[0].tr_mul(&t_v) + kfb[0].tr_mul(&qux[1]) + qux[0].tr_mul(&kfb[1]),
                vq: qxx.vq + kfb[1].tr_mul(&t_q) + kfb[1].tr_mul(&qux[0]) + qux[1].tr_mul(&kfb[0]),
                vv: qxx.vv + kfb[1].tr_mul(&t_v) + kfb[1].tr_mul(&qux[1]) + qux[1].tr_mul(&kfb[1]),
            };
            let qv = (next.qv + next.vq.transpose()) * 0.5;
            vxx = Blocks {
                qq: (next.qq + next.qq.transpose()) * 0.5,
                qv,
                vq: qv.transpose(),
                vv: (next.vv + next.vv.transpose()) * 0.5,
            };
            if k > 0 {
                self.add_limit_terms(
                    &t.x[k],
                    &m.limits[k - 1],
                    rho,
                    (&mut vx_q, &mut vx_v),
                    &mut vxx,
                );
            }
            gains[k] = KnotGains {
                feedforward: kff,
                feedback: kfb,
            };
        }
        Some((gains, dv1, dv2))
    }

    /// Adds the gradient and Gauss–Newton Hessian of a knot's joint-limit terms.
    fn add_limit_terms(
        &self,
        x: &DVector<f64>,
        lam: &DVector<f64>,
        rho: f64,
        (vx_q, vx_v): (&mut JointVector<N>, &mut JointVector<N>),
        vxx: &mut Blocks<N>,
    ) {
        let g = self.limit_excess(x);
        for i in 0..LIMIT_ROWS * N {
            let a = lam[i] + rho * g[i];
            if a > 0.0 {
                // d g / d x_j = +1 for an upper excess, -1 for a lower one; rows 2 and 3
                // are of the velocities.
                let j = i % N;
                let sign = if (i / N).is_multiple_of(2) { 1.0 } else { -1.0 };
                if i / N < 2 {
                    vx_q[j] += sign * a;
                    vxx.qq[(j, j)] += rho;
                } else {
                    vx_v[j] += sign * a;
                    vxx.vv[(j, j)] += rho;
                }
            }
        }
    }
}
