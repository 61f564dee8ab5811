//! `armdyn sweep FILE`: a Monte Carlo sweep over the distributions of a scenario's `[sweep]`
//! table, trials in parallel, a progress bar on a terminal; writes `trials.csv`,
//! `summary.json` and histograms.

use std::io::IsTerminal;
use std::path::PathBuf;

use anyhow::Context;
use clap::Args;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

use armdyn::report::Table;
use armdyn::scenario::Scenario;
use armdyn::sweep::{run_sweep, write_sweep, SweepSpec};

/// Arguments of `armdyn sweep`.
#[derive(Debug, Args)]
pub struct SweepArgs {
    /// Scenario file with a `[sweep]` table.
    #[arg(value_name = "FILE")]
    file: PathBuf,
    /// Number of trials.
    #[arg(long, value_name = "N")]
    samples: usize,
    /// Seed of the draws (the same seed gives the same trials.csv whatever the threads).
    #[arg(long, default_value_t = 1)]
    seed: u64,
    /// Worker threads (default: one per core).
    #[arg(long, value_name = "T")]
    threads: Option<usize>,
    /// The controller's model, over the file's `controller_model`: `nominal` or an
    /// `identification.json`.
    #[arg(long, value_name = "nominal|FILE")]
    controller_model: Option<String>,
    /// Output folder (default `out/sweep-<name>`).
    #[arg(long, value_name = "DIR")]
    out: Option<PathBuf>,
}

/// Runs `armdyn sweep`.
pub fn run(a: &SweepArgs) -> anyhow::Result<()> {
    let mut scenario = Scenario::load_with(&a.file, &[armdyn::sweep::TABLE])?;
    if let Some(m) = &a.controller_model {
        scenario.controller_model = crate::run_cmd::controller_model(&scenario, m)?;
    }
    let spec = SweepSpec::of(&scenario)?.with_context(|| {
        format!(
            "{}: has no [sweep] table; nothing to vary (see scenarios/README.md)",
            a.file.display()
        )
    })?;
    if a.samples == 0 {
        anyhow::bail!("--samples must be at least 1");
    }
    if a.threads == Some(0) {
        anyhow::bail!("--threads must be at least 1");
    }
    // The nominal scenario must set up; a draw that breaks a rule is a failed trial.
    armdyn::scenario::prepare(&scenario)
        .with_context(|| format!("{}: nothing was run", a.file.display()))?;
    let bar = ProgressBar::new(a.samples as u64);
    if std::io::stderr().is_terminal() {
        bar.set_style(
            ProgressStyle::with_template(
                "{msg} [{bar:40}] {pos}/{len} trials, {elapsed_precise} elapsed, ETA {eta}",
            )
            .map_err(|e| anyhow::anyhow!("{e}"))?
            .progress_chars("=> "),
        );
        bar.set_message(scenario.name.clone());
    } else {
        bar.set_draw_target(ProgressDrawTarget::hidden());
    }
    let run = run_sweep(
        &scenario,
        &spec,
        a.samples,
        a.seed,
        a.threads.unwrap_or(0),
        &|| bar.inc(1),
    )?;
    bar.finish_and_clear();
    let dir = a
        .out
        .clone()
        .unwrap_or_else(|| PathBuf::from(format!("out/sweep-{}", scenario.name)));
    let files = write_sweep(&dir, &scenario, &spec, &run, a.seed)?;
    outln!(
        "{}: {} trials in {:.2} s on {} thread{}: {:.2} trials/s, {:.1} ms per trial and thread",
        scenario.name,
        run.results.len(),
        run.elapsed_s,
        run.threads,
        if run.threads == 1 { "" } else { "s" },
        run.trials_per_s(),
        1e3 * run.elapsed_s * run.threads as f64 / run.results.len() as f64
    );
    print_summary(&run);
    outln!("wrote {}/: {}", dir.display(), files.join(", "));
    Ok(())
}

fn print_summary(run: &armdyn::sweep::SweepRun) {
    let mut t = Table::new(["metric", "trials", "p5", "p50", "p95", "max"]);
    for m in armdyn::sweep::output::summarise(run) {
        let Some((p5, p50, p95, max)) = m.spread else {
            continue;
        };
        t.push_row([
            m.name.to_string(),
            m.count.to_string(),
            format!("{p5:.4}"),
            format!("{p50:.4}"),
            format!("{p95:.4}"),
            format!("{max:.4}"),
        ]);
    }
    outln!("\n{}", t.markdown());
    let failures = armdyn::sweep::output::failures(run);
    let reasons: Vec<String> = failures
        .by_reason
        .iter()
        .map(|(f, trials)| format!("{}: {}", f.name(), trials.len()))
        .collect();
    outln!(
        "failed trials: {} of {} ({})",
        failures.failed,
        run.results.len(),
        reasons.join(", ")
    );
}
