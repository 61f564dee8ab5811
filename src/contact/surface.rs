//! The thesis's reaction surface (eq. 5.1 and its `reactionforces` function).

use super::Environment;
use crate::model::Wrench;
use nalgebra::Vector3;

/// A horizontal, frictionless, linearly elastic plane patch: `z = height` over
/// `x in [x_min, x_max]`, `y in [y_min, y_max]`. Below the plane and within the patch the
/// tool exerts `fz = -stiffness (height - z)` on it (N; negative = pushing down), eq. 5.1;
/// elsewhere exactly zero. Bounds are inclusive, as the thesis's code.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ReactionSurface {
    height: f64,
    x_range: [f64; 2],
    y_range: [f64; 2],
    stiffness: f64,
}

/// Invalid surface parameters.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
pub enum SurfaceError {
    /// A parameter is NaN or infinite.
    #[error("reaction surface: `{0}` must be finite")]
    NonFinite(&'static str),
    /// A range is empty.
    #[error("reaction surface: `{0}` must have min < max")]
    EmptyRange(&'static str),
    /// Stiffness not positive.
    #[error("reaction surface: stiffness must be positive (N/m)")]
    Stiffness,
}

impl ReactionSurface {
    /// A surface with the given height (m), ranges (m) and stiffness (N/m), validated.
    ///
    /// # Errors
    ///
    /// [`SurfaceError`] naming the bad parameter.
    pub fn new(
        height: f64,
        x_range: [f64; 2],
        y_range: [f64; 2],
        stiffness: f64,
    ) -> Result<Self, SurfaceError> {
        for (name, v) in [
            ("height", height),
            ("x_min", x_range[0]),
            ("x_max", x_range[1]),
            ("y_min", y_range[0]),
            ("y_max", y_range[1]),
            ("stiffness", stiffness),
        ] {
            if !v.is_finite() {
                return Err(SurfaceError::NonFinite(name));
            }
        }
        if x_range[0] >= x_range[1] {
            return Err(SurfaceError::EmptyRange("x_range"));
        }
        if y_range[0] >= y_range[1] {
            return Err(SurfaceError::EmptyRange("y_range"));
        }
        if stiffness <= 0.0 {
            return Err(SurfaceError::Stiffness);
        }
        Ok(Self {
            height,
            x_range,
            y_range,
            stiffness,
        })
    }

    /// Height of the plane, m.
    #[must_use]
    pub fn height(&self) -> f64 {
        self.height
    }

    /// `[x_min, x_max]` of the patch, m.
    #[must_use]
    pub fn x_range(&self) -> [f64; 2] {
        self.x_range
    }

    /// `[y_min, y_max]` of the patch, m.
    #[must_use]
    pub fn y_range(&self) -> [f64; 2] {
        self.y_range
    }

    /// Stiffness, N/m.
    #[must_use]
    pub fn stiffness(&self) -> f64 {
        self.stiffness
    }

    /// Whether `(x, y)` lies over the patch.
    #[must_use]
    pub fn covers(&self, x: f64, y: f64) -> bool {
        self.x_range[0] <= x && x <= self.x_range[1] && self.y_range[0] <= y && y <= self.y_range[1]
    }
}

impl Environment for ReactionSurface {
    fn wrench(&self, position: &Vector3<f64>, _velocity: &Vector3<f64>) -> Wrench {
        let mut w = Wrench::zeros();
        if self.covers(position.x, position.y) && position.z <= self.height {
            w[2] = -self.stiffness * (self.height - position.z);
        }
        w
    }
}
