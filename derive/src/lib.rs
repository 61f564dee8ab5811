//! `robot_model!`: turns a robot model graph (JSON, format `armdyn-model-graph/1`, see
//! `derive/FORMAT.md`) into `no_std` Rust functions over fixed-size arrays.
//!
//! ```ignore
//! pub mod scara {
//!     armdyn_runtime::robot_model!("models/scara.json", f32);
//! }
//!
//! let m: [[f64; 4]; 4] = scara::mass_matrix(&[0.1, 0.2, 0.0, 0.3]);
//! let m32: [[f32; 4]; 4] = scara::f32::mass_matrix(&[0.1, 0.2, 0.0, 0.3]);
//! assert_eq!(scara::DOF, 4);
//! ```
//!
//! # What the macro emits
//!
//! Into the module where it is called:
//!
//! - constants `ROBOT_NAME`, `DESCRIPTION`, `DOF`, `GENERATOR`, `CASADI_VERSION`, `SOURCE`,
//!   `SOURCE_SHA256`, `JOINT_NAMES`, `JOINT_IS_PRISMATIC`, `JOINT_LIMITS` (`[lower, upper]`),
//!   `EFFORT_LIMITS`, `GRAVITY`, `TASK_ROWS` (where the graph names a task) and
//!   `OPERATION_COUNTS` (`(function, flops, trig)`, file order);
//! - per function of the file, `#[inline] pub fn name(input: &[f64; len], ...) -> [[f64; c]; r]`
//!   (the output shape nested row-major), with one `let vI: f64 = ...;` per instruction and
//!   `::armdyn_runtime::libm` for `sqrt`, `sin`, `cos`, `fabs` and `atan2`. A body of more than 200
//!   instructions is cut into blocks of at most 200 `let`s, each
//!   `let (vA, vB, ...) = { let vI: f64 = ...; ...; (vA, vB, ...) };` handing on the values
//!   read after it: every `let` opens a scope nested in the previous one, and rustc's debug
//!   info emission overflows its stack on a few thousand nested scopes. No heap, no `unsafe`,
//!   no panics: every index is checked at expansion time. The calling crate must depend on
//!   `armdyn-runtime` (under that name), which re-exports this macro, `libm` and `wide`.
//! - with the optional second argument `f32` (`robot_model!("models/scara.json", f32)`), a
//!   submodule `f32` holding every function again over `f32`: `&[f32; len]` inputs, `f32`
//!   outputs and locals, each constant the model's `f64` rounded to the nearest `f32` (written
//!   as the shortest literal that reads back as it; a constant beyond `f32::MAX` is a compile
//!   error), `2.0_f32`/`1.0_f32` for `twice`/`inv`, and `::armdyn_runtime::libm::sinf`, `cosf`, `sqrtf`,
//!   `fabsf`, `atan2f`. Same instructions in the same order, so the same operation counts; the
//!   constants stay in the parent module (they are `f64`). For FPUs without double precision
//!   (Cortex-M4F), where every `f64` operation is a software routine. The `generated` crate
//!   asks for it on every robot's main model, not on the parametric models (identification
//!   and model-mismatch studies, which run on the host in `f64`).
//! - with the optional argument `lanes` (`robot_model!("models/scara.json", f32, lanes)`, the
//!   variants in either order), a submodule `lanes` holding every function again, generic over
//!   the lane type: `pub fn name<L: ::armdyn_runtime::lanes::Lane>(input: &[L; len], ...) ->
//!   [[L; c]; r]`, each constant `L::splat(c_f64)`, and `L::sqrt`, `L::sin`, `L::cos`,
//!   `L::sincos`, `L::fabs`, `L::atan2` for the calls (`armdyn-runtime` implements the trait
//!   for `f64` and `wide`'s `f64x2` and `f64x4`). Same instructions in the same order: several states per call, one per SIMD lane.
//! - `const _: &str = include_str!(...)` on the model file, so that cargo rebuilds the calling
//!   crate when the file changes.
//!
//! # Path resolution
//!
//! The first argument is a string literal. A relative path is resolved against the calling crate's
//! `CARGO_MANIFEST_DIR` (as `include_str!` would be against the source file); an absolute path
//! is used as is. If the environment variable `ARMDYN_DERIVE_MANIFEST_DIR` is set it replaces
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
//! `validate` (the rules) with `instruction` (the instruction set, decoding one instruction),
//! and `expand` (path resolution, running the phases, gathering the errors). The emission
//! with `quote` is split by concept: `emit` (the constants and functions), `sincos` (the
//! sin/cos fusion pass), `chunk` (cutting long bodies into blocks); `scalar` is what differs
//! between the `f64` and `f32` emissions (type, literals, `libm` names).

#![forbid(unsafe_code)]

extern crate proc_macro;

mod chunk;
mod emit;
mod expand;
#[cfg(test)]
mod f32_test;
mod instruction;
mod message;
mod names;
mod parse;
mod scalar;
mod sincos;
#[cfg(test)]
mod snapshot_test;
mod validate;

use proc_macro::TokenStream;
use syn::parse::{Parse, ParseStream};
use syn::{parse_macro_input, Ident, LitStr, Token};

/// The macro's arguments: the model path, then optionally `, f32` and `, lanes` (in either
/// order, each at most once).
struct Args {
    path: LitStr,
    variants: emit::Variants,
}

impl Parse for Args {
    fn parse(input: ParseStream<'_>) -> syn::Result<Self> {
        let path: LitStr = input.parse()?;
        let mut variants = emit::Variants::default();
        while input.parse::<Option<Token![,]>>()?.is_some() && !input.is_empty() {
            let variant: Ident = input.parse()?;
            let flag = match variant.to_string().as_str() {
                "f32" => &mut variants.single,
                "lanes" => &mut variants.lanes,
                _ => {
                    let message = format!(
                        "expected `f32` or `lanes` (the extra variants to emit), found `{variant}`"
                    );
                    return Err(syn::Error::new(variant.span(), message));
                }
            };
            if *flag {
                return Err(syn::Error::new(
                    variant.span(),
                    format!("`{variant}` is given twice"),
                ));
            }
            *flag = true;
        }
        if !input.is_empty() {
            return Err(
                input.error("expected `\"path\"`, `\"path\", f32` or `\"path\", f32, lanes`")
            );
        }
        Ok(Self { path, variants })
    }
}

/// Expands a model file into constants and functions, and with `, f32` a submodule `f32` of
/// the same functions in single precision; see the [crate docs](crate).
///
/// ```ignore
/// armdyn_derive::robot_model!("models/scara.json", f32);
/// ```
#[proc_macro]
pub fn robot_model(input: TokenStream) -> TokenStream {
    let args = parse_macro_input!(input as Args);
    expand::expand_file(&args.path, args.variants)
        .unwrap_or_else(syn::Error::into_compile_error)
        .into()
}
