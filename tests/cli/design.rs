//! `armdyn design force` and `armdyn run scenario --force-law` end to end, and the scenario
//! keys of the force laws: outputs on success, clear errors on bad input.

use std::path::{Path, PathBuf};

use crate::common::{armdyn, tmp};
use approx::{abs_diff_eq, assert_abs_diff_eq};
use armdyn::scenario::Scenario;

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

fn design_json(args: &[&str]) -> serde_json::Value {
    let o = armdyn(&[&["design", "force", "--json"], args].concat());
    assert!(o.status.success(), "{}", text(&o.stderr));
    serde_json::from_slice(&o.stdout).unwrap()
}

#[test]
fn design_force_prints_gains_poles_and_the_stiffness_range() {
    let j = design_json(&[
        "--k",
        "10000",
        "--dt",
        "0.001",
        "--mass",
        "4.94",
        "--bandwidth-hz",
        "20",
        "--damping",
        "1",
    ]);
    for key in [
        "kfp",
        "kfi",
        "kvd",
        "stable",
        "poles",
        "k_min",
        "k_max",
        "phase_margin_deg",
    ] {
        assert!(j.get(key).is_some(), "no {key} in {j}");
    }
    assert_eq!(j["stable"], true);
    assert_eq!(j["poles"].as_array().unwrap().len(), 3);
    assert!(j["k_min"].as_f64().unwrap() <= 2e3 && j["k_max"].as_f64().unwrap() >= 5e4);
    // The same from the thesis scenario's contact pose: m3 + m4 along z.
    let s = design_json(&[
        "--scenario",
        "scenarios/thesis-hybrid.toml",
        "--bandwidth-hz",
        "20",
        "--damping",
        "1",
    ]);
    assert!(
        abs_diff_eq!(s["mass_kg"].as_f64().unwrap(), 4.94, epsilon = 0.01),
        "{s}"
    );
    assert_abs_diff_eq!(
        s["kvd"].as_f64().unwrap(),
        j["kvd"].as_f64().unwrap(),
        epsilon = 5.0
    );
}

#[test]
fn design_force_states_the_actuator_bound_of_a_scenario() {
    // 200 N into 1 kN/m on d3's 1000 N: no gains settle before about 50 ms.
    let args = [
        "--scenario",
        "scenarios/stiffness-1k.toml",
        "--bandwidth-hz",
        "20",
        "--damping",
        "0.97",
    ];
    let j = design_json(&args);
    assert_eq!(j["actuator_max_force_n"], 1000.0);
    assert_eq!(j["step_n"], 200.0);
    let bound = j["bang_bang_settling_s"].as_f64().unwrap();
    assert!((0.045..=0.055).contains(&bound), "{j}");
    let model = j["model_step_settling_s"].as_f64().unwrap();
    assert!(model < bound);
    let o = armdyn(&[&["design", "force"], &args[..]].concat());
    let out = text(&o.stdout);
    assert!(
        out.contains("actuator limit (pushing into the surface): 1000 N"),
        "{out}"
    );
    assert!(
        out.contains("out of reach: the actuators, not the gains, set the pace"),
        "{out}"
    );
    // At 10 kN/m the loop, not the actuator, is the slower: no such line.
    let o = armdyn(&[
        "design",
        "force",
        "--scenario",
        "scenarios/stiffness-10k.toml",
        "--bandwidth-hz",
        "20",
        "--damping",
        "1",
    ]);
    let out = text(&o.stdout);
    assert!(out.contains("reaches the 5 % band"), "{out}");
    assert!(!out.contains("out of reach"), "{out}");
    // Without a scenario there is no step to bound.
    let m = design_json(&[
        "--k",
        "1000",
        "--dt",
        "0.001",
        "--mass",
        "4.94",
        "--bandwidth-hz",
        "20",
        "--damping",
        "1",
    ]);
    assert!(m["bang_bang_settling_s"].is_null());
}

#[test]
fn design_force_evaluates_the_thesis_gains() {
    let base = [
        "--k",
        "10000",
        "--dt",
        "0.001",
        "--mass",
        "4.94",
        "--evaluate",
    ];
    let pi_ff = design_json(&[&base[..], &["20,5,0"]].concat());
    assert_eq!(pi_ff["stable"], false);
    assert!(pi_ff["k_min"].is_null());
    let vd = design_json(&[&base[..], &["20,5,2000"]].concat());
    assert_eq!(vd["stable"], true);
    assert!(vd["gain_margin"].as_f64().unwrap() > 2.0);
    let o = armdyn(&[
        "design", "force", "--k", "10000", "--dt", "0.001", "--mass", "4.94",
    ]);
    assert!(!o.status.success() && text(&o.stderr).contains("--bandwidth-hz"));
    let o = armdyn(&[&["design", "force"], &base[..], &["20,5"]].concat());
    assert!(
        !o.status.success() && text(&o.stderr).contains("three: kfp,kfi,kvd"),
        "{}",
        text(&o.stderr)
    );
    let o = armdyn(&[
        "design",
        "force",
        "--k",
        "-5",
        "--dt",
        "0.001",
        "--mass",
        "4.94",
        "--evaluate",
        "1,1,1",
    ]);
    assert!(
        !o.status.success() && text(&o.stderr).contains("contact stiffness"),
        "{}",
        text(&o.stderr)
    );
}

