//! Tests of `armdyn::trajectory::sampled`: the sampled reference: linear positions through its
//! samples, exact derivatives of a parabola, the sampled thesis reference against the analytic one,
//! slerped full poses, two samples, bad sample lists.

use armdyn::robots::scara::thesis::PositionTest;
use armdyn::target::{orientation, PoseSample};
use armdyn::trajectory::sampled::*;
use armdyn::trajectory::{sample, CartesianTrajectory};
use nalgebra::{UnitQuaternion, Vector3};

fn read(text: &str) -> Result<SampledTrajectory, armdyn::trajectory::CsvError> {
    SampledTrajectory::from_csv_reader(text.as_bytes())
}

#[test]
fn interpolates_positions_linearly_and_hits_samples() {
    let r = read("t,x,y,z,yaw\n0,0.5,0,0.2,0\n1,0.6,0.1,0.1,1\n3,0.6,0.3,0.1,1\n").unwrap();
    assert_eq!(r.at(1.0).position, Vector3::new(0.6, 0.1, 0.1));
    let mid = r.at(0.25);
    assert!((mid.position - Vector3::new(0.525, 0.025, 0.175)).norm() < 1e-15);
    assert!((mid.yaw() - 0.25).abs() < 1e-15);
    assert_eq!(r.at(-1.0).position, r.at(0.0).position);
    assert_eq!(r.at(5.0).position, Vector3::new(0.6, 0.3, 0.1));
    assert_eq!(r.duration(), 3.0);
}

#[test]
fn derivatives_are_exact_for_a_parabola_with_uneven_spacing() {
    // y = 1 + 2 t - 3 t^2 on an uneven grid: three-point differences are exact.
    let times = [0.0, 0.1, 0.25, 0.3, 0.7, 1.0];
    let samples: Vec<PoseSample> = times
        .iter()
        .map(|&t| PoseSample::with_yaw(t, Vector3::new(0.0, 1.0 + 2.0 * t - 3.0 * t * t, 0.0), t))
        .collect();
    let r = SampledTrajectory::new(&samples).unwrap();
    for &t in &times {
        let target = r.at(t);
        assert!(
            (target.velocity.y - (2.0 - 6.0 * t)).abs() < 1e-12,
            "t = {t}"
        );
        assert!((target.acceleration.y + 6.0).abs() < 1e-10, "t = {t}");
        assert!((target.angular_velocity.z - 1.0).abs() < 1e-12);
        assert!(target.angular_acceleration.z.abs() < 1e-10);
    }
}

#[test]
fn a_sampled_thesis_reference_matches_the_analytic_one() {
    let analytic = PositionTest::new();
    let samples = sample(&analytic, 0.005);
    let sampled = SampledTrajectory::new(&samples).unwrap();
    for k in 0..=1000 {
        let t = 0.01 * k as f64 + 0.0013;
        let (a, s) = (analytic.at(t), sampled.at(t));
        // Linear interpolation: error ~ h^2/8 |x''|; differences: ~ h^2 |x'''|/6.
        assert!((a.position - s.position).norm() < 1e-5, "t = {t}");
        assert!((a.velocity - s.velocity).norm() < 2e-4, "t = {t}");
        assert!((a.acceleration - s.acceleration).norm() < 2e-2, "t = {t}");
    }
}

#[test]
fn full_poses_are_slerped_and_differentiated() {
    // A constant angular velocity about a tilted axis, sampled unevenly.
    let w = Vector3::new(0.3, -0.2, 0.5);
    let start = orientation::from_rpy(0.2, 0.1, -0.4);
    let times = [0.0, 0.05, 0.12, 0.2, 0.31, 0.4];
    let samples: Vec<PoseSample> = times
        .iter()
        .map(|&t| {
            let q = UnitQuaternion::from_scaled_axis(w * t) * start;
            PoseSample::new(t, Vector3::new(t, 0.0, 0.0), q)
        })
        .collect();
    let r = SampledTrajectory::new(&samples).unwrap();
    for t in [0.0, 0.07, 0.2, 0.33, 0.4] {
        let target = r.at(t);
        let exact = UnitQuaternion::from_scaled_axis(w * t) * start;
        assert!(target.orientation.angle_to(&exact) < 1e-14, "t = {t}");
        assert!((target.angular_velocity - w).norm() < 1e-12, "t = {t}");
        assert!(target.angular_acceleration.norm() < 1e-9, "t = {t}");
    }
    let text = "t,x,y,z,roll,pitch,yaw\n0,0.5,0,0.2,3.0,0,0\n1,0.5,0.1,0.2,3.0,0.2,0\n";
    let r = read(text).unwrap();
    let (roll, pitch, _) = orientation::rpy(&r.at(0.5).orientation);
    assert!((roll - 3.0).abs() < 1e-12 && (pitch - 0.1).abs() < 1e-12);
}

#[test]
fn two_samples_give_their_slope() {
    let r = read("t,x,y,z,yaw\n1,0,0,0,0\n3,2,0,0,0\n").unwrap();
    assert_eq!(r.at(2.0).velocity.x, 1.0);
    assert_eq!(r.at(2.0).acceleration.x, 0.0);
}

#[test]
fn sample_list_errors() {
    let p = Vector3::zeros();
    let one = [PoseSample::with_yaw(0.0, p, 0.0)];
    assert_eq!(
        SampledTrajectory::new(&one),
        Err(SampledError::TooFewSamples { count: 1 })
    );
    let nan = [
        PoseSample::with_yaw(0.0, p, 0.0),
        PoseSample::with_yaw(1.0, p, f64::NAN),
    ];
    assert!(matches!(
        SampledTrajectory::new(&nan),
        Err(SampledError::NonFinite {
            index: 1,
            name: "orientation",
            ..
        })
    ));
    let same = [
        PoseSample::with_yaw(0.0, p, 0.0),
        PoseSample::with_yaw(0.0, p, 0.0),
    ];
    assert!(matches!(
        SampledTrajectory::new(&same),
        Err(SampledError::NotIncreasing { index: 1, .. })
    ));
}
