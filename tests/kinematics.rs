//! Inverse kinematics for every robot of the registry: FK(IK(x)) = x to 1e-9 m and 1e-9 rad
//! at 1,000 random reachable poses per robot (poses from FK of random configurations within
//! the limits), solutions within the limits, and a clear error for unreachable poses. The
//! SCARA's closed form passes the same test behind the same interface.

use nalgebra::{SVector, Vector3};
use rand::rngs::Xoshiro256PlusPlus;
use rand::{RngExt, SeedableRng};

use armdyn::kinematics::{IkError, IkOptions, InverseKinematics, NumericalIk};
use armdyn::model::{RobotModel, Scara, ROBOTS};
use armdyn::robots::scara::ClosedFormIk;
use armdyn::target::{orientation, CartesianTarget};

const POSES: usize = 1000;
const TOLERANCE: f64 = 1e-9;

fn random_q<const N: usize, R: RobotModel<N>>(rng: &mut Xoshiro256PlusPlus) -> SVector<f64, N> {
    SVector::<f64, N>::from_fn(|i, _| {
        let [lo, hi] = R::JOINT_LIMITS[i];
        let (lo, hi) = (lo.max(-std::f64::consts::PI), hi.min(std::f64::consts::PI));
        rng.random_range(lo..=hi)
    })
}

fn pose_of<const N: usize, R: RobotModel<N>>(robot: &R, q: &SVector<f64, N>) -> CartesianTarget {
    let pose = robot.end_effector_pose(q);
    CartesianTarget::at_rest(
        pose.fixed_view::<3, 1>(0, 3).into_owned(),
        orientation::of_pose(&pose),
    )
}

/// Checks `ik` at `POSES` random reachable poses; returns the largest errors found.
fn check<const N: usize, R: RobotModel<N>, S: InverseKinematics<N>>(
    robot: &R,
    ik: &S,
    seed: &SVector<f64, N>,
    rng_seed: u64,
) -> (f64, f64) {
    let mut rng = Xoshiro256PlusPlus::seed_from_u64(rng_seed);
    let (mut worst_p, mut worst_o) = (0.0f64, 0.0f64);
    for k in 0..POSES {
        let q_true = random_q::<N, R>(&mut rng);
        let target = pose_of(robot, &q_true);
        let s = ik
            .solve(&target, seed)
            .unwrap_or_else(|e| panic!("{} pose {k} (from q = {q_true:?}): {e}", R::NAME));
        // Checked independently of the solver's own report.
        let got = pose_of(robot, &s.q);
        let e = R::TASK.pose_error(
            &target.position,
            &target.orientation,
            &got.position,
            &got.orientation,
        );
        let (ep, eo) = (e.fixed_rows::<3>(0).norm(), e.fixed_rows::<3>(3).norm());
        assert!(
            ep <= TOLERANCE && eo <= TOLERANCE,
            "{} pose {k}: {ep} m, {eo} rad",
            R::NAME
        );
        assert!(
            robot.within_joint_limits(&s.q),
            "{} pose {k}: {:?}",
            R::NAME,
            s.q
        );
        worst_p = worst_p.max(ep);
        worst_o = worst_o.max(eo);
    }
    (worst_p, worst_o)
}

/// The numerical IK of `robot` at random poses, out of reach and at a NaN.
fn numerical<const N: usize, R: RobotModel<N> + Copy + 'static>(robot: &R) {
    let ik = NumericalIk::new(*robot, IkOptions::default());
    let seed = *ik.posture();
    let (p, o) = check(robot, &ik, &seed, 7);
    println!(
        "{}: numerical IK, {POSES} poses, worst {p:.1e} m, {o:.1e} rad",
        R::NAME
    );
    // Out of reach: 10 m from the base.
    let mut far = pose_of(robot, &seed);
    far.position = Vector3::new(10.0, 0.0, 0.0);
    match ik.solve(&far, &seed) {
        Err(IkError::NotReached {
            position_error_m, ..
        }) => {
            assert!(position_error_m > 5.0, "{}: {position_error_m}", R::NAME);
            let message = ik.solve(&far, &seed).unwrap_err().to_string();
            assert!(message.contains("mm"), "{message}");
        }
        other => panic!("{}: an unreachable pose gave {other:?}", R::NAME),
    }
    let mut nan = far;
    nan.position.x = f64::NAN;
    assert_eq!(ik.solve(&nan, &seed).unwrap_err(), IkError::NonFinite);
}

#[test]
fn numerical_ik_reaches_random_poses_of_every_robot() {
    for name in ROBOTS {
        armdyn::with_robot_named!(*name, |robot: R, N, _module| numerical(&robot)).unwrap();
    }
}

#[test]
fn the_scara_closed_form_passes_the_same_test() {
    let ik = ClosedFormIk::new(&Scara);
    // The seed's elbow is tried first; the other one when the first is outside the limits.
    let (p, o) = check(&Scara, &ik, &SVector::<f64, 4>::new(0.0, 0.5, 0.2, 0.0), 11);
    println!("scara: closed form, {POSES} poses, worst {p:.1e} m, {o:.1e} rad");
}

#[test]
fn a_redundant_arm_takes_the_solution_nearest_its_posture() {
    // The Panda's usual home posture; poses near it, elbow (joint 4) free to move.
    let posture = SVector::<f64, 7>::from([0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785]);
    let ik = NumericalIk::new(
        armdyn::model::Panda,
        IkOptions {
            posture: Some(posture),
            ..IkOptions::default()
        },
    );
    let mut rng = Xoshiro256PlusPlus::seed_from_u64(3);
    for _ in 0..200 {
        let q_true = posture + SVector::<f64, 7>::from_fn(|_, _| rng.random_range(-0.3..=0.3));
        let target = pose_of(&armdyn::model::Panda, &q_true);
        let s = ik.solve(&target, &posture).unwrap();
        // Nearer the posture than the configuration the pose came from (or as near).
        assert!(
            (s.q - posture).norm() <= (q_true - posture).norm() + 1e-6,
            "{} vs {}",
            (s.q - posture).norm(),
            (q_true - posture).norm()
        );
    }
}
