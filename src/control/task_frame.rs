//! The task frame of hybrid control: the direction in which force is controlled (the
//! contact normal) at the tool's current position, from the controller's own knowledge of
//! the surface (its nominal geometry, which may differ from the real one).

use crate::surface::SurfaceGeometry;
use nalgebra::Vector3;

/// Where the force-controlled direction comes from.
///
/// The task frame's first axis is the outward contact normal `n`; the tangent plane and the
/// yaw are position controlled. The thesis's selection `S = diag(1, 1, 0, 1, 1, 1)` in base
/// axes is [`TaskFrame::Fixed`] with `n = z`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TaskFrame {
    /// A constant outward unit normal, base frame.
    Fixed(Vector3<f64>),
    /// The outward normal of a (nominal) surface at the point closest to the tool: the frame
    /// follows the surface as the tool moves over a curved one.
    Surface(SurfaceGeometry),
}

impl TaskFrame {
    /// Force along base z (the thesis's frame).
    #[must_use]
    pub fn along_z() -> Self {
        Self::Fixed(Vector3::z())
    }

    /// The outward unit normal for the tool at `p` (m, base frame).
    #[must_use]
    pub fn normal_at(&self, p: &Vector3<f64>) -> Vector3<f64> {
        match self {
            Self::Fixed(n) => *n,
            Self::Surface(g) => g.closest(p).normal,
        }
    }

    /// Signed distance of `p` from the nominal surface along its normal, m (`None` for a
    /// fixed frame, which knows no surface, or where `p` is not over the surface).
    #[must_use]
    pub fn signed_distance(&self, p: &Vector3<f64>) -> Option<f64> {
        match self {
            Self::Fixed(_) => None,
            Self::Surface(g) => {
                let c = g.closest(p);
                c.covered.then_some(c.signed_distance)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_frame_follows_a_sphere() {
        let f = TaskFrame::Surface(SurfaceGeometry::Sphere(crate::surface::Sphere {
            centre: Vector3::zeros(),
            radius: 1.0,
        }));
        let p = Vector3::new(0.6, 0.0, 0.8);
        assert!((f.normal_at(&p) - p).norm() < 1e-15);
        assert!(f.signed_distance(&(p * 1.1)).unwrap() > 0.0);
        assert_eq!(TaskFrame::along_z().normal_at(&p), Vector3::z());
        assert_eq!(TaskFrame::along_z().signed_distance(&p), None);
    }
}
