//! A log as a real robot would record it, made on the simulated plant: the measurement of
//! [`super::measurement`] (friction and torque noise as set there) with the defects of real
//! logging added ([`LogDefects`]), for examples and tests of the log reader and
//! identification.

use rand::rngs::Xoshiro256PlusPlus;
use rand::{RngExt, SeedableRng};
use rand_distr::StandardNormal;

use super::log::JointLog;
use super::measurement::{rms, Measurement, CONTROL_DT_S};
use crate::model::JointVector;

/// The defects added to a simulated measurement.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LogDefects {
    /// Late time stamps: each sample is taken `|n|` s after its period's start, `n` Gaussian
    /// with this standard deviation (at most 0.9 periods), s.
    pub jitter_s: f64,
    /// Probability that a sample is lost.
    pub drop_probability: f64,
    /// One gap of this length (s) in the middle of the log (samples lost in a row).
    pub gap_s: f64,
    /// Probability that a row is written twice (a duplicated stamp).
    pub duplicate_probability: f64,
    /// Probability that a row has a NaN torque.
    pub nan_probability: f64,
    /// A constant offset of each joint's torque sensor, % of its RMS torque (sign alternating
    /// from joint to joint).
    pub offset_pct: f64,
    /// Encoder resolution: positions are rounded to it, rad or m.
    pub position_resolution: f64,
    /// Torque resolution, N m or N.
    pub torque_resolution: f64,
}

impl Default for LogDefects {
    /// 0.1 ms jitter, 1 % of samples lost, one 30 ms gap, 0.2 % duplicated stamps, 0.1 % NaN
    /// rows, a 2 % torque offset, 1e-6 rad and 1e-4 N m resolution.
    fn default() -> Self {
        Self {
            jitter_s: 1e-4,
            drop_probability: 0.01,
            gap_s: 0.03,
            duplicate_probability: 0.002,
            nan_probability: 0.001,
            offset_pct: 2.0,
            position_resolution: 1e-6,
            torque_resolution: 1e-4,
        }
    }
}

fn round_to(x: f64, step: f64) -> f64 {
    if step > 0.0 {
        libm::round(x / step) * step
    } else {
        x
    }
}

/// Cubic Hermite interpolation of a position between samples `(q0, v0)` and `(q1, v1)` a period
/// `h` apart, at the fraction `s` of it.
fn hermite(q0: f64, v0: f64, q1: f64, v1: f64, h: f64, s: f64) -> f64 {
    let (s2, s3) = (s * s, s * s * s);
    (2.0 * s3 - 3.0 * s2 + 1.0) * q0
        + (s3 - 2.0 * s2 + s) * h * v0
        + (-2.0 * s3 + 3.0 * s2) * q1
        + (s3 - s2) * h * v1
}

/// The measurement `m` as a logged file with `defects`, drawn from `seed`: time stamps late by
/// the jitter (the positions at the late instant, the torque of the period, which the plant
/// holds through it), samples lost, one gap, duplicated and NaN rows, offset and rounded
/// torques. No velocities (a log may omit them).
#[must_use]
pub fn defective_log<const N: usize>(
    m: &Measurement<N>,
    defects: &LogDefects,
    seed: u64,
) -> JointLog<N> {
    let mut rng = Xoshiro256PlusPlus::seed_from_u64(seed);
    let h = CONTROL_DT_S;
    let offset: [f64; N] = core::array::from_fn(|i| {
        let sign = if i % 2 == 0 { 1.0 } else { -1.0 };
        sign * defects.offset_pct / 100.0 * rms(&m.tau_true, i)
    });
    let t_mid = m.t.get(m.t.len() / 2).copied().unwrap_or(0.0);
    let mut log = JointLog::<N> {
        t: Vec::new(),
        q: Vec::new(),
        qd: None,
        tau: Vec::new(),
        lines: Vec::new(),
    };
    for k in 0..m.t.len().saturating_sub(1) {
        if m.t[k] >= t_mid && m.t[k] < t_mid + defects.gap_s {
            continue;
        }
        if rng.random::<f64>() < defects.drop_probability {
            continue;
        }
        let z: f64 = rng.sample(StandardNormal);
        let late = (z.abs() * defects.jitter_s).min(0.9 * h);
        let s = late / h;
        let q = JointVector::<N>::from_fn(|i, _| {
            let x = hermite(m.q[k][i], m.qd[k][i], m.q[k + 1][i], m.qd[k + 1][i], h, s);
            round_to(x, defects.position_resolution)
        });
        let nan = rng.random::<f64>() < defects.nan_probability;
        let tau = JointVector::<N>::from_fn(|i, _| {
            if nan && i == N - 1 {
                f64::NAN
            } else {
                round_to(m.tau[k][i] + offset[i], defects.torque_resolution)
            }
        });
        let t = round_to(m.t[k] + late, 1e-6);
        let copies = if rng.random::<f64>() < defects.duplicate_probability {
            2
        } else {
            1
        };
        for _ in 0..copies {
            log.t.push(t);
            log.q.push(q);
            log.tau.push(tau);
            log.lines.push(log.lines.len() + 2);
        }
    }
    log
}
