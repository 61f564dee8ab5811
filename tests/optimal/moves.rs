//! Minimum-effort moves meet the goal at rest, keep every torque within its share and every
//! joint inside its limits, follow the model's own dynamics knot to knot, and spend less
//! effort than the quintic of the same duration; the shortest move is shorter than the
//! shortest quintic within the same share, and one knot step shorter is infeasible.

use armdyn::model::DynamicsDerivatives;
use armdyn::model::{JointVector, Panda, RobotModel, Scara, Ur5};
use armdyn::optimal::{
    optimise_move, quintic_peak_effort_share, shortest_move, shortest_quintic, IlqrOptions,
    MoveProblem, OptimalMove, PlanError,
};
use armdyn::sim::rk4::rk4_step;

/// The quintic's effort `integral sum (tau_i / e_i)^2 dt` (midpoint rule, 2000 points).
fn quintic_effort<const N: usize, R: RobotModel<N>>(
    robot: &R,
    from: &JointVector<N>,
    to: &JointVector<N>,
    t: f64,
) -> f64 {
    let e = robot.effort_limits();
    let d = to - from;
    let n = 2000;
    (0..n)
        .map(|k| {
            let u = (k as f64 + 0.5) / n as f64;
            let s = u * u * u * (10.0 - 15.0 * u + 6.0 * u * u);
            let ds = 30.0 * u * u * (1.0 - u) * (1.0 - u) / t;
            let dds = 60.0 * u * (1.0 - 3.0 * u + 2.0 * u * u) / (t * t);
            let tau = robot.inverse_dynamics(&(from + d * s), &(d * ds), &(d * dds));
            (0..N).map(|i| (tau[i] / e[i]).powi(2)).sum::<f64>() * t / n as f64
        })
        .sum()
}

/// Every property a plan must have (see the module documentation).
fn check_plan<const N: usize, R: DynamicsDerivatives<N>>(
    robot: &R,
    p: &MoveProblem<N>,
    m: &OptimalMove<N>,
) {
    let e = robot.effort_limits();
    let steps = m.qdd.len();
    assert_eq!(m.q.len(), steps + 1);
    assert!(
        (m.q[steps] - p.to).amax() <= 1e-6,
        "goal missed: {}",
        (m.q[steps] - p.to).amax()
    );
    assert!(
        m.qd[steps].amax() <= 1e-6,
        "not at rest: {}",
        m.qd[steps].amax()
    );
    assert_eq!(m.q[0], p.from);
    let (lo, hi) = (robot.lower_limits(), robot.upper_limits());
    for k in 0..steps {
        for i in 0..N {
            assert!(
                (m.tau[k][i] / e[i]).abs() <= p.max_effort_share + 1e-12,
                "knot {k} joint {i}: {} of the effort limit",
                m.tau[k][i] / e[i]
            );
            assert!(m.q[k + 1][i] >= lo[i] + p.limit_margin - 1e-6);
            assert!(m.q[k + 1][i] <= hi[i] - p.limit_margin + 1e-6);
        }
        // The knots follow the model: the torque held over the step, p.substeps RK4 steps.
        let qdd = robot
            .forward_dynamics(&m.q[k], &m.qd[k], &m.tau[k])
            .unwrap();
        assert!((qdd - m.qdd[k]).amax() <= 1e-9 * (1.0 + qdd.amax()));
        let h = m.step_s;
        let (mut q1, mut qd1) = (m.q[k], m.qd[k]);
        for _ in 0..p.substeps {
            (q1, qd1) = rk4_step(&q1, &qd1, h / p.substeps as f64, |q, qd| {
                robot.forward_dynamics(q, qd, &m.tau[k])
            })
            .unwrap();
        }
        assert!((q1 - m.q[k + 1]).amax() <= 1e-12 && (qd1 - m.qd[k + 1]).amax() <= 1e-10);
        // The reference reproduces the knots.
        let at = m.at(k as f64 * h);
        assert!((at.q - m.q[k]).amax() <= 1e-12 && (at.qd - m.qd[k]).amax() <= 1e-12);
    }
    assert!(
        (m.peak_effort_share
            - m.tau
                .iter()
                .map(|t| (0..N).map(|i| (t[i] / e[i]).abs()).fold(0.0, f64::max))
                .fold(0.0, f64::max))
        .abs()
            < 1e-12
    );
}

fn min_effort<const N: usize, R: DynamicsDerivatives<N>>(
    robot: &R,
    from: JointVector<N>,
    to: JointVector<N>,
    duration_s: f64,
) {
    let p = MoveProblem {
        from,
        to,
        duration_s,
        step_s: 0.005,
        substeps: 2,
        max_effort_share: 1.0,
        limit_margin: 0.0,
        max_joint_speed: None,
    };
    let m = optimise_move(robot, &p, &IlqrOptions::default()).unwrap();
    check_plan(robot, &p, &m);
    let quintic = quintic_effort(robot, &from, &to, duration_s);
    println!(
        "{}: {duration_s} s, effort {:.5} (quintic {quintic:.5}), peak share {:.3} (quintic {:.3}), {} iterations",
        R::NAME,
        m.effort,
        m.peak_effort_share,
        quintic_peak_effort_share(robot, &from, &to, duration_s),
        m.iterations
    );
    assert!(m.effort < quintic, "{} >= quintic {quintic}", m.effort);
}

#[test]
fn scara_minimum_effort_move() {
    min_effort(
        &Scara,
        JointVector::<4>::new(1.2, -2.0, 0.1, 0.0),
        JointVector::<4>::new(-0.7, 2.0, 0.25, 0.3),
        1.0,
    );
}

#[test]
fn ur5_minimum_effort_move() {
    min_effort(
        &Ur5,
        JointVector::<6>::from_column_slice(&[0.0, -1.5, 1.2, -1.0, -1.5, 0.0]),
        JointVector::<6>::from_column_slice(&[1.5, -1.0, 0.5, -1.5, -1.0, 1.0]),
        1.0,
    );
}

#[test]
fn panda_minimum_effort_move() {
    min_effort(
        &Panda,
        JointVector::<7>::from_column_slice(&[0.0, -0.5, 0.0, -2.0, 0.0, 1.6, 0.8]),
        JointVector::<7>::from_column_slice(&[1.0, 0.3, -0.5, -1.5, 0.5, 2.0, 0.0]),
        1.0,
    );
}

#[test]
fn scara_shortest_move_beats_the_quintic() {
    let from = JointVector::<4>::new(1.2, -2.0, 0.1, 0.0);
    let to = JointVector::<4>::new(-0.7, 2.0, 0.25, 0.3);
    let share = 0.8;
    let p = MoveProblem {
        from,
        to,
        duration_s: 1.0,
        step_s: 0.005,
        substeps: 2,
        max_effort_share: share,
        limit_margin: 0.0,
        max_joint_speed: None,
    };
    let options = IlqrOptions::default();
    let m = shortest_move(&Scara, &p, &options).unwrap();
    check_plan(&Scara, &p, &m);
    let quintic = shortest_quintic(&Scara, &from, &to, share).unwrap();
    println!(
        "shortest: optimised {:.4} s, quintic {quintic:.4} s",
        m.duration_s()
    );
    assert!(m.duration_s() < 0.95 * quintic);
    let shorter = MoveProblem {
        duration_s: m.duration_s() - p.step_s,
        ..p
    };
    assert!(matches!(
        optimise_move(&Scara, &shorter, &options),
        Err(PlanError::Infeasible { .. })
    ));
}
