//! The scalar of a deployable controller: `f64` (the host's, the reference) or `f32` (a
//! Cortex-M4F's FPU), with the SCARA's generated functions in that precision.

use nalgebra::RealField;
use scara_generated::scara as generated;

/// A floating-point type the deployable controllers run on, supplying the SCARA's generated
/// kinematics and dynamics in its own precision (`scara_generated::scara` for `f64`,
/// `scara_generated::scara::f32` for `f32`).
///
/// ```
/// use scara::deploy::ScaraScalar;
/// let g32 = <f32 as ScaraScalar>::gravity(&[0.0, 0.0, 0.2, 0.0]);
/// let g64 = <f64 as ScaraScalar>::gravity(&[0.0, 0.0, 0.2, 0.0]);
/// assert!((f64::from(g32[2]) - g64[2]).abs() < 1e-5 * g64[2].abs());
/// ```
pub trait ScaraScalar: RealField + Copy {
    /// Bits of the type: 32 or 64.
    const BITS: u32;
    /// The smallest positive normal number.
    const MIN_POSITIVE: Self;
    /// The nearest value to `x` (rounding to nearest for `f32`).
    fn round_from(x: f64) -> Self;
    /// The value as `f64` (exact).
    fn widen(self) -> f64;
    /// Whether the value is neither infinite nor NaN.
    fn is_finite_value(self) -> bool;
    /// End-effector pose `T_0^4` (translation in m), row-major.
    fn end_effector_pose(q: &[Self; 4]) -> [[Self; 4]; 4];
    /// Geometric Jacobian, 6 x 4, base frame, row-major.
    fn jacobian(q: &[Self; 4]) -> [[Self; 4]; 6];
    /// Geometric Jacobian and tool position in one call: `[J | p]` on rows 0 to 2 (p in m),
    /// `[J | 0]` on rows 3 to 5.
    fn jacobian_and_position(q: &[Self; 4]) -> [[Self; 5]; 6];
    /// Mass matrix `M(q)`, kg m^2, kg m, kg.
    fn mass_matrix(q: &[Self; 4]) -> [[Self; 4]; 4];
    /// `[M(q) | c(q, qd) + g(q)]` in one call.
    fn mass_matrix_and_bias(q: &[Self; 4], qd: &[Self; 4]) -> [[Self; 5]; 4];
    /// Velocity term `c(q, qd) = C(q, qd) qd`, N m or N.
    fn coriolis(q: &[Self; 4], qd: &[Self; 4]) -> [Self; 4];
    /// Gravity term `g(q)`, N m or N.
    fn gravity(q: &[Self; 4]) -> [Self; 4];
}

impl ScaraScalar for f64 {
    const BITS: u32 = 64;
    const MIN_POSITIVE: Self = f64::MIN_POSITIVE;

    #[inline]
    fn round_from(x: f64) -> Self {
        x
    }

    #[inline]
    fn widen(self) -> f64 {
        self
    }

    #[inline]
    fn is_finite_value(self) -> bool {
        self.is_finite()
    }

    #[inline]
    fn end_effector_pose(q: &[Self; 4]) -> [[Self; 4]; 4] {
        generated::end_effector_pose(q)
    }

    #[inline]
    fn jacobian(q: &[Self; 4]) -> [[Self; 4]; 6] {
        generated::jacobian(q)
    }

    #[inline]
    fn jacobian_and_position(q: &[Self; 4]) -> [[Self; 5]; 6] {
        generated::jacobian_and_position(q)
    }

    #[inline]
    fn mass_matrix(q: &[Self; 4]) -> [[Self; 4]; 4] {
        generated::mass_matrix(q)
    }

    #[inline]
    fn mass_matrix_and_bias(q: &[Self; 4], qd: &[Self; 4]) -> [[Self; 5]; 4] {
        generated::mass_matrix_and_bias(q, qd)
    }

    #[inline]
    fn coriolis(q: &[Self; 4], qd: &[Self; 4]) -> [Self; 4] {
        generated::coriolis(q, qd)
    }

    #[inline]
    fn gravity(q: &[Self; 4]) -> [Self; 4] {
        generated::gravity(q)
    }
}

impl ScaraScalar for f32 {
    const BITS: u32 = 32;
    const MIN_POSITIVE: Self = f32::MIN_POSITIVE;

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
    fn is_finite_value(self) -> bool {
        self.is_finite()
    }

    #[inline]
    fn end_effector_pose(q: &[Self; 4]) -> [[Self; 4]; 4] {
        generated::f32::end_effector_pose(q)
    }

    #[inline]
    fn jacobian(q: &[Self; 4]) -> [[Self; 4]; 6] {
        generated::f32::jacobian(q)
    }

    #[inline]
    fn jacobian_and_position(q: &[Self; 4]) -> [[Self; 5]; 6] {
        generated::f32::jacobian_and_position(q)
    }

    #[inline]
    fn mass_matrix(q: &[Self; 4]) -> [[Self; 4]; 4] {
        generated::f32::mass_matrix(q)
    }

    #[inline]
    fn mass_matrix_and_bias(q: &[Self; 4], qd: &[Self; 4]) -> [[Self; 5]; 4] {
        generated::f32::mass_matrix_and_bias(q, qd)
    }

    #[inline]
    fn coriolis(q: &[Self; 4], qd: &[Self; 4]) -> [Self; 4] {
        generated::f32::coriolis(q, qd)
    }

    #[inline]
    fn gravity(q: &[Self; 4]) -> [Self; 4] {
        generated::f32::gravity(q)
    }
}
