//! Runs the thesis trials through the library (shared by the trial tests).

use armdyn::contact::{Environment, FreeSpace};
use armdyn::control::Controller;
use armdyn::model::Scara;
use armdyn::robots::scara::presets::{position_controller, ForceReference, HybridSetup};
use armdyn::robots::scara::reference::ScaraReference;
use armdyn::robots::scara::thesis::{ContactTest, PositionTest};
use armdyn::robots::scara::{ScaraGeometry, SwitchPolicy};
use armdyn::scenario::{run, DesiredForce, ForceController, PositionController, RunOutput};
use armdyn::sim::{ReferenceSource, Setpoint, SimConfig};
use armdyn::trajectory::{CartesianTrajectory, ForceProfile};

/// A joint reference with the desired force along base z added.
struct WithForce<S> {
    inner: S,
    force: Option<DesiredForce>,
}

impl<S: ReferenceSource<4>> ReferenceSource<4> for WithForce<S> {
    fn at(&mut self, t: f64) -> Setpoint<4> {
        let mut s = self.inner.at(t);
        if let Some(f) = &self.force {
            s.wrench = f.wrench(t, &s.cartesian.position);
        }
        s
    }
}

pub fn run_trial(
    controller: &mut dyn Controller<4>,
    trajectory: &dyn CartesianTrajectory,
    force: Option<ForceProfile>,
    environment: &dyn Environment,
) -> RunOutput<4> {
    let geometry = ScaraGeometry::from_model(&Scara);
    let plan = geometry
        .plan_trajectory(trajectory, 0.005, SwitchPolicy::Latest)
        .expect("thesis references are reachable");
    let mut reference = WithForce {
        inner: ScaraReference::new(geometry, trajectory, plan),
        force: force.map(DesiredForce::along_z),
    };
    run(
        &Scara,
        controller,
        &mut reference,
        environment,
        &SimConfig::new(&Scara),
        |_| {},
    )
    .expect("the trial simulates")
}

pub fn position_trial(c: PositionController) -> RunOutput<4> {
    let (mut controller, _) = position_controller(c).expect("gains");
    run_trial(controller.as_mut(), &PositionTest::new(), None, &FreeSpace)
}

pub fn hybrid_trial(f: ForceController, r: ForceReference) -> RunOutput<4> {
    let (mut controller, _) = HybridSetup::build(f).expect("gains");
    run_trial(
        controller.as_mut(),
        &ContactTest::thesis(),
        Some(r.profile()),
        &armdyn::robots::scara::thesis_setup::thesis_surface(),
    )
}
