//! Gain design for the force loop along the contact normal: plain functions from a loop
//! model ([`ForceLoop`]: apparent mass, contact stiffness and damping, period, delay) to
//! gains ([`design`]), poles, margins and the stiffness range they tolerate
//! ([`analyse`]), usable without a simulation; and what the actuators allow
//! ([`push_limit`], [`bang_bang_settling`]), the bound below which no gains can settle.
//!
//! The thesis chose `Kfp = 20`, `Kfi = 5`, `Kvd = 2000` by trial and error (Section 5.3)
//! and lists principled gain design as future work; this is that design, for the sampled
//! law of eq. 5.11.
//!
//! ```
//! use armdyn::control::design::{analyse, default_sweep, design, DesignSpec, ForceLoop};
//! let l = ForceLoop::new(4.94, 1e4, 0.0, 1e-3, false).unwrap();
//! let (gains, _) = design(&l, &DesignSpec::new(20.0, 1.0, None).unwrap()).unwrap();
//! let a = analyse(&l, &gains, default_sweep(1e4));
//! assert!(a.stable && a.range.unwrap().k_max > 5e4);
//! ```

mod actuator;
mod analysis;
mod loop_model;
mod placement;

pub use actuator::{bang_bang_settling, push_limit, PushLimit};
pub use analysis::{
    analyse, default_sweep, margins, step_metrics, stiffness_range, well_damped, Analysis, Margins,
    StepMetrics, StiffnessRange, MIN_DAMPING_RATIO,
};
pub use loop_model::{apparent_mass, ForceGains, ForceLoop, Poles};
pub use placement::{design, design_continuous, DesignSpec, DEFAULT_INTEGRAL_RATIO};

/// Why a design or analysis could not be made.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum DesignError {
    /// An input out of range.
    #[error("{what} = {value}: {rule}")]
    Input {
        /// Which input.
        what: &'static str,
        /// Its value.
        value: f64,
        /// The rule broken.
        rule: &'static str,
    },
    /// The robot model cannot give the apparent mass.
    #[error("apparent mass: {0}")]
    Model(&'static str),
    /// The poles cannot be placed.
    #[error("cannot place the poles: {0}")]
    Unplaceable(&'static str),
}
