//! A rectangular plane patch: the thesis's table and its tilted variants.

use nalgebra::Vector3;

use super::shape::{Setting, SettingsReader, Shape, SurfacePoint};

/// A rectangular plane patch through `point` with outward unit `normal`; it extends
/// `half_extent[0]` along `axes[0]` and `half_extent[1]` along `axes[1]` (the in-plane unit
/// axes, see [`plane_axes`]), bounds inclusive. Base frame, m.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plane {
    /// A point of the plane, the patch's centre, m.
    pub point: Vector3<f64>,
    /// Outward unit normal.
    pub normal: Vector3<f64>,
    /// In-plane unit axes of the patch.
    pub axes: [Vector3<f64>; 2],
    /// Half sizes of the patch along `axes`, m.
    pub half_extent: [f64; 2],
}

impl Plane {
    /// The patch through `point` with unit `normal`, its axes from [`plane_axes`].
    #[must_use]
    pub fn new(point: Vector3<f64>, normal: Vector3<f64>, half_extent: [f64; 2]) -> Self {
        Self {
            point,
            normal,
            axes: plane_axes(&normal),
            half_extent,
        }
    }

    /// The patch's point at patch coordinates `(a, b)` (-1 to 1 each, corner to corner).
    #[cfg(feature = "std")]
    fn at(&self, a: f64, b: f64) -> Vector3<f64> {
        self.point
            + self.axes[0] * (a * self.half_extent[0])
            + self.axes[1] * (b * self.half_extent[1])
    }
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

impl Shape for Plane {
    const KIND: &'static str = "plane";
    const KEYS: &'static [&'static str] = &["point", "normal", "half_extent"];

    fn read<R: SettingsReader>(s: &mut R) -> Result<Self, R::Error> {
        Ok(Self::new(
            s.point("point", "the patch's centre in m")?,
            s.direction("normal", "the outward normal")?,
            s.lengths("half_extent", "the patch's half sizes [a, b] in m")?,
        ))
    }

    fn write(&self, each: &mut dyn FnMut(&'static str, Setting<'_>)) {
        each("point", Setting::Vector(self.point));
        each("normal", Setting::Vector(self.normal));
        each("axes", Setting::Vectors(&self.axes));
        each("half_extent", Setting::Numbers(&self.half_extent));
    }

    fn closest(&self, p: &Vector3<f64>) -> SurfacePoint {
        let r = p - self.point;
        SurfacePoint {
            signed_distance: self.normal.dot(&r),
            normal: self.normal,
            covered: self.axes[0].dot(&r).abs() <= self.half_extent[0]
                && self.axes[1].dot(&r).abs() <= self.half_extent[1],
        }
    }

    fn shifted(&self, distance: f64) -> Self {
        Self {
            point: self.point + self.normal * distance,
            ..*self
        }
    }

    /// The rectangle, filled, and a grid of ten cells a side.
    #[cfg(feature = "std")]
    fn drawing(&self, _path: &[Vector3<f64>], _segments: usize) -> super::Drawing {
        let mut d = super::Drawing::default();
        d.fills.push(std::vec![
            self.at(-1.0, -1.0),
            self.at(1.0, -1.0),
            self.at(1.0, 1.0),
            self.at(-1.0, 1.0),
        ]);
        for k in 0..=10 {
            let x = -1.0 + 0.2 * f64::from(k);
            d.grid.push(std::vec![self.at(x, -1.0), self.at(x, 1.0)]);
            d.grid.push(std::vec![self.at(-1.0, x), self.at(1.0, x)]);
        }
        d
    }
}
