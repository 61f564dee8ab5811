//! Inverse kinematics against the generated forward kinematics, joint references against
//! finite differences, and the elbow planner on the thesis's references (Sections 3.1.4,
//! 3.1.5, 3.2.2, 4.4).

use std::f64::consts::PI;

use approx::{abs_diff_eq, assert_abs_diff_eq};
use armdyn::model::{JointVector, RobotModel, Scara};
use armdyn::robots::scara::thesis::{ContactTest, PositionTest, ThreeZone};
use armdyn::robots::scara::{
    Conditioning, Elbow, Reachability, Reason, ScaraGeometry, SwitchPolicy, WorkspaceError,
    MAX_DAMPING, SINGULARITY_THRESHOLD,
};
use armdyn::target::wrap_angle;
use armdyn::target::{CartesianTarget, PoseSample};
use armdyn::trajectory::{sample, CartesianTrajectory, SampledTrajectory};
use nalgebra::{Vector3, Vector4};

fn ik() -> ScaraGeometry {
    ScaraGeometry::from_model(&Scara)
}

/// Position (m) and yaw (rad) of the generated forward kinematics.
fn fk(q: &JointVector<4>) -> (Vector3<f64>, f64) {
    let pose = Scara.end_effector_pose(q);
    let p = Vector3::new(pose[(0, 3)], pose[(1, 3)], pose[(2, 3)]);
    // R = Rz(yaw) Rx(pi) (thesis eq. 3.11 with nu = 0, psi = pi): yaw from r21, r11.
    (p, pose[(1, 0)].atan2(pose[(0, 0)]))
}

#[test]
fn forward_of_inverse_is_identity_over_the_whole_workspace() {
    let g = ik();
    let (inner, outer) = ((g.l1() - g.l2()).abs(), g.l1() + g.l2());
    let [_, _, [d3_lo, d3_hi], _] = g.limits();
    let mut count = 0;
    let mut worst: f64 = 0.0;
    for ir in 0..=40 {
        // Radii from the folded to the stretched arm, both ends included.
        let r = inner + (outer - inner) * ir as f64 / 40.0;
        for ia in 0..72 {
            let angle = -PI + 2.0 * PI * ia as f64 / 72.0;
            for iz in 0..=4 {
                let z = g.z0() - (d3_lo + (d3_hi - d3_lo) * iz as f64 / 4.0);
                for yaw in [-3.0, -1.0, 0.0, 0.5, 2.5] {
                    let p = Vector3::new(r * angle.cos(), r * angle.sin(), z);
                    for elbow in [Elbow::Up, Elbow::Down] {
                        let q = g.inverse(&p, yaw, elbow).unwrap();
                        assert!(q[3] > -PI && q[3] <= PI);
                        assert!(elbow.sign() * q[1] >= 0.0, "{elbow}: q2 = {}", q[1]);
                        let (p_fk, yaw_fk) = fk(&q);
                        let err = (p_fk - p).norm().max(wrap_angle(yaw_fk - yaw).abs());
                        worst = worst.max(err);
                        assert!(err < 1e-12, "p = {p}, yaw = {yaw}, {elbow}: error {err:e}");
                        count += 1;
                    }
                }
            }
        }
    }
    assert_eq!(count, 41 * 72 * 5 * 5 * 2);
    println!("FK(IK(x)) over {count} poses: worst error {worst:e}");
}

#[test]
fn geometry_is_read_from_the_generated_model() {
    let (g, t) = (ik(), ScaraGeometry::thesis());
    assert_abs_diff_eq!(g.l1(), t.l1(), epsilon = 1e-15);
    assert_abs_diff_eq!(g.l2(), t.l2(), epsilon = 1e-15);
    assert_abs_diff_eq!(g.z0(), t.z0(), epsilon = 1e-15);
    assert_eq!(g.limits(), Scara::JOINT_LIMITS);
}

