//! Names of the locals in the emitted code.

use proc_macro2::Ident;
use quote::format_ident;

/// The local that holds the value of instruction `i`: `v{i}`.
pub(crate) fn local(i: usize) -> Ident {
    format_ident!("v{}", i)
}
