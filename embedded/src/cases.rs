//! The fixed inputs that the firmware (`embedded/src/main.rs`) and the host
//! (`tests/embedded_qemu.rs`) both evaluate, and the one function that evaluates them.
//!
//! Both builds compile this same file, so the only thing that can make their outputs differ is
//! the arithmetic of the target: the Cortex-M4F has no double-precision unit, so every `f64`
//! operation there is a software routine (compiler-rt's `__aeabi_d*`), while the host uses the
//! x86 instructions. Both are IEEE 754 with round-to-nearest, and `sin`, `cos` and `sqrt` come
//! from the same `libm` source in both builds (the host's `sqrt` is the hardware one, which is
//! correctly rounded like `libm`'s), so the results are expected to be equal to the last bit.
//!
//! The same holds for the single-precision variants ([`evaluate_f32`]: the generated
//! `armdyn_generated::scara::f32` functions, the deployable hybrid step
//! `armdyn::robots::scara::deploy::ScaraHybrid<f32>` and the same inside its `f32` supervisor,
//! `SupervisedHybrid<f32>`, through a NaN reading), which run on the Cortex-M4F's FPU and on the host's SSE
//! unit, both IEEE 754 single precision with round-to-nearest, with `sinf`/`cosf` from the same
//! `libm` source.

use armdyn::control::hybrid::{HybridForcePosition, JointHybrid};
use armdyn::control::mass_split::SplitKind;
use armdyn::control::pid_fl::PidFeedbackLinearization;
use armdyn::control::safety::SafetyLimits;
use armdyn::control::task_frame::TaskFrame;
use armdyn::control::{Controller, ControllerInput};
use armdyn::model::RobotModel;
use armdyn::model::{Scara, Wrench};
use armdyn::robots::scara::deploy::{HybridInput, ScaraHybrid, SupervisedHybrid};
use armdyn::robots::scara::thesis_setup;
use armdyn::target::CartesianTarget;
use armdyn::target::JointTarget;
use armdyn_generated::scara as g;
use nalgebra::{Vector3, Vector4};

/// Number of states.
pub const CASES: usize = 6;

/// `(q, qd, tau)` per case: positions within the SCARA's limits (rad, rad, m, rad), velocities
/// (rad/s, m/s) and torques (N m, N), chosen generic (no zero or special angle) except case 0,
/// the home configuration at rest holding its own weight.
pub const STATES: [[[f64; 4]; 3]; CASES] = [
    [[0.0, 0.0, 0.2, 0.0], [0.0; 4], [0.0, 0.0, -48.412, 0.0]],
    [
        [0.3, 0.8, 0.2, 0.1],
        [0.2, -0.1, 0.05, 0.3],
        [5.0, -2.0, -40.0, 0.1],
    ],
    [
        [-1.2, 2.1, 0.05, -2.5],
        [1.5, -2.0, -0.3, 4.0],
        [120.0, 35.0, -80.0, -0.4],
    ],
    [
        [1.4, -2.6, 0.33, 2.9],
        [-0.7, 1.9, 0.2, -3.1],
        [-60.0, 15.5, 10.0, 0.25],
    ],
    [
        [0.65, 1.3, 0.12, 0.7],
        [0.05, 0.4, -0.02, 1.1],
        [33.3, -7.25, -55.0, 0.05],
    ],
    [
        [-0.4, -0.9, 0.27, -1.3],
        [-2.2, 0.6, 0.15, -0.8],
        [-210.0, 48.0, -20.0, -0.6],
    ],
];

/// Control period of the controller step, s.
pub const CONTROL_DT: f64 = 1e-3;

/// The thesis's hybrid force/position controller on the SCARA: PID with feedback
/// linearization in position (constant part of `M`, the thesis's rounding), PI + feedforward +
/// velocity damping in force, `S` switched at 2 s, task rows `vx vy vz wz`.
pub type Hybrid = JointHybrid<4, Scara, PidFeedbackLinearization<4, Scara>>;

/// Builds [`Hybrid`]; `None` only if a gain design fails (not for the committed robot).
#[must_use]
pub fn hybrid() -> Option<Hybrid> {
    let position = thesis_setup::thesis_position_loop(SplitKind::ConstantPart)?;
    HybridForcePosition::new(
        Scara,
        position,
        thesis_setup::thesis_force_law(true),
        TaskFrame::along_z(),
        thesis_setup::THESIS_SELECTION,
        [0, 1, 2, 5],
    )
}