#[test]
fn run_scenario_with_several_force_laws_prints_one_table() {
    let out = tmp("design", "laws");
    let o = armdyn(&[
        "run",
        "scenario",
        "scenarios/unknown-height.toml",
        "--force-law",
        "pi-ff-vd:design,impedance,admittance",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", text(&o.stderr));
    let table = text(&o.stdout);
    for law in ["pi-ff-vd:design", "impedance", "admittance"] {
        assert!(
            table.contains(&format!("| unknown-height | {law} ")),
            "{table}"
        );
    }
    for dir in ["pi-ff-vd-design", "impedance", "admittance"] {
        let m: serde_json::Value = serde_json::from_str(
            &std::fs::read_to_string(out.join("unknown-height").join(dir).join("metrics.json"))
                .unwrap(),
        )
        .unwrap();
        assert!(m["normal_force_steady_error_n"].is_number(), "{dir}");
    }
    let o = armdyn(&[
        "run",
        "scenario",
        "scenarios/unknown-height.toml",
        "--force-law",
        "impedance:design",
    ]);
    assert!(!o.status.success() && text(&o.stderr).contains("only pi-ff-vd has designed gains"));
}

fn parse(force_extra: &str) -> Result<Scenario, String> {
    let base = std::fs::read_to_string(
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("scenarios/stiffness-10k.toml"),
    )
    .unwrap();
    let text = base.replace("[force.design]", &format!("{force_extra}\n[force.design]"));
    Scenario::parse("test.toml", &text, Path::new(".")).map_err(|e| e.to_string())
}

#[test]
fn the_force_law_keys_are_checked() {
    let s = parse("").unwrap();
    assert!(!s.force.unwrap().laws.design_gains);
    let s = parse("gains = \"design\"").unwrap();
    assert!(s.force.unwrap().laws.design_gains);
    let e = parse("gains = \"designed\"").unwrap_err();
    assert!(
        e.contains("force.gains") && e.contains("known: design"),
        "{e}"
    );
    let e = parse("gains = \"design\"\nkfp = 3.0").unwrap_err();
    assert!(e.contains("force.kfp") && e.contains("computes it"), "{e}");
    let e = parse("[force.impedance]\nstiffness = -1.0").unwrap_err();
    assert!(e.contains("force.impedance.stiffness"), "{e}");
    let e = parse("[force.admittance]\nmass = 1.0\nspring = 3.0").unwrap_err();
    assert!(e.contains("spring"), "{e}");
    let text = std::fs::read_to_string(
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("scenarios/stiffness-10k.toml"),
    )
    .unwrap()
    .replace(
        "law = \"pi-ff-vd\"",
        "law = \"impedance\"\ngains = \"design\"",
    );
    let e = Scenario::parse("t.toml", &text, Path::new("."))
        .unwrap_err()
        .to_string();
    assert!(e.contains("needs law = \"pi-ff-vd\""), "{e}");
}

fn linearize_json(args: &[&str]) -> serde_json::Value {
    let o = armdyn(&[&["design", "linearize", "--json"], args].concat());
    assert!(o.status.success(), "{}", text(&o.stderr));
    serde_json::from_slice(&o.stdout).unwrap()
}

#[test]
fn design_linearize_gives_the_verdict_and_the_equilibrium_where_the_reference_rests() {
    // The thesis trial in contact, at the run's own state: stable, in force control
    // throughout the second before, so it settles.
    let j = linearize_json(&["--scenario", "scenarios/thesis-hybrid.toml", "--at", "2.5"]);
    assert_eq!(j["stable"], true);
    assert_eq!(j["mode_exits_last_s"], 0);
    assert_eq!(j["settles"], true);
    assert!(j["equilibrium"].is_null());
    // The Panda pressing with an uncompensated tool, where its reference rests (from 10.6 s):
    // the equilibrium near the run's state, at rest, and stable.
    let j = linearize_json(&[
        "--scenario",
        "scenarios/panda-tool-uncompensated.toml",
        "--at",
        "11.2",
        "--equilibrium",
    ]);
    let e = &j["equilibrium"];
    assert!(e["relative_residual"].as_f64().unwrap() <= 1e-11, "{e}");
    assert!(e["joint_distance_from_run"].as_f64().unwrap() < 1e-3, "{e}");
    assert!(j["qd"]
        .as_array()
        .unwrap()
        .iter()
        .all(|v| v.as_f64().unwrap().abs() < 1e-9));
    assert_eq!(j["settles"], true);
    // The thesis trial's reference slides along its line at 2.5 s: no rest point, refused.
    let o = armdyn(&[
        "design",
        "linearize",
        "--scenario",
        "scenarios/thesis-hybrid.toml",
        "--at",
        "2.5",
        "--equilibrium",
    ]);
    assert!(!o.status.success());
    let err = text(&o.stderr);
    assert!(err.contains("the reference moves at t = 2.5 s"), "{err}");
}
