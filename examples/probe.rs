use scara::contact::{FreeSpace, ReactionSurface};
use scara::kinematics::{ScaraGeometry, SwitchPolicy};
use scara::metrics::{ForceMetrics, TrackingMetrics};
use scara::model::Scara;
use scara::scenario::*;
use scara::sim::SimConfig;
use scara::trajectory::{ContactTest, PositionTest};

fn main() {
    let geo = ScaraGeometry::from_model(&Scara);
    let traj = PositionTest::new();
    let plan = geo.plan_trajectory(&traj, 0.005, SwitchPolicy::Latest).unwrap();
    for c in PositionController::ALL {
        let (mut ctrl, _g) = c.build().unwrap();
        let mut r = ScaraReference::new(geo, &traj, plan.clone(), None);
        let cfg = SimConfig::thesis(&Scara);
        let out = run(&Scara, ctrl.as_mut(), &mut r, &FreeSpace, &cfg, |_| {}).unwrap();
        let mut m = TrackingMetrics::new(2.0);
        for s in &out.samples { m.push(s); }
        let s = m.summary();
        println!("{:16} max_after2 {:?} rms {:?} maxtau {:?} sat {:?}", c.name(), s.max_joint_error_after.as_slice(), s.rms_joint_error.as_slice(), s.max_abs_tau.as_slice(), out.stats.saturated_samples);
    }
    let traj = ContactTest::thesis();
    let plan = geo.plan_trajectory(&traj, 0.005, SwitchPolicy::Latest).unwrap();
    for f in ForceController::ALL { for fr in ForceReference::ALL {
        let (mut ctrl, _g) = HybridSetup::build(f).unwrap();
        let mut r = ScaraReference::new(geo, &traj, plan.clone(), Some(fr.profile()));
        let cfg = SimConfig::thesis(&Scara);
        let out = run(&Scara, ctrl.as_mut(), &mut r, &ReactionSurface::thesis(), &cfg, |_| {}).unwrap();
        let mut m = ForceMetrics::thesis();
        for s in &out.samples { m.push(s); }
        println!("{} {} {:?}", f.name(), fr.name(), m.summary());
    }}
}