#[test]
fn singular_targets_are_finite_and_flagged() {
    let g = ik();
    // The arm stretched (q2 = 0) in several directions, moving in every direction.
    for ia in 0..12 {
        let angle = -1.5 + 0.25 * ia as f64;
        let p = Vector3::new(0.8 * angle.cos(), 0.8 * angle.sin(), 0.2);
        let mut target = CartesianTarget::at_rest(p, armdyn::target::orientation::from_yaw(0.3));
        target.velocity = Vector3::new(-0.1, 0.07, 0.02);
        target.angular_velocity.z = -0.5;
        target.acceleration = Vector3::new(0.5, -0.3, 0.1);
        target.angular_acceleration.z = 0.2;
        for elbow in [Elbow::Up, Elbow::Down] {
            let r = g.joint_target(&target, elbow).unwrap();
            assert!(
                abs_diff_eq!(r.target.q[1], 0.0, epsilon = 1e-7),
                "q2 = {}",
                r.target.q[1]
            );
            let Conditioning::Damped { sin_q2, lambda } = r.conditioning else {
                panic!("not flagged: {:?}", r.conditioning);
            };
            assert!(sin_q2.abs() < SINGULARITY_THRESHOLD && lambda > 0.0 && lambda <= MAX_DAMPING);
            let all = r.target.q.iter().chain(&r.target.qd).chain(&r.target.qdd);
            assert!(all.into_iter().all(|v| v.is_finite()));
            // Only the motion along the arm is given up: across it, z and yaw are met.
            let v = Scara.jacobian(&r.target.q) * r.target.qd;
            let along = Vector3::new(angle.cos(), angle.sin(), 0.0);
            let across = Vector3::new(-angle.sin(), angle.cos(), 0.0);
            let v_lin = v.fixed_rows::<3>(0).into_owned();
            // Along and across are those of the exactly stretched arm; the weak direction
            // turns by O(q2) from them (q2 ~ 1e-8 here: the rounding of r near l1 + l2).
            let slack = 1e-12 + 10.0 * r.target.q[1].abs() * target.velocity.norm();
            assert_abs_diff_eq!(
                v_lin.dot(&across),
                target.velocity.dot(&across),
                epsilon = slack
            );
            assert_abs_diff_eq!(v[2], target.velocity.z, epsilon = 1e-12);
            assert!(
                abs_diff_eq!(v[5], target.angular_velocity.z, epsilon = 1e-12),
                "yaw rate {} vs {}; v = {v}",
                v[5],
                target.angular_velocity.z
            );
            assert_abs_diff_eq!(v_lin.dot(&along), 0.0, epsilon = slack);
        }
    }
}

#[test]
fn joint_references_match_differences_of_inverse_kinematics() {
    let g = ik();
    let h = 1e-5;
    let references: [(&dyn CartesianTrajectory, Elbow); 3] = [
        (&PositionTest::new(), Elbow::Up),
        (&PositionTest::new(), Elbow::Down),
        (&ThreeZone::new(), Elbow::Up),
    ];
    for (reference, elbow) in references {
        for k in 1..200 {
            let t = 10.0 * k as f64 / 200.0;
            let r = g.joint_target(&reference.at(t), elbow).unwrap();
            if r.conditioning.is_singular() {
                continue;
            }
            let q_at = |t: f64| g.inverse(&reference.at(t).position, 0.0, elbow).unwrap();
            let qd_at = |t: f64| g.joint_target(&reference.at(t), elbow).unwrap().target.qd;
            let mut dq: Vector4<f64> = (q_at(t + h) - q_at(t - h)) / (2.0 * h);
            dq[3] = wrap_angle(q_at(t + h)[3] - q_at(t - h)[3]) / (2.0 * h);
            let dqd = (qd_at(t + h) - qd_at(t - h)) / (2.0 * h);
            let scale = 1.0 + r.target.qd.norm();
            assert!(
                abs_diff_eq!((dq - r.target.qd).norm(), 0.0, epsilon = 1e-6 * scale),
                "t = {t}: {dq} vs {}",
                r.target.qd
            );
            let scale = 1.0 + r.target.qdd.norm();
            assert!(
                abs_diff_eq!((dqd - r.target.qdd).norm(), 0.0, epsilon = 1e-5 * scale),
                "t = {t}: {dqd} vs {}",
                r.target.qdd
            );
        }
    }
}

/// Times (s) at which the classification of a sampled reference changes, with the new class.
fn zone_changes(samples: &[PoseSample]) -> Vec<(f64, Reachability)> {
    let g = ik();
    let mut out: Vec<(f64, Reachability)> = Vec::new();
    for s in samples {
        let class = g.classify(&s.position, s.yaw());
        match out.last() {
            Some((_, last)) if *last == class => {}
            _ => out.push((s.t, class)),
        }
    }
    out
}

#[test]
fn position_test_keeps_one_elbow() {
    let samples = sample(&PositionTest::new(), 0.005);
    println!("position test zones: {:?}", zone_changes(&samples));
    let plan = ik().plan_elbows(&samples).unwrap();
    assert_eq!(plan.single(), Some(Elbow::Up));
}

#[test]
fn contact_test_keeps_one_elbow() {
    let samples = sample(&ContactTest::thesis(), 0.005);
    println!("contact test zones: {:?}", zone_changes(&samples));
    let plan = ik().plan_elbows(&samples).unwrap();
    assert!(plan.single().is_some());
}

