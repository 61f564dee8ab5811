//! A convex cylinder of infinite length, touched on its mantle from outside.

use nalgebra::Vector3;

use super::shape::{Setting, SettingsReader, Shape, SurfacePoint};

/// A convex cylinder of infinite length (the tool touches its mantle from outside). Base
/// frame, m.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cylinder {
    /// A point on the axis, m.
    pub point: Vector3<f64>,
    /// Unit axis direction.
    pub axis: Vector3<f64>,
    /// Radius, m.
    pub radius: f64,
}

impl Shape for Cylinder {
    const KIND: &'static str = "cylinder";
    const KEYS: &'static [&'static str] = &["point", "axis", "radius"];

    fn read<R: SettingsReader>(s: &mut R) -> Result<Self, R::Error> {
        Ok(Self {
            point: s.point("point", "a point on the axis in m")?,
            axis: s.direction("axis", "the axis direction")?,
            radius: s.length("radius", "a radius in m")?,
        })
    }

    fn write(&self, each: &mut dyn FnMut(&'static str, Setting<'_>)) {
        each("point", Setting::Vector(self.point));
        each("axis", Setting::Vector(self.axis));
        each("radius", Setting::Number(self.radius));
    }

    fn closest(&self, p: &Vector3<f64>) -> SurfacePoint {
        let r = p - self.point;
        SurfacePoint::radial(r - self.axis * self.axis.dot(&r), self.radius)
    }

    fn shifted(&self, distance: f64) -> Self {
        Self {
            radius: self.radius + distance,
            ..*self
        }
    }

    /// Over the length its axis spans beside `path`, 0.1 m more each way (0.2 m each way
    /// of its point without a path): the two end circles, the circle halfway between them
    /// (the section where the tool is) and twelve lines along it.
    #[cfg(feature = "std")]
    fn drawing(&self, path: &[Vector3<f64>], segments: usize) -> super::Drawing {
        let (lo, hi) = path
            .iter()
            .map(|p| (p - self.point).dot(&self.axis))
            .filter(|s| s.is_finite())
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), s| {
                (lo.min(s), hi.max(s))
            });
        let (lo, hi) = if lo <= hi {
            (lo - 0.1, hi + 0.1)
        } else {
            (-0.2, 0.2)
        };
        let mid = 0.5 * (lo + hi);
        let around = super::plane_axes(&self.axis);
        let ends = [lo, hi]
            .map(|s| super::circle(self.point + self.axis * s, self.radius, around, segments));
        let mut d = super::Drawing::default();
        for k in (0..segments).step_by((segments / 12).max(1)) {
            d.lines.push(std::vec![ends[0][k], ends[1][k]]);
        }
        d.lines.splice(0..0, ends);
        d.lines.insert(
            2,
            super::circle(self.point + self.axis * mid, self.radius, around, segments),
        );
        d
    }
}
