//! The desired contact force of a run: a signed magnitude over time along the normal of the
//! controller's (nominal) surface at the reference point.

use crate::control::task_frame::TaskFrame;
use crate::model::Wrench;
use crate::trajectory::force_csv::SampledForce;
use crate::trajectory::ForceProfile;

/// The desired contact force: a signed magnitude over time along the inward normal of the
/// controller's (nominal) surface at the reference point.
#[derive(Clone, Debug, PartialEq)]
pub struct DesiredForce {
    /// The magnitude as the thesis's profiles give it (negative = pressing).
    pub profile: ForceShape,
    /// Where the normal comes from.
    pub frame: TaskFrame,
    /// The tool axis (tool frame) the controller holds along the inward normal, if it holds
    /// one (an arm controlling all three rotations).
    pub tool_axis: Option<nalgebra::Vector3<f64>>,
}

/// The shape of a desired force over time.
#[derive(Clone, Debug, PartialEq)]
pub enum ForceShape {
    /// A thesis profile (constant or variable, zero before its start).
    Profile(ForceProfile),
    /// Sampled magnitudes (N, positive pressing), zero before `start_s`.
    Sampled {
        /// The samples.
        samples: SampledForce,
        /// Start time, s.
        start_s: f64,
    },
}

impl DesiredForce {
    /// The desired force along base z (the thesis's `fz_d`, negative pushing down).
    #[must_use]
    pub fn along_z(profile: ForceProfile) -> Self {
        Self {
            profile: ForceShape::Profile(profile),
            frame: TaskFrame::along_z(),
            tool_axis: None,
        }
    }

    /// The signed magnitude at `t` (N, negative pressing).
    #[must_use]
    pub fn signed(&self, t: f64) -> f64 {
        match &self.profile {
            ForceShape::Profile(p) => p.fz(t),
            ForceShape::Sampled { samples, start_s } => {
                if t < *start_s {
                    0.0
                } else {
                    -samples.at(t)
                }
            }
        }
    }

    /// The desired wrench of the tool on the surface at `t` with the reference at
    /// `position` (m): the signed magnitude along the outward normal there.
    #[must_use]
    pub fn wrench(&self, t: f64, position: &nalgebra::Vector3<f64>) -> Wrench {
        let f = self.frame.normal_at(position) * self.signed(t);
        // `+ 0.0` turns the -0.0 of `0 * negative` into 0.0.
        Wrench::new(f.x + 0.0, f.y + 0.0, f.z + 0.0, 0.0, 0.0, 0.0)
    }
}
