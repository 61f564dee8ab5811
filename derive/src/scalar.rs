//! The floating-point type of an emitted set of functions: the one place that knows how `f64`,
//! `f32` and a generic lane type `L: ::armdyn_runtime::lanes::Lane` differ in the expansion (type,
//! literal, the calls of `sqrt`, `sin`, `cos`, `fabs`, `atan2` and `sincos`, and how a model
//! constant is rounded).

use proc_macro2::{Ident, Literal, Span, TokenStream};
use quote::quote;

/// `f64` (the model's own precision), `f32` (single precision, for FPUs without `f64`) or a
/// generic lane type `L` (several `f64` states at once, one per SIMD lane).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Scalar {
    /// IEEE double: constants exactly as in the model file.
    F64,
    /// IEEE single: every constant is the model's `f64` rounded to the nearest `f32`.
    F32,
    /// `L: ::armdyn_runtime::lanes::Lane`: a vector of IEEE doubles (`wide::f64x2`, `f64x4`, or `f64`
    /// itself), each constant the model's `f64` in every lane (`L::splat`), the functions the
    /// trait's (`L::sin_cos`, `L::atan2`, ...).
    Lane,
}

impl Scalar {
    /// The type's name, `f64`, `f32` or `L`.
    pub(crate) fn name(self) -> &'static str {
        match self {
            Self::F64 => "f64",
            Self::F32 => "f32",
            Self::Lane => "L",
        }
    }

    /// The type as a token.
    pub(crate) fn ty(self) -> Ident {
        Ident::new(self.name(), Span::call_site())
    }

    /// `::armdyn_runtime::libm::<function>` for `f64` and `f32`: `sin` stays `sin` for `f64` and becomes
    /// `sinf` for `f32` (libm's C names). The lanes call the trait's functions instead
    /// ([`Self::call`]).
    pub(crate) fn libm(self, function: &str) -> TokenStream {
        let name = match self {
            Self::F64 | Self::Lane => Ident::new(function, Span::call_site()),
            Self::F32 => Ident::new(&format!("{function}f"), Span::call_site()),
        };
        quote!(::armdyn_runtime::libm::#name)
    }

    /// The call of `function` (`sqrt`, `sin`, `cos`, `fabs`, `atan2`, `sincos`) on `args`:
    /// `::armdyn_runtime::libm::function(args)` for `f64` and `f32`, the trait's function for the lanes
    /// (`L::sqrt(x)`, `L::sin(x)`, `L::cos(x)`, `L::fabs(x)`, `L::atan2(y, x)`,
    /// `L::sincos(x)`).
    pub(crate) fn call(self, function: &str, args: &[Ident]) -> TokenStream {
        if self == Self::Lane {
            let name = Ident::new(function, Span::call_site());
            return quote!(L::#name(#(#args),*));
        }
        let path = self.libm(function);
        quote!(#path(#(#args),*))
    }

    /// A literal with this type's suffix from a validated decimal text (a finite `f64` that
    /// round-trips); a leading `-` becomes a separate negation token. For `f32` the value is
    /// the `f64` rounded to the nearest `f32`, written in the shortest text that reads back as
    /// that `f32`; a value beyond `f32::MAX` is an error.
    pub(crate) fn literal(self, text: &str) -> Result<TokenStream, String> {
        let (negative, body) = match text.strip_prefix('-') {
            Some(body) => (true, body),
            None => (false, text),
        };
        let body = match self {
            Self::F64 | Self::Lane => body.to_owned(),
            Self::F32 => {
                let value: f64 = body
                    .parse()
                    .map_err(|_| format!("internal error: constant \"{text}\" is not a number"))?;
                // `as` rounds to nearest, ties to even.
                let single = value as f32;
                if !single.is_finite() {
                    return Err(format!(
                        "constant {text} does not fit in f32 (largest {:e})",
                        f32::MAX
                    ));
                }
                format!("{single:?}")
            }
        };
        let dot = if body.contains(['.', 'e', 'E']) {
            ""
        } else {
            ".0"
        };
        let suffix = if self == Self::Lane {
            "f64"
        } else {
            self.name()
        };
        let lit: Literal = format!("{body}{dot}_{suffix}").parse().map_err(|_| {
            format!("internal error: cannot write constant \"{text}\" as a literal")
        })?;
        let lit = if self == Self::Lane {
            quote!(L::splat(#lit))
        } else {
            quote!(#lit)
        };
        Ok(if negative {
            quote!(-#lit)
        } else {
            quote!(#lit)
        })
    }
}

#[cfg(test)]
mod tests {
    use super::Scalar;
    use proc_macro2::{Ident, Span};

    fn text(scalar: Scalar, s: &str) -> String {
        scalar
            .literal(s)
            .map(|t| t.to_string())
            .unwrap_or_else(|e| e)
    }

    #[test]
    fn literals_of_both_types() {
        assert_eq!(text(Scalar::F64, "2"), "2.0_f64");
        assert_eq!(text(Scalar::F64, "-1.5"), "- 1.5_f64");
        assert_eq!(text(Scalar::F32, "2"), "2.0_f32");
        assert_eq!(text(Scalar::F32, "-1.5"), "- 1.5_f32");
        // 0.1 as f64, rounded to f32, shortest text of that f32.
        assert_eq!(text(Scalar::F32, "0.1"), "0.1_f32");
        assert_eq!(text(Scalar::F32, "3.141592653589793"), "3.1415927_f32");
        assert_eq!(text(Scalar::F32, "1e-3"), "0.001_f32");
        assert_eq!(text(Scalar::F32, "6.02e+23"), "6.02e23_f32");
        assert!(Scalar::F32.literal("1e300").is_err());
        assert_eq!(
            Scalar::F32.libm("sin").to_string(),
            ":: armdyn_runtime :: libm :: sinf"
        );
        assert_eq!(
            Scalar::F64.libm("atan2").to_string(),
            ":: armdyn_runtime :: libm :: atan2"
        );
        assert_eq!(text(Scalar::Lane, "-1.5"), "- L :: splat (1.5_f64)");
        let (x, y) = (
            Ident::new("v1", Span::call_site()),
            Ident::new("v2", Span::call_site()),
        );
        assert_eq!(
            Scalar::Lane.call("fabs", &[x.clone()]).to_string(),
            "L :: fabs (v1)"
        );
        assert_eq!(
            Scalar::Lane.call("atan2", &[x.clone(), y]).to_string(),
            "L :: atan2 (v1 , v2)"
        );
        assert_eq!(
            Scalar::Lane.call("sincos", &[x.clone()]).to_string(),
            "L :: sincos (v1)"
        );
        assert_eq!(
            Scalar::F32.call("sqrt", &[x]).to_string(),
            ":: armdyn_runtime :: libm :: sqrtf (v1)"
        );
    }

    /// The `f32` literal reads back as the `f64` constant rounded to nearest.
    #[test]
    fn f32_literals_are_the_rounded_f64() {
        for text in [
            "2.33736",
            "0.07",
            "-9.81",
            "1.0000001192092896",
            "123456789.0",
        ] {
            let value: f64 = text.parse().unwrap();
            let lit = Scalar::F32.literal(text).unwrap().to_string();
            let digits = lit.replace(' ', "").replace("_f32", "");
            let back: f32 = digits.parse().unwrap();
            assert_eq!(back.to_bits(), (value as f32).to_bits(), "{text}");
        }
    }
}
