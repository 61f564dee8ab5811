//! How well an arm holds its tool to the surface and its posture: the angle between the tool
//! axis and the real surface's inward normal while in contact, and a redundant arm's joint
//! error against its posture (the reference's joints) in the null space.

use super::RmsMax;
use crate::contact::Scene;
use crate::model::JointVector;
use crate::sim::Sample;
use nalgebra::Vector3;

/// The tool axis's angle from the inward normal, accumulated over the force-controlled samples
/// in contact (no allocation).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AlignmentMetrics {
    axis: Vector3<f64>,
    angle_deg: RmsMax,
}

/// Final values of [`AlignmentMetrics`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AlignmentSummary {
    /// RMS angle between the tool axis and the inward normal while force controlled and
    /// touching, degrees.
    pub rms_deg: f64,
    /// Its largest value, degrees.
    pub max_deg: f64,
    /// Samples it was measured on.
    pub samples: usize,
}

impl AlignmentMetrics {
    /// An accumulator for the tool axis `axis` (unit vector, tool frame).
    #[must_use]
    pub fn new(axis: Vector3<f64>) -> Self {
        Self {
            axis,
            angle_deg: RmsMax::default(),
        }
    }

    /// Adds one sample against the real surfaces of `scene`: `acos((R a) . (-n))` when the
    /// sample is force controlled and the tool pushes on a surface.
    pub fn push<const N: usize>(&mut self, s: &Sample<N>, scene: &Scene) {
        if !s.force_controlled {
            return;
        }
        let (push, _, _, n) = super::contact::normal_components(s, scene);
        if push <= 0.0 {
            return;
        }
        let tool = s.orientation * self.axis;
        let angle = libm::acos((-tool.dot(&n)).clamp(-1.0, 1.0)).to_degrees();
        self.angle_deg.push(angle);
    }

    /// The metrics so far (zeros without a sample).
    #[must_use]
    pub fn summary(&self) -> AlignmentSummary {
        AlignmentSummary {
            rms_deg: self.angle_deg.rms(),
            max_deg: self.angle_deg.max(),
            samples: self.angle_deg.count(),
        }
    }
}

/// A redundant arm's posture error `|q_ref - q|` (the Euclidean norm over the joints, rad),
/// from `after_s` on.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PostureMetrics {
    after_s: f64,
    error_rad: RmsMax,
}

/// Final values of [`PostureMetrics`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PostureSummary {
    /// RMS of `|q_ref - q|`, rad.
    pub rms_rad: f64,
    /// Its largest value, rad.
    pub max_rad: f64,
}

impl PostureMetrics {
    /// An accumulator from `after_s` (s) on.
    #[must_use]
    pub fn new(after_s: f64) -> Self {
        Self {
            after_s,
            error_rad: RmsMax::default(),
        }
    }

    /// Adds one sample.
    pub fn push<const N: usize>(&mut self, s: &Sample<N>) {
        if !super::reached(s.t, self.after_s) {
            return;
        }
        let e: JointVector<N> = s.setpoint.joint.q - s.q;
        self.error_rad.push(e.norm());
    }

    /// The metrics so far (zeros without a sample).
    #[must_use]
    pub fn summary(&self) -> PostureSummary {
        PostureSummary {
            rms_rad: self.error_rad.rms(),
            max_rad: self.error_rad.max(),
        }
    }
}
