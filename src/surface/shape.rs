//! What every surface shape is: its name in files, its settings (read from any file format
//! through [`SettingsReader`], written through [`Setting`]s), the distance and outward
//! normal of a point, its shift along the normal and, with `std`, its drawing. A new shape
//! is one file implementing [`Shape`] and one line in [`SurfaceGeometry`]'s list.
//!
//! [`SurfaceGeometry`]: super::SurfaceGeometry

use nalgebra::Vector3;

/// The largest length a shape's setting may have, m (a larger one is most likely in the
/// wrong unit).
pub const MAX_LENGTH_M: f64 = 100.0;

/// The part of a surface closest to a point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfacePoint {
    /// Signed distance of the point from the surface along the outward normal, m: positive
    /// outside (in free space), negative inside (penetrating).
    pub signed_distance: f64,
    /// Outward unit normal at the closest surface point.
    pub normal: Vector3<f64>,
    /// Whether the point lies over the surface's extent (a plane patch's rectangle; always
    /// for a round surface: sphere, infinite cylinder, torus). Outside it the surface exerts
    /// nothing.
    pub covered: bool,
}

impl SurfacePoint {
    /// A convex round surface of radius `radius` whose centre (or axis foot) is `r` away
    /// from the point: distance `|r| - radius` along `r / |r|`; at the centre itself the
    /// normal is taken as base z.
    #[must_use]
    pub fn radial(r: Vector3<f64>, radius: f64) -> Self {
        let len = libm::sqrt(r.dot(&r));
        let normal = if len > 0.0 { r / len } else { Vector3::z() };
        Self {
            signed_distance: len - radius,
            normal,
            covered: true,
        }
    }
}

