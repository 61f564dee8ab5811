//! Tests of `armdyn::control::design::actuator`: the actuator's push bound: the closed form of
//! push and brake without a spring, and the SCARA pushing down with d3 alone.

use approx::assert_relative_eq;
use armdyn::control::design::*;
use armdyn::model::{JointVector, RobotModel, Scara};
use nalgebra::Vector3;

#[test]
fn without_a_spring_the_bound_is_the_closed_form_of_push_and_brake() {
    // k so soft that the spring force (at most 0.1 N) is negligible against 100 N: push
    // to half of the 1.02 D stop, brake symmetrically, meet the band 0.07 D before the
    // stop: t = sqrt(D m / F) (2 sqrt(1.02) - sqrt(0.14)).
    let (d, m, f) = (0.1, 5.0, 100.0);
    let limit = PushLimit {
        max_force_n: f,
        gravity_n: 0.0,
        mass_kg: m,
    };
    let t = bang_bang_settling(&limit, 1.0, 0.0, d).unwrap();
    let expected = (d * m / f).sqrt() * (2.0 * 1.02f64.sqrt() - 0.14f64.sqrt());
    assert!((t - expected).abs() < 5e-4, "{t} s against {expected} s");
    // More force, sooner; gravity helping, sooner; no switch stops in 0.2 s: none.
    let stronger = PushLimit {
        max_force_n: 2.0 * f,
        ..limit
    };
    assert!(bang_bang_settling(&stronger, 1.0, 0.0, d).unwrap() < t);
    let helped = PushLimit {
        gravity_n: 20.0,
        ..limit
    };
    assert!(bang_bang_settling(&helped, 1.0, 0.0, d).unwrap() < t);
    assert_eq!(bang_bang_settling(&limit, 1.0, 0.0, 100.0), None);
}

#[test]
fn the_scara_pushes_down_with_d3_alone() {
    // Along -z only d3 is loaded: its 1000 N limit, its weight helping, the mass it moves.
    let q = JointVector::<4>::new(0.3, 0.8, 0.2, 0.1);
    let p = push_limit(&Scara, &q, &Vector3::new(0.0, 0.0, -1.0)).unwrap();
    assert_relative_eq!(
        p.max_force_n,
        <Scara as RobotModel<4>>::EFFORT_LIMITS[2],
        max_relative = 1e-12
    );
    let m = Scara.mass_matrix(&q);
    assert_relative_eq!(p.mass_kg, m[(2, 2)], max_relative = 1e-12);
    let weight = Scara.gravity(&q)[2].abs();
    assert_relative_eq!(p.gravity_n, weight, max_relative = 1e-12);
    assert!(weight > 40.0);
}
