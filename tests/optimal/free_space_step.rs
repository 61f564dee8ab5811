//! Tests of `armdyn::optimal::free_space_step`: the knot step: in free space it equals the
//! plant's own period.

use armdyn::contact::FreeSpace;
use armdyn::model::{JointVector, Panda, RobotModel};
use armdyn::optimal::free_space_step::*;
use armdyn::sim::linearize::plant::plant_period;
use armdyn::sim::SimConfig;

/// Equal to the general plant linearisation in free space, for one and three substeps.
#[test]
fn equals_the_plant_period_in_free_space() {
    let q = JointVector::<7>::from([0.3, -0.4, 0.2, -1.9, 0.1, 1.5, 0.6]);
    let qd = JointVector::<7>::from([0.5, -0.3, 0.8, 0.2, -0.6, 0.4, 1.0]);
    let tau = Panda.gravity(&q) + JointVector::<7>::from([3.0, -2.0, 1.0, 4.0, -1.0, 0.5, 0.2]);
    let mut config = SimConfig::new(&Panda);
    config.end_stops = None;
    config.friction = None;
    for substeps in [1, 3] {
        let h = 0.01 / substeps as f64;
        let ours = knot_step(&Panda, &q, &qd, &tau, substeps, h).unwrap();
        let general =
            plant_period(&Panda, &FreeSpace, &config, 0.0, &q, &qd, &tau, substeps, h).unwrap();
        assert!((ours.q - general.q).amax() < 1e-14);
        assert!((ours.qd - general.qd).amax() < 1e-13);
        for r in 0..7 {
            for c in 0..7 {
                let close = |a: f64, b: f64| (a - b).abs() <= 1e-11 * (1.0 + b.abs());
                assert!(close(ours.dq.q[(r, c)], general.dx[(r, c)]));
                assert!(close(ours.dq.qd[(r, c)], general.dx[(r, 7 + c)]));
                assert!(close(ours.dqd.q[(r, c)], general.dx[(7 + r, c)]));
                assert!(close(ours.dqd.qd[(r, c)], general.dx[(7 + r, 7 + c)]));
                assert!(close(ours.dq.tau[(r, c)], general.du[(r, c)]));
                assert!(close(ours.dqd.tau[(r, c)], general.du[(7 + r, c)]));
            }
        }
    }
}
