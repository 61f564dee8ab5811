//! The SCARA against the thesis (McDonald 2022, Section 3.3) and `docs/thesis.md` sections 1–2:
//! the numeric mass matrix of eq. 3.67 to its printed digits and at the parameter level,
//! the correct velocity term (not the thesis's printed C, eq. 3.61–3.64/3.68), the gravity
//! vector of eq. 3.68, and the forward-kinematics checks of section 1.

use crate::common;

use approx::{abs_diff_eq, assert_abs_diff_eq};
use armdyn::model::{RobotModel, Scara};
use common::{assert_close, load_robot, max_abs, Rng, Robot, SEED, STATES};
use nalgebra::{Matrix4, SVector, Vector4};

/// Generated values vs. closed forms of the same parameters: only rounding separates them.
const TOL_EXACT: f64 = 1e-12;

type V4 = SVector<f64, 4>;

/// Parameter-level constants of the SCARA's dynamics, from `robots/scara.toml`.
struct ScaraParams {
    /// `M11 = a + 2 h c2`.
    a: f64,
    /// `M12 = b + h c2`, `M22 = b`.
    b: f64,
    /// `h = l1 (m2 lc2 + (m3 + m4) l2)`, lc2 the COM of link 2 from joint 2.
    h: f64,
    /// `m3 + m4`, the mass carried by the prismatic joint.
    m34: f64,
    /// Izz of link 4.
    izz4: f64,
    /// Gravity along z (negative: down).
    gz: f64,
}

fn params(desc: &Robot) -> ScaraParams {
    let j = &desc.joints;
    let (l1, l2) = (j[0].a, j[1].a);
    let lc1 = l1 + j[0].com.x; // COM of link 1 from the joint-1 axis
    let lc2 = l2 + j[1].com.x; // COM of link 2 from the joint-2 axis
    let (m1, m2, m34) = (j[0].mass, j[1].mass, j[2].mass + j[3].mass);
    let izz: Vec<f64> = j.iter().map(|joint| joint.inertia[(2, 2)]).collect();
    // Links 3 and 4 have their COMs on the joint-3/4 axis.
    assert_eq!(
        (j[2].com.x, j[2].com.y, j[3].com.x, j[3].com.y),
        (0.0, 0.0, 0.0, 0.0)
    );
    let vertical = izz[1] + izz[2] + izz[3];
    ScaraParams {
        a: izz[0]
            + m1 * lc1 * lc1
            + vertical
            + m2 * (l1 * l1 + lc2 * lc2)
            + m34 * (l1 * l1 + l2 * l2),
        b: vertical + m2 * lc2 * lc2 + m34 * l2 * l2,
        h: l1 * (m2 * lc2 + m34 * l2),
        m34,
        izz4: izz[3],
        gz: desc.gravity.z,
    }
}

fn round_to(x: f64, decimals: i32) -> f64 {
    let scale = 10f64.powi(decimals);
    (x * scale).round() / scale
}

/// Eq. 3.67 as printed: `(constant, coefficient of cos q2, decimals printed)` per entry.
#[rustfmt::skip]
const THESIS_M: [[(f64, f64, i32); 4]; 4] = [
    [(3.23, 2.34, 2), (1.12, 1.17, 2), (0.0, 0.0, 2), (-0.0025, 0.0, 4)],
    [(1.12, 1.17, 2), (1.12, 0.0, 2), (0.0, 0.0, 2), (-0.0025, 0.0, 4)],
    [(0.0, 0.0, 2), (0.0, 0.0, 2), (4.94, 0.0, 2), (0.0, 0.0, 4)],
    [(-0.0025, 0.0, 4), (-0.0025, 0.0, 4), (0.0, 0.0, 4), (0.0025, 0.0, 4)],
];

#[test]
fn mass_matrix_matches_eq_3_67_to_printed_digits() {
    // M = K + L cos q2: K at q2 = pi/2, L = M(q2 = 0) - K; the other joints do not enter.
    let k = Scara.mass_matrix(&V4::new(0.3, core::f64::consts::FRAC_PI_2, 0.2, -0.7));
    let l = Scara.mass_matrix(&V4::new(-0.5, 0.0, 0.3, 1.1)) - k;
    for r in 0..4 {
        for c in 0..4 {
            let (constant, coefficient, decimals) = THESIS_M[r][c];
            let got = (round_to(k[(r, c)], decimals), round_to(l[(r, c)], decimals));
            assert!(
                abs_diff_eq!(got.0, constant, epsilon = 1e-12)
                    && abs_diff_eq!(got.1, coefficient, epsilon = 1e-12),
                "M[{r}][{c}] = {} + {} c2 rounds to {got:?}, thesis prints {constant} + {coefficient} c2",
                k[(r, c)],
                l[(r, c)]
            );
        }
    }
    // The structure K + L c2 holds at every state.
    let desc = load_robot("scara");
    for state in desc.random_states::<4>("scara", SEED ^ 0x10, STATES) {
        let q = state.q;
        let expected = k + l * q[1].cos();
        assert_close(
            "M = K + L c2",
            &Scara.mass_matrix(&q),
            &expected,
            TOL_EXACT,
            max_abs(&expected),
            &state,
        );
    }
}

