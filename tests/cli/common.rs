//! What every command-line test needs: running the binary, a fresh folder, the output as text.

use std::path::Path;

use crate::scratch::Scratch;
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

/// An empty folder of its own for the test `name` of the file `area`, removed when the test
/// passes ([`Scratch`]).
pub fn tmp(area: &str, name: &str) -> Scratch {
    Scratch::new(&format!("cli-{area}-{name}"))
}

/// A path as `&str`, for an argument.
pub fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// The standard error as text.
pub fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}
