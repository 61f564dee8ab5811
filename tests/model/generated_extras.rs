//! The generated functions beyond `M`, `C`, `c`, `g` and the kinematics, for every robot:
//!
//! - `jdot_qd` equals central differences of `J` along `qd`, times `qd`;
//! - `inverse_dynamics` (recursive Newton–Euler) equals `M qdd + c + g`;
//! - `mass_matrix_and_bias` is `[M | c + g]` of `mass_matrix`, `coriolis` and `gravity`;
//! - `jacobian_and_position` is `[J | p; 0]` of `jacobian` and the translation of
//!   `end_effector_pose`;
//! - `standard_parameters` equals the inertial parameters of the description
//!   (`[m, m c, I about the frame origin]` per link);
//! - `regressor(q, qd, qdd) * standard_parameters() = inverse_dynamics(q, qd, qdd)`, and each
//!   regressor column is the parametric inverse dynamics with that unit parameter;
//! - the `parametric` module evaluated at the standard parameters equals the numeric one;
//! - the parametric `forward_dynamics` equals the Cholesky solve of the parametric
//!   `M qdd = tau - c - g`, and its inverse dynamics gives `tau` back, at physical parameter
//!   sets other than the description's (each link's parameters scaled by a factor in
//!   [0.7, 1.3]).

use crate::common;

use ::armdyn::model::cholesky::Cholesky;
use approx::{abs_diff_eq, relative_eq};
use common::{assert_close, load_robot, max_abs, Rng, State, SEED, STATES};
use nalgebra::{SMatrix, SVector};

/// `Jdot qd` vs. central differences of the Jacobian (step `H_JACOBIAN`).
const TOL_JDOT: f64 = 1e-7;
const H_JACOBIAN: f64 = 1e-6;
/// Two exact evaluations of the same quantity: only rounding separates them.
const TOL_EXACT: f64 = 1e-12;
/// Parametric forward dynamics vs the Cholesky solve, and back through inverse dynamics:
/// exact, rounding amplified by the condition number of `M` (relative to the larger entry).
const TOL_FD: f64 = 1e-10;
/// Parameter sets of the parametric forward-dynamics test, each at every state.
const PARAMETER_SETS: usize = 4;

