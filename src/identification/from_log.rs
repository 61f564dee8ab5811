//! Identification from a recorded log: processing ([`super::processing`]), base parameters and
//! friction by weighted least squares, the smooth-Coulomb slopes by nonlinear least squares
//! around the linear solution, physically consistent standard parameters
//! ([`super::physical`]), and validation on samples the fit did not see.
//!
//! The model fitted is `tau = Y(q, qd, qdd) pi + F(qd) phi` with `pi` the standard parameters
//! (only their base combinations are identifiable) and `F phi` the friction and offset terms
//! ([`FrictionTerms`]). Estimation rows are the processed samples decimated to about
//! `DECIMATION_PER_CUTOFF` times the cutoff (after the low-pass, closer samples carry the same
//! information); validation uses every processed sample.

use nalgebra::{DMatrix, DVector};

use super::base::BaseParameters;
use super::error::IdentificationError;
use super::estimation::{estimate, joint_sigmas, weigh, Estimate};
use super::friction_model::{FrictionModel, FrictionTerms};
use super::friction_slopes::SlopeProblem;
use super::log::JointLog;
use super::physical::{fit_consistent, Compressed, ConsistentFit, ConsistentSolver};
use super::processing::{process, ProcessReport, ProcessSettings, Processed};
use super::robots::Identifiable;
use super::stages::{Event, Stage, StageTimer};
use super::BASE_STATES;
use crate::model::JointVector;

/// Estimation samples per second over the cutoff frequency.
pub const DECIMATION_PER_CUTOFF: f64 = 20.0;
pub use super::friction_slopes::SLOPE_GRID;

/// How a log is identified.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LogIdentifySettings {
    /// Resampling and filtering.
    pub process: ProcessSettings,
    /// The friction model.
    pub friction: FrictionModel,
    /// A constant torque offset per joint.
    pub offset: bool,
    /// Physically consistent standard parameters (else the base estimate, expanded).
    pub consistent: bool,
    /// The consistent fit's solver.
    pub solver: ConsistentSolver,
    /// Seed of the random states of the base-parameter computation.
    pub seed: u64,
}

impl Default for LogIdentifySettings {
    fn default() -> Self {
        Self {
            process: ProcessSettings::default(),
            friction: FrictionModel::Smooth,
            offset: true,
            consistent: true,
            solver: ConsistentSolver::Barrier,
            seed: 1,
        }
    }
}

/// RMS torque errors per joint of one model on the validation samples.
#[derive(Clone, Debug, PartialEq)]
pub struct TorqueError {
    /// RMS error against the logged torques, N m or N.
    pub rms: Vec<f64>,
    /// The same in % of the logged torque's RMS.
    pub pct: Vec<f64>,
    /// RMS error against the filtered torques, N m or N.
    pub rms_filtered: Vec<f64>,
}

/// Everything an identification from a log found.
#[derive(Clone, Debug)]
pub struct LogIdentification<const N: usize> {
    /// Robot name.
    pub robot: &'static str,
    /// The settings.
    pub settings: LogIdentifySettings,
    /// Processing of the estimation part.
    pub estimation_report: ProcessReport,
    /// Processing of the validation part (same rate and cutoff).
    pub validation_report: ProcessReport,
    /// Estimation samples used (after decimation) and the decimation factor.
    pub estimation_samples: usize,
    /// Every `decimation`-th processed sample is an estimation row.
    pub decimation: usize,
    /// The friction terms, slopes fitted.
    pub terms: FrictionTerms,
    /// Base parameters of the standard parameters plus the friction terms.
    pub base: BaseParameters,
    /// The unconstrained weighted least-squares estimate of the base parameters.
    pub estimate: Estimate,
    /// The consistent fit, if asked.
    pub consistent: Option<ConsistentFit>,
    /// The identified standard parameters (consistent when asked).
    pub standard: DVector<f64>,
    /// The identified friction and offset coefficients (in the order of `terms.names()`).
    pub friction: DVector<f64>,
    /// The base parameters of the identified standard set with its friction.
    pub base_of_identified: DVector<f64>,
    /// The description's standard parameters (the prior, and the nominal model).
    pub nominal: DVector<f64>,
    /// Validation samples.
    pub validation: Processed<N>,
    /// Torques of the validation predicted by the identified model.
    pub predicted: Vec<JointVector<N>>,
    /// Torques of the validation predicted by the description's model (no friction).
    pub predicted_nominal: Vec<JointVector<N>>,
    /// Errors of the identified model.
    pub error: TorqueError,
    /// Errors of the unconstrained base estimate.
    pub error_unconstrained: TorqueError,
    /// Errors of the nominal model.
    pub error_nominal: TorqueError,
    /// Per joint, for the friction figure: `(qd, tau - Y pi)` at the estimation samples.
    pub friction_residual: Vec<Vec<(f64, f64)>>,
    /// Seconds per stage, in order (filtering, linear fit, consistent fit if asked,
    /// validation).
    pub timings: Vec<(Stage, f64)>,
}

