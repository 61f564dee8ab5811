//! Faults of the environment: a surface that ends, a stiffness step, a dropped payload.

use crate::contact::{Environment, Scene};
use crate::model::Wrench;
use nalgebra::Vector3;

/// An edge across a surface: contact only where `(p - point) . beyond <= 0`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfaceEdge {
    /// The surface's index in the scene.
    pub surface: usize,
    /// A point of the edge, m, base frame.
    pub point: Vector3<f64>,
    /// Unit direction, in the surface's tangent plane, pointing off the surface.
    pub beyond: Vector3<f64>,
}

/// A scene with time-dependent faults: an edge across one surface, one surface's stiffness
/// multiplied from a time on, and a payload of `m` kg held by the tool until a time (its
/// weight only: the tool exerts `-m g` on it, base frame; its inertia, `m a`, is left out).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FaultyEnvironment {
    /// The real surfaces as they start.
    pub scene: Scene,
    /// An edge.
    pub edge: Option<SurfaceEdge>,
    /// `(surface, from_s, factor)`: the stiffness multiplied by `factor` from `from_s` on.
    pub stiffness_step: Option<(usize, f64, f64)>,
    /// `(mass_kg, drop_s, gravity)`: a payload held until `drop_s`, gravity in m/s^2.
    pub payload: Option<(f64, f64, Vector3<f64>)>,
}

impl FaultyEnvironment {
    /// No fault in `scene`.
    #[must_use]
    pub fn new(scene: Scene) -> Self {
        Self {
            scene,
            edge: None,
            stiffness_step: None,
            payload: None,
        }
    }
}

impl Environment for FaultyEnvironment {
    /// The wrench without its time-dependent faults (the surfaces as they start, the edge
    /// included): [`Environment::wrench_at`] is the one the simulator uses.
    fn wrench(&self, position: &Vector3<f64>, velocity: &Vector3<f64>) -> Wrench {
        self.wrench_at(0.0, position, velocity)
    }

    fn wrench_at(&self, t: f64, position: &Vector3<f64>, velocity: &Vector3<f64>) -> Wrench {
        let mut w = Wrench::zeros();
        for (i, s) in self.scene.surfaces().enumerate() {
            if let Some(e) = self.edge {
                if e.surface == i && (position - e.point).dot(&e.beyond) > 0.0 {
                    continue;
                }
            }
            let mut s = *s;
            if let Some((j, from_s, factor)) = self.stiffness_step {
                if j == i && t >= from_s {
                    s.stiffness *= factor;
                }
            }
            w += s.wrench(position, velocity);
        }
        if let Some((m, drop_s, g)) = self.payload {
            if t < drop_s {
                let f = -g * m;
                for a in 0..3 {
                    w[a] += f[a];
                }
            }
        }
        w
    }
}
