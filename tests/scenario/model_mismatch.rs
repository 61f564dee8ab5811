//! Model mismatch: a plant with its own parameters and friction, a controller on an
//! identified model.

use std::path::Path;

use crate::scratch::Scratch;

use armdyn::identification::file::to_json;
use armdyn::identification::{identify, IdentifySettings};
use armdyn::model::{RobotModel, Scara};
use armdyn::scenario::{execute, metrics_json, prepare, ControllerModel, Scenario};

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn scenario_with(extra: &str) -> Result<Scenario, armdyn::scenario::ScenarioError> {
    let text = std::fs::read_to_string(root().join("scenarios/thesis-hybrid.toml")).unwrap();
    Scenario::parse(
        "thesis-hybrid+.toml",
        &format!("{text}\n{extra}\n"),
        &root().join("scenarios"),
    )
}

fn metrics(s: &Scenario) -> serde_json::Value {
    let o = execute(s, prepare(s).unwrap(), |_| {}).unwrap();
    metrics_json(s, &o)
}

#[test]
fn a_nominal_plant_table_changes_nothing() {
    let plain = metrics(&scenario_with("").unwrap());
    let nominal = metrics(
        &scenario_with("[plant]\nmass_scale = [1.0, 1.0, 1.0, 1.0]\ninertia_scale = [1.0, 1.0, 1.0, 1.0]\npayload_kg = 0.0\n").unwrap(),
    );
    assert_eq!(plain, nominal);
}

#[test]
fn a_payload_and_friction_change_the_plant() {
    let s = scenario_with("[plant]\npayload_kg = 2.0\nfriction_viscous = [1.0, 1.0, 20.0, 0.01]\nfriction_coulomb = [2.0, 2.0, 10.0, 0.01]\n").unwrap();
    let p = s.plant.parameters::<4, Scara>();
    approx::assert_relative_eq!(p[30], 0.91 + 2.0, epsilon = 1e-12);
    assert!(s.plant.friction::<4>().is_some());
    let m = metrics(&s);
    let plain = metrics(&scenario_with("").unwrap());
    assert_ne!(m["max_abs_tau"], plain["max_abs_tau"]);
    assert!(m["plant"]["payload_kg"] == 2.0);
    // Still the thesis's bar: the force loop takes up the extra weight and the friction.
    assert!(m["force_overshoot_pct"].as_f64().unwrap() <= 5.0, "{m}");
    assert!(
        m["force_rms_error_last5s_n"].as_f64().unwrap() <= 2.0,
        "{m}"
    );
}

#[test]
fn bad_plant_tables_are_refused_by_key() {
    for (extra, key, rule) in [
        (
            "[plant]\nmass_scale = [1.0, 1.0]\n",
            "`plant.mass_scale`",
            "needs 4 numbers",
        ),
        (
            "[plant]\nmass_scale = [1.0, -1.0, 1.0, 1.0]\n",
            "`plant.mass_scale`",
            "entry 1",
        ),
        (
            "[plant]\ninertia_scale = [1.0, 1.0, 10.5, 1.0]\n",
            "`plant.inertia_scale`",
            "entry 2",
        ),
        (
            "[plant]\npayload_kg = -1.0\n",
            "`plant.payload_kg`",
            "out of range",
        ),
        (
            "[plant]\ncom_offset_m = [[0.0, 0.0]]\n",
            "`plant.com_offset_m`",
            "needs 4 rows",
        ),
        ("[plant]\nmass = 2.0\n", "`plant.mass`", "unknown field"),
        (
            "controller_model = \"no-such-file.json\"\n",
            "`controller_model`",
            "cannot read",
        ),
    ] {
        // Top-level keys must come before the tables.
        let text = std::fs::read_to_string(root().join("scenarios/thesis-hybrid.toml")).unwrap();
        let source = if extra.starts_with('[') {
            format!("{text}\n{extra}")
        } else {
            format!("{extra}{text}")
        };
        let e = Scenario::parse("x.toml", &source, &root().join("scenarios"))
            .unwrap_err()
            .to_string();
        assert!(
            e.starts_with("x.toml:") && e.contains(key) && e.contains(rule),
            "{e}"
        );
    }
}

#[test]
fn an_identified_model_in_the_controller_meets_the_hybrid_bar() {
    let id = identify(&Scara, &IdentifySettings::new(1.0, false, 1)).unwrap();
    let dir = Scratch::new("mismatch-identified");
    let file = dir.join("identification.json");
    std::fs::write(&file, serde_json::to_string(&to_json(&id)).unwrap()).unwrap();
    let model = armdyn::identification::file::read_model(&file, armdyn::model::Scara).unwrap();
    let mut s = scenario_with("").unwrap();
    s.controller_model = ControllerModel::Identified {
        file: file.clone(),
        parameters: model.parameters().to_vec(),
    };
    let m = metrics(&s);
    assert!(m["controller_model"]
        .as_str()
        .unwrap()
        .starts_with("identified"));
    assert!(m["force_overshoot_pct"].as_f64().unwrap() <= 5.0, "{m}");
    assert!(m["settling_time_s"].as_f64().unwrap() <= 0.1, "{m}");
    assert!(
        m["force_rms_error_last5s_n"].as_f64().unwrap() <= 2.0,
        "{m}"
    );
    // The identified model is not the nominal one, only close to it.
    let q = nalgebra::Vector4::new(0.3, -0.6, 0.2, 0.1);
    let d = (model.mass_matrix(&q) - Scara.mass_matrix(&q)).norm() / Scara.mass_matrix(&q).norm();
    assert!(d > 0.0 && d < 1e-2, "{d}");
}
