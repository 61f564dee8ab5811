//! What every command-line test needs: running the binary and its output as text
//! (`tests/common/command.rs`), and a fresh folder.

pub use crate::command::{armdyn, armdyn_in, s, stderr};
use crate::scratch::Scratch;

/// An empty folder of its own for the test `name` of the file `area`, removed when the test
/// passes ([`Scratch`]).
pub fn tmp(area: &str, name: &str) -> Scratch {
    Scratch::new(&format!("cli-{area}-{name}"))
}
