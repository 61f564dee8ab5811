//! Tests of `armdyn::control::design::analysis`: the force loop's analysis: the thesis's gains
//! (PI+FF unstable, PI+FF+VD stable, with margins), the gain margin, the stiffness range and a
//! designed step's bandwidth.

use armdyn::control::design::*;

#[test]
fn the_thesis_gains_pi_ff_unstable_pi_ff_vd_stable_with_margins() {
    let l = ForceLoop::new(4.94, 1e4, 0.0, 1e-3, false).unwrap();
    let a = analyse(&l, &ForceGains::THESIS, default_sweep(1e4));
    assert!(!a.stable && a.range.is_none());
    // The 33 Hz mode grows: faster at 1 ms than the continuous +0.119 1/s.
    let growth = a.poles.s().map(|s| s.re).fold(f64::MIN, f64::max);
    assert!(growth > 1.0, "{growth}");
    let b = analyse(&l, &ForceGains::THESIS_DAMPED, default_sweep(1e4));
    assert!(b.stable, "{:?}", b.poles);
    assert!(b.margins.gain_up.unwrap() > 2.0, "{:?}", b.margins);
    assert!(b.margins.phase_deg.unwrap() > 45.0, "{:?}", b.margins);
}

#[test]
fn the_gain_margin_is_where_the_poles_leave_the_circle() {
    let l = ForceLoop::new(4.94, 1e4, 0.0, 1e-3, false).unwrap();
    let (g, _) = design(&l, &DesignSpec::new(20.0, 1.0, None).unwrap()).unwrap();
    let m = margins(&l, &g);
    let up = m.gain_up.unwrap();
    let s = |f: f64| ForceGains {
        kfp: g.kfp * f,
        kfi: g.kfi * f,
        kvd: g.kvd * f,
    };
    assert!(l.poles(&s(up * 0.999)).stable() && !l.poles(&s(up * 1.001)).stable());
}

#[test]
fn the_stiffness_range_ends_where_the_damping_margin_does() {
    let l = ForceLoop::new(4.94, 1e4, 0.0, 1e-3, false).unwrap();
    let (g, _) = design(&l, &DesignSpec::new(20.0, 1.0, None).unwrap()).unwrap();
    let r = stiffness_range(&l, &g, default_sweep(1e4)).unwrap();
    assert!(r.k_min <= 2e3 && r.k_max >= 5e4, "{r:?}");
    assert!(!r.k_max_is_sweep_end);
    let ok = |k: f64| well_damped(&l.with_stiffness(k).poles(&g));
    assert!(ok(r.k_max) && !ok(r.k_max * 1.001));
    // The thesis's damped gains keep a range too (their slow integral pole is real).
    assert!(stiffness_range(&l, &ForceGains::THESIS_DAMPED, default_sweep(1e4)).is_some());
}

#[test]
fn the_designed_step_meets_its_bandwidth() {
    let l = ForceLoop::new(4.94, 1e4, 0.0, 1e-3, false).unwrap();
    let (g, _) = design(&l, &DesignSpec::new(20.0, 1.0, None).unwrap()).unwrap();
    let s = step_metrics(&l, &g, 5.0);
    // Critically damped at 20 Hz: 5 % reached in about 4.74 / w = 38 ms.
    assert!(s.settling_s.unwrap() < 0.05, "{s:?}");
    assert!(s.overshoot_pct < 2.0, "{s:?}");
}
