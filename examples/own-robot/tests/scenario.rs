//! A task-space contact scenario on the Jaco2, a robot armdyn's registry does not know: the
//! file names it (`robot = "jaco2"`), `Scenario::load_for` reads it for this crate's type,
//! and the hybrid law in the full task frame presses 10 N on a table 5 mm higher than
//! believed while the tool follows a line, held along the normal.

use std::path::PathBuf;

use armdyn::scenario::{prepare_for, write_outputs_for, Scenario};
use own_robot::Jaco2;

fn scenario() -> Scenario {
    let file = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("scenarios/jaco2-press-table.toml");
    Scenario::load_for(&Jaco2, &file).unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn the_jaco2_presses_on_a_table_and_follows_a_line() {
    let s = scenario();
    let recorded = prepare_for(&s, Jaco2).unwrap().execute(&s, |_| {}).unwrap();
    let r = &recorded.outcome;
    assert_eq!(r.robot, "jaco2");
    assert_eq!(r.controller_name, "task-space-hybrid-pi-ff-vd");
    let c = r.contact.expect("contact metrics");
    let a = r.alignment.expect("the tool axis is held to the normal");
    println!("jaco2-press-table: {c:?}\n{a:?}");
    assert!(c.force_start_s.is_some(), "{c:?}");
    assert_eq!(c.contact_losses, 0, "{c:?}");
    assert!(c.normal_force_overshoot_pct <= 10.0, "{c:?}");
    assert!(c.normal_force_rms_error_last3s_n <= 0.2, "{c:?}");
    assert!(c.path_rms_error_contact_mm <= 0.1, "{c:?}");
    assert!(a.rms_deg <= 0.1, "{a:?}");
    assert_eq!(r.stats.saturated_samples.iter().sum::<usize>(), 0);
    assert_eq!(r.stats.end_stop_samples.iter().sum::<usize>(), 0);

    // The run's files, as `armdyn run scenario` writes them for the registry's robots.
    let out = std::env::temp_dir().join(format!("own-robot-scenario-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&out);
    write_outputs_for(&out, &s, &recorded, true, &Jaco2).unwrap();
    let metrics = std::fs::read_to_string(out.join("metrics.json")).unwrap();
    assert!(metrics.contains("\"jaco2\""), "{metrics}");
    for file in ["trajectory.csv", "normal_force.svg", "view.html"] {
        assert!(out.join(file).is_file(), "{file} is missing");
    }
    std::fs::remove_dir_all(&out).unwrap();
}

#[test]
fn a_robot_that_is_neither_this_one_nor_in_the_registry_is_refused() {
    let s = scenario();
    let text = s.source.replace("robot = \"jaco2\"", "robot = \"jaco3\"");
    let e = Scenario::parse_for(&Jaco2, "bad.toml", &text, ".".as_ref()).unwrap_err();
    let message = e.to_string();
    assert!(
        message.contains("unknown robot `jaco3`") && message.contains("jaco2"),
        "{message}"
    );
}
