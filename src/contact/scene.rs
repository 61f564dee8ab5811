//! Elastic, damped surfaces with Coulomb friction, and a scene of several of them (thesis
//! eq. 5.1 generalised: any surface shape, any normal, damping and friction).

use super::Environment;
use crate::model::Wrench;
#[cfg(doc)]
use crate::surface::FRICTION_REGULARISATION_SPEED;
use crate::surface::{sliding_friction, SurfaceGeometry, SurfacePoint};
use nalgebra::Vector3;

/// One surface: a shape, its normal stiffness (N/m) and damping (N s/m), and its Coulomb
/// friction coefficient.
///
/// In contact (the tool point over the surface's extent and at or below it, penetration
/// `d = -signed_distance >= 0`), the surface pushes the tool out along the outward normal
/// `n` with `f_n = max(0, k d - c (n . v))` and resists sliding with
/// `mu f_n v_t / max(|v_t|, FRICTION_REGULARISATION_SPEED)`, `v_t = v - n (n . v)`. The
/// wrench the *tool exerts on the surface* (the thesis's `f_ext`) is the opposite:
/// `-f_n n + mu f_n v_t / max(|v_t|, v_eps)`. For the thesis's plane (`n = z`, `c = mu = 0`)
/// this is exactly eq. 5.1, `fz = -k (z_rs - z)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactSurface {
    /// The shape.
    pub geometry: SurfaceGeometry,
    /// Normal stiffness, N/m (> 0).
    pub stiffness: f64,
    /// Normal damping, N s/m (>= 0).
    pub damping: f64,
    /// Coulomb friction coefficient (>= 0).
    pub friction: f64,
}

/// What a surface does to the tool at one state.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactState {
    /// The closest part of the surface.
    pub closest: SurfacePoint,
    /// Normal force magnitude the tool exerts on the surface, N (0 out of contact).
    pub normal_force: f64,
    /// Tangential (friction) force the tool exerts on the surface, N, base frame.
    pub tangential_force: Vector3<f64>,
}

impl ContactSurface {
    /// The contact at tool position `p` (m) moving at `v` (m/s).
    #[must_use]
    pub fn state(&self, p: &Vector3<f64>, v: &Vector3<f64>) -> ContactState {
        let closest = self.geometry.closest(p);
        let mut out = ContactState {
            closest,
            normal_force: 0.0,
            tangential_force: Vector3::zeros(),
        };
        if !(closest.covered && closest.signed_distance <= 0.0) {
            return out;
        }
        let n = closest.normal;
        let depth = -closest.signed_distance;
        let vn = n.dot(v);
        let fn_ = self.stiffness * depth - self.damping * vn;
        if fn_ <= 0.0 {
            return out;
        }
        out.normal_force = fn_;
        if self.friction > 0.0 {
            out.tangential_force = sliding_friction(self.friction, fn_, &(v - n * vn));
        }
        out
    }

    /// The wrench the tool exerts on this surface, base frame (see the type's docs).
    #[must_use]
    pub fn wrench(&self, p: &Vector3<f64>, v: &Vector3<f64>) -> Wrench {
        let s = self.state(p, v);
        let mut w = Wrench::zeros();
        if s.normal_force > 0.0 {
            let f = s.tangential_force - s.closest.normal * s.normal_force;
            w.fixed_rows_mut::<3>(0).copy_from(&f);
        }
        w
    }
}

/// Most surfaces a [`Scene`] holds (fixed, so a scene never allocates).
pub const MAX_SURFACES: usize = 8;

/// Up to [`MAX_SURFACES`] surfaces; the tool's wrench on the scene is the sum over them.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Scene {
    surfaces: [Option<ContactSurface>; MAX_SURFACES],
    len: usize,
}

impl Scene {
    /// A scene of the given surfaces.
    ///
    /// # Errors
    ///
    /// The count, if more than [`MAX_SURFACES`].
    pub fn new(surfaces: &[ContactSurface]) -> Result<Self, usize> {
        if surfaces.len() > MAX_SURFACES {
            return Err(surfaces.len());
        }
        let mut s = Self::default();
        for (slot, surface) in s.surfaces.iter_mut().zip(surfaces) {
            *slot = Some(*surface);
        }
        s.len = surfaces.len();
        Ok(s)
    }

    /// The surfaces, in order.
    pub fn surfaces(&self) -> impl Iterator<Item = &ContactSurface> {
        self.surfaces[..self.len].iter().flatten()
    }

    /// The surface the tool touches at `p` moving at `v` (the one pushing hardest), or else
    /// the covered one nearest to `p`, with its index and contact state.
    #[must_use]
    pub fn nearest(&self, p: &Vector3<f64>, v: &Vector3<f64>) -> Option<(usize, ContactState)> {
        let mut best: Option<(usize, ContactState)> = None;
        for (i, s) in self.surfaces().enumerate() {
            let c = s.state(p, v);
            let better = match &best {
                None => true,
                Some((_, b)) => {
                    if c.normal_force != b.normal_force {
                        c.normal_force > b.normal_force
                    } else {
                        (c.closest.covered, -c.closest.signed_distance.abs())
                            > (b.closest.covered, -b.closest.signed_distance.abs())
                    }
                }
            };
            if better {
                best = Some((i, c));
            }
        }
        best
    }
}

impl Environment for Scene {
    fn wrench(&self, position: &Vector3<f64>, velocity: &Vector3<f64>) -> Wrench {
        let mut w = Wrench::zeros();
        for s in self.surfaces() {
            w += s.wrench(position, velocity);
        }
        w
    }
}
