//! Every robot through the whole control stack: the shipped UR5 and Panda scenarios meet
//! their bars, the same task at other poses and on other arms meets them too, the joint-space
//! laws follow the inverse kinematics of a Cartesian reference, and a scenario for any robot
//! is checked against that robot (joint counts, its task, what it has).

use std::path::{Path, PathBuf};

use nalgebra::{SVector, UnitQuaternion, Vector3};
use rand::rngs::Xoshiro256PlusPlus;
use rand::{RngExt, SeedableRng};
use serde_json::Value;

use armdyn::model::RobotModel;
use armdyn::model::Ur5;
use armdyn::scenario::{execute, metrics_json, prepare, prepare_for, Outcome, Recorded, Scenario};
use armdyn::sweep::{run_sweep, SweepSpec, TABLE};
use armdyn::target::orientation;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn load(file: &str) -> Scenario {
    Scenario::load_with(&root().join("scenarios").join(file), &[TABLE]).unwrap()
}

fn run(s: &Scenario) -> (Outcome, Value) {
    let r = execute(s, prepare(s).unwrap(), |_| {}).unwrap();
    let m = metrics_json(s, &r);
    (r, m)
}

/// The bars of the shipped tasks: position RMS <= 0.5 mm and orientation RMS <= 0.1 degree
/// after the first 0.5 s, no saturated sample, no joint outside its limits.
fn meets_the_bars(what: &str, r: &Outcome) {
    assert_eq!(r.pose.after_s, 0.5, "{what}");
    assert!(r.pose.position_rms_m <= 0.5e-3, "{what}: {:?}", r.pose);
    assert!(
        r.pose.orientation_rms_rad.to_degrees() <= 0.1,
        "{what}: {:?}",
        r.pose
    );
    assert_eq!(r.stats.saturated_samples.iter().sum::<usize>(), 0, "{what}");
    assert_eq!(r.joint_limit_violation_samples, 0, "{what}");
}

#[test]
fn ur5_square_meets_its_bar() {
    let s = load("ur5-square.toml");
    let Recorded {
        outcome: r,
        samples,
    } = prepare_for(&s, Ur5).unwrap().execute(&s, |_| {}).unwrap();
    let m = metrics_json(&s, &r);
    meets_the_bars("ur5-square", &r);
    println!("ur5-square: {:?}", r.pose);
    assert_eq!(
        m["task"],
        serde_json::json!(["x", "y", "z", "rx", "ry", "rz"])
    );
    // The tilt happened: 30 degrees about base x at t = 5 s.
    let tilted = samples.iter().find(|x| x.t >= 5.0).unwrap();
    let level = samples.iter().find(|x| x.t >= 4.0).unwrap();
    let angle = tilted.orientation.angle_to(&level.orientation);
    assert!(
        (angle.to_degrees() - 30.0).abs() < 0.1,
        "{}",
        angle.to_degrees()
    );
}

#[test]
fn panda_square_meets_its_bar_and_holds_the_elbow() {
    let s = load("panda-square.toml");
    let (r, m) = run(&s);
    meets_the_bars("panda-square", &r);
    let deviation = m["posture_max_deviation_rad"][3].as_f64().unwrap();
    println!(
        "panda-square: {:?}, elbow within {deviation} rad of its posture",
        r.pose
    );
    assert!(deviation <= 0.05, "joint 4 strays {deviation} rad");
}

#[test]
fn panda_payload_sweep_keeps_every_trial_within_2_mm() {
    let s = load("panda-payload-sweep.toml");
    let spec = SweepSpec::of(&s).unwrap().unwrap();
    assert_eq!(spec.max_position_error_mm, Some(2.0));
    let run = run_sweep(&s, &spec, 200, 1, 0, &|| {}).unwrap();
    assert_eq!(run.results.len(), 200);
    let column = armdyn::sweep::METRICS
        .iter()
        .position(|m| *m == "position_max_error_mm")
        .unwrap();
    let mut worst: Vec<f64> = run
        .results
        .iter()
        .map(|r| r.metrics[column].unwrap())
        .collect();
    worst.sort_by(f64::total_cmp);
    let p = |q| armdyn::sweep::output::percentile(&worst, q);
    println!(
        "panda-payload-sweep, largest position error of each trial (mm): p5 {:.3}, p50 {:.3}, p95 {:.3}, max {:.3}",
        p(5.0),
        p(50.0),
        p(95.0),
        worst[worst.len() - 1]
    );
    let failed: Vec<(usize, _)> = run
        .results
        .iter()
        .enumerate()
        .filter(|(_, r)| !r.failures.is_empty())
        .map(|(i, r)| (i, r.failures.clone()))
        .collect();
    assert!(failed.is_empty(), "failed trials: {failed:?}");
    assert!(worst[worst.len() - 1] <= 2.0);
}

