//! References: Cartesian paths of the end effector and force profiles (thesis Appendix B).
//!
//! - [`CartesianTrajectory`]: a reference of [`CartesianTarget`]s (full poses,
//!   [`crate::target`]) defined for `t` in `[0, duration]`.
//! - [`force`]: desired contact-force profiles (B.3).
//! - `sampled` (feature `std`): a user reference given as samples (CSV), interpolated.
//! - [`PoseSample`] and `sample` (feature `std`): a reference read at discrete times, as
//!   the workspace planner ([`crate::robots::scara::ScaraGeometry::plan_elbows`]) wants it.

pub mod force;
#[cfg(feature = "std")]
pub mod force_csv;
#[cfg(feature = "std")]
pub mod joint_csv;
#[cfg(feature = "std")]
pub mod pause;
#[cfg(feature = "std")]
pub mod pose_csv;
#[cfg(feature = "std")]
pub mod sampled;
#[cfg(feature = "std")]
pub mod waypoints;

pub use force::ForceProfile;
#[cfg(feature = "std")]
pub use joint_csv::JointReference;
#[cfg(feature = "std")]
pub use pose_csv::CsvError;
#[cfg(feature = "std")]
pub use sampled::{SampledError, SampledTrajectory};

use crate::target::CartesianTarget;
#[cfg(feature = "std")]
use crate::target::PoseSample;

/// A Cartesian end-effector reference over `[0, duration]` seconds.
///
/// # Example
///
/// ```
/// use armdyn::trajectory::CartesianTrajectory;
/// use armdyn::robots::scara::thesis::ThreeZone;
///
/// let reference = ThreeZone::new();
/// assert_eq!(reference.duration(), 10.0);
/// // Times past the end are clamped: the reference holds its final value.
/// assert_eq!(reference.at(12.0), reference.at(10.0));
/// ```
pub trait CartesianTrajectory {
    /// Length of the reference, s.
    fn duration(&self) -> f64;
    /// The reference at time `t` (s); `t` outside `[0, duration]` is clamped.
    fn at(&self, t: f64) -> CartesianTarget;
}

/// A reference behind a pointer is the reference it points to.
macro_rules! forward_trajectory {
    ($($(#[$attr:meta])* $pointer:ty;)+) => {$(
        $(#[$attr])*
        impl<T: CartesianTrajectory + ?Sized> CartesianTrajectory for $pointer {
            fn duration(&self) -> f64 {
                (**self).duration()
            }

            fn at(&self, t: f64) -> CartesianTarget {
                (**self).at(t)
            }
        }
    )+};
}

forward_trajectory! {
    &T;
    #[cfg(feature = "std")]
    std::boxed::Box<T>;
    #[cfg(feature = "std")]
    std::sync::Arc<T>;
}

/// Reads `reference` every `dt` seconds from 0 to its duration, both ends included.
///
/// The times are `k dt` for `k = 0, 1, ...` while `k dt` is below the duration (with a
/// relative slack of 1e-9 so that `10 / 0.005` gives exactly 2001 samples), then the
/// duration itself. A non-positive or non-finite `dt`, or a non-finite duration, gives the
/// single sample at `t = 0`.
///
/// # Example
///
/// ```
/// use armdyn::trajectory::sample;
/// use armdyn::robots::scara::thesis::PositionTest;
///
/// let samples = sample(&PositionTest::new(), 0.005);
/// assert_eq!(samples.len(), 2001); // the thesis's 0.005 s grid over T = 10 s, plus t = T
/// assert_eq!(samples[2000].t, 10.0);
/// ```
#[cfg(feature = "std")]
pub fn sample<R: CartesianTrajectory + ?Sized>(reference: &R, dt: f64) -> Vec<PoseSample> {
    let duration = reference.duration();
    let mut out = Vec::new();
    out.push(PoseSample::from_target(0.0, &reference.at(0.0)));
    if !(dt > 0.0 && dt.is_finite() && duration.is_finite() && duration > 0.0) {
        return out;
    }
    let mut k: u64 = 1;
    loop {
        let t = k as f64 * dt;
        if t >= duration * (1.0 - 1e-9) {
            break;
        }
        out.push(PoseSample::from_target(t, &reference.at(t)));
        k += 1;
    }
    out.push(PoseSample::from_target(duration, &reference.at(duration)));
    out
}
