//! Dynamics of every generated robot against quantities rebuilt from the description:
//!
//! - `M(q)` is the Hessian (w.r.t. `qd`) of the kinetic energy computed from frame
//!   velocities (central differences of the independent forward kinematics);
//! - `C(q, qd)` equals the Christoffel form built from central differences of `M`, and
//!   `Mdot - 2C` is skew-symmetric;
//! - `c = C qd`;
//! - `g(q)` is the gradient of the potential energy;
//! - forward and inverse dynamics invert each other (`ID(FD(tau)) = tau`, with a contact
//!   torque);
//! - the generated forward dynamics (sparse `L^T D L`) equals the Cholesky solve of
//!   `M qdd = tau - c - g`;
//! - `mass_matrix_and_bias` (one generated graph `[M | c + g]`) equals `M` and `c + g` of the
//!   separate functions;
//! - `jacobian_and_position` (one generated graph `[J | p; 0]`) equals `J` and the translation
//!   of the end-effector pose.

use crate::common;

use armdyn::model::{forward_dynamics, forward_dynamics_cholesky, inverse_dynamics, RobotModel};
use common::{assert_close, load_robot, max_abs, Rng, SEED, STATES};
use nalgebra::{SMatrix, SVector};

/// M vs. the Hessian of the kinetic energy (velocities by central differences, step
/// `H_VELOCITY` in time).
const TOL_MASS: f64 = 1e-8;
const H_VELOCITY: f64 = 1e-5;
/// C vs. Christoffel symbols of central differences of M (step `H_MASS`), and the skew
/// symmetry of `Mdot - 2C` with Mdot by central differences along qd.
const TOL_CORIOLIS: f64 = 1e-7;
const H_MASS: f64 = 1e-6;
/// `c = C qd`: same data, different code path; only rounding separates them.
const TOL_EXACT: f64 = 1e-12;
/// g vs. central differences of the potential energy (step `H_POTENTIAL`).
const TOL_GRAVITY: f64 = 1e-8;
const H_POTENTIAL: f64 = 1e-5;
/// Forward then inverse dynamics gives the torque back.
const TOL_ROUNDTRIP: f64 = 1e-10;
/// Generated forward dynamics vs the Cholesky path: both exact, only rounding (amplified by
/// the condition number of `M`) separates them.
const TOL_FD_PATHS: f64 = 1e-10;

fn mass_matrix_is_hessian_of_kinetic_energy<const N: usize, R: RobotModel<N>>(
    robot: &R,
    name: &str,
) {
    let desc = load_robot(name);
    for state in desc.random_states::<N>(name, SEED ^ 0x2, STATES) {
        let (q, qd) = (state.q, state.qd);
        let unit = |j: usize| SVector::<f64, N>::from_fn(|i, _| if i == j { 1.0 } else { 0.0 });
        let energy =
            |v: &SVector<f64, N>| desc.kinetic_energy(q.as_slice(), v.as_slice(), H_VELOCITY);
        // T is quadratic in qd: T(v) = 1/2 v^T M v. Polarisation gives the Hessian exactly:
        // M_jj = 2 T(e_j), M_jk = T(e_j + e_k) - T(e_j) - T(e_k).
        let diag: Vec<f64> = (0..N).map(|j| energy(&unit(j))).collect();
        let expected = SMatrix::<f64, N, N>::from_fn(|j, k| {
            if j == k {
                2.0 * diag[j]
            } else {
                energy(&(unit(j) + unit(k))) - diag[j] - diag[k]
            }
        });
        let m = robot.mass_matrix(&q);
        assert_close(
            "M vs Hessian of T",
            &m,
            &expected,
            TOL_MASS,
            max_abs(&expected),
            &state,
        );
        // The kinetic energy at this qd, too (1/2 qd^T M qd).
        let t = SMatrix::<f64, 1, 1>::new(0.5 * qd.dot(&(m * qd)));
        let t_ref = SMatrix::<f64, 1, 1>::new(energy(&qd));
        assert_close(
            "T = 1/2 qd^T M qd",
            &t,
            &t_ref,
            TOL_MASS,
            max_abs(&expected) * qd.norm_squared(),
            &state,
        );
        assert_close(
            "M symmetric",
            &m,
            &m.transpose(),
            TOL_EXACT,
            max_abs(&m),
            &state,
        );
        assert!(m.cholesky().is_some(), "M not positive definite at {state}");
    }
}

