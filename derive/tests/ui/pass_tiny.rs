//! The expansion of a small valid model compiles without warnings, and its functions compute
//! what the instructions say.

#![deny(warnings, missing_docs)]

/// The tiny model.
pub mod tiny {
    scara_derive::robot_model!("tests/ui/pass_tiny.json");
}

/// The tiny model with its single-precision functions.
pub mod tiny_both {
    scara_derive::robot_model!("tests/ui/pass_tiny.json", f32);
}

fn close(a: f64, b: f64) -> bool {
    libm::fabs(a - b) <= 1e-12 * (1.0 + libm::fabs(b))
}

fn main() {
    let q = [0.3, 0.25];
    let p: [f64; 2] = tiny::position(&q);
    assert!(close(p[0], 0.25 * libm::cos(0.3)));
    assert!(close(p[1], 0.25 * libm::sin(0.3)));

    let m: [[f64; 2]; 2] = tiny::mass_matrix(&q);
    assert_eq!(m, [[2.0 + 2.0 * 0.0625, -0.5], [-0.5, 1.25]]);

    let t: [[[f64; 2]; 2]; 2] = tiny::misc(&[-2.0], &[1.0, 2.0, 4.0]);
    let r = libm::sqrt(2.0);
    assert_eq!(
        t,
        [
            [[2.0, 0.25], [2.0, r]],
            [[r - 0.25, (r - 0.25) / 4.0], [libm::atan2(-2.0, 4.0), 1e-3]],
        ]
    );

    assert_eq!(tiny::three(), [3.0]);

    // The f32 module: the same functions, in single precision, with libm's f32 routines.
    let qs = [0.3f32, 0.25];
    let p: [f32; 2] = tiny_both::f32::position(&qs);
    assert!(libm::fabsf(p[0] - 0.25 * libm::cosf(0.3)) <= 1e-7);
    assert!(libm::fabsf(p[1] - 0.25 * libm::sinf(0.3)) <= 1e-7);
    let m: [[f32; 2]; 2] = tiny_both::f32::mass_matrix(&qs);
    assert_eq!(m, [[2.0 + 2.0 * 0.0625, -0.5], [-0.5, 1.25]]);
    let t: [[[f32; 2]; 2]; 2] = tiny_both::f32::misc(&[-2.0], &[1.0, 2.0, 4.0]);
    let r = libm::sqrtf(2.0);
    assert_eq!(
        t,
        [
            [[2.0, 0.25], [2.0, r]],
            [[r - 0.25, (r - 0.25) / 4.0], [libm::atan2f(-2.0, 4.0), 1e-3]],
        ]
    );
    assert_eq!(tiny_both::f32::three(), [3.0f32]);
    assert_eq!(tiny_both::mass_matrix(&q), tiny::mass_matrix(&q));

    assert_eq!(tiny::ROBOT_NAME, "tiny");
    assert_eq!(tiny::DOF, 2);
    assert_eq!(tiny::CASADI_VERSION, "3.7.2");
    assert_eq!(tiny::SOURCE_SHA256.len(), 64);
    assert_eq!(tiny::JOINT_NAMES, ["q1", "d2"]);
    assert_eq!(tiny::JOINT_IS_PRISMATIC, [false, true]);
    assert_eq!(tiny::JOINT_LIMITS, [[-3.0, 3.0], [0.0, 0.5]]);
    assert_eq!(tiny::EFFORT_LIMITS, [10.0, 100.0]);
    assert_eq!(tiny::GRAVITY, [0.0, 0.0, -9.81]);
    assert_eq!(
        tiny::OPERATION_COUNTS,
        [("position", 2, 2), ("mass_matrix", 3, 0), ("misc", 6, 1), ("three", 0, 0)]
    );
}
