//! The faults of a scenario's environment and plant, placed in the run: the edge of a surface
//! that ends, a stiffness step, a dropped payload; weak actuators, delays and jitter.

// `!(x <= limit)` on purpose: a NaN fails the check and trips.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use super::super::error::ScenarioError;
use super::super::fault_spec::FaultSpec;
use super::super::planned::PlannedReference;
use super::super::spec::Scenario;
use crate::contact::Scene;
use crate::sim::faults::{FaultyEnvironment, PlantFaults, SurfaceEdge};
use nalgebra::Vector3;

/// The plant's faults of `scenario`.
#[must_use]
pub fn plant_faults(scenario: &Scenario) -> PlantFaults {
    let mut p = PlantFaults::default();
    for f in &scenario.faults {
        match f {
            FaultSpec::Actuator(a) => p.actuator = Some(*a),
            FaultSpec::Delay(d) => p.delay = Some(*d),
            FaultSpec::Jitter(j) => p.jitter = Some(*j),
            _ => {}
        }
    }
    p
}

/// `scene` with the environment's faults of `scenario`; a surface's edge goes where
/// `reference` is at the fault's start, square to its motion in the surface's tangent plane.
///
/// # Errors
///
/// [`ScenarioError`] on `faults` if the reference does not move along the surface at the
/// start of a `surface-ends` fault.
pub fn environment<const N: usize>(
    scenario: &Scenario,
    scene: &Scene,
    reference: &dyn PlannedReference<N>,
    gravity: [f64; 3],
) -> Result<FaultyEnvironment, ScenarioError> {
    let mut e = FaultyEnvironment::new(*scene);
    for (i, f) in scenario.faults.iter().enumerate() {
        match *f {
            FaultSpec::SurfaceEnds { surface, start_s } => {
                let c = reference.trajectory().at(start_s);
                let normal = scenario.surfaces[surface]
                    .geometry
                    .closest(&c.position)
                    .normal;
                let along = c.velocity - normal * normal.dot(&c.velocity);
                if !(along.norm() > 1e-6) {
                    return Err(scenario.error(
                        &format!("faults[{i}].start_s"),
                        format!(
                            "the reference does not move along surfaces[{surface}] at {start_s} s ({:.3} mm/s): a surface ends where the tool moves off it",
                            along.norm() * 1e3
                        ),
                    ));
                }
                e.edge = Some(SurfaceEdge {
                    surface,
                    point: c.position,
                    beyond: along / along.norm(),
                });
            }
            FaultSpec::StiffnessStep {
                surface,
                start_s,
                factor,
            } => e.stiffness_step = Some((surface, start_s, factor)),
            FaultSpec::PayloadDrop { mass_kg, start_s } => {
                e.payload = Some((mass_kg, start_s, Vector3::from(gravity)));
            }
            _ => {}
        }
    }
    Ok(e)
}
