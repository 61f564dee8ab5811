//! Tests of `armdyn::contact::scene`: the scene: the thesis plane is eq. 5.1 exactly, friction
//! opposes sliding, damping resists penetration and never pulls, the surface in contact is the
//! nearest.

use armdyn::contact::*;
use armdyn::model::Wrench;
use armdyn::surface::SurfaceGeometry;
use nalgebra::Vector3;

fn thesis_plane(friction: f64) -> ContactSurface {
    ContactSurface {
        geometry: SurfaceGeometry::plane(Vector3::new(0.4, 0.0, 0.13), Vector3::z(), [0.2, 0.4]),
        stiffness: 10_000.0,
        damping: 0.0,
        friction,
    }
}

#[test]
fn the_thesis_plane_is_eq_5_1_exactly() {
    let scene = Scene::new(&[thesis_plane(0.0)]).unwrap();
    let thesis = ReactionSurface::new(0.13, [0.2, 0.6], [-0.4, 0.4], 10_000.0).unwrap();
    let v = Vector3::new(0.1, -0.2, 0.3);
    for (x, y, z) in [(0.5, 0.0, 0.11), (0.45, -0.3, 0.1299), (0.5, 0.2, 0.14)] {
        let p = Vector3::new(x, y, z);
        assert_eq!(scene.wrench(&p, &v), thesis.wrench(&p, &v));
    }
}

#[test]
fn friction_opposes_sliding_with_mu_times_the_normal_force() {
    let s = thesis_plane(0.2);
    let p = Vector3::new(0.5, 0.0, 0.11);
    let w = s.wrench(&p, &Vector3::new(0.0, 0.075, 0.0));
    assert!((w[2] + 200.0).abs() < 1e-9);
    // The tool drags the surface along its own motion: +y, 0.2 * 200 N.
    assert!((w[1] - 40.0).abs() < 1e-9 && w[0] == 0.0, "{w}");
    // Below the regularisation speed the force shrinks linearly to zero.
    let slow = s.wrench(&p, &Vector3::new(0.0, 0.001, 0.0));
    assert!((slow[1] - 4.0).abs() < 1e-9, "{slow}");
    assert_eq!(s.wrench(&p, &Vector3::zeros())[1], 0.0);
}

#[test]
fn damping_resists_penetration_and_never_pulls() {
    let mut s = thesis_plane(0.0);
    s.damping = 100.0;
    let p = Vector3::new(0.5, 0.0, 0.129);
    // Moving in at 0.1 m/s: 10 N of stiffness plus 10 N of damping.
    assert!((s.wrench(&p, &Vector3::new(0.0, 0.0, -0.1))[2] + 20.0).abs() < 1e-9);
    // Moving out fast: the damping would pull, so the force is zero.
    assert_eq!(s.wrench(&p, &Vector3::new(0.0, 0.0, 1.0)), Wrench::zeros());
}

#[test]
fn nearest_prefers_the_surface_in_contact() {
    let mut high = thesis_plane(0.0);
    high.geometry = SurfaceGeometry::plane(Vector3::new(0.4, 0.0, 0.2), Vector3::z(), [0.01, 0.01]);
    let scene = Scene::new(&[high, thesis_plane(0.0)]).unwrap();
    let (i, c) = scene
        .nearest(&Vector3::new(0.5, 0.0, 0.12), &Vector3::zeros())
        .unwrap();
    assert_eq!(i, 1);
    assert!((c.normal_force - 100.0).abs() < 1e-9);
    assert!(Scene::new(&[thesis_plane(0.0); MAX_SURFACES + 1]).is_err());
}
