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
