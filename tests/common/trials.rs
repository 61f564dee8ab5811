//! Runs the thesis trials through the library (shared by the trial tests).

use scara::contact::{Environment, FreeSpace, ReactionSurface};
use scara::control::Controller;
use scara::model::Scara;
use scara::robots::scara::thesis::{ContactTest, PositionTest};
use scara::robots::scara::{ScaraGeometry, SwitchPolicy};
use scara::scenario::{
    run, ForceController, ForceReference, HybridSetup, PositionController, RunOutput,
    ScaraReference,
};
use scara::sim::SimConfig;
use scara::trajectory::{CartesianTrajectory, ForceProfile};

pub fn run_trial(
    controller: &mut dyn Controller<4>,
    trajectory: &dyn CartesianTrajectory,
    force: Option<ForceProfile>,
    environment: &dyn Environment,
) -> RunOutput {
    let geometry = ScaraGeometry::from_model(&Scara);
    let plan = geometry
        .plan_trajectory(trajectory, 0.005, SwitchPolicy::Latest)
        .expect("thesis references are reachable");
    let mut reference = ScaraReference::new(
        geometry,
        trajectory,
        plan,
        force.map(scara::scenario::DesiredForce::thesis),
    );
    run(
        &Scara,
        controller,
        &mut reference,
        environment,
        &SimConfig::thesis(&Scara),
        |_| {},
    )
    .expect("the trial simulates")
}

pub fn position_trial(c: PositionController) -> RunOutput {
    let (mut controller, _) = c.build().expect("gains");
    run_trial(controller.as_mut(), &PositionTest::new(), None, &FreeSpace)
}

pub fn hybrid_trial(f: ForceController, r: ForceReference) -> RunOutput {
    let (mut controller, _) = HybridSetup::build(f).expect("gains");
    run_trial(
        controller.as_mut(),
        &ContactTest::thesis(),
        Some(r.profile()),
        &ReactionSurface::thesis(),
    )
}