#[test]
fn mass_matrix_matches_parameter_level_closed_form() {
    let desc = load_robot("scara");
    let p = params(&desc);
    // The printed numbers, from the parameters: a = 3.22955, b = 1.121436, h = 1.168448.
    assert_eq!(round_to(p.a, 2), 3.23);
    assert_eq!(round_to(2.0 * p.h, 2), 2.34);
    assert_eq!(round_to(p.b, 2), 1.12);
    assert_eq!(round_to(p.h, 2), 1.17);
    for state in desc.random_states::<4>("scara", SEED ^ 0x11, STATES) {
        let q = state.q;
        let c2 = q[1].cos();
        #[rustfmt::skip]
        let expected = Matrix4::new(
            p.a + 2.0 * p.h * c2, p.b + p.h * c2, 0.0, -p.izz4,
            p.b + p.h * c2, p.b, 0.0, -p.izz4,
            0.0, 0.0, p.m34, 0.0,
            -p.izz4, -p.izz4, 0.0, p.izz4,
        );
        assert_close(
            "M vs closed form",
            &Scara.mass_matrix(&q),
            &expected,
            TOL_EXACT,
            max_abs(&expected),
            &state,
        );
    }
}

#[test]
fn velocity_term_matches_spec_not_printed_thesis() {
    let desc = load_robot("scara");
    let p = params(&desc);
    // docs/thesis.md section 2: h = 1.1685 (rounded from 1.168448; within its last printed digit).
    assert_abs_diff_eq!(p.h, 1.1685, epsilon = 1e-4);
    for state in desc.random_states::<4>("scara", SEED ^ 0x12, STATES) {
        let (q, qd) = (state.q, state.qd);
        let s2 = q[1].sin();
        let expected = V4::new(
            -p.h * s2 * (2.0 * qd[0] * qd[1] + qd[1] * qd[1]),
            p.h * s2 * qd[0] * qd[0],
            0.0,
            0.0,
        );
        let got = Scara.coriolis(&q, &qd);
        let scale = p.h * qd.amax() * qd.amax();
        assert_close(
            "c vs docs/thesis.md",
            &got,
            &expected,
            TOL_EXACT,
            scale,
            &state,
        );
    }
}

#[test]
fn velocity_term_is_not_the_thesis_printed_c() {
    // Thesis eq. 3.68 / Simulink: C1 = 0, C2 = 1.17 qd1 (qd1 + qd2) s2 (docs/thesis.md, erratum 1).
    let printed =
        |q: &V4, qd: &V4| V4::new(0.0, 1.17 * qd[0] * (qd[0] + qd[1]) * q[1].sin(), 0.0, 0.0);
    let q = V4::new(0.2, 1.0, 0.2, 0.0);
    let qd = V4::new(1.0, 1.0, 0.0, 0.0);
    let ours = Scara.coriolis(&q, &qd);
    let theirs = printed(&q, &qd);
    // Ours: c1 = -3 h s2 = -2.95, c2 = h s2 = 0.98; printed: c1 = 0, c2 = 2.34 s2 = 1.97.
    assert!(
        (ours[0] - theirs[0]).abs() > 2.0,
        "c1: ours {} printed {}",
        ours[0],
        theirs[0]
    );
    assert!(
        (ours[1] - theirs[1]).abs() > 0.5,
        "c2: ours {} printed {}",
        ours[1],
        theirs[1]
    );
    // At random states (q2 within its limits, qd in [-2, 2]) the two differ almost always.
    let desc = load_robot("scara");
    let differing = desc
        .random_states::<4>("scara", SEED ^ 0x13, STATES)
        .filter(|s| (Scara.coriolis(&s.q, &s.qd) - printed(&s.q, &s.qd)).amax() > 1e-2)
        .count();
    assert!(
        differing > STATES * 3 / 4,
        "only {differing} of {STATES} states differ"
    );
}

