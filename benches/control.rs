//! Criterion benchmarks of the controllers and the simulator: one controller step on the
//! SCARA (position controllers and the full hybrid force/position step: kinematics,
//! feedback linearization, PID, force PI, selection, Jacobian transpose) and on the UR5 and
//! the Panda (task-space inverse dynamics, PID-FL with acceleration feedforward, computed
//! torque; the UR5's hybrid law), the reference of one sample on the UR5 (numerical IK) and
//! the Panda (its planned path) and the SCARA (closed-form IK, damped Jacobian solve), and whole 10 s SCARA trials (10 000 control samples, RK4 at
//! 1 ms, with inverse kinematics of the reference at every sample).
//!
//! Run: `cargo bench --bench control`.

use std::hint::black_box;
use std::time::Duration;

use armdyn::contact::FreeSpace;
use armdyn::control::ControllerInput;
use armdyn::model::{Scara, Wrench};
use armdyn::robots::scara::presets::{
    position_controller, ForceReference, HybridSetup, THESIS_FORCE_LAWS, THESIS_POSITION_LAWS,
};
use armdyn::robots::scara::reference::ScaraReference;
use armdyn::robots::scara::thesis::{ContactTest, PositionTest};
use armdyn::robots::scara::{ScaraGeometry, SwitchPolicy};
use armdyn::scenario::{run, DesiredForce, ForceController, PositionController};
use armdyn::sim::{ReferenceSource, Setpoint, SimConfig};
use armdyn::target::CartesianTarget;
use armdyn::target::JointTarget;
use criterion::{criterion_group, criterion_main, Criterion};
use nalgebra::{Vector3, Vector4};

fn steps(c: &mut Criterion) {
    let q = Vector4::new(0.3, 0.8, 0.2, 0.1);
    let qd = Vector4::new(0.2, -0.1, 0.05, 0.3);
    let target = JointTarget {
        q: q * 1.01,
        qd: qd * 0.9,
        qdd: Vector4::new(0.1, 0.2, 0.0, -0.1),
    };
    let cart = CartesianTarget::at_rest(
        Vector3::new(0.45, -0.1, 0.13),
        armdyn::target::orientation::from_yaw(0.0),
    );
    let f = Wrench::new(0.0, 0.0, -150.0, 0.0, 0.0, 0.0);
    let f_d = Wrench::new(0.0, 0.0, -200.0, 0.0, 0.0, 0.0);
    let mut group = c.benchmark_group("step");
    for pc in THESIS_POSITION_LAWS {
        let (mut ctrl, _) = position_controller(pc).expect("gains");
        group.bench_function(pc.name(), |b| {
            b.iter(|| {
                let input = ControllerInput {
                    t: 1.0,
                    q: &q,
                    qd: &qd,
                    target: &target,
                    cartesian: &cart,
                    wrench: &f,
                    wrench_ref: &f_d,
                    wrench_age_s: 0.0,
                };
                ctrl.step(black_box(&input), 1e-3)
            })
        });
    }
    for fc in THESIS_FORCE_LAWS {
        let (mut ctrl, _) = HybridSetup::build(fc).expect("gains");
        // t = 3 s: after the switch, so the Jacobian solve and the force loop both run.
        group.bench_function(format!("hybrid-{}", fc.name()), |b| {
            b.iter(|| {
                let input = ControllerInput {
                    t: 3.0,
                    q: &q,
                    qd: &qd,
                    target: &target,
                    cartesian: &cart,
                    wrench: &f,
                    wrench_ref: &f_d,
                    wrench_age_s: 0.0,
                };
                ctrl.step(black_box(&input), 1e-3)
            })
        });
    }
    // The task-frame hybrid of a shipped scenario: the sphere's normal at the tool, contact
    // switching (force controlled after the debounce), gravity along the normal.
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios/sphere-patch.toml");
    let mut scenario = armdyn::scenario::Scenario::load(&path).expect("shipped scenario");
    scenario.safety.enabled = false;
    let mut ctrl = armdyn::scenario::prepare_for(&scenario, Scara)
        .expect("prepares")
        .controller;
    let input = ControllerInput {
        t: 3.0,
        q: &q,
        qd: &qd,
        target: &target,
        cartesian: &cart,
        wrench: &f,
        wrench_ref: &f_d,
        wrench_age_s: 0.0,
    };
    for _ in 0..10 {
        ctrl.step(&input, 1e-3);
    }
    assert!(
        ctrl.report().force_controlled,
        "the benchmark measures the force-controlled step"
    );
    group.bench_function("hybrid-sphere-contact", |b| {
        b.iter(|| ctrl.step(black_box(&input), 1e-3))
    });
    group.finish();
    arm_steps(c);
    safety_steps(c);
}

