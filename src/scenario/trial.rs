//! From a checked [`Scenario`] to a run: the reference, the controller line-up with its
//! gains, the environment and the plant, the checks that need them (workspace, reach), and
//! the run with its metrics.

use super::controllers::GainReport;
use super::error::ScenarioError;
use super::plant::ControllerModel;
use super::runner::{run, RunOutput};
use super::spec::{ElbowSwitchSpec, ForceReferenceSpec, ReferenceSpec, Scenario, ThesisReference};
use crate::contact::{ForceSensor, Scene, Sensed, SurfaceGeometry};
use crate::control::selection::SelectionPolicy;
use crate::control::task_frame::TaskFrame;
use crate::control::Controller;
use crate::metrics::{ContactMetrics, ContactSummary, ForceMetrics, ForceSummary};
use crate::metrics::{TrackingMetrics, TrackingSummary};
use crate::model::{Parametric, RobotModel, Scara, Wrench};
type ParametricScara = Parametric<4, Scara>;
use crate::robots::scara::elbow_flip::{plan_flips, ElbowFlip, FlipError};
use crate::robots::scara::reference::{DesiredForce, ForceShape, ScaraReference};
use crate::robots::scara::thesis::{ContactTest, PositionTest, ThreeZone};
use crate::robots::scara::{ElbowPlan, ScaraGeometry, SwitchPolicy};
use crate::sim::{EndStops, SimConfig, SimError};
use crate::trajectory::pause::Paused;
use crate::trajectory::{sample, CartesianTrajectory, ForceProfile};

/// How far the reference must come to a force-controlled surface (its nominal position), m:
/// a reference that never gets this close is refused ("a surface the reference never
/// reaches").
pub const MAX_REACH_GAP_M: f64 = 0.02;

/// Start of the "after the transient" window of the tracking metrics, s (the thesis's).
pub const TRACKING_AFTER_S: f64 = 2.0;

/// A scenario ready to run.
pub struct Prepared {
    /// The controller (with its sensor, if any).
    pub controller: Box<dyn Controller<4>>,
    /// Its gains.
    pub gains: GainReport,
    /// The motion reference.
    pub trajectory: Box<dyn CartesianTrajectory>,
    /// The desired force.
    pub force: Option<DesiredForce>,
    /// The real surfaces.
    pub scene: Scene,
    /// The plant and timing.
    pub config: SimConfig<4>,
    /// The elbow plan (the reference checked against the workspace).
    pub plan: ElbowPlan,
    /// Planned elbow flips (empty for a stepped switch or none).
    pub flips: Vec<ElbowFlip>,
    /// The plant's own rigid-body model (`None`: the description's, [`Scara`]).
    pub plant: Option<ParametricScara>,
}

