//! Model-based control of robot arms, built on generated, allocation-free dynamics.
//!
//! The robot models come from `scara-generated`: a Python + CasADi generator turns a
//! robot description (`robots/*.toml`, standard Denavit–Hartenberg, SI units) into
//! expression graphs, and a proc-macro turns those into `no_std` Rust functions over
//! fixed-size arrays. This crate puts them behind one trait, [`model::RobotModel`], and
//! adds what every controller and the simulator need on top: forward dynamics by a
//! fixed-size Cholesky solve and inverse dynamics.
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
//! # Example
//!
//! ```
//! use scara::model::{RobotModel, Scara, forward_dynamics};
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
//! - `std` (default): the `scara` command-line tool and its dependencies. Without it the
//!   library is `no_std` and never allocates.
#![cfg_attr(not(feature = "std"), no_std)]
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod contact;
pub mod control;
#[cfg(feature = "std")]
mod csv_text;
pub mod identification;
pub mod kinematics;
mod math;
pub mod metrics;
pub mod model;
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
