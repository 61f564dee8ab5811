//! Excitation design: Fourier coefficients that make the stacked base regressor well
//! conditioned while the motion stays within the joint position, velocity, acceleration and
//! effort limits.
//!
//! Every candidate is made feasible by construction: its offsets are kept inside the position
//! range less a margin and each joint's motion is scaled to the largest amplitude that meets
//! its position, velocity and acceleration limits (checked on a fine grid). Effort (inverse
//! dynamics of the nominal model) is a penalty. The search is a seeded (1+1) evolution
//! strategy with the one-fifth success rule from the best of several random starts,
//! minimising `log10 cond(W_b)` over one period.

use nalgebra::DMatrix;
use rand::rngs::Xoshiro256PlusPlus;
use rand::{RngExt, SeedableRng};
use rand_distr::StandardNormal;

use super::base::BaseParameters;
use super::fourier::{FourierExcitation, HARMONICS};
use super::robots::Identifiable;
use super::signals::full_regressor;
use crate::model::{JointKind, JointVector, RobotModel};

/// Limits the excitation must respect (the robot descriptions give position and effort
/// limits; velocity and acceleration limits are set here).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ExcitationLimits<const N: usize> {
    /// Largest joint speed, rad/s or m/s.
    pub velocity: [f64; N],
    /// Largest joint acceleration, rad/s^2 or m/s^2.
    pub acceleration: [f64; N],
    /// Part of each joint's range kept free at both ends (0.05: 5 %).
    pub position_margin: f64,
    /// Largest torque as a part of the actuator limit (0.8: 80 %).
    pub effort_fraction: f64,
}

impl<const N: usize> ExcitationLimits<N> {
    /// 2 rad/s and 10 rad/s^2 for revolute joints, 0.5 m/s and 2 m/s^2 for prismatic ones,
    /// 5 % position margin, 80 % of the actuator limits.
    #[must_use]
    pub fn default_for<R: RobotModel<N>>() -> Self {
        let prismatic = |i: usize| R::JOINT_KINDS[i] == JointKind::Prismatic;
        Self {
            velocity: core::array::from_fn(|i| if prismatic(i) { 0.5 } else { 2.0 }),
            acceleration: core::array::from_fn(|i| if prismatic(i) { 2.0 } else { 10.0 }),
            position_margin: 0.05,
            effort_fraction: 0.8,
        }
    }
}

/// How the search runs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ExcitationSettings {
    /// Period of the series, s.
    pub period_s: f64,
    /// Samples per period in the condition number.
    pub samples: usize,
    /// Cost evaluations in all.
    pub evaluations: usize,
    /// Random starts (each one evaluation) before the local search.
    pub starts: usize,
    /// Seed of the search.
    pub seed: u64,
}

impl Default for ExcitationSettings {
    fn default() -> Self {
        Self {
            period_s: 10.0,
            samples: 100,
            evaluations: 1500,
            starts: 40,
            seed: 1,
        }
    }
}

/// The designed excitation.
#[derive(Clone, Debug, PartialEq)]
pub struct Excitation<const N: usize> {
    /// The trajectory.
    pub trajectory: FourierExcitation<N>,
    /// Condition number of the stacked base regressor over one period (`samples` points).
    pub condition_number: f64,
    /// The condition number of the best random start, before the local search.
    pub initial_condition_number: f64,
    /// Peak `|tau_i| / limit_i` of the nominal model along the trajectory.
    pub peak_effort_fraction: [f64; N],
    /// Evaluations made.
    pub evaluations: usize,
}

/// Per-joint usable position range `[lo, hi]` after the margin.
fn ranges<const N: usize, R: RobotModel<N>>(m: f64) -> [(f64, f64); N] {
    core::array::from_fn(|i| {
        let [lo, hi] = R::JOINT_LIMITS[i];
        let (lo, hi) = if lo.is_finite() && hi.is_finite() {
            (lo, hi)
        } else {
            (-core::f64::consts::PI, core::f64::consts::PI)
        };
        let d = m * (hi - lo);
        (lo + d, hi - d)
    })
}

