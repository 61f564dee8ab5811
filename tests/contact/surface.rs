//! Tests of `armdyn::contact::surface`: the reaction surface: zero off it, pushing along the normal
//! in contact; bad parameters refused.

use armdyn::contact::*;
use armdyn::model::Wrench;
use nalgebra::Vector3;

#[test]
fn zero_off_the_surface_and_pushing_down_in_contact() {
    let s = ReactionSurface::new(0.13, [0.2, 0.6], [-0.4, 0.4], 10_000.0).unwrap();
    let v = Vector3::zeros();
    assert_eq!(s.wrench(&Vector3::new(0.5, 0.0, 0.14), &v), Wrench::zeros()); // above
    assert_eq!(s.wrench(&Vector3::new(0.7, 0.0, 0.10), &v), Wrench::zeros()); // beside
    assert_eq!(s.wrench(&Vector3::new(0.5, 0.5, 0.10), &v), Wrench::zeros());
    let w = s.wrench(&Vector3::new(0.5, 0.0, 0.11), &v);
    assert!((w[2] + 200.0).abs() < 1e-9, "{w}"); // 2 cm in at 10 kN/m: the tool pushes down 200 N
    assert_eq!(
        w.fixed_rows::<2>(0).norm() + w.fixed_rows::<3>(3).norm(),
        0.0
    );
}

#[test]
fn bad_parameters_are_refused() {
    assert!(ReactionSurface::new(f64::NAN, [0.0, 1.0], [0.0, 1.0], 1.0).is_err());
    assert!(ReactionSurface::new(0.1, [1.0, 0.0], [0.0, 1.0], 1.0).is_err());
    assert!(ReactionSurface::new(0.1, [0.0, 1.0], [0.0, 1.0], -1.0).is_err());
}