macro_rules! extras {
    ($module:ident, $n:literal, $p:expr $(, #[$sp_attr:meta])?) => {
        mod $module {
            use super::*;
            use armdyn_generated::$module as g;

            type V = SVector<f64, $n>;
            type M = SMatrix<f64, $n, $n>;

            fn arr(v: &V) -> [f64; $n] {
                (*v).into()
            }
            fn mat<const R: usize, const C: usize>(m: &[[f64; C]; R]) -> SMatrix<f64, R, C> {
                SMatrix::from_fn(|i, j| m[i][j])
            }
            fn jacobian(q: &V) -> SMatrix<f64, 6, $n> {
                mat(&g::jacobian(&arr(q)))
            }
            /// `STATES` random states, each with a random `qdd`.
            fn states(salt: u64) -> Vec<(State<'static, $n>, V)> {
                let desc = load_robot(stringify!($module));
                let mut rng = Rng::new(SEED ^ salt ^ 0x100);
                desc.random_states::<$n>(stringify!($module), SEED ^ salt, STATES)
                    .map(|state| (state, V::from_fn(|_, _| rng.uniform(-5.0, 5.0))))
                    .collect()
            }

            #[test]
            fn jdot_qd_matches_differences_of_the_jacobian() {
                for (state, _) in &states(0x20) {
                    let (q, qd) = (&state.q, &state.qd);
                    let jdot = (jacobian(&(q + qd * H_JACOBIAN))
                        - jacobian(&(q - qd * H_JACOBIAN)))
                        / (2.0 * H_JACOBIAN);
                    let expected = jdot * qd;
                    let got = SVector::<f64, 6>::from(g::jdot_qd(&arr(q), &arr(qd)));
                    let scale =
                        max_abs(&jdot) * qd.amax() + max_abs(&jacobian(q)) * qd.norm_squared();
                    assert_close("Jdot qd", &got, &expected, TOL_JDOT, scale, &state);
                }
            }

            #[test]
            fn mass_matrix_and_bias_is_m_beside_c_plus_g() {
                for (state, _) in &states(0x22) {
                    let (q, qd) = (&state.q, &state.qd);
                    let (qa, qda) = (arr(q), arr(qd));
                    let rows: SMatrix<f64, $n, { $n + 1 }> =
                        mat(&g::mass_matrix_and_bias(&qa, &qda));
                    let m: M = mat(&g::mass_matrix(&qa));
                    let c = V::from(g::coriolis(&qa, &qda));
                    let gr = V::from(g::gravity(&qa));
                    let got_m: M = rows.fixed_columns::<$n>(0).into_owned();
                    let got_b: V = rows.column($n).into_owned();
                    let scale = max_abs(&m);
                    assert_close("M of [M | c + g]", &got_m, &m, TOL_EXACT, scale, &state);
                    let scale = max_abs(&c) + max_abs(&gr);
                    assert_close("c + g", &got_b, &(c + gr), TOL_EXACT, scale, &state);
                }
            }

            #[test]
            fn jacobian_and_position_is_j_beside_the_tool_position() {
                for (state, _) in &states(0x24) {
                    let q = &state.q;
                    let qa = arr(q);
                    let rows: SMatrix<f64, 6, { $n + 1 }> = mat(&g::jacobian_and_position(&qa));
                    let j = jacobian(q);
                    let pose: SMatrix<f64, 4, 4> = mat(&g::end_effector_pose(&qa));
                    let got_j: SMatrix<f64, 6, $n> = rows.fixed_columns::<$n>(0).into_owned();
                    assert_close("J of [J | p; 0]", &got_j, &j, TOL_EXACT, max_abs(&j), &state);
                    let p: SVector<f64, 3> = pose.fixed_view::<3, 1>(0, 3).into_owned();
                    let got_p: SVector<f64, 3> = rows.fixed_view::<3, 1>(0, $n).into_owned();
                    assert_close("p of [J | p; 0]", &got_p, &p, TOL_EXACT, p.amax(), &state);
                    for r in 3..6 {
                        assert_eq!(rows[(r, $n)], 0.0, "row {r} of the last column");
                    }
                }
            }

            #[test]
            fn inverse_dynamics_is_m_qdd_plus_c_plus_g() {
                for (state, qdd) in &states(0x21) {
                    let (q, qd) = (&state.q, &state.qd);
                    let (qa, qda, qdda) = (arr(q), arr(qd), arr(qdd));
                    let m: M = mat(&g::mass_matrix(&qa));
                    let c = V::from(g::coriolis(&qa, &qda));
                    let gr = V::from(g::gravity(&qa));
                    let expected = m * qdd + c + gr;
                    let got = V::from(g::inverse_dynamics(&qa, &qda, &qdda));
                    let scale = max_abs(&m) * qdd.amax() + max_abs(&c) + max_abs(&gr);
                    assert_close(
                        "RNEA vs M qdd + c + g",
                        &got,
                        &expected,
                        TOL_EXACT,
                        scale,
                        &state,
                    );
                }
            }

            #[test]
            $(#[$sp_attr])?
            fn standard_parameters_match_the_description() {
                let desc = load_robot(stringify!($module));
                let expected = desc.standard_parameters();
                let got = g::standard_parameters();
                assert_eq!(got.len(), $p);
                for (k, (a, b)) in got.iter().zip(&expected).enumerate() {
                    assert!(
                        abs_diff_eq!(*a, *b, epsilon = TOL_EXACT * b.abs().max(1.0)),
                        "parameter {k} (link {}, entry {}): generated {a}, description {b}",
                        k / 10 + 1,
                        k % 10
                    );
                }
            }

            #[test]
            fn regressor_times_parameters_is_inverse_dynamics() {
                let params = SVector::<f64, $p>::from(g::standard_parameters());
                for (state, qdd) in &states(0x22) {
                    let (q, qd) = (&state.q, &state.qd);
                    let (qa, qda, qdda) = (arr(q), arr(qd), arr(qdd));
                    let y: SMatrix<f64, $n, $p> = mat(&g::regressor(&qa, &qda, &qdda));
                    let expected = V::from(g::inverse_dynamics(&qa, &qda, &qdda));
                    let scale = max_abs(&y) * params.amax();
                    assert_close(
                        "Y pi vs RNEA",
                        &(y * params),
                        &expected,
                        TOL_EXACT,
                        scale,
                        &state,
                    );
                    // Column k of Y is the parametric inverse dynamics with parameter k alone.
                    if state.index % 16 == 0 {
                        for k in 0..$p {
                            let mut unit = [0.0; $p];
                            unit[k] = 1.0;
                            let column =
                                V::from(g::parametric::inverse_dynamics(&qa, &qda, &qdda, &unit));
                            let col_y: V = y.column(k).into_owned();
                            assert_close(
                                &format!("Y column {k}"),
                                &col_y,
                                &column,
                                TOL_EXACT,
                                max_abs(&column),
                                &state,
                            );
                        }
                    }
                }
            }

            #[test]
            fn parametric_model_at_standard_parameters_is_the_numeric_model() {
                let params = g::standard_parameters();
                for (state, qdd) in &states(0x23) {
                    let (q, qd) = (&state.q, &state.qd);
                    let (qa, qda, qdda) = (arr(q), arr(qd), arr(qdd));
                    let m: M = mat(&g::mass_matrix(&qa));
                    let mp: M = mat(&g::parametric::mass_matrix(&qa, &params));
                    assert_close("parametric M", &mp, &m, TOL_EXACT, max_abs(&m), &state);
                    let c: M = mat(&g::coriolis_matrix(&qa, &qda));
                    let cp: M = mat(&g::parametric::coriolis_matrix(&qa, &qda, &params));
                    let scale = max_abs(&m) * qd.amax();
                    assert_close("parametric C", &cp, &c, TOL_EXACT, scale, &state);
                    let cv = V::from(g::coriolis(&qa, &qda));
                    let cvp = V::from(g::parametric::coriolis(&qa, &qda, &params));
                    assert_close(
                        "parametric c",
                        &cvp,
                        &cv,
                        TOL_EXACT,
                        scale * qd.amax(),
                        &state,
                    );
                    let gr = V::from(g::gravity(&qa));
                    let grp = V::from(g::parametric::gravity(&qa, &params));
                    assert_close("parametric g", &grp, &gr, TOL_EXACT, max_abs(&gr), &state);
                    let tau = V::from(g::inverse_dynamics(&qa, &qda, &qdda));
                    let taup = V::from(g::parametric::inverse_dynamics(&qa, &qda, &qdda, &params));
                    let scale = max_abs(&m) * qdd.amax() + max_abs(&cv) + max_abs(&gr);
                    assert_close("parametric ID", &taup, &tau, TOL_EXACT, scale, &state);
                }
            }

            /// The generated parametric forward dynamics (`L^T D L` with pivots that depend
            /// on `params`) at physical parameter sets other than the description's: every
            /// link's ten parameters scaled by one factor in [0.7, 1.3] (a rigid body of
            /// scaled mass and inertia about the same centre of mass).
            #[test]
            fn parametric_forward_dynamics_equals_cholesky_at_scaled_parameters() {
                let nominal = g::standard_parameters();
                let mut rng = Rng::new(SEED ^ 0x24);
                let sets: Vec<[f64; $p]> = (0..PARAMETER_SETS)
                    .map(|_| {
                        let factors: Vec<f64> = (0..$n).map(|_| rng.uniform(0.7, 1.3)).collect();
                        core::array::from_fn(|k| nominal[k] * factors[k / 10])
                    })
                    .collect();
                let desc = load_robot(stringify!($module));
                for (state, _) in &states(0x24) {
                    let (q, qd) = (&state.q, &state.qd);
                    let (qa, qda) = (arr(q), arr(qd));
                    let tau = V::from_fn(|i, _| rng.uniform(-1.0, 1.0) * desc.joints[i].effort);
                    for (set, params) in sets.iter().enumerate() {
                        let m: M = mat(&g::parametric::mass_matrix(&qa, params));
                        let bias = V::from(g::parametric::coriolis(&qa, &qda, params))
                            + V::from(g::parametric::gravity(&qa, params));
                        let want = Cholesky::new(&m)
                            .unwrap_or_else(|e| panic!("set {set}: M not positive definite at {state}: {e}"))
                            .solve(&(tau - bias));
                        let got = V::from(g::parametric::forward_dynamics(&qa, &qda, &arr(&tau), params));
                        let scale = want.amax().max(1.0);
                        assert!(
                            relative_eq!(got, want, epsilon = TOL_FD * scale, max_relative = TOL_FD),
                            "set {set}: parametric FD {got} vs Cholesky {want} at {state}"
                        );
                        // Inverse dynamics of the same parameters gives the torque back.
                        let back = V::from(g::parametric::inverse_dynamics(&qa, &qda, &arr(&got), params));
                        let scale = max_abs(&tau) + max_abs(&(m * got));
                        assert!(
                            relative_eq!(back, tau, epsilon = TOL_FD * scale, max_relative = TOL_FD),
                            "set {set}: ID(FD(tau)) {back} vs tau {tau} at {state}"
                        );
                    }
                }
            }
        }
    };
}

/// Every robot of the generated registry. Parameters of a DH robot are in the description's
/// own link frames (modified-DH ones too); a URDF robot's are its links lumped per body.
macro_rules! extras_for_every_robot {
    ([] $(($module:ident, $ty:ident, $n:literal, $doc:literal))*) => {
        $( extras!($module, $n, { 10 * $n }); )*
    };
}

armdyn_generated::for_each_robot!(extras_for_every_robot);

/// `Parametric<N, R>`, the sampled plant of sweeps and `[plant]`, solves forward dynamics
/// with the generated parametric function of every robot: the trait method agrees with the
/// Cholesky path of the same model (`forward_dynamics_cholesky`), inverse dynamics gives the
/// torque back, and parameters with a singular `M` give an error, not a value.
fn parametric_forward_dynamics_is_the_generated_one<
    const N: usize,
    R: ::armdyn::model::ParametricModel<N>,
>(
    name: &str,
) {
    use ::armdyn::model::{forward_dynamics_cholesky, ModelError, Parametric, RobotModel};
    type V<const N: usize> = SVector<f64, N>;

    let desc = load_robot(name);
    let nominal = R::standard_parameters();
    let mut rng = Rng::new(SEED ^ 0x25);
    let plants: Vec<Parametric<N, R>> = (0..PARAMETER_SETS)
        .map(|_| {
            let factors: Vec<f64> = (0..N).map(|_| rng.uniform(0.7, 1.3)).collect();
            let mut p = nominal;
            for (k, x) in p.as_mut().iter_mut().enumerate() {
                *x *= factors[k / 10];
            }
            Parametric::new(R::default(), p)
        })
        .collect();
    for state in desc.random_states::<N>(name, SEED ^ 0x26, STATES) {
        let (q, qd) = (state.q, state.qd);
        let tau = V::<N>::from_fn(|i, _| rng.uniform(-1.0, 1.0) * desc.joints[i].effort);
        for (set, plant) in plants.iter().enumerate() {
            let got = plant
                .forward_dynamics(&q, &qd, &tau)
                .unwrap_or_else(|e| panic!("set {set}: forward dynamics failed at {state}: {e}"));
            let generated = R::forward_dynamics_with(&q, &qd, &tau, plant.parameters());
            assert_eq!(
                got, generated,
                "set {set}: the trait method is the generated function"
            );
            let want = forward_dynamics_cholesky(plant, &q, &qd, &tau, &V::<N>::zeros())
                .unwrap_or_else(|e| panic!("set {set}: Cholesky failed at {state}: {e}"));
            let scale = want.amax().max(1.0);
            assert!(
                relative_eq!(got, want, epsilon = TOL_FD * scale, max_relative = TOL_FD),
                "{name} set {set}: parametric FD {got} vs Cholesky {want} at {state}"
            );
            let back = plant.inverse_dynamics(&q, &qd, &got);
            let scale = max_abs(&tau) + max_abs(&(plant.mass_matrix(&q) * got));
            assert!(
                relative_eq!(back, tau, epsilon = TOL_FD * scale, max_relative = TOL_FD),
                "{name} set {set}: ID(FD(tau)) {back} vs tau {tau} at {state}"
            );
        }
    }
    // No mass, no inertia: M = 0, every pivot is zero.
    let (q, qd) = (V::<N>::repeat(0.1), V::<N>::zeros());
    let mut zero = nominal;
    zero.as_mut().fill(0.0);
    match Parametric::new(R::default(), zero).forward_dynamics(&q, &qd, &V::<N>::repeat(1.0)) {
        Err(ModelError::NonFinite { what: "qdd", .. }) => {}
        other => panic!("{name}, singular M: expected a NonFinite error, got {other:?}"),
    }
}

macro_rules! parametric_for_every_robot {
    ([] $(($module:ident, $ty:ident, $n:literal, $doc:literal))*) => {
        #[test]
        fn every_robots_parametric_forward_dynamics_is_the_generated_one() {
            $(parametric_forward_dynamics_is_the_generated_one::<$n, ::armdyn::model::$ty>(stringify!($module));)*
        }
    };
}

armdyn_generated::for_each_robot!(parametric_for_every_robot);
