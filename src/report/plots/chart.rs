//! The chart elements every figure is built from: the figure and its title, axes with tick
//! labels that tell ticks apart, legends placed away from the data, curve styles, and one
//! panel of curves over time.

use super::{draw_err, PlotError, FIGURE_SIZE, FONT, GRID_BOLD, GRID_LIGHT, MAX_POINTS};
use crate::report::decimate::decimate_min_max;
use crate::sim::Sample;
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;

pub(in crate::report) type Area<'a> = DrawingArea<SVGBackend<'a>, Shift>;
pub(in crate::report) type Chart<'a> =
    ChartContext<'a, SVGBackend<'a>, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// How a curve is drawn.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(in crate::report) enum Style {
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
pub(in crate::report) struct Curve {
    label: String,
    points: Vec<(f64, f64)>,
    style: Style,
}

impl Curve {
    pub(in crate::report) fn new(
        label: impl Into<String>,
        style: Style,
        points: Vec<(f64, f64)>,
    ) -> Self {
        Self {
            label: label.into(),
            points: decimate_min_max(&points, MAX_POINTS),
            style,
        }
    }
}

/// Smallest and largest finite value, if any.
pub(in crate::report) fn extent(values: impl IntoIterator<Item = f64>) -> Option<(f64, f64)> {
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
pub(in crate::report) fn padded(range: Option<(f64, f64)>) -> (f64, f64) {
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
pub(in crate::report) fn time_range(t0: f64, t1: f64) -> (f64, f64) {
    if t1 > t0 {
        (t0, t1)
    } else {
        (t0, t0 + 1.0)
    }
}

/// Tick labels for an axis over `[lo, hi]` with about `ticks` labels: enough decimals to
/// tell ticks apart, trailing zeros dropped, an exponent for very small or large values.
pub(in crate::report) fn tick_format(lo: f64, hi: f64, ticks: usize) -> impl Fn(&f64) -> String {
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

pub(in crate::report) fn trim_zeros(s: &str) -> &str {
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
pub(in crate::report) fn grid(n: usize) -> (usize, usize) {
    if n <= 3 {
        (n.max(1), 1)
    } else {
        (n.div_ceil(2), 2)
    }
}

/// Figure size for a grid of `rows` rows.
pub(in crate::report) fn size_for(rows: usize) -> (u32, u32) {
    let (w, h) = FIGURE_SIZE;
    (w, h.max(60 + 215 * rows as u32))
}

/// Colour of the path at fraction `u` of the run: blue (start) through cyan, green and
/// yellow to red (end), as the thesis's rainbow.
pub(in crate::report) fn time_colour(u: f64) -> RGBAColor {
    let u = if u.is_finite() {
        u.clamp(0.0, 1.0)
    } else {
        0.0
    };
    HSLColor(2.0 / 3.0 * (1.0 - u), 0.95, 0.45).to_rgba()
}

/// Draws a whole figure into a string: white background, a title, then `body` on the
/// rest.
pub(in crate::report) fn figure(
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
pub(in crate::report) fn mesh<'a>(
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
pub(in crate::report) fn legend(
    chart: &mut Chart<'_>,
    position: SeriesLabelPosition,
) -> Result<(), PlotError> {
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
pub(in crate::report) fn legend_corner(
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
pub(in crate::report) fn dashed_glyph<'a, DB: DrawingBackend + 'a>(
    (x, y): (i32, i32),
) -> impl IntoDynElement<'a, DB, (i32, i32)> {
    let style = BLACK.stroke_width(2);
    EmptyElement::at((x, y))
        + PathElement::new(vec![(0, 0), (6, 0)], style)
        + PathElement::new(vec![(10, 0), (16, 0)], style)
        + PathElement::new(vec![(20, 0), (22, 0)], style)
}

/// One panel: `curves` over time in `t_range`, with a caption and axis titles.
pub(in crate::report) fn time_panel(
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
pub(in crate::report) fn series<const N: usize>(
    samples: &[Sample<N>],
    f: impl Fn(&Sample<N>) -> f64,
) -> Vec<(f64, f64)> {
    samples.iter().map(|s| (s.t, f(s))).collect()
}

pub(in crate::report) fn run_range<const N: usize>(
    samples: &[Sample<N>],
) -> Result<(f64, f64), PlotError> {
    match (samples.first(), samples.last()) {
        (Some(a), Some(b)) => Ok(time_range(a.t, b.t)),
        _ => Err(PlotError::Empty),
    }
}

/// Panels in a grid, one per item, drawn by `panel(area, index)`.
pub(in crate::report) fn panels(
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

#[cfg(test)]
mod tests {
    use super::*;

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
}
