//! What a scenario run writes: `trajectory.csv`, `metrics.json` and SVG figures, into one
//! folder, all or nothing.

use std::path::Path;

use serde_json::{json, Map, Value};

use super::outcome::{Outcome, Recorded};
use super::robot::ScenarioRobot;
use super::spec::Scenario;
use crate::contact::{Plane, SurfaceGeometry};
use crate::model::JointKind;
use crate::report::{self, OutputDir, SurfacePatch};

fn gains_json(g: &super::GainReport) -> Value {
    let mut gains = Map::new();
    let mut put = |k: &str, v: Value| {
        gains.insert(k.into(), v);
    };
    if let Some(v) = &g.kp {
        put("kp", json!(v));
    }
    if let Some(v) = &g.ki {
        put("ki", json!(v));
    }
    if let Some(v) = &g.kd {
        put("kd", json!(v));
    }
    if let Some(v) = &g.k1 {
        put("k1", json!(v));
    }
    if let Some(v) = &g.k2 {
        put("k2", json!(v));
    }
    if !g.poles.is_empty() {
        put("poles", json!(g.poles));
    }
    if let Some(v) = g.riccati_residual {
        put("riccati_residual", json!(v));
    }
    if let Some((kfp, kfi, kvd)) = g.force {
        put("kfp", json!(kfp));
        put("kfi", json!(kfi));
        put("kvd", json!(kvd));
    }
    put("note", json!(g.note));
    Value::Object(gains)
}

/// `"joint errors in rad (q1, q2, q4) and m (d3); torques in N m (q1, q2, q4) and N (d3)"`
/// for the robot's joints: the units of the per-joint metrics.
#[must_use]
pub fn units(names: &[&str], kinds: &[JointKind]) -> String {
    let of = |kind: JointKind| {
        names
            .iter()
            .zip(kinds)
            .filter(|(_, k)| **k == kind)
            .map(|(n, _)| *n)
            .collect::<Vec<_>>()
            .join(", ")
    };
    let (revolute, prismatic) = (of(JointKind::Revolute), of(JointKind::Prismatic));
    match (revolute.is_empty(), prismatic.is_empty()) {
        (false, false) => format!(
            "joint errors in rad ({revolute}) and m ({prismatic}); torques in N m ({revolute}) and N ({prismatic})"
        ),
        (false, true) => format!("joint errors in rad ({revolute}); torques in N m ({revolute})"),
        (true, _) => format!("joint errors in m ({prismatic}); forces in N ({prismatic})"),
    }
}