fn stack_standard<const N: usize, R: Identifiable<N>>(
    robot: &R,
    p: &Processed<N>,
    rows: &[usize],
) -> (DMatrix<f64>, DVector<f64>) {
    let mut w = DMatrix::zeros(rows.len() * N, 10 * N);
    let mut y = DVector::zeros(rows.len() * N);
    for (r, k) in rows.iter().enumerate() {
        w.view_mut((r * N, 0), (N, 10 * N))
            .copy_from(&robot.regressor(&p.q[*k], &p.qd[*k], &p.qdd[*k]));
        for i in 0..N {
            y[r * N + i] = p.tau[*k][i];
        }
    }
    (w, y)
}

fn friction_block<const N: usize>(
    terms: &FrictionTerms,
    p: &Processed<N>,
    rows: &[usize],
) -> DMatrix<f64> {
    let nf = terms.per_joint() * N;
    let mut f = DMatrix::zeros(rows.len() * N, nf);
    for (r, k) in rows.iter().enumerate() {
        f.view_mut((r * N, 0), (N, nf))
            .copy_from(&terms.columns(p.qd[*k].as_slice()));
    }
    f
}

fn join(a: &DMatrix<f64>, b: &DMatrix<f64>) -> DMatrix<f64> {
    let mut m = DMatrix::zeros(a.nrows(), a.ncols() + b.ncols());
    m.view_mut((0, 0), a.shape()).copy_from(a);
    m.view_mut((0, a.ncols()), b.shape()).copy_from(b);
    m
}

fn torque_error<const N: usize>(predicted: &[JointVector<N>], p: &Processed<N>) -> TorqueError {
    let n = p.len().max(1) as f64;
    let rms = |f: &dyn Fn(usize, usize) -> f64| -> Vec<f64> {
        (0..N)
            .map(|i| libm::sqrt((0..p.len()).map(|k| f(k, i).powi(2)).sum::<f64>() / n))
            .collect()
    };
    let err = rms(&|k, i| predicted[k][i] - p.tau_raw[k][i]);
    let scale = rms(&|k, i| p.tau_raw[k][i]);
    TorqueError {
        pct: err
            .iter()
            .zip(&scale)
            .map(|(e, s)| if *s > 0.0 { 100.0 * e / s } else { f64::NAN })
            .collect(),
        rms: err,
        rms_filtered: rms(&|k, i| predicted[k][i] - p.tau[k][i]),
    }
}

/// Identifies `robot` from the log `estimation`, validated on `validation` (the held-out end of
/// the same log or another log).
///
/// # Errors
///
/// [`IdentificationError`] from the processing or the estimation.
pub fn identify_log<const N: usize, R: Identifiable<N>>(
    robot: &R,
    estimation: &JointLog<N>,
    validation: &JointLog<N>,
    settings: &LogIdentifySettings,
) -> Result<LogIdentification<N>, IdentificationError> {
    identify_log_observed(robot, estimation, validation, settings, &mut |_| {})
}