#[test]
fn three_zone_trial_switches_elbow() {
    let samples = sample(&ThreeZone::new(), 0.005);
    let zones = zone_changes(&samples);
    println!("three-zone zones: {zones:?}");
    assert_eq!(zones.len(), 3);
    assert_eq!(zones[0], (0.0, Reachability::DownOnly));
    assert_eq!(zones[1].1, Reachability::Both);
    assert_eq!(zones[2].1, Reachability::UpOnly);

    let g = ik();
    for policy in [
        SwitchPolicy::Latest,
        SwitchPolicy::Earliest,
        SwitchPolicy::SmallestJump,
    ] {
        let plan = g.plan_elbows_with(&samples, policy).unwrap();
        println!("{policy:?}: {plan:?}");
        assert_eq!(plan.initial(), Elbow::Down);
        assert_eq!(plan.switches().len(), 1);
        let switch = plan.switches()[0];
        assert_eq!(switch.to, Elbow::Up);
        // The window is the both-zone.
        assert_eq!(switch.earliest, zones[1].0);
        assert_eq!(switch.latest, zones[2].0);
        assert_eq!(plan.elbow_at(switch.t - 1e-9), Elbow::Down);
        assert_eq!(plan.elbow_at(switch.t), Elbow::Up);
        match policy {
            SwitchPolicy::Latest => assert_eq!(switch.t, switch.latest),
            SwitchPolicy::Earliest => assert_eq!(switch.t, switch.earliest),
            SwitchPolicy::SmallestJump => {
                assert!(switch.earliest <= switch.t && switch.t <= switch.latest)
            }
        }
        // Every sample is feasible with the planned elbow.
        for s in &samples {
            let q = g.inverse(&s.position, s.yaw(), plan.elbow_at(s.t)).unwrap();
            assert!(g.within_limits(&q), "t = {}: {q}", s.t);
        }
    }
}

#[test]
fn unreachable_samples_are_named_before_the_run() {
    // The position test pushed 0.1 m further out: its start leaves the annulus.
    let samples: Vec<PoseSample> = sample(&PositionTest::new(), 0.005)
        .into_iter()
        .map(|mut s| {
            s.position.x += 0.1;
            s
        })
        .collect();
    let err = ik().plan_elbows(&samples).unwrap_err();
    let WorkspaceError::Unreachable {
        count,
        total,
        first,
    } = &err
    else {
        panic!("{err:?}");
    };
    assert_eq!(*total, 2001);
    assert!(*count > 0 && *count < 2001);
    assert_eq!(first.0.len(), 5);
    assert_eq!(first.0[0].t, 0.0);
    assert_eq!(first.0[0].position, Vector3::new(0.9, 0.0, 0.25));
    assert!(matches!(first.0[0].reason, Reason::OutOfReach(_)));
    let text = err.to_string();
    println!("{text}");
    assert!(
        text.contains("sample 0 at t = 0 s, position (0.9, 0, 0.25) m"),
        "{text}"
    );
    assert!(text.contains("beyond l1 + l2 = 0.8"), "{text}");

    // A point behind the base, in the middle of an otherwise fine line: q1 limit for both.
    let mut samples = sample(&ThreeZone::new(), 0.5);
    samples[7].position = Vector3::new(-0.3, 0.0, 0.1);
    let err = ik().plan_elbows(&samples).unwrap_err();
    let text = err.to_string();
    println!("{text}");
    assert!(
        text.starts_with("1 of 21 reference samples are outside the workspace"),
        "{text}"
    );
    assert!(
        text.contains("sample 7 at t = 3.5 s, position (-0.3, 0, 0.1) m: elbow up: q1 = "),
        "{text}"
    );
}

#[test]
fn a_reference_read_from_csv_plans_like_the_original() {
    let samples = sample(&ThreeZone::new(), 0.01);
    let mut text = String::from("t,x,y,z,yaw\n");
    for s in &samples {
        text += &format!(
            "{},{},{},{},{}\n",
            s.t,
            s.position.x,
            s.position.y,
            s.position.z,
            s.yaw()
        );
    }
    let reference = SampledTrajectory::from_csv_reader(text.as_bytes()).unwrap();
    assert_eq!(reference.len(), samples.len());
    let from_csv: Vec<PoseSample> = reference.samples().collect();
    assert_eq!(from_csv, samples); // shortest round-trip formatting of f64 is exact
    let g = ik();
    assert_eq!(
        g.plan_elbows(&from_csv).unwrap(),
        g.plan_elbows(&samples).unwrap()
    );
    // Its joint references are close to the analytic ones (second-order differences).
    for k in 1..100 {
        let t = 0.1 * k as f64 + 0.003;
        let elbow = Elbow::Down;
        let a = g.joint_target(&ThreeZone::new().at(t), elbow);
        let b = g.joint_target(&reference.at(t), elbow);
        if let (Ok(a), Ok(b)) = (a, b) {
            assert!(
                abs_diff_eq!((a.target.q - b.target.q).norm(), 0.0, epsilon = 1e-4),
                "t = {t}"
            );
            assert!(
                abs_diff_eq!(
                    (a.target.qd - b.target.qd).norm(),
                    0.0,
                    epsilon = 1e-2 * (1.0 + a.target.qd.norm())
                ),
                "t = {t}"
            );
        }
    }
}
