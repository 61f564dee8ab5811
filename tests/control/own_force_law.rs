//! A force law of one's own is one file: `ForceDamping` below, written outside the library,
//! implements [`NormalLaw`] and nothing else, and runs in the hybrid law in place of a
//! scenario's PI law: in the full task frame on the shipped contact scenarios of the UR5 and
//! the Panda (and the UR5's table moved, stiffer, pressed harder), and through the SCARA's task
//! rows in the thesis's joint-space loop on its contact scenarios.
//!
//! The law is damping (first-order admittance) control: the position loop's target along the
//! outward normal moves at `h' = (f_d - f) / b`. Pressed on a surface of stiffness `k` through a
//! stiff position loop, `f = k h` and the force error decays as `exp(-t k / b)`: the force
//! settles on its reference without a force gain, and a larger `b` settles it more slowly.

use std::path::Path;

use armdyn::control::hybrid::{HybridForcePosition, TaskSpaceHybrid};
use armdyn::control::mass_split::SplitKind;
use armdyn::control::normal_law::{NormalCommand, NormalLaw, NormalSample};
use armdyn::control::task_frame::TaskFrame;
use armdyn::control::task_space::TaskSpaceGains;
use armdyn::control::tool_orientation::ToolOrientation;
use armdyn::control::Controller;
use armdyn::metrics::ContactSummary;
use armdyn::model::{Panda, Scara, Ur5};
use armdyn::robots::scara::presets::HybridSetup;
use armdyn::robots::scara::thesis_setup::thesis_position_loop;
use armdyn::scenario::{prepare_for, Scenario, ScenarioRobot, TASK_SPACE_OMEGA};

/// `h' = (f_d - f) / b` (m/s), `b` in N s/m; `h` (m) is the target's height above the
/// expected surface along its outward normal. Forces along the normal are negative when the
/// tool presses.
#[derive(Clone, Debug)]
struct ForceDamping {
    b: f64,
    height_m: f64,
}

impl NormalLaw for ForceDamping {
    fn name(&self) -> &'static str {
        "force-damping"
    }

    fn controller_names(&self) -> (&'static str, &'static str) {
        ("hybrid-force-damping", "task-space-hybrid-force-damping")
    }

    fn reset(&mut self) {
        self.height_m = 0.0;
    }

    /// Bumpless: from where the position loop's target is at the switch.
    fn start(&mut self, _sample: &NormalSample, height_m: f64, _rate_m_s: f64) {
        self.height_m = height_m;
    }

    fn step(&mut self, s: &NormalSample, dt: f64) -> NormalCommand {
        let rate_m_s = (s.f_d - s.f) / self.b;
        self.height_m += rate_m_s * dt;
        NormalCommand::Height {
            height_m: self.height_m,
            rate_m_s,
        }
    }
}

fn shipped(file: &str) -> Scenario {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenarios")
        .join(file);
    Scenario::load(&path).expect("a shipped scenario")
}

/// Runs `scenario` with `controller` in place of its own: the controller's name and the
/// contact metrics.
fn run_with<const N: usize, R: ScenarioRobot<N> + Copy + 'static>(
    scenario: &Scenario,
    robot: R,
    controller: Box<dyn Controller<N>>,
) -> (&'static str, ContactSummary) {
    let mut prepared = prepare_for(scenario, robot).expect("prepares");
    prepared.controller = controller;
    let run = prepared.execute(scenario, |_| {}).expect("runs");
    let contact = run.outcome.contact.expect("contact metrics");
    (run.outcome.controller_name, contact)
}

/// Runs `scenario` with its hybrid PI law in the full task frame replaced by
/// [`ForceDamping`] of damping `b` (the file's motion gains, surface belief and switching
/// kept).
fn in_task_frame<const N: usize, R: ScenarioRobot<N> + Copy + 'static>(
    scenario: &Scenario,
    robot: R,
    b: f64,
) -> (&'static str, ContactSummary) {
    let force = scenario.force.as_ref().expect("a force scenario");
    let settings = &scenario.position_settings;
    let omega = vec![TASK_SPACE_OMEGA; R::TASK.len()];
    let gains = TaskSpaceGains::critically_damped::<N, R>(
        settings.omega_rad_s.as_deref().unwrap_or(&omega),
        settings.damping_ratio,
        settings.posture_omega_rad_s,
        settings.integral,
    );
    let belief = scenario.surfaces[force.surface]
        .geometry
        .shifted(force.expected_shift_m);
    let law = TaskSpaceHybrid::in_task_frame(
        robot,
        gains,
        ForceDamping { b, height_m: 0.0 },
        TaskFrame::Surface(belief),
        ToolOrientation::Reference,
        scenario.selection.expect("a switching rule"),
    )
    .expect("the task controls the three translations");
    run_with(scenario, robot, Box::new(law))
}

