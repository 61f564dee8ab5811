//! A torus, touched from outside its tube: a pipe bend.

use nalgebra::Vector3;

use super::shape::{Setting, SettingsReader, Shape, SurfacePoint};

/// A torus about `axis` through `centre`: a tube of radius `tube_radius` round the circle of
/// radius `radius` about the axis (a pipe bend; the tool touches the tube from outside).
/// Base frame, m.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Torus {
    /// Centre, m.
    pub centre: Vector3<f64>,
    /// Unit axis direction.
    pub axis: Vector3<f64>,
    /// Radius of the circle the tube runs round, m.
    pub radius: f64,
    /// Radius of the tube, m (smaller than `radius`).
    pub tube_radius: f64,
}

impl Torus {
    /// The unit direction from the axis towards `p`, in the plane normal to the axis (for a
    /// point on the axis the first of [`plane_axes`](super::plane_axes)).
    fn outward(&self, p: &Vector3<f64>) -> Vector3<f64> {
        let r = p - self.centre;
        let across = r - self.axis * self.axis.dot(&r);
        let len = libm::sqrt(across.dot(&across));
        if len > 0.0 {
            across / len
        } else {
            super::plane_axes(&self.axis)[0]
        }
    }
}

impl Shape for Torus {
    const KIND: &'static str = "torus";
    const KEYS: &'static [&'static str] = &["point", "axis", "radius", "tube_radius"];

    fn read<R: SettingsReader>(s: &mut R) -> Result<Self, R::Error> {
        let torus = Self {
            centre: s.point("point", "the centre in m")?,
            axis: s.direction("axis", "the axis direction")?,
            radius: s.length("radius", "the radius of the tube's circle in m")?,
            tube_radius: s.length("tube_radius", "the tube's radius in m")?,
        };
        if torus.tube_radius >= torus.radius {
            return Err(s.refuse(
                "tube_radius",
                format_args!("must be smaller than `radius` (the tube would cross the axis)"),
            ));
        }
        Ok(torus)
    }

    fn write(&self, each: &mut dyn FnMut(&'static str, Setting<'_>)) {
        each("point", Setting::Vector(self.centre));
        each("axis", Setting::Vector(self.axis));
        each("radius", Setting::Number(self.radius));
        each("tube_radius", Setting::Number(self.tube_radius));
    }

    /// The tube's centre circle nearest `p` is at `c = centre + radius e` (`e` towards `p`
    /// across the axis); the distance is `|p - c| - tube_radius` along `(p - c) / |p - c|`.
    fn closest(&self, p: &Vector3<f64>) -> SurfacePoint {
        let c = self.centre + self.outward(p) * self.radius;
        SurfacePoint::radial(p - c, self.tube_radius)
    }

    fn shifted(&self, distance: f64) -> Self {
        Self {
            tube_radius: self.tube_radius + distance,
            ..*self
        }
    }

    /// Over the arc of the tube beside `path`, 0.1 m more each way (the whole ring without
    /// a path or when the path goes round more than half of it): the tube's sections at the
    /// ends and the middle of the arc and twelve lines along the tube.
    #[cfg(feature = "std")]
    fn drawing(&self, path: &[Vector3<f64>], segments: usize) -> super::Drawing {
        use core::f64::consts::{PI, TAU};
        let [u, v] = super::plane_axes(&self.axis);
        let angle = |p: &Vector3<f64>| {
            let e = self.outward(p);
            libm::atan2(e.dot(&v), e.dot(&u))
        };
        // The path's angles about the axis, unwrapped from the first one.
        let first = path.first().map_or(0.0, angle);
        let (lo, hi) = path.iter().fold((0.0_f64, 0.0_f64), |(lo, hi), p| {
            let a = (angle(p) - first + PI).rem_euclid(TAU) - PI;
            (lo.min(a), hi.max(a))
        });
        let margin = 0.1 / self.radius;
        let (from, to) = if path.is_empty() || hi - lo + 2.0 * margin > PI {
            (0.0, TAU)
        } else {
            (first + lo - margin, first + hi + margin)
        };
        let ring = |a: f64| u * libm::cos(a) + v * libm::sin(a);
        let section = |a: f64| {
            let e = ring(a);
            super::circle(
                self.centre + e * self.radius,
                self.tube_radius,
                [e, self.axis],
                segments,
            )
        };
        let mut d = super::Drawing::default();
        for a in [from, to, 0.5 * (from + to)] {
            d.lines.push(section(a));
        }
        for k in (0..segments).step_by((segments / 12).max(1)) {
            let t = TAU * k as f64 / segments as f64;
            d.lines.push(
                (0..=segments)
                    .map(|j| {
                        let e = ring(from + (to - from) * j as f64 / segments as f64);
                        let off = e * libm::cos(t) + self.axis * libm::sin(t);
                        self.centre + e * self.radius + off * self.tube_radius
                    })
                    .collect(),
            );
        }
        d
    }
}
