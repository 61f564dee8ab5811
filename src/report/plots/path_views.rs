//! The end-effector path seen from above and from the side, coloured by time.

use super::chart::{
    dashed_glyph, extent, figure, legend, legend_corner, mesh, padded, run_range, tick_format,
    time_colour, trim_zeros, Area,
};
use super::{draw_err, PlotError, COLOUR_STEPS, FIGURE_SIZE, FONT, MAX_POINTS, SURFACE};
use crate::report::decimate::decimate_stride;
use crate::sim::Sample;
use plotters::prelude::*;

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

/// Widens `(x, y)` ranges so that one metre is as long on both axes of a plotting area of
/// `pixels` (width, height).
pub(in crate::report) fn equal_aspect(
    x: (f64, f64),
    y: (f64, f64),
    pixels: (u32, u32),
) -> ((f64, f64), (f64, f64)) {
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

/// One view of a path figure: the actual path (`x, y, t`), the reference, and what is drawn
/// under them (a surface block `[(x0, y0), (x1, y1)]`, its edge, outlines).
pub(in crate::report) struct PathPanel<'a> {
    pub(in crate::report) caption: &'a str,
    pub(in crate::report) axes: (&'a str, &'a str),
    /// The axis ranges (`None`: the data's, padded, at equal aspect).
    pub(in crate::report) ranges: Option<((f64, f64), (f64, f64))>,
    pub(in crate::report) actual: &'a [(f64, f64, f64)],
    pub(in crate::report) reference: &'a [(f64, f64)],
    pub(in crate::report) surface: Option<[(f64, f64); 2]>,
    pub(in crate::report) surface_edge: Option<[(f64, f64); 2]>,
    pub(in crate::report) outlines: &'a [Vec<(f64, f64)>],
}

impl<'a> PathPanel<'a> {
    /// The top view (x, y) of a path and its reference, at equal aspect, nothing under them.
    pub(in crate::report) fn top(
        actual: &'a [(f64, f64, f64)],
        reference: &'a [(f64, f64)],
    ) -> Self {
        Self {
            caption: "Top view",
            axes: ("x (m)", "y (m)"),
            ranges: None,
            actual,
            reference,
            surface: None,
            surface_edge: None,
            outlines: &[],
        }
    }
}

/// A figure of two path views side by side (top, side) over a colour bar of time.
pub(in crate::report) fn two_path_views(
    title: &str,
    top: &PathPanel<'_>,
    side: &PathPanel<'_>,
    t_range: (f64, f64),
) -> Result<String, PlotError> {
    figure(FIGURE_SIZE, title, |area| {
        let (views, bar) = area.split_vertically(area.dim_in_pixel().1 - 95);
        let halves = views.split_evenly((1, 2));
        path_panel(&halves[0], top, t_range)?;
        path_panel(&halves[1], side, t_range)?;
        colour_bar(&bar, t_range)
    })
}

/// Time-coloured path in one view: the reference dashed black, the actual path in pieces
/// coloured from blue to red, and optionally a surface under them.
fn path_panel(area: &Area, panel: &PathPanel<'_>, t_range: (f64, f64)) -> Result<(), PlotError> {
    let PathPanel {
        caption,
        axes,
        ranges,
        actual,
        reference,
        surface,
        surface_edge,
        outlines,
    } = *panel;
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
fn colour_bar(area: &Area, t_range: (f64, f64)) -> Result<(), PlotError> {
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
    // (x, y) seen from above, (x, z) from the side: index 1 or 2 of the position.
    let measured = |axis: usize| -> Vec<(f64, f64, f64)> {
        thin.iter()
            .map(|s| (s.position.x, s.position[axis], s.t))
            .collect()
    };
    let reference = |axis: usize| -> Vec<(f64, f64)> {
        thin.iter()
            .map(|s| {
                let p = &s.setpoint.cartesian.position;
                (p.x, p[axis])
            })
            .collect()
    };
    let (top, side) = (measured(1), measured(2));
    let (top_ref, side_ref) = (reference(1), reference(2));
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
    two_path_views(
        "End-effector path",
        &PathPanel {
            surface: surface.map(|s| [(s.x_range[0], s.y_range[0]), (s.x_range[1], s.y_range[1])]),
            ..PathPanel::top(&top, &top_ref)
        },
        &PathPanel {
            caption: "Side view",
            axes: ("x (m)", "z (m)"),
            ranges: Some((side_x, side_z)),
            actual: &side,
            reference: &side_ref,
            surface: surface.map(|s| [(s.x_range[0], side_z.0), (s.x_range[1], s.z)]),
            surface_edge: surface.map(|s| [(s.x_range[0], s.z), (s.x_range[1], s.z)]),
            outlines: &[],
        },
        t_range,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn equal_aspect_widens_the_short_side() {
        let (x, y) = equal_aspect((0.0, 1.0), (0.0, 1.0), (200, 100));
        assert_eq!(y, (0.0, 1.0));
        assert!((x.1 - x.0 - 2.0).abs() < 1e-12);
        assert!((0.5 * (x.0 + x.1) - 0.5).abs() < 1e-12);
    }
}
