//! Zero heap allocations across every generated function of every robot, called directly
//! and through `RobotModel`, and across forward and inverse dynamics.
//!
//! A counting global allocator wraps the system allocator and counts the allocations made
//! by this thread while counting is switched on (so the test harness's own threads do not
//! interfere). `unsafe` is needed only to implement `GlobalAlloc`; the library under test
//! forbids it, and this test file is a separate crate.

use armdyn_generated::wide::{f64x2, f64x4};
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::hint::black_box;

use approx::assert_abs_diff_eq;
use armdyn::model::{
    external_joint_torque, forward_dynamics, forward_dynamics_cholesky,
    forward_dynamics_derivatives_with_wrench, inverse_dynamics,
    inverse_dynamics_derivatives_with_wrench, DynamicsDerivatives, RobotModel, Scara, Wrench,
};
use nalgebra::SVector;

thread_local! {
    // Const-initialised and without `Drop`: reading these never allocates.
    static COUNTING: Cell<bool> = const { Cell::new(false) };
    static ALLOCATIONS: Cell<usize> = const { Cell::new(0) };
}

fn note_allocation() {
    // `try_with`: the thread-locals may already be gone while a thread shuts down.
    let _ = COUNTING.try_with(|on| {
        if on.get() {
            let _ = ALLOCATIONS.try_with(|n| n.set(n.get() + 1));
        }
    });
}

/// The system allocator, plus a per-thread count of allocations.
struct CountingAllocator;

