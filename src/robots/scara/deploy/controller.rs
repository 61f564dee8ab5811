//! [`ScaraHybrid`] (bare or [`SupervisedHybrid`]) behind the simulator's [`Controller`]
//! trait: the `f64` inputs rounded to `T`, the torques returned as `f64`, so a trial runs the
//! deployable step in either precision against the usual `f64` plant.

use nalgebra::Vector4;

use super::hybrid::{HybridInput, ScaraHybrid};
use super::scalar::ScaraScalar;
use super::supervised::SupervisedHybrid;
use crate::control::{Controller, ControllerInput, StepReport};
use crate::model::JointVector;

/// The deployable hybrid step in precision `T` as a [`Controller<4>`].
///
/// ```
/// use armdyn::control::Controller;
/// use armdyn::robots::scara::deploy::{Deployed, ScaraHybrid};
/// let c = Deployed::new(ScaraHybrid::<f32>::thesis().unwrap());
/// assert_eq!(c.name(), "hybrid-pi-ff-vd-f32");
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Deployed<T: ScaraScalar> {
    step: Step<T>,
}

/// The step, bare or supervised.
#[derive(Clone, Debug, PartialEq)]
enum Step<T: ScaraScalar> {
    Bare(ScaraHybrid<T>),
    Supervised(SupervisedHybrid<T>),
}

impl<T: ScaraScalar> Deployed<T> {
    /// Wraps a deployable step.
    #[must_use]
    pub fn new(step: ScaraHybrid<T>) -> Self {
        Self {
            step: Step::Bare(step),
        }
    }

    /// Wraps a deployable step inside its own supervisor (in `T`).
    #[must_use]
    pub fn supervised(step: SupervisedHybrid<T>) -> Self {
        Self {
            step: Step::Supervised(step),
        }
    }

    /// The hybrid step.
    #[must_use]
    pub fn inner(&self) -> &ScaraHybrid<T> {
        match &self.step {
            Step::Bare(s) => s,
            Step::Supervised(s) => s.inner(),
        }
    }
}

fn cast<T: ScaraScalar, const N: usize>(x: &[f64]) -> [T; N] {
    core::array::from_fn(|i| T::round_from(x[i]))
}

impl<T: ScaraScalar> Controller<4> for Deployed<T> {
    fn name(&self) -> &'static str {
        match (self.inner().velocity_damping(), T::BITS) {
            (true, 32) => "hybrid-pi-ff-vd-f32",
            (true, _) => "hybrid-pi-ff-vd-f64",
            (false, 32) => "hybrid-pi-ff-f32",
            (false, _) => "hybrid-pi-ff-f64",
        }
    }

    fn reset(&mut self) {
        match &mut self.step {
            Step::Bare(s) => s.reset(),
            Step::Supervised(s) => s.reset(),
        }
    }

    /// Whether the step controls the force, and the supervisor's report widened to `f64`
    /// (`None` for a bare step).
    fn report(&self) -> StepReport<4> {
        let (force_controlled, safety) = match &self.step {
            Step::Bare(s) => (s.force_controlled(), None),
            Step::Supervised(s) => (s.force_controlled(), Some(s.monitor().report())),
        };
        StepReport {
            force_controlled,
            safety,
            ..StepReport::default()
        }
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
        let dt = T::round_from(dt);
        let tau = match &mut self.step {
            Step::Bare(s) => s.step(&x, dt),
            Step::Supervised(s) => s.step(&x, T::round_from(input.wrench_age_s), dt),
        };
        Vector4::from(tau.map(T::widen))
    }
}
