//! The kinematic and torque limits as one period's checks compare them: [`PeriodBounds`].
//!
//! A limit that is not checked becomes an infinity (a joint margin `-inf`, a speed `+inf`, a
//! workspace wall at `-inf`/`+inf`) and a torque rate becomes the largest step in one period
//! (`rate dt`), so the per-period pass over the joints is the same comparisons whatever is
//! configured, with no branch on the configuration. Computed once per period length.

use super::limits::SafetyLimits;
use nalgebra::{RealField, SVector, Vector3};

/// [`SafetyLimits`]' joint, tool and torque-rate limits for a period `dt`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PeriodBounds<T: RealField + Copy, const N: usize> {
    /// The period they are for, s.
    pub dt: T,
    /// Per joint, the closest approach to a limit before a trip, rad or m (`-inf`: unchecked).
    pub joint_margin: SVector<T, N>,
    /// Per joint, the largest speed, rad/s or m/s (`+inf`: unchecked).
    pub joint_speed: SVector<T, N>,
    /// The largest squared tool speed, m^2/s^2 (`+inf`: unchecked).
    pub tool_speed2: T,
    /// The workspace box's lower corner, m (`-inf`: no box).
    pub workspace_lo: Vector3<T>,
    /// Its upper corner, m (`+inf`: no box).
    pub workspace_hi: Vector3<T>,
    /// Per joint, the largest step of the applied torque in one period, `rate dt`, N m or N
    /// (`+inf`: not limited).
    pub torque_step: SVector<T, N>,
}

impl<T: RealField + Copy, const N: usize> PeriodBounds<T, N> {
    /// The bounds of `limits` at the period `dt` (s).
    #[must_use]
    pub fn new(limits: &SafetyLimits<T, N>, dt: T) -> Self {
        let inf = T::one() / T::zero();
        let (workspace_lo, workspace_hi) = limits
            .workspace
            .unwrap_or((Vector3::repeat(-inf), Vector3::repeat(inf)));
        Self {
            dt,
            joint_margin: limits.joint_margin.unwrap_or(SVector::repeat(-inf)),
            joint_speed: limits.max_joint_speed.unwrap_or(SVector::repeat(inf)),
            tool_speed2: limits.max_tool_speed_m_s.map_or(inf, |m| m * m),
            workspace_lo,
            workspace_hi,
            torque_step: limits
                .max_torque_rate
                .map_or(SVector::repeat(inf), |rate| rate * dt),
        }
    }
}

/// The larger of `a` and `b` (`a` if they are unordered): one `max` instruction, where
/// `f64::max` also orders NaN.
#[inline(always)]
pub(crate) fn larger<T: RealField + Copy>(a: T, b: T) -> T {
    if b > a {
        b
    } else {
        a
    }
}

/// Whether `x` is finite: `x - x` is zero for a finite `x` and NaN for an infinite or NaN
/// one (a subtraction and a comparison, in the vector unit, where `is_finite` masks bits).
#[inline(always)]
#[allow(clippy::eq_op)]
pub(crate) fn finite<T: RealField + Copy>(x: T) -> bool {
    x - x == T::zero()
}

/// The smaller of `a` and `b` (`a` if they are unordered).
#[inline(always)]
pub(crate) fn smaller<T: RealField + Copy>(a: T, b: T) -> T {
    if b < a {
        b
    } else {
        a
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unchecked_limits_are_infinities_and_the_rate_a_step_per_period() {
        let mut l = SafetyLimits::<f64, 2>::unit_joints(10.0, Some(50.0));
        let b = PeriodBounds::new(&l, 1e-3);
        assert_eq!(b.joint_speed, SVector::<f64, 2>::repeat(f64::INFINITY));
        assert_eq!(b.torque_step, SVector::<f64, 2>::repeat(f64::INFINITY));
        assert_eq!(b.tool_speed2, f64::INFINITY);
        assert_eq!(b.workspace_lo, Vector3::repeat(f64::NEG_INFINITY));
        assert_eq!(b.joint_margin, SVector::<f64, 2>::repeat(-1e-3));
        l.max_torque_rate = Some(nalgebra::Vector2::new(1000.0, 2000.0));
        l.max_tool_speed_m_s = Some(0.5);
        l.joint_margin = None;
        let b = PeriodBounds::new(&l, 1e-3);
        assert_eq!(b.torque_step, nalgebra::Vector2::new(1.0, 2.0));
        assert_eq!(b.tool_speed2, 0.25);
        assert_eq!(b.joint_margin, SVector::<f64, 2>::repeat(f64::NEG_INFINITY));
        let b32 = PeriodBounds::<f32, 2>::new(&l.cast(), 1e-3);
        assert_eq!(b32.joint_margin[0], f32::NEG_INFINITY);
        assert_eq!(larger(1.0, f64::NAN), 1.0);
        assert_eq!(smaller(1.0, f64::NAN), 1.0);
        assert_eq!((larger(1.0, 2.0), smaller(1.0, 2.0)), (2.0, 1.0));
    }
}
