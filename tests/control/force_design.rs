//! The force-loop design against simulation: designed gains meet their bars at 1, 10 and
//! 100 kN/m, stay stable over the stiffness range they report, tolerate sensor noise; the
//! thesis's gains are judged as docs/force-design.md's analysis says; admittance removes the force
//! error a wrong surface height leaves to impedance.

use std::path::PathBuf;

use approx::{abs_diff_eq, assert_relative_eq};
use armdyn::control::design::{
    analyse, bang_bang_settling, default_sweep, design, DesignSpec, ForceGains, ForceLoop,
};
use armdyn::control::selection::{ContactSwitch, SelectionPolicy};
use armdyn::metrics::ContactSummary;
use armdyn::model::Scara;
use armdyn::scenario::{
    contact_model, prepare_for, ForceController, LawChoice, Recorded, Scenario,
};

fn load(file: &str) -> Scenario {
    Scenario::load(
        &PathBuf::from(env!("CARGO_MANIFEST_DIR"))
            .join("scenarios")
            .join(file),
    )
    .unwrap()
}

fn with_law(file: &str, law: &str) -> Scenario {
    let mut s = load(file);
    LawChoice::parse(law).unwrap().apply(&mut s).unwrap();
    s
}

/// A run of the SCARA's scenario `s`, with every sample.
fn run(s: &Scenario) -> Recorded<4> {
    prepare_for(s, Scara).unwrap().execute(s, |_| {}).unwrap()
}

fn contact(r: &Recorded<4>) -> ContactSummary {
    r.outcome.contact.expect("contact metrics")
}

/// The bar of the designed gains: overshoot <= 2 %, settling (5 %) <= 50 ms, RMS <= 1 N.
fn meets_the_design_bar(what: &str, c: &ContactSummary, settling: Option<f64>) {
    assert!(c.normal_force_overshoot_pct <= 2.0, "{what}: {c:?}");
    assert!(settling.is_some_and(|t| t <= 0.05), "{what}: {c:?}");
    assert!(c.normal_force_rms_error_last5s_n <= 1.0, "{what}: {c:?}");
}

#[test]
fn designed_gains_meet_the_bar_at_10_and_100_kn_per_m_on_a_step() {
    for file in [
        "stiffness-10k.toml",
        "stiffness-100k.toml",
        "thesis-hybrid.toml",
    ] {
        let r = run(&with_law(file, "pi-ff-vd:design"));
        let c = contact(&r);
        meets_the_design_bar(file, &c, c.normal_force_settling_time_s);
    }
}

#[test]
fn designed_gains_meet_the_bar_at_1_kn_per_m_at_the_actuator_limit() {
    // A 200 N step into 1 kN/m needs 0.2 m of travel on d3's 1000 N: d3 saturates for about
    // 50 samples, and with the integral held while it does (anti-windup, the file's default)
    // the designed gains (20 Hz, damping 0.97) reach the band no later than a bang-bang push.
    let s = with_law("stiffness-1k.toml", "pi-ff-vd:design");
    assert!(s.force.as_ref().unwrap().anti_windup);
    let r = run(&s);
    let c = contact(&r);
    meets_the_design_bar("stiffness-1k", &c, c.normal_force_settling_time_s);
    let m = contact_model(&s).unwrap();
    // Pushing down, only d3 is loaded: its limit, its weight, the mass it moves.
    let limit = m.push_limit().unwrap();
    let weight = -armdyn::model::RobotModel::<4>::gravity(
        &armdyn::model::Scara,
        &nalgebra::Vector4::from_column_slice(&m.q),
    )[2];
    let d3_limit = <armdyn::model::Scara as armdyn::model::RobotModel<4>>::EFFORT_LIMITS[2];
    assert_relative_eq!(limit.max_force_n, d3_limit, max_relative = 1e-12);
    assert_relative_eq!(limit.gravity_n, weight, max_relative = 1e-12);
    assert_relative_eq!(limit.mass_kg, m.mass_kg, max_relative = 1e-12);
    // From d3's velocity at the switch (d3 extends downwards, into the surface).
    let v0 = r.samples[2000].qd[2];
    let bound = bang_bang_settling(&limit, m.stiffness, v0, 200.0).unwrap();
    let settling = c.normal_force_settling_time_s.unwrap();
    eprintln!("stiffness-1k: settling {settling:.4} s, bang-bang bound {bound:.4} s");
    assert!(
        (0.045..=0.055).contains(&bound) && settling <= bound + 2e-3,
        "settling {settling} s, bang-bang bound {bound} s"
    );
    // Without the anti-windup the same gains wind up during the saturation and overshoot.
    let mut plain = s.clone();
    plain.force.as_mut().unwrap().anti_windup = false;
    let p = contact(&run(&plain));
    assert!(
        p.normal_force_overshoot_pct > 2.0 * c.normal_force_overshoot_pct,
        "{p:?}"
    );
}

