//! [`ScaraHybrid`] behind the simulator's [`Controller`] trait: the `f64` inputs rounded to
//! `T`, the torques returned as `f64`, so a trial runs the deployable step in either precision
//! against the usual `f64` plant.

use nalgebra::Vector4;

use super::hybrid::{HybridInput, ScaraHybrid};
use super::scalar::ScaraScalar;
use crate::control::{Controller, ControllerInput};
use crate::model::JointVector;

/// The deployable hybrid step in precision `T` as a [`Controller<4>`].
///
/// ```
/// use scara::control::Controller;
/// use scara::robots::scara::deploy::{Deployed, ScaraHybrid};
/// let c = Deployed::new(ScaraHybrid::<f32>::thesis().unwrap());
/// assert_eq!(c.name(), "hybrid-pi-ff-vd-f32");
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Deployed<T: ScaraScalar> {
    step: ScaraHybrid<T>,
}

impl<T: ScaraScalar> Deployed<T> {
    /// Wraps a deployable step.
    #[must_use]
    pub fn new(step: ScaraHybrid<T>) -> Self {
        Self { step }
    }

    /// The step.
    #[must_use]
    pub fn inner(&self) -> &ScaraHybrid<T> {
        &self.step
    }
}

fn cast<T: ScaraScalar, const N: usize>(x: &[f64]) -> [T; N] {
    core::array::from_fn(|i| T::round_from(x[i]))
}

impl<T: ScaraScalar> Controller<4> for Deployed<T> {
    fn name(&self) -> &'static str {
        match (self.step.velocity_damping(), T::BITS) {
            (true, 32) => "hybrid-pi-ff-vd-f32",
            (true, _) => "hybrid-pi-ff-vd-f64",
            (false, 32) => "hybrid-pi-ff-f32",
            (false, _) => "hybrid-pi-ff-f64",
        }
    }

    fn reset(&mut self) {
        self.step.reset();
    }

    fn force_controlled(&self) -> bool {
        self.step.force_controlled()
    }

    fn step(&mut self, input: &ControllerInput<'_, 4>, dt: f64) -> JointVector<4> {
        let x = HybridInput {
            t: T::round_from(input.t),
            q: cast(input.q.as_slice()),
            qd: cast(input.qd.as_slice()),
            q_ref: cast(input.target.q.as_slice()),
            qd_ref: cast(input.target.qd.as_slice()),
            position_ref: cast(input.cartesian.position.as_slice()),
            velocity_ref: cast(input.cartesian.velocity.as_slice()),
            force: cast(&input.wrench.as_slice()[..3]),
            force_ref: cast(&input.wrench_ref.as_slice()[..3]),
        };
        let tau = self.step.step(&x, T::round_from(dt));
        Vector4::from(tau.map(T::widen))
    }
}
