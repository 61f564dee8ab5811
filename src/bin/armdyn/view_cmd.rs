//! `armdyn view DIR`: the viewer of an existing output folder, written again.

use std::path::PathBuf;

use clap::Args;

/// Arguments of `armdyn view`.
#[derive(Debug, Args)]
pub struct ViewArgs {
    /// Output folders of runs (each with `metrics.json`, `trajectory.csv` and, for a run with
    /// surfaces, `scene.json`).
    #[arg(required = true, value_name = "DIR")]
    dirs: Vec<PathBuf>,
}

/// Writes `DIR/view.html` for each folder.
pub fn run(args: &ViewArgs) -> anyhow::Result<()> {
    for dir in &args.dirs {
        let page = armdyn::scenario::write_view(dir)?;
        outln!("wrote {}", page.display());
    }
    Ok(())
}