/// One setting of a shape as a file writes it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Setting<'a> {
    /// A point or a direction, m or unitless: `[x, y, z]`.
    Vector(Vector3<f64>),
    /// Several of them: `[[x, y, z], ...]`.
    Vectors(&'a [Vector3<f64>]),
    /// A length, m.
    Number(f64),
    /// Several lengths, m: `[a, b, ...]`.
    Numbers(&'a [f64]),
}

/// Reads a shape's settings from one file format. A format gives three things: a number, `N`
/// numbers (each finite) and its error for a value that breaks a rule; the points,
/// directions and lengths a shape asks for, and their rules, are written here once. An error
/// names the key and the rule (`what` says what the value is, for the message of a missing
/// or wrong one).
pub trait SettingsReader {
    /// The format's error.
    type Error;

    /// The finite number at `key`.
    ///
    /// # Errors
    ///
    /// If `key` is missing, not a number or not finite.
    fn number(&mut self, key: &'static str, what: &'static str) -> Result<f64, Self::Error>;

    /// `N` finite numbers at `key`.
    ///
    /// # Errors
    ///
    /// If `key` is missing, not `N` numbers or one is not finite.
    fn numbers<const N: usize>(
        &mut self,
        key: &'static str,
        what: &'static str,
    ) -> Result<[f64; N], Self::Error>;

    /// The error at `key` for a value that breaks the rule `why` (a range, a zero direction,
    /// a rule between settings).
    fn refuse(&mut self, key: &'static str, why: core::fmt::Arguments<'_>) -> Self::Error;

    /// A point, m: three finite numbers `[x, y, z]`.
    ///
    /// # Errors
    ///
    /// As [`Self::numbers`].
    fn point(
        &mut self,
        key: &'static str,
        what: &'static str,
    ) -> Result<Vector3<f64>, Self::Error> {
        self.numbers::<3>(key, what).map(Vector3::from)
    }

    /// A direction: a point not at the origin, normalised to unit length.
    ///
    /// # Errors
    ///
    /// As [`Self::point`], or if the vector is zero.
    fn direction(
        &mut self,
        key: &'static str,
        what: &'static str,
    ) -> Result<Vector3<f64>, Self::Error> {
        let v = self.point(key, what)?;
        let n = libm::sqrt(v.dot(&v));
        if n > 1e-9 {
            Ok(v / n)
        } else {
            Err(self.refuse(
                key,
                format_args!(
                    "is zero; a direction needs a non-zero vector (it is normalised if not unit)"
                ),
            ))
        }
    }

    /// A length, m: `> 0` and `<=` [`MAX_LENGTH_M`].
    ///
    /// # Errors
    ///
    /// As [`Self::number`], or if it is out of that range.
    fn length(&mut self, key: &'static str, what: &'static str) -> Result<f64, Self::Error> {
        let x = self.number(key, what)?;
        self.in_length_range(key, what, x)
    }

    /// `N` lengths, m, each as [`Self::length`].
    ///
    /// # Errors
    ///
    /// As [`Self::numbers`], or if one is out of range.
    fn lengths<const N: usize>(
        &mut self,
        key: &'static str,
        what: &'static str,
    ) -> Result<[f64; N], Self::Error> {
        let v = self.numbers::<N>(key, what)?;
        for x in v {
            self.in_length_range(key, what, x)?;
        }
        Ok(v)
    }

    /// `x` if it is a length, `> 0` and `<=` [`MAX_LENGTH_M`].
    ///
    /// # Errors
    ///
    /// The refusal naming the range.
    fn in_length_range(
        &mut self,
        key: &'static str,
        what: &'static str,
        x: f64,
    ) -> Result<f64, Self::Error> {
        if x > 0.0 && x <= MAX_LENGTH_M {
            Ok(x)
        } else {
            Err(self.refuse(
                key,
                format_args!("{x} is out of range: {what}, > 0 and <= {MAX_LENGTH_M}"),
            ))
        }
    }
}

/// A surface the tool can touch, base frame, m.
pub trait Shape: Sized {
    /// Its name in files (`kind = "sphere"`).
    const KIND: &'static str;
    /// The keys of its settings, in the order files write them (a file's other keys are
    /// refused, naming these).
    const KEYS: &'static [&'static str];

    /// The shape from a file's settings.
    ///
    /// # Errors
    ///
    /// The reader's, for the first setting missing or breaking its rule.
    fn read<R: SettingsReader>(settings: &mut R) -> Result<Self, R::Error>;

    /// Its settings, in the order of [`Self::KEYS`] (and any derived one after the key it
    /// derives from, such as a plane patch's in-plane axes), each given to `each`.
    fn write(&self, each: &mut dyn FnMut(&'static str, Setting<'_>));

    /// The closest part of the surface to `p`.
    fn closest(&self, p: &Vector3<f64>) -> SurfacePoint;

    /// The surface moved `distance` m along its outward normal (a plane's point; a round
    /// surface's radius).
    #[must_use]
    fn shifted(&self, distance: f64) -> Self;

    /// The surface as lines to draw, near `path` (the tool's positions, m), each circle in
    /// `segments` pieces.
    #[cfg(feature = "std")]
    fn drawing(&self, path: &[Vector3<f64>], segments: usize) -> Drawing;
}

/// A surface drawn: polygons to fill and polylines to stroke, base frame, m.
#[cfg(feature = "std")]
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Drawing {
    /// Closed polygons, each a list of corners.
    pub fills: std::vec::Vec<std::vec::Vec<Vector3<f64>>>,
    /// Open polylines: the shape's own lines (a round surface's circles).
    pub lines: std::vec::Vec<std::vec::Vec<Vector3<f64>>>,
    /// Open polylines that mark out a filled face in a 3-D view (a plane patch's grid); a
    /// figure in two dimensions leaves them out.
    pub grid: std::vec::Vec<std::vec::Vec<Vector3<f64>>>,
}

/// `segments + 1` points of the circle of radius `radius` about `centre` in the plane of the
/// unit vectors `u` and `v` (the first point again at the end): `centre + r (u cos a + v sin a)`.
#[cfg(feature = "std")]
#[must_use]
pub fn circle(
    centre: Vector3<f64>,
    radius: f64,
    [u, v]: [Vector3<f64>; 2],
    segments: usize,
) -> std::vec::Vec<Vector3<f64>> {
    (0..=segments)
        .map(|k| {
            let a = core::f64::consts::TAU * k as f64 / segments as f64;
            centre + (u * libm::cos(a) + v * libm::sin(a)) * radius
        })
        .collect()
}