#[test]
fn anti_windup_changes_nothing_when_no_actuator_saturates() {
    let on = load("oblique-plane.toml");
    assert!(on.force.as_ref().unwrap().anti_windup);
    let mut off = on.clone();
    off.force.as_mut().unwrap().anti_windup = false;
    let (a, b) = (run(&on), run(&off));
    assert_eq!(a.outcome.stats.saturated_samples.iter().sum::<usize>(), 0);
    assert_eq!(a.samples.len(), b.samples.len());
    for (x, y) in a.samples.iter().zip(b.samples) {
        assert_eq!(x.tau, y.tau);
    }
}

#[test]
fn designed_gains_follow_a_ramp_at_1_kn_per_m_without_saturating() {
    // Switched on contact with the force ramped over 1 s, the same gains follow the ramp
    // within the 5 % band throughout, and d3 never saturates.
    let mut s = with_law("stiffness-1k.toml", "pi-ff-vd:design");
    s.selection = Some(SelectionPolicy::Contact(ContactSwitch {
        ramp_s: 1.0,
        ..ContactSwitch::for_sensor(0.0, 0.0)
    }));
    let r = run(&s);
    let c = contact(&r);
    meets_the_design_bar(
        "stiffness-1k, ramped",
        &c,
        c.normal_force_tracking_settling_s,
    );
    assert_eq!(r.outcome.stats.saturated_samples.iter().sum::<usize>(), 0);
}

#[test]
fn gains_designed_for_10_kn_per_m_hold_over_their_stiffness_range() {
    let s = with_law("stiffness-10k.toml", "pi-ff-vd:design");
    let m = contact_model(&s).unwrap();
    let l = ForceLoop::new(m.mass_kg, 1e4, 0.0, 1e-3, false).unwrap();
    let (g, _) = design(&l, &DesignSpec::new(20.0, 1.0, None).unwrap()).unwrap();
    let range = analyse(&l, &g, default_sweep(1e4)).range.unwrap();
    assert!(range.k_min <= 2e3 && range.k_max >= 5e4, "{range:?}");
    for k in [range.k_min, range.k_max] {
        let mut s = load("stiffness-10k.toml");
        s.surfaces[0].stiffness = k;
        let f = s.force.as_mut().unwrap();
        f.gains = (g.kfp, g.kfi, g.kvd);
        f.gravity_compensation = true;
        // The loop's stability is judged unsupervised: at k_min (about 1 kN/m) the 200 N
        // target is 200 mm deep, at d3's stroke end, where the supervisor's joint-limit
        // watch rightly trips and holds.
        s.safety.enabled = false;
        let r = run(&s);
        let c = contact(&r);
        // Settled, and no growing oscillation: the last second's swing is within the band.
        assert!(c.normal_force_settling_time_s.is_some(), "k = {k}: {c:?}");
        let tail: Vec<f64> = r.samples[r.samples.len() - 1000..]
            .iter()
            .map(|x| x.wrench[2])
            .collect();
        let swing = tail.iter().copied().fold(f64::MIN, f64::max)
            - tail.iter().copied().fold(f64::MAX, f64::min);
        assert!(
            swing < 10.0,
            "k = {k}: the force swings {swing} N at the end"
        );
    }
}

#[test]
fn designed_gains_tolerate_5_n_of_sensor_noise_on_the_thesis_plane() {
    let s = load("thesis-plane-designed-noisy.toml");
    assert_eq!(s.sensor.noise_n, 5.0);
    assert!(s.force.as_ref().unwrap().laws.design_gains);
    let c = contact(&run(&s));
    assert!(c.normal_force_overshoot_pct <= 5.0, "{c:?}");
    assert!(c.normal_force_rms_error_last5s_n <= 2.0, "{c:?}");
}

/// The pushes beyond 200 N (N) at the successive peaks of the push after `from_s`, with
/// their times (s).
fn peaks(r: &Recorded<4>, from_s: f64, count: usize) -> Vec<(f64, f64)> {
    let f: Vec<(f64, f64)> = r
        .samples
        .iter()
        .filter(|x| x.t >= from_s)
        .map(|x| (x.t, -x.wrench[2]))
        .collect();
    f.windows(3)
        .filter(|w| w[1].1 > w[0].1 && w[1].1 >= w[2].1 && w[1].1 > 200.0)
        .map(|w| (w[1].0, w[1].1 - 200.0))
        .take(count)
        .collect()
}

