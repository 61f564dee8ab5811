//! Monte Carlo robustness sweeps (feature `std`): a scenario plus the distributions of its
//! `[sweep]` table, many trials in parallel, results as data (`trials.csv`, `summary.json`)
//! first and histograms second.
//!
//! - [`spec`]: the `[sweep]` table and its checks.
//! - [`draw`]: every trial's values, drawn up front from one seeded generator (so the same
//!   seed gives the same trials whatever the thread count), and the scenario with them.
//! - [`trial`]: one trial run as `armdyn run` runs it, reduced to metrics and failure
//!   reasons.
//! - [`run`]: the trials on a rayon pool.
//! - [`output`]: the files.

pub mod draw;
pub mod output;
pub mod run;
pub mod spec;
pub mod trial;

pub use draw::{apply, draw_all, Draw};
pub use output::{summary_json, trials_csv, write_sweep};
pub use run::{run_sweep, run_trials, SweepRun};
pub use spec::{Distribution, SweepKey, SweepSpec, TABLE};
pub use trial::{run_trial, Failure, TrialResult, METRICS};
