//! Square roots that compile to the hardware instruction wherever there is one.
//!
//! With `std`, `f64::sqrt` is an LLVM intrinsic: `sqrtsd`, or `vsqrtsd` in a build with AVX
//! enabled (`-C target-cpu=native`). `libm::sqrt` is inline assembly on x86 that always emits
//! the legacy-SSE `sqrtsd`, which stalls when mixed with the AVX code of such a build; it is
//! used only without `std` (a Cortex-M4F has no double-precision square root, so there it is
//! the software routine either way). Both are correctly rounded, so results are identical.

/// `sqrt(x)`, correctly rounded (IEEE 754).
#[inline(always)]
#[must_use]
pub(crate) fn sqrt(x: f64) -> f64 {
    #[cfg(feature = "std")]
    {
        x.sqrt()
    }
    #[cfg(not(feature = "std"))]
    {
        libm::sqrt(x)
    }
}

/// `sqrt(x^2 + y^2)` without undue overflow or underflow.
#[inline(always)]
#[must_use]
pub(crate) fn hypot(x: f64, y: f64) -> f64 {
    #[cfg(feature = "std")]
    {
        x.hypot(y)
    }
    #[cfg(not(feature = "std"))]
    {
        libm::hypot(x, y)
    }
}
