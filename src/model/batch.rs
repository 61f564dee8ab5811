//! Batched evaluation: the generated lane functions (`armdyn_generated::<robot>::lanes`) over
//! slices of states, [`LANES`] states per call.
//!
//! ```text
//! states k = 0 .. len:   lane k mod LANES of call k / LANES   (the last call padded by
//!                                                             repeating the last state;
//!                                                             its extra lanes dropped)
//! ```
//!
//! For sweeps, sampling-based planners and the Python batch API: one call keeps the lanes of
//! a SIMD register busy with several states: [`Batch`], `wide::f64x4` (one `ymm` register)
//! when the build has AVX (`-C target-cpu=native` on this machine), `wide::f64x2` (one `xmm`)
//! on the x86-64 baseline. Each lane is the scalar function's arithmetic, the trig `wide`'s
//! vectorised `sin_cos` (within a few ulp of `libm`'s: results agree with the scalar
//! functions to 1e-12 relative, `tests/model/generated_lanes.rs`, not bit for bit).
//! `benches/generated.rs` (group `<robot>-batch`) measures the gain per state.
//!
//! # Example
//!
//! ```
//! use armdyn::model::batch::{forward_dynamics_batch, mass_matrix_and_bias_batch};
//! use armdyn::model::{Panda, RobotModel};
//! use nalgebra::SVector;
//!
//! let q: Vec<[f64; 7]> = (0..10).map(|k| [0.1 * k as f64; 7]).collect();
//! let qd = vec![[0.2; 7]; 10];
//! let tau = vec![[1.0; 7]; 10];
//! let mut qdd = vec![[0.0; 7]; 10];
//! forward_dynamics_batch(&Panda, &q, &qd, &tau, &mut qdd).unwrap();
//! let one = Panda.forward_dynamics(&q[3].into(), &qd[3].into(), &tau[3].into()).unwrap();
//! assert!((SVector::from(qdd[3]) - one).norm() < 1e-9 * one.norm());
//!
//! let (mut m, mut bias) = (vec![[[0.0; 7]; 7]; 10], vec![[0.0; 7]; 10]);
//! mass_matrix_and_bias_batch(&Panda, &q, &qd, &mut m, &mut bias).unwrap();
//! assert!((m[9][0][0] - Panda.mass_matrix(&q[9].into())[(0, 0)]).abs() < 1e-12);
//! ```

use armdyn_generated::lanes::Lane;

/// The lane type of a batch on this target (`wide::f64x4` with AVX, `wide::f64x2` otherwise).
pub use armdyn_generated::lanes::Batch;

use super::robot::RobotModel;

/// States per call of the lane functions: 4 with AVX, 2 otherwise ([`Batch`]).
pub const LANES: usize = Batch::LANES;

/// A joint vector of [`LANES`] states: joint `i`'s values, one state a lane.
pub type Lanes<const N: usize> = [Batch; N];

/// An `N x N` matrix of [`LANES`] states, row-major, one state a lane.
pub type LaneMatrix<const N: usize> = [[Batch; N]; N];

/// A robot whose generated functions also come in lanes (every robot of the registry).
pub trait BatchModel<const N: usize>: RobotModel<N> {
    /// `(M, c + g)` of [`LANES`] states: `M(q)` (N x N) and `c(q, qd) + g(q)`, lane by lane.
    fn mass_matrix_and_bias_lanes(&self, q: &Lanes<N>, qd: &Lanes<N>) -> (LaneMatrix<N>, Lanes<N>);
    /// `qdd = M^-1 (tau - c - g)` of [`LANES`] states (the generated forward dynamics).
    fn forward_dynamics_lanes(&self, q: &Lanes<N>, qd: &Lanes<N>, tau: &Lanes<N>) -> Lanes<N>;
    /// `tau = M qdd + c + g` of [`LANES`] states (the generated inverse dynamics).
    fn inverse_dynamics_lanes(&self, q: &Lanes<N>, qd: &Lanes<N>, qdd: &Lanes<N>) -> Lanes<N>;
    /// `[d tau/d q, d tau/d qd, M]` of [`LANES`] states (the generated
    /// `inverse_dynamics_derivatives`), each `N x N` row-major, lane by lane.
    fn inverse_dynamics_derivatives_lanes(
        &self,
        q: &Lanes<N>,
        qd: &Lanes<N>,
        qdd: &Lanes<N>,
    ) -> [LaneMatrix<N>; 3];
    /// `[d qdd/d q, d qdd/d qd, M^-1]` of [`LANES`] states (the generated
    /// `forward_dynamics_derivatives`), each `N x N` row-major; not checked for finiteness.
    fn forward_dynamics_derivatives_lanes(
        &self,
        q: &Lanes<N>,
        qd: &Lanes<N>,
        tau: &Lanes<N>,
    ) -> [LaneMatrix<N>; 3];
}

