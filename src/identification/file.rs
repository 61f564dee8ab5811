//! `identification.json`: what `armdyn identify` writes, and the controller model read back
//! from it.

use std::path::Path;

use serde_json::{json, Value};

use super::identify::Identification;
use crate::model::{Parametric, ParametricModel};

/// An `identification.json` that cannot give a controller model.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{file}: {}{rule}", if key.is_empty() { String::new() } else { format!("`{key}`: ") })]
pub struct ModelFileError {
    /// The file.
    pub file: String,
    /// The key at fault (empty for the whole file).
    pub key: String,
    /// What is wrong.
    pub rule: String,
}

/// The JSON of an identification.
#[must_use]
pub fn to_json<const N: usize>(id: &Identification<N>) -> Value {
    let e = &id.excitation;
    let t = &e.trajectory;
    let friction = id.friction.map(|f| {
        json!({
            "viscous_true": f.viscous().as_slice(),
            "coulomb_true": f.coulomb().as_slice(),
            "coulomb_smoothing": f.smoothing(),
            "law": "tau_f = fv qd + fc tanh(qd / coulomb_smoothing)",
        })
    });
    json!({
        "robot": id.robot,
        "units": "SI: kg, kg m, kg m^2 (inertia about each link frame's origin), N m s/rad or N s/m (fv), N m or N (fc); torques N m or N",
        "noise_pct": id.settings.noise_pct,
        "friction": friction,
        "seed": id.settings.seed,
        "parameter_names": id.base.parameter_names(),
        "base_parameter_count": id.base.count(),
        "base_parameter_names": id.base.names(),
        "base_parameter_indices": id.base.independent(),
        "unidentifiable_parameters": id.base.unidentifiable(),
        "base_parameters_true": id.truth.as_slice(),
        "base_parameters_estimated": id.estimate.weighted.as_slice(),
        "base_parameters_ordinary_ls": id.estimate.ordinary.as_slice(),
        "relative_errors": id.relative_errors,
        "relative_std_pct": id.estimate.relative_std_pct,
        "residual_std": id.estimate.residual_std,
        "condition_number": e.condition_number,
        "excitation": {
            "period_s": t.period_s(),
            "harmonics": super::HARMONICS,
            "offset": t.offset().as_slice(),
            "a": (0..N).map(|i| t.coefficients(i).0.to_vec()).collect::<Vec<_>>(),
            "b": (0..N).map(|i| t.coefficients(i).1.to_vec()).collect::<Vec<_>>(),
            "condition_number_best_random_start": e.initial_condition_number,
            "evaluations": e.evaluations,
            "peak_effort_fraction": e.peak_effort_fraction.as_slice(),
            "max_tracking_error": id.measurement.max_tracking_error.as_slice(),
            "samples": id.measurement.t.len(),
        },
        "noise_std": id.measurement.noise_std.as_slice(),
        "physical_consistency": {
            "all_checks_passed": id.consistency.all_ok(),
            "checks": id.consistency.checks.iter().map(|c| json!({"rule": c.rule, "ok": c.ok})).collect::<Vec<_>>(),
            "summary": id.consistency.summary(),
        },
        "validation_torque_rms_error_pct": id.validation_error_pct,
        "validation_torque_rms_error_noise_free_pct": id.validation_error_noise_free_pct,
    })
}

/// The model of `robot` an `identification.json` describes: the estimated base parameters
/// put back into a standard parameter vector (each base parameter on its leading parameter,
/// the regrouped ones zero), which gives the same torques as the estimate at every state.
///
/// # Errors
///
/// [`ModelFileError`] naming the file, the key and the rule: not readable, not JSON, another
/// robot, missing or mistyped keys, indices out of range, non-finite values.
pub fn read_model<const N: usize, R: ParametricModel<N>>(
    path: &Path,
    robot: R,
) -> Result<Parametric<N, R>, ModelFileError> {
    let file = path.display().to_string();
    let err = |key: &str, rule: String| ModelFileError {
        file: file.clone(),
        key: key.to_string(),
        rule,
    };
    let text = std::fs::read_to_string(path).map_err(|e| err("", format!("cannot read: {e}")))?;
    let v: Value = serde_json::from_str(&text).map_err(|e| err("", format!("not JSON: {e}")))?;
    let name = v
        .get("robot")
        .and_then(Value::as_str)
        .ok_or_else(|| err("robot", "is missing or not a string".into()))?;
    if name != R::NAME {
        return Err(err(
            "robot",
            format!(
                "identifies `{name}`; a controller model must be of `{}`, the scenario's robot",
                R::NAME
            ),
        ));
    }
    let numbers = |key: &str| -> Result<Vec<f64>, ModelFileError> {
        let a = v
            .get(key)
            .and_then(Value::as_array)
            .ok_or_else(|| err(key, "is missing or not an array".into()))?;
        a.iter()
            .enumerate()
            .map(|(i, x)| {
                x.as_f64()
                    .filter(|x| x.is_finite())
                    .ok_or_else(|| err(&format!("{key}[{i}]"), "is not a finite number".into()))
            })
            .collect()
    };
    let names = v
        .get("parameter_names")
        .and_then(Value::as_array)
        .ok_or_else(|| err("parameter_names", "is missing or not an array".into()))?;
    let indices = numbers("base_parameter_indices")?;
    let values = numbers("base_parameters_estimated")?;
    if indices.len() != values.len() || indices.is_empty() {
        return Err(err(
            "base_parameters_estimated",
            format!(
                "has {} values for {} base_parameter_indices; they must match and not be empty",
                values.len(),
                indices.len()
            ),
        ));
    }
    let mut params = R::standard_parameters();
    params.as_mut().fill(0.0);
    for (k, (i, x)) in indices.iter().zip(&values).enumerate() {
        let key = format!("base_parameter_indices[{k}]");
        if i.fract() != 0.0 || *i < 0.0 || *i as usize >= names.len() {
            return Err(err(
                &key,
                format!(
                    "{i} is not an index of parameter_names (0 to {})",
                    names.len().saturating_sub(1)
                ),
            ));
        }
        let i = *i as usize;
        if indices[..k].contains(&(i as f64)) {
            return Err(err(
                &key,
                format!("{i} appears twice; each parameter leads one base parameter at most"),
            ));
        }
        // Friction parameters (after the 10 N standard ones) are not part of the rigid-body
        // model.
        if let Some(p) = params.as_mut().get_mut(i) {
            *p = *x;
        }
    }
    Ok(Parametric::new(robot, params))
}
