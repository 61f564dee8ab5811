//! Figures of a recorded run as SVG text, after the thesis's (Figures 4.3–4.6, 4.9, 5.2,
//! 5.8, 5.10, 5.11).
//!
//! Every function returns the whole SVG document as a `String`, for the caller to write
//! (atomically, with [`crate::report::write_atomic`] or [`crate::report::OutputDir`]).
//! Drawing uses `plotters`' SVG backend without its TrueType features: text is written as
//! SVG `<text>` elements in a generic `sans-serif` family and laid out by the viewer, so no
//! font files, fontconfig or freetype are needed. Long series are thinned to at most
//! [`MAX_POINTS`] points each ([`decimate_min_max`](crate::report::decimate_min_max) keeps every run's extremes).
//!
//! | function | figure |
//! | --- | --- |
//! | [`path_views`] | top (x-y) and side (x-z) views of the path, coloured by time (4.3, 4.14, 5.2) |
//! | [`joint_tracking`] | each joint, actual and reference over time (4.4, 4.5) |
//! | [`joint_errors`] | each joint, `q_ref - q` over time, optionally a time window (4.6, 4.9) |
//! | [`cartesian_tracking`] | x, y, z and yaw, actual and reference over time |
//! | [`force_tracking`] | `fz` and its reference over time (5.8, 5.10, 5.11) |

mod chart;
mod path_views;
mod time_series;

pub use path_views::{path_views, SurfacePatch};
pub use time_series::{cartesian_tracking, force_tracking, joint_errors, joint_tracking};

pub(in crate::report) use chart::{extent, figure, padded, run_range, time_panel, Curve, Style};
pub(in crate::report) use path_views::{two_path_views, PathPanel};

use plotters::prelude::RGBColor;

/// Size of every figure, pixels (width, height); grids of more than three rows grow taller.
pub const FIGURE_SIZE: (u32, u32) = (1000, 700);

/// Most points drawn per series.
pub const MAX_POINTS: usize = 2000;

const FONT: &str = "sans-serif";
pub(in crate::report) const ACTUAL: RGBColor = RGBColor(31, 119, 180);
const ERROR: RGBColor = RGBColor(214, 39, 40);
pub(in crate::report) const SURFACE: RGBColor = RGBColor(230, 190, 0);
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

pub(in crate::report) fn draw_err(e: impl std::fmt::Display) -> PlotError {
    PlotError::Draw(e.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{RobotModel, Scara};
    use crate::report::test_support::synthetic_run;
    use crate::sim::Sample;

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
    /// by `ARMDYN_REPORT_DUMP`, for looking at them: `ARMDYN_REPORT_DUMP=/tmp/figs cargo test
    /// --lib report::plots::tests::dump -- --ignored`.
    #[test]
    #[ignore = "writes files for visual inspection"]
    fn dump() {
        let Some(dir) = std::env::var_os("ARMDYN_REPORT_DUMP") else {
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
}