/// The safety supervisor's overhead: the hybrid step of the thesis's trial (the SCARA) and
/// of the Panda wiping, each bare and inside the supervisor with the scenario's defaults,
/// force controlled and nothing tripped.
fn safety_steps(c: &mut Criterion) {
    use armdyn::model::Panda;
    let mut group = c.benchmark_group("safety");
    for (label, edit) in [("bare", ""), ("supervised", "\n# supervised\n")] {
        let edits = [("switch_s = 2.0", &*format!("switch_s = 2.0{edit}"))];
        let p = edited_controller(Scara, "thesis-hybrid.toml", &edits);
        bench_step(&mut group, &format!("scara-hybrid-{label}"), p, 3.0);
        let edits = [(
            "mode = \"contact\"",
            &*format!("mode = \"time\"\nswitch_s = 1.0{edit}"),
        )];
        let p = edited_controller(Panda, "panda-wipe.toml", &edits);
        bench_step(
            &mut group,
            &format!("panda-task-space-hybrid-{label}"),
            p,
            4.0,
        );
    }
    group.finish();
}

/// A scenario file's controller for `robot`, with its position law replaced by `law` (the
/// `[position]` lines) and `extra` appended.
fn arm_controller<const N: usize, R: armdyn::scenario::ScenarioRobot<N>>(
    robot: R,
    file: &str,
    law: &str,
    extra: &str,
) -> armdyn::scenario::PreparedRun<N, R> {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios");
    let text = std::fs::read_to_string(dir.join(file))
        .expect("shipped scenario")
        .replace("law = \"task-space\"", law);
    let mut s =
        armdyn::scenario::Scenario::parse(file, &format!("{text}\n{extra}"), &dir).expect("checks");
    // The law's own step (the supervisor's overhead is the `safety` group's).
    s.safety.enabled = false;
    armdyn::scenario::prepare_for(&s, robot).expect("prepares")
}

/// A shipped scenario file's controller for `robot`, with the text edits `edits` made.
fn edited_controller<const N: usize, R: armdyn::scenario::ScenarioRobot<N>>(
    robot: R,
    file: &str,
    edits: &[(&str, &str)],
) -> armdyn::scenario::PreparedRun<N, R> {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios");
    let mut text = std::fs::read_to_string(dir.join(file)).expect("shipped scenario");
    for (from, to) in edits {
        assert!(text.contains(from), "{file} has no `{from}`");
        text = text.replace(from, to);
    }
    let mut s = armdyn::scenario::Scenario::parse(file, &text, &dir).expect("checks");
    s.safety.enabled = supervised(&text);
    armdyn::scenario::prepare_for(&s, robot).expect("prepares")
}

/// Whether an edited scenario keeps its supervisor: only where the edits say so (the
/// `safety` group), the other steps being the laws' own.
fn supervised(text: &str) -> bool {
    text.contains("# supervised")
}

