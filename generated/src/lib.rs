// The functions of this crate are expanded at compile time by `armdyn_runtime::robot_model!`
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
//! Each robot module also holds a submodule `f32` with the same functions in single precision
//! (`armdyn_generated::scara::f32::mass_matrix(&[f32; 4]) -> [[f32; 4]; 4]`, ...): the same
//! expressions with every constant rounded to the nearest `f32` and `libm`'s `f32` routines,
//! for processors whose FPU has no `f64` (on a Cortex-M4F they run in hardware, the `f64` ones
//! in software). Their error against `f64` over the workspace is bounded by the root crate's
//! `tests/model/generated_f32.rs`.
//!
//! And a submodule `lanes` with the same functions over several states at once, generic over
//! a [`lanes::Lane`] type (`armdyn_generated::panda::lanes::mass_matrix_and_bias(&[f64x4; 7],
//! &[f64x4; 7])`, or `f64x2`, or `f64`): the same instructions, each on one double per state,
//! for sweeps, planners and batches (`armdyn::model::batch` packs slices of states into
//! [`lanes::Batch`]). `wide` is a kept portable-SIMD crate on stable Rust (`std::simd` is not
//! stable); its types are SSE2/AVX registers where the target has them and plain arrays
//! elsewhere, so the lanes build for `thumbv7em` too. Their agreement with the `f64` functions
//! is checked by `tests/model/generated_lanes.rs`. The
//! parametric models (`<robot>::parametric`) are `f64` only.
//!
//! **The robot modules are generated — do not edit `models/`, `src/models.rs` or `expanded/`;
//! regenerate with `bash codegen/regenerate.sh`.** The source of
//! truth is `robots/<name>.toml`; the generator writes `models/<name>.json`, which
//! [`armdyn_runtime::robot_model!`] turns into Rust at compile time. The formatted expansions
//! are committed as `expanded/<name>.rs` and checked by a test.
//!
//! # Your own robot
//!
//! Describe it in `robots/<name>.toml` (a DH table, or a URDF with a base and a tip link) and
//! run `bash codegen/regenerate.sh`: it becomes a module here, `armdyn_generated::<name>`, and
//! an entry of `ROBOTS` and `for_each_robot!`. Every robot's module has the same functions,
//! over arrays of its own joint count; for the UR5, read from its URDF:
//!
//! ```
//! use armdyn_generated::ur5;
//!
//! let q = [0.0, -1.57, 1.57, 0.0, 1.57, 0.0]; // rad
//! let qd = [0.0; ur5::DOF];
//! let g = ur5::gravity(&q); // N m, the torques that hold the arm still
//! let tau = ur5::inverse_dynamics(&q, &qd, &[0.0; ur5::DOF]);
//! for (a, b) in g.iter().zip(&tau) {
//!     assert!((a - b).abs() < 1e-12);
//! }
//! let pose = ur5::end_effector_pose(&q); // 4 x 4, base frame, m
//! assert!((pose[3][3] - 1.0).abs() < 1e-15);
//! assert!(armdyn_generated::ROBOTS.contains(&"ur5"));
//! ```
//!
//! # Example
//!
//! ```
//! use armdyn_generated::scara;
//!
//! let q = [0.0; scara::DOF];
//! let m = scara::mass_matrix(&q);
//! // The mass matrix is symmetric.
//! for i in 0..scara::DOF {
//!     for j in 0..scara::DOF {
//!         assert_eq!(m[i][j], m[j][i]);
//!     }
//! }
//! // The single-precision variant agrees to about f32's precision.
//! let m32 = scara::f32::mass_matrix(&[0.0f32; scara::DOF]);
//! assert!((f64::from(m32[0][0]) - m[0][0]).abs() <= 1e-6 * m[0][0].abs());
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

/// The lane types of the `lanes` functions (from `armdyn-runtime`).
pub use armdyn_runtime::lanes;
/// The portable-SIMD crate whose `f64x2` and `f64x4` the lane functions take and return.
pub use armdyn_runtime::wide;

include!("models.rs");
