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

/// `s` drawn: a plane patch as its rectangle with a grid of ten cells a side; a sphere as
/// its equator, two meridians and four parallels; an infinite cylinder over the length its
/// axis spans beside `path` (the tool's), 0.1 m more each way, as its end circles and twelve
/// lines along it.
pub fn mesh(s: &SurfaceGeometry, path: &[[f64; 3]]) -> Mesh {
    let p3 = |v: Vector3<f64>| [v.x, v.y, v.z];
    let mut m = Mesh::default();
    match *s {
        SurfaceGeometry::Plane {
            point,
            axes: [a, b],
            half_extent: [ha, hb],
            ..
        } => {
            let at = |u: f64, v: f64| p3(point + a * (u * ha) + b * (v * hb));
            m.fills.push(vec![
                at(-1.0, -1.0),
                at(1.0, -1.0),
                at(1.0, 1.0),
                at(-1.0, 1.0),
            ]);
            for k in 0..=10 {
                let x = -1.0 + 0.2 * f64::from(k);
                m.lines.push(vec![at(x, -1.0), at(x, 1.0)]);
                m.lines.push(vec![at(-1.0, x), at(1.0, x)]);
            }
        }
        SurfaceGeometry::Sphere { centre, radius } => {
            let circle = |c: Vector3<f64>, r: f64, u: Vector3<f64>, v: Vector3<f64>| {
                (0..=SEGMENTS)
                    .map(|k| {
                        let a = std::f64::consts::TAU * k as f64 / SEGMENTS as f64;
                        p3(c + (u * a.cos() + v * a.sin()) * r)
                    })
                    .collect::<Vec<_>>()
            };
            let (x, y, z) = (Vector3::x(), Vector3::y(), Vector3::z());
            m.lines.push(circle(centre, radius, x, z));
            m.lines.push(circle(centre, radius, y, z));
            for lat in [-0.6_f64, -0.3, 0.0, 0.3, 0.6] {
                let h = lat * radius;
                let r = (radius * radius - h * h).sqrt();
                m.lines.push(circle(centre + z * h, r, x, y));
            }
        }
        SurfaceGeometry::Cylinder {
            point,
            axis,
            radius,
        } => {
            let along = |p: &[f64; 3]| (Vector3::new(p[0], p[1], p[2]) - point).dot(&axis);
            let (lo, hi) = path
                .iter()
                .map(along)
                .filter(|s| s.is_finite())
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), s| {
                    (lo.min(s), hi.max(s))
                });
            let (lo, hi) = if lo <= hi {
                (lo - 0.1, hi + 0.1)
            } else {
                (-0.2, 0.2)
            };
            let [u, v] = crate::contact::plane_axes(&axis);
            let rim = |k: usize| {
                let a = std::f64::consts::TAU * k as f64 / SEGMENTS as f64;
                (u * a.cos() + v * a.sin()) * radius
            };
            for s in [lo, hi] {
                m.lines.push(
                    (0..=SEGMENTS)
                        .map(|k| p3(point + axis * s + rim(k)))
                        .collect(),
                );
            }
            for k in (0..SEGMENTS).step_by(SEGMENTS / 12) {
                m.lines.push(vec![
                    p3(point + axis * lo + rim(k)),
                    p3(point + axis * hi + rim(k)),
                ]);
            }
        }
    }
    m
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
        let c = SurfaceGeometry::Cylinder {
            point: Vector3::zeros(),
            axis: Vector3::y(),
            radius: 0.2,
        };
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
