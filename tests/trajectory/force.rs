//! Tests of `armdyn::trajectory::force`: the force profile commands the normal (z) force only.

use armdyn::model::Wrench;
use armdyn::trajectory::force::*;

#[test]
fn only_fz_is_commanded() {
    let w = ForceProfile::constant(-10.0, 0.0).wrench(1.0);
    assert_eq!(w, Wrench::new(0.0, 0.0, -10.0, 0.0, 0.0, 0.0));
}
