//! The SCARA in a scenario: its thesis references by name, its elbow plan (a stepped switch
//! or planned flips) with the closed-form inverse kinematics at every sample, and its
//! deployable hybrid step; the generic scenario layer reaches them through
//! [`ScenarioRobot`].

use std::sync::Arc;

use nalgebra::Vector3;
use serde_json::json;

use super::deploy::{Deployed, ScaraHybrid, ScaraScalar, SupervisedHybrid};
use super::elbow_flip::{plan_flips, ElbowFlip, FlipError, FlipOptions};
use super::elbow_keys::{ElbowSwitchSpec, REFERENCE_KEYS};
use super::reference::ScaraReference;
use super::thesis::{ContactTest, PositionTest, ThreeZone};
use super::{ElbowPlan, ScaraGeometry, SwitchPolicy};
use crate::contact::SurfaceGeometry;
use crate::control::force::ForcePi;
use crate::control::safety::SafetyLimits;
use crate::control::selection::SelectionPolicy;
use crate::control::task_frame::TaskFrame;
use crate::control::Controller;
use crate::model::{JointVector, Scara};
use crate::scenario::vocabulary::KeyError;
use crate::scenario::{
    ControllerModel, ForceController, PlannedReference, Precision, ReferenceReport,
    RobotVocabulary, Scenario, ScenarioError, ScenarioRobot, SharedTrajectory,
};
use crate::sim::{ReferenceSource, Sample, Setpoint};
use crate::trajectory::pause::Paused;
use crate::trajectory::CartesianTrajectory;

/// The thesis references by name.
pub const NAMED_REFERENCES: [&str; 3] = ["position", "contact", "three-zone"];

/// The contact reference's on-surface height when a file gives none, m (Appendix B.3).
pub const CONTACT_SURFACE_Z_M: f64 = 0.13;

/// The SCARA's planned reference: the elbow plan, its flips, and the closed form at every
/// sample.
pub struct ScaraPlan {
    reference: ScaraReference<Box<dyn CartesianTrajectory + Send + Sync>>,
    flips: Vec<ElbowFlip>,
    start: JointVector<4>,
}

impl ScaraPlan {
    /// The elbow plan.
    #[must_use]
    pub fn plan(&self) -> &ElbowPlan {
        self.reference.plan()
    }

    /// The planned flips.
    #[must_use]
    pub fn flips(&self) -> &[ElbowFlip] {
        &self.flips
    }
}

/// What a run did during one planned flip.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FlipSummary {
    /// Start of the joint moves, s.
    pub start_s: f64,
    /// Their length, s.
    pub duration_s: f64,
    /// How much later the reference resumes than it would have, s.
    pub time_shift_s: f64,
    /// Largest applied `|tau_i| / effort_i` during the moves.
    pub max_tau_fraction: f64,
    /// Lowest tool height while the arm swings to the other elbow (between the lift and the
    /// lowering), m.
    pub min_tool_z_m: f64,
}

impl ScaraPlan {
    /// What the run of `samples` did during each planned flip.
    #[must_use]
    pub fn flip_summaries(
        &self,
        samples: &[Sample<4>],
        effort: &JointVector<4>,
    ) -> Vec<(ElbowFlip, FlipSummary)> {
        self.flips
            .iter()
            .map(|f| {
                let (a, b) = f.interval();
                let during = || samples.iter().filter(move |s| a <= s.t && s.t <= b);
                let (sa, sb) = f.swing().map_or((a, b), |m| (m.start_s, m.end_s()));
                let swinging = || samples.iter().filter(move |s| sa <= s.t && s.t <= sb);
                let summary = FlipSummary {
                    start_s: a,
                    duration_s: b - a,
                    time_shift_s: f.pause.shift_s(),
                    max_tau_fraction: during()
                        .flat_map(|s| (0..4).map(move |i| (s.tau[i] / effort[i]).abs()))
                        .fold(0.0, f64::max),
                    min_tool_z_m: swinging()
                        .map(|s| s.position.z)
                        .fold(f64::INFINITY, f64::min),
                };
                (f.clone(), summary)
            })
            .collect()
    }
}

impl ReferenceSource<4> for ScaraPlan {
    fn at(&mut self, t: f64) -> Setpoint<4> {
        self.reference.at(t)
    }
}

impl PlannedReference<4> for ScaraPlan {
    fn trajectory(&self) -> &dyn CartesianTrajectory {
        self.reference.trajectory().as_ref()
    }

    fn start(&self) -> JointVector<4> {
        self.start
    }

    fn joints_at(&self, t: f64, position: &Vector3<f64>) -> Result<JointVector<4>, String> {
        let yaw = self.trajectory().at(t).yaw();
        self.reference
            .geometry()
            .inverse(position, yaw, self.plan().elbow_at(t))
            .map_err(|e| e.to_string())
    }