/// A square of 0.2 m in the horizontal plane through the pose of `q` in 4 s, then a tilt of
/// 30 degrees about base x and back, as a scenario for `robot`.
fn square_at<const N: usize, R: RobotModel<N>>(
    robot: &R,
    q: &SVector<f64, N>,
    law: &str,
) -> String {
    let pose = robot.end_effector_pose(q);
    let p = pose.fixed_view::<3, 1>(0, 3).into_owned();
    let o = orientation::of_pose(&pose);
    let tilted = UnitQuaternion::from_scaled_axis(Vector3::x() * 30f64.to_radians()) * o;
    let row = |t: f64, x: f64, y: f64, o: &UnitQuaternion<f64>| {
        let (r, pi, ya) = orientation::rpy(o);
        format!(
            "  [{t}, {}, {}, {}, {r}, {pi}, {ya}],\n",
            p.x + x,
            p.y + y,
            p.z
        )
    };
    let mut points = String::new();
    for (t, x, y) in [
        (0.0, -0.1, -0.1),
        (1.0, 0.1, -0.1),
        (2.0, 0.1, 0.1),
        (3.0, -0.1, 0.1),
        (4.0, -0.1, -0.1),
    ] {
        points += &row(t, x, y, &o);
    }
    points += &row(5.0, -0.1, -0.1, &tilted);
    points += &row(6.0, -0.1, -0.1, &o);
    let seed: Vec<String> = q.iter().map(|x| x.to_string()).collect();
    format!(
        "format = 1\nname = \"square\"\nrobot = \"{}\"\nstart_on_reference = true\n\n[reference]\nkind = \"waypoints\"\ninterpolation = \"quintic\"\nseed = [{}]\npoints = [\n{points}]\n\n[position]\nlaw = \"{law}\"\n{}\n[metrics]\nafter_s = 0.5\n",
        R::NAME,
        seed.join(", "),
        if law.starts_with("pid-fl") { "acceleration_feedforward = true\n" } else { "" }
    )
}

/// Runs of the square at other poses of `robot` with `law`: (met the bars, refused).
fn other_poses<const N: usize, R: RobotModel<N>>(robot: &R, law: &str) -> (usize, usize) {
    let mut rng = Xoshiro256PlusPlus::seed_from_u64(5);
    let (mut ran, mut refused) = (0, 0);
    let mut k = 0;
    while ran < 6 && k < 200 {
        k += 1;
        // Away from the limits: the middle 60 % of each joint's range (within +-pi).
        let q = SVector::<f64, N>::from_fn(|i, _| {
            let [lo, hi] = R::JOINT_LIMITS[i];
            let (lo, hi) = (lo.max(-3.0), hi.min(3.0));
            let mid = 0.5 * (lo + hi);
            mid + 0.3 * (hi - lo) * rng.random_range(-1.0..=1.0)
        });
        // And away from singularities: the Jacobian's smallest singular value at least
        // a twentieth of its largest (a pose inside the workspace, not at its edge).
        let j = robot.jacobian(&q);
        let sv = nalgebra::DMatrix::from_column_slice(6, N, j.as_slice())
            .svd(false, false)
            .singular_values;
        if sv.min() < 0.05 * sv.max() {
            continue;
        }
        let text = square_at(robot, &q, law);
        let s = Scenario::parse("square.toml", &text, Path::new(".")).unwrap();
        let p = match prepare(&s) {
            Ok(p) => p,
            Err(e) => {
                // Out of the workspace or through a singularity: said, not run.
                println!("{} pose {k}: {}", R::NAME, e.rule);
                refused += 1;
                continue;
            }
        };
        let r = execute(&s, p, |_| {}).unwrap();
        if r.reference.singular_samples > 0 {
            println!(
                "{} pose {k}: {} samples near a singularity",
                R::NAME,
                r.reference.singular_samples
            );
            refused += 1;
            continue;
        }
        meets_the_bars(&format!("{} pose {k} {law}", R::NAME), &r);
        ran += 1;
    }
    (ran, refused)
}