/// Benchmarks one step of `p`'s controller at its reference's state at `t` (s), the joint
/// velocities 2 % off the reference's and the tool pressing with 5 N more than asked.
fn bench_step<const N: usize, R: armdyn::scenario::ScenarioRobot<N>>(
    group: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
    name: &str,
    mut p: armdyn::scenario::PreparedRun<N, R>,
    t: f64,
) {
    let mut sp = p.reference.at(t);
    if let Some(f) = &p.force {
        sp.wrench = f.wrench(t, &sp.cartesian.position);
    }
    let qd = sp.joint.qd * 0.98;
    let q = sp.joint.q;
    let f = sp.wrench * 1.0 + Wrench::new(0.0, 0.0, -5.0, 0.0, 0.0, 0.0);
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
    group.bench_function(name, |b| {
        b.iter(|| p.controller.step(black_box(&input), 1e-3))
    });
    let trips = p.controller.report().safety.map_or(0, |r| r.trips.len());
    assert_eq!(trips, 0, "{name}: the supervisor tripped while benchmarked");
}

/// One controller step of the UR5 and the Panda, at a state of their shipped square
/// (t = 1.5 s, on the second side), beside the SCARA's.
fn arm_steps(c: &mut Criterion) {
    use armdyn::model::{Panda, Ur5};
    let mut group = c.benchmark_group("step");
    let laws = [
        ("task-space", "law = \"task-space\""),
        (
            "pid-fl-ff",
            "law = \"pid-fl\"\nacceleration_feedforward = true",
        ),
        ("computed-torque", "law = \"computed-torque\""),
    ];
    macro_rules! bench_arm {
        ($robot:expr, $name:literal, $file:literal, $laws:expr, $extra:expr) => {
            for (label, law) in $laws {
                let mut p = arm_controller($robot, $file, law, $extra);
                let sp = p.reference.at(1.5);
                let qd = sp.joint.qd * 0.98;
                let q = sp.joint.q;
                let f = Wrench::new(0.0, 0.0, -5.0, 0.0, 0.0, 0.0);
                let input = ControllerInput {
                    t: 1.5,
                    q: &q,
                    qd: &qd,
                    target: &sp.joint,
                    cartesian: &sp.cartesian,
                    wrench: &f,
                    wrench_ref: &sp.wrench,
                    wrench_age_s: 0.0,
                };
                group.bench_function(format!("{}-{label}", $name), |b| {
                    b.iter(|| p.controller.step(black_box(&input), 1e-3))
                });
            }
        };
    }
    bench_arm!(Ur5, "ur5", "ur5-square.toml", laws, "");
    bench_arm!(Panda, "panda", "panda-square.toml", laws, "");
    // The UR5's hybrid law, force controlled along a plane's normal (the time switch at
    // 1 s is behind the benchmarked state).
    let plane = "[[surfaces]]\nkind = \"plane\"\npoint = [0.5, 0.0, 0.29]\nnormal = [0.0, 0.0, 1.0]\nhalf_extent = [0.5, 0.5]\nstiffness = 10000.0\n\n[force]\nlaw = \"pi-ff-vd\"\nreference = \"constant\"\nvalue = 10.0\n\n[selection]\nmode = \"time\"\nswitch_s = 1.0\n";
    bench_arm!(
        Ur5,
        "ur5",
        "ur5-square.toml",
        [(
            "hybrid-pi-ff-vd",
            "law = \"pid-fl\"\nacceleration_feedforward = true"
        )],
        plane
    );
    // The hybrid law in the full task frame (task-space motion, force along the normal),
    // force controlled: the UR5 on its table and the Panda wiping, at t = 4 s, with the
    // contact switch replaced by a time switch at 1 s (behind the benchmarked state).
    for (name, file) in [
        ("ur5-task-space-hybrid", "ur5-press-table.toml"),
        ("panda-task-space-hybrid", "panda-wipe.toml"),
    ] {
        let edits = [("mode = \"contact\"", "mode = \"time\"\nswitch_s = 1.0")];
        match file {
            "ur5-press-table.toml" => {
                let p = edited_controller(Ur5, file, &edits);
                bench_step(&mut group, name, p, 4.0);
            }
            _ => {
                let p = edited_controller(Panda, file, &edits);
                bench_step(&mut group, name, p, 4.0);
            }
        }
    }
    // The reference of one sample: the UR5's numerical inverse kinematics (warm-started) and
    // the Panda's planned path.
    let mut ur5 = arm_controller(Ur5, "ur5-square.toml", "law = \"task-space\"", "");
    let mut t = 0.0;
    group.bench_function("ur5-reference-ik", |b| {
        b.iter(|| {
            t = (t + 1e-3) % 6.0;
            ur5.reference.at(black_box(t))
        })
    });
    // The SCARA's: closed-form inverse kinematics, the reduced Jacobian's (damped) solve
    // for qd and qdd, on the thesis contact trajectory.
    let geometry = ScaraGeometry::from_model(&Scara);
    let contact = ContactTest::thesis();
    let plan = geometry
        .plan_trajectory(&contact, 0.005, SwitchPolicy::Latest)
        .expect("reachable");
    let mut scara_reference = ScaraReference::new(geometry, &contact, plan);
    group.bench_function("scara-reference-ik", |b| {
        b.iter(|| {
            t = (t + 1e-3) % 10.0;
            scara_reference.at(black_box(t))
        })
    });
    let mut panda = arm_controller(Panda, "panda-square.toml", "law = \"task-space\"", "");
    group.bench_function("panda-reference-path", |b| {
        b.iter(|| {
            t = (t + 1e-3) % 6.0;
            panda.reference.at(black_box(t))
        })
    });
    group.finish();
}