/// The metrics of a run as one JSON object: the thesis trials' keys (unchanged), the pose
/// tracking keys, the reference's own keys (a SCARA's elbow plan), then the contact keys of
/// scenarios with surfaces.
#[must_use]
pub fn metrics_json(scenario: &Scenario, r: &Outcome) -> Value {
    let t = &r.tracking;
    let stats = &r.stats;
    let mut m = json!({
        "trial": scenario.name,
        "scenario": scenario.file,
        "robot": r.robot,
        "controller": r.controller_name,
        "gains": gains_json(&r.gains),
        "units": units(&r.joint_names, &r.joint_kinds),
        "rms_joint_error": t.rms_joint_error,
        "rms_joint_error_after_2s": t.rms_joint_error_after,
        "max_joint_error_after_2s": t.max_joint_error_after,
        "max_abs_tau": t.max_abs_tau,
        "saturated_samples": stats.saturated_samples,
        "first_joint_limit_violation_s": stats.first_limit_violation,
        "singular_reference_samples": r.reference.singular_samples,
        "samples": stats.samples,
        "task": r.task.names(),
        "metrics_after_s": r.pose.after_s,
        "rms_joint_error_after": r.tracking_after.rms_joint_error_after,
        "max_joint_error_after": r.tracking_after.max_joint_error_after,
        "max_abs_joint_error_after": r
            .tracking_after
            .max_joint_error_after
            .iter()
            .fold(0.0f64, |m, x| m.max(x.abs())),
        "position_rms_error_mm": r.pose.position_rms_m * 1e3,
        "position_max_error_mm": r.pose.position_max_m * 1e3,
        "orientation_rms_error_deg": r.pose.orientation_rms_rad.to_degrees(),
        "orientation_max_error_deg": r.pose.orientation_max_rad.to_degrees(),
    });
    let Some(obj) = m.as_object_mut() else {
        return m;
    };
    for (k, v) in &r.reference.metrics {
        obj.insert(k.clone(), v.clone());
    }
    if let Some(f) = &r.force {
        append(
            obj,
            json!({
                "force_overshoot_pct": f.force_overshoot_pct,
                "settling_time_s": f.settling_time_s,
                "force_rms_error_last5s_n": f.force_rms_error_last_n,
                "xy_rms_error_contact_mm": f.xy_rms_error_contact_mm,
                "min_z_m": f.min_z_m,
            }),
        );
    }
    append(
        obj,
        json!({
            "saturated_samples_total": stats.saturated_samples.iter().sum::<usize>(),
            "end_stops": scenario.end_stops,
            "joint_limit_violation_samples": r.joint_limit_violation_samples,
            "end_stop_samples": stats.end_stop_samples,
        }),
    );
    if scenario.controller_model != super::ControllerModel::Nominal {
        obj.insert(
            "controller_model".into(),
            json!(scenario.controller_model.describe()),
        );
    }
    if !scenario.plant.is_nominal() {
        let p = &scenario.plant;
        obj.insert(
            "plant".into(),
            json!({
                "mass_scale": p.mass_scale,
                "com_offset_m": p.com_offset_m,
                "inertia_scale": p.inertia_scale,
                "payload_kg": p.payload_kg,
                "payload_offset_m": p.payload_offset_m,
                "friction_viscous": p.friction_viscous,
                "friction_coulomb": p.friction_coulomb,
                "friction_smoothing": p.friction_smoothing,
            }),
        );
    }
    if let Some(c) = &r.contact {
        let detected = c.force_start_s.filter(|_| r.selection == Some("contact"));
        append(
            obj,
            json!({
                "selection": r.selection,
                "normal_force_overshoot_pct": c.normal_force_overshoot_pct,
                "normal_force_settling_time_s": c.normal_force_settling_time_s,
                "normal_force_rms_error_last5s_n": c.normal_force_rms_error_last5s_n,
                "normal_force_tracking_settling_s": c.normal_force_tracking_settling_s,
                "normal_force_steady_error_n": c.normal_force_steady_error_n,
                "path_rms_error_contact_mm": c.path_rms_error_contact_mm,
                "first_touch_s": c.first_touch_s,
                "contact_detected_s": detected,
                "force_control_start_s": c.force_start_s,
                "peak_normal_force_n": c.peak_normal_force_n,
                "contact_losses_after_first_touch": c.contact_losses,
                "max_tangential_force_n": c.max_tangential_force_n,
                "normal_force_rms_error_last3s_n": c.normal_force_rms_error_last3s_n,
            }),
        );
    }
    if let Some(a) = &r.alignment {
        append(
            obj,
            json!({"tool_normal_angle_error_deg": a.rms_deg, "tool_normal_angle_max_error_deg": a.max_deg}),
        );
    }
    if let Some(p) = &r.posture {
        append(
            obj,
            json!({"posture_error_rad": p.rms_rad, "posture_max_error_rad": p.max_rad}),
        );
    }
    if let Some(b) = &r.sensor_bias {
        append(
            obj,
            json!({
                "sensor_bias_estimate_n": b.estimate_n,
                "sensor_bias_true_n": b.true_n,
                "sensor_bias_error_n": b.error_n,
            }),
        );
    }
    if let Some(step) = r.switch_torque_step {
        obj.insert("switch_torque_step_nm".into(), json!(step));
    }
    if let Some(step) = r.settled_torque_step {
        obj.insert("settled_torque_step_max_nm".into(), json!(step));
    }
    super::safety_outcome::insert_json(obj, &r.safety);
    m
}

/// Appends the keys of the JSON object `keys` to `obj`, in their order.
fn append(obj: &mut serde_json::Map<String, Value>, keys: Value) {
    if let Value::Object(keys) = keys {
        obj.extend(keys);
    }
}

/// The thesis's plane as the path figure draws it (a horizontal patch), if `scenario` has
/// exactly that kind of surface.
fn horizontal_patch(r: &Outcome) -> Option<SurfacePatch> {
    let s = r.scene.surfaces().next()?;
    match s.geometry {
        SurfaceGeometry::Plane(Plane {
            point,
            normal,
            half_extent,
            ..
        }) if normal == nalgebra::Vector3::z() => Some(SurfacePatch {
            z: point.z,
            x_range: [point.x - half_extent[0], point.x + half_extent[0]],
            y_range: [point.y - half_extent[1], point.y + half_extent[1]],
        }),
        _ => None,
    }
}

