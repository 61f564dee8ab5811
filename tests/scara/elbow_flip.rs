//! The three-zone trial with the planned elbow flip: no saturation, no joint outside its
//! limits, the flip within 80 % of the effort limits and above its clearance, tracking back
//! below the position test's bound within 1 s of the resumption; and the planned reference
//! continuous in position, velocity and acceleration across the pause and the resumption.

use approx::abs_diff_eq;
use armdyn::model::{RobotModel, Scara};
use armdyn::robots::scara::scenario::plan;
use armdyn::scenario::{
    built_in, execute, metrics_json, prepare, prepare_for, Recorded, RobotVocabulary, Scenario,
};
use armdyn::sim::ReferenceSource;

/// The SCARA's plan of a built-in scenario's reference.
fn planned(s: &Scenario) -> armdyn::robots::scara::scenario::ScaraPlan {
    let trajectory = match &s.reference {
        armdyn::scenario::ReferenceSpec::Named { name, surface_z_m } => {
            Scara::named_reference(name, *surface_z_m).unwrap()
        }
        other => panic!("{other:?}"),
    };
    plan(s, trajectory).unwrap()
}

/// A run of the SCARA's scenario `s`, with every sample.
fn recorded(s: &Scenario) -> Recorded<4> {
    prepare_for(s, Scara).unwrap().execute(s, |_| {}).unwrap()
}

/// The pid family's bound of the position test (max joint error after the transient).
const TRACKING_BOUND: f64 = 1e-3;

#[test]
fn the_planned_three_zone_trial_meets_its_bar() {
    let s = built_in("three-zone.toml").unwrap();
    let Recorded {
        outcome: r,
        samples,
    } = recorded(&s);
    assert_eq!(r.stats.saturated_samples, [0; 4]);
    assert_eq!(r.joint_limit_violation_samples, 0);
    let m = metrics_json(&s, &r);
    let number = |k: &str| m[k].as_f64().unwrap_or_else(|| panic!("{k}: {m}"));
    assert_eq!(m["elbow"]["switches_s"].as_array().unwrap().len(), 1);
    assert!(number("flip_max_tau_fraction") <= 0.8, "{m}");
    assert!(
        number("min_tool_z_during_flip_m") >= number("flip_clearance_z_m"),
        "{m}"
    );
    let resume = number("flip_start_s") + number("flip_duration_s");
    let worst = samples
        .iter()
        .filter(|x| x.t >= resume + 1.0)
        .map(|x| (x.setpoint.joint.q - x.q).amax())
        .fold(0.0, f64::max);
    assert!(
        worst < TRACKING_BOUND,
        "max joint error from 1 s after the resumption: {worst}"
    );
    // The thesis's step, for contrast: saturation and a joint past its limit.
    let step = built_in("thesis-three-zone.toml").unwrap();
    let Recorded {
        outcome: r,
        samples,
    } = recorded(&step);
    assert!(r.stats.saturated_samples[0] > 0 && r.stats.saturated_samples[1] > 0);
    assert!(samples.iter().any(|x| x.q[1] > Scara.upper_limits()[1]));
}

#[test]
fn the_planned_reference_is_continuous_across_the_pause_and_the_resumption() {
    let s = built_in("three-zone.toml").unwrap();
    let mut reference = planned(&s);
    let flip = reference.flips()[0].clone();
    let (hold_start, hold_end) = flip.interval();
    let moves: Vec<_> = flip.moves.clone();
    let h = 1e-6;
    // Every boundary: the stop ramp's start and end, each joint move's start and end, the
    // start ramp's start and end.
    let ramp = flip.pause.ramp_s;
    let mut instants = vec![hold_start - ramp, hold_start, hold_end, hold_end + ramp];
    instants.extend(moves.iter().flat_map(|m| [m.start_s, m.end_s()]));
    for t in instants {
        let (a, b) = (reference.at(t - h).joint, reference.at(t + h).joint);
        assert!(
            abs_diff_eq!(a.q, b.q, epsilon = 1e-5),
            "position jumps at {t}: {} vs {}",
            a.q,
            b.q
        );
        assert!(
            abs_diff_eq!(a.qd, b.qd, epsilon = 1e-3),
            "velocity jumps at {t}: {} vs {}",
            a.qd,
            b.qd
        );
        assert!(
            abs_diff_eq!(a.qdd, b.qdd, epsilon = 0.5),
            "acceleration jumps at {t}: {} vs {}",
            a.qdd,
            b.qdd
        );
    }
    // And the stepped reference does jump, by radians, in one sample.
    let step = built_in("thesis-three-zone.toml").unwrap();
    let mut stepped = planned(&step);
    assert!(stepped.flips().is_empty());
    let t = stepped.plan().switches()[0].t;
    assert!((stepped.at(t - 1e-3).joint.q - stepped.at(t).joint.q).amax() > 2.0);
}