/// Variables per joint: the offset, then `a` and `b`.
const PER_JOINT: usize = 1 + 2 * HARMONICS;

/// The feasible trajectory of decision vector `x`, limits checked on `grid` points.
fn trajectory<const N: usize, R: RobotModel<N>>(
    x: &[f64],
    limits: &ExcitationLimits<N>,
    period_s: f64,
    grid: usize,
) -> FourierExcitation<N> {
    let r = ranges::<N, R>(limits.position_margin);
    let offset: [f64; N] = core::array::from_fn(|i| {
        let (lo, hi) = r[i];
        0.5 * (lo + hi) + 0.45 * (hi - lo) * libm::tanh(x[i * PER_JOINT])
    });
    let mut f = FourierExcitation::new(period_s, offset);
    for i in 0..N {
        let v = &x[i * PER_JOINT + 1..(i + 1) * PER_JOINT];
        f.set_coefficients(
            i,
            core::array::from_fn(|l| v[l]),
            core::array::from_fn(|l| v[HARMONICS + l]),
        );
        let (mut pq, mut pqd, mut pqdd) = (0.0_f64, 0.0_f64, 0.0_f64);
        for k in 0..grid {
            let (q, qd, qdd) = f.unscaled(i, period_s * k as f64 / grid as f64);
            pq = pq.max(q.abs());
            pqd = pqd.max(qd.abs());
            pqdd = pqdd.max(qdd.abs());
        }
        let room = (offset[i] - r[i].0).min(r[i].1 - offset[i]);
        let s = (room / pq)
            .min(limits.velocity[i] / pqd)
            .min(limits.acceleration[i] / pqdd);
        f.set_scale(i, if s.is_finite() { s } else { 0.0 });
    }
    f
}

/// The stacked base regressor of `f` at `samples` points of one period.
pub fn stacked_base<const N: usize, R: Identifiable<N>>(
    robot: &R,
    base: &BaseParameters,
    f: &FourierExcitation<N>,
    samples: usize,
    friction_smoothing: Option<f64>,
) -> DMatrix<f64> {
    let mut w = DMatrix::zeros(samples * N, base.count());
    for k in 0..samples {
        let (q, qd, qdd) = f.state(f.period_s() * k as f64 / samples as f64);
        let y = full_regressor(
            robot,
            &q.into(),
            &qd.into(),
            &qdd.into(),
            friction_smoothing,
        );
        w.view_mut((k * N, 0), (N, base.count()))
            .copy_from(&base.select(&y));
    }
    w
}

/// Condition number (largest over smallest singular value) of `w`.
#[must_use]
pub fn condition_number(w: &DMatrix<f64>) -> f64 {
    let sv = w.singular_values();
    sv.max() / sv.min()
}

fn peak_effort<const N: usize, R: Identifiable<N>>(
    robot: &R,
    f: &FourierExcitation<N>,
    samples: usize,
) -> [f64; N] {
    let mut peak = [0.0_f64; N];
    for k in 0..samples {
        let (q, qd, qdd) = f.state(f.period_s() * k as f64 / samples as f64);
        let tau = robot.inverse_dynamics(&q.into(), &qd.into(), &qdd.into());
        for i in 0..N {
            peak[i] = peak[i].max(tau[i].abs() / R::EFFORT_LIMITS[i]);
        }
    }
    peak
}