/// What a run gives.
pub struct Outcome {
    /// Every sample and the run's counts.
    pub run: RunOutput,
    /// The elbow plan.
    pub plan: ElbowPlan,
    /// Samples at which the reference's inverse kinematics was damped.
    pub singular_samples: usize,
    /// Joint tracking metrics.
    pub tracking: TrackingSummary<4>,
    /// The thesis's z-force metrics (force-controlled scenarios).
    pub force: Option<ForceSummary>,
    /// Contact metrics along the real normal (scenarios with surfaces).
    pub contact: Option<ContactSummary>,
    /// The controller's name.
    pub controller_name: &'static str,
    /// Its gains.
    pub gains: GainReport,
    /// The real surfaces.
    pub scene: Scene,
    /// Force control mode: `"time"`, `"contact"` or `None`.
    pub selection: Option<&'static str>,
    /// Planned elbow flips and what the run did during them.
    pub flips: Vec<(ElbowFlip, FlipSummary)>,
    /// Samples with any joint outside its limits.
    pub joint_limit_violation_samples: usize,
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

/// Surface `geometry` shifted by `shift` m along its outward normal (the controller's belief
/// of a surface; a sweep's offset of the real one).
pub fn shifted(geometry: &SurfaceGeometry, shift: f64) -> SurfaceGeometry {
    match *geometry {
        SurfaceGeometry::Plane {
            point,
            normal,
            axes,
            half_extent,
        } => SurfaceGeometry::Plane {
            point: point + normal * shift,
            normal,
            axes,
            half_extent,
        },
        SurfaceGeometry::Sphere { centre, radius } => SurfaceGeometry::Sphere {
            centre,
            radius: radius + shift,
        },
        SurfaceGeometry::Cylinder {
            point,
            axis,
            radius,
        } => SurfaceGeometry::Cylinder {
            point,
            axis,
            radius: radius + shift,
        },
    }
}

pub(super) fn trajectory(scenario: &Scenario) -> Box<dyn CartesianTrajectory> {
    match &scenario.reference {
        ReferenceSpec::Thesis(ThesisReference::Position) => Box::new(PositionTest::new()),
        ReferenceSpec::Thesis(ThesisReference::Contact { surface_z_m }) => {
            Box::new(ContactTest::new(*surface_z_m))
        }
        ReferenceSpec::Thesis(ThesisReference::ThreeZone) => Box::new(ThreeZone::new()),
        ReferenceSpec::Waypoints(w) => Box::new(w.clone()),
        ReferenceSpec::Csv(_, t) => Box::new(t.clone()),
    }
}

/// Length of a scenario's run, s, known without planning the reference: its `duration_s`,
/// or else its reference's. Without `duration_s`, a planned elbow flip lengthens the run by
/// its pauses; [`prepare`]'s `config.duration` is the exact length.
#[must_use]
pub fn run_duration(scenario: &Scenario) -> f64 {
    scenario
        .duration_s
        .unwrap_or_else(|| trajectory(scenario).duration())
}

/// Builds everything a run needs and checks what needs it: the reference against the
/// workspace, the force-controlled surface against the reference.
///
/// # Errors
///
/// [`ScenarioError`] naming the key at fault.
pub fn prepare(scenario: &Scenario) -> Result<Prepared, ScenarioError> {
    let mut p = match &scenario.controller_model {
        ControllerModel::Nominal => prepare_with(scenario, Scara)?,
        ControllerModel::Identified { model, .. } => {
            let mut p = prepare_with(scenario, **model)?;
            p.gains.note = format!(
                "{}; controller model: {}",
                p.gains.note,
                scenario.controller_model.describe()
            );
            p
        }
    };
    p.plant = scenario.plant.model();
    p.config.friction = scenario.plant.friction();
    Ok(p)
}

/// [`prepare`] with the controller designed on `model`.
fn prepare_with<R: RobotModel<4> + Copy + 'static>(
    scenario: &Scenario,
    model: R,
) -> Result<Prepared, ScenarioError> {
    let geometry = ScaraGeometry::from_model(&Scara);
    let plan_step = 0.005_f64.min(scenario.control_dt_s);
    let leaves = |e: String| {
        scenario.error(
            "reference",
            format!("the reference leaves the workspace: {e}"),
        )
    };
    let mut trajectory = trajectory(scenario);
    let mut flips = Vec::new();
    let plan = match scenario.elbow_switch {
        ElbowSwitchSpec::Planned(mut options) => {
            options.sample_dt_s = plan_step;
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
                trajectory = Box::new(
                    Paused::new(trajectory, pauses)
                        .map_err(|e| scenario.error("reference.elbow_switch", e))?,
                );
            }
            flips = planned;
            plan
        }
        ElbowSwitchSpec::Step => geometry
            .plan_trajectory(trajectory.as_ref(), plan_step, SwitchPolicy::Latest)
            .map_err(|e| leaves(e.to_string()))?,
    };
    let duration = scenario.duration_s.unwrap_or_else(|| trajectory.duration());
    let q0 = if scenario.start_on_reference {
        let start = trajectory.at(0.0);
        geometry
            .inverse(&start.position, start.yaw(), plan.initial())
            .map_err(|e| {
                scenario.error(
                    "start_on_reference",
                    format!("the reference's first point has no solution: {e}"),
                )
            })?
    } else {
        nalgebra::Vector4::from(scenario.q0)
    };
    let scene = Scene::new(&scenario.surfaces).map_err(|n| {
        scenario.error(
            "surfaces",
            format!("{n} surfaces; at most {}", crate::contact::MAX_SURFACES),
        )
    })?;
    let mut config = SimConfig::thesis(&Scara);
    config.duration = duration;
    config.control_dt = scenario.control_dt_s;
    config.plant_dt = scenario.plant_dt_s;
    config.q0 = q0;
    config.end_stops = scenario.end_stops.then(|| EndStops::from_model(&Scara));
    let (position, mut gains) = scenario
        .position
        .build_with(model)
        .map_err(|e| scenario.error("position.law", e))?;
    let (mut controller, force): (Box<dyn Controller<4>>, _) =
        match (&scenario.force, &scenario.selection) {
            (Some(f), Some(selection)) => {
                let key = format!("surfaces[{}]", f.surface);
                let nominal = shifted(&scenario.surfaces[f.surface].geometry, f.expected_shift_m);
                let frame = TaskFrame::Surface(nominal);
                check_reach(scenario, trajectory.as_ref(), duration, &frame, &key)?;
                let start_s =
                    match selection {
                        SelectionPolicy::Time { switch_s } => {
                            if *switch_s >= duration {
                                return Err(scenario.error(
                            "selection.switch_s",
                            format!("{switch_s} s is not before the end of the run ({duration} s)"),
                        ));
                            }
                            *switch_s
                        }
                        SelectionPolicy::Contact(_) => 0.0,
                    };
                let profile = match &f.reference {
                    ForceReferenceSpec::Constant => {
                        ForceShape::Profile(ForceProfile::constant(-f.value_n, start_s))
                    }
                    ForceReferenceSpec::ThesisVariable => {
                        ForceShape::Profile(ForceProfile::Variable {
                            magnitude: -f.value_n,
                            amplitude: -f.value_n,
                            omega: 10.0 / crate::robots::scara::thesis::THESIS_DURATION,
                            switch_time: start_s,
                        })
                    }
                    ForceReferenceSpec::Csv(samples) => ForceShape::Sampled {
                        samples: samples.clone(),
                        start_s,
                    },
                };
                let controller = super::force_design::build(
                    scenario, f, model, position, frame, *selection, &mut gains,
                )?;
                (controller, Some(DesiredForce { profile, frame }))
            }
            _ => (position, None),
        };
    if let Some(sensor) = force_sensor(scenario)? {
        let s = scenario.sensor;
        gains.note = format!(
            "{}; force sensor: noise {} N (1 sigma per axis), bias {} N on fz, low-pass {}, seed {}",
            gains.note,
            s.noise_n,
            s.bias_n,
            s.cutoff_hz.map_or("none".to_string(), |c| format!("{c} Hz")),
            s.seed
        );
        controller = Box::new(Sensed::new(controller, sensor));
    }
    Ok(Prepared {
        controller,
        gains,
        trajectory,
        force,
        scene,
        config,
        plan,
        flips,
        plant: None,
    })
}