/// The shipped optimised flip (`scenarios/three-zone-optimal.toml`, each move of the flip the
/// shortest iLQR move within the same 78 % share, no joint faster than in the quintic flip):
/// the same bars as the quintic's (no saturated sample, no joint outside its limits, effort
/// within 80 %), and a shorter flip.
#[test]
fn the_optimised_three_zone_flip_meets_the_bar_and_is_shorter() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scenarios/three-zone-optimal.toml"
    );
    let s = Scenario::load(std::path::Path::new(path)).unwrap();
    let Recorded {
        outcome: r,
        samples,
    } = recorded(&s);
    assert_eq!(r.stats.saturated_samples, [0; 4]);
    assert_eq!(r.joint_limit_violation_samples, 0);
    let m = metrics_json(&s, &r);
    let number = |k: &str| m[k].as_f64().unwrap_or_else(|| panic!("{k}: {m}"));
    assert!(number("flip_max_tau_fraction") <= 0.8, "{m}");
    assert!(
        number("flip_planned_max_tau_fraction") <= 0.78 + 1e-12,
        "{m}"
    );
    assert!(
        number("min_tool_z_during_flip_m") >= number("flip_clearance_z_m"),
        "{m}"
    );
    let quintic = built_in("three-zone.toml").unwrap();
    let rq = execute(&quintic, prepare(&quintic).unwrap(), |_| {}).unwrap();
    let mq = metrics_json(&quintic, &rq);
    let (optimised, planned) = (
        number("flip_duration_s"),
        mq["flip_duration_s"].as_f64().unwrap(),
    );
    println!("flip: optimised {optimised:.4} s, quintic {planned:.4} s");
    assert!(optimised < 0.95 * planned, "{optimised} vs {planned}");
    // The plan is the plant's own sampled trajectory: computed torque follows it closely.
    let (start, end) = (number("flip_start_s"), optimised + number("flip_start_s"));
    let worst = samples
        .iter()
        .filter(|x| x.t >= start && x.t <= end)
        .map(|x| (x.setpoint.joint.q - x.q).amax())
        .fold(0.0, f64::max);
    assert!(
        worst < TRACKING_BOUND,
        "max joint error in the flip: {worst}"
    );
}

/// The SCARA's own `[reference]` keys are checked by the SCARA, each error on its key and
/// line; every other robot refuses them as keys it does not have.
#[test]
fn the_elbow_keys_are_the_scaras_and_checked_on_their_line() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios/three-zone.toml");
    let text = std::fs::read_to_string(&path).unwrap();
    let line = |key: &str| 1 + text.lines().position(|l| l.starts_with(key)).unwrap();
    let refused = |from: &str, to: &str| {
        Scenario::parse("t.toml", &text.replace(from, to), path.parent().unwrap())
            .err()
            .unwrap_or_else(|| panic!("{to}: accepted"))
    };
    let e = refused("max_effort_share = 0.78", "max_effort_share = 1.5");
    assert_eq!(
        (e.key.as_str(), e.line),
        ("reference.max_effort_share", Some(line("max_effort_share")))
    );
    assert!(e.rule.contains("1.5 is out of range"), "{e}");
    let e = refused("elbow_switch = \"planned\"", "elbow_switch = \"step\"");
    assert_eq!(
        (e.key.as_str(), e.line),
        ("reference.max_effort_share", Some(line("max_effort_share")))
    );
    let e = refused("elbow_switch = \"planned\"", "elbow_switch = \"jump\"");
    assert_eq!(e.key, "reference.elbow_switch", "{e}");
    assert!(e.rule.contains("known: planned, optimal, step"), "{e}");
    let e = refused("pause_ramp_s = 0.5", "pause_ramp = 0.5");
    assert_eq!(
        (e.key.as_str(), e.line),
        ("reference.pause_ramp", Some(line("pause_ramp")))
    );
    assert!(e.rule.contains("`pause_ramp_s`"), "{e}");
    // The keys reach the plan: an optimal flip is the optimised scenario's.
    let s = Scenario::parse(
        "t.toml",
        &text.replace("elbow_switch = \"planned\"", "elbow_switch = \"optimal\""),
        path.parent().unwrap(),
    )
    .unwrap();
    assert_eq!(
        s.reference_robot_keys["elbow_switch"].as_str(),
        Some("optimal")
    );
}

/// The SCARA's reading of its keys: defaults, the optimal flip, the step, and each refusal
/// on its key (an integer reads as a number).
#[test]
fn the_elbow_keys_read_as_the_switch_they_name() {
    use armdyn::robots::scara::elbow_keys::ElbowSwitchSpec;
    let read = |text: &str| ElbowSwitchSpec::from_keys(&toml::from_str(text).unwrap());
    let planned = |optimal, max_effort_share, clearance_z_m| ElbowSwitchSpec::Planned {
        max_effort_share,
        clearance_z_m,
        ramp_s: None,
        optimal,
    };
    assert_eq!(read(""), Ok(planned(false, None, None)));
    assert_eq!(
        read("elbow_switch = \"optimal\"\nmax_effort_share = 1\nclearance_z_m = 0.1"),
        Ok(planned(true, Some(1.0), Some(0.1)))
    );
    assert_eq!(read("elbow_switch = \"step\""), Ok(ElbowSwitchSpec::Step));
    for (text, key) in [
        (
            "elbow_switch = \"step\"\npause_ramp_s = 0.5",
            "pause_ramp_s",
        ),
        ("elbow_switch = \"jump\"", "elbow_switch"),
        ("elbow_switch = 1", "elbow_switch"),
        ("max_effort_share = 1.5", "max_effort_share"),
        ("max_effort_share = \"most\"", "max_effort_share"),
        ("pause_ramp_s = 0", "pause_ramp_s"),
        ("clearance_z_m = nan", "clearance_z_m"),
    ] {
        assert_eq!(read(text).unwrap_err().key, key, "{text}");
    }
}
