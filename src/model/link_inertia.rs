//! One link's inertial parameters in physical form (mass, centre of mass, inertia about it)
//! and the ten standard parameters of the regressor, both ways; the perturbations of a
//! model-mismatch study (scale factors, centre-of-mass offsets, a payload).

use nalgebra::{Matrix3, Vector3};

/// Mass (kg), centre of mass in the link frame (m) and inertia tensor about the centre of
/// mass in link-frame axes (kg m^2).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LinkInertia {
    /// kg.
    pub mass: f64,
    /// m, link frame.
    pub com: Vector3<f64>,
    /// kg m^2, about the centre of mass.
    pub inertia: Matrix3<f64>,
}

/// `|c|^2 I - c c^T`: the parallel-axis term per unit mass.
fn shift(c: &Vector3<f64>) -> Matrix3<f64> {
    Matrix3::identity() * c.norm_squared() - c * c.transpose()
}

impl LinkInertia {
    /// From `[m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz]` (inertia about the link
    /// frame's origin). A massless link has its centre at the origin.
    ///
    /// ```
    /// use armdyn::model::LinkInertia;
    /// let p = [2.0, 0.2, 0.0, 0.0, 0.1, 0.0, 0.0, 0.12, 0.0, 0.13];
    /// let back = LinkInertia::from_standard(&p).to_standard();
    /// for (a, b) in p.iter().zip(back.iter()) {
    ///     assert!((a - b).abs() < 1e-15);
    /// }
    /// ```
    #[must_use]
    pub fn from_standard(p: &[f64; 10]) -> Self {
        let mass = p[0];
        let com = if mass != 0.0 {
            Vector3::new(p[1], p[2], p[3]) / mass
        } else {
            Vector3::zeros()
        };
        let origin = Matrix3::new(p[4], p[5], p[6], p[5], p[7], p[8], p[6], p[8], p[9]);
        Self {
            mass,
            com,
            inertia: origin - shift(&com) * mass,
        }
    }

    /// The ten standard parameters.
    #[must_use]
    pub fn to_standard(&self) -> [f64; 10] {
        let i = self.inertia + shift(&self.com) * self.mass;
        let mc = self.com * self.mass;
        [
            self.mass,
            mc.x,
            mc.y,
            mc.z,
            i[(0, 0)],
            i[(0, 1)],
            i[(0, 2)],
            i[(1, 1)],
            i[(1, 2)],
            i[(2, 2)],
        ]
    }

    /// This link with its mass scaled by `mass_scale`, its centre moved by `com_offset` (m)
    /// and its inertia about the centre scaled by `inertia_scale`.
    #[must_use]
    pub fn perturbed(&self, mass_scale: f64, com_offset: Vector3<f64>, inertia_scale: f64) -> Self {
        Self {
            mass: self.mass * mass_scale,
            com: self.com + com_offset,
            inertia: self.inertia * inertia_scale,
        }
    }

    /// This link carrying a point mass `mass` (kg) at `at` (m, link frame).
    #[must_use]
    pub fn with_point_mass(&self, mass: f64, at: Vector3<f64>) -> Self {
        let total = self.mass + mass;
        if total == 0.0 {
            return *self;
        }
        let com = (self.com * self.mass + at * mass) / total;
        let inertia =
            self.inertia + shift(&(self.com - com)) * self.mass + shift(&(at - com)) * mass;
        Self {
            mass: total,
            com,
            inertia,
        }
    }
}