/// The scenario's force sensor (`None` for an ideal one).
pub(super) fn force_sensor(scenario: &Scenario) -> Result<Option<ForceSensor>, ScenarioError> {
    if scenario.sensor.is_ideal() {
        return Ok(None);
    }
    let s = scenario.sensor;
    let noise = Wrench::new(s.noise_n, s.noise_n, s.noise_n, 0.0, 0.0, 0.0);
    let bias = Wrench::new(0.0, 0.0, s.bias_n, 0.0, 0.0, 0.0);
    ForceSensor::new(bias, noise, s.cutoff_hz, s.seed)
        .map(Some)
        .map_err(|e| scenario.error("sensor", e.to_string()))
}

/// Refuses a force-controlled surface that the reference never comes near.
fn check_reach(
    scenario: &Scenario,
    trajectory: &dyn CartesianTrajectory,
    duration: f64,
    frame: &TaskFrame,
    key: &str,
) -> Result<(), ScenarioError> {
    let mut closest: Option<(f64, f64)> = None;
    for s in sample(trajectory, 0.005)
        .into_iter()
        .filter(|s| s.t <= duration)
    {
        if let Some(gap) = frame.signed_distance(&s.position) {
            if closest.is_none_or(|(g, _)| gap < g) {
                closest = Some((gap, s.t));
            }
        }
    }
    match closest {
        Some((gap, _)) if gap <= MAX_REACH_GAP_M => Ok(()),
        Some((gap, t)) => Err(scenario.error(key, format!(
            "the reference never reaches this surface: it comes no closer than {:.1} mm (at t = {t:.3} s); it must come within {:.0} mm",
            gap * 1e3,
            MAX_REACH_GAP_M * 1e3
        ))),
        None => Err(scenario.error(key, "the reference never passes over this surface's extent")),
    }
}

