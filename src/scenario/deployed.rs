//! A scenario run with its hybrid controller as the deployable step
//! ([`ScaraHybrid`](crate::robots::scara::deploy::ScaraHybrid)) in `f32` or `f64`: the controller a
//! microcontroller would run, rounding included, against the usual `f64` plant, to see
//! before deployment what single precision changes.

use super::controllers::ForceController;
use super::error::ScenarioError;
use super::plant::ControllerModel;
use super::spec::Scenario;
use super::trial::{force_sensor, prepare, Prepared};
use crate::contact::{Sensed, SurfaceGeometry};
use crate::control::force::ForcePi;
use crate::control::selection::SelectionPolicy;
use crate::control::task_frame::TaskFrame;
use crate::model::Scara;
use crate::robots::scara::deploy::{Deployed, ScaraHybrid, ScaraScalar};

/// [`prepare`], with the controller replaced by the deployable step in precision `T` (behind
/// the scenario's force sensor, if any), its gains those `prepare` chose (given or designed).
///
/// The deployable step is the hybrid law with PID and feedback linearization, PI +
/// feedforward (+ velocity damping) along a fixed normal and a switch at a time, on the
/// description's model; a scenario asking for more is refused.
///
/// # Errors
///
/// [`ScenarioError`] naming the first key the deployable step cannot follow (or any error
/// of [`prepare`]).
pub fn prepare_deployed<T: ScaraScalar>(scenario: &Scenario) -> Result<Prepared, ScenarioError> {
    let (normal, switch_s) = deployable(scenario)?;
    let mut p = prepare(scenario)?;
    let (kfp, kfi, kvd) = p.gains.force.ok_or_else(|| {
        scenario.error(
            "force",
            "the deployable step needs the force loop's PI gains",
        )
    })?;
    let position = scenario
        .position
        .feedback_linearization(Scara)
        .ok_or_else(|| scenario.error("position.law", "not a PID with feedback linearization"))?
        .map_err(|e| scenario.error("position.law", e))?;
    let step = ScaraHybrid::<T>::new(
        &position,
        &ForcePi::new(kfp, kfi, kvd),
        &TaskFrame::Fixed(normal),
        &SelectionPolicy::Time { switch_s },
    )
    .map_err(|e| scenario.error("force", e.to_string()))?;
    p.controller = match force_sensor(scenario)? {
        Some(sensor) => Box::new(Sensed::new(Deployed::new(step), sensor)),
        None => Box::new(Deployed::new(step)),
    };
    p.gains.note = format!(
        "{}; run by the deployable step (scara::robots::scara::deploy::ScaraHybrid) in f{}",
        p.gains.note,
        T::BITS
    );
    Ok(p)
}

/// What the deployable step needs of a scenario: the force surface's (plane's) normal and the
/// switching time; an error naming the first key it cannot follow.
fn deployable(scenario: &Scenario) -> Result<(nalgebra::Vector3<f64>, f64), ScenarioError> {
    let refuse =
        |key: &str, why: &str| Err(scenario.error(key, format!("the deployable step {why}")));
    if !matches!(scenario.controller_model, ControllerModel::Nominal) {
        return refuse(
            "controller_model",
            "runs on the description's generated model only, not an identified one",
        );
    }
    if scenario.position.feedback_linearization(Scara).is_none() {
        return refuse(
            "position.law",
            "has PID with feedback linearization as its position loop (pid-fl or pid-fl-central)",
        );
    }
    let Some(f) = &scenario.force else {
        return refuse(
            "force",
            "is a hybrid force/position law: the scenario needs a [force] table",
        );
    };
    if !matches!(f.law, ForceController::PiFf | ForceController::PiFfVd) {
        return refuse(
            "force.law",
            "controls force by PI + feedforward (pi-ff or pi-ff-vd)",
        );
    }
    let normal = match scenario.surfaces[f.surface].geometry {
        SurfaceGeometry::Plane { normal, .. } => normal,
        _ => {
            return refuse(
                &format!("surfaces[{}]", f.surface),
                "controls force along a fixed normal: the force surface must be a plane",
            )
        }
    };
    let Some(SelectionPolicy::Time { switch_s }) = scenario.selection else {
        return refuse(
            "selection",
            "switches to force control at a time, not on detected contact",
        );
    };
    if f.anti_windup {
        return refuse(
            "force.anti_windup",
            "has no anti-windup: set anti_windup = false",
        );
    }
    if f.friction_feedforward != 0.0 {
        return refuse("force.friction_feedforward", "has no friction feedforward");
    }
    if f.gravity_compensation {
        return refuse(
            "force.gravity_compensation",
            "has no gravity compensation along the normal",
        );
    }
    Ok((normal, switch_s))
}
