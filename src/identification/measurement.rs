//! The measurement run: the excitation tracked on the simulated plant, torques recorded with
//! seeded noise.
//!
//! A computed-torque controller on the nominal model tracks the trajectory (1 ms sample,
//! 0.2 ms RK4 plant step; the plant may have joint friction the controller does not know).
//! At each sample the record holds the state, the plant's acceleration under the torque just
//! applied (an ideal differentiator: a rig would filter and differentiate its encoders) and
//! that torque plus white Gaussian noise of `noise_pct` % of the joint's RMS torque.

use rand::rngs::Xoshiro256PlusPlus;
use rand::{RngExt, SeedableRng};
use rand_distr::StandardNormal;

use super::error::IdentificationError;
use super::fourier::FourierExcitation;
use super::robots::Identifiable;
use crate::contact::FreeSpace;
use crate::control::computed_torque::ComputedTorque;
use crate::model::{forward_dynamics, JointVector, RobotModel, Wrench};
use crate::sim::{simulate, JointFriction, ReferenceSource, Setpoint, SimConfig};
use crate::target::CartesianTarget;
use crate::target::JointTarget;

/// Controller sample period of the measurement run, s.
pub const CONTROL_DT_S: f64 = 1e-3;
/// Plant step of the measurement run, s.
pub const PLANT_DT_S: f64 = 2e-4;
/// Natural frequency of the tracking controller, rad/s.
pub const TRACKING_OMEGA: f64 = 20.0;

/// What was measured, one entry per control sample.
#[derive(Clone, Debug, PartialEq)]
pub struct Measurement<const N: usize> {
    /// Time, s.
    pub t: Vec<f64>,
    /// Joint positions, rad or m.
    pub q: Vec<JointVector<N>>,
    /// Joint velocities.
    pub qd: Vec<JointVector<N>>,
    /// Joint accelerations.
    pub qdd: Vec<JointVector<N>>,
    /// Applied torques, N m or N, as the plant felt them.
    pub tau_true: Vec<JointVector<N>>,
    /// Applied torques with the measurement noise.
    pub tau: Vec<JointVector<N>>,
    /// Standard deviation of the noise per joint, N m or N.
    pub noise_std: [f64; N],
    /// Largest tracking error per joint, rad or m.
    pub max_tracking_error: [f64; N],
}

struct Follow<'a, const N: usize>(&'a FourierExcitation<N>);

impl<const N: usize> ReferenceSource<N> for Follow<'_, N> {
    fn at(&mut self, t: f64) -> Setpoint<N> {
        let (q, qd, qdd) = self.0.state(t);
        Setpoint {
            joint: JointTarget {
                q: q.into(),
                qd: qd.into(),
                qdd: qdd.into(),
            },
            cartesian: CartesianTarget::at_rest(
                nalgebra::Vector3::zeros(),
                nalgebra::UnitQuaternion::identity(),
            ),
            wrench: Wrench::zeros(),
        }
    }
}

/// Runs `excitation` for `periods` periods on the plant (`robot` with `friction`) and
/// records it with `noise_pct` % noise drawn from `seed`.
///
/// # Errors
///
/// [`IdentificationError::Simulation`] if the run breaks down;
/// [`IdentificationError::Setting`] for a negative or non-finite noise level.
pub fn measure<const N: usize, R: Identifiable<N>>(
    robot: &R,
    friction: Option<JointFriction<N>>,
    excitation: &FourierExcitation<N>,
    periods: usize,
    noise_pct: f64,
    seed: u64,
) -> Result<Measurement<N>, IdentificationError> {
    let duration = excitation.period_s() * periods as f64 - CONTROL_DT_S;
    measure_plant(
        robot, robot, friction, excitation, duration, noise_pct, seed,
    )
}

/// [`measure`] on a plant other than the controller's model (`plant`, for instance `robot`'s
/// kinematics with other inertial parameters), for `duration` s of the (periodic) excitation.
///
/// # Errors
///
/// As [`measure`].
pub fn measure_plant<const N: usize, P: RobotModel<N>, R: Identifiable<N>>(
    plant: &P,
    robot: &R,
    friction: Option<JointFriction<N>>,
    excitation: &FourierExcitation<N>,
    duration: f64,
    noise_pct: f64,
    seed: u64,
) -> Result<Measurement<N>, IdentificationError> {
    if !(noise_pct.is_finite() && noise_pct >= 0.0) {
        return Err(IdentificationError::Setting(format!(
            "noise {noise_pct} %: must be finite and >= 0"
        )));
    }
    let (q0, qd0, _) = excitation.state(0.0);
    if !(duration.is_finite() && duration > 0.0) {
        return Err(IdentificationError::Setting(format!(
            "measurement of {duration} s: must be finite and > 0"
        )));
    }
    let mut config = SimConfig::new(plant);
    config.duration = duration;
    config.control_dt = CONTROL_DT_S;
    config.plant_dt = PLANT_DT_S;
    config.q0 = q0.into();
    config.qd0 = qd0.into();
    config.friction = friction;
    let mut controller = ComputedTorque::critically_damped(*robot, TRACKING_OMEGA);
    let mut reference = Follow(excitation);
    let capacity = (config.duration / CONTROL_DT_S) as usize + 2;
    let mut m = Measurement {
        t: Vec::with_capacity(capacity),
        q: Vec::with_capacity(capacity),
        qd: Vec::with_capacity(capacity),
        qdd: Vec::with_capacity(capacity),
        tau_true: Vec::with_capacity(capacity),
        tau: Vec::new(),
        noise_std: [0.0; N],
        max_tracking_error: [0.0; N],
    };
    let mut failure = None;
    simulate(
        plant,
        &mut controller,
        &mut reference,
        &FreeSpace,
        &config,
        |s| {
            let tau_f = friction.map_or(JointVector::zeros(), |f| f.torque(&s.qd));
            match forward_dynamics(plant, &s.q, &s.qd, &s.tau, &tau_f) {
                Ok(qdd) => {
                    m.t.push(s.t);
                    m.q.push(s.q);
                    m.qd.push(s.qd);
                    m.qdd.push(qdd);
                    m.tau_true.push(s.tau);
                    for i in 0..N {
                        let e = (s.setpoint.joint.q[i] - s.q[i]).abs();
                        m.max_tracking_error[i] = m.max_tracking_error[i].max(e);
                    }
                }
                Err(e) => failure = Some(format!("t = {} s: {e}", s.t)),
            }
        },
    )
    .map_err(|e| IdentificationError::Simulation(e.to_string()))?;
    if let Some(f) = failure {
        return Err(IdentificationError::Simulation(f));
    }
    let n = m.tau_true.len() as f64;
    let mut rng = Xoshiro256PlusPlus::seed_from_u64(seed);
    for i in 0..N {
        let rms = libm::sqrt(m.tau_true.iter().map(|t| t[i] * t[i]).sum::<f64>() / n);
        m.noise_std[i] = noise_pct / 100.0 * rms;
    }
    m.tau = m
        .tau_true
        .iter()
        .map(|t| {
            JointVector::<N>::from_fn(|i, _| {
                let z: f64 = rng.sample(StandardNormal);
                t[i] + m.noise_std[i] * z
            })
        })
        .collect();
    Ok(m)
}

/// Root mean square of joint `i` over `v`.
#[must_use]
pub fn rms<const N: usize>(v: &[JointVector<N>], i: usize) -> f64 {
    libm::sqrt(v.iter().map(|x| x[i] * x[i]).sum::<f64>() / v.len().max(1) as f64)
}