fn coriolis_matrix_is_christoffel_form<const N: usize, R: RobotModel<N>>(robot: &R, name: &str) {
    let desc = load_robot(name);
    for state in desc.random_states::<N>(name, SEED ^ 0x3, STATES) {
        let (q, qd) = (state.q, state.qd);
        let c = robot.coriolis_matrix(&q, &qd);
        // dM/dq_i by central differences.
        let dm: Vec<SMatrix<f64, N, N>> = (0..N)
            .map(|i| {
                let (mut plus, mut minus) = (q, q);
                plus[i] += H_MASS;
                minus[i] -= H_MASS;
                (robot.mass_matrix(&plus) - robot.mass_matrix(&minus)) / (2.0 * H_MASS)
            })
            .collect();
        // C_kj = sum_i 1/2 (dM_kj/dq_i + dM_ki/dq_j - dM_ij/dq_k) qd_i
        let expected = SMatrix::<f64, N, N>::from_fn(|k, j| {
            (0..N)
                .map(|i| 0.5 * (dm[i][(k, j)] + dm[j][(k, i)] - dm[k][(i, j)]) * qd[i])
                .sum()
        });
        let scale = max_abs(&expected) + max_abs(&robot.mass_matrix(&q)) * qd.amax();
        assert_close(
            "C vs Christoffel(dM/dq)",
            &c,
            &expected,
            TOL_CORIOLIS,
            scale,
            &state,
        );

        // Mdot - 2C is skew-symmetric, Mdot = dM/dt along qd.
        let mdot = (robot.mass_matrix(&(q + qd * H_MASS)) - robot.mass_matrix(&(q - qd * H_MASS)))
            / (2.0 * H_MASS);
        let n = mdot - 2.0 * c;
        let scale = max_abs(&mdot) + 2.0 * max_abs(&c);
        assert_close(
            "(Mdot - 2C) + (Mdot - 2C)^T",
            &(n + n.transpose()),
            &SMatrix::zeros(),
            TOL_CORIOLIS,
            scale,
            &state,
        );
    }
}

fn coriolis_vector_is_c_times_qd<const N: usize, R: RobotModel<N>>(robot: &R, name: &str) {
    let desc = load_robot(name);
    for state in desc.random_states::<N>(name, SEED ^ 0x4, STATES) {
        let (q, qd) = (state.q, state.qd);
        let c_matrix = robot.coriolis_matrix(&q, &qd);
        let expected = c_matrix * qd;
        let got = robot.coriolis(&q, &qd);
        let scale = max_abs(&c_matrix) * qd.amax();
        assert_close("c vs C qd", &got, &expected, TOL_EXACT, scale, &state);
    }
}

fn gravity_is_gradient_of_potential<const N: usize, R: RobotModel<N>>(robot: &R, name: &str) {
    let desc = load_robot(name);
    for state in desc.random_states::<N>(name, SEED ^ 0x5, STATES) {
        let q = state.q;
        let expected = SVector::<f64, N>::from_fn(|j, _| {
            let (mut plus, mut minus) = (q, q);
            plus[j] += H_POTENTIAL;
            minus[j] -= H_POTENTIAL;
            (desc.potential_energy(plus.as_slice()) - desc.potential_energy(minus.as_slice()))
                / (2.0 * H_POTENTIAL)
        });
        let got = robot.gravity(&q);
        assert_close(
            "g vs dU/dq",
            &got,
            &expected,
            TOL_GRAVITY,
            max_abs(&expected),
            &state,
        );
    }
}

fn forward_and_inverse_dynamics_agree<const N: usize, R: RobotModel<N>>(robot: &R, name: &str) {
    let desc = load_robot(name);
    // The inputs beside each state, from a seed of their own.
    let mut rng = Rng::new(SEED ^ 0x6 ^ 0x100);
    for state in desc.random_states::<N>(name, SEED ^ 0x6, STATES) {
        let (q, qd) = (state.q, state.qd);
        let tau = SVector::<f64, N>::from_fn(|i, _| rng.uniform(-1.0, 1.0) * desc.joints[i].effort);
        let tau_ext = SVector::<f64, N>::from_fn(|_, _| rng.uniform(-5.0, 5.0));
        let qdd = match forward_dynamics(robot, &q, &qd, &tau, &tau_ext) {
            Ok(qdd) => qdd,
            Err(e) => panic!("forward dynamics failed at {state}: {e}"),
        };
        let back = inverse_dynamics(robot, &q, &qd, &qdd, &tau_ext);
        let scale = max_abs(&tau) + max_abs(&(robot.mass_matrix(&q) * qdd));
        assert_close("ID(FD(tau))", &back, &tau, TOL_ROUNDTRIP, scale, &state);
    }
}