/// A joint reference with the desired force added.
struct WithForce<S> {
    inner: S,
    force: DesiredForce,
}

impl<S: ReferenceSource<4>> ReferenceSource<4> for WithForce<S> {
    fn at(&mut self, t: f64) -> Setpoint<4> {
        let mut s = self.inner.at(t);
        s.wrench = self.force.wrench(t, &s.cartesian.position);
        s
    }
}

fn trials(c: &mut Criterion) {
    let geometry = ScaraGeometry::from_model(&Scara);
    let mut group = c.benchmark_group("trial_10s");
    group
        .sample_size(20)
        .measurement_time(Duration::from_secs(8));
    let contact = ContactTest::thesis();
    let plan = geometry
        .plan_trajectory(&contact, 0.005, SwitchPolicy::Latest)
        .expect("reachable");
    group.bench_function("hybrid-pi-ff-vd-const", |b| {
        b.iter(|| {
            let (mut ctrl, _) = HybridSetup::build(ForceController::PiFfVd).expect("gains");
            let mut reference = WithForce {
                inner: ScaraReference::new(geometry, &contact, plan.clone()),
                force: DesiredForce::along_z(ForceReference::Const.profile()),
            };
            run(
                &Scara,
                ctrl.as_mut(),
                &mut reference,
                &armdyn::robots::scara::thesis_setup::thesis_surface(),
                &SimConfig::new(&Scara),
                |_| {},
            )
            .expect("simulates")
            .samples
            .len()
        })
    });
    let position = PositionTest::new();
    let plan = geometry
        .plan_trajectory(&position, 0.005, SwitchPolicy::Latest)
        .expect("reachable");
    group.bench_function("position-pid-fl", |b| {
        b.iter(|| {
            let (mut ctrl, _) = position_controller(PositionController::PidFl).expect("gains");
            let mut reference = ScaraReference::new(geometry, &position, plan.clone());
            run(
                &Scara,
                ctrl.as_mut(),
                &mut reference,
                &FreeSpace,
                &SimConfig::new(&Scara),
                |_| {},
            )
            .expect("simulates")
            .samples
            .len()
        })
    });
    group.finish();
}

criterion_group!(benches, steps, trials);
criterion_main!(benches);
