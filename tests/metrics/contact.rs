//! `metrics/contact.rs`: the force along the real surface's normal, the tangential force and
//! path, contact losses and settling.

use super::{at, times};
use armdyn::contact::{ContactSurface, Scene};
use armdyn::metrics::contact::normal_components;
use armdyn::metrics::ContactMetrics;
use armdyn::surface::SurfaceGeometry;
use nalgebra::Vector3;

/// A plane through the origin whose outward normal is `normal`.
fn plane(normal: Vector3<f64>) -> Scene {
    Scene::new(&[ContactSurface {
        geometry: SurfaceGeometry::plane(Vector3::zeros(), normal, [1.0, 1.0]),
        stiffness: 10_000.0,
        damping: 0.0,
        friction: 0.0,
    }])
    .unwrap()
}

#[test]
fn the_push_is_along_the_real_normal_and_the_rest_is_tangential() {
    let n = Vector3::new(1.0, 0.0, 1.0).normalize();
    let scene = plane(n);
    let mut s = at(0.0);
    // 12 N into the surface and 5 N along it; the reference asks 10 N into it.
    let t = Vector3::new(0.0, 1.0, 0.0);
    let f = -n * 12.0 + t * 5.0;
    s.wrench.fixed_rows_mut::<3>(0).copy_from(&f);
    s.setpoint
        .wrench
        .fixed_rows_mut::<3>(0)
        .copy_from(&(-n * 10.0));
    let (push, push_ref, tangential, normal) = normal_components(&s, &scene);
    assert!((push - 12.0).abs() < 1e-12 && (push_ref - 10.0).abs() < 1e-12);
    assert!((tangential - 5.0).abs() < 1e-12 && (normal - n).norm() < 1e-15);
}

/// 10 s on the plane z = 0, force control from 2 s with 10 N; the tool touches at 1 s,
/// leaves from 3 s to 3.5 s, pushes 14 N until 4 s and 10.3 N from then on, with 3 N of
/// friction and the reference 3 mm, 4 mm off in the tangent plane and 1 cm off along the
/// normal.
fn run(ramp_s: f64, push_of: impl Fn(f64) -> f64) -> armdyn::metrics::ContactSummary {
    let scene = plane(Vector3::z());
    let mut m = ContactMetrics::new(Some(2.0), 10.0, 10.0).with_ramp(ramp_s);
    for t in times(0.01, 10.0) {
        let mut s = at(t);
        s.force_controlled = t >= 2.0 - 1e-12;
        s.setpoint.cartesian.position = Vector3::new(0.003, 0.004, -0.01);
        if s.force_controlled {
            s.setpoint.wrench[2] = -10.0;
        }
        let push = push_of(t);
        if push > 0.0 {
            s.wrench[0] = 3.0;
            s.wrench[2] = -push;
        }
        m.push(&s, &scene);
    }
    m.summary()
}

fn pressing(t: f64) -> f64 {
    match t {
        t if t < 1.0 - 1e-12 => 0.0,
        t if (3.0 - 1e-12..3.5 - 1e-12).contains(&t) => 0.0,
        t if t < 4.0 - 1e-12 => 14.0,
        _ => 10.3,
    }
}

#[test]
fn touch_losses_peaks_overshoot_settling_and_windows() {
    let r = run(0.0, pressing);
    assert_eq!(r.force_start_s, Some(2.0));
    assert_eq!(r.first_touch_s, Some(1.0));
    assert_eq!(r.contact_losses, 1);
    assert_eq!(
        (r.peak_normal_force_n, r.max_tangential_force_n),
        (14.0, 3.0)
    );
    assert!((r.normal_force_overshoot_pct - 40.0).abs() < 1e-12, "{r:?}");
    // Last outside the 0.5 N band at 3.99 s.
    assert!(
        (r.normal_force_settling_time_s.unwrap() - 1.99).abs() < 1e-12,
        "{r:?}"
    );
    assert!(
        (r.normal_force_rms_error_last5s_n - 0.3).abs() < 1e-12,
        "{r:?}"
    );
    assert!(
        (r.normal_force_rms_error_last3s_n - 0.3).abs() < 1e-12,
        "{r:?}"
    );
    assert!((r.normal_force_steady_error_n - 0.3).abs() < 1e-12, "{r:?}");
    // The 1 cm along the normal is not a path error.
    assert!((r.path_rms_error_contact_mm - 5.0).abs() < 1e-9, "{r:?}");
    // Without a ramp, tracking settling is settling.
    assert_eq!(
        r.normal_force_tracking_settling_s,
        r.normal_force_settling_time_s
    );
}

#[test]
fn a_push_that_follows_the_ramp_settles_against_it_at_once() {
    // From 4 N at the switch to 10 N over 1 s, exactly as the controller ramps it.
    let ramped = |t: f64| {
        if t < 2.0 - 1e-12 {
            4.0
        } else {
            4.0 + 6.0 * ((t - 2.0) / 1.0).min(1.0)
        }
    };
    let r = run(1.0, ramped);
    assert_eq!(r.normal_force_tracking_settling_s, Some(0.0));
    // Against the constant reference it was outside the band until the push passed 9.5 N.
    let settled = r.normal_force_settling_time_s.unwrap();
    assert!((settled - 0.91).abs() < 1e-9, "{r:?}");
    assert_eq!(r.normal_force_overshoot_pct, 0.0);
}

#[test]
fn without_force_control_there_is_no_settling() {
    let scene = plane(Vector3::z());
    let mut m = ContactMetrics::new(None, 10.0, 1.0);
    let mut s = at(0.5);
    s.wrench[2] = -20.0;
    m.push(&s, &scene);
    let r = m.summary();
    assert_eq!(r.normal_force_settling_time_s, None);
    assert_eq!(r.normal_force_tracking_settling_s, None);
    assert_eq!((r.peak_normal_force_n, r.first_touch_s), (20.0, Some(0.5)));
    assert_eq!(r.normal_force_overshoot_pct, 0.0);
}
