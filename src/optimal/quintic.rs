//! The rest-to-rest quintic between two configurations, the plan the optimised moves are
//! compared with and start from:
//!
//! ```text
//! q(t) = from + (to - from) S(t / T),   S(u) = 10 u^3 - 15 u^4 + 6 u^5
//! ```
//!
//! its peak effort share and effort by inverse dynamics, and its shortest duration within an
//! effort share (bisection).

use super::problem::PlanError;
use crate::model::{JointVector, RobotModel};
use crate::target::JointTarget;

/// Points at which a quintic's inverse dynamics is checked for its peak effort share.
pub const QUINTIC_SAMPLES: usize = 400;
/// Longest move searched, s.
pub const MAX_DURATION_S: f64 = 60.0;
/// Relative precision of the shortest durations (bisection stops below it).
pub const DURATION_PRECISION: f64 = 2e-3;

/// The rest-to-rest quintic `from -> to` of duration `T` at the share `u` in `[0, 1]` of it:
/// `q = from + (to - from) S(u)`, `S(u) = 10 u^3 - 15 u^4 + 6 u^5`, and its rates.
#[must_use]
pub fn quintic<const N: usize>(
    from: &JointVector<N>,
    to: &JointVector<N>,
    duration_s: f64,
    u: f64,
) -> JointTarget<N> {
    let d = to - from;
    let t = duration_s;
    let (u2, u3) = (u * u, u * u * u);
    let s = u3 * (10.0 - 15.0 * u + 6.0 * u2);
    let ds = 30.0 * u2 * (1.0 - u) * (1.0 - u) / t;
    let dds = 60.0 * u * (1.0 - 3.0 * u + 2.0 * u2) / (t * t);
    JointTarget {
        q: from + d * s,
        qd: d * ds,
        qdd: d * dds,
    }
}

/// The largest `|tau_i| / e_i` of the rest-to-rest quintic `from -> to` of duration `T`
/// (inverse dynamics at [`QUINTIC_SAMPLES`] + 1 points).
#[must_use]
pub fn quintic_peak_effort_share<const N: usize, R: RobotModel<N>>(
    robot: &R,
    from: &JointVector<N>,
    to: &JointVector<N>,
    duration_s: f64,
) -> f64 {
    (0..=QUINTIC_SAMPLES)
        .map(|k| {
            let shares = effort_shares(
                robot,
                from,
                to,
                duration_s,
                k as f64 / QUINTIC_SAMPLES as f64,
            );
            shares.iter().map(|x| x.abs()).fold(0.0, f64::max)
        })
        .fold(0.0, f64::max)
}

/// `tau_i / e_i` (inverse dynamics over the effort limits) at the fraction `s` of the
/// rest-to-rest quintic `from -> to` of duration `T`.
fn effort_shares<const N: usize, R: RobotModel<N>>(
    robot: &R,
    from: &JointVector<N>,
    to: &JointVector<N>,
    duration_s: f64,
    s: f64,
) -> JointVector<N> {
    let j = quintic(from, to, duration_s, s);
    robot
        .inverse_dynamics(&j.q, &j.qd, &j.qdd)
        .component_div(&robot.effort_limits())
}

/// The effort `integral of sum_i (tau_i / e_i)^2 dt` of the rest-to-rest quintic
/// `from -> to` of duration `T`, s (midpoint rule over [`QUINTIC_SAMPLES`] intervals).
#[must_use]
pub fn quintic_effort<const N: usize, R: RobotModel<N>>(
    robot: &R,
    from: &JointVector<N>,
    to: &JointVector<N>,
    duration_s: f64,
) -> f64 {
    let n = QUINTIC_SAMPLES as f64;
    (0..QUINTIC_SAMPLES)
        .map(|k| {
            let shares = effort_shares(robot, from, to, duration_s, (k as f64 + 0.5) / n);
            shares.iter().map(|x| x.powi(2)).sum::<f64>() * duration_s / n
        })
        .sum()
}

/// The shortest quintic `from -> to` whose peak effort share is at most `share` (to
/// [`DURATION_PRECISION`]); 0 if the two are equal.
///
/// # Errors
///
/// [`PlanError::Setting`] if even [`MAX_DURATION_S`] exceeds the share (gravity alone is
/// too much for it).
pub fn shortest_quintic<const N: usize, R: RobotModel<N>>(
    robot: &R,
    from: &JointVector<N>,
    to: &JointVector<N>,
    share: f64,
) -> Result<f64, PlanError> {
    if (to - from).amax() == 0.0 {
        return Ok(0.0);
    }
    let fits = |t: f64| quintic_peak_effort_share(robot, from, to, t) <= share;
    if !fits(MAX_DURATION_S) {
        return Err(PlanError::Setting(format!(
            "no quintic of up to {MAX_DURATION_S} s stays within an effort share of {share}: \
             holding the configurations takes more"
        )));
    }
    Ok(shortest_fitting(MAX_DURATION_S, DURATION_PRECISION, fits))
}

/// The shortest duration in `[1 ms, longest]` s that `fits`, by bisection to `relative` of
/// it, for a `fits` that holds at `longest` and for every duration longer than one that
/// holds; the result fits.
pub fn shortest_fitting(longest: f64, relative: f64, mut fits: impl FnMut(f64) -> bool) -> f64 {
    let (mut lo, mut hi) = (1e-3, longest);
    while hi - lo > relative * hi {
        let mid = 0.5 * (lo + hi);
        if fits(mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    hi
}