/// The runs of `run(b)` for the damping `b` (N s/m) and four times it name the law and settle
/// on the reference `value_n` without steady error, the second later.
fn settles_on_its_reference(
    file: &str,
    value_n: f64,
    name_with_law: &str,
    b: f64,
    run: impl Fn(f64) -> (&'static str, ContactSummary),
) {
    let (name, fast) = run(b);
    let (_, slow) = run(4.0 * b);
    println!(
        "{file}: {name}\n  b = {b}: {fast:?}\n  b = {}: {slow:?}",
        4.0 * b
    );
    assert_eq!(name, name_with_law);
    for m in [&fast, &slow] {
        assert!(m.first_touch_s.is_some(), "{m:?}");
        assert_eq!(m.contact_losses, 0, "{m:?}");
        // Integral action: no steady force error beyond a hundredth of the reference.
        assert!(
            m.normal_force_steady_error_n.abs() <= 0.01 * value_n,
            "{m:?}"
        );
        assert!(m.normal_force_settling_time_s.is_some(), "{m:?}");
    }
    let (t_fast, t_slow) = (
        fast.normal_force_settling_time_s.unwrap(),
        slow.normal_force_settling_time_s.unwrap(),
    );
    assert!(
        t_slow > t_fast,
        "four times the damping settles in {t_slow} s, not slower than {t_fast} s"
    );
}

#[test]
fn a_force_law_written_outside_the_library_presses_the_ur5_on_its_table() {
    let file = "ur5-press-table.toml";
    let name = "task-space-hybrid-force-damping";
    let scenario = shipped(file);
    settles_on_its_reference(file, 30.0, name, 1000.0, |b| {
        in_task_frame(&scenario, Ur5, b)
    });
}

#[test]
fn a_force_law_written_outside_the_library_presses_the_panda_while_it_wipes() {
    let file = "panda-wipe.toml";
    let name = "task-space-hybrid-force-damping";
    let scenario = shipped(file);
    settles_on_its_reference(file, 15.0, name, 1000.0, |b| {
        in_task_frame(&scenario, Panda, b)
    });
}

#[test]
fn a_force_law_written_outside_the_library_presses_a_higher_stiffer_table_harder() {
    // Not the shipped file: the table 12 mm above the belief (not 5), twice as stiff, 50 N.
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios/ur5-press-table.toml");
    let text = std::fs::read_to_string(&path)
        .expect("the shipped file")
        .replace("point = [0.40, 0.0, 0.255]", "point = [0.40, 0.0, 0.262]")
        .replace("stiffness = 10000.0", "stiffness = 20000.0")
        .replace("value = 30.0", "value = 50.0");
    let scenario = Scenario::parse("variant.toml", &text, path.parent().unwrap()).expect("parses");
    assert_eq!(scenario.surfaces[0].stiffness, 20000.0);
    assert_eq!(scenario.force.as_ref().expect("a force").value_n, 50.0);
    let name = "task-space-hybrid-force-damping";
    settles_on_its_reference("variant", 50.0, name, 1000.0, |b| {
        in_task_frame(&scenario, Ur5, b)
    });
}

/// Runs the shipped SCARA `file` with its hybrid law replaced by the thesis's joint-space
/// position loop (PID with feedback linearisation through the x, y, z, yaw rows) and
/// [`ForceDamping`] of damping `b` (the file's surface belief and switching kept).
fn through_task_rows(file: &str, b: f64) -> (&'static str, ContactSummary) {
    let scenario = shipped(file);
    let force = scenario.force.as_ref().expect("a force scenario");
    let belief = scenario.surfaces[force.surface]
        .geometry
        .shifted(force.expected_shift_m);
    let position = thesis_position_loop(SplitKind::ConstantPart).expect("the design");
    let hybrid = HybridForcePosition::new(
        Scara,
        position,
        ForceDamping { b, height_m: 0.0 },
        TaskFrame::Surface(belief),
        scenario.selection.expect("a switching rule"),
        HybridSetup::ROWS,
    )
    .expect("the SCARA's task rows");
    run_with(&scenario, Scara, Box::new(hybrid))
}

#[test]
fn a_force_law_written_outside_the_library_runs_in_the_thesiss_joint_space_loop() {
    // The thesis's PID settles its integral slowly: the damping law in front of it stays
    // well damped for time constants up to a few hundredths of a second (b = 100 and 400 N
    // s/m on 10 kN/m; from b = 1000 on it swings for seconds).
    for file in ["oblique-plane.toml", "unknown-height.toml"] {
        let run = |b| through_task_rows(file, b);
        settles_on_its_reference(file, 200.0, "hybrid-force-damping", 100.0, run);
    }
}