// SAFETY: every method forwards to `System` with the caller's arguments unchanged; the
// bookkeeping touches only thread-local `Cell`s and never allocates.
unsafe impl GlobalAlloc for CountingAllocator {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        note_allocation();
        // SAFETY: forwarded verbatim; the caller upholds `GlobalAlloc::alloc`'s contract.
        unsafe { System.alloc(layout) }
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        note_allocation();
        // SAFETY: as above.
        unsafe { System.alloc_zeroed(layout) }
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        note_allocation();
        // SAFETY: as above.
        unsafe { System.realloc(ptr, layout, new_size) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: as above.
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static GLOBAL: CountingAllocator = CountingAllocator;

/// Runs `f` with counting on and returns the number of allocations it made.
fn allocations_in(f: impl FnOnce()) -> usize {
    ALLOCATIONS.with(|n| n.set(0));
    COUNTING.with(|on| on.set(true));
    f();
    COUNTING.with(|on| on.set(false));
    ALLOCATIONS.with(|n| n.get())
}

/// Calls every generated function of `$module` (and of `$module::parametric`) at a few
/// states.
macro_rules! call_generated {
    ($module:ident, $n:literal) => {{
        use armdyn_generated::$module as g;
        let params = black_box(g::standard_parameters());
        for k in 0..8 {
            let q: [f64; $n] = core::array::from_fn(|i| 0.1 * (k as f64) - 0.05 * (i as f64));
            let qd: [f64; $n] =
                core::array::from_fn(|i| 0.3 - 0.1 * (i as f64) + 0.01 * (k as f64));
            let qdd: [f64; $n] = core::array::from_fn(|i| 1.0 - 0.2 * (i as f64));
            let (q, qd, qdd) = (black_box(&q), black_box(&qd), black_box(&qdd));
            black_box(g::frame_poses(q));
            black_box(g::end_effector_pose(q));
            black_box(g::jacobian(q));
            black_box(g::jacobian_and_position(q));
            black_box(g::jdot_qd(q, qd));
            black_box(g::mass_matrix(q));
            black_box(g::coriolis_matrix(q, qd));
            black_box(g::coriolis(q, qd));
            black_box(g::gravity(q));
            black_box(g::inverse_dynamics(q, qd, qdd));
            black_box(g::forward_dynamics(q, qd, qdd));
            black_box(g::regressor(q, qd, qdd));
            black_box(g::standard_parameters());
            black_box(g::jacobian_derivatives(q));
            black_box(g::inverse_dynamics_derivatives(q, qd, qdd));
            black_box(g::forward_dynamics_derivatives(q, qd, qdd));
            black_box(g::f32::forward_dynamics_derivatives(
                &q.map(|v| v as f32),
                &qd.map(|v| v as f32),
                &qdd.map(|v| v as f32),
            ));
            black_box(g::parametric::mass_matrix(q, &params));
            black_box(g::parametric::coriolis_matrix(q, qd, &params));
            black_box(g::parametric::coriolis(q, qd, &params));
            black_box(g::parametric::gravity(q, &params));
            black_box(g::parametric::inverse_dynamics(q, qd, qdd, &params));
            black_box(g::parametric::forward_dynamics(q, qd, qdd, &params));
            // The lane functions, in both SIMD widths.
            let (q4, qd4) = (q.map(f64x4::splat), qd.map(f64x4::splat));
            black_box(g::lanes::mass_matrix_and_bias(&q4, &qd4));
            black_box(g::lanes::forward_dynamics(&q4, &qd4, &qd4));
            black_box(g::lanes::inverse_dynamics(&q4, &qd4, &qd4));
            black_box(g::lanes::jacobian(&q4));
            let (q2, qd2) = (q.map(f64x2::splat), qd.map(f64x2::splat));
            black_box(g::lanes::mass_matrix_and_bias(&q2, &qd2));
            black_box(g::lanes::forward_dynamics(&q2, &qd2, &qd2));
        }
    }};
}

/// Calls every `RobotModel` method and the dynamics functions.
fn call_model<const N: usize, R: DynamicsDerivatives<N>>(robot: &R) {
    for k in 0..8 {
        let q = SVector::<f64, N>::from_fn(|i, _| 0.1 * (k as f64) - 0.05 * (i as f64));
        let qd = SVector::<f64, N>::from_fn(|i, _| 0.3 - 0.1 * (i as f64));
        let q = black_box(q);
        let qd = black_box(qd);
        black_box(robot.frame_poses(&q));
        black_box(robot.end_effector_pose(&q));
        black_box(robot.jacobian(&q));
        black_box(robot.jacobian_and_position(&q));
        black_box(robot.mass_matrix(&q));
        black_box(robot.coriolis_matrix(&q, &qd));
        black_box(robot.coriolis(&q, &qd));
        black_box(robot.gravity(&q));
        black_box(robot.jdot_qd(&q, &qd));
        black_box(robot.inverse_dynamics(&q, &qd, &qd));
        let tau = robot.gravity(&q);
        let qdd = forward_dynamics(robot, &q, &qd, &tau, &SVector::zeros());
        let qdd = black_box(qdd).unwrap_or_else(|_| SVector::zeros());
        black_box(forward_dynamics_cholesky(robot, &q, &qd, &tau, &SVector::zeros()).ok());
        black_box(external_joint_torque(
            robot,
            &q,
            &Wrench::new(0.0, 0.0, -200.0, 0.0, 0.0, 0.0),
        ));
        black_box(inverse_dynamics(robot, &q, &qd, &qdd, &SVector::zeros()));
        let wrench = Wrench::new(10.0, -5.0, -200.0, 1.0, 0.5, -0.2);
        black_box(robot.inverse_dynamics_derivatives(&q, &qd, &qdd));
        black_box(robot.forward_dynamics_derivatives(&q, &qd, &tau).ok());
        black_box(inverse_dynamics_derivatives_with_wrench(
            robot, &q, &qd, &qdd, &wrench,
        ));
        black_box(forward_dynamics_derivatives_with_wrench(robot, &q, &qd, &tau, &wrench).ok());
        // The error path must not allocate either.
        let bad = SVector::<f64, N>::from_element(f64::NAN);
        let _ = black_box(forward_dynamics(robot, &bad, &qd, &tau, &SVector::zeros()));
    }
}

// One test only, so nothing else runs in this process while counting.
#[test]
fn generated_code_and_dynamics_never_allocate() {
    // Sanity: the counter does see an allocation.
    let seen = allocations_in(|| {
        black_box(vec![1u8; 16]);
    });
    assert_eq!(seen, 1, "the counting allocator does not count");

    // Every robot of the generated registry: its generated functions, then its model type.
    macro_rules! count_every_robot {
        ([] $(($module:ident, $ty:ident, $n:literal, $doc:literal))*) => {
            [
                $((
                    concat!(stringify!($module), " (generated)"),
                    allocations_in(|| call_generated!($module, $n)),
                ),)*
                $((
                    concat!(stringify!($module), " (model + dynamics)"),
                    allocations_in(|| call_model(&armdyn::model::$ty)),
                ),)*
            ]
        };
    }
    let counts = armdyn_generated::for_each_robot!(count_every_robot);
    for (what, n) in counts {
        assert_eq!(n, 0, "{what}: {n} allocation(s)");
    }

    // The slice API of batched evaluation, into outputs allocated beforehand.
    use armdyn::model::batch::{
        forward_dynamics_batch, inverse_dynamics_batch, mass_matrix_and_bias_batch,
    };
    let q = vec![[0.2; 7]; 11];
    let (mut out, mut mass, mut bias) = (
        vec![[0.0; 7]; 11],
        vec![[[0.0; 7]; 7]; 11],
        vec![[0.0; 7]; 11],
    );
    let n = allocations_in(|| {
        let panda = armdyn::model::Panda;
        forward_dynamics_batch(&panda, &q, &q, &q, &mut out).unwrap();
        inverse_dynamics_batch(&panda, &q, &q, &q, &mut out).unwrap();
        mass_matrix_and_bias_batch(&panda, &q, &q, &mut mass, &mut bias).unwrap();
        black_box((&out, &mass, &bias));
    });
    assert_eq!(n, 0, "batched evaluation: {n} allocation(s)");
}

/// Every controller's `step` (built beforehand: gain design may allocate) and a whole
/// simulated second of the hybrid loop through `simulate` allocate nothing.
#[test]
fn controller_steps_and_the_simulator_never_allocate() {
    use armdyn::control::ControllerInput;
    use armdyn::robots::scara::presets::{
        position_controller, HybridSetup, THESIS_FORCE_LAWS, THESIS_POSITION_LAWS,
    };
    use armdyn::scenario::ForceController;
    use armdyn::sim::{simulate, ReferenceSource, Setpoint, SimConfig};
    use armdyn::target::CartesianTarget;
    use armdyn::target::JointTarget;
    use nalgebra::{Vector3, Vector4};

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
    let mut controllers: Vec<Box<dyn armdyn::control::Controller<4>>> = THESIS_POSITION_LAWS
        .iter()
        .map(|c| position_controller(*c).unwrap().0)
        .collect();
    for fc in THESIS_FORCE_LAWS {
        controllers.push(HybridSetup::build(fc).unwrap().0);
    }
    let sensor =
        armdyn::contact::ForceSensor::new(Wrench::repeat(1.0), Wrench::repeat(2.0), Some(50.0), 3)
            .unwrap();
    controllers.push(Box::new(armdyn::control::sensed::Sensed::new(
        HybridSetup::build(ForceController::PiFfVd).unwrap().0,
        sensor,
    )));
    // The deployable hybrid step in both precisions.
    controllers.push(Box::new(armdyn::robots::scara::deploy::Deployed::new(
        armdyn::robots::scara::deploy::ScaraHybrid::<f32>::thesis().unwrap(),
    )));
    controllers.push(Box::new(armdyn::robots::scara::deploy::Deployed::new(
        armdyn::robots::scara::deploy::ScaraHybrid::<f64>::thesis().unwrap(),
    )));
    // The task-frame controllers of the shipped contact scenarios: a sphere's moving normal,
    // contact switching with approach, ramp and bumpless transfer, friction feedforward.
    let mut scenes = Vec::new();
    for file in ["sphere-patch.toml", "friction.toml", "oblique-plane.toml"] {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("scenarios")
            .join(file);
        let scenario = armdyn::scenario::Scenario::load(&path).unwrap();
        let prepared = armdyn::scenario::prepare_for(&scenario, Scara).unwrap();
        scenes.push((prepared.scene, prepared.config));
        controllers.push(prepared.controller);
    }
    let contact_controllers = controllers.len() - scenes.len();
    // The supervisors (the scenario files' controllers above run inside the host's) through a
    // trip and its reaction: the deployable step's own in f32, and the host's around the
    // thesis's hybrid law, each fed a NaN reading from 2.5 s.
    let limits = armdyn::control::safety::SafetyLimits::defaults(
        Scara.lower_limits(),
        Scara.upper_limits(),
        Scara.effort_limits(),
        Some(200.0),
        0.0,
    );
    let mut supervised: Vec<Box<dyn armdyn::control::Controller<4>>> = vec![
        Box::new(armdyn::robots::scara::deploy::Deployed::supervised(
            armdyn::robots::scara::deploy::SupervisedHybrid::new(
                armdyn::robots::scara::deploy::ScaraHybrid::<f32>::thesis().unwrap(),
                &limits,
            ),
        )),
        Box::new(armdyn::control::safety::Supervised::new(
            HybridSetup::build(ForceController::PiFfVd).unwrap().0,
            Scara,
            limits,
            armdyn::control::task_frame::TaskFrame::along_z(),
        )),
    ];
    let nan = Wrench::repeat(f64::NAN);
    let input_at = |t: f64, wrench| ControllerInput {
        t,
        q: &q,
        qd: &qd,
        target: &target,
        cartesian: &cart,
        wrench,
        wrench_ref: &f_d,
        wrench_age_s: 0.0,
    };
    for c in &mut supervised {
        let n = allocations_in(|| {
            for t in [0.5, 1.5, 2.5, 3.5] {
                let input = input_at(t, if t > 2.0 { &nan } else { &f });
                let tau = c.step(black_box(&input), 1e-3);
                assert!(tau.iter().all(|x| x.is_finite()), "{}", c.name());
            }
        });
        assert_eq!(n, 0, "{}: {n} allocation(s) in a supervised step", c.name());
        assert!(
            c.report().safety.is_some_and(|r| !r.trips.is_empty()),
            "{}",
            c.name()
        );
    }
    for c in &mut controllers {
        let n = allocations_in(|| {
            for t in [0.5, 1.5, 2.5, 3.5] {
                black_box(c.step(black_box(&input_at(t, &f)), 1e-3));
            }
        });
        assert_eq!(n, 0, "{}: {n} allocation(s) in step", c.name());
    }

    struct Hold(Setpoint<4>);
    impl ReferenceSource<4> for Hold {
        fn at(&mut self, t: f64) -> Setpoint<4> {
            let mut s = self.0;
            s.wrench = armdyn::robots::scara::thesis::constant_force().wrench(t);
            s
        }
    }
    let mut reference = Hold(Setpoint {
        joint: target,
        cartesian: cart,
        wrench: f_d,
    });
    let mut config = SimConfig::new(&Scara);
    config.duration = 3.0;
    config.q0 = q;
    let hybrid = &mut controllers[THESIS_POSITION_LAWS.len() + 1];
    let surface = armdyn::robots::scara::thesis_setup::thesis_surface();
    let mut last = 0.0;
    let n = allocations_in(|| {
        simulate(
            &Scara,
            hybrid.as_mut(),
            &mut reference,
            &surface,
            &config,
            |s| last = s.t,
        )
        .unwrap();
    });
    assert_eq!(n, 0, "simulate: {n} allocation(s)");
    assert_abs_diff_eq!(last, 3.0, epsilon = 1e-9);
    // A contact scenario's plant (a scene of surfaces, end stops) and controller.
    for (k, (scene, mut config)) in scenes.into_iter().enumerate() {
        config.duration = 3.0;
        config.q0 = q;
        let controller = &mut controllers[contact_controllers + k];
        let n = allocations_in(|| {
            simulate(
                &Scara,
                controller.as_mut(),
                &mut reference,
                &scene,
                &config,
                |s| last = s.t,
            )
            .unwrap();
        });
        assert_eq!(
            n, 0,
            "simulate with a scene and end stops: {n} allocation(s)"
        );
        assert!(config.end_stops.is_some());
    }
}

/// The force laws beyond the thesis's (designed PI gains, impedance, admittance; time and
/// contact switching) allocate nothing in `step`.
#[test]
fn designed_impedance_and_admittance_steps_never_allocate() {
    use armdyn::control::ControllerInput;
    use armdyn::scenario::{prepare_for, LawChoice, Scenario};
    use armdyn::target::CartesianTarget;
    use armdyn::target::JointTarget;
    use nalgebra::{Vector3, Vector4};

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
    for file in ["stiffness-10k.toml", "unknown-height.toml"] {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("scenarios")
            .join(file);
        for law in ["pi-ff-vd:design", "impedance", "admittance"] {
            let mut s = Scenario::load(&path).unwrap();
            LawChoice::parse(law).unwrap().apply(&mut s).unwrap();
            let mut c = prepare_for(&s, Scara).unwrap().controller;
            let n = allocations_in(|| {
                for t in [0.5, 1.5, 2.5, 3.5] {
                    let input = ControllerInput {
                        t,
                        q: &q,
                        qd: &qd,
                        target: &target,
                        cartesian: &cart,
                        wrench: &f,
                        wrench_ref: &f_d,
                        wrench_age_s: 0.0,
                    };
                    black_box(c.step(black_box(&input), 1e-3));
                }
            });
            assert_eq!(n, 0, "{file} {law}: {n} allocation(s) in step");
        }
    }
}

/// The controller step of the UR5 and the Panda (task-space inverse dynamics, PID with
/// feedback linearization and acceleration feedforward, computed torque; the UR5's hybrid
/// force law too, and the hybrid law, the impedance and the admittance in the full task frame
/// on both), their reference at every sample (numerical inverse kinematics, a redundant
/// arm's planned path) and a simulated second allocate nothing.
#[test]
fn ur5_and_panda_steps_and_references_never_allocate() {
    use armdyn::contact::Environment;
    use armdyn::control::ControllerInput;
    use armdyn::model::{Panda, Ur5};
    use armdyn::scenario::{prepare_for, PreparedRun, Scenario, ScenarioRobot};
    use armdyn::sim::simulate;

    fn scenario(file: &str, law: &str, extra: &str) -> Scenario {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios");
        let text = std::fs::read_to_string(dir.join(file))
            .unwrap()
            .replace("law = \"task-space\"", law);
        Scenario::parse(file, &format!("{text}\n{extra}"), &dir).unwrap()
    }

    fn check<const N: usize, R: ScenarioRobot<N>>(robot: R, s: &Scenario, what: &str) {
        let mut p: PreparedRun<N, R> = prepare_for(s, robot).unwrap();
        let start = p.reference.start();
        let qd = SVector::<f64, N>::repeat(0.05);
        let f = Wrench::new(0.0, 0.0, -5.0, 0.0, 0.0, 0.0);
        // The reference first (the controller reads its setpoint), then the step.
        let mut setpoints = Vec::with_capacity(8);
        let n = allocations_in(|| {
            for k in 0..8 {
                setpoints.push(p.reference.at(0.5 * k as f64));
            }
        });
        assert_eq!(n, 0, "{what}: {n} allocation(s) in the reference");
        let n = allocations_in(|| {
            for (k, sp) in setpoints.iter().enumerate() {
                let input = ControllerInput {
                    t: 0.5 * k as f64,
                    q: &start,
                    qd: &qd,
                    target: &sp.joint,
                    cartesian: &sp.cartesian,
                    wrench: &f,
                    wrench_ref: &sp.wrench,
                    wrench_age_s: 0.0,
                };
                black_box(p.controller.step(black_box(&input), 1e-3));
            }
        });
        assert_eq!(n, 0, "{what}: {n} allocation(s) in step");
        let mut config = p.config;
        config.duration = 1.0;
        let scene: &dyn Environment = &p.scene;
        let n = allocations_in(|| {
            simulate(
                &robot,
                p.controller.as_mut(),
                p.reference.as_mut(),
                scene,
                &config,
                |s| {
                    black_box(s);
                },
            )
            .unwrap();
        });
        assert_eq!(n, 0, "{what}: {n} allocation(s) in a simulated second");
        // The scenario's controller stepped by a loop of one's own.
        let mut c = armdyn::scenario::SteppedController::new(s, robot).unwrap();
        c.reset(0.0, &start, &qd);
        let n = allocations_in(|| {
            for k in 0..100 {
                black_box(c.step(1e-3 * k as f64, &start, &qd, &f));
                black_box(c.report());
            }
        });
        assert_eq!(n, 0, "{what}: {n} allocation(s) in SteppedController::step");
    }

    for law in [
        "law = \"task-space\"",
        "law = \"pid-fl\"\nacceleration_feedforward = true",
        "law = \"computed-torque\"",
    ] {
        check(
            Ur5,
            &scenario("ur5-square.toml", law, ""),
            &format!("ur5 {law}"),
        );
        check(
            Panda,
            &scenario("panda-square.toml", law, ""),
            &format!("panda {law}"),
        );
    }
    // The UR5 pressing on a plane under its square: the hybrid law in its 6 task rows.
    let plane = "[[surfaces]]\nkind = \"plane\"\npoint = [0.5, 0.0, 0.29]\nnormal = [0.0, 0.0, 1.0]\nhalf_extent = [0.5, 0.5]\nstiffness = 10000.0\n\n[force]\nlaw = \"pi-ff-vd\"\nreference = \"constant\"\nvalue = 10.0\n\n[selection]\nmode = \"contact\"\n";
    let s = scenario(
        "ur5-square.toml",
        "law = \"pid-fl\"\nacceleration_feedforward = true",
        plane,
    );
    check(Ur5, &s, "ur5 hybrid");
    // The hybrid law in the full task frame: the UR5 on its table, the Panda wiping (a time
    // switch at 1 s, so that most checked steps are force controlled).
    let timed = |file: &str| {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios");
        let text = std::fs::read_to_string(dir.join(file))
            .unwrap()
            .replace("mode = \"contact\"", "mode = \"time\"\nswitch_s = 1.0");
        Scenario::parse(file, &text, &dir).unwrap()
    };
    check(Ur5, &timed("ur5-press-table.toml"), "ur5 task-space hybrid");
    check(Panda, &timed("panda-wipe.toml"), "panda task-space hybrid");
    // A tool behind the force sensor: taring, weight compensation, the sensor's model.
    check(
        Panda,
        &timed("panda-tool-bias.toml"),
        "panda with a tool behind the sensor",
    );
    // The impedance and the admittance in the full task frame.
    for law in ["impedance", "admittance"] {
        let with = |file: &str| {
            let mut s = timed(file);
            armdyn::scenario::LawChoice::parse(law)
                .unwrap()
                .apply(&mut s)
                .unwrap();
            s
        };
        check(
            Ur5,
            &with("ur5-press-table.toml"),
            &format!("ur5 task-space {law}"),
        );
        check(
            Panda,
            &with("panda-wipe.toml"),
            &format!("panda task-space {law}"),
        );
    }
}