#[test]
fn gravity_matches_eq_3_68() {
    let desc = load_robot("scara");
    let p = params(&desc);
    assert_abs_diff_eq!(p.gz * p.m34, -48.412, epsilon = 1e-12);
    for state in desc.random_states::<4>("scara", SEED ^ 0x14, STATES) {
        let q = state.q;
        let g = Scara.gravity(&q);
        assert_close(
            "g vs eq. 3.68",
            &g,
            &V4::new(0.0, 0.0, -48.412, 0.0),
            TOL_EXACT,
            48.412,
            &state,
        );
        assert_eq!(round_to(g[2], 1), -48.4);
    }
}

#[test]
fn end_effector_at_zero_is_thesis_check() {
    let pose = Scara.end_effector_pose(&V4::zeros());
    #[rustfmt::skip]
    let expected = Matrix4::new(
        1.0, 0.0, 0.0, 0.8,
        0.0, -1.0, 0.0, 0.0,
        0.0, 0.0, -1.0, 0.35,
        0.0, 0.0, 0.0, 1.0,
    );
    assert_close(
        "end effector at q = 0",
        &pose,
        &expected,
        TOL_EXACT,
        1.0,
        &"robot scara at q = 0",
    );
}

#[test]
fn end_effector_yaw_and_height_match_spec() {
    // docs/thesis.md section 1: yaw phi = q1 + q2 - q4, z_E = l0 - l4 - d3, tool pointing down.
    let desc = load_robot("scara");
    let (l0, l4) = (desc.joints[0].d, desc.joints[3].d);
    for state in desc.random_states::<4>("scara", SEED ^ 0x15, STATES) {
        let q = state.q;
        let pose = Scara.end_effector_pose(&q);
        let phi = q[0] + q[1] - q[3];
        let (s, c) = phi.sin_cos();
        #[rustfmt::skip]
        let rotation = Matrix4::new(
            c, s, 0.0, 0.0,
            s, -c, 0.0, 0.0,
            0.0, 0.0, -1.0, 0.0,
            0.0, 0.0, 0.0, 1.0,
        );
        let mut got = pose;
        got.set_column(3, &Vector4::new(0.0, 0.0, 0.0, 1.0));
        assert_close("tool orientation", &got, &rotation, TOL_EXACT, 1.0, &state);
        assert!(
            abs_diff_eq!(pose[(2, 3)], l0 - l4 - q[2], epsilon = TOL_EXACT),
            "z_E at {state}"
        );
    }
}

#[test]
fn modified_dh_description_is_the_same_robot() {
    // robots/scara_mdh.toml describes the same arm in modified DH: the end effector, its
    // Jacobian and all the dynamics agree; only the intermediate frames differ.
    use armdyn::model::ScaraMdh;
    let desc = load_robot("scara");
    // The inputs beside each state, from a seed of their own.
    let mut rng = Rng::new(SEED ^ 0x16 ^ 0x100);
    for state in desc.random_states::<4>("scara vs scara_mdh", SEED ^ 0x16, STATES) {
        let (q, qd) = (state.q, state.qd);
        let qdd = V4::from_fn(|_, _| rng.uniform(-5.0, 5.0));
        let pairs = [
            (
                "pose",
                Scara.end_effector_pose(&q),
                ScaraMdh.end_effector_pose(&q),
            ),
            ("M", Scara.mass_matrix(&q), ScaraMdh.mass_matrix(&q)),
            (
                "C",
                Scara.coriolis_matrix(&q, &qd),
                ScaraMdh.coriolis_matrix(&q, &qd),
            ),
        ];
        for (what, a, b) in pairs {
            assert_close(what, &b, &a, TOL_EXACT, max_abs(&a), &state);
        }
        let j = Scara.jacobian(&q);
        assert_close(
            "J",
            &ScaraMdh.jacobian(&q),
            &j,
            TOL_EXACT,
            max_abs(&j),
            &state,
        );
        let vectors = [
            ("c", Scara.coriolis(&q, &qd), ScaraMdh.coriolis(&q, &qd)),
            ("g", Scara.gravity(&q), ScaraMdh.gravity(&q)),
            (
                "ID",
                Scara.inverse_dynamics(&q, &qd, &qdd),
                ScaraMdh.inverse_dynamics(&q, &qd, &qdd),
            ),
        ];
        for (what, a, b) in vectors {
            assert_close(what, &b, &a, TOL_EXACT, max_abs(&a).max(10.0), &state);
        }
        let a = Scara.jdot_qd(&q, &qd);
        assert_close(
            "Jdot qd",
            &ScaraMdh.jdot_qd(&q, &qd),
            &a,
            TOL_EXACT,
            max_abs(&a),
            &state,
        );
    }
}