/// Runs a prepared scenario; `progress` gets the simulated time about every 0.5 s.
///
/// # Errors
///
/// [`SimError`] if the simulation breaks down.
#[allow(clippy::result_large_err)]
pub fn execute(
    scenario: &Scenario,
    mut p: Prepared,
    progress: impl FnMut(f64),
) -> Result<Outcome, SimError> {
    let geometry = ScaraGeometry::from_model(&Scara);
    let mut reference = ScaraReference::new(
        geometry,
        p.trajectory.as_ref(),
        p.plan.clone(),
        p.force.clone(),
    )
    .with_joint_moves(
        p.flips
            .iter()
            .flat_map(|f| f.moves.iter().copied())
            .collect(),
    );
    let out = match &p.plant {
        None => run(
            &Scara,
            p.controller.as_mut(),
            &mut reference,
            &p.scene,
            &p.config,
            progress,
        )?,
        Some(plant) => run(
            plant,
            p.controller.as_mut(),
            &mut reference,
            &p.scene,
            &p.config,
            progress,
        )?,
    };
    let mut tracking = TrackingMetrics::new(TRACKING_AFTER_S);
    out.samples.iter().for_each(|s| tracking.push(s));
    let duration = p.config.duration;
    let switch_s = out.samples.iter().find(|s| s.force_controlled).map(|s| s.t);
    let force = scenario.force.as_ref().map(|f| {
        let mut m = ForceMetrics::new(switch_s.unwrap_or(duration), duration, 5.0, f.value_n, 0.05);
        out.samples.iter().for_each(|s| m.push(s));
        m.summary()
    });
    let contact = (!scenario.surfaces.is_empty()).then(|| {
        let value = scenario.force.as_ref().map_or(1.0, |f| f.value_n);
        let ramp_s = match scenario.selection {
            Some(SelectionPolicy::Contact(c)) => c.ramp_s,
            _ => 0.0,
        };
        let mut m = ContactMetrics::new(switch_s, value, duration).with_ramp(ramp_s);
        out.samples.iter().for_each(|s| m.push(s, &p.scene));
        m.summary()
    });
    let limits = (Scara.lower_limits(), Scara.upper_limits());
    let joint_limit_violation_samples = out
        .samples
        .iter()
        .filter(|s| (0..4).any(|i| !(limits.0[i] <= s.q[i] && s.q[i] <= limits.1[i])))
        .count();
    let effort = p.config.effort_limits;
    let flips = p
        .flips
        .iter()
        .map(|f| {
            let (a, b) = f.interval();
            let during = || out.samples.iter().filter(move |s| a <= s.t && s.t <= b);
            let (sa, sb) = f.swing().map_or((a, b), |m| (m.start_s, m.end_s()));
            let swinging = || out.samples.iter().filter(move |s| sa <= s.t && s.t <= sb);
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
        .collect();
    Ok(Outcome {
        flips,
        joint_limit_violation_samples,
        controller_name: p.controller.name(),
        singular_samples: reference.singular_samples(),
        plan: p.plan,
        tracking: tracking.summary(),
        force,
        contact,
        gains: p.gains,
        scene: p.scene,
        selection: scenario.selection.map(|s| match s {
            SelectionPolicy::Time { .. } => "time",
            SelectionPolicy::Contact(_) => "contact",
        }),
        run: out,
    })
}
