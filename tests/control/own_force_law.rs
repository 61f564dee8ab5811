//! A force law of one's own is one file: `ForceDamping` below, written outside the library,
//! implements [`NormalLaw`] and nothing else, and runs in the hybrid law in the full task frame
//! on the shipped contact scenarios of the UR5 and the Panda, in place of their PI law.
//!
//! The law is damping (first-order admittance) control: the position loop's target along the
//! outward normal moves at `h' = (f_d - f) / b`. Pressed on a surface of stiffness `k` through a
//! stiff position loop, `f = k h` and the force error decays as `exp(-t k / b)`: the force
//! settles on its reference without a force gain, and a larger `b` settles it more slowly.

use std::path::Path;

use armdyn::control::hybrid::TaskSpaceHybrid;
use armdyn::control::normal_law::{NormalCommand, NormalLaw, NormalSample};
use armdyn::control::task_frame::TaskFrame;
use armdyn::control::task_space::TaskSpaceGains;
use armdyn::control::tool_orientation::ToolOrientation;
use armdyn::metrics::ContactSummary;
use armdyn::model::{Panda, Ur5};
use armdyn::scenario::{prepare_for, shifted, Scenario, ScenarioRobot, TASK_SPACE_OMEGA};

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

/// Runs the shipped `file` with its hybrid PI law replaced by [`ForceDamping`] of damping `b`
/// (the file's motion gains, surface belief and switching kept): the controller's name and
/// the contact metrics.
fn run_with_damping<const N: usize, R: ScenarioRobot<N> + Copy + 'static>(
    file: &str,
    robot: R,
    b: f64,
) -> (&'static str, ContactSummary) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenarios")
        .join(file);
    let scenario = Scenario::load(&path).expect("a shipped scenario");
    let force = scenario.force.as_ref().expect("a force scenario");
    let settings = &scenario.position_settings;
    let omega = vec![TASK_SPACE_OMEGA; R::TASK.len()];
    let gains = TaskSpaceGains::critically_damped::<N, R>(
        settings.omega_rad_s.as_deref().unwrap_or(&omega),
        settings.damping_ratio,
        settings.posture_omega_rad_s,
        settings.integral,
    );
    let belief = shifted(
        &scenario.surfaces[force.surface].geometry,
        force.expected_shift_m,
    );
    let law = TaskSpaceHybrid::in_task_frame(
        robot,
        gains,
        ForceDamping { b, height_m: 0.0 },
        TaskFrame::Surface(belief),
        ToolOrientation::Reference,
        scenario.selection.expect("a switching rule"),
    )
    .expect("the task controls the three translations");
    let mut prepared = prepare_for(&scenario, robot).expect("prepares");
    prepared.controller = Box::new(law);
    let run = prepared.execute(&scenario, |_| {}).expect("runs");
    let contact = run.outcome.contact.expect("contact metrics");
    (run.outcome.controller_name, contact)
}

fn settles_on_its_reference<const N: usize, R: ScenarioRobot<N> + Copy + 'static>(
    file: &str,
    robot: R,
    value_n: f64,
) {
    // The contact is 10 kN/m: b = 1000 N s/m is a time constant of 0.1 s, b = 4000 of 0.4 s.
    let (name, fast) = run_with_damping(file, robot, 1000.0);
    let (_, slow) = run_with_damping(file, robot, 4000.0);
    println!("{file}: {name}\n  b = 1000: {fast:?}\n  b = 4000: {slow:?}");
    assert_eq!(name, "task-space-hybrid-force-damping");
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
    settles_on_its_reference("ur5-press-table.toml", Ur5, 30.0);
}

#[test]
fn a_force_law_written_outside_the_library_presses_the_panda_while_it_wipes() {
    settles_on_its_reference("panda-wipe.toml", Panda, 15.0);
}
