//! [`SurfaceGeometry`]: one of the shapes, by the list below; the one place a new shape is
//! named besides its own file.

use nalgebra::Vector3;

use super::shape::{Setting, SettingsReader, Shape, SurfacePoint};
use super::{Cylinder, Plane, Sphere, Torus};

/// The shapes a scenario may give, each `Variant(Type)` with `Type:` [`Shape`]: a new shape
/// is its file and a line here.
macro_rules! shapes {
    ($($variant:ident($shape:ty),)+) => {
        /// A rigid surface shape, base frame, m.
        #[derive(Clone, Copy, Debug, PartialEq)]
        pub enum SurfaceGeometry {
            $(
                #[doc = concat!("A [`", stringify!($shape), "`].")]
                $variant($shape),
            )+
        }

        impl SurfaceGeometry {
            /// Every shape's name in files, in the list's order.
            pub const KINDS: &'static [&'static str] = &[$(<$shape as Shape>::KIND),+];

            /// The keys of the settings of the shape named `kind`, if there is one.
            #[must_use]
            pub fn keys_of(kind: &str) -> Option<&'static [&'static str]> {
                match kind {
                    $(k if k == <$shape as Shape>::KIND => Some(<$shape as Shape>::KEYS),)+
                    _ => None,
                }
            }

            /// The shape named `kind` from a file's settings; `None` for no such kind.
            ///
            /// # Errors
            ///
            /// The reader's, as [`Shape::read`].
            pub fn read<R: SettingsReader>(kind: &str, settings: &mut R) -> Option<Result<Self, R::Error>> {
                match kind {
                    $(k if k == <$shape as Shape>::KIND => Some(<$shape>::read(settings).map(Self::$variant)),)+
                    _ => None,
                }
            }

            /// Its name in files.
            #[must_use]
            pub fn kind(&self) -> &'static str {
                match self {
                    $(Self::$variant(_) => <$shape as Shape>::KIND,)+
                }
            }

            /// Its settings, as [`Shape::write`].
            pub fn write(&self, each: &mut dyn FnMut(&'static str, Setting<'_>)) {
                match self {
                    $(Self::$variant(s) => s.write(each),)+
                }
            }

            /// The closest part of the surface to `p`.
            #[must_use]
            pub fn closest(&self, p: &Vector3<f64>) -> SurfacePoint {
                match self {
                    $(Self::$variant(s) => s.closest(p),)+
                }
            }

            /// The surface moved `distance` m along its outward normal (the controller's belief
            /// of a surface; a sweep's offset of the real one).
            #[must_use]
            pub fn shifted(&self, distance: f64) -> Self {
                match self {
                    $(Self::$variant(s) => Self::$variant(s.shifted(distance)),)+
                }
            }

            /// The surface as lines to draw near `path`, as [`Shape::drawing`].
            #[cfg(feature = "std")]
            #[must_use]
            pub fn drawing(&self, path: &[Vector3<f64>], segments: usize) -> super::Drawing {
                match self {
                    $(Self::$variant(s) => s.drawing(path, segments),)+
                }
            }
        }
    };
}

shapes! {
    Plane(Plane),
    Sphere(Sphere),
    Cylinder(Cylinder),
    Torus(Torus),
}

impl SurfaceGeometry {
    /// A plane patch; `normal` must be a unit vector (see [`plane_axes`](super::plane_axes)
    /// for the patch axes).
    #[must_use]
    pub fn plane(point: Vector3<f64>, normal: Vector3<f64>, half_extent: [f64; 2]) -> Self {
        Self::Plane(Plane::new(point, normal, half_extent))
    }
}