    fn report(&self, samples: &[Sample<4>], effort_limits: &JointVector<4>) -> ReferenceReport {
        let plan = self.plan();
        let mut metrics = serde_json::Map::new();
        metrics.insert(
            "elbow".into(),
            json!({
                "initial": plan.initial().to_string(),
                "switches_s": plan.switches().iter().map(|s| s.t).collect::<Vec<_>>(),
            }),
        );
        let flips = self.flip_summaries(samples, effort_limits);
        let mut notes = Vec::new();
        if let Some((first, _)) = flips.first() {
            let sum = |f: fn(&FlipSummary) -> f64| flips.iter().map(|(_, s)| f(s)).sum::<f64>();
            let max = |f: fn(&FlipSummary) -> f64| {
                flips
                    .iter()
                    .map(|(_, s)| f(s))
                    .fold(f64::NEG_INFINITY, f64::max)
            };
            metrics.insert("elbow_switch".into(), json!("planned"));
            metrics.insert("flip_start_s".into(), json!(flips[0].1.start_s));
            metrics.insert("flip_duration_s".into(), json!(sum(|s| s.duration_s)));
            metrics.insert(
                "reference_time_shift_s".into(),
                json!(sum(|s| s.time_shift_s)),
            );
            metrics.insert(
                "flip_max_tau_fraction".into(),
                json!(max(|s| s.max_tau_fraction)),
            );
            metrics.insert(
                "flip_planned_max_tau_fraction".into(),
                json!(first.planned_effort_fraction),
            );
            metrics.insert(
                "min_tool_z_during_flip_m".into(),
                json!(-max(|s| -s.min_tool_z_m)),
            );
            metrics.insert("flip_clearance_z_m".into(), json!(first.clearance_z_m));
        }
        for (f, s) in &flips {
            notes.push(format!(
                "elbow flip {} -> {}: from {:.3} s for {:.3} s (reference resumes {:.3} s later), max |tau| {:.1} % of the effort limits (planned {:.1} %), tool z >= {:.4} m",
                f.from,
                f.to,
                s.start_s,
                s.duration_s,
                s.time_shift_s,
                100.0 * s.max_tau_fraction,
                100.0 * f.planned_effort_fraction,
                s.min_tool_z_m
            ));
        }
        if !plan.switches().is_empty() {
            let s: Vec<String> = plan
                .switches()
                .iter()
                .map(|s| format!("{:.3} s -> {}", s.t, s.to))
                .collect();
            notes.push(format!(
                "elbow: starts {}, switches at {}",
                plan.initial(),
                s.join(", ")
            ));
        }
        ReferenceReport {
            singular_samples: self.reference.singular_samples(),
            failed_samples: self.reference.failed_samples(),
            metrics,
            notes,
        }
    }
}

/// The planned flip's settings of a scenario (`None`: the thesis's step).
fn flip_options(
    scenario: &Scenario,
    sample_dt_s: f64,
) -> Result<Option<FlipOptions>, ScenarioError> {
    let d = FlipOptions::default();
    let spec = ElbowSwitchSpec::from_keys(&scenario.reference_robot_keys)
        .map_err(|e| scenario.error(&format!("reference.{}", e.key), e.rule))?;
    // An optimised move is planned on the scenario's own control period and integration.
    let control_dt_s = scenario.control_dt_s;
    let substeps = ((scenario.control_dt_s / scenario.plant_dt_s).round() as usize).max(1);
    Ok(match spec {
        ElbowSwitchSpec::Step => None,
        ElbowSwitchSpec::Planned {
            max_effort_share,
            clearance_z_m,
            ramp_s,
            optimal,
        } => Some(FlipOptions {
            optimal,
            optimal_step_s: control_dt_s,
            optimal_substeps: substeps,
            max_effort_share: max_effort_share.unwrap_or(d.max_effort_share),
            clearance_z_m,
            ramp_s: ramp_s.unwrap_or(d.ramp_s),
            sample_dt_s,
            ..d
        }),
    })
}

