//! The sin/cos fusion pass: a `sin` and a `cos` of the same operand become one
//! `::libm::sincos` call (`sincosf` for `f32`), which returns the same bits as the two calls.

use crate::instruction::{Op, Unary};
use crate::names::local;
use crate::scalar::Scalar;
use proc_macro2::TokenStream;
use quote::quote;

/// Fuses each `sin` and `cos` of the same operand into one `::armdyn_runtime::libm::sincos` call (`sincosf`
/// for `f32`): the earlier of the two `let`s becomes
/// `let (vS, vC): (f64, f64) = ::libm::sincos(vX);` and the later one
/// is emitted as nothing. (libm's `sincos` is the same argument reduction and kernels as its
/// `sin` and `cos`, and returns bit-identical values; `tests::sincos_is_sin_and_cos` checks
/// it.) Returns `home`: `home[i]` is the instruction whose statement defines value `i` (`i`
/// itself, but the earlier partner for the later of a pair), for [`crate::chunk::chunked`].
pub(crate) fn sincos_pairs(program: &[Op], lets: &mut [TokenStream], scalar: Scalar) -> Vec<usize> {
    let ty = scalar.ty();
    let mut home: Vec<usize> = (0..program.len()).collect();
    // operand -> (first sin, first cos); CasADi's instruction lists compute each at most once.
    let mut trig: std::collections::BTreeMap<usize, (Option<usize>, Option<usize>)> =
        std::collections::BTreeMap::new();
    for (i, op) in program.iter().enumerate() {
        match *op {
            Op::Unary(Unary::Sin, x) => {
                trig.entry(x).or_default().0.get_or_insert(i);
            }
            Op::Unary(Unary::Cos, x) => {
                trig.entry(x).or_default().1.get_or_insert(i);
            }
            _ => {}
        }
    }
    for (x, pair) in trig {
        let (Some(s), Some(c)) = pair else { continue };
        let (first, second) = (s.min(c), s.max(c));
        let (vs, vc, vx) = (local(s), local(c), local(x));
        let sincos = scalar.call("sincos", &[vx]);
        lets[first] = quote!(let (#vs, #vc): (#ty, #ty) = #sincos;);
        lets[second] = TokenStream::new();
        home[second] = first;
    }
    home
}

#[cfg(test)]
mod tests {
    use crate::expand::expand_str;
    use proc_macro2::Span;

    const TINY: &str = include_str!("../tests/ui/pass_tiny.json");
    const LONG: &str = include_str!("../tests/ui/pass_long.json");

    /// A sin and a cos of one operand are one `::armdyn_runtime::libm::sincos` call, at the first of the two.
    #[test]
    fn sin_and_cos_of_one_operand_are_one_sincos() {
        let text = expand_str(TINY, Span::call_site(), crate::emit::Variants::SINGLE)
            .expect("valid")
            .to_string();
        let fused = "let (v3 , v2) : (f64 , f64) = :: armdyn_runtime :: libm :: sincos (v0) ;";
        assert!(text.contains(fused), "{text}");
        let fused = "let (v3 , v2) : (f32 , f32) = :: armdyn_runtime :: libm :: sincosf (v0) ;";
        assert!(text.contains(fused), "{text}");
        assert!(
            !text.contains(":: armdyn_runtime :: libm :: sinf (")
                && !text.contains(":: armdyn_runtime :: libm :: cosf (")
        );
        assert!(
            !text.contains(":: armdyn_runtime :: libm :: sin (")
                && !text.contains(":: armdyn_runtime :: libm :: cos (")
        );
        // The long fixture has sines without a cosine of the same operand: they stay `sin`.
        let text = expand_str(LONG, Span::call_site(), crate::emit::Variants::NONE)
            .expect("valid")
            .to_string();
        assert!(
            text.contains(":: armdyn_runtime :: libm :: sin (")
                && !text.contains(":: armdyn_runtime :: libm :: sincos (")
        );
    }

    /// libm's `sincos` is bit for bit its `sin` and `cos` (the same argument reduction and
    /// kernels; only the tiny-argument shortcut differs in its threshold, where both round to
    /// `x` and 1), so the fusion changes no result: over the ranges of joint angles, the
    /// thresholds, large arguments and special values.
    #[test]
    fn sincos_is_sin_and_cos() {
        let mut state = 0x9e37_79b9_7f4a_7c15_u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
        let check = |x: f64| {
            let (s, c) = libm::sincos(x);
            assert_eq!(s.to_bits(), libm::sin(x).to_bits(), "sin {x:e}");
            assert_eq!(c.to_bits(), libm::cos(x).to_bits(), "cos {x:e}");
        };
        for x in [
            0.0,
            -0.0,
            f64::MIN_POSITIVE,
            5e-324,
            1e300,
            -1e300,
            f64::MAX,
        ] {
            check(x);
        }
        let (inf, nan) = (libm::sincos(f64::INFINITY), libm::sincos(f64::NAN));
        assert!(inf.0.is_nan() && inf.1.is_nan() && nan.0.is_nan() && nan.1.is_nan());
        for _ in 0..1_000_000 {
            let r = next();
            let unit = (r >> 11) as f64 / (1u64 << 53) as f64;
            check((unit - 0.5) * 20.0); // joint angles, with offsets
            check(f64::from_bits(next() & !(1 << 63)) * if r & 1 == 0 { 1.0 } else { -1.0 });
            // |x| around 2^-27 sqrt(2) .. 2^-26, where sin's and sincos's shortcuts differ
            check((1.0 + unit) * 2e-8 * if r & 2 == 0 { 1.0 } else { -1.0 });
        }
    }

    /// The same for `f32` (`sincosf` against `sinf` and `cosf`, emitted in the `f32` modules):
    /// four million arguments spread over [-16, 16] (where joint angles are), every `f32` in
    /// [1e-5, 1e-3] (the small-argument shortcuts), and a million random bit patterns.
    #[test]
    fn sincosf_is_sinf_and_cosf() {
        let check = |x: f32| {
            let (s, c) = libm::sincosf(x);
            assert_eq!(s.to_bits(), libm::sinf(x).to_bits(), "sinf {x:e}");
            assert_eq!(c.to_bits(), libm::cosf(x).to_bits(), "cosf {x:e}");
        };
        for i in 0..4_000_000u32 {
            check(-16.0 + 32.0 * (i as f32) / 4.0e6);
        }
        let mut x = 1e-5f32;
        while x <= 1e-3 {
            check(x);
            check(-x);
            x = x.next_up();
        }
        let mut state = 0x2545_f491_u32;
        for _ in 0..1_000_000 {
            state ^= state << 13;
            state ^= state >> 17;
            state ^= state << 5;
            let v = f32::from_bits(state);
            if v.is_finite() {
                check(v);
            }
        }
    }
}
