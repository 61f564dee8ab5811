//! The hybrid step of the thesis trial (SCARA) or of the Panda wiping at one state, run
//! `STEPS` times, bare or inside the supervisor: the loop whose instructions
//! `scripts/safety_instructions.sh` counts (the scenarios, states and inputs of the `safety`
//! group of `benches/control.rs`).
//!
//! Run: `cargo run --release --example safety_step -- scara|panda bare|supervised STEPS`.

use armdyn::control::{Controller, ControllerInput};
use armdyn::model::{Panda, Scara, Wrench};
use std::hint::black_box;
use std::process::ExitCode;

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let parsed = match (
        args.first().map(String::as_str),
        args.get(1).map(String::as_str),
        args.get(2),
    ) {
        (Some(r @ ("scara" | "panda")), Some(m @ ("bare" | "supervised")), Some(n)) => {
            match n.parse::<usize>() {
                Ok(n) => Ok((r == "panda", m == "supervised", n)),
                Err(e) => Err(format!("STEPS `{n}`: {e}")),
            }
        }
        _ => Err("usage: safety_step scara|panda bare|supervised STEPS".to_owned()),
    };
    let (panda, supervised, steps) = match parsed {
        Ok(p) => p,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::FAILURE;
        }
    };
    let trips = if panda {
        // As the benchmark: the wipe switched to force control by time, at t = 4 s.
        let edits = [("mode = \"contact\"", "mode = \"time\"\nswitch_s = 1.0")];
        run(Panda, "panda-wipe.toml", &edits, supervised, 4.0, steps)
    } else {
        run(Scara, "thesis-hybrid.toml", &[], supervised, 3.0, steps)
    };
    if trips > 0 {
        eprintln!("error: the supervisor tripped");
        return ExitCode::FAILURE;
    }
    ExitCode::SUCCESS
}

/// `steps` controller steps of the shipped scenario `file` (with the text `edits`) for
/// `robot` at its reference's state at `t` (s), as `benches/control.rs` `bench_step`: the
/// supervisor's trips.
fn run<const N: usize, R: armdyn::scenario::ScenarioRobot<N>>(
    robot: R,
    file: &str,
    edits: &[(&str, &str)],
    supervised: bool,
    t: f64,
    steps: usize,
) -> usize {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios");
    let mut text = std::fs::read_to_string(dir.join(file)).expect("the shipped scenario");
    for (from, to) in edits {
        assert!(text.contains(from), "{file} has no `{from}`");
        text = text.replace(from, to);
    }
    let mut s = armdyn::scenario::Scenario::parse(file, &text, &dir).expect("checks");
    s.safety.enabled = supervised;
    let mut p = armdyn::scenario::prepare_for(&s, robot).expect("prepares");
    let mut sp = p.reference.at(t);
    if let Some(f) = &p.force {
        sp.wrench = f.wrench(t, &sp.cartesian.position);
    }
    let qd = sp.joint.qd * 0.98;
    let q = sp.joint.q;
    let f = sp.wrench + Wrench::new(0.0, 0.0, -5.0, 0.0, 0.0, 0.0);
    let input = ControllerInput {
        t,
        q: &q,
        qd: &qd,
        target: &sp.joint,
        cartesian: &sp.cartesian,
        wrench: &f,
        wrench_ref: &sp.wrench,
        wrench_age_s: 0.0,
    };
    for _ in 0..steps {
        black_box(p.controller.step(black_box(&input), 1e-3));
    }
    p.controller.report().safety.map_or(0, |r| r.trips.len())
}
