//! The thesis's 4-DOF SCARA (`robots/scara.toml`): its own code, used through the generic
//! interfaces of the rest of the crate.
//!
//! - [`ScaraGeometry`]: link lengths and joint limits read from the generated model;
//!   closed-form inverse kinematics with [`Elbow`] choice ([`ScaraGeometry::inverse`]),
//!   joint-space references through the reduced Jacobian, damped near the singularity
//!   ([`ScaraGeometry::joint_target`], [`Conditioning`]) (thesis Sections 3.1.4, 3.1.5, 3.2.2);
//!   [`ClosedFormIk`]: the closed form behind the generic
//!   [`InverseKinematics`](crate::kinematics::InverseKinematics) interface.
//! - [`Reachability`] of one pose ([`ScaraGeometry::classify`]) and, with feature `std`, an
//!   [`ElbowPlan`] for a whole sampled reference ([`ScaraGeometry::plan_elbows`]), the
//!   workspace zones of Section 4.4.
//! - `elbow_flip` (feature `std`): a planned change of elbow.
//! - [`thesis`]: the thesis's references (position test, contact test, three-zone trial).
//! - `reference` (feature `std`): the SCARA's joint reference from a Cartesian one (elbow
//!   plan, planned flips, inverse kinematics at every sample).
//! - [`deploy`]: the hybrid step for a microcontroller, in `f32` or `f64`.
//! - `presets` (feature `std`): the thesis's controller line-up on the SCARA.
//!
//! # Example
//!
//! ```
//! use armdyn::robots::scara::{Elbow, Reachability, ScaraGeometry};
//! use armdyn::model::Scara;
//! use nalgebra::Vector3;
//!
//! let ik = ScaraGeometry::from_model(&Scara);
//! let p = Vector3::new(0.25, -0.4, 0.05); // start of the three-zone trial
//! assert_eq!(ik.classify(&p, 0.0), Reachability::DownOnly);
//! let q = ik.inverse(&p, 0.0, Elbow::Down).unwrap();
//! assert!(ik.within_limits(&q));
//! ```

pub mod deploy;
#[cfg(feature = "std")]
pub mod elbow_flip;
#[cfg(feature = "std")]
pub mod elbow_keys;
#[cfg(feature = "std")]
pub mod elbow_plan;
pub mod geometry;
mod ik;
pub mod joint_target;
#[cfg(feature = "std")]
pub mod presets;
#[cfg(feature = "std")]
pub mod reference;
#[cfg(feature = "std")]
pub mod scenario;
pub mod singularity;
pub mod thesis;
pub mod thesis_setup;
pub mod workspace;

#[cfg(feature = "std")]
pub use elbow_plan::{
    ElbowPlan, ElbowSwitch, SwitchPolicy, UnreachableSample, UnreachableSamples, WorkspaceError,
    MAX_REPORTED,
};
pub use geometry::{
    Elbow, IkError, LimitViolation, ScaraGeometry, LIMIT_TOLERANCE, REACH_TOLERANCE,
};
pub use ik::ClosedFormIk;
pub use joint_target::JointReference;
pub use singularity::{
    damped_solve, damping, reduced_jacobian, Conditioning, DampedSolver, MAX_DAMPING,
    SINGULARITY_THRESHOLD,
};
pub use workspace::{Reachability, Reason};

/// The task rows of the SCARA's 6 x 4 Jacobian a Cartesian controller keeps: `vx vy vz wz`
/// (its rows `wx wy` are zero), so that the reduced Jacobian is square.
pub const TASK_ROWS: [usize; 4] = [0, 1, 2, 5];
