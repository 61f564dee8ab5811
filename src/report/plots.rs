//! Figures of a recorded run as SVG text, after the thesis's (Figures 4.3–4.6, 4.9, 5.2,
//! 5.8, 5.10, 5.11).
//!
//! Every function returns the whole SVG document as a `String`, for the caller to write
//! (atomically, with [`crate::report::write_atomic`] or [`crate::report::OutputDir`]).
//! Drawing uses `plotters`' SVG backend without its TrueType features: text is written as
//! SVG `<text>` elements in a generic `sans-serif` family and laid out by the viewer, so no
//! font files, fontconfig or freetype are needed. Long series are thinned to at most
//! [`MAX_POINTS`] points each ([`decimate_min_max`] keeps every run's extremes).
//!
//! | function | figure |
//! | --- | --- |
//! | [`path_views`] | top (x-y) and side (x-z) views of the path, coloured by time (4.3, 4.14, 5.2) |
//! | [`joint_tracking`] | each joint, actual and reference over time (4.4, 4.5) |
//! | [`joint_errors`] | each joint, `q_ref - q` over time, optionally a time window (4.6, 4.9) |
//! | [`cartesian_tracking`] | x, y, z and yaw, actual and reference over time |
//! | [`force_tracking`] | `fz` and its reference over time (5.8, 5.10, 5.11) |

use super::decimate::{decimate_min_max, decimate_stride};
use crate::model::JointKind;
use crate::sim::Sample;
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;

/// Size of every figure, pixels (width, height); grids of more than three rows grow taller.
pub const FIGURE_SIZE: (u32, u32) = (1000, 700);

/// Most points drawn per series.
pub const MAX_POINTS: usize = 2000;

const FONT: &str = "sans-serif";
pub(super) const ACTUAL: RGBColor = RGBColor(31, 119, 180);
const ERROR: RGBColor = RGBColor(214, 39, 40);
pub(super) const SURFACE: RGBColor = RGBColor(230, 190, 0);
const GRID_BOLD: RGBColor = RGBColor(205, 205, 205);
const GRID_LIGHT: RGBColor = RGBColor(238, 238, 238);
/// Pieces of one colour the time-coloured path is drawn in.
const COLOUR_STEPS: usize = 128;

/// Why a figure could not be drawn.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum PlotError {
    /// There are no samples.
    #[error("no samples to plot")]
    Empty,
    /// The time window is empty, reversed or holds no sample.
    #[error("no samples in the time window [{0}, {1}] s")]
    Window(f64, f64),
    /// The drawing backend failed.
    #[error("drawing the figure: {0}")]
    Draw(String),
}

pub(super) fn draw_err(e: impl std::fmt::Display) -> PlotError {
    PlotError::Draw(e.to_string())
}

/// A reaction surface to draw in [`path_views`]: the plane `z` (m) over `x_range` ×
/// `y_range` (m, `[min, max]`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfacePatch {
    /// Height of the plane, m.
    pub z: f64,
    /// `[x_min, x_max]`, m.
    pub x_range: [f64; 2],
    /// `[y_min, y_max]`, m.
    pub y_range: [f64; 2],
}

pub(super) type Area<'a> = DrawingArea<SVGBackend<'a>, Shift>;
type Chart<'a> = ChartContext<'a, SVGBackend<'a>, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// How a curve is drawn.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Style {
    /// Solid, coloured, 2 px.
    Solid(RGBColor),
    /// Dashed black: a reference.
    Reference,
    /// Thin grey, no legend entry: the zero line.
    Zero,
    /// Dotted, coloured, not counted in the y range: an event (a vertical line).
    Marker(RGBColor),
}

/// One curve of a panel over time.
pub(super) struct Curve {
    label: String,
    points: Vec<(f64, f64)>,
    style: Style,
}

impl Curve {
    pub(super) fn new(label: impl Into<String>, style: Style, points: Vec<(f64, f64)>) -> Self {
        Self {
            label: label.into(),
            points: decimate_min_max(&points, MAX_POINTS),
            style,
        }
    }
}

