//! Shapes of contact surfaces: a plane patch, a convex sphere and a cylinder, each able to
//! say, for a point, how far it is from the surface, along which outward normal, and whether
//! it lies over the surface at all (thesis Chapter 6: surfaces beyond the flat plane).

use nalgebra::Vector3;

/// The part of a surface closest to a point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfacePoint {
    /// Signed distance of the point from the surface along the outward normal, m: positive
    /// outside (in free space), negative inside (penetrating).
    pub signed_distance: f64,
    /// Outward unit normal at the closest surface point.
    pub normal: Vector3<f64>,
    /// Whether the point lies over the surface's extent (a plane patch's rectangle; always
    /// for a sphere or an infinite cylinder). Outside it the surface exerts nothing.
    pub covered: bool,
}

/// A rigid surface shape, base frame, m.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SurfaceGeometry {
    /// A rectangular plane patch through `point` with outward unit `normal`; it extends
    /// `half_extent[0]` along `axes[0]` and `half_extent[1]` along `axes[1]` (the in-plane
    /// unit axes, see [`plane_axes`]), bounds inclusive.
    Plane {
        /// A point of the plane, the patch's centre, m.
        point: Vector3<f64>,
        /// Outward unit normal.
        normal: Vector3<f64>,
        /// In-plane unit axes of the patch.
        axes: [Vector3<f64>; 2],
        /// Half sizes of the patch along `axes`, m.
        half_extent: [f64; 2],
    },
    /// A convex sphere (the tool touches it from outside).
    Sphere {
        /// Centre, m.
        centre: Vector3<f64>,
        /// Radius, m.
        radius: f64,
    },
    /// A convex cylinder of infinite length (the tool touches its mantle from outside).
    Cylinder {
        /// A point on the axis, m.
        point: Vector3<f64>,
        /// Unit axis direction.
        axis: Vector3<f64>,
        /// Radius, m.
        radius: f64,
    },
}

/// The in-plane axes of a plane with unit normal `n`: the first is the base x axis projected
/// into the plane (the base y axis if `n` is nearly along x), the second `n x first`.
/// For the horizontal plane `n = z` they are exactly the base x and y axes.
///
/// ```
/// use armdyn::contact::plane_axes;
/// use nalgebra::Vector3;
/// let [a, b] = plane_axes(&Vector3::z());
/// assert_eq!((a, b), (Vector3::x(), Vector3::y()));
/// ```
#[must_use]
pub fn plane_axes(n: &Vector3<f64>) -> [Vector3<f64>; 2] {
    let seed = if n.x.abs() < 0.9 {
        Vector3::x()
    } else {
        Vector3::y()
    };
    let a = seed - n * n.dot(&seed);
    let a = a / libm::sqrt(a.dot(&a));
    [a, n.cross(&a)]
}

impl SurfaceGeometry {
    /// A plane patch; `normal` must be a unit vector (see [`plane_axes`] for the patch axes).
    #[must_use]
    pub fn plane(point: Vector3<f64>, normal: Vector3<f64>, half_extent: [f64; 2]) -> Self {
        Self::Plane {
            point,
            normal,
            axes: plane_axes(&normal),
            half_extent,
        }
    }

    /// The closest part of the surface to `p`.
    #[must_use]
    pub fn closest(&self, p: &Vector3<f64>) -> SurfacePoint {
        match self {
            Self::Plane {
                point,
                normal,
                axes,
                half_extent,
            } => {
                let r = p - point;
                SurfacePoint {
                    signed_distance: normal.dot(&r),
                    normal: *normal,
                    covered: axes[0].dot(&r).abs() <= half_extent[0]
                        && axes[1].dot(&r).abs() <= half_extent[1],
                }
            }
            Self::Sphere { centre, radius } => radial(p - centre, *radius),
            Self::Cylinder {
                point,
                axis,
                radius,
            } => {
                let r = p - point;
                radial(r - axis * axis.dot(&r), *radius)
            }
        }
    }
}

/// Distance and normal for a convex round surface of radius `radius` whose centre (or axis
/// foot) is `r` away from the point; at the centre itself the normal is taken as base z.
fn radial(r: Vector3<f64>, radius: f64) -> SurfacePoint {
    let len = libm::sqrt(r.dot(&r));
    let normal = if len > 0.0 { r / len } else { Vector3::z() };
    SurfacePoint {
        signed_distance: len - radius,
        normal,
        covered: true,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plane_patch_distance_normal_and_extent() {
        let s = SurfaceGeometry::plane(Vector3::new(0.4, 0.0, 0.13), Vector3::z(), [0.2, 0.4]);
        let c = s.closest(&Vector3::new(0.5, 0.1, 0.11));
        assert!((c.signed_distance + 0.02).abs() < 1e-15);
        assert_eq!(c.normal, Vector3::z());
        assert!(c.covered);
        assert!(!s.closest(&Vector3::new(0.7, 0.0, 0.1)).covered);
        assert!(!s.closest(&Vector3::new(0.5, -0.41, 0.1)).covered);
    }

    #[test]
    fn tilted_plane_axes_are_orthonormal() {
        let a = 20_f64.to_radians();
        let n = Vector3::new(libm::sin(a), 0.0, libm::cos(a));
        let [u, v] = plane_axes(&n);
        for (x, y) in [(u, v), (u, n), (v, n)] {
            assert!(x.dot(&y).abs() < 1e-15);
        }
        assert!((u.norm() - 1.0).abs() < 1e-15 && (v.norm() - 1.0).abs() < 1e-15);
        assert!((v - Vector3::y()).norm() < 1e-15, "{v}");
    }

    #[test]
    fn sphere_and_cylinder_are_convex_from_outside() {
        let s = SurfaceGeometry::Sphere {
            centre: Vector3::new(0.5, 0.0, -0.87),
            radius: 1.0,
        };
        let c = s.closest(&Vector3::new(0.5, 0.0, 0.12));
        assert!((c.signed_distance + 0.01).abs() < 1e-12);
        assert!((c.normal - Vector3::z()).norm() < 1e-15);
        let cyl = SurfaceGeometry::Cylinder {
            point: Vector3::new(0.5, 0.0, -0.37),
            axis: Vector3::y(),
            radius: 0.5,
        };
        let c = cyl.closest(&Vector3::new(0.5, 0.3, 0.15));
        assert!((c.signed_distance - 0.02).abs() < 1e-12);
        assert!((c.normal - Vector3::z()).norm() < 1e-15);
    }
}