/// Writes every output file of a run `recorded` of `scenario` on `robot` into `dir`, all or
/// nothing, with the viewer `view.html` or without it (`view` false). A scenario of any robot
/// of the registry reaches its type through [`with_robot_named!`](crate::with_robot_named);
/// a user's own arm is given (see [`Scenario::load_for`]).
///
/// # Errors
///
/// If the run is not of `robot`, a figure cannot be drawn or a file cannot be written
/// (nothing is left behind).
pub fn write_outputs_for<const N: usize, R: ScenarioRobot<N>>(
    dir: &Path,
    scenario: &Scenario,
    recorded: &Recorded<N>,
    view: bool,
    robot: &R,
) -> anyhow::Result<()> {
    use anyhow::Context;
    let (r, samples) = (&recorded.outcome, recorded.samples.as_slice());
    if r.robot != R::NAME {
        anyhow::bail!("the run is of robot `{}`, not `{}`", r.robot, R::NAME);
    }
    let mut out =
        OutputDir::create(dir).with_context(|| format!("cannot create {}", dir.display()))?;
    let csv = report::trajectory_csv(samples, &R::JOINT_NAMES, &R::JOINT_KINDS);
    let metrics = metrics_json(scenario, r);
    let surfaces: Vec<SurfaceGeometry> = r.scene.surfaces().map(|s| s.geometry).collect();
    out.write(
        "scene.json",
        serde_json::to_string_pretty(&report::view::scene_json(&surfaces))? + "\n",
    )?;
    if view {
        let page = super::view_file::view_page(robot, &scenario.robot, &metrics, &csv, &surfaces)?;
        out.write("view.html", page)?;
    }
    out.write("trajectory.csv", csv)?;
    out.write(
        "metrics.json",
        serde_json::to_string_pretty(&metrics)? + "\n",
    )?;
    let has_surface = r.scene.surfaces().next().is_some();
    if has_surface && horizontal_patch(r).is_none() {
        out.write("path.svg", report::surface_path_views(samples, &r.scene)?)?;
    } else {
        out.write(
            "path.svg",
            report::path_views(samples, horizontal_patch(r).as_ref())?,
        )?;
    }
    out.write(
        "joints.svg",
        report::joint_tracking(samples, &R::JOINT_NAMES, &R::JOINT_KINDS)?,
    )?;
    out.write(
        "joint_errors.svg",
        report::joint_errors(samples, &R::JOINT_NAMES, &R::JOINT_KINDS, None)?,
    )?;
    out.write(
        "joint_errors_first_2s.svg",
        report::joint_errors(samples, &R::JOINT_NAMES, &R::JOINT_KINDS, Some((0.0, 2.0)))?,
    )?;
    out.write("cartesian.svg", report::cartesian_tracking(samples)?)?;
    if has_surface {
        out.write("force.svg", report::force_tracking(samples)?)?;
        out.write(
            "normal_force.svg",
            report::normal_force_tracking(
                samples,
                &r.scene,
                r.contact.and_then(|c| c.force_start_s),
                &report::contact_plots::Events {
                    faults: r
                        .safety
                        .faults
                        .iter()
                        .map(|(k, t)| ((*k).to_string(), *t))
                        .collect(),
                    trips: r
                        .safety
                        .trips
                        .iter()
                        .map(|t| (format!("{}, {}", t.cause, t.reaction), t.t_s))
                        .collect(),
                },
            )?,
        )?;
    }
    out.commit()
        .with_context(|| format!("cannot write into {}", dir.display()))?;
    if !view {
        // A viewer of an earlier run would not show this one.
        let stale = dir.join("view.html");
        match std::fs::remove_file(&stale) {
            Err(e) if e.kind() != std::io::ErrorKind::NotFound => {
                return Err(e).with_context(|| format!("cannot remove {}", stale.display()));
            }
            _ => {}
        }
    }
    Ok(())
}

/// The names of the files [`write_outputs_for`] writes for `r`, with the viewer or not.
#[must_use]
pub fn output_names(r: &Outcome, view: bool) -> String {
    let mut names = vec!["trajectory.csv", "metrics.json", "scene.json"];
    if view {
        names.push("view.html");
    }
    names.extend([
        "path.svg",
        "joints.svg",
        "joint_errors*.svg",
        "cartesian.svg",
    ]);
    if r.scene.surfaces().next().is_some() {
        names.extend(["force.svg", "normal_force.svg"]);
    }
    names.join(", ")
}
