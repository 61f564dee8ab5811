// The functions of this crate are expanded at compile time by `scara_derive::robot_model!`
// from the model graphs in `models/*.json`, which `codegen/` writes from `robots/*.toml`. A
// formatted copy of each expansion is in `expanded/*.rs`, for reading.

//! Dynamics and kinematics of each robot, generated from its description.
//!
//! One module per robot in `robots/`, each holding the functions the generator derived
//! (mass matrix, Coriolis matrix, gravity, Jacobian, forward kinematics, ...) as
//! `#[inline] pub fn` over fixed-size arrays, plus constants describing the robot (`DOF`,
//! `JOINT_NAMES`, `JOINT_LIMITS`, `EFFORT_LIMITS`, `GRAVITY`, provenance, operation counts).
//! `no_std`, no allocation, no `unsafe`, no panics: the crate builds for
//! `thumbv7em-none-eabihf`.
//!
//! **The robot modules are generated — do not edit `models/`, `src/models.rs` or `expanded/`;
//! regenerate with `bash codegen/regenerate.sh`.** The source of
//! truth is `robots/<name>.toml`; the generator writes `models/<name>.json`, which
//! [`scara_derive::robot_model!`] turns into Rust at compile time. The formatted expansions
//! are committed as `expanded/<name>.rs` and checked by a test.
//!
//! # Example
//!
//! ```
//! use scara_generated::scara;
//!
//! let q = [0.0; scara::DOF];
//! let m = scara::mass_matrix(&q);
//! // The mass matrix is symmetric.
//! for i in 0..scara::DOF {
//!     for j in 0..scara::DOF {
//!         assert_eq!(m[i][j], m[j][i]);
//!     }
//! }
//! ```
//!
//! # Not checked here
//!
//! The functions evaluate the expressions as generated; they do not check that inputs are
//! finite or within `JOINT_LIMITS`. Numerical agreement with the reference models is tested
//! in the generator and in the root crate.

#![no_std]
#![forbid(unsafe_code)]
#![warn(missing_docs)]

include!("models.rs");
