//! A convex sphere, touched from outside.

use nalgebra::Vector3;

use super::shape::{Setting, SettingsReader, Shape, SurfacePoint};

/// A convex sphere (the tool touches it from outside). Base frame, m.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sphere {
    /// Centre, m.
    pub centre: Vector3<f64>,
    /// Radius, m.
    pub radius: f64,
}

impl Shape for Sphere {
    const KIND: &'static str = "sphere";
    const KEYS: &'static [&'static str] = &["point", "radius"];

    fn read<R: SettingsReader>(s: &mut R) -> Result<Self, R::Error> {
        Ok(Self {
            centre: s.point("point", "the centre in m")?,
            radius: s.length("radius", "a radius in m")?,
        })
    }

    fn write(&self, each: &mut dyn FnMut(&'static str, Setting<'_>)) {
        each("point", Setting::Vector(self.centre));
        each("radius", Setting::Number(self.radius));
    }

    fn closest(&self, p: &Vector3<f64>) -> SurfacePoint {
        SurfacePoint::radial(p - self.centre, self.radius)
    }

    fn shifted(&self, distance: f64) -> Self {
        Self {
            radius: self.radius + distance,
            ..*self
        }
    }

    /// Two meridians (in the base x-z and y-z planes) and five parallels (the equator and
    /// 0.3 and 0.6 radii above and below it).
    #[cfg(feature = "std")]
    fn drawing(&self, _path: &[Vector3<f64>], segments: usize) -> super::Drawing {
        let (x, y, z) = (Vector3::x(), Vector3::y(), Vector3::z());
        let mut d = super::Drawing::default();
        d.lines
            .push(super::circle(self.centre, self.radius, [x, z], segments));
        d.lines
            .push(super::circle(self.centre, self.radius, [y, z], segments));
        for lat in [-0.6_f64, -0.3, 0.0, 0.3, 0.6] {
            let h = lat * self.radius;
            let r = libm::sqrt(self.radius * self.radius - h * h);
            d.lines
                .push(super::circle(self.centre + z * h, r, [x, y], segments));
        }
        d
    }
}