fn generated_forward_dynamics_equals_cholesky<const N: usize, R: RobotModel<N>>(
    robot: &R,
    name: &str,
) {
    let desc = load_robot(name);
    // The inputs beside each state, from a seed of their own.
    let mut rng = Rng::new(SEED ^ 0x7 ^ 0x100);
    for state in desc.random_states::<N>(name, SEED ^ 0x7, STATES) {
        let (q, qd) = (state.q, state.qd);
        let tau = SVector::<f64, N>::from_fn(|i, _| rng.uniform(-1.0, 1.0) * desc.joints[i].effort);
        let tau_ext = SVector::<f64, N>::from_fn(|_, _| rng.uniform(-5.0, 5.0));
        let want = forward_dynamics_cholesky(robot, &q, &qd, &tau, &tau_ext)
            .unwrap_or_else(|e| panic!("Cholesky forward dynamics failed at {state}: {e}"));
        // The trait method is the generated function for the generated robots.
        let got = robot
            .forward_dynamics(&q, &qd, &(tau - tau_ext))
            .unwrap_or_else(|e| panic!("generated forward dynamics failed at {state}: {e}"));
        assert_close(
            "generated FD vs Cholesky FD",
            &got,
            &want,
            TOL_FD_PATHS,
            max_abs(&want).max(1.0),
            &state,
        );
        let free = forward_dynamics(robot, &q, &qd, &tau, &tau_ext).unwrap();
        assert_eq!(
            free, got,
            "forward_dynamics is the trait method of tau - tau_ext"
        );
    }
}

fn mass_matrix_and_bias_is_m_and_c_plus_g<const N: usize, R: RobotModel<N>>(robot: &R, name: &str) {
    let desc = load_robot(name);
    for state in desc.random_states::<N>(name, SEED ^ 0x8, STATES) {
        let (q, qd) = (state.q, state.qd);
        let (m, bias) = robot.mass_matrix_and_bias(&q, &qd);
        let want_m = robot.mass_matrix(&q);
        let (c, g) = (robot.coriolis(&q, &qd), robot.gravity(&q));
        let scale = max_abs(&want_m);
        assert_close("M of [M | c + g]", &m, &want_m, TOL_EXACT, scale, &state);
        let scale = max_abs(&c) + max_abs(&g);
        assert_close(
            "c + g of [M | c + g]",
            &bias,
            &(c + g),
            TOL_EXACT,
            scale,
            &state,
        );
    }
}

fn jacobian_and_position_is_j_and_p<const N: usize, R: RobotModel<N>>(robot: &R, name: &str) {
    let desc = load_robot(name);
    for state in desc.random_states::<N>(name, SEED ^ 0x9, STATES) {
        let q = state.q;
        let (j, p) = robot.jacobian_and_position(&q);
        let want_j = robot.jacobian(&q);
        let pose = robot.end_effector_pose(&q);
        let want_p: nalgebra::Vector3<f64> = pose.fixed_view::<3, 1>(0, 3).into_owned();
        let scale = max_abs(&want_j);
        assert_close("J of (J, p)", &j, &want_j, TOL_EXACT, scale, &state);
        let scale = want_p.amax();
        assert_close("p of (J, p)", &p, &want_p, TOL_EXACT, scale, &state);
    }
}

per_robot!(
    mass_matrix_is_hessian_of_kinetic_energy,
    coriolis_matrix_is_christoffel_form,
    coriolis_vector_is_c_times_qd,
    gravity_is_gradient_of_potential,
    forward_and_inverse_dynamics_agree,
    generated_forward_dynamics_equals_cholesky,
    mass_matrix_and_bias_is_m_and_c_plus_g,
    jacobian_and_position_is_j_and_p,
);
