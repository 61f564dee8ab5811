//! A log as a real robot would record it, made on the simulated plant: the measurement of
//! [`super::measurement`] (friction and torque noise as set there, optionally on a plant with
//! [`super::unmodelled`] effects) with the defects of real logging added ([`LogDefects`]), for
//! examples and tests of the log reader and identification ([`simulated_log`], what
//! `armdyn identify --write-log` writes, as [`logged_csv`]).

use rand::rngs::Xoshiro256PlusPlus;
use rand::{RngExt, SeedableRng};
use rand_distr::StandardNormal;

use super::error::IdentificationError;
use super::identify::{IdentifySettings, PlantRun};
use super::log::JointLog;
use super::measurement::{measure_plant, rms, Measurement, CONTROL_DT_S};
use super::robots::Identifiable;
use super::unmodelled::{measure_unmodelled, Unmodelled};
use crate::model::{JointVector, ParametricModel};

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

/// How a simulated log is made beyond the identification settings.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct LogRecipe {
    /// Length, s (the excitation repeated; `None`: one period).
    pub seconds: Option<f64>,
    /// The logging defects.
    pub defects: LogDefects,
    /// What the plant has that the identification does not model.
    pub unmodelled: Unmodelled,
}

/// A simulated log and what it was made of.
#[derive(Clone, Debug, PartialEq)]
pub struct SimulatedLog<const N: usize> {
    /// The log.
    pub log: JointLog<N>,
    /// Length of the measurement, s.
    pub duration_s: f64,
    /// Period of the excitation, s.
    pub period_s: f64,
}

/// The log `armdyn identify --write-log` writes: the excitation designed for `robot` as
/// `settings` say (search, seed), tracked on the plant (`settings`' friction and noise, plus
/// `recipe.unmodelled`) for `recipe.seconds` and logged with `recipe.defects`. Seeds: the base
/// parameters and excitation `seed`, the noise `seed + 1`, the defects `seed + 4`.
///
/// # Errors
///
/// [`IdentificationError::Setting`] for a length that is not finite in `(0, 3600]` s,
/// unmodelled friction without friction or a designed excitation that breaks a limit; those
/// of the base parameters and the measurement.
pub fn simulated_log<const N: usize, R: Identifiable<N> + ParametricModel<N>>(
    robot: &R,
    settings: &IdentifySettings,
    recipe: &LogRecipe,
) -> Result<SimulatedLog<N>, IdentificationError> {
    if let Some(d) = recipe.seconds {
        if !(d.is_finite() && d > 0.0 && d <= 3600.0) {
            return Err(IdentificationError::Setting(format!(
                "log of {d} s: must be in (0, 3600]"
            )));
        }
    }
    let PlantRun {
        friction,
        excitation: e,
        ..
    } = PlantRun::new(robot, settings)?;
    let period_s = e.trajectory.period_s();
    let duration_s = recipe.seconds.unwrap_or(period_s - CONTROL_DT_S);
    let seed = settings.seed.wrapping_add(1);
    let noise = settings.noise_pct;
    let m = if recipe.unmodelled == Unmodelled::default() {
        measure_plant(
            robot,
            robot,
            friction,
            &e.trajectory,
            duration_s,
            noise,
            seed,
        )?
    } else {
        let u = &recipe.unmodelled;
        measure_unmodelled(robot, friction, u, &e.trajectory, duration_s, noise, seed)?
    };
    Ok(SimulatedLog {
        log: defective_log(&m, &recipe.defects, settings.seed.wrapping_add(4)),
        duration_s,
        period_s,
    })
}

/// `log` as CSV (`t, q1..qN, tau1..tauN`) at the resolutions of [`LogDefects::default`]:
/// time stamps and positions to 1e-6, torques to 1e-4.
#[must_use]
pub fn logged_csv<const N: usize>(log: &JointLog<N>) -> String {
    let mut text = String::from("t");
    for p in ["q", "tau"] {
        for i in 1..=N {
            text.push_str(&format!(",{p}{i}"));
        }
    }
    text.push('\n');
    let fixed = |x: f64, d: usize| {
        if x.is_nan() {
            "NaN".to_string()
        } else {
            format!("{x:.d$}")
        }
    };
    for k in 0..log.len() {
        text.push_str(&fixed(log.t[k], 6));
        for x in log.q[k].iter() {
            text.push(',');
            text.push_str(&fixed(*x, 6));
        }
        for x in log.tau[k].iter() {
            text.push(',');
            text.push_str(&fixed(*x, 4));
        }
        text.push('\n');
    }
    text
}
