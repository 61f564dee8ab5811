//! Tests of `armdyn::control::design::loop_model`: the force loop's model: its zero-order hold
//! against the exact solution, the continuous limit, the step response, and bad inputs named.

use armdyn::control::design::*;
use nalgebra::Complex;

#[test]
fn zoh_of_a_spring_mass_is_its_exact_solution() {
    let l = ForceLoop::new(2.0, 800.0, 0.0, 1e-3, false).unwrap();
    let (ad, bd) = l.zoh();
    let w = 20.0_f64; // sqrt(800 / 2)
    let (s, c) = (w * 1e-3).sin_cos();
    assert!((ad[(0, 0)] - c).abs() < 1e-14 && (ad[(0, 1)] - s / w).abs() < 1e-14);
    assert!((ad[(1, 0)] + w * s).abs() < 1e-12 && (ad[(1, 1)] - c).abs() < 1e-14);
    assert!((bd[0] - (1.0 - c) / 800.0).abs() < 1e-16);
    assert!((bd[1] - s / (w * 2.0)).abs() < 1e-14);
}

#[test]
fn small_periods_give_the_continuous_cubic() {
    // The continuous analysis (docs/control.md) of the thesis's PI + FF: roots of
    // 4.94 s^3 + 210e3 s + 50e3 (no s^2 term): +0.119 +- 206 j and -0.238.
    // (The hold's lag, w dt / 2, moves the slowly growing pair by about w^2 dt / 4:
    // 0.01 1/s at 1 us, hence the shorter period.)
    let l = ForceLoop::new(4.94, 1e4, 0.0, 1e-8, false).unwrap();
    let mut s: Vec<Complex<f64>> = l.poles(&ForceGains::THESIS).s().collect();
    s.sort_by(|a, b| a.im.total_cmp(&b.im));
    assert!(
        (s[2].re - 0.119).abs() < 1e-3 && (s[2].im - 206.2).abs() < 0.1,
        "{s:?}"
    );
    assert!(
        (s[1].re + 0.238).abs() < 1e-3 && s[1].im.abs() < 1e-6,
        "{s:?}"
    );
    let cubic = |s: Complex<f64>| s * s * s * 4.94 + s * 210e3 + 50e3;
    for p in &s {
        assert!(cubic(*p).norm() < 1e-3 * 210e3 * p.norm(), "{p}");
    }
}

#[test]
fn the_step_response_settles_on_the_reference_when_stable() {
    let l = ForceLoop::new(4.94, 1e4, 0.0, 1e-3, false).unwrap();
    let mut f = vec![0.0; 20_000];
    l.step_response(&ForceGains::THESIS_DAMPED, 200.0, &mut f);
    assert!((f[19_999] - 200.0).abs() < 0.05, "{}", f[19_999]);
    // With a period of delay the same gains still settle, later.
    let d = ForceLoop::new(4.94, 1e4, 0.0, 1e-3, true).unwrap();
    d.step_response(&ForceGains::THESIS_DAMPED, 200.0, &mut f);
    assert!((f[19_999] - 200.0).abs() < 0.05, "{}", f[19_999]);
}

#[test]
fn bad_inputs_are_named() {
    let e = ForceLoop::new(4.94, -1.0, 0.0, 1e-3, false).unwrap_err();
    assert!(e.to_string().contains("contact stiffness"), "{e}");
    let e = ForceLoop::new(4.94, 1e4, 0.0, f64::NAN, false).unwrap_err();
    assert!(e.to_string().contains("period"), "{e}");
}
