//! Energy conservation of the simulated plant: RK4 at 1 ms over 10 s, no torque, no
//! friction, no contact (issue acceptance: relative drift below 1e-6).

use armdyn::contact::FreeSpace;
use armdyn::control::open_loop::ZeroTorque;
use armdyn::model::{Planar2, Puma560, RobotModel, Scara, WithoutGravity, Wrench};
use armdyn::sim::{simulate, ReferenceSource, Setpoint, SimConfig};
use armdyn::target::CartesianTarget;
use armdyn::target::JointTarget;
use nalgebra::{SVector, UnitQuaternion, Vector3};

/// Largest allowed |E(t) - E(0)| / E_scale over the run.
const DRIFT_TOL: f64 = 1e-6;

struct Still<const N: usize>;

impl<const N: usize> ReferenceSource<N> for Still<N> {
    fn at(&mut self, _t: f64) -> Setpoint<N> {
        let z = SVector::<f64, N>::zeros();
        Setpoint {
            joint: JointTarget {
                q: z,
                qd: z,
                qdd: z,
            },
            cartesian: CartesianTarget::at_rest(Vector3::zeros(), UnitQuaternion::identity()),
            wrench: Wrench::zeros(),
        }
    }
}

/// Potential energy from the generated frame poses and the robot's standard parameters
/// (mass and first moment per link, in the link frames): `U = -sum g . (m p + R h)`.
fn potential<const N: usize, R: RobotModel<N>>(
    robot: &R,
    params: &[f64],
    q: &SVector<f64, N>,
) -> f64 {
    let g = Vector3::from(R::GRAVITY);
    robot
        .frame_poses(q)
        .iter()
        .enumerate()
        .map(|(i, t)| {
            let m = params[10 * i];
            let h = Vector3::new(params[10 * i + 1], params[10 * i + 2], params[10 * i + 3]);
            let r = t.fixed_view::<3, 3>(0, 0);
            let p = t.fixed_view::<3, 1>(0, 3);
            -g.dot(&(p * m + r * h))
        })
        .sum()
}

fn drift<const N: usize, R: RobotModel<N>>(
    robot: R,
    params: &[f64],
    q0: [f64; N],
    qd0: [f64; N],
) -> f64 {
    let mut cfg = SimConfig::new(&robot);
    cfg.q0 = SVector::from(q0);
    cfg.qd0 = SVector::from(qd0);
    let energy = |q: &SVector<f64, N>, qd: &SVector<f64, N>| {
        0.5 * (qd.transpose() * robot.mass_matrix(q) * qd)[0] + potential(&robot, params, q)
    };
    let e0 = energy(&cfg.q0, &cfg.qd0);
    let mut worst = 0.0f64;
    let mut scale = e0.abs().max(1e-12);
    simulate(
        &robot,
        &mut ZeroTorque,
        &mut Still::<N>,
        &FreeSpace,
        &cfg,
        |s| {
            let kinetic = 0.5 * (s.qd.transpose() * robot.mass_matrix(&s.q) * s.qd)[0];
            scale = scale
                .max(kinetic.abs())
                .max(potential(&robot, params, &s.q).abs());
            worst = worst.max((energy(&s.q, &s.qd) - e0).abs());
        },
    )
    .expect("free motion simulates");
    worst / scale
}

#[test]
fn energy_is_conserved_without_gravity() {
    let p = armdyn_generated::scara::standard_parameters();
    let d = drift(
        WithoutGravity(Scara),
        &p,
        [0.1, 0.5, 0.2, 0.0],
        [1.0, -0.8, 0.1, 2.0],
    );
    assert!(d < DRIFT_TOL, "SCARA, no gravity: relative drift {d:e}");
    let p = armdyn_generated::puma560::standard_parameters();
    let d = drift(
        WithoutGravity(Puma560),
        &p,
        [0.1, -0.5, 0.3, 0.2, 0.4, 0.0],
        [0.5, -0.4, 0.6, 1.0, -1.0, 2.0],
    );
    assert!(d < DRIFT_TOL, "PUMA 560, no gravity: relative drift {d:e}");
}

#[test]
fn kinetic_plus_potential_energy_is_conserved_with_gravity() {
    let p = armdyn_generated::scara::standard_parameters();
    let d = drift(Scara, &p, [0.1, 0.5, 0.2, 0.0], [1.0, -0.8, 0.1, 2.0]);
    assert!(d < DRIFT_TOL, "SCARA with gravity: relative drift {d:e}");
    let p = armdyn_generated::planar2::standard_parameters();
    let d = drift(Planar2, &p, [0.3, -0.2], [0.0, 0.0]);
    assert!(d < DRIFT_TOL, "planar arm swinging: relative drift {d:e}");
}