/// Smallest and largest finite value, if any.
pub(super) fn extent(values: impl IntoIterator<Item = f64>) -> Option<(f64, f64)> {
    values
        .into_iter()
        .filter(|v| v.is_finite())
        .fold(None, |acc, v| match acc {
            None => Some((v, v)),
            Some((lo, hi)) => Some((lo.min(v), hi.max(v))),
        })
}

/// An axis range around `[lo, hi]` with 5 % margin; a flat or missing range is widened
/// to show the value in the middle.
pub(super) fn padded(range: Option<(f64, f64)>) -> (f64, f64) {
    let Some((lo, hi)) = range else {
        return (-1.0, 1.0);
    };
    let span = hi - lo;
    let mid = 0.5 * (lo + hi);
    if span <= 1e-12 * mid.abs().max(1e-300) || span == 0.0 {
        let pad = if mid == 0.0 { 1.0 } else { 0.1 * mid.abs() };
        return (mid - pad, mid + pad);
    }
    (lo - 0.05 * span, hi + 0.05 * span)
}

/// Time axis: first to last sample (one second if there is a single time).
fn time_range(t0: f64, t1: f64) -> (f64, f64) {
    if t1 > t0 {
        (t0, t1)
    } else {
        (t0, t0 + 1.0)
    }
}

/// Tick labels for an axis over `[lo, hi]` with about `ticks` labels: enough decimals to
/// tell ticks apart, trailing zeros dropped, an exponent for very small or large values.
fn tick_format(lo: f64, hi: f64, ticks: usize) -> impl Fn(&f64) -> String {
    let span = (hi - lo).abs();
    let magnitude = lo.abs().max(hi.abs());
    let scientific = !(1e-3..1e5).contains(&magnitude);
    let step = span / ticks.max(1) as f64;
    let decimals = if step > 0.0 {
        (-step.log10()).ceil().clamp(0.0, 12.0) as usize
    } else {
        3
    };
    move |v: &f64| {
        let v = if v.abs() <= span * 1e-9 { 0.0 } else { *v };
        if scientific && v != 0.0 {
            let s = format!("{v:.3e}");
            let (mantissa, exponent) = s.split_once('e').unwrap_or((&s, "0"));
            format!("{}e{exponent}", trim_zeros(mantissa))
        } else {
            trim_zeros(&format!("{v:.decimals$}")).to_owned()
        }
    }
}

fn trim_zeros(s: &str) -> &str {
    if s.contains('.') {
        let t = s.trim_end_matches('0').trim_end_matches('.');
        if t == "-0" {
            "0"
        } else {
            t
        }
    } else {
        s
    }
}

/// Rows and columns for `n` panels: one column up to three, then two.
fn grid(n: usize) -> (usize, usize) {
    if n <= 3 {
        (n.max(1), 1)
    } else {
        (n.div_ceil(2), 2)
    }
}

/// Figure size for a grid of `rows` rows.
fn size_for(rows: usize) -> (u32, u32) {
    let (w, h) = FIGURE_SIZE;
    (w, h.max(60 + 215 * rows as u32))
}

/// Colour of the path at fraction `u` of the run: blue (start) through cyan, green and
/// yellow to red (end), as the thesis's rainbow.
fn time_colour(u: f64) -> RGBAColor {
    let u = if u.is_finite() {
        u.clamp(0.0, 1.0)
    } else {
        0.0
    };
    HSLColor(2.0 / 3.0 * (1.0 - u), 0.95, 0.45).to_rgba()
}

/// Draws a whole figure into a string: white background, a title, then `body` on the
/// rest.
pub(super) fn figure(
    size: (u32, u32),
    title: &str,
    body: impl FnOnce(&Area) -> Result<(), PlotError>,
) -> Result<String, PlotError> {
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, size).into_drawing_area();
        root.fill(&WHITE).map_err(draw_err)?;
        let area = root.titled(title, (FONT, 28)).map_err(draw_err)?;
        body(&area)?;
        root.present().map_err(draw_err)?;
    }
    Ok(svg)
}

