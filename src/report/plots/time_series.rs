//! Figures of the joints and of the end effector over time: tracking, errors, force.

use super::chart::{
    figure, grid, panels, run_range, series, size_for, time_panel, time_range, trim_zeros, Curve,
    Style,
};
use super::{PlotError, ACTUAL, ERROR, FIGURE_SIZE};
use crate::model::JointKind;
use crate::sim::Sample;

fn kind_name(kind: JointKind) -> &'static str {
    match kind {
        JointKind::Revolute => "revolute",
        JointKind::Prismatic => "prismatic",
    }
}

/// Joint positions against their references over time, one panel per joint (thesis
/// Figures 4.4 and 4.5). Axis titles carry the joint's unit (rad or m).
///
/// # Errors
///
/// [`PlotError::Empty`] without samples; [`PlotError::Draw`] if drawing fails.
///
/// # Example
///
/// ```
/// use armdyn::model::{RobotModel, Scara};
/// use armdyn::report::plots::joint_tracking;
/// # let samples: Vec<armdyn::sim::Sample<4>> = vec![];
/// // `samples` as recorded by `armdyn::sim::simulate`'s observer.
/// match joint_tracking(&samples, &Scara::JOINT_NAMES, &Scara::JOINT_KINDS) {
///     Ok(svg) => assert!(svg.starts_with("<svg")),
///     Err(e) => assert_eq!(e.to_string(), "no samples to plot"),
/// }
/// ```
pub fn joint_tracking<const N: usize>(
    samples: &[Sample<N>],
    names: &[&str; N],
    kinds: &[JointKind; N],
) -> Result<String, PlotError> {
    let t_range = run_range(samples)?;
    figure(size_for(grid(N).0), "Joint tracking", |area| {
        panels(area, N, |cell, i| {
            let unit = kinds[i].position_unit();
            let curves = [
                Curve::new("actual", Style::Solid(ACTUAL), series(samples, |s| s.q[i])),
                Curve::new(
                    "reference",
                    Style::Reference,
                    series(samples, |s| s.setpoint.joint.q[i]),
                ),
            ];
            time_panel(
                cell,
                &format!("Joint {} ({}, {})", i + 1, names[i], kind_name(kinds[i])),
                &format!("{} ({unit})", names[i]),
                t_range,
                &curves,
            )
        })
    })
}

/// Joint tracking errors `q_ref - q` over time, one panel per joint (thesis Figures 4.6
/// and 4.9), optionally only over `window = Some((t_start, t_end))` seconds (the thesis
/// shows the first 2 s).
///
/// # Errors
///
/// [`PlotError::Empty`] without samples; [`PlotError::Window`] if the window is not
/// `t_start < t_end` or holds no sample; [`PlotError::Draw`] if drawing fails.
pub fn joint_errors<const N: usize>(
    samples: &[Sample<N>],
    names: &[&str; N],
    kinds: &[JointKind; N],
    window: Option<(f64, f64)>,
) -> Result<String, PlotError> {
    let full = run_range(samples)?;
    let (shown, t_range) = match window {
        None => (samples, full),
        Some((a, b)) => {
            if a.is_nan() || b.is_nan() || a >= b {
                return Err(PlotError::Window(a, b));
            }
            let first = samples.partition_point(|s| s.t < a);
            let end = samples.partition_point(|s| s.t <= b);
            if first >= end {
                return Err(PlotError::Window(a, b));
            }
            let shown = &samples[first..end];
            (
                shown,
                (a.max(full.0), b.min(shown[shown.len() - 1].t.max(a))),
            )
        }
    };
    let t_range = time_range(t_range.0, t_range.1);
    let title = match window {
        None => "Joint tracking errors (reference - actual)".to_owned(),
        Some(_) => format!(
            "Joint tracking errors (reference - actual), {} to {} s",
            trim_zeros(&format!("{:.3}", t_range.0)),
            trim_zeros(&format!("{:.3}", t_range.1))
        ),
    };
    figure(size_for(grid(N).0), &title, |area| {
        panels(area, N, |cell, i| {
            let unit = kinds[i].position_unit();
            let name = names[i];
            let curves = [
                Curve::new("", Style::Zero, vec![(t_range.0, 0.0), (t_range.1, 0.0)]),
                Curve::new(
                    format!("{name}_ref - {name}"),
                    Style::Solid(ERROR),
                    series(shown, |s| s.setpoint.joint.q[i] - s.q[i]),
                ),
            ];
            time_panel(
                cell,
                &format!("Joint {} ({name}, {})", i + 1, kind_name(kinds[i])),
                &format!("error ({unit})"),
                t_range,
                &curves,
            )
        })
    })
}

/// End-effector x, y, z (m) and yaw (rad) against their references over time.
///
/// # Errors
///
/// [`PlotError::Empty`] without samples; [`PlotError::Draw`] if drawing fails.
pub fn cartesian_tracking<const N: usize>(samples: &[Sample<N>]) -> Result<String, PlotError> {
    let t_range = run_range(samples)?;
    type Get<const N: usize> = fn(&Sample<N>) -> f64;
    let axes: [(&str, &str, Get<N>, Get<N>); 4] = [
        (
            "x",
            "x (m)",
            |s| s.position.x,
            |s| s.setpoint.cartesian.position.x,
        ),
        (
            "y",
            "y (m)",
            |s| s.position.y,
            |s| s.setpoint.cartesian.position.y,
        ),
        (
            "z",
            "z (m)",
            |s| s.position.z,
            |s| s.setpoint.cartesian.position.z,
        ),
        (
            "yaw",
            "yaw (rad)",
            |s| s.yaw(),
            |s| s.setpoint.cartesian.yaw(),
        ),
    ];
    figure(size_for(grid(4).0), "Cartesian tracking", |area| {
        panels(area, axes.len(), |cell, i| {
            let (name, desc, actual, reference) = axes[i];
            let curves = [
                Curve::new("actual", Style::Solid(ACTUAL), series(samples, actual)),
                Curve::new("reference", Style::Reference, series(samples, reference)),
            ];
            time_panel(
                cell,
                &format!("End effector {name}"),
                desc,
                t_range,
                &curves,
            )
        })
    })
}

/// The contact force `fz` the tool exerts on the environment (N; negative pushes down)
/// and its reference over time (thesis Figures 5.8, 5.10, 5.11).
///
/// # Errors
///
/// [`PlotError::Empty`] without samples; [`PlotError::Draw`] if drawing fails.
pub fn force_tracking<const N: usize>(samples: &[Sample<N>]) -> Result<String, PlotError> {
    let t_range = run_range(samples)?;
    figure(FIGURE_SIZE, "Contact force tracking", |area| {
        let curves = [
            Curve::new(
                "fz measured",
                Style::Solid(ACTUAL),
                series(samples, |s| s.wrench[2]),
            ),
            Curve::new(
                "fz reference",
                Style::Reference,
                series(samples, |s| s.setpoint.wrench[2]),
            ),
        ];
        time_panel(
            area,
            "z component of the force of the tool on the surface (negative: pushing down)",
            "fz (N)",
            t_range,
            &curves,
        )
    })
}
