//! SCARA kinematics beyond the generated forward model: closed-form inverse kinematics with
//! elbow choice, joint-space references from Cartesian ones, and workspace classification
//! of a whole reference before a run (thesis Sections 3.1.4, 3.1.5 and 4.4).
//!
//! - [`ScaraGeometry`]: link lengths and joint limits read from the generated model;
//!   [`ScaraGeometry::inverse`] (closed form, [`Elbow`] choice),
//!   [`ScaraGeometry::check_limits`], [`ScaraGeometry::joint_target`] (positions,
//!   velocities and accelerations through the reduced Jacobian, damped near the singularity,
//!   [`Conditioning`]).
//! - [`Reachability`] of one pose ([`ScaraGeometry::classify`]) and, with feature `std`, an
//!   [`ElbowPlan`] for a whole sampled reference ([`ScaraGeometry::plan_elbows`]).
//!
//! Nothing here allocates except the planner (feature `std`).
//!
//! # Example
//!
//! ```
//! use scara::kinematics::{Elbow, Reachability, ScaraGeometry};
//! use scara::model::Scara;
//! use nalgebra::Vector3;
//!
//! let ik = ScaraGeometry::from_model(&Scara);
//! let p = Vector3::new(0.25, -0.4, 0.05); // start of the three-zone trial
//! assert_eq!(ik.classify(&p, 0.0), Reachability::DownOnly);
//! let q = ik.inverse(&p, 0.0, Elbow::Down).unwrap();
//! assert!(ik.within_limits(&q));
//! ```

#[cfg(feature = "std")]
pub mod elbow_flip;
pub mod scara_ik;
pub mod workspace;

pub use scara_ik::{
    damped_solve, damping, reduced_jacobian, wrap_angle, Conditioning, Elbow, IkError,
    JointReference, LimitViolation, ScaraGeometry, LIMIT_TOLERANCE, MAX_DAMPING, REACH_TOLERANCE,
    SINGULARITY_THRESHOLD,
};
#[cfg(feature = "std")]
pub use workspace::{
    ElbowPlan, ElbowSwitch, SwitchPolicy, UnreachableSample, UnreachableSamples, WorkspaceError,
    MAX_REPORTED,
};
pub use workspace::{Reachability, Reason};
