//! Prints a Markdown table of the `rust_vs_c` benchmark: for each function of `scara` and
//! `puma560` (numeric, then parametric), its operation count (from `OPERATION_COUNTS`; the C
//! is generated from the same graph and has the same counts, checked by `tests/agree.rs`), the
//! median ns per call of the Rust and of CasADi's C, and the ratio C/Rust.
//!
//! Reads criterion's `<dir>/**/new/benchmark.json` and `estimates.json`, where `<dir>` is the
//! first argument, else `$CARGO_TARGET_DIR/criterion`, else the workspace's
//! `target/criterion`.
//!
//! ```text
//! cargo bench -p armdyn-casadi-c-bench --bench rust_vs_c
//! cargo run -p armdyn-casadi-c-bench --bin bench_table --release
//! ```

use std::collections::HashMap;
use std::error::Error;
use std::fs;
use std::path::{Path, PathBuf};

use serde_json::Value;

type Counts = &'static [(&'static str, u32, u32)];

/// `(robot, prefix of the function in the benchmark ids, operation counts)`.
const MODELS: &[(&str, &str, Counts)] = &[
    ("scara", "", &armdyn_generated::scara::OPERATION_COUNTS),
    (
        "scara",
        "parametric/",
        &armdyn_generated::scara::parametric::OPERATION_COUNTS,
    ),
    ("puma560", "", &armdyn_generated::puma560::OPERATION_COUNTS),
    (
        "puma560",
        "parametric/",
        &armdyn_generated::puma560::parametric::OPERATION_COUNTS,
    ),
];

/// Collects `full_id -> median ns` from every `new/` directory under `dir`.
fn collect(dir: &Path, found: &mut HashMap<String, f64>) -> Result<(), Box<dyn Error>> {
    for entry in fs::read_dir(dir)? {
        let path = entry?.path();
        if !path.is_dir() {
            continue;
        }
        if path.file_name().is_some_and(|n| n == "new") {
            let bench = path.join("benchmark.json");
            let estimates = path.join("estimates.json");
            if bench.is_file() && estimates.is_file() {
                let bench: Value = serde_json::from_str(&fs::read_to_string(&bench)?)?;
                let estimates: Value = serde_json::from_str(&fs::read_to_string(&estimates)?)?;
                let id = bench["full_id"]
                    .as_str()
                    .ok_or("benchmark.json without full_id")?;
                let ns = estimates["median"]["point_estimate"]
                    .as_f64()
                    .ok_or("estimates.json without median.point_estimate")?;
                found.insert(id.to_owned(), ns);
            }
        } else {
            collect(&path, found)?;
        }
    }
    Ok(())
}

fn ns(x: Option<f64>) -> String {
    x.map_or_else(|| "–".to_owned(), |x| format!("{x:.1}"))
}

fn main() -> Result<(), Box<dyn Error>> {
    let dir = std::env::args_os()
        .nth(1)
        .map(PathBuf::from)
        .unwrap_or_else(|| {
            std::env::var_os("CARGO_TARGET_DIR").map_or_else(
                || Path::new(env!("CARGO_MANIFEST_DIR")).join("../../target/criterion"),
                |t| PathBuf::from(t).join("criterion"),
            )
        });
    let mut found = HashMap::new();
    collect(&dir, &mut found).map_err(|e| format!("reading {}: {e}", dir.display()))?;

    println!("Median ns per call (criterion, `rust_vs_c`); flops+trig from `OPERATION_COUNTS`.");
    println!();
    println!("| robot | function | flops+trig | Rust ns | CasADi C ns | C/Rust |");
    println!("|---|---|---:|---:|---:|---:|");
    let mut missing = 0;
    for &(robot, prefix, counts) in MODELS {
        for &(function, flops, trig) in counts {
            let rust = found
                .get(&format!("{robot}/{prefix}{function}/rust"))
                .copied();
            let c = found
                .get(&format!("{robot}/{prefix}{function}/casadi_c"))
                .copied();
            missing += usize::from(rust.is_none()) + usize::from(c.is_none());
            let ratio = match (rust, c) {
                (Some(r), Some(c)) => format!("{:.2}", c / r),
                _ => "–".to_owned(),
            };
            println!(
                "| {robot} | {prefix}{function} | {flops}+{trig} | {} | {} | {ratio} |",
                ns(rust),
                ns(c)
            );
        }
    }
    if missing > 0 {
        eprintln!(
            "{missing} measurements missing under {}: run \
             `cargo bench -p armdyn-casadi-c-bench --bench rust_vs_c` first",
            dir.display()
        );
    }
    Ok(())
}