#[test]
fn the_same_task_at_other_poses_and_on_other_arms_meets_the_same_bars() {
    for robot in ["ur5", "puma560", "panda"] {
        let (ran, refused) =
            armdyn::with_robot_named!(robot, |r: R, N, _module| { other_poses(&r, "task-space") })
                .unwrap();
        println!("{robot}: {ran} poses met the bars, {refused} refused by the planner");
        assert!(ran >= 6, "{robot}: only {ran} poses could run");
    }
}

#[test]
fn joint_space_laws_follow_the_inverse_kinematics_of_a_cartesian_reference() {
    for law in ["pid-fl", "computed-torque"] {
        let text = std::fs::read_to_string(root().join("scenarios/ur5-square.toml"))
            .unwrap()
            .replace(
                "law = \"task-space\"",
                &format!(
                    "law = \"{law}\"{}",
                    if law == "pid-fl" {
                        "\nacceleration_feedforward = true"
                    } else {
                        ""
                    }
                ),
            );
        let s = Scenario::parse("ur5.toml", &text, &root().join("scenarios")).unwrap();
        let (r, _) = run(&s);
        meets_the_bars(&format!("ur5-square with {law}"), &r);
    }
    // Without the acceleration feedforward (the thesis's law) the fast corners lag.
    let text = std::fs::read_to_string(root().join("scenarios/ur5-square.toml"))
        .unwrap()
        .replace("law = \"task-space\"", "law = \"pid-fl\"");
    let s = Scenario::parse("ur5.toml", &text, &root().join("scenarios")).unwrap();
    let (r, _) = run(&s);
    assert!(r.pose.position_rms_m > 0.5e-3, "{:?}", r.pose);
}

#[test]
fn the_scara_runs_the_task_space_law_in_its_four_directions() {
    let text = "format = 1\nname = \"scara-square\"\nrobot = \"scara\"\nstart_on_reference = true\n\n[reference]\nkind = \"waypoints\"\ninterpolation = \"quintic\"\npoints = [\n  [0.0, 0.45, -0.1, 0.2, 0.0],\n  [1.0, 0.65, -0.1, 0.2, 0.3],\n  [2.0, 0.65, 0.1, 0.15, 0.3],\n  [3.0, 0.45, 0.1, 0.2, 0.0],\n]\n\n[position]\nlaw = \"task-space\"\n\n[metrics]\nafter_s = 0.5\n";
    let s = Scenario::parse("scara.toml", text, Path::new(".")).unwrap();
    let (r, m) = run(&s);
    assert_eq!(m["task"], serde_json::json!(["x", "y", "z", "rz"]));
    meets_the_bars("scara-square", &r);
}

/// `text` refused, naming `key` and containing `rule`.
fn refused(text: &str, key: &str, rule: &str) {
    let e = match Scenario::parse("t.toml", text, &root().join("scenarios")) {
        Err(e) => e,
        Ok(s) => prepare(&s).err().expect("refused"),
    };
    assert_eq!(e.key, key, "{e}");
    assert!(e.rule.contains(rule), "{e}");
}

#[test]
fn a_scenario_is_prepared_only_on_its_own_robot() {
    let s = load("ur5-square.toml");
    let e = prepare_for(&s, armdyn::model::Panda)
        .err()
        .expect("a UR5 scenario is refused on the Panda");
    assert_eq!(e.key, "robot", "{e}");
    assert!(
        e.rule.contains("`ur5`") && e.rule.contains("`panda`"),
        "{e}"
    );
}