/// Applies the common axis style and draws the mesh.
fn mesh<'a>(
    chart: &mut Chart<'a>,
    x_desc: &str,
    y_desc: &str,
    x_fmt: &dyn Fn(&f64) -> String,
    y_fmt: &dyn Fn(&f64) -> String,
) -> Result<(), PlotError> {
    chart
        .configure_mesh()
        .x_desc(x_desc)
        .y_desc(y_desc)
        .x_labels(10)
        .y_labels(8)
        .x_label_formatter(x_fmt)
        .y_label_formatter(y_fmt)
        .label_style((FONT, 14))
        .axis_desc_style((FONT, 16))
        .bold_line_style(GRID_BOLD)
        .light_line_style(GRID_LIGHT)
        .max_light_lines(2)
        .draw()
        .map_err(draw_err)
}

/// The legend box, upper right.
fn legend(chart: &mut Chart<'_>, position: SeriesLabelPosition) -> Result<(), PlotError> {
    chart
        .configure_series_labels()
        .position(position)
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK.mix(0.5))
        .label_font((FONT, 14))
        .draw()
        .map_err(draw_err)
}

/// The corner of the plotting area `x` × `y` where a legend box (about a third of the
/// width, a quarter of the height) covers the fewest `points`; upper right on ties.
fn legend_corner(
    points: impl IntoIterator<Item = (f64, f64)>,
    x: (f64, f64),
    y: (f64, f64),
) -> SeriesLabelPosition {
    const W: f64 = 0.36;
    const H: f64 = 0.28;
    // [upper right, upper left, lower right, lower left]
    let mut counts = [0usize; 4];
    for (px, py) in points {
        let u = (px - x.0) / (x.1 - x.0);
        let v = (py - y.0) / (y.1 - y.0);
        let (right, left) = (u >= 1.0 - W, u <= W);
        let (top, bottom) = (v >= 1.0 - H, v <= H);
        counts[0] += usize::from(right && top);
        counts[1] += usize::from(left && top);
        counts[2] += usize::from(right && bottom);
        counts[3] += usize::from(left && bottom);
    }
    let best = (0..4).min_by_key(|&i| (counts[i], i)).unwrap_or(0);
    match best {
        1 => SeriesLabelPosition::UpperLeft,
        2 => SeriesLabelPosition::LowerRight,
        3 => SeriesLabelPosition::LowerLeft,
        _ => SeriesLabelPosition::UpperRight,
    }
}

/// A legend glyph: a short dashed black line.
fn dashed_glyph<'a, DB: DrawingBackend + 'a>(
    (x, y): (i32, i32),
) -> impl IntoDynElement<'a, DB, (i32, i32)> {
    let style = BLACK.stroke_width(2);
    EmptyElement::at((x, y))
        + PathElement::new(vec![(0, 0), (6, 0)], style)
        + PathElement::new(vec![(10, 0), (16, 0)], style)
        + PathElement::new(vec![(20, 0), (22, 0)], style)
}

