//! The tool's orientation target near a surface, for the force laws in the full task frame:
//! the tool axis `a` (tool frame) turned onto the inward normal, the rotation about the
//! normal the reference's, blended from the reference's own orientation as it comes down:
//!
//! ```text
//! R_d = slerp(R_ref, Rot(R_ref a -> -n) R_ref, w)     w = 3 s^2 - 2 s^3,
//! s   = clamp((far - h_ref) / (far - near), 0, 1)     (w = 1 under force control)
//! ```

use nalgebra::{UnitQuaternion, Vector3};

/// Within this height of the reference above the surface the tool is held along the normal
/// ([`ToolOrientation::target_at`]), m.
pub const ALIGN_NEAR_M: f64 = 0.01;
/// From this height of the reference above the surface on, the reference's orientation is
/// tracked unchanged, m.
pub const ALIGN_FAR_M: f64 = 0.03;

/// How the orientation target is chosen while the tool is near the surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ToolOrientation {
    /// The tool axis (a unit vector in the tool frame) held along the inward normal, the
    /// rotation about the normal from the reference (the default).
    AlongNormal(Vector3<f64>),
    /// The reference's orientation, unchanged.
    Reference,
}

impl ToolOrientation {
    /// The orientation target for the reference orientation `reference` and the outward
    /// normal `n`: the reference turned by the smallest rotation that takes its tool axis onto
    /// `-n` (by half a turn about a perpendicular axis if it points along `+n`).
    ///
    /// ```
    /// use armdyn::control::tool_orientation::ToolOrientation;
    /// use nalgebra::{UnitQuaternion, Vector3};
    /// let hold = ToolOrientation::AlongNormal(Vector3::z());
    /// // A tool whose z axis points 10 degrees off straight down, on a table (n = +z).
    /// let r = UnitQuaternion::from_euler_angles(std::f64::consts::PI - 0.1745, 0.0, 0.3);
    /// let d = hold.target(&r, &Vector3::z());
    /// assert!((d * Vector3::z() + Vector3::z()).norm() < 1e-12);
    /// ```
    #[must_use]
    pub fn target(&self, reference: &UnitQuaternion<f64>, n: &Vector3<f64>) -> UnitQuaternion<f64> {
        match self {
            Self::Reference => *reference,
            Self::AlongNormal(axis) => {
                let from = reference * axis;
                let to = -n;
                let turn = UnitQuaternion::rotation_between(&from, &to).unwrap_or_else(|| {
                    // Antiparallel: half a turn about any axis perpendicular to `from`.
                    let other = if from.x.abs() < 0.9 {
                        Vector3::x()
                    } else {
                        Vector3::y()
                    };
                    let axis = nalgebra::Unit::new_normalize(from.cross(&other));
                    UnitQuaternion::from_axis_angle(&axis, core::f64::consts::PI)
                });
                turn * reference
            }
        }
    }

    /// The orientation target where the reference is `gap` m above the (believed) surface
    /// (`None`: off its extent, or a frame without a surface): [`target`](Self::target) when
    /// force is controlled or within [`ALIGN_NEAR_M`] of the surface, the reference's own
    /// orientation from [`ALIGN_FAR_M`] on, and between them the two slerped with the
    /// smoothstep weight `w = 3 s^2 - 2 s^3`, `s = (far - gap) / (far - near)`: in free space the
    /// tool follows the reference, and it turns onto the normal as it comes down.
    ///
    /// ```
    /// use armdyn::control::tool_orientation::{ToolOrientation, ALIGN_FAR_M};
    /// use nalgebra::{UnitQuaternion, Vector3};
    /// let hold = ToolOrientation::AlongNormal(Vector3::z());
    /// let r = UnitQuaternion::from_euler_angles(std::f64::consts::PI - 0.3, 0.0, 0.0);
    /// let n = Vector3::z();
    /// assert_eq!(hold.target_at(&r, &n, Some(ALIGN_FAR_M + 0.01), false), r);
    /// assert_eq!(hold.target_at(&r, &n, Some(0.0), false), hold.target(&r, &n));
    /// assert_eq!(hold.target_at(&r, &n, Some(0.1), true), hold.target(&r, &n));
    /// ```
    #[must_use]
    pub fn target_at(
        &self,
        reference: &UnitQuaternion<f64>,
        n: &Vector3<f64>,
        gap: Option<f64>,
        forcing: bool,
    ) -> UnitQuaternion<f64> {
        let full = self.target(reference, n);
        let w = match gap {
            Some(g) if !forcing => {
                let s = ((ALIGN_FAR_M - g) / (ALIGN_FAR_M - ALIGN_NEAR_M)).clamp(0.0, 1.0);
                s * s * (3.0 - 2.0 * s)
            }
            _ => 1.0,
        };
        if w >= 1.0 {
            full
        } else if w <= 0.0 {
            *reference
        } else {
            reference.slerp(&full, w)
        }
    }

    /// The tool axis held along the inward normal, if any (tool frame).
    #[must_use]
    pub fn axis(&self) -> Option<Vector3<f64>> {
        match self {
            Self::AlongNormal(a) => Some(*a),
            Self::Reference => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_orientation_target_turns_the_tool_onto_the_normal() {
        let hold = ToolOrientation::AlongNormal(Vector3::x());
        let n = Vector3::new(0.0, (25f64).to_radians().sin(), (25f64).to_radians().cos());
        let r = UnitQuaternion::from_euler_angles(0.1, 1.5, -0.4);
        let d = hold.target(&r, &n);
        assert!((d * Vector3::x() + n).norm() < 1e-12);
        // The rotation about the normal is the reference's: the smallest turn.
        let turn = d * r.inverse();
        let axis = turn.axis().unwrap();
        assert!(axis.dot(&n).abs() < 1e-12);
        // Antiparallel: still onto -n.
        let up = UnitQuaternion::rotation_between(&Vector3::x(), &n).unwrap();
        assert!((hold.target(&up, &n) * Vector3::x() + n).norm() < 1e-12);
        assert_eq!(ToolOrientation::Reference.target(&r, &n), r);
    }
}
