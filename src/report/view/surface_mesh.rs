//! Surfaces as what the page draws: filled polygons and polylines, m, base frame.

use nalgebra::Vector3;

use crate::contact::SurfaceGeometry;

/// One surface as polygons to fill and polylines to stroke.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Mesh {
    /// Closed polygons, each a list of points.
    pub fills: Vec<Vec<[f64; 3]>>,
    /// Open polylines.
    pub lines: Vec<Vec<[f64; 3]>>,
}

/// Segments of a circle.
const SEGMENTS: usize = 48;

/// `s` drawn near `path` (the tool's), each shape as its own
/// [`drawing`](crate::surface::Shape::drawing) says, a circle in 48 segments.
pub fn mesh(s: &SurfaceGeometry, path: &[[f64; 3]]) -> Mesh {
    let path: Vec<Vector3<f64>> = path.iter().map(|p| Vector3::from(*p)).collect();
    let d = s.drawing(&path, SEGMENTS);
    let p3 = |line: Vec<Vector3<f64>>| line.iter().map(|v| [v.x, v.y, v.z]).collect();
    Mesh {
        fills: d.fills.into_iter().map(p3).collect(),
        lines: d.lines.into_iter().chain(d.grid).map(p3).collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_plane_is_its_rectangle_and_a_cylinder_spans_the_path() {
        let plane = SurfaceGeometry::plane(Vector3::new(0.4, 0.0, 0.22), Vector3::z(), [0.2, 0.4]);
        let m = mesh(&plane, &[]);
        assert_eq!(m.fills[0][0], [0.2, -0.4, 0.22]);
        assert_eq!(m.fills[0][2], [0.6000000000000001, 0.4, 0.22]);
        assert_eq!(m.lines.len(), 22);
        let c = SurfaceGeometry::Cylinder(crate::contact::Cylinder {
            point: Vector3::zeros(),
            axis: Vector3::y(),
            radius: 0.2,
        });
        let m = mesh(&c, &[[0.0, -0.3, 0.2], [0.0, 0.5, 0.2]]);
        let ends: Vec<f64> = m.lines[..2].iter().map(|l| l[0][1]).collect();
        approx::assert_relative_eq!(ends[0], -0.4, epsilon = 1e-12);
        approx::assert_relative_eq!(ends[1], 0.6, epsilon = 1e-12);
        // Every rim point at the radius from the axis.
        for p in &m.lines[0] {
            approx::assert_relative_eq!(p[0].hypot(p[2]), 0.2, epsilon = 1e-12);
        }
    }
}
