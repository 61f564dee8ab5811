//! The scalar of a deployable controller: `f64` (the host's, the reference) or `f32` (a
//! Cortex-M4F's FPU), with the SCARA's generated functions in that precision.

use armdyn_generated::scara as generated;
use nalgebra::RealField;

/// A floating-point type the deployable controllers run on, supplying the SCARA's generated
/// functions the hybrid step calls in its own precision (`armdyn_generated::scara` for `f64`,
/// `armdyn_generated::scara::f32` for `f32`).
///
/// ```
/// use armdyn::robots::scara::deploy::ScaraScalar;
/// let (q, qd) = ([0.3, 0.8, 0.2, 0.1], [0.2, -0.1, 0.05, 0.3]);
/// let single = <f32 as ScaraScalar>::mass_matrix_and_bias(&q.map(|x| x as f32), &qd.map(|x| x as f32));
/// let double = <f64 as ScaraScalar>::mass_matrix_and_bias(&q, &qd);
/// assert!((f64::from(single[2][4]) - double[2][4]).abs() < 1e-5 * double[2][4].abs());
/// ```
pub trait ScaraScalar: RealField + Copy {
    /// Bits of the type: 32 or 64.
    const BITS: u32;
    /// The nearest value to `x` (rounding to nearest for `f32`).
    fn round_from(x: f64) -> Self;
    /// The value as `f64` (exact).
    fn widen(self) -> f64;
    /// Geometric Jacobian and tool position in one call: `[J | p]` on rows 0 to 2 (p in m),
    /// `[J | 0]` on rows 3 to 5.
    fn jacobian_and_position(q: &[Self; 4]) -> [[Self; 5]; 6];
    /// `[M(q) | c(q, qd) + g(q)]` in one call: kg m^2, kg m, kg, then N m or N.
    fn mass_matrix_and_bias(q: &[Self; 4], qd: &[Self; 4]) -> [[Self; 5]; 4];
}

impl ScaraScalar for f64 {
    const BITS: u32 = 64;

    #[inline]
    fn round_from(x: f64) -> Self {
        x
    }

    #[inline]
    fn widen(self) -> f64 {
        self
    }

    #[inline]
    fn jacobian_and_position(q: &[Self; 4]) -> [[Self; 5]; 6] {
        generated::jacobian_and_position(q)
    }

    #[inline]
    fn mass_matrix_and_bias(q: &[Self; 4], qd: &[Self; 4]) -> [[Self; 5]; 4] {
        generated::mass_matrix_and_bias(q, qd)
    }
}

impl ScaraScalar for f32 {
    const BITS: u32 = 32;

    #[inline]
    #[allow(clippy::cast_possible_truncation)]
    fn round_from(x: f64) -> Self {
        x as f32
    }

    #[inline]
    fn widen(self) -> f64 {
        f64::from(self)
    }

    #[inline]
    fn jacobian_and_position(q: &[Self; 4]) -> [[Self; 5]; 6] {
        generated::f32::jacobian_and_position(q)
    }

    #[inline]
    fn mass_matrix_and_bias(q: &[Self; 4], qd: &[Self; 4]) -> [[Self; 5]; 4] {
        generated::f32::mass_matrix_and_bias(q, qd)
    }
}
