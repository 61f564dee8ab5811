//! Synthetic runs for the report tests: the SCARA following smooth joint references with
//! a decaying error, its pose from forward kinematics, and a contact force that settles
//! onto a stepped reference.

use crate::model::{JointVector, RobotModel, Scara, Wrench};
use crate::sim::{Sample, Setpoint};
use crate::target::CartesianTarget;
use crate::target::JointTarget;
use nalgebra::Vector3;

fn pose(q: &JointVector<4>) -> (Vector3<f64>, f64) {
    let p = Scara.end_effector_pose(q);
    (
        Vector3::new(p[(0, 3)], p[(1, 3)], p[(2, 3)]),
        libm::atan2(p[(1, 0)], p[(0, 0)]),
    )
}

/// `n` samples evenly over `[0, duration]` seconds.
pub(crate) fn synthetic_run(n: usize, duration: f64) -> Vec<Sample<4>> {
    (0..n)
        .map(|k| {
            let t = if n > 1 {
                duration * k as f64 / (n - 1) as f64
            } else {
                0.0
            };
            let q_ref = JointVector::<4>::new(
                0.9 * (0.6 * t).sin() + 0.3,
                -1.2 + 0.6 * (0.5 * t).cos(),
                0.06 + 0.03 * (0.8 * t).sin(),
                0.2 * (0.4 * t).sin(),
            );
            let qd_ref = JointVector::<4>::new(
                0.54 * (0.6 * t).cos(),
                -0.3 * (0.5 * t).sin(),
                0.024 * (0.8 * t).cos(),
                0.08 * (0.4 * t).cos(),
            );
            let decay = (-3.0 * t).exp() * (6.0 * t).cos();
            let e0 = JointVector::<4>::new(0.3, -0.6, 0.06, 0.0);
            let q = q_ref - e0 * decay;
            let qd = qd_ref;
            let (position, yaw) = pose(&q);
            let (position_ref, yaw_ref) = pose(&q_ref);
            let contact = (t >= 0.2 * duration) as u8 as f64;
            let fz_ref = contact * (-20.0 - 5.0 * (2.0 * t).sin());
            let ts = (t - 0.2 * duration).max(0.0);
            let fz = fz_ref * (1.0 - (-4.0 * ts).exp() * (9.0 * ts).cos());
            let tau = JointVector::<4>::new(
                20.0 * decay,
                -10.0 * decay,
                98.1 + 5.0 * decay,
                0.1 * t.sin(),
            );
            Sample {
                t,
                q,
                qd,
                tau_command: tau * 1.1,
                tau,
                setpoint: Setpoint {
                    joint: JointTarget {
                        q: q_ref,
                        qd: qd_ref,
                        qdd: JointVector::zeros(),
                    },
                    cartesian: CartesianTarget::at_rest(
                        position_ref,
                        crate::target::orientation::from_yaw(yaw_ref),
                    ),
                    wrench: Wrench::new(0.0, 0.0, fz_ref, 0.0, 0.0, 0.0),
                },
                position,
                orientation: crate::target::orientation::from_yaw(yaw),
                wrench: Wrench::new(0.0, 0.0, fz, 0.0, 0.0, 0.0),
                measured_wrench: Wrench::new(0.0, 0.0, fz, 0.0, 0.0, 0.0),
                force_controlled: t >= 2.0,
            }
        })
        .collect()
}

/// Joint sinusoids about an elbow-down pose, the Cartesian target from forward kinematics.
struct JointSines;

impl crate::sim::ReferenceSource<4> for JointSines {
    fn at(&mut self, t: f64) -> Setpoint<4> {
        let w = JointVector::<4>::new(0.6, 0.5, 1.5, 0.4);
        let a = JointVector::<4>::new(0.9, 0.6, 0.05, 0.2);
        // d3 in [0.15, 0.25] m: the tool dips below the surface (z = 0.35 - d3 < 0.13).
        let c = JointVector::<4>::new(0.3, -1.2, 0.2, 0.0);
        let q = c + JointVector::from_fn(|i, _| a[i] * (w[i] * t).sin());
        let qd = JointVector::from_fn(|i, _| a[i] * w[i] * (w[i] * t).cos());
        let qdd = JointVector::from_fn(|i, _| -a[i] * w[i] * w[i] * (w[i] * t).sin());
        let (position, yaw) = pose(&q);
        Setpoint {
            joint: JointTarget { q, qd, qdd },
            cartesian: CartesianTarget::at_rest(
                position,
                crate::target::orientation::from_yaw(yaw),
            ),
            wrench: Wrench::zeros(),
        }
    }
}

/// A real closed loop: computed torque (20 rad/s) from rest at q = 0 tracking
/// [`JointSines`] for `duration` s, above the thesis's reaction surface.
pub(crate) fn simulated_run(duration: f64) -> Vec<Sample<4>> {
    use crate::contact::ReactionSurface;
    use crate::control::computed_torque::ComputedTorque;
    use crate::sim::{simulate, SimConfig};
    let mut controller = ComputedTorque::critically_damped(Scara, 20.0);
    let mut config = SimConfig::new(&Scara);
    config.duration = duration;
    let mut samples = Vec::new();
    simulate(
        &Scara,
        &mut controller,
        &mut JointSines,
        &ReactionSurface::new(0.13, [0.2, 0.6], [-0.4, 0.4], 10_000.0).unwrap(),
        &config,
        |s| samples.push(*s),
    )
    .unwrap();
    samples
}
