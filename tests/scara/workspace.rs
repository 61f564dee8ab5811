//! Tests of `armdyn::robots::scara::workspace`: the SCARA's workspace: the zones of the
//! three-zone line, and stroke and reach given as reasons.

use armdyn::robots::scara::geometry::{IkError, ScaraGeometry};
use armdyn::robots::scara::workspace::*;
use nalgebra::Vector3;

#[test]
fn zones_of_the_three_zone_line() {
    let ik = ScaraGeometry::thesis();
    let at = |y: f64| ik.classify(&Vector3::new(0.25, y, 0.1), 0.0);
    assert_eq!(at(-0.4), Reachability::DownOnly);
    assert_eq!(at(0.0), Reachability::Both);
    assert_eq!(at(0.4), Reachability::UpOnly);
}

#[test]
fn stroke_and_reach_are_reasons() {
    let ik = ScaraGeometry::thesis();
    // z = 0.3 m needs d3 = 0.05 m, below the stroke [0.1, 0.35].
    match ik.classify(&Vector3::new(0.5, 0.0, 0.3), 0.0) {
        Reachability::Unreachable(Reason::JointLimits { up, down }) => {
            assert_eq!((up.joint, down.joint), (2, 2));
        }
        other => panic!("{other:?}"),
    }
    assert!(matches!(
        ik.classify(&Vector3::new(0.0, 0.81, 0.1), 0.0),
        Reachability::Unreachable(Reason::OutOfReach(IkError::TooFar { .. }))
    ));
    // The stretched arm: both solutions coincide.
    assert_eq!(
        ik.classify(&Vector3::new(0.8, 0.0, 0.25), 0.0),
        Reachability::Both
    );
}
