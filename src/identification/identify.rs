//! Identification end to end: base parameters, excitation, measurement, estimation,
//! consistency and validation on another trajectory.

use nalgebra::DVector;

use super::base::BaseParameters;
use super::consistency::{check, Consistency};
use super::error::IdentificationError;
use super::estimation::{estimate, rms_error_pct, stack, Estimate};
use super::excitation::{self, design, Excitation, ExcitationLimits, ExcitationSettings};
use super::measurement::{measure, Measurement};
use super::robots::Identifiable;
use crate::model::{JointVector, RobotModel};
use crate::sim::friction::DEFAULT_SMOOTHING;
use crate::sim::JointFriction;

/// Random states of the base-parameter computation.
pub const BASE_STATES: usize = 200;
/// Periods of the excitation measured (and of the validation trajectory).
pub const PERIODS: usize = 2;

/// What to identify and how.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct IdentifySettings {
    /// Torque noise, % of each joint's RMS torque (1 sigma).
    pub noise_pct: f64,
    /// Joint friction in the plant, identified too.
    pub friction: bool,
    /// Seed of everything random (states, search, noise, validation trajectory).
    pub seed: u64,
    /// The excitation search.
    pub excitation: ExcitationSettings,
}

impl IdentifySettings {
    /// `noise_pct` % noise, friction on or off, seed `seed`, the default search.
    #[must_use]
    pub fn new(noise_pct: f64, friction: bool, seed: u64) -> Self {
        Self {
            noise_pct,
            friction,
            seed,
            excitation: ExcitationSettings {
                seed,
                ..ExcitationSettings::default()
            },
        }
    }
}

/// The plant's joint friction in identification runs: per joint, viscous `1.0 m_i` N m s/rad
/// (N s/m) and Coulomb `1.0 m_i` N m (N), with `m_i` the mass-matrix diagonal at the middle
/// of the joint ranges rounded to two significant figures, smoothed over
/// [`DEFAULT_SMOOTHING`]: friction worth a few percent to a few tens of percent of each
/// joint's torque during the excitation.
#[must_use]
pub fn plant_friction<const N: usize, R: RobotModel<N>>(robot: &R) -> JointFriction<N> {
    let m = robot.mass_matrix(&robot.middle_of_limits()).diagonal();
    let round2 = |x: f64| {
        let e = libm::pow(10.0, libm::floor(libm::log10(x)) - 1.0);
        libm::round(x / e) * e
    };
    let c = JointVector::<N>::from_fn(|i, _| round2(m[i]));
    // Diagonal entries of a positive definite M are positive and finite.
    JointFriction::new(c, c, DEFAULT_SMOOTHING).unwrap_or_else(|_| {
        JointFriction::new(
            JointVector::zeros(),
            JointVector::zeros(),
            DEFAULT_SMOOTHING,
        )
        .expect("zero friction is valid")
    })
}

/// What a run on the simulated plant starts from, as [`IdentifySettings`] say: the plant's
/// friction (when asked), the base parameters of the robot with it, and the excitation designed
/// for them within the robot's default limits. [`identify`] and the simulated log
/// ([`simulated_log`](super::sim_log::simulated_log)) both start here, so that the log written
/// for a robot is the run its identification makes.
pub(crate) struct PlantRun<const N: usize> {
    /// The plant's joint friction ([`plant_friction`]); `None` without friction.
    pub friction: Option<JointFriction<N>>,
    /// The base parameters (with the friction terms when there is friction).
    pub base: BaseParameters,
    /// The limits the excitation keeps ([`ExcitationLimits::default_for`]).
    pub limits: ExcitationLimits<N>,
    /// The designed excitation.
    pub excitation: Excitation<N>,
}

impl<const N: usize> PlantRun<N> {
    /// The start of a run of `robot` as `settings` say.
    ///
    /// # Errors
    ///
    /// Those of the base parameters; [`IdentificationError::Setting`] if the designed
    /// excitation breaks a limit.
    pub(crate) fn new<R: Identifiable<N>>(
        robot: &R,
        settings: &IdentifySettings,
    ) -> Result<Self, IdentificationError> {
        let friction = settings.friction.then(|| plant_friction(robot));
        let smoothing = friction.map(|f| f.smoothing());
        let base = BaseParameters::of_robot(robot, smoothing, BASE_STATES, settings.seed)?;
        let limits = ExcitationLimits::default_for::<R>();
        let excitation = design(robot, &base, smoothing, &limits, &settings.excitation);
        if let Some(v) = excitation::check_limits::<N, R>(&excitation.trajectory, &limits) {
            return Err(IdentificationError::Setting(format!(
                "the designed excitation breaks a limit: {v}"
            )));
        }
        Ok(Self {
            friction,
            base,
            limits,
            excitation,
        })
    }
}

