//! `robot_model!`: turns a robot model graph (JSON, format `scara-model-graph/1`, see
//! `derive/FORMAT.md`) into `no_std` Rust functions over fixed-size arrays.
//!
//! ```ignore
//! pub mod scara {
//!     scara_derive::robot_model!("models/scara.json");
//! }
//!
//! let m: [[f64; 4]; 4] = scara::mass_matrix(&[0.1, 0.2, 0.0, 0.3]);
//! assert_eq!(scara::DOF, 4);
//! ```
//!
//! # What the macro emits
//!
//! Into the module where it is called:
//!
//! - constants `ROBOT_NAME`, `DESCRIPTION`, `DOF`, `GENERATOR`, `CASADI_VERSION`, `SOURCE`,
//!   `SOURCE_SHA256`, `JOINT_NAMES`, `JOINT_IS_PRISMATIC`, `JOINT_LIMITS` (`[lower, upper]`),
//!   `EFFORT_LIMITS`, `GRAVITY` and `OPERATION_COUNTS` (`(function, flops, trig)`, file order);
//! - per function of the file, `#[inline] pub fn name(input: &[f64; len], ...) -> [[f64; c]; r]`
//!   (the output shape nested row-major), with one `let vI: f64 = ...;` per instruction and
//!   `::libm` for `sqrt`, `sin`, `cos`, `fabs` and `atan2`. A body of more than 200
//!   instructions is cut into blocks of at most 200 `let`s, each
//!   `let (vA, vB, ...) = { let vI: f64 = ...; ...; (vA, vB, ...) };` handing on the values
//!   read after it: every `let` opens a scope nested in the previous one, and rustc's debug
//!   info emission overflows its stack on a few thousand nested scopes. No heap, no `unsafe`,
//!   no panics: every index is checked at expansion time. The calling crate must depend on
//!   `libm`.
//! - `const _: &str = include_str!(...)` on the model file, so that cargo rebuilds the calling
//!   crate when the file changes.
//!
//! # Path resolution
//!
//! The argument is a string literal. A relative path is resolved against the calling crate's
//! `CARGO_MANIFEST_DIR` (as `include_str!` would be against the source file); an absolute path
//! is used as is. If the environment variable `SCARA_DERIVE_MANIFEST_DIR` is set it replaces
//! `CARGO_MANIFEST_DIR` as the base: the UI tests set it to the `derive/` directory, because
//! trybuild compiles each case in a crate of its own under `target/tests/trybuild/`. Nothing
//! else should set it.
//!
//! # Errors
//!
//! Any problem with the file is a compile error spanned on the path literal, never a panic:
//! an unreadable file, malformed JSON (with serde's line and column), a wrong type, a missing
//! or unknown key (with its JSON path), and every rule of `FORMAT.md` (unknown operation,
//! operand that does not refer to an earlier instruction, input number or element out of
//! range, result length that does not match the output shape, `counts` that do not match the
//! instructions, a constant that is not finite or does not round-trip, duplicate or non-identifier
//! names, and so on). All rule violations are reported at once, each naming the function and
//! instruction concerned.
//!
//! # Layout
//!
//! One module per phase, as in `thiserror-impl`: `parse` (serde structs, file reading),
//! `validate` (the rules, decoding instructions), `expand` (`quote`).

#![forbid(unsafe_code)]

extern crate proc_macro;

mod expand;
mod parse;
#[cfg(test)]
mod snapshot_test;
mod validate;

use proc_macro::TokenStream;
use syn::{parse_macro_input, LitStr};

/// Expands a model file into constants and functions; see the [crate docs](crate).
///
/// ```ignore
/// scara_derive::robot_model!("models/scara.json");
/// ```
#[proc_macro]
pub fn robot_model(input: TokenStream) -> TokenStream {
    let path = parse_macro_input!(input as LitStr);
    expand::expand_file(&path)
        .unwrap_or_else(syn::Error::into_compile_error)
        .into()
}
