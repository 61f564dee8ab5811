//! Run metrics, accumulated sample by sample without allocation: joint tracking errors,
//! torques (Chapter 4), the tool's pose tracking, and contact-force quality (Chapter 5).

pub mod alignment;
pub mod contact;
pub mod force;
pub mod pose;
pub mod rms;
pub mod settling;
pub mod tracking;

pub use alignment::{AlignmentMetrics, AlignmentSummary, PostureMetrics, PostureSummary};
pub use contact::{ContactMetrics, ContactSummary};
pub use force::{ForceMetrics, ForceSummary};
pub use pose::{PoseMetrics, PoseSummary};
pub use rms::{Rms, RmsMax};
pub use settling::Settling;
pub use tracking::{TrackingMetrics, TrackingSummary};

/// Whether a sample at `t` (s) is at or after `start_s`: `t >= start_s - 1e-12`, the 1e-12 s
/// for the rounding of sample times (`k dt` summed or multiplied).
#[inline]
pub(crate) fn reached(t: f64, start_s: f64) -> bool {
    t >= start_s - 1e-12
}
