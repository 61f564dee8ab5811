//! Dynamic identification on the generated regressor: base parameters, excitation design,
//! measurement on the simulated plant, least-squares estimation, physical consistency and
//! validation.
//!
//! - [`FourierExcitation`]: the excitation trajectories (`no_std`, no allocation).
//! - With feature `std` (dynamic matrices need an allocator): [`BaseParameters`]
//!   (identifiable combinations of the standard parameters, Gautier's numerical method),
//!   [`excitation`] (Fourier coefficients minimising the base regressor's condition number
//!   within the joint limits), [`measurement`] (the excitation tracked on the plant, seeded
//!   torque noise), [`estimation`] (ordinary and weighted least squares), [`consistency`]
//!   (signs and triangle inequalities where the base parameters allow a check), [`identify`]
//!   (all of it, plus validation on another trajectory) and [`file`](mod@file) (`identification.json`
//!   and the controller model read back from it).
//!
//! ```
//! use armdyn::identification::{identify, IdentifySettings};
//! use armdyn::model::Planar2;
//!
//! let mut settings = IdentifySettings::new(0.0, false, 1);
//! settings.excitation.evaluations = 60;
//! let id = identify(&Planar2, &settings).unwrap();
//! // Noise-free data: the base parameters come back to rounding.
//! assert!(id.relative_errors.iter().all(|e| *e < 1e-8));
//! ```

pub mod fourier;
pub use fourier::{FourierExcitation, HARMONICS};

#[cfg(feature = "std")]
pub mod barrier;
#[cfg(feature = "std")]
pub mod base;
#[cfg(feature = "std")]
pub mod consistency;
#[cfg(feature = "std")]
pub mod description_out;
#[cfg(feature = "std")]
mod error;
#[cfg(feature = "std")]
pub mod estimation;
#[cfg(feature = "std")]
pub mod excitation;
#[cfg(feature = "std")]
pub mod file;
#[cfg(feature = "std")]
pub mod filter;
#[cfg(feature = "std")]
pub mod friction_model;
#[cfg(feature = "std")]
pub mod friction_slopes;
#[cfg(feature = "std")]
pub mod from_log;
#[cfg(feature = "std")]
mod identify;
#[cfg(feature = "std")]
pub mod log;
#[cfg(feature = "std")]
pub mod log_cholesky;
#[cfg(feature = "std")]
pub mod log_report;
#[cfg(feature = "std")]
pub mod measurement;
#[cfg(feature = "std")]
pub mod nonlinear;
#[cfg(feature = "std")]
pub mod physical;
#[cfg(feature = "std")]
pub mod processing;
#[cfg(feature = "std")]
pub mod resample;
#[cfg(feature = "std")]
mod robots;
#[cfg(feature = "std")]
mod signals;
#[cfg(feature = "std")]
pub mod sim_log;
#[cfg(feature = "std")]
pub mod stages;
#[cfg(feature = "std")]
pub mod unmodelled;

#[cfg(feature = "std")]
pub use base::BaseParameters;
#[cfg(feature = "std")]
pub use error::IdentificationError;
#[cfg(feature = "std")]
pub use identify::{
    identify, plant_friction, relative_errors, Identification, IdentifySettings, BASE_STATES,
    PERIODS,
};
#[cfg(feature = "std")]
pub use robots::{standard_names, Identifiable, PER_LINK};
#[cfg(feature = "std")]
pub use signals::{friction_names, full_regressor};

/// Without `std`: nothing (the `std` version, in `robots.rs`, implements `Identifiable` for a
/// type of [`robot_type!`](crate::robot_type)).
#[cfg(not(feature = "std"))]
#[doc(hidden)]
#[macro_export]
macro_rules! __identifiable {
    ($($anything:tt)*) => {};
}
