//! Tests of `armdyn::robots::scara::elbow_plan`: the SCARA's elbow plan: a trip there and back
//! switches twice, the longer run chosen at the start, and times that must increase.

use armdyn::robots::scara::elbow_plan::*;
use armdyn::robots::scara::geometry::{Elbow, ScaraGeometry};
use armdyn::target::PoseSample;
use nalgebra::Vector3;

fn line(ys: &[f64]) -> Vec<PoseSample> {
    ys.iter()
        .enumerate()
        .map(|(i, &y)| PoseSample::with_yaw(i as f64, Vector3::new(0.25, y, 0.1), 0.0))
        .collect()
}

#[test]
fn a_trip_there_and_back_switches_twice() {
    let ik = ScaraGeometry::thesis();
    // Down-only -> both -> up-only -> both -> down-only.
    let samples = line(&[-0.4, -0.2, 0.0, 0.2, 0.4, 0.2, 0.0, -0.2, -0.4]);
    let plan = ik.plan_elbows(&samples).unwrap();
    assert_eq!(plan.initial(), Elbow::Down);
    let to: Vec<Elbow> = plan.switches().iter().map(|s| s.to).collect();
    assert_eq!(to, [Elbow::Up, Elbow::Down]);
    for s in plan.switches() {
        assert!(s.earliest <= s.t && s.t <= s.latest);
        assert!(s.jump > 0.0);
    }
    // Every policy needs the same number of switches.
    for policy in [SwitchPolicy::Earliest, SwitchPolicy::SmallestJump] {
        assert_eq!(
            ik.plan_elbows_with(&samples, policy)
                .unwrap()
                .switches()
                .len(),
            2
        );
    }
}

#[test]
fn the_longer_run_is_chosen_at_the_start() {
    let ik = ScaraGeometry::thesis();
    // Starts in the both-zone, goes to up-only: a single elbow (up) serves.
    let plan = ik.plan_elbows(&line(&[0.0, 0.2, 0.4])).unwrap();
    assert_eq!(plan.single(), Some(Elbow::Up));
    // Starts in the both-zone, goes to down-only: a single elbow (down) serves.
    let plan = ik.plan_elbows(&line(&[0.0, -0.2, -0.4])).unwrap();
    assert_eq!(plan.single(), Some(Elbow::Down));
}

#[test]
fn times_must_increase() {
    let mut samples = line(&[0.0, 0.1]);
    samples[1].t = 0.0;
    assert!(matches!(
        ScaraGeometry::thesis().plan_elbows(&samples),
        Err(WorkspaceError::NotIncreasing { index: 1, .. })
    ));
}