/// Inputs or outputs of a batched call whose lengths differ.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("batch: `{name}` has {len} states, `{first}` has {expected}")]
pub struct LengthMismatch {
    /// The argument whose length differs.
    pub name: &'static str,
    /// Its length.
    pub len: usize,
    /// The first argument's name.
    pub first: &'static str,
    /// The first argument's length.
    pub expected: usize,
}

/// Checks that every `(name, len)` has the first one's length.
fn same_lengths(lengths: &[(&'static str, usize)]) -> Result<usize, LengthMismatch> {
    let (first, expected) = lengths[0];
    for &(name, len) in &lengths[1..] {
        if len != expected {
            return Err(LengthMismatch {
                name,
                len,
                first,
                expected,
            });
        }
    }
    Ok(expected)
}

/// Lanes `start .. start + 4` of `states` (the last state repeated past the end).
#[inline]
fn pack<const N: usize>(states: &[[f64; N]], start: usize) -> Lanes<N> {
    let last = states.len() - 1;
    core::array::from_fn(|i| Batch::from_fn(|k| states[(start + k).min(last)][i]))
}

/// Writes lane `k` of `lanes` into `out[start + k]` for the lanes inside `out`.
#[inline]
fn unpack<const N: usize>(lanes: &Lanes<N>, out: &mut [[f64; N]], start: usize) {
    for (k, state) in out.iter_mut().skip(start).take(LANES).enumerate() {
        for (value, lane) in state.iter_mut().zip(lanes) {
            *value = lane.lane(k);
        }
    }
}

/// `qdd` of every state (rad/s^2 or m/s^2): `out[k] = FD(q[k], qd[k], tau[k])`, [`LANES`] states
/// per generated call. Inputs are not checked for finiteness (NaN in, NaN out, as the scalar
/// functions).
///
/// # Errors
///
/// [`LengthMismatch`] when the slices differ in length (nothing is written then).
pub fn forward_dynamics_batch<const N: usize, R: BatchModel<N>>(
    robot: &R,
    q: &[[f64; N]],
    qd: &[[f64; N]],
    tau: &[[f64; N]],
    out: &mut [[f64; N]],
) -> Result<(), LengthMismatch> {
    three_inputs_one_output(("tau", tau), q, qd, out, |q, qd, tau| {
        robot.forward_dynamics_lanes(q, qd, tau)
    })
}

/// `tau` of every state (N m or N): `out[k] = ID(q[k], qd[k], qdd[k])`, [`LANES`] states per call.
///
/// # Errors
///
/// [`LengthMismatch`] when the slices differ in length (nothing is written then).
pub fn inverse_dynamics_batch<const N: usize, R: BatchModel<N>>(
    robot: &R,
    q: &[[f64; N]],
    qd: &[[f64; N]],
    qdd: &[[f64; N]],
    out: &mut [[f64; N]],
) -> Result<(), LengthMismatch> {
    three_inputs_one_output(("qdd", qdd), q, qd, out, |q, qd, qdd| {
        robot.inverse_dynamics_lanes(q, qd, qdd)
    })
}

/// `out[k] = f(q[k], qd[k], third[k])`, [`LANES`] states per call of `f`, after the length
/// check (`third` named for its error).
fn three_inputs_one_output<const N: usize>(
    (name, third): (&'static str, &[[f64; N]]),
    q: &[[f64; N]],
    qd: &[[f64; N]],
    out: &mut [[f64; N]],
    f: impl Fn(&Lanes<N>, &Lanes<N>, &Lanes<N>) -> Lanes<N>,
) -> Result<(), LengthMismatch> {
    let len = same_lengths(&[
        ("q", q.len()),
        ("qd", qd.len()),
        (name, third.len()),
        ("out", out.len()),
    ])?;
    for start in (0..len).step_by(LANES) {
        let y = f(&pack(q, start), &pack(qd, start), &pack(third, start));
        unpack(&y, out, start);
    }
    Ok(())
}

/// `M(q[k])` into `mass[k]` (row-major) and `c(q[k], qd[k]) + g(q[k])` into `bias[k]`, [`LANES`]
/// states per call.
///
/// # Errors
///
/// [`LengthMismatch`] when the slices differ in length (nothing is written then).
pub fn mass_matrix_and_bias_batch<const N: usize, R: BatchModel<N>>(
    robot: &R,
    q: &[[f64; N]],
    qd: &[[f64; N]],
    mass: &mut [[[f64; N]; N]],
    bias: &mut [[f64; N]],
) -> Result<(), LengthMismatch> {
    let len = same_lengths(&[
        ("q", q.len()),
        ("qd", qd.len()),
        ("mass", mass.len()),
        ("bias", bias.len()),
    ])?;
    for start in (0..len).step_by(LANES) {
        let (m, b) = robot.mass_matrix_and_bias_lanes(&pack(q, start), &pack(qd, start));
        for (k, state) in mass.iter_mut().skip(start).take(LANES).enumerate() {
            for (out_row, row) in state.iter_mut().zip(&m) {
                for (value, lane) in out_row.iter_mut().zip(row) {
                    *value = lane.lane(k);
                }
            }
        }
        unpack(&b, bias, start);
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{Scara, Ur5};
    use nalgebra::SVector;

    /// Every length from 0 to 9 (full calls, a padded last call, none) gives the scalar result.
    #[test]
    fn every_length_matches_the_scalar_functions() {
        for len in 0..10 {
            let q: Vec<[f64; 6]> = (0..len)
                .map(|k| core::array::from_fn(|i| 0.1 * k as f64 - 0.07 * i as f64))
                .collect();
            let qd: Vec<[f64; 6]> = (0..len).map(|k| [0.3 - 0.05 * k as f64; 6]).collect();
            let x: Vec<[f64; 6]> = (0..len).map(|k| [1.0 + k as f64; 6]).collect();
            let mut fd = vec![[f64::NAN; 6]; len];
            let mut id = vec![[f64::NAN; 6]; len];
            let (mut m, mut b) = (vec![[[f64::NAN; 6]; 6]; len], vec![[f64::NAN; 6]; len]);
            forward_dynamics_batch(&Ur5, &q, &qd, &x, &mut fd).unwrap();
            inverse_dynamics_batch(&Ur5, &q, &qd, &x, &mut id).unwrap();
            mass_matrix_and_bias_batch(&Ur5, &q, &qd, &mut m, &mut b).unwrap();
            for k in 0..len {
                let (qk, qdk, xk) = (q[k].into(), qd[k].into(), x[k].into());
                let close = |a: SVector<f64, 6>, e: SVector<f64, 6>| {
                    assert!(
                        (a - e).norm() <= 1e-11 * (1.0 + e.norm()),
                        "{len} {k}: {a} {e}"
                    );
                };
                close(fd[k].into(), Ur5.forward_dynamics(&qk, &qdk, &xk).unwrap());
                close(id[k].into(), Ur5.inverse_dynamics(&qk, &qdk, &xk));
                let bias = Ur5.coriolis(&qk, &qdk) + Ur5.gravity(&qk);
                close(b[k].into(), bias);
                let mass = Ur5.mass_matrix(&qk);
                for (i, row) in m[k].iter().enumerate() {
                    close((*row).into(), mass.row(i).transpose());
                }
            }
        }
    }

    /// Each lane of the derivative lane functions is the scalar derivatives of its state.
    #[test]
    fn derivative_lanes_match_the_scalar_derivatives() {
        use crate::model::DynamicsDerivatives;
        let q: Vec<[f64; 6]> = (0..LANES)
            .map(|k| core::array::from_fn(|i| 0.3 * k as f64 - 0.11 * i as f64))
            .collect();
        let qd: Vec<[f64; 6]> = (0..LANES).map(|k| [0.4 - 0.2 * k as f64; 6]).collect();
        let x: Vec<[f64; 6]> = (0..LANES).map(|k| [2.0 - k as f64; 6]).collect();
        let (pq, pqd, px) = (pack(&q, 0), pack(&qd, 0), pack(&x, 0));
        let id = Ur5.inverse_dynamics_derivatives_lanes(&pq, &pqd, &px);
        let fd = Ur5.forward_dynamics_derivatives_lanes(&pq, &pqd, &px);
        for k in 0..LANES {
            let (qk, qdk, xk) = (q[k].into(), qd[k].into(), x[k].into());
            let i = Ur5.inverse_dynamics_derivatives(&qk, &qdk, &xk);
            let f = Ur5.forward_dynamics_derivatives(&qk, &qdk, &xk).unwrap();
            let expected = [
                i.dtau_dq,
                i.dtau_dqd,
                i.mass_matrix,
                f.dqdd_dq,
                f.dqdd_dqd,
                f.mass_matrix_inverse,
            ];
            let lanes = id.iter().chain(&fd);
            for (b, (e, m)) in expected.iter().zip(lanes).enumerate() {
                let scale = 1.0 + e.norm();
                for (r, row) in m.iter().enumerate() {
                    for (c, value) in row.iter().enumerate() {
                        let d = (value.lane(k) - e[(r, c)]).abs();
                        assert!(d <= 1e-11 * scale, "block {b} lane {k} ({r}, {c}): {d}");
                    }
                }
            }
        }
    }

    #[test]
    fn lengths_that_differ_are_refused_before_anything_is_written() {
        let q = [[0.0; 4]; 5];
        let mut out = [[7.0; 4]; 5];
        let error = forward_dynamics_batch(&Scara, &q, &q[..4], &q, &mut out).unwrap_err();
        assert_eq!(error.to_string(), "batch: `qd` has 4 states, `q` has 5");
        assert_eq!(out, [[7.0; 4]; 5]);
    }
}
