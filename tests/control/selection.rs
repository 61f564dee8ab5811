//! Tests of `armdyn::control::selection`: the contact decision: the time policy, the contact
//! policy's debounce and ramp, and the approach and its resumption after a loss.

use armdyn::control::selection::*;

fn contact() -> ModeSelector {
    ModeSelector::new(SelectionPolicy::Contact(ContactSwitch::for_sensor(
        0.0, 0.0,
    )))
}

#[test]
fn time_policy_switches_at_its_time() {
    let mut s = ModeSelector::new(SelectionPolicy::Time { switch_s: 2.0 });
    assert!(matches!(
        s.step(1.999, 1e-3, 0.0, 0.0, None, None),
        Decision::Position { .. }
    ));
    assert!(matches!(
        s.step(2.0, 1e-3, 0.0, 0.0, None, None),
        Decision::Force { ramp, .. } if ramp == 1.0
    ));
}

#[test]
fn contact_needs_the_debounce_then_ramps() {
    let mut s = contact();
    let dt = 1e-3;
    // Noise-like blips shorter than the debounce do not switch.
    for k in 0..10 {
        let push = if k % 2 == 0 { 5.0 } else { 0.0 };
        let d = s.step(k as f64 * dt, dt, push, -push, Some(0.01), Some(0.01));
        assert!(matches!(d, Decision::Position { .. }));
    }
    let mut switched_at = None;
    for k in 10..20 {
        let t = k as f64 * dt;
        if let Decision::Force {
            just_switched: true,
            from_n,
            ..
        } = s.step(t, dt, 5.0, -5.0, Some(0.0), Some(0.0))
        {
            assert_eq!(from_n, -5.0);
            switched_at = Some(t);
            break;
        }
    }
    assert!(
        (switched_at.unwrap() - 0.012).abs() < 1e-12,
        "{switched_at:?}"
    );
    let Decision::Force { ramp, .. } = s.step(0.037, dt, 50.0, -50.0, None, None) else {
        panic!("still force controlled")
    };
    assert!((ramp - 0.5).abs() < 1e-9);
}

#[test]
fn approach_starts_at_the_expected_surface_and_resumes_after_loss() {
    let mut s = contact();
    let dt = 1e-3;
    assert!(matches!(
        s.step(0.0, dt, 0.0, 0.0, Some(0.001), Some(0.001)),
        Decision::Position { offset_m, .. } if offset_m == 0.0
    ));
    s.step(0.1, dt, 0.0, 0.0, Some(0.0), Some(0.0));
    let Decision::Position {
        offset_m,
        offset_rate_m_s,
    } = s.step(0.2, dt, 0.0, 0.0, Some(-0.001), Some(0.0))
    else {
        panic!("approach")
    };
    assert!((offset_m - 0.002).abs() < 1e-12 && offset_rate_m_s == 0.02);
    for k in 0..3 {
        s.step(
            0.3 + k as f64 * dt,
            dt,
            10.0,
            -10.0,
            Some(0.0),
            Some(-0.001),
        );
    }
    assert!(matches!(s.phase(), Phase::Force { .. }));
    // Lost for 20 ms: back to the approach, offset from the tool's gap (3 mm up).
    let mut last = None;
    for k in 0..25 {
        last = Some(s.step(0.4 + k as f64 * dt, dt, 0.0, 0.0, Some(0.0), Some(-0.003)));
    }
    assert!(
        matches!(s.phase(), Phase::Approach { .. }),
        "{:?}",
        s.phase()
    );
    assert!(matches!(last, Some(Decision::Position { offset_m, .. }) if offset_m > 0.003));
    assert_eq!(s.switches(), 1);
}