#[test]
fn a_scenario_is_checked_against_its_robot() {
    let ur5 = std::fs::read_to_string(root().join("scenarios/ur5-square.toml")).unwrap();
    let panda = std::fs::read_to_string(root().join("scenarios/panda-square.toml")).unwrap();
    refused(
        &ur5.replace("start_on_reference = true", "q0 = [0.0, 0.0, 0.0, 0.0]"),
        "q0",
        "needs 6 values",
    );
    refused(
        &ur5.replace(
            "seed = [0.0, -1.5708, 1.5708, -1.5708, -1.5708, 0.0]",
            "seed = [0.0, 1.0]",
        ),
        "reference.seed",
        "needs 6 values",
    );
    refused(
        &ur5.replace("[reference]", "[reference]\nelbow_switch = \"step\""),
        "reference.elbow_switch",
        "`elbow_switch` is robot `scara`'s, not `ur5`'s",
    );
    refused(
        &ur5.replace("[reference]", "[reference]\nelbow_swich = \"step\""),
        "reference.elbow_swich",
        "unknown field `elbow_swich`, expected one of `kind`",
    );
    refused(
        "format = 1\nname = \"t\"\nrobot = \"ur5\"\n[reference]\nkind = \"thesis\"\nname = \"position\"\n[position]\nlaw = \"pid\"\n",
        "reference.kind",
        "no thesis references",
    );
    refused(
        &ur5.replace("[0.6, 0.10, 0.30,", "[3.0, 0.10, 0.30,")
            .replace("0.60, 0.10, 0.30", "3.00, 0.10, 0.30"),
        "reference",
        "leaves the workspace",
    );
    refused(
        &ur5.replace(
            "law = \"task-space\"",
            "law = \"task-space\"\nomega_rad_s = [1.0, 2.0]",
        ),
        "position.law",
        "omega_rad_s has 2 values",
    );
    refused(
        &ur5.replace("robot = \"ur5\"", "robot = \"kuka\""),
        "robot",
        "unknown robot `kuka`",
    );
    refused(
        &panda.replace(
            "posture_weights = [1.0, 1.0, 1.0, 1000.0, 1.0, 1.0, 1.0]",
            "posture_weights = [1.0, 1.0, 1.0, -1.0, 1.0, 1.0, 1.0]",
        ),
        "reference.posture_weights",
        "> 0",
    );
    // Force control needs a square task: a redundant arm is refused, naming [force].
    let with_force = format!(
        "{panda}\n[[surfaces]]\nkind = \"plane\"\npoint = [0.1, 0.0, 0.525]\nnormal = [0.0, 0.0, 1.0]\nhalf_extent = [0.5, 0.5]\nstiffness = 10000.0\n\n[force]\nlaw = \"pi-ff-vd\"\nreference = \"constant\"\nvalue = 10.0\n\n[selection]\nmode = \"contact\"\n"
    );
    // The hybrid law in the full task frame runs it (task-space position law); another
    // position law needs a square task: refused, naming [force] and the way out.
    let s = Scenario::parse("t.toml", &with_force, &root().join("scenarios")).unwrap();
    assert!(prepare(&s).is_ok());
    let other_law = with_force.replace("law = \"task-space\"", "law = \"computed-torque\"");
    assert_ne!(other_law, with_force);
    refused(&other_law, "force", "square task");
    refused(&other_law, "force", "law = \"task-space\"");
}

#[test]
fn plant_mismatch_runs_for_any_robot() {
    let text = std::fs::read_to_string(root().join("scenarios/ur5-square.toml"))
        .unwrap()
        .replace(
            "[metrics]",
            "[plant]\npayload_kg = 2.0\nmass_scale = [1.05, 0.95, 1.1, 1.0, 0.9, 1.0]\nfriction_viscous = [0.5, 0.5, 0.5, 0.1, 0.1, 0.1]\n\n[metrics]",
        );
    let s = Scenario::parse("ur5.toml", &text, &root().join("scenarios")).unwrap();
    let (r, m) = run(&s);
    assert_eq!(m["plant"]["payload_kg"], 2.0);
    // Integral action takes the payload up: still within a millimetre.
    assert!(r.pose.position_max_m < 1e-3, "{:?}", r.pose);
    let e = Scenario::parse(
        "ur5.toml",
        &text.replace(
            "mass_scale = [1.05, 0.95, 1.1, 1.0, 0.9, 1.0]",
            "mass_scale = [1.0, 1.0, 1.0, 1.0]",
        ),
        &root().join("scenarios"),
    )
    .unwrap_err();
    assert!(e.to_string().contains("needs 6 numbers"), "{e}");
}
