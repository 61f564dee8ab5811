//! Figures of contact tasks on any surface: the normal force against its reference with the
//! switch instant marked, and the path over the surface in top and side views.

use nalgebra::Vector3;
use plotters::style::RGBColor;

use super::decimate::decimate_stride;
use super::plots::{
    extent, figure, padded, run_range, time_panel, two_path_views, Curve, PathPanel, PlotError,
    Style, ACTUAL, FIGURE_SIZE, MAX_POINTS,
};
use crate::contact::{Scene, SurfaceGeometry};
use crate::metrics::contact::normal_components;
use crate::sim::Sample;

const SWITCH: RGBColor = RGBColor(44, 160, 44);
const FAULT: RGBColor = RGBColor(255, 127, 14);
const TRIP: RGBColor = RGBColor(214, 39, 40);

/// What a figure marks besides the switch: the injected faults and the supervisor's trips.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Events {
    /// `(kind, start)` of each fault, s.
    pub faults: Vec<(String, f64)>,
    /// `(cause and reaction, time)` of each trip, s.
    pub trips: Vec<(String, f64)>,
}

/// Coordinates of a point in one view.
type View = fn(&Vector3<f64>) -> (f64, f64);
/// A view's actual path (with times) and reference.
type ViewPaths = (Vec<(f64, f64, f64)>, Vec<(f64, f64)>);

/// The normal force the tool presses with (N, along the real surface's normal at the
/// contact point) and its reference over time, the switch to force control, the faults and
/// the safety trips marked.
///
/// # Errors
///
/// [`PlotError::Empty`] without samples; [`PlotError::Draw`] if drawing fails.
pub fn normal_force_tracking<const N: usize>(
    samples: &[Sample<N>],
    scene: &Scene,
    switch_s: Option<f64>,
    events: &Events,
) -> Result<String, PlotError> {
    let t_range = run_range(samples)?;
    let push: Vec<(f64, f64, f64)> = samples
        .iter()
        .map(|s| {
            let (p, r, _, _) = normal_components(s, scene);
            (s.t, p, r)
        })
        .collect();
    figure(FIGURE_SIZE, "Normal contact force", |area| {
        let mut curves = vec![
            Curve::new(
                "normal force",
                Style::Solid(ACTUAL),
                push.iter().map(|p| (p.0, p.1)).collect(),
            ),
            Curve::new(
                "reference",
                Style::Reference,
                push.iter().map(|p| (p.0, p.2)).collect(),
            ),
        ];
        if let Some(t) = switch_s {
            curves.push(Curve::new(
                format!("force control from {t:.3} s"),
                Style::Marker(SWITCH),
                vec![(t, 0.0)],
            ));
        }
        for (kind, t) in &events.faults {
            curves.push(Curve::new(
                format!("fault: {kind} at {t:.3} s"),
                Style::Marker(FAULT),
                vec![(*t, 0.0)],
            ));
        }
        for (what, t) in &events.trips {
            curves.push(Curve::new(
                format!("trip: {what} at {t:.3} s"),
                Style::Marker(TRIP),
                vec![(*t, 0.0)],
            ));
        }
        time_panel(
            area,
            "force the tool presses on the surface with, along its normal",
            "force (N)",
            t_range,
            &curves,
        )
    })
}

/// Segments of a circle in a figure.
const SEGMENTS: usize = 720;

