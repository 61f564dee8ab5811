//! Model-based control of robot arms, built on generated, allocation-free dynamics.
//!
//! The robot models come from `armdyn-generated`: a Python + CasADi generator turns a
//! robot description (`robots/*.toml`: a Denavit–Hartenberg table or a URDF, SI units) into
//! expression graphs, and a proc-macro turns those into `no_std` Rust functions over
//! fixed-size arrays. This crate puts them behind one trait, [`model::RobotModel`], and
//! adds what every controller and the simulator need on top: forward dynamics by a
//! fixed-size Cholesky solve and inverse dynamics.
//!
//! # Your own robot
//!
//! A robot described in `robots/<name>.toml` and generated (`bash codegen/regenerate.sh`) is a
//! type of [`model`] with every generated function behind [`model::RobotModel`], and runs
//! through everything above it: inverse kinematics, the controllers, the simulator, scenario
//! files and sweeps. Here the UR5 (the model of its URDF) is put at a Cartesian pose by the
//! numerical inverse kinematics, and held there by its gravity torques:
//!
//! ```
//! use nalgebra::{SVector, Vector3};
//! use armdyn::kinematics::{IkOptions, InverseKinematics, NumericalIk};
//! use armdyn::model::{forward_dynamics, RobotModel, Ur5};
//! use armdyn::target::{orientation, CartesianTarget};
//!
//! let robot = Ur5;
//! // Tool 0.5 m in front of the base and 0.3 m up, pointing down (fixed-axis roll, pitch, yaw).
//! let goal = CartesianTarget::at_rest(
//!     Vector3::new(0.5, 0.1, 0.3),
//!     orientation::from_rpy(0.0, std::f64::consts::FRAC_PI_2, 0.0),
//! );
//! let seed = SVector::<f64, 6>::new(0.0, -1.57, 1.57, -1.57, -1.57, 0.0);
//! let q = NumericalIk::new(robot, IkOptions::default()).solve(&goal, &seed).unwrap().q;
//! let pose = robot.end_effector_pose(&q);
//! assert!((pose.fixed_view::<3, 1>(0, 3) - goal.position).norm() < 1e-9);
//! // Holding still there: the gravity torques give zero acceleration.
//! let zero = SVector::<f64, 6>::zeros();
//! let qdd = forward_dynamics(&robot, &q, &zero, &robot.gravity(&q), &zero).unwrap();
//! assert!(qdd.norm() < 1e-9);
//! ```
//!
//! # Conventions
//!
//! The dynamics convention is the thesis's (McDonald 2022, Section 3.3):
//!
//! ```text
//! tau = M(q) qdd + c(q, qd) + g(q) + J(q)^T f_ext
//! ```
//!
//! with `f_ext` the wrench the end effector exerts on the environment, in the base frame,
//! ordered `[fx fy fz tx ty tz]`.
//!
//! # The SCARA of the thesis
//!
//! ```
//! use armdyn::model::{RobotModel, Scara, forward_dynamics};
//! use nalgebra::SVector;
//!
//! let robot = Scara;
//! let q = SVector::<f64, 4>::new(0.1, -0.4, 0.2, 0.0);
//! let qd = SVector::<f64, 4>::zeros();
//! // Holding still: the torque that cancels gravity gives zero acceleration.
//! let tau = robot.gravity(&q);
//! let qdd = forward_dynamics(&robot, &q, &qd, &tau, &SVector::zeros()).unwrap();
//! assert!(qdd.norm() < 1e-12);
//! ```
//!
//! # Features
//!
//! - `std` (default): the `armdyn` command-line tool and its dependencies. Without it the
//!   library is `no_std` and never allocates.
#![cfg_attr(not(feature = "std"), no_std)]
#![forbid(unsafe_code)]
#![warn(missing_docs)]

/// The linear algebra crate of every type here (`JointVector<N>` is `nalgebra::SVector<f64, N>`):
/// use this one, so that the versions agree.
pub use nalgebra;

/// The generated functions, for the macros ([`with_robot_named!`]).
#[doc(hidden)]
pub use armdyn_generated as __generated;

pub mod contact;
pub mod control;
#[cfg(feature = "std")]
pub mod csv_text;
pub mod identification;
pub mod kinematics;
mod math;
pub mod metrics;
pub mod model;
#[cfg(feature = "std")]
pub mod optimal;
#[cfg(feature = "std")]
pub mod report;
pub mod robots;
#[cfg(feature = "std")]
pub mod scenario;
pub mod sim;
pub mod surface;
#[cfg(feature = "std")]
pub mod sweep;
pub mod target;
pub mod trajectory;
