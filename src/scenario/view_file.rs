//! A run's viewer, `view.html`, from what its output folder holds: `armdyn view DIR`, and the
//! page `armdyn run` writes (the same function on the same texts).

use std::path::{Path, PathBuf};

use anyhow::Context;
use serde_json::Value;

use crate::contact::SurfaceGeometry;
use crate::model::RobotModel;
use crate::report::view::{events_from_metrics, scene_from_json, view_html};

/// The page of a run of `robot` (named `robot_name`): its `metrics` (the title, the events),
/// the text of its `trajectory.csv` and its `surfaces`.
///
/// # Errors
///
/// If the trajectory is not one of `robot` (see [`view_html`]).
pub(crate) fn view_page<const N: usize, R: RobotModel<N>>(
    robot: &R,
    robot_name: &str,
    metrics: &Value,
    csv: &str,
    surfaces: &[SurfaceGeometry],
) -> anyhow::Result<String> {
    let title = metrics["trial"].as_str().unwrap_or(robot_name);
    let events = events_from_metrics(metrics);
    Ok(view_html(robot, robot_name, title, csv, surfaces, &events)?)
}

/// Writes `DIR/view.html` for the output folder `dir` of a run (its `metrics.json`,
/// `trajectory.csv` and, if there, `scene.json`), replacing it whole; its path.
///
/// # Errors
///
/// If a file is missing or not what a run writes (named with the line or key), or the page
/// cannot be written (nothing half-written is left).
pub fn write_view(dir: &Path) -> anyhow::Result<PathBuf> {
    let read = |name: &str| {
        let p = dir.join(name);
        std::fs::read_to_string(&p).with_context(|| format!("cannot read {}", p.display()))
    };
    let metrics: Value = serde_json::from_str(&read("metrics.json")?)
        .with_context(|| format!("{}: not JSON", dir.join("metrics.json").display()))?;
    let robot = metrics["robot"]
        .as_str()
        .with_context(|| format!("{}: no `robot`", dir.join("metrics.json").display()))?
        .to_string();
    let csv = read("trajectory.csv")?;
    let scene = dir.join("scene.json");
    let surfaces = if scene.exists() {
        scene_from_json(&read("scene.json")?).with_context(|| format!("{}", scene.display()))?
    } else {
        Vec::new()
    };
    let page = crate::with_robot_named!(robot.as_str(), |model: R, N, _module| {
        view_page(&model, &robot, &metrics, &csv, &surfaces)
    })
    .unwrap_or_else(|| {
        Err(anyhow::anyhow!(
            "{}: unknown robot `{robot}`",
            dir.join("metrics.json").display()
        ))
    })
    .with_context(|| format!("{}", dir.display()))?;
    let out = dir.join("view.html");
    crate::report::write_atomic(&out, &page)
        .with_context(|| format!("cannot write {}", out.display()))?;
    Ok(out)
}
