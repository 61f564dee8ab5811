//! A run starts from where the arm is: a redundant arm started on its reference gets a joint
//! reference that does not jump in the first samples (its plan begins where its pull towards
//! the posture is at rest), so nothing saturates at the start; for the shipped Panda square
//! and for it moved around the workspace.

use std::path::Path;

use armdyn::model::Panda;
use armdyn::scenario::{prepare_for, Recorded, Scenario};

fn moved(dx: f64, dy: f64, dz: f64) -> String {
    let text = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios/panda-square.toml"),
    )
    .unwrap();
    let mut out = String::new();
    for line in text.lines() {
        let trimmed = line.trim_start();
        // A waypoint: [t, x, y, z, roll, pitch, yaw],
        if trimmed.starts_with('[')
            && trimmed.matches(',').count() >= 6
            && !trimmed.starts_with("[[")
        {
            let inner = trimmed.trim_start_matches('[');
            let end = inner.find(']').unwrap();
            let v: Vec<f64> = inner[..end]
                .split(',')
                .map(|x| x.trim().parse().unwrap())
                .collect();
            let rest = &inner[end..];
            out += &format!(
                "  [{}, {}, {}, {}, {}, {}, {}{rest}\n",
                v[0],
                v[1] + dx,
                v[2] + dy,
                v[3] + dz,
                v[4],
                v[5],
                v[6]
            );
        } else {
            out += line;
            out.push('\n');
        }
    }
    out
}

#[test]
fn a_redundant_arm_started_on_its_reference_does_not_jump() {
    let variants = [
        (0.0, 0.0, 0.0),
        (0.04, -0.03, 0.02),
        (0.06, 0.02, 0.0),
        (-0.02, -0.02, 0.03),
        (0.05, -0.05, 0.0),
    ];
    for (dx, dy, dz) in variants {
        let text = moved(dx, dy, dz);
        let s = Scenario::parse("panda-square-moved.toml", &text, Path::new(".")).unwrap();
        let Recorded {
            outcome: r,
            samples,
        } = prepare_for(&s, Panda).unwrap().execute(&s, |_| {}).unwrap();
        // Nothing saturates at the start (later in a moved square the elbow's weight can ask
        // joint 1 for more than it has on the last side; the shipped square and the one
        // moved by (4, -3, 2) cm saturate nowhere).
        let early = samples
            .iter()
            .take_while(|x| x.t < 1.0)
            .filter(|x| x.tau != x.tau_command)
            .count();
        assert_eq!(
            early, 0,
            "moved by ({dx}, {dy}, {dz}): {early} saturated samples in the first second"
        );
        if (dx, dy, dz) == (0.0, 0.0, 0.0) || (dx, dy, dz) == (0.04, -0.03, 0.02) {
            let saturated: usize = r.stats.saturated_samples.iter().sum();
            assert_eq!(saturated, 0, "moved by ({dx}, {dy}, {dz})");
        }
        // The reference is at rest where the tool is at rest: its first millisecond moves
        // the joints by less than a micro-radian, and the arm starts on it.
        let step = (samples[1].setpoint.joint.q - samples[0].setpoint.joint.q).amax();
        assert!(
            step < 1e-6,
            "moved by ({dx}, {dy}, {dz}): the reference moves {step} rad in the first period"
        );
        assert!((samples[0].q - samples[0].setpoint.joint.q).amax() < 1e-12);
    }
}
