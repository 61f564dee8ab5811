//! Criterion benchmarks of the controllers and the simulator on the SCARA: one controller
//! step (position controllers and the full hybrid force/position step: kinematics,
//! feedback linearization, PID, force PI, selection, Jacobian transpose), and whole 10 s
//! trials (10 000 control samples, RK4 at 1 ms, with inverse kinematics of the reference
//! at every sample).
//!
//! Run: `cargo bench --bench control`.

use std::hint::black_box;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, Criterion};
use nalgebra::{Vector3, Vector4};
use scara::contact::{FreeSpace, ReactionSurface};
use scara::control::ControllerInput;
use scara::model::{Scara, Wrench};
use scara::robots::scara::presets::{position_controller, ForceReference, HybridSetup};
use scara::robots::scara::reference::ScaraReference;
use scara::robots::scara::thesis::{ContactTest, PositionTest};
use scara::robots::scara::{ScaraGeometry, SwitchPolicy};
use scara::scenario::{run, DesiredForce, ForceController, PositionController};
use scara::sim::{ReferenceSource, Setpoint, SimConfig};
use scara::target::CartesianTarget;
use scara::target::JointTarget;

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
        scara::target::orientation::from_yaw(0.0),
    );
    let f = Wrench::new(0.0, 0.0, -150.0, 0.0, 0.0, 0.0);
    let f_d = Wrench::new(0.0, 0.0, -200.0, 0.0, 0.0, 0.0);
    let mut group = c.benchmark_group("step");
    for pc in PositionController::ALL {
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
                };
                ctrl.step(black_box(&input), 1e-3)
            })
        });
    }
    for fc in ForceController::ALL {
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
                };
                ctrl.step(black_box(&input), 1e-3)
            })
        });
    }
    // The task-frame hybrid of a shipped scenario: the sphere's normal at the tool, contact
    // switching (force controlled after the debounce), gravity along the normal.
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios/sphere-patch.toml");
    let scenario = scara::scenario::Scenario::load(&path).expect("shipped scenario");
    let mut ctrl = scara::scenario::prepare_for(&scenario, Scara)
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
    };
    for _ in 0..10 {
        ctrl.step(&input, 1e-3);
    }
    assert!(
        ctrl.force_controlled(),
        "the benchmark measures the force-controlled step"
    );
    group.bench_function("hybrid-sphere-contact", |b| {
        b.iter(|| ctrl.step(black_box(&input), 1e-3))
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
                &ReactionSurface::thesis(),
                &SimConfig::thesis(&Scara),
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
                &SimConfig::thesis(&Scara),
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
