//! Tests of `armdyn::robots::scara::thesis_setup`: the thesis's set-up: the force law scenarios
//! call `thesis`, and the PID poles of the scenarios and of the generic pattern are the
//! thesis's.

use armdyn::robots::scara::thesis_setup::*;

#[test]
fn the_force_law_is_the_one_scenarios_call_thesis() {
    #[cfg(feature = "std")]
    {
        use armdyn::scenario::ForceController;
        for (fc, damped) in [
            (ForceController::PiFf, false),
            (ForceController::PiFfVd, true),
        ] {
            let l = thesis_force_law(damped);
            assert_eq!((l.kfp(), l.kfi(), l.kvd()), fc.thesis_gains());
        }
    }
    assert_eq!(thesis_force_law(true).kvd(), 2000.0);
}

#[cfg(feature = "std")]
#[test]
fn the_scenarios_pid_poles_are_the_thesis_poles() {
    assert_eq!(armdyn::scenario::PID_POLES, THESIS_PID_POLES);
}

#[test]
fn the_generic_pole_pattern_is_the_thesis_poles_for_four_joints() {
    assert_eq!(
        armdyn::control::fsf::fsf_poles(4),
        THESIS_FSF_POLES.to_vec()
    );
}
