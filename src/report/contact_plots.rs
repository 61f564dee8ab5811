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

/// Outline points of a surface in a view that keeps coordinates `(a, b)` of a point,
/// limited to the box `lo..hi` (in 3-D) around the path.
fn outline(
    g: &SurfaceGeometry,
    lo: Vector3<f64>,
    hi: Vector3<f64>,
    view: View,
) -> Vec<Vec<(f64, f64)>> {
    let inside = |p: &Vector3<f64>| (0..3).all(|i| lo[i] <= p[i] && p[i] <= hi[i]);
    let keep = |pts: Vec<Vector3<f64>>| -> Vec<(f64, f64)> {
        pts.iter().filter(|p| inside(p)).map(view).collect()
    };
    match *g {
        SurfaceGeometry::Plane {
            point,
            axes,
            half_extent,
            ..
        } => {
            let corner = |a: f64, b: f64| {
                point + axes[0] * (a * half_extent[0]) + axes[1] * (b * half_extent[1])
            };
            let c = [
                corner(-1.0, -1.0),
                corner(1.0, -1.0),
                corner(1.0, 1.0),
                corner(-1.0, 1.0),
                corner(-1.0, -1.0),
            ];
            vec![c.iter().map(view).collect()]
        }
        SurfaceGeometry::Sphere { centre, radius } => {
            // The great circles in the base planes through the centre.
            let ring = |u: Vector3<f64>, v: Vector3<f64>| -> Vec<Vector3<f64>> {
                (0..=720)
                    .map(|k| {
                        let a = k as f64 * core::f64::consts::PI / 360.0;
                        centre + (u * libm::cos(a) + v * libm::sin(a)) * radius
                    })
                    .collect()
            };
            vec![
                keep(ring(Vector3::x(), Vector3::z())),
                keep(ring(Vector3::y(), Vector3::z())),
                keep(ring(Vector3::x(), Vector3::y())),
            ]
        }
        SurfaceGeometry::Cylinder {
            point,
            axis,
            radius,
        } => {
            let [u, v] = crate::contact::plane_axes(&axis);
            let circle: Vec<Vector3<f64>> = (0..=720)
                .map(|k| {
                    let a = k as f64 * core::f64::consts::PI / 360.0;
                    point + (u * libm::cos(a) + v * libm::sin(a)) * radius
                })
                .collect();
            let line = |off: Vector3<f64>| -> Vec<Vector3<f64>> {
                (-200..=200)
                    .map(|k| point + off + axis * (k as f64 * 0.01))
                    .collect()
            };
            vec![
                keep(circle),
                keep(line(u * radius)),
                keep(line(-u * radius)),
                keep(line(v * radius)),
                keep(line(-v * radius)),
            ]
        }
    }
    .into_iter()
    .filter(|l| l.len() >= 2)
    .collect()
}

/// Top (x-y) and side (x-z, or y-z when the path runs more along y) views of the path with every surface of `scene` drawn (a plane
/// patch as its outline, a sphere as its great circles, a cylinder as its section and
/// mantle lines, each where it is near the path).
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
    for s in scene.surfaces() {
        top_lines.extend(outline(&s.geometry, lo, hi, top_view));
        side_lines.extend(outline(&s.geometry, lo, hi, side_view));
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
