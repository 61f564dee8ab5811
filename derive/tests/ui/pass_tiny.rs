//! The expansion of a small valid model compiles without warnings, and its functions compute
//! what the instructions say.

#![deny(warnings, missing_docs)]

/// The tiny model.
pub mod tiny {
    armdyn_derive::robot_model!("tests/ui/pass_tiny.json");
}

/// The tiny model with its single-precision functions.
pub mod tiny_both {
    armdyn_derive::robot_model!("tests/ui/pass_tiny.json", f32);
}

/// The tiny model with its single-precision and lane functions, asked in either order.
pub mod tiny_lanes {
    armdyn_derive::robot_model!("tests/ui/pass_tiny.json", lanes, f32);
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

    // The lanes module over f64x4: four states per call, lane k of every output is state k's.
    use wide::f64x4;
    let q4 = [f64x4::new([0.3, -1.0, 2.0, 0.0]), f64x4::new([0.25, 0.1, 0.0, 0.5])];
    let p4 = tiny_lanes::lanes::position(&q4);
    let m4 = tiny_lanes::lanes::mass_matrix(&q4);
    let t4 = tiny_lanes::lanes::misc(
        &[f64x4::splat(-2.0)],
        &[f64x4::splat(1.0), f64x4::splat(2.0), f64x4::new([4.0, -4.0, 0.5, 1e-3])],
    );
    for k in 0..4 {
        let qk = [q4[0].as_array()[k], q4[1].as_array()[k]];
        let (p, m) = (tiny::position(&qk), tiny::mass_matrix(&qk));
        for i in 0..2 {
            assert!(close(p4[i].as_array()[k], p[i]));
            for j in 0..2 {
                assert_eq!(m4[i][j].as_array()[k], m[i][j]);
            }
        }
        let b2 = [4.0, -4.0, 0.5, 1e-3][k];
        let t = tiny::misc(&[-2.0], &[1.0, 2.0, b2]);
        let flat4 = t4.as_flattened().as_flattened();
        for (a, b) in flat4.iter().zip(t.as_flattened().as_flattened()) {
            assert!(close(a.as_array()[k], *b));
        }
    }
    assert_eq!(tiny_lanes::f32::three(), [3.0f32]);

    assert_eq!(tiny::ROBOT_NAME, "tiny");
    assert_eq!(tiny::DOF, 2);
    assert_eq!(tiny::CASADI_VERSION, "3.7.2");
    assert_eq!(tiny::SOURCE_SHA256.len(), 64);
    assert_eq!(tiny::JOINT_NAMES, ["q1", "d2"]);
    assert_eq!(tiny::JOINT_IS_PRISMATIC, [false, true]);
    assert_eq!(tiny::JOINT_LIMITS, [[-3.0, 3.0], [0.0, 0.5]]);
    assert_eq!(tiny::EFFORT_LIMITS, [10.0, 100.0]);
    assert_eq!(tiny::GRAVITY, [0.0, 0.0, -9.81]);
    assert_eq!(tiny::TASK_ROWS, [0, 1]);
    assert_eq!(
        tiny::OPERATION_COUNTS,
        [("position", 2, 2), ("mass_matrix", 3, 0), ("misc", 6, 1), ("three", 0, 0)]
    );
}