/// `|e_i - t_i| / |t_i|`, or over the norm of `t` where `t_i` is zero (a combination the
/// description sets to zero, such as a first moment off the link's axis).
#[must_use]
pub fn relative_errors(estimate: &DVector<f64>, truth: &DVector<f64>) -> Vec<f64> {
    let scale = truth.norm();
    estimate
        .iter()
        .zip(truth.iter())
        .map(|(e, t)| {
            let d = if t.abs() > 1e-12 * scale {
                t.abs()
            } else {
                scale
            };
            (e - t).abs() / d
        })
        .collect()
}

/// Everything an identification found.
#[derive(Clone, Debug)]
pub struct Identification<const N: usize> {
    /// Robot name.
    pub robot: &'static str,
    /// The settings.
    pub settings: IdentifySettings,
    /// Base parameters (of the standard parameters, plus friction when on).
    pub base: BaseParameters,
    /// Friction in the plant, if on.
    pub friction: Option<JointFriction<N>>,
    /// The excitation.
    pub excitation: Excitation<N>,
    /// The measurement on it.
    pub measurement: Measurement<N>,
    /// True base parameters (the plant's).
    pub truth: DVector<f64>,
    /// The estimate.
    pub estimate: Estimate,
    /// [`relative_errors`] of the weighted estimate.
    pub relative_errors: Vec<f64>,
    /// Physical consistency.
    pub consistency: Consistency,
    /// The validation measurement (another trajectory).
    pub validation: Measurement<N>,
    /// Torques of the validation predicted by the estimate, stacked sample by sample.
    pub validation_predicted: DVector<f64>,
    /// Relative RMS prediction error per joint against the measured (noisy) torques, %.
    pub validation_error_pct: Vec<f64>,
    /// The same against the noise-free torques, %.
    pub validation_error_noise_free_pct: Vec<f64>,
}

/// Identifies `robot` as the settings say.
///
/// # Errors
///
/// [`IdentificationError`] from any stage.
pub fn identify<const N: usize, R: Identifiable<N>>(
    robot: &R,
    settings: &IdentifySettings,
) -> Result<Identification<N>, IdentificationError> {
    let PlantRun {
        friction,
        base,
        limits,
        excitation,
    } = PlantRun::new(robot, settings)?;
    let smoothing = friction.map(|f| f.smoothing());
    let measurement = measure(
        robot,
        friction,
        &excitation.trajectory,
        PERIODS,
        settings.noise_pct,
        settings.seed.wrapping_add(1),
    )?;
    let mut pi = robot.standard_parameters();
    if let Some(f) = &friction {
        let len = pi.len() + 2 * N;
        pi = pi.resize_vertically(len, 0.0);
        let p = 10 * N;
        for i in 0..N {
            pi[p + i] = f.viscous()[i];
            pi[p + N + i] = f.coulomb()[i];
        }
    }
    let truth = base.project(&pi);
    let (w, y) = stack(robot, &base, &measurement, smoothing, &measurement.tau);
    let estimate = estimate(&w, &y, N)?;
    let relative_errors = relative_errors(&estimate.weighted, &truth);
    let consistency = check(&base, estimate.weighted.as_slice());
    let validation_trajectory = excitation::random::<N, R>(
        &limits,
        settings.excitation.period_s * 0.8,
        settings.seed.wrapping_add(2),
    );
    let validation = measure(
        robot,
        friction,
        &validation_trajectory,
        PERIODS,
        settings.noise_pct,
        settings.seed.wrapping_add(3),
    )?;
    let (wv, yv) = stack(robot, &base, &validation, smoothing, &validation.tau);
    let (_, yv_true) = stack(robot, &base, &validation, smoothing, &validation.tau_true);
    let validation_predicted = wv * &estimate.weighted;
    Ok(Identification {
        robot: R::NAME,
        settings: *settings,
        base,
        friction,
        excitation,
        validation_error_pct: rms_error_pct(&validation_predicted, &yv, N),
        validation_error_noise_free_pct: rms_error_pct(&validation_predicted, &yv_true, N),
        validation_predicted,
        measurement,
        truth,
        estimate,
        relative_errors,
        consistency,
        validation,
    })
}