/// The controller input of case `k`: after the switch (t = 3 s, so the Jacobian solve and the
/// force loop both run), a reference near the state, and a measured wrench short of the
/// desired -200 N.
pub fn with_step_input<R>(k: usize, f: impl FnOnce(&ControllerInput<'_, 4>) -> R) -> R {
    let [q, qd, _] = STATES[k];
    let (q, qd) = (Vector4::from(q), Vector4::from(qd));
    let target = JointTarget {
        q: q * 1.01,
        qd: qd * 0.9,
        qdd: Vector4::new(0.1, 0.2, 0.0, -0.1),
    };
    let cart = CartesianTarget::at_rest(
        Vector3::new(0.45, -0.1, 0.13),
        armdyn::target::orientation::from_yaw(0.0),
    );
    let wrench = Wrench::new(1.5, -2.0, -150.0 - 10.0 * k as f64, 0.0, 0.0, 0.3);
    let wrench_ref = Wrench::new(0.0, 0.0, -200.0, 0.0, 0.0, 0.0);
    let input = ControllerInput {
        t: 3.0,
        q: &q,
        qd: &qd,
        target: &target,
        cartesian: &cart,
        wrench: &wrench,
        wrench_ref: &wrench_ref,
        wrench_age_s: 0.0,
    };
    f(&input)
}

/// The deployable step of the same controller in single precision.
pub type HybridF32 = ScaraHybrid<f32>;

/// Builds [`HybridF32`] (gains designed in `f64`, rounded); `None` only if the design fails.
#[must_use]
pub fn hybrid_f32() -> Option<HybridF32> {
    ScaraHybrid::thesis().ok()
}

/// [`HybridF32`] inside its own supervisor in `f32`, with the stated default limits for the
/// SCARA pressing 200 N through a noise-free sensor (`SafetyLimits::defaults`).
pub type SupervisedF32 = SupervisedHybrid<f32>;

/// Builds [`SupervisedF32`]; `None` only if the design fails.
#[must_use]
pub fn supervised_f32() -> Option<SupervisedF32> {
    let limits = SafetyLimits::defaults(
        Scara.lower_limits(),
        Scara.upper_limits(),
        Scara.effort_limits(),
        Some(200.0),
        0.0,
    );
    Some(SupervisedHybrid::new(hybrid_f32()?, &limits))
}

/// The input of [`with_step_input`]'s case `k`, each value rounded to `f32`.
#[must_use]
pub fn step_input_f32(k: usize) -> HybridInput<f32> {
    fn single<const N: usize>(x: &[f64]) -> [f32; N] {
        core::array::from_fn(|i| x[i] as f32)
    }
    with_step_input(k, |input| HybridInput {
        t: input.t as f32,
        q: single(input.q.as_slice()),
        qd: single(input.qd.as_slice()),
        q_ref: single(input.target.q.as_slice()),
        qd_ref: single(input.target.qd.as_slice()),
        position_ref: single(input.cartesian.position.as_slice()),
        velocity_ref: single(input.cartesian.velocity.as_slice()),
        force: single(&input.wrench.as_slice()[..3]),
        force_ref: single(&input.wrench_ref.as_slice()[..3]),
    })
}

/// The states of [`STATES`] rounded to `f32`.
#[must_use]
pub fn states_f32() -> [[[f32; 4]; 3]; CASES] {
    STATES.map(|state| state.map(|v| v.map(|x| x as f32)))
}

/// As [`evaluate`], in single precision: the generated `f32` functions and the deployable
/// `f32` hybrid step, at the states rounded to `f32`, in the same order.
///
/// Returns `false` if the controller could not be built.
pub fn evaluate_f32(emit: &mut dyn FnMut(&str, usize, &[f32])) -> bool {
    let (Some(mut controller), Some(mut supervised)) = (hybrid_f32(), supervised_f32()) else {
        return false;
    };
    for (k, [q, qd, tau]) in states_f32().iter().enumerate() {
        let m = g::f32::mass_matrix(q);
        emit("mass_matrix", k, m.as_flattened());
        emit("coriolis", k, &g::f32::coriolis(q, qd));
        emit("gravity", k, &g::f32::gravity(q));
        emit("forward_dynamics", k, &g::f32::forward_dynamics(q, qd, tau));
        let u = controller.step(&step_input_f32(k), CONTROL_DT as f32);
        emit("hybrid_step", k, &u);
        let u = supervised.step(&step_input_f32(k), 0.0, CONTROL_DT as f32);
        emit("supervised_step", k, &u);
    }
    // Then a NaN force reading: the supervisor trips and holds (case 1's state); the torque,
    // the trip's time and the count of trips.
    let mut input = step_input_f32(1);
    input.force[2] = f32::NAN;
    input.t += CONTROL_DT as f32;
    let u = supervised.step(&input, 0.0, CONTROL_DT as f32);
    emit("supervised_step_nan", 1, &u);
    let trips = supervised.monitor().trips();
    let first = trips.first().map_or(f32::NAN, |t| t.t);
    emit("supervised_trip", 1, &[first, trips.len() as f32]);
    true
}

/// Evaluates every function at every case, in a fixed order (case by case, functions `mass_matrix`,
/// `coriolis`, `gravity`, `forward_dynamics`, `hybrid_step`), handing each result to `emit(function, case, values)`. The
/// controller is stepped once per case, in case order, from a fresh [`hybrid`] (its
/// integrators carry over from case to case, identically in both builds).
///
/// Returns `false` if the controller could not be built.
pub fn evaluate(emit: &mut dyn FnMut(&str, usize, &[f64])) -> bool {
    let Some(mut controller) = hybrid() else {
        return false;
    };
    for (k, [q, qd, tau]) in STATES.iter().enumerate() {
        let m = g::mass_matrix(q);
        emit("mass_matrix", k, m.as_flattened());
        emit("coriolis", k, &g::coriolis(q, qd));
        emit("gravity", k, &g::gravity(q));
        emit("forward_dynamics", k, &g::forward_dynamics(q, qd, tau));
        let u = with_step_input(k, |input| controller.step(input, CONTROL_DT));
        emit("hybrid_step", k, u.as_slice());
    }
    true
}