/// One panel: `curves` over time in `t_range`, with a caption and axis titles.
pub(super) fn time_panel(
    area: &Area,
    caption: &str,
    y_desc: &str,
    t_range: (f64, f64),
    curves: &[Curve],
) -> Result<(), PlotError> {
    let area = area.titled(caption, (FONT, 19)).map_err(draw_err)?;
    let (y0, y1) = padded(extent(
        curves
            .iter()
            .filter(|c| !matches!(c.style, Style::Zero | Style::Marker(_)))
            .flat_map(|c| c.points.iter().map(|p| p.1)),
    ));
    let (t0, t1) = t_range;
    let mut chart = ChartBuilder::on(&area)
        .margin(8)
        .margin_right(16)
        .x_label_area_size(44)
        .y_label_area_size(78)
        .build_cartesian_2d(t0..t1, y0..y1)
        .map_err(draw_err)?;
    let t_fmt = tick_format(t0, t1, 10);
    let y_fmt = tick_format(y0, y1, 8);
    mesh(&mut chart, "time (s)", y_desc, &t_fmt, &y_fmt)?;
    for c in curves {
        let points = c.points.iter().copied();
        match c.style {
            Style::Solid(colour) => {
                let style = colour.stroke_width(2);
                chart
                    .draw_series(LineSeries::new(points, style))
                    .map_err(draw_err)?
                    .label(c.label.as_str())
                    .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 22, y)], style));
            }
            Style::Reference => {
                chart
                    .draw_series(DashedLineSeries::new(points, 7, 4, BLACK.stroke_width(2)))
                    .map_err(draw_err)?
                    .label(c.label.as_str())
                    .legend(dashed_glyph);
            }
            Style::Zero => {
                chart
                    .draw_series(LineSeries::new(points, BLACK.mix(0.45).stroke_width(1)))
                    .map_err(draw_err)?;
            }
            Style::Marker(colour) => {
                // A vertical line at the marker's time, over the whole y range.
                let style = colour.stroke_width(2);
                let t = c.points.first().map_or(t0, |p| p.0);
                chart
                    .draw_series(DashedLineSeries::new([(t, y0), (t, y1)], 3, 3, style))
                    .map_err(draw_err)?
                    .label(c.label.as_str())
                    .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 22, y)], style));
            }
        }
    }
    let corner = legend_corner(
        curves
            .iter()
            .filter(|c| !matches!(c.style, Style::Zero | Style::Marker(_)))
            .flat_map(|c| c.points.iter().copied()),
        (t0, t1),
        (y0, y1),
    );
    legend(&mut chart, corner)
}

/// `(t, f(sample))` for every sample.
pub(super) fn series<const N: usize>(
    samples: &[Sample<N>],
    f: impl Fn(&Sample<N>) -> f64,
) -> Vec<(f64, f64)> {
    samples.iter().map(|s| (s.t, f(s))).collect()
}

pub(super) fn run_range<const N: usize>(samples: &[Sample<N>]) -> Result<(f64, f64), PlotError> {
    match (samples.first(), samples.last()) {
        (Some(a), Some(b)) => Ok(time_range(a.t, b.t)),
        _ => Err(PlotError::Empty),
    }
}

fn kind_name(kind: JointKind) -> &'static str {
    match kind {
        JointKind::Revolute => "revolute",
        JointKind::Prismatic => "prismatic",
    }
}