/// Designs an excitation for `robot` whose base parameters are `base` (with the friction
/// columns if `friction_smoothing` is given).
#[must_use]
pub fn design<const N: usize, R: Identifiable<N>>(
    robot: &R,
    base: &BaseParameters,
    friction_smoothing: Option<f64>,
    limits: &ExcitationLimits<N>,
    settings: &ExcitationSettings,
) -> Excitation<N> {
    let grid = 4 * settings.samples;
    let cost = |x: &[f64]| -> (f64, FourierExcitation<N>) {
        let f = trajectory::<N, R>(x, limits, settings.period_s, grid);
        let w = stacked_base(robot, base, &f, settings.samples, friction_smoothing);
        let cond = condition_number(&w);
        let effort = peak_effort(robot, &f, settings.samples);
        let excess: f64 = effort
            .iter()
            .map(|e| (e - limits.effort_fraction).max(0.0))
            .sum();
        let c = if cond.is_finite() {
            libm::log10(cond)
        } else {
            1e3
        };
        (c + 100.0 * excess, f)
    };
    let mut rng = Xoshiro256PlusPlus::seed_from_u64(settings.seed);
    let dim = N * PER_JOINT;
    let mut best_x = vec![0.0; dim];
    let mut best = f64::INFINITY;
    let mut used = 0;
    for _ in 0..settings.starts.max(1) {
        let x: Vec<f64> = (0..dim).map(|_| rng.sample(StandardNormal)).collect();
        let (c, _) = cost(&x);
        used += 1;
        if c < best {
            best = c;
            best_x = x;
        }
    }
    let initial = best;
    let mut sigma = 0.3;
    while used < settings.evaluations && sigma > 1e-4 {
        let x: Vec<f64> = best_x
            .iter()
            .map(|v| v + sigma * rng.sample::<f64, _>(StandardNormal))
            .collect();
        let (c, _) = cost(&x);
        used += 1;
        if c < best {
            best = c;
            best_x = x;
            sigma *= 1.5;
        } else {
            sigma *= libm::pow(1.5, -0.25);
        }
    }
    // The final trajectory, limits checked on a 1 ms grid.
    let fine = (settings.period_s / 1e-3).round().max(grid as f64) as usize;
    let trajectory = trajectory::<N, R>(&best_x, limits, settings.period_s, fine);
    let w = stacked_base(
        robot,
        base,
        &trajectory,
        settings.samples,
        friction_smoothing,
    );
    Excitation {
        condition_number: condition_number(&w),
        initial_condition_number: libm::pow(10.0, initial.min(300.0)),
        peak_effort_fraction: peak_effort(robot, &trajectory, fine),
        trajectory,
        evaluations: used,
    }
}

/// A random (not optimised) feasible excitation, for validation: another trajectory than
/// the one identified on.
#[must_use]
pub fn random<const N: usize, R: Identifiable<N>>(
    limits: &ExcitationLimits<N>,
    period_s: f64,
    seed: u64,
) -> FourierExcitation<N> {
    let mut rng = Xoshiro256PlusPlus::seed_from_u64(seed);
    let x: Vec<f64> = (0..N * PER_JOINT)
        .map(|_| rng.sample(StandardNormal))
        .collect();
    let fine = (period_s / 1e-3).round() as usize;
    trajectory::<N, R>(&x, limits, period_s, fine.max(100))
}

/// Whether `f` stays within `limits` (positions with their margin, velocities,
/// accelerations) at every millisecond of one period; the largest violation otherwise.
#[must_use]
pub fn check_limits<const N: usize, R: RobotModel<N>>(
    f: &FourierExcitation<N>,
    limits: &ExcitationLimits<N>,
) -> Option<String> {
    let r = ranges::<N, R>(limits.position_margin);
    let n = (f.period_s() / 1e-3).round() as usize;
    for k in 0..=n {
        let t = f.period_s() * k as f64 / n as f64;
        let (q, qd, qdd) = f.state(t);
        let q = JointVector::<N>::from(q);
        for i in 0..N {
            let tol = 1e-9;
            if q[i] < r[i].0 - tol || q[i] > r[i].1 + tol {
                return Some(format!("joint {} position {} at t = {t} s", i + 1, q[i]));
            }
            if qd[i].abs() > limits.velocity[i] * (1.0 + tol) {
                return Some(format!("joint {} velocity {} at t = {t} s", i + 1, qd[i]));
            }
            if qdd[i].abs() > limits.acceleration[i] * (1.0 + tol) {
                return Some(format!(
                    "joint {} acceleration {} at t = {t} s",
                    i + 1,
                    qdd[i]
                ));
            }
        }
    }
    None
}
