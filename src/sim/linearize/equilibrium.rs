//! The closed loop's equilibrium near a run's state, and the loop linearised there.
//!
//! A run that has not settled (it oscillates, slides or bounces) passes through states that
//! are not where it would come to rest, and the loop linearised at such a state speaks of the
//! motion through it, not of the rest point. With the reference at rest, the sampled loop
//! with its time frozen at the sample is a time-invariant map `s -> Phi(s)`; its fixed point
//! `Phi(s*) = s*` nearest the run's state is found by Newton's method,
//!
//! ```text
//! (A(s_i) - I) d_i = -(Phi(s_i) - s_i),   s_(i+1) = s_i + alpha_i d_i
//! ```
//!
//! with `A` the module's Jacobian, the step solved in the least-squares sense by the SVD
//! (directions the loop does not move, such as an integral no law reads, `z = 1` exactly,
//! stay where the run left them), and `alpha_i` halved until the residual falls. The loop
//! is stable at rest exactly when `A(s*)` is.

use nalgebra::{DMatrix, DVector};

use super::{FrozenLoop, LinearizeError, MapAt, Probed};
use crate::contact::Environment;
use crate::model::{DynamicsDerivatives, JointVector};

/// Newton iterations at most.
pub const MAX_ITERATIONS: usize = 60;
/// Converged when every element of `Phi(s) - s` is within this of zero, relative to
/// `max(1, |s_i|)`.
pub const TOLERANCE: f64 = 1e-11;
/// Singular values of `A - I` below this share of the largest are taken as zero.
const SINGULAR_SHARE: f64 = 1e-10;
/// A reference velocity or acceleration within this of zero counts as at rest (rad/s, m/s,
/// rad/s^2, m/s^2).
const AT_REST: f64 = 1e-9;

/// How the equilibrium was found.
#[derive(Clone, Debug, PartialEq)]
pub struct Equilibrium {
    /// Newton iterations taken.
    pub iterations: usize,
    /// `max_i |Phi(s*) - s*|_i / max(1, |s*_i|)` at the equilibrium.
    pub residual: f64,
    /// Largest distance of the equilibrium's joint positions from the run's at the sample,
    /// rad or m.
    pub joint_distance: f64,
    /// Largest joint speed of the run at the sample, rad/s or m/s (the equilibrium's is 0).
    pub run_joint_speed: f64,
}

/// `max_i |r_i| / max(1, |s_i|)`.
fn relative_residual(r: &DVector<f64>, s: &DVector<f64>) -> f64 {
    r.iter()
        .zip(s.iter())
        .map(|(r, s)| r.abs() / s.abs().max(1.0))
        .fold(0.0, f64::max)
}

/// [`LinearizeError::Unsupported`] unless the reference rests at the probed sample (a moving
/// loop has no rest point).
pub(super) fn check_at_rest<const N: usize>(probed: &Probed<N>) -> Result<(), LinearizeError> {
    let (t, target, cartesian) = (probed.t, &probed.target, &probed.cartesian);
    let moving = target
        .qd
        .iter()
        .chain(target.qdd.iter())
        .chain(cartesian.velocity.iter())
        .chain(cartesian.angular_velocity.iter())
        .chain(cartesian.acceleration.iter())
        .chain(cartesian.angular_acceleration.iter())
        .fold(0.0f64, |m, x| m.max(x.abs()));
    if moving > AT_REST {
        return Err(LinearizeError::Unsupported(format!(
            "the reference moves at t = {t} s (a velocity or acceleration of {moving:.3e}): \
             only a loop whose reference is at rest has an equilibrium; linearise at the run's \
             own state instead, or at a time where the reference rests"
        )));
    }
    Ok(())
}

/// The fixed point of `frozen`'s map nearest the probed state (controller state `z0`), from
/// the map `at` there: its joint state, the map at it, and how it was found.
///
/// # Errors
///
/// [`LinearizeError::Unsupported`] when Newton's method finds no equilibrium (the message
/// gives the residual it stopped at), or the model's error at a trial state.
#[allow(clippy::type_complexity)]
pub(super) fn newton<const N: usize, R, E>(
    frozen: &mut FrozenLoop<'_, '_, N, R, E>,
    z0: &[f64],
    mut at: MapAt<N>,
) -> Result<(JointVector<N>, JointVector<N>, MapAt<N>, Equilibrium), LinearizeError>
where
    R: DynamicsDerivatives<N>,
    E: Environment + ?Sized,
{
    let probed = frozen.probed;
    let t = probed.t;
    let ns = 2 * N + z0.len();
    let split = |s: &DVector<f64>| {
        let q = JointVector::<N>::from_fn(|i, _| s[i]);
        let qd = JointVector::<N>::from_fn(|i, _| s[N + i]);
        (
            q,
            qd,
            s.rows(2 * N, ns - 2 * N)
                .iter()
                .copied()
                .collect::<Vec<_>>(),
        )
    };
    let mut s = DVector::<f64>::zeros(ns);
    s.rows_mut(0, N).copy_from(&probed.q);
    s.rows_mut(N, N).copy_from(&probed.qd);
    s.rows_mut(2 * N, ns - 2 * N)
        .copy_from(&DVector::from_column_slice(z0));

    let mut r = DVector::from_column_slice(&at.next) - &s;
    let mut residual = relative_residual(&r, &s);
    let mut iterations = 0;
    while residual > TOLERANCE {
        if iterations == MAX_ITERATIONS {
            return Err(LinearizeError::Unsupported(format!(
                "no equilibrium near the run's state at t = {t} s: Newton's method stopped at a \
                 relative residual of {residual:.3e} after {iterations} iterations"
            )));
        }
        iterations += 1;
        let a_minus_i = &at.a - DMatrix::<f64>::identity(ns, ns);
        let svd = a_minus_i.svd(true, true);
        let eps = SINGULAR_SHARE * svd.singular_values.max();
        let step = svd
            .solve(&(-&r), eps)
            .map_err(|e| LinearizeError::Unsupported(format!("Newton step at t = {t} s: {e}")))?;
        let mut alpha = 1.0;
        loop {
            let trial = &s + &step * alpha;
            let (q, qd, z) = split(&trial);
            let trial_at = frozen.map(&q, &qd, &z)?;
            let trial_r = DVector::from_column_slice(&trial_at.next) - &trial;
            let trial_residual = relative_residual(&trial_r, &trial);
            if trial_residual < residual || alpha < 1e-3 {
                (s, at, r, residual) = (trial, trial_at, trial_r, trial_residual);
                break;
            }
            alpha *= 0.5;
        }
    }
    let (q, qd, _) = split(&s);
    let joint_distance = (q - probed.q).amax();
    let found = Equilibrium {
        iterations,
        residual,
        joint_distance,
        run_joint_speed: probed.qd.amax(),
    };
    Ok((q, qd, at, found))
}
