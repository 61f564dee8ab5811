//! The optional `f32` module of an expansion (`robot_model!(path, f32)`) mirrors the `f64`
//! functions instruction for instruction.

use crate::expand::expand_str;
use proc_macro2::Span;
use quote::quote;

const TINY: &str = include_str!("../tests/ui/pass_tiny.json");
const LONG: &str = include_str!("../tests/ui/pass_long.json");

/// With `f32`, a submodule `f32` holds the same functions over `f32`: same names,
/// statements and operands, `f32` types and literals, `libm`'s `f32` functions, and no
/// `f64` anywhere; without, there is no such module.
#[test]
fn f32_module_mirrors_the_f64_functions() {
    for json in [TINY, LONG] {
        let without =
            expand_str(json, Span::call_site(), crate::emit::Variants::NONE).expect("valid");
        assert!(!without.to_string().contains("mod f32"));
        let tokens =
            expand_str(json, Span::call_site(), crate::emit::Variants::SINGLE).expect("valid");
        let file: syn::File = syn::parse2(tokens).expect("a Rust file");
        let double: Vec<&syn::ItemFn> = file
            .items
            .iter()
            .filter_map(|item| match item {
                syn::Item::Fn(f) => Some(f),
                _ => None,
            })
            .collect();
        let single = file
            .items
            .iter()
            .find_map(|item| match item {
                syn::Item::Mod(m) if m.ident == "f32" => m.content.as_ref(),
                _ => None,
            })
            .expect("a module f32");
        let single: Vec<&syn::ItemFn> = single
            .1
            .iter()
            .filter_map(|item| match item {
                syn::Item::Fn(f) => Some(f),
                _ => None,
            })
            .collect();
        assert_eq!(double.len(), single.len());
        for (d, s) in double.iter().zip(&single) {
            assert_eq!(d.sig.ident, s.sig.ident);
            let text = quote!(#s).to_string();
            assert!(!text.contains("f64"), "{}", s.sig.ident);
            let expected = quote!(#d)
                .to_string()
                .replace("f64", "f32")
                .replace(
                    ":: armdyn_runtime :: libm :: sincos (",
                    ":: armdyn_runtime :: libm :: sincosf (",
                )
                .replace(
                    ":: armdyn_runtime :: libm :: sin (",
                    ":: armdyn_runtime :: libm :: sinf (",
                )
                .replace(
                    ":: armdyn_runtime :: libm :: cos (",
                    ":: armdyn_runtime :: libm :: cosf (",
                )
                .replace(
                    ":: armdyn_runtime :: libm :: sqrt (",
                    ":: armdyn_runtime :: libm :: sqrtf (",
                )
                .replace(
                    ":: armdyn_runtime :: libm :: fabs (",
                    ":: armdyn_runtime :: libm :: fabsf (",
                )
                .replace(
                    ":: armdyn_runtime :: libm :: atan2 (",
                    ":: armdyn_runtime :: libm :: atan2f (",
                )
                .replace("1e-3_f32", "0.001_f32");
            // Every constant of the fixtures is exact in f32, so the texts agree fully
            // (but for 1e-3, which f32 writes in its own shortest form).
            assert_eq!(text, expected, "{}", s.sig.ident);
        }
    }
}
