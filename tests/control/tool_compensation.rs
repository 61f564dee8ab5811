//! Tests of `armdyn::control::tool_compensation`: the tool compensation: the tare finds the
//! bias, and the tool's weight comes out as the tool turns.

use armdyn::contact::ForceSensor;
use armdyn::control::sensed_behind_tool::SensedBehindTool;
use armdyn::control::tool_compensation::*;
use armdyn::control::{Controller, ControllerInput};
use armdyn::model::{JointVector, Panda, SensorMount, Wrench};
use armdyn::target::{CartesianTarget, JointTarget};
use nalgebra::{UnitQuaternion, Vector3};

/// Records the wrench it is given.
#[derive(Clone, Debug, Default)]
struct Probe {
    seen: Wrench,
}

impl Controller<7> for Probe {
    fn name(&self) -> &'static str {
        "probe"
    }
    fn reset(&mut self) {}
    fn step(&mut self, input: &ControllerInput<'_, 7>, _dt: f64) -> JointVector<7> {
        self.seen = *input.wrench;
        JointVector::zeros()
    }
}

#[test]
fn the_tare_finds_the_bias_and_the_weight_comes_out_as_the_tool_turns() {
    let mount = SensorMount {
        origin_m: Vector3::new(0.0, 0.0, -0.1),
        tool_mass_kg: 1.2,
        tool_com_m: Vector3::new(0.0, 0.01, 0.05),
    };
    let bias = Wrench::new(0.4, -0.2, 3.0, 0.01, 0.0, -0.02);
    let sensor = ForceSensor::new(bias, Wrench::zeros(), None, 1).unwrap();
    let compensated = ToolCompensation::new::<7>(
        Probe::default(),
        Panda,
        mount,
        true,
        Some(TareWindow {
            start_s: 0.0,
            end_s: 0.1,
        }),
    );
    let mut c = SensedBehindTool::behind_tool::<7>(compensated, Panda, mount, sensor);
    let qd = JointVector::<7>::zeros();
    let target = JointTarget::at_rest(qd);
    let cart = CartesianTarget::at_rest(Vector3::zeros(), UnitQuaternion::identity());
    let step = |c: &mut SensedBehindTool<ToolCompensation<Probe, Panda>, Panda>,
                t: f64,
                q: &JointVector<7>,
                w: &Wrench| {
        let input = ControllerInput {
            t,
            q,
            qd: &qd,
            target: &target,
            cartesian: &cart,
            wrench: w,
            wrench_ref: w,
            wrench_age_s: 0.0,
        };
        c.step(&input, 1e-3);
    };
    let q0 = JointVector::<7>::from([0.0, -0.6, 0.0, -2.3, 0.0, 1.7, 0.8]);
    for k in 0..100 {
        step(&mut c, k as f64 * 1e-3, &q0, &Wrench::zeros());
    }
    // Nothing reaches the force law during the tare (the sensor reads bias and weight).
    assert_eq!(c.inner().inner().seen, Wrench::zeros());
    // Turned by 0.6 rad at joints 5 and 6, pressing: the force law sees the contact alone.
    let q1 = q0 + JointVector::<7>::from([0.0, 0.0, 0.0, 0.0, 0.6, -0.6, 0.0]);
    let contact = Wrench::new(1.5, -0.5, -15.0, 0.0, 0.0, 0.0);
    step(&mut c, 0.2, &q1, &contact);
    let estimate = c.report().sensor_bias_estimate.unwrap();
    assert!((estimate - bias).norm() < 1e-12, "{estimate}");
    let seen = c.inner().inner().seen;
    assert!((seen - contact).norm() < 1e-9, "{seen}");
    assert_eq!(c.inner().tare_samples(), 100);
}
