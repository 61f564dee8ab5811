//! The lane types of the generated `<robot>::lanes` functions: what one value of them must do.
//!
//! A lane type holds one `f64` per state and computes lane by lane. Implemented for
//! [`wide::f64x2`] (two states, one SSE2 register: the widest that stays in registers on the
//! x86-64 baseline), [`wide::f64x4`] (four states, one AVX register with `target-cpu` that has
//! AVX) and `f64` itself (one state, `libm`'s functions: bit for bit the scalar functions).
//! [`Batch`] names the widest that pays on the target being built.

use core::ops::{Add, Div, Mul, Neg, Sub};

use wide::{f64x2, f64x4};

/// One value of several states, computed lane by lane in IEEE `f64`.
pub trait Lane:
    Copy
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    /// States per value.
    const LANES: usize;
    /// `value` in every lane.
    fn splat(value: f64) -> Self;
    /// Square root.
    fn sqrt(x: Self) -> Self;
    /// Sine, rad.
    fn sin(x: Self) -> Self;
    /// Cosine, rad.
    fn cos(x: Self) -> Self;
    /// `(sin x, cos x)`, rad.
    fn sincos(x: Self) -> (Self, Self);
    /// Absolute value.
    fn fabs(x: Self) -> Self;
    /// `atan2(y, x)`, rad in `[-pi, pi]`.
    fn atan2(y: Self, x: Self) -> Self;
    /// Lane `k` (`k < LANES`).
    fn lane(self, k: usize) -> f64;
    /// A value whose lane `k` is `f(k)`.
    fn from_fn(f: impl FnMut(usize) -> f64) -> Self;
}

impl Lane for f64 {
    const LANES: usize = 1;
    #[inline(always)]
    fn splat(value: f64) -> Self {
        value
    }
    #[inline(always)]
    fn sqrt(x: Self) -> Self {
        libm::sqrt(x)
    }
    #[inline(always)]
    fn sin(x: Self) -> Self {
        libm::sin(x)
    }
    #[inline(always)]
    fn cos(x: Self) -> Self {
        libm::cos(x)
    }
    #[inline(always)]
    fn sincos(x: Self) -> (Self, Self) {
        libm::sincos(x)
    }
    #[inline(always)]
    fn fabs(x: Self) -> Self {
        libm::fabs(x)
    }
    #[inline(always)]
    fn atan2(y: Self, x: Self) -> Self {
        libm::atan2(y, x)
    }
    #[inline(always)]
    fn lane(self, _: usize) -> f64 {
        self
    }
    #[inline(always)]
    fn from_fn(mut f: impl FnMut(usize) -> f64) -> Self {
        f(0)
    }
}

macro_rules! wide_lane {
    ($ty:ident, $n:literal) => {
        impl Lane for $ty {
            const LANES: usize = $n;
            #[inline(always)]
            fn splat(value: f64) -> Self {
                $ty::splat(value)
            }
            #[inline(always)]
            fn sqrt(x: Self) -> Self {
                x.sqrt()
            }
            #[inline(always)]
            fn sin(x: Self) -> Self {
                x.sin()
            }
            #[inline(always)]
            fn cos(x: Self) -> Self {
                x.cos()
            }
            #[inline(always)]
            fn sincos(x: Self) -> (Self, Self) {
                x.sin_cos()
            }
            #[inline(always)]
            fn fabs(x: Self) -> Self {
                x.abs()
            }
            #[inline(always)]
            fn atan2(y: Self, x: Self) -> Self {
                y.atan2(x)
            }
            #[inline(always)]
            fn lane(self, k: usize) -> f64 {
                self.as_array()[k]
            }
            #[inline(always)]
            fn from_fn(f: impl FnMut(usize) -> f64) -> Self {
                $ty::new(core::array::from_fn(f))
            }
        }
    };
}

wide_lane!(f64x2, 2);
wide_lane!(f64x4, 4);

/// The lane type batches use on this target: [`wide::f64x4`] where AVX gives it one register,
/// [`wide::f64x2`] otherwise (on SSE2 an `f64x4` is two registers, and the long generated
/// bodies then spill: measured slower per state than the scalar call, see `benches/generated.rs`).
#[cfg(target_feature = "avx")]
pub type Batch = f64x4;
/// The lane type batches use on this target: [`wide::f64x4`] where AVX gives it one register,
/// [`wide::f64x2`] otherwise (on SSE2 an `f64x4` is two registers, and the long generated
/// bodies then spill: measured slower per state than the scalar call, see `benches/generated.rs`).
#[cfg(not(target_feature = "avx"))]
pub type Batch = f64x2;