/// Panels in a grid, one per item, drawn by `panel(area, index)`.
fn panels(
    area: &Area,
    n: usize,
    mut panel: impl FnMut(&Area, usize) -> Result<(), PlotError>,
) -> Result<(), PlotError> {
    let (rows, cols) = grid(n);
    for (i, cell) in area.split_evenly((rows, cols)).iter().enumerate().take(n) {
        panel(cell, i)?;
    }
    Ok(())
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
/// use scara::model::{RobotModel, Scara};
/// use scara::report::plots::joint_tracking;
/// # let samples: Vec<scara::sim::Sample<4>> = vec![];
/// // `samples` as recorded by `scara::sim::simulate`'s observer.
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

/// Widens `(x, y)` ranges so that one metre is as long on both axes of a plotting area of
/// `pixels` (width, height).
fn equal_aspect(x: (f64, f64), y: (f64, f64), pixels: (u32, u32)) -> ((f64, f64), (f64, f64)) {
    let (w, h) = (f64::from(pixels.0.max(1)), f64::from(pixels.1.max(1)));
    let (sx, sy) = ((x.1 - x.0) / w, (y.1 - y.0) / h);
    let widen = |r: (f64, f64), scale: f64, px: f64| {
        let mid = 0.5 * (r.0 + r.1);
        (mid - 0.5 * scale * px, mid + 0.5 * scale * px)
    };
    if sx > sy {
        (x, widen(y, sx, h))
    } else {
        (widen(x, sy, w), y)
    }
}

/// Time-coloured path in one view: the reference dashed black, the actual path in pieces
/// coloured from blue to red, and optionally a surface `[(x0, y0), (x1, y1)]` under them.
#[allow(clippy::too_many_arguments)]
pub(super) fn path_panel(
    area: &Area,
    caption: &str,
    axes: (&str, &str),
    ranges: Option<((f64, f64), (f64, f64))>,
    actual: &[(f64, f64, f64)],
    reference: &[(f64, f64)],
    surface: Option<[(f64, f64); 2]>,
    surface_edge: Option<[(f64, f64); 2]>,
    outlines: &[Vec<(f64, f64)>],
    t_range: (f64, f64),
) -> Result<(), PlotError> {
    const MARGIN: u32 = 10;
    const X_LABELS: u32 = 44;
    const Y_LABELS: u32 = 78;
    let area = area.titled(caption, (FONT, 19)).map_err(draw_err)?;
    let ((x0, x1), (y0, y1)) = match ranges {
        Some(r) => r,
        None => {
            let xs = actual
                .iter()
                .map(|p| p.0)
                .chain(reference.iter().map(|p| p.0));
            let ys = actual
                .iter()
                .map(|p| p.1)
                .chain(reference.iter().map(|p| p.1));
            let surf = surface.iter().flat_map(|s| s.iter().copied());
            let (sx, sy): (Vec<f64>, Vec<f64>) = surf.unzip();
            let x = padded(extent(xs.chain(sx)));
            let y = padded(extent(ys.chain(sy)));
            let (w, h) = area.dim_in_pixel();
            let plot = (
                w.saturating_sub(2 * MARGIN + Y_LABELS),
                h.saturating_sub(2 * MARGIN + X_LABELS),
            );
            equal_aspect(x, y, plot)
        }
    };
    let mut chart = ChartBuilder::on(&area)
        .margin(MARGIN)
        .x_label_area_size(X_LABELS)
        .y_label_area_size(Y_LABELS)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(draw_err)?;
    let x_fmt = tick_format(x0, x1, 10);
    let y_fmt = tick_format(y0, y1, 8);
    mesh(&mut chart, axes.0, axes.1, &x_fmt, &y_fmt)?;
    if let Some([a, b]) = surface {
        let fill = SURFACE.mix(0.35).filled();
        chart
            .draw_series([Rectangle::new([a, b], fill)])
            .map_err(draw_err)?
            .label("reaction surface")
            .legend(move |(x, y)| Rectangle::new([(x, y - 6), (x + 22, y + 6)], fill));
    }
    if let Some([a, b]) = surface_edge {
        chart
            .draw_series([PathElement::new(vec![a, b], SURFACE.stroke_width(3))])
            .map_err(draw_err)?;
    }
    for (k, line) in outlines.iter().enumerate() {
        let s = chart
            .draw_series([PathElement::new(line.clone(), SURFACE.stroke_width(3))])
            .map_err(draw_err)?;
        if k == 0 {
            s.label("surface").legend(|(x, y)| {
                PathElement::new(vec![(x, y), (x + 22, y)], SURFACE.stroke_width(3))
            });
        }
    }
    let (t0, t1) = t_range;
    let n = actual.len();
    let pieces = COLOUR_STEPS.min(n.saturating_sub(1)).max(1);
    for k in 0..pieces {
        let start = k * (n - 1) / pieces;
        let end = ((k + 1) * (n - 1) / pieces).min(n - 1);
        let piece = &actual[start..=end];
        let t_mid = 0.5 * (piece[0].2 + piece[piece.len() - 1].2);
        let colour = time_colour((t_mid - t0) / (t1 - t0));
        let series = chart
            .draw_series(LineSeries::new(
                piece.iter().map(|p| (p.0, p.1)),
                colour.stroke_width(3),
            ))
            .map_err(draw_err)?;
        if k == 0 {
            series.label("actual (colour: time)").legend(|(x, y)| {
                EmptyElement::at((x, y))
                    + PathElement::new(vec![(0, 0), (8, 0)], time_colour(0.0).stroke_width(3))
                    + PathElement::new(vec![(8, 0), (15, 0)], time_colour(0.5).stroke_width(3))
                    + PathElement::new(vec![(15, 0), (22, 0)], time_colour(1.0).stroke_width(3))
            });
        }
    }
    // The reference on top, thin and dashed, so both show where they coincide.
    chart
        .draw_series(DashedLineSeries::new(
            reference.iter().copied(),
            6,
            5,
            BLACK.stroke_width(1),
        ))
        .map_err(draw_err)?
        .label("reference")
        .legend(dashed_glyph);
    let corner = legend_corner(
        actual
            .iter()
            .map(|p| (p.0, p.1))
            .chain(reference.iter().copied()),
        (x0, x1),
        (y0, y1),
    );
    legend(&mut chart, corner)
}

/// The colour bar: time from blue (start) to red (end).
pub(super) fn colour_bar(area: &Area, t_range: (f64, f64)) -> Result<(), PlotError> {
    let (t0, t1) = t_range;
    let fmt_t = |t: f64| trim_zeros(&format!("{t:.3}")).to_owned();
    let caption = format!(
        "Colour of the actual path: time, blue = {} s (start) to red = {} s (end)",
        fmt_t(t0),
        fmt_t(t1)
    );
    let area = area.titled(&caption, (FONT, 16)).map_err(draw_err)?;
    let mut chart = ChartBuilder::on(&area)
        .margin_left(88)
        .margin_right(20)
        .x_label_area_size(40)
        .build_cartesian_2d(t0..t1, 0.0..1.0)
        .map_err(draw_err)?;
    let t_fmt = tick_format(t0, t1, 10);
    chart
        .configure_mesh()
        .disable_mesh()
        .disable_y_axis()
        .x_labels(10)
        .x_label_formatter(&t_fmt)
        .x_desc("time (s)")
        .label_style((FONT, 14))
        .axis_desc_style((FONT, 16))
        .draw()
        .map_err(draw_err)?;
    let steps = COLOUR_STEPS;
    chart
        .draw_series((0..steps).map(|k| {
            let a = t0 + (t1 - t0) * k as f64 / steps as f64;
            let b = t0 + (t1 - t0) * (k + 1) as f64 / steps as f64;
            let u = (k as f64 + 0.5) / steps as f64;
            Rectangle::new([(a, 0.0), (b, 1.0)], time_colour(u).filled())
        }))
        .map_err(draw_err)?;
    Ok(())
}

/// Top view (x-y, equal scales) and side view (x-z) of the end-effector path: the actual
/// path coloured by time from blue (start) to red (end), the reference dashed black, a
/// colour bar naming the start and end times, and `surface` (a reaction surface) in
/// yellow if given (thesis Figures 4.3, 4.14 and 5.2, as two views instead of a 3-D one).
///
/// # Errors
///
/// [`PlotError::Empty`] without samples; [`PlotError::Draw`] if drawing fails.
pub fn path_views<const N: usize>(
    samples: &[Sample<N>],
    surface: Option<&SurfacePatch>,
) -> Result<String, PlotError> {
    let t_range = run_range(samples)?;
    let thin = decimate_stride(samples, MAX_POINTS);
    let top: Vec<(f64, f64, f64)> = thin
        .iter()
        .map(|s| (s.position.x, s.position.y, s.t))
        .collect();
    let side: Vec<(f64, f64, f64)> = thin
        .iter()
        .map(|s| (s.position.x, s.position.z, s.t))
        .collect();
    let top_ref: Vec<(f64, f64)> = thin
        .iter()
        .map(|s| {
            (
                s.setpoint.cartesian.position.x,
                s.setpoint.cartesian.position.y,
            )
        })
        .collect();
    let side_ref: Vec<(f64, f64)> = thin
        .iter()
        .map(|s| {
            (
                s.setpoint.cartesian.position.x,
                s.setpoint.cartesian.position.z,
            )
        })
        .collect();
    // Side view ranges include the surface's top; its block is drawn down to the axis.
    let side_x = padded(extent(
        side.iter()
            .map(|p| p.0)
            .chain(side_ref.iter().map(|p| p.0))
            .chain(surface.iter().flat_map(|s| s.x_range)),
    ));
    let side_z = padded(extent(
        side.iter()
            .map(|p| p.1)
            .chain(side_ref.iter().map(|p| p.1))
            .chain(surface.iter().map(|s| s.z)),
    ));
    figure(FIGURE_SIZE, "End-effector path", |area| {
        let (views, bar) = area.split_vertically(area.dim_in_pixel().1 - 95);
        let halves = views.split_evenly((1, 2));
        path_panel(
            &halves[0],
            "Top view",
            ("x (m)", "y (m)"),
            None,
            &top,
            &top_ref,
            surface.map(|s| [(s.x_range[0], s.y_range[0]), (s.x_range[1], s.y_range[1])]),
            None,
            &[],
            t_range,
        )?;
        path_panel(
            &halves[1],
            "Side view",
            ("x (m)", "z (m)"),
            Some((side_x, side_z)),
            &side,
            &side_ref,
            surface.map(|s| [(s.x_range[0], side_z.0), (s.x_range[1], s.z)]),
            surface.map(|s| [(s.x_range[0], s.z), (s.x_range[1], s.z)]),
            &[],
            t_range,
        )?;
        colour_bar(&bar, t_range)
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{RobotModel, Scara};
    use crate::report::test_support::synthetic_run;

    fn check_svg(svg: &str, texts: &[&str]) {
        assert!(svg.starts_with("<svg"), "{}", &svg[..svg.len().min(80)]);
        assert!(svg.trim_end().ends_with("</svg>"));
        for t in texts {
            assert!(svg.contains(t), "missing {t:?}");
        }
        // Decimation keeps the file small for 10 001 samples.
        assert!(svg.len() < 1_500_000, "{} bytes", svg.len());
    }

    #[test]
    fn joint_figures() {
        let run = synthetic_run(10_001, 10.0);
        let svg = joint_tracking(&run, &Scara::JOINT_NAMES, &Scara::JOINT_KINDS).unwrap();
        check_svg(
            &svg,
            &[
                "Joint tracking",
                "d3 (m)",
                "q4 (rad)",
                "time (s)",
                "reference",
                "actual",
            ],
        );
        let svg = joint_errors(
            &run,
            &Scara::JOINT_NAMES,
            &Scara::JOINT_KINDS,
            Some((0.0, 2.0)),
        )
        .unwrap();
        check_svg(
            &svg,
            &[
                "Joint tracking errors",
                "0 to 2 s",
                "error (m)",
                "q1_ref - q1",
            ],
        );
        let svg = joint_errors(&run, &Scara::JOINT_NAMES, &Scara::JOINT_KINDS, None).unwrap();
        check_svg(&svg, &["error (rad)"]);
    }

    #[test]
    fn cartesian_force_and_path_figures() {
        let run = synthetic_run(10_001, 10.0);
        check_svg(
            &cartesian_tracking(&run).unwrap(),
            &["Cartesian tracking", "x (m)", "yaw (rad)"],
        );
        check_svg(
            &force_tracking(&run).unwrap(),
            &["Contact force tracking", "fz (N)", "fz reference"],
        );
        let patch = SurfacePatch {
            z: 0.13,
            x_range: [0.2, 0.6],
            y_range: [-0.4, 0.4],
        };
        check_svg(
            &path_views(&run, Some(&patch)).unwrap(),
            &[
                "End-effector path",
                "Top view",
                "Side view",
                "reaction surface",
                "blue = 0 s (start) to red = 10 s (end)",
            ],
        );
        let svg = path_views(&run, None).unwrap();
        assert!(!svg.contains("reaction surface"));
    }

    #[test]
    fn errors_and_degenerate_runs() {
        let none: [Sample<4>; 0] = [];
        assert_eq!(force_tracking(&none), Err(PlotError::Empty));
        assert_eq!(path_views(&none, None), Err(PlotError::Empty));
        let run = synthetic_run(101, 1.0);
        let names = &Scara::JOINT_NAMES;
        let kinds = &Scara::JOINT_KINDS;
        assert_eq!(
            joint_errors(&run, names, kinds, Some((2.0, 1.0))),
            Err(PlotError::Window(2.0, 1.0))
        );
        assert_eq!(
            joint_errors(&run, names, kinds, Some((5.0, 6.0))),
            Err(PlotError::Window(5.0, 6.0))
        );
        // One sample: flat ranges are widened, nothing panics.
        let one = &run[..1];
        check_svg(&joint_tracking(one, names, kinds).unwrap(), &["Joint 3"]);
        check_svg(&path_views(one, None).unwrap(), &["Top view"]);
        check_svg(&force_tracking(one).unwrap(), &["fz (N)"]);
    }

    /// Writes every figure of a synthetic and of a simulated run as SVG to the folder named
    /// by `SCARA_REPORT_DUMP`, for looking at them: `SCARA_REPORT_DUMP=/tmp/figs cargo test
    /// --lib report::plots::tests::dump -- --ignored`.
    #[test]
    #[ignore = "writes files for visual inspection"]
    fn dump() {
        let Some(dir) = std::env::var_os("SCARA_REPORT_DUMP") else {
            return;
        };
        let dir = std::path::PathBuf::from(dir);
        std::fs::create_dir_all(&dir).unwrap();
        let patch = SurfacePatch {
            z: 0.13,
            x_range: [0.2, 0.6],
            y_range: [-0.4, 0.4],
        };
        let names = &Scara::JOINT_NAMES;
        let kinds = &Scara::JOINT_KINDS;
        for (tag, run) in [
            ("synthetic", synthetic_run(10_001, 10.0)),
            (
                "simulated",
                crate::report::test_support::simulated_run(10.0),
            ),
        ] {
            let figures = [
                ("path", path_views(&run, Some(&patch)).unwrap()),
                ("joints", joint_tracking(&run, names, kinds).unwrap()),
                (
                    "errors",
                    joint_errors(&run, names, kinds, Some((0.0, 2.0))).unwrap(),
                ),
                ("cartesian", cartesian_tracking(&run).unwrap()),
                ("force", force_tracking(&run).unwrap()),
            ];
            for (name, svg) in figures {
                crate::report::write_atomic(dir.join(format!("{tag}_{name}.svg")), svg).unwrap();
            }
        }
    }

    #[test]
    fn tick_labels() {
        let f = tick_format(0.0, 10.0, 10);
        assert_eq!(f(&2.0), "2");
        let f = tick_format(-0.05, 0.05, 8);
        assert_eq!(f(&0.02), "0.02");
        assert_eq!(f(&-0.0), "0");
        let f = tick_format(-2e-5, 2e-5, 8);
        assert_eq!(f(&1e-5), "1e-5");
        assert_eq!(f(&0.0), "0");
        let f = tick_format(0.0, 2e5, 8);
        assert_eq!(f(&150_000.0), "1.5e5");
    }

    #[test]
    fn legend_avoids_the_data() {
        let rising: Vec<(f64, f64)> = (0..=100).map(|i| (f64::from(i), f64::from(i))).collect();
        // A rising line fills the upper right and lower left corners.
        assert_eq!(
            legend_corner(rising.iter().copied(), (0.0, 100.0), (0.0, 100.0)),
            SeriesLabelPosition::UpperLeft
        );
        let falling = rising.iter().map(|&(x, y)| (x, 100.0 - y));
        assert_eq!(
            legend_corner(falling, (0.0, 100.0), (0.0, 100.0)),
            SeriesLabelPosition::UpperRight
        );
    }

    #[test]
    fn equal_aspect_widens_the_short_side() {
        let (x, y) = equal_aspect((0.0, 1.0), (0.0, 1.0), (200, 100));
        assert_eq!(y, (0.0, 1.0));
        assert!((x.1 - x.0 - 2.0).abs() < 1e-12);
        assert!((0.5 * (x.0 + x.1) - 0.5).abs() < 1e-12);
    }
}
