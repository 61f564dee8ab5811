//! Running the `armdyn` binary from a test, and its output as text (the command-line tests and
//! the scenario tests that run a file through the command).

use std::path::Path;
use std::process::{Command, Output};

/// Runs `armdyn args` in the crate's folder.
pub fn armdyn(args: &[&str]) -> Output {
    armdyn_in(args, Path::new(env!("CARGO_MANIFEST_DIR")))
}

/// Runs `armdyn args` in `cwd`.
pub fn armdyn_in(args: &[&str], cwd: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_armdyn"))
        .args(args)
        .current_dir(cwd)
        .output()
        .expect("running the armdyn binary")
}

/// A path as `&str`, for an argument.
#[allow(dead_code)] // not every test crate passes paths
pub fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// The standard error as text.
pub fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}