#[test]
fn the_thesis_gains_judged_by_the_model_and_by_simulation() {
    let l = ForceLoop::new(4.94, 1e4, 0.0, 1e-3, false).unwrap();
    // PI + FF: unstable at 1 ms, an oscillation of about 32.7 Hz growing at about 10 1/s.
    let a = analyse(&l, &ForceGains::THESIS, default_sweep(1e4));
    assert!(!a.stable);
    let mode = a.poles.s().max_by(|x, y| x.re.total_cmp(&y.re)).unwrap();
    assert!(mode.re > 5.0, "{mode}");
    // Simulated from contact switching (the force ramped from the touch, so the loop
    // starts near its equilibrium): the first peaks of the push grow at the model's rate and
    // recur at its frequency, before the swing saturates d3.
    let mut s = load("unknown-height.toml");
    let f = s.force.as_mut().unwrap();
    f.law = ForceController::PiFf;
    f.gains = ForceController::PiFf.thesis_gains();
    // The thesis ran without a supervisor; its divergence is what is judged here.
    s.safety.enabled = false;
    let r = run(&s);
    let start = contact(&r).force_start_s.unwrap();
    let p = peaks(&r, start, 3);
    assert_eq!(p.len(), 3, "{p:?}");
    let f_sim = 2.0 / (p[2].0 - p[0].0);
    let f_model = mode.im.abs() / (2.0 * std::f64::consts::PI);
    assert!(
        abs_diff_eq!(f_sim, f_model, epsilon = 0.15 * f_model.abs()),
        "{f_sim} Hz vs {f_model} Hz"
    );
    let growth = (p[2].1 / p[0].1).ln() / (p[2].0 - p[0].0);
    assert!(
        abs_diff_eq!(growth, mode.re, epsilon = 0.3 * mode.re.abs()),
        "growth {growth} 1/s vs {}",
        mode.re
    );
    // And it never settles: the swing grows until the actuator and the surface bound it.
    let c = contact(&r);
    assert!(
        c.normal_force_settling_time_s.is_none() && c.peak_normal_force_n > 400.0,
        "{c:?}"
    );
    // Supervised (the default), the same divergence trips within a few of its periods
    // (the swing lifts the tool off: contact lost, or the oscillation watch) and the hold
    // that follows ends the bouncing the unsupervised run keeps up to its end.
    s.safety.enabled = true;
    let supervised = run(&s);
    let trip = supervised.outcome.safety.trips.first().expect("a trip");
    assert!(
        trip.t_s > start && trip.t_s < start + 0.3,
        "{trip:?}, force from {start} s"
    );
    assert!(
        ["contact-lost", "oscillation"].contains(&trip.cause),
        "{trip:?}"
    );
    let held = contact(&supervised);
    assert!(
        held.peak_normal_force_n < c.peak_normal_force_n && held.contact_losses <= 2,
        "{held:?} vs {c:?}"
    );
    // PI + FF + VD: stable with margins; the model's step response and the simulated one
    // agree (settling within 10 ms, both without a notable overshoot).
    let b = analyse(&l, &ForceGains::THESIS_DAMPED, default_sweep(1e4));
    assert!(b.stable && b.margins.gain_up.unwrap() > 2.0 && b.margins.phase_deg.unwrap() > 45.0);
    let c = contact(&run(&load("thesis-hybrid.toml")));
    let (sim, model) = (
        c.normal_force_settling_time_s.unwrap(),
        b.step.settling_s.unwrap(),
    );
    assert!(
        abs_diff_eq!(sim, model, epsilon = 0.01),
        "settling: simulated {sim} s, model {model} s"
    );
    assert!(b.step.overshoot_pct < 2.0 && c.normal_force_overshoot_pct < 2.0);
}

#[test]
fn admittance_removes_the_force_error_of_a_wrong_height_impedance_keeps_it() {
    for file in [
        "thesis-hybrid.toml",
        "unknown-height.toml",
        "unknown-height-lower.toml",
    ] {
        let c = contact(&run(&with_law(file, "admittance")));
        assert!(c.normal_force_steady_error_n.abs() <= 2.0, "{file}: {c:?}");
    }
    // Impedance: the series stiffness of its 2 kN/m and the 10 kN/m surface times 5 mm,
    // more force where the surface is higher, less where it is lower.
    let series: f64 = 2000.0 * 1e4 / (2000.0 + 1e4);
    for (file, sign) in [
        ("unknown-height.toml", 1.0),
        ("unknown-height-lower.toml", -1.0),
    ] {
        let c = contact(&run(&with_law(file, "impedance")));
        let expected = sign * series * 0.005;
        let e = c.normal_force_steady_error_n;
        assert!(
            abs_diff_eq!(e, expected, epsilon = 0.05 * expected.abs()),
            "{file}: {e} N vs {expected} N"
        );
    }
}