/// A surface in a view that keeps coordinates `(a, b)` of a point: its
/// [`drawing`](crate::surface::Shape::drawing) near `path` without its grid, each fill as
/// its closed outline, each line cut to the box `lo..hi` (in 3-D) around the path: the runs of it inside, each
/// segment first cut into pieces of at most a 400th of the box's diagonal.
fn outline(
    g: &SurfaceGeometry,
    path: &[Vector3<f64>],
    lo: Vector3<f64>,
    hi: Vector3<f64>,
    view: View,
) -> Vec<Vec<(f64, f64)>> {
    let inside = |p: &Vector3<f64>| (0..3).all(|i| lo[i] <= p[i] && p[i] <= hi[i]);
    let step = (hi - lo).norm() / 400.0;
    let drawing = g.drawing(path, SEGMENTS);
    let mut out: Vec<Vec<(f64, f64)>> = drawing
        .fills
        .iter()
        .map(|f| f.iter().chain(f.first()).map(view).collect())
        .collect();
    for line in &drawing.lines {
        let mut run = Vec::new();
        let pieces = line.windows(2).flat_map(|ab| {
            let n = ((ab[1] - ab[0]).norm() / step).ceil().max(1.0) as usize;
            (0..n).map(move |k| ab[0] + (ab[1] - ab[0]) * (k as f64 / n as f64))
        });
        for p in pieces.chain(line.last().copied()) {
            if inside(&p) {
                run.push(view(&p));
            } else if !run.is_empty() {
                out.push(std::mem::take(&mut run));
            }
        }
        out.push(run);
    }
    out.retain(|l| l.len() >= 2);
    out
}

/// Top (x-y) and side (x-z, or y-z when the path runs more along y) views of the path with
/// every surface of `scene` drawn as its shape draws itself, where it is near the path.
///
/// # Errors
///
/// [`PlotError::Empty`] without samples; [`PlotError::Draw`] if drawing fails.
pub fn surface_path_views<const N: usize>(
    samples: &[Sample<N>],
    scene: &Scene,
) -> Result<String, PlotError> {
    let t_range = run_range(samples)?;
    let thin = decimate_stride(samples, MAX_POINTS);
    let pts = |f: View| -> ViewPaths {
        (
            thin.iter()
                .map(|s| {
                    let (a, b) = f(&s.position);
                    (a, b, s.t)
                })
                .collect(),
            thin.iter()
                .map(|s| f(&s.setpoint.cartesian.position))
                .collect(),
        )
    };
    let all = thin
        .iter()
        .flat_map(|s| [s.position, s.setpoint.cartesian.position]);
    let (lo, hi) = all.fold(
        (
            Vector3::repeat(f64::INFINITY),
            Vector3::repeat(f64::NEG_INFINITY),
        ),
        |(lo, hi), p| (lo.inf(&p), hi.sup(&p)),
    );
    let margin = Vector3::repeat(0.05);
    // The side view looks across the path's longer horizontal extent.
    let along_y = hi.y - lo.y > hi.x - lo.x;
    let top_view: View = |p| (p.x, p.y);
    let side_view: View = if along_y {
        |p| (p.y, p.z)
    } else {
        |p| (p.x, p.z)
    };
    let (top, top_ref) = pts(top_view);
    let (side, side_ref) = pts(side_view);
    let (lo, hi) = (lo - margin, hi + margin);
    let mut top_lines = Vec::new();
    let mut side_lines = Vec::new();
    let path: Vec<Vector3<f64>> = thin.iter().map(|s| s.position).collect();
    for s in scene.surfaces() {
        top_lines.extend(outline(&s.geometry, &path, lo, hi, top_view));
        side_lines.extend(outline(&s.geometry, &path, lo, hi, side_view));
    }
    let side_x = padded(extent(
        side.iter().map(|p| p.0).chain(side_ref.iter().map(|p| p.0)),
    ));
    let side_z = padded(extent(
        side.iter().map(|p| p.1).chain(side_ref.iter().map(|p| p.1)),
    ));
    two_path_views(
        "End-effector path over the surface",
        &PathPanel {
            outlines: &top_lines,
            ..PathPanel::top(&top, &top_ref)
        },
        &PathPanel {
            caption: if along_y {
                "Side view (along y)"
            } else {
                "Side view (along x)"
            },
            axes: (if along_y { "y (m)" } else { "x (m)" }, "z (m)"),
            ranges: Some((side_x, side_z)),
            actual: &side,
            reference: &side_ref,
            surface: None,
            surface_edge: None,
            outlines: &side_lines,
        },
        t_range,
    )
}
