//! Output of a run: CSV with units in the headers, SVG figures like the thesis's, text
//! tables, and atomic file writing (feature `std`).
//!
//! - [`csv`]: [`trajectory_csv`] for a closed-loop run, [`open_loop_csv`] for
//!   `armdyn simulate`.
//! - [`plots`]: [`path_views`], [`joint_tracking`], [`joint_errors`],
//!   [`cartesian_tracking`], [`force_tracking`], each returning an SVG document.
//! - [`table`]: [`Table`], Markdown or plain aligned tables.
//! - [`atomic`]: [`write_atomic`] and [`OutputDir`], so that a failed run leaves no partial
//!   output.
//! - [`decimate`]: thinning long series for plotting.
//!
//! # Example
//!
//! ```
//! use armdyn::report::{OutputDir, Table};
//!
//! let dir = std::env::temp_dir().join(format!("armdyn-doc-report-{}", std::process::id()));
//! let mut out = OutputDir::create(&dir).unwrap();
//! let table = Table::new(["metric", "value"]).row(["rms (rad)", "0.01"]);
//! out.write("metrics.md", table.markdown()).unwrap();
//! out.commit().unwrap();
//! assert!(dir.join("metrics.md").exists());
//! # std::fs::remove_dir_all(&dir).unwrap();
//! ```

pub mod atomic;
pub mod contact_plots;
pub mod csv;
pub mod data_plots;
pub mod decimate;
pub mod plots;
pub mod table;
#[cfg(test)]
mod test_support;
pub mod view;

pub use atomic::{write_atomic, OutputDir};
pub use contact_plots::{normal_force_tracking, surface_path_views};
pub use csv::{open_loop_csv, trajectory_csv, trajectory_csv_header};
pub use decimate::{decimate_min_max, decimate_stride};
pub use plots::{
    cartesian_tracking, force_tracking, joint_errors, joint_tracking, path_views, PlotError,
    SurfacePatch,
};
pub use table::{Align, Table};