/// [`identify_log`], telling `observer` where it is ([`Event`]s of the stages filtering,
/// linear fit, consistent fit and validation); the stages' times are in the result.
///
/// # Errors
///
/// As [`identify_log`].
pub fn identify_log_observed<const N: usize, R: Identifiable<N>>(
    robot: &R,
    estimation: &JointLog<N>,
    validation: &JointLog<N>,
    settings: &LogIdentifySettings,
    observer: &mut dyn FnMut(Event<'_>),
) -> Result<LogIdentification<N>, IdentificationError> {
    let mut timer = StageTimer::new(observer);
    timer.start(Stage::Filtering);
    let (pe, estimation_report) = process(estimation, &settings.process)
        .map_err(|e| IdentificationError::Setting(format!("estimation log: {e}")))?;
    timer.progress(1, Some(2), "parts");
    let fixed = ProcessSettings {
        rate_hz: Some(estimation_report.rate_hz),
        cutoff_hz: Some(estimation_report.cutoff_hz),
        ..settings.process
    };
    let (pv, validation_report) = process(validation, &fixed)
        .map_err(|e| IdentificationError::Setting(format!("validation log: {e}")))?;
    timer.progress(2, Some(2), "parts");
    timer.start(Stage::LinearFit);
    let decimation = (libm::floor(
        estimation_report.rate_hz / (DECIMATION_PER_CUTOFF * estimation_report.cutoff_hz),
    ) as usize)
        .max(1);
    let rows: Vec<usize> = (0..pe.len()).step_by(decimation).collect();
    let mut terms = FrictionTerms::new(settings.friction, settings.offset, N, 0.05);
    let mut names = robot.parameter_names();
    names.extend(terms.names());
    let structure = terms.clone();
    let base =
        BaseParameters::of_regressor(robot, names, BASE_STATES, settings.seed, |q, qd, qdd| {
            join(
                &robot.regressor(q, qd, qdd),
                &structure.columns(qd.as_slice()),
            )
        })?;
    let (w_std, y) = stack_standard(robot, &pe, &rows);
    let full = |terms: &FrictionTerms| join(&w_std, &friction_block(terms, &pe, &rows));
    let first = estimate(&base.select(&full(&terms)), &y, N)?;
    if settings.friction == FrictionModel::Smooth {
        let sigma = joint_sigmas(&first.residual_std);
        let friction = friction_block(&terms, &pe, &rows);
        let problem = SlopeProblem::new(&base, &w_std, &friction, &y, &sigma, N)?;
        let qd: Vec<&[f64]> = rows.iter().map(|k| pe.qd[*k].as_slice()).collect();
        terms.slopes = problem.fit(&qd, &mut |done| {
            timer.progress(done as u64, None, "friction-slope residuals");
        });
    }
    let w_full = full(&terms);
    let est = estimate(&base.select(&w_full), &y, N)?;
    let p = 10 * N;
    let nf = terms.per_joint() * N;
    let expanded = base.expand(&est.weighted);
    let nominal = robot.standard_parameters();
    let (consistent, standard, friction) = if settings.consistent {
        timer.start(Stage::ConsistentFit);
        let sigma = joint_sigmas(&est.residual_std);
        let (ww, yw) = weigh(&w_full, &y, &sigma);
        let data = Compressed::of(&ww, &yw)?;
        let mut report = |done: usize, budget: usize| {
            timer.progress(done as u64, Some(budget as u64), "evaluations");
        };
        let fit = fit_consistent(
            &data,
            &nominal,
            &expanded.rows(p, nf).into_owned(),
            settings.solver,
            &settings.solver.stopping(),
            Some(&mut report),
        )?;
        let (s, f) = (fit.standard.clone(), fit.extra.clone());
        (Some(fit), s, f)
    } else {
        (
            None,
            expanded.rows(0, p).into_owned(),
            expanded.rows(p, nf).into_owned(),
        )
    };
    let mut identified_full = DVector::zeros(p + nf);
    identified_full.rows_mut(0, p).copy_from(&standard);
    identified_full.rows_mut(p, nf).copy_from(&friction);
    let base_of_identified = base.project(&identified_full);
    timer.start(Stage::Validation);
    // Validation.
    let mut predicted = Vec::with_capacity(pv.len());
    let mut predicted_unconstrained = Vec::with_capacity(pv.len());
    let mut predicted_nominal = Vec::with_capacity(pv.len());
    for k in 0..pv.len() {
        let yk = robot.regressor(&pv.q[k], &pv.qd[k], &pv.qdd[k]);
        let fk = terms.columns(pv.qd[k].as_slice());
        let rigid = &yk * &standard;
        let with_friction = rigid + &fk * &friction;
        predicted.push(JointVector::<N>::from_column_slice(
            with_friction.as_slice(),
        ));
        let fullk = join(&yk, &fk);
        let b = base.select(&fullk) * &est.weighted;
        predicted_unconstrained.push(JointVector::<N>::from_column_slice(b.as_slice()));
        let nom = &yk * &nominal;
        predicted_nominal.push(JointVector::<N>::from_column_slice(nom.as_slice()));
    }
    let friction_residual = (0..N)
        .map(|i| {
            rows.iter()
                .map(|k| {
                    let yk = robot.regressor(&pe.q[*k], &pe.qd[*k], &pe.qdd[*k]);
                    let rigid = (yk.row(i) * &standard)[0];
                    (pe.qd[*k][i], pe.tau[*k][i] - rigid)
                })
                .collect()
        })
        .collect();
    let timings = timer.times();
    Ok(LogIdentification {
        robot: R::NAME,
        settings: *settings,
        estimation_report,
        validation_report,
        estimation_samples: rows.len(),
        decimation,
        error: torque_error(&predicted, &pv),
        error_unconstrained: torque_error(&predicted_unconstrained, &pv),
        error_nominal: torque_error(&predicted_nominal, &pv),
        terms,
        base,
        estimate: est,
        consistent,
        standard,
        friction,
        base_of_identified,
        nominal,
        validation: pv,
        predicted,
        predicted_nominal,
        friction_residual,
        timings,
    })
}
