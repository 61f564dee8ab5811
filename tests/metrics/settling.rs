//! `metrics/settling.rs`: the settling time against a band.

use armdyn::metrics::Settling;

#[test]
fn an_error_never_outside_the_band_settles_at_once() {
    let mut s = Settling::new(0.5);
    for k in 0..100 {
        // On the band's edge is inside it.
        s.push(k as f64 * 0.01, if k % 2 == 0 { 0.5 } else { -0.5 });
    }
    assert_eq!(s.time_after(0.2, 1.0), Some(0.0));
}

#[test]
fn the_settling_time_is_the_last_time_outside_less_the_start() {
    let mut s = Settling::new(0.5);
    // A decaying oscillation 2 exp(-3 t) cos(20 t) from t = 1 s.
    let mut last_outside = None;
    for k in 0..=300 {
        let t = 1.0 + k as f64 * 0.01;
        let e = 2.0 * (-3.0 * (t - 1.0)).exp() * (20.0 * (t - 1.0)).cos();
        s.push(t, e);
        if e.abs() > 0.5 {
            last_outside = Some(t);
        }
    }
    let last = last_outside.unwrap();
    assert!(last > 1.2 && last < 1.5, "{last}");
    assert!((s.time_after(1.0, 4.0).unwrap() - (last - 1.0)).abs() < 1e-15);
}

#[test]
fn an_error_still_outside_at_the_end_has_not_settled() {
    let mut s = Settling::new(0.5);
    s.push(0.5, 0.1);
    s.push(1.0, -0.6);
    assert_eq!(s.time_after(0.0, 1.0), None);
    // Outside only before the end: settled.
    assert_eq!(s.time_after(0.0, 2.0), Some(1.0));
}
