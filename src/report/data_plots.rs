//! Figures of plain data series as SVG text: measured against predicted time series per
//! panel (identification) and histograms (sweeps).

use plotters::prelude::*;

use super::decimate::decimate_min_max;
use super::plots::{PlotError, MAX_POINTS};

const FONT: &str = "sans-serif";
const COLOURS: [RGBColor; 3] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
];

fn draw_err(e: impl std::fmt::Display) -> PlotError {
    PlotError::Draw(e.to_string())
}

/// One panel: a title, a y-axis label and named series of `(x, y)` points.
pub struct Panel {
    /// Panel title.
    pub title: String,
    /// y-axis label with its unit.
    pub y_label: String,
    /// `(name, points)`, drawn in blue, red, green.
    pub series: Vec<(String, Vec<(f64, f64)>)>,
}

fn bounds(points: impl Iterator<Item = (f64, f64)>) -> Option<((f64, f64), (f64, f64))> {
    let mut b: Option<((f64, f64), (f64, f64))> = None;
    for (x, y) in points.filter(|(x, y)| x.is_finite() && y.is_finite()) {
        b = Some(match b {
            None => ((x, x), (y, y)),
            Some(((x0, x1), (y0, y1))) => ((x0.min(x), x1.max(x)), (y0.min(y), y1.max(y))),
        });
    }
    b.map(|((x0, x1), (y0, y1))| {
        let pad = |lo: f64, hi: f64| {
            let d = if hi > lo {
                0.05 * (hi - lo)
            } else {
                0.5 * lo.abs().max(1.0)
            };
            (lo - d, hi + d)
        };
        (pad(x0, x1), pad(y0, y1))
    })
}

/// Panels stacked in one column, x in seconds, each series thinned to [`MAX_POINTS`].
///
/// # Errors
///
/// [`PlotError::Empty`] if a panel has no finite point; [`PlotError::Draw`] if drawing fails.
pub fn time_panels(title: &str, panels: &[Panel]) -> Result<String, PlotError> {
    draw_panels(title, "t (s)", panels, false)
}

/// Panels stacked in one column against any `x_label`: each panel's first series as dots (a
/// scatter, thinned by stride to [`MAX_POINTS`]), the others as lines.
///
/// # Errors
///
/// As [`time_panels`].
pub fn scatter_panels(title: &str, x_label: &str, panels: &[Panel]) -> Result<String, PlotError> {
    draw_panels(title, x_label, panels, true)
}

fn draw_panels(
    title: &str,
    x_label: &str,
    panels: &[Panel],
    scatter_first: bool,
) -> Result<String, PlotError> {
    let mut svg = String::new();
    {
        let height = 60 + 260 * panels.len().max(1) as u32;
        let root = SVGBackend::with_string(&mut svg, (1000, height)).into_drawing_area();
        root.fill(&WHITE).map_err(draw_err)?;
        let root = root.titled(title, (FONT, 22)).map_err(draw_err)?;
        for (area, p) in root
            .split_evenly((panels.len().max(1), 1))
            .iter()
            .zip(panels)
        {
            let all = p.series.iter().flat_map(|(_, s)| s.iter().copied());
            let ((x0, x1), (y0, y1)) = bounds(all).ok_or(PlotError::Empty)?;
            let mut chart = ChartBuilder::on(area)
                .caption(&p.title, (FONT, 16))
                .margin(8)
                .x_label_area_size(30)
                .y_label_area_size(70)
                .build_cartesian_2d(x0..x1, y0..y1)
                .map_err(draw_err)?;
            chart
                .configure_mesh()
                .x_desc(x_label)
                .y_desc(&p.y_label)
                .label_style((FONT, 12))
                .draw()
                .map_err(draw_err)?;
            for (k, (name, points)) in p.series.iter().enumerate() {
                let colour = COLOURS[k % COLOURS.len()];
                if scatter_first && k == 0 {
                    let stride = points.len().div_ceil(MAX_POINTS).max(1);
                    chart
                        .draw_series(
                            points
                                .iter()
                                .step_by(stride)
                                .filter(|(x, y)| x.is_finite() && y.is_finite())
                                .map(|p| Circle::new(*p, 1, colour.filled())),
                        )
                        .map_err(draw_err)?
                        .label(name.as_str())
                        .legend(move |(x, y)| Circle::new((x + 9, y), 2, colour.filled()));
                    continue;
                }
                let thin = decimate_min_max(points, MAX_POINTS);
                chart
                    .draw_series(LineSeries::new(thin, colour.stroke_width(1)))
                    .map_err(draw_err)?
                    .label(name.as_str())
                    .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], colour));
            }
            chart
                .configure_series_labels()
                .background_style(WHITE.mix(0.85))
                .border_style(BLACK)
                .label_font((FONT, 12))
                .draw()
                .map_err(draw_err)?;
        }
        root.present().map_err(draw_err)?;
    }
    Ok(svg)
}

/// A histogram of `values` (non-finite ones left out) in `bins` equal bins.
///
/// # Errors
///
/// [`PlotError::Empty`] without a finite value; [`PlotError::Draw`] if drawing fails.
pub fn histogram(
    title: &str,
    x_label: &str,
    values: &[f64],
    bins: usize,
) -> Result<String, PlotError> {
    let v: Vec<f64> = values.iter().copied().filter(|x| x.is_finite()).collect();
    let (lo, hi) = v
        .iter()
        .fold(None, |b: Option<(f64, f64)>, x| {
            Some(b.map_or((*x, *x), |(l, h)| (l.min(*x), h.max(*x))))
        })
        .ok_or(PlotError::Empty)?;
    let bins = bins.max(1);
    let (lo, hi) = if hi > lo {
        (lo, hi)
    } else {
        (lo - 0.5, hi + 0.5)
    };
    let width = (hi - lo) / bins as f64;
    let mut counts = vec![0usize; bins];
    for x in &v {
        let k = (((x - lo) / width) as usize).min(bins - 1);
        counts[k] += 1;
    }
    let top = *counts.iter().max().unwrap_or(&1) as f64 * 1.1;
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (800, 500)).into_drawing_area();
        root.fill(&WHITE).map_err(draw_err)?;
        let mut chart = ChartBuilder::on(&root)
            .caption(title, (FONT, 18))
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(60)
            .build_cartesian_2d(lo..hi, 0.0..top.max(1.0))
            .map_err(draw_err)?;
        chart
            .configure_mesh()
            .x_desc(x_label)
            .y_desc("trials")
            .label_style((FONT, 12))
            .draw()
            .map_err(draw_err)?;
        chart
            .draw_series(counts.iter().enumerate().map(|(k, c)| {
                let x0 = lo + width * k as f64;
                Rectangle::new(
                    [(x0, 0.0), (x0 + width, *c as f64)],
                    COLOURS[0].mix(0.7).filled(),
                )
            }))
            .map_err(draw_err)?;
        root.present().map_err(draw_err)?;
    }
    Ok(svg)
}
