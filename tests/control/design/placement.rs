//! Tests of `armdyn::control::design::placement`: pole placement: the placed poles are the
//! requested ones, the continuous limit, a placement by hand, and bad specifications named.

use armdyn::control::design::*;
use nalgebra::Complex;

fn sorted(mut v: Vec<Complex<f64>>) -> Vec<Complex<f64>> {
    v.sort_by(|a, b| a.re.total_cmp(&b.re).then(a.im.total_cmp(&b.im)));
    v
}

#[test]
fn the_placed_poles_are_the_requested_ones() {
    for (k, c, delay, zeta) in [
        (1e4, 0.0, false, 0.7),
        (1e3, 50.0, false, 1.3),
        (1e5, 0.0, false, 0.9),
        (1e4, 0.0, true, 0.8),
    ] {
        let l = ForceLoop::new(4.94, k, c, 1e-3, delay).unwrap();
        let spec = DesignSpec::new(20.0, zeta, Some(1.0)).unwrap();
        let (_, poles) = design(&l, &spec).unwrap();
        let want = sorted(
            spec.continuous_poles()
                .iter()
                .map(|s| (s * 1e-3).exp())
                .collect(),
        );
        // With a delay, the fourth pole is wherever it falls; the other three placed.
        for w in &want {
            let best = poles
                .z()
                .iter()
                .map(|z| (z - w).norm())
                .fold(f64::INFINITY, f64::min);
            assert!(
                best < 1e-7,
                "k = {k}, delay = {delay}: {w} not in {:?}",
                poles.z()
            );
        }
        assert!(poles.stable());
    }
}

#[test]
fn a_small_period_gives_the_continuous_design() {
    for (k, c) in [(1e4, 0.0), (2e3, 30.0), (1e5, 0.0)] {
        let l = ForceLoop::new(4.94, k, c, 1e-6, false).unwrap();
        let spec = DesignSpec::new(20.0, 0.9, None).unwrap();
        let (g, _) = design(&l, &spec).unwrap();
        let ct = design_continuous(&l, &spec);
        for (a, b, what) in [
            (1.0 + g.kfp, 1.0 + ct.kfp, "1 + kfp"),
            (g.kfi, ct.kfi, "kfi"),
            (g.kvd, ct.kvd, "kvd"),
        ] {
            assert!(
                (a - b).abs() <= 1e-3 * b.abs(),
                "k = {k}: {what} {a} vs {b}"
            );
        }
    }
}

#[test]
fn a_known_placement_by_hand() {
    // Continuous limit, c = 0: Lambda = 2 kg, k = 1000 N/m, poles -10 +- 10 j and -1:
    // (s^2 + 20 s + 200)(s + 1) = s^3 + 21 s^2 + 220 s + 200, so Kvd = 42,
    // (1 + Kfp) = 2 * 220 / 1000 = 0.44, Kfi = 2 * 200 / 1000 = 0.4.
    let l = ForceLoop::new(2.0, 1000.0, 0.0, 1e-7, false).unwrap();
    let w = 200_f64.sqrt() / (2.0 * core::f64::consts::PI);
    let spec = DesignSpec::new(
        w,
        10.0 / 200_f64.sqrt(),
        Some(1.0 / (2.0 * core::f64::consts::PI)),
    )
    .unwrap();
    let (g, _) = design(&l, &spec).unwrap();
    assert!((g.kvd - 42.0).abs() < 1e-3, "{g:?}");
    assert!((g.kfp + 0.56).abs() < 1e-5, "{g:?}");
    assert!((g.kfi - 0.4).abs() < 1e-5, "{g:?}");
}

#[test]
fn bad_specs_are_named() {
    let e = DesignSpec::new(0.0, 1.0, None).unwrap_err();
    assert!(e.to_string().contains("bandwidth"), "{e}");
    let e = DesignSpec::new(20.0, -1.0, None).unwrap_err();
    assert!(e.to_string().contains("damping"), "{e}");
}