/// The SCARA's plan of `trajectory` for `scenario` (see [`ScenarioRobot::plan`]).
///
/// # Errors
///
/// [`ScenarioError`] on `reference` for a reference that leaves the workspace, on
/// `reference.elbow_switch` for a flip that cannot be planned, on `start_on_reference` if
/// the first point has no solution.
pub fn plan(scenario: &Scenario, trajectory: SharedTrajectory) -> Result<ScaraPlan, ScenarioError> {
    let geometry = ScaraGeometry::from_model(&Scara);
    let plan_step = 0.005_f64.min(scenario.control_dt_s);
    let leaves = |e: String| {
        scenario.error(
            "reference",
            format!("the reference leaves the workspace: {e}"),
        )
    };
    let mut run_trajectory: Box<dyn CartesianTrajectory + Send + Sync> =
        Box::new(trajectory.clone());
    let mut flips = Vec::new();
    let plan = match flip_options(scenario, plan_step)? {
        Some(options) => {
            let (planned, plan) = plan_flips(&Scara, &geometry, trajectory.as_ref(), &options)
                .map_err(|e| match e {
                    FlipError::Workspace(m) => leaves(m),
                    e => scenario.error(
                        "reference.elbow_switch",
                        format!("the elbow flip cannot be planned: {e}"),
                    ),
                })?;
            if !planned.is_empty() {
                let pauses = planned.iter().map(|f| f.pause).collect();
                run_trajectory = Box::new(
                    Paused::new(trajectory.clone(), pauses)
                        .map_err(|e| scenario.error("reference.elbow_switch", e))?,
                );
            }
            flips = planned;
            plan
        }
        None => geometry
            .plan_trajectory(trajectory.as_ref(), plan_step, SwitchPolicy::Latest)
            .map_err(|e| leaves(e.to_string()))?,
    };
    let first = run_trajectory.at(0.0);
    let start = match geometry.inverse(&first.position, first.yaw(), plan.initial()) {
        Ok(q) => q,
        Err(e) if scenario.start_on_reference => {
            return Err(scenario.error(
                "start_on_reference",
                format!("the reference's first point has no solution: {e}"),
            ))
        }
        Err(_) => JointVector::<4>::zeros(),
    };
    let moves = flips.iter().flat_map(|f| f.moves.iter().cloned()).collect();
    Ok(ScaraPlan {
        reference: ScaraReference::new(geometry, run_trajectory, plan).with_joint_moves(moves),
        flips,
        start,
    })
}

/// What the deployable step needs of a scenario: the force surface's (plane's) normal and the
/// switching time; an error naming the first key it cannot follow.
fn deployable(scenario: &Scenario) -> Result<(Vector3<f64>, f64), ScenarioError> {
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
    if scenario.position_settings.acceleration_feedforward {
        return refuse(
            "position.acceleration_feedforward",
            "has no acceleration feedforward: set acceleration_feedforward = false",
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
        SurfaceGeometry::Plane(plane) => plane.normal,
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

/// The deployable step in precision `T` for `scenario` with the PI gains `gains`.
fn deployed_in<T: ScaraScalar>(
    scenario: &Scenario,
    gains: Option<(f64, f64, f64)>,
    safety: Option<&SafetyLimits<f64, 4>>,
) -> Result<Box<dyn Controller<4>>, ScenarioError> {
    let (normal, switch_s) = deployable(scenario)?;
    let (kfp, kfi, kvd) = gains.ok_or_else(|| {
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
    Ok(Box::new(match safety {
        Some(limits) => Deployed::supervised(SupervisedHybrid::new(step, limits)),
        None => Deployed::new(step),
    }))
}

impl RobotVocabulary<4> for Scara {
    fn named_references() -> &'static [&'static str] {
        &NAMED_REFERENCES
    }

    fn named_reference(name: &str, surface_z_m: Option<f64>) -> Option<SharedTrajectory> {
        match name {
            "position" if surface_z_m.is_none() => Some(Arc::new(PositionTest::new())),
            "contact" => Some(Arc::new(ContactTest::new(
                surface_z_m.unwrap_or(CONTACT_SURFACE_Z_M),
            ))),
            "three-zone" if surface_z_m.is_none() => Some(Arc::new(ThreeZone::new())),
            _ => None,
        }
    }

    fn reference_keys() -> &'static [&'static str] {
        &REFERENCE_KEYS
    }

    fn check_reference_keys(keys: &toml::Table) -> Result<(), KeyError> {
        ElbowSwitchSpec::from_keys(keys).map(drop)
    }
}

impl ScenarioRobot<4> for Scara {
    fn plan(
        &self,
        scenario: &Scenario,
        trajectory: SharedTrajectory,
    ) -> Result<Box<dyn PlannedReference<4>>, ScenarioError> {
        Ok(Box::new(plan(scenario, trajectory)?))
    }

    fn deployed(
        scenario: &Scenario,
        precision: Precision,
        gains: Option<(f64, f64, f64)>,
        safety: Option<&SafetyLimits<f64, 4>>,
    ) -> Result<Box<dyn Controller<4>>, ScenarioError> {
        match precision {
            Precision::F32 => deployed_in::<f32>(scenario, gains, safety),
            Precision::F64 => deployed_in::<f64>(scenario, gains, safety),
        }
    }
}
