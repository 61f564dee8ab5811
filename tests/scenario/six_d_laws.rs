//! The four force laws (`pi-ff-vd` with the thesis's and with designed gains, impedance,
//! admittance) in the full task frame on six- and seven-joint arms, on generated planes: each
//! holds the tool axis along the normal and a redundant arm's posture; the admittance reaches
//! the force whatever the surface's height; the impedance, which feeds no force back, is off
//! by exactly the series stiffness of its spring and the contact times the height error.

use std::path::Path;

use armdyn::scenario::{execute, prepare, LawChoice, Outcome, Scenario};
use armdyn::target::orientation;
use nalgebra::{UnitQuaternion, Vector3};

use super::six_d::{alignment, contact, plane_task, saturated};

/// `text` run with the force law `law` (`--force-law`'s syntax).
fn run_with(text: &str, law: &str) -> Outcome {
    let mut s = Scenario::parse("generated.toml", text, Path::new("."))
        .unwrap_or_else(|e| panic!("{e}\n{text}"));
    LawChoice::parse(law).unwrap().apply(&mut s).unwrap();
    execute(&s, prepare(&s).unwrap(), |_| {}).unwrap()
}

/// The impedance's normal stiffness (the default of `[force.impedance]`), N/m, and the
/// generated planes' contact stiffness.
const K_N: f64 = 2000.0;
const K_C: f64 = 10_000.0;

/// Every law on the plane of `text` (really `offset` m above the believed one): the tool
/// along the normal, no saturation, no loss of contact, and each law's force at rest.
fn four_laws(text: &str, offset: f64, what: &str) -> Vec<Outcome> {
    let mut out = Vec::new();
    for law in [
        "pi-ff-vd:thesis",
        "pi-ff-vd:design",
        "impedance",
        "admittance",
    ] {
        let r = run_with(text, law);
        let c = contact(&r);
        let a = alignment(&r);
        let what = format!("{what}, {law}");
        assert!(c.force_start_s.is_some(), "{what}: {c:?}");
        assert_eq!(c.contact_losses, 0, "{what}: {c:?}");
        assert!(a.rms_deg <= 0.5, "{what}: {a:?}");
        assert_eq!(saturated(&r), 0, "{what}");
        if let Some(p) = r.posture {
            assert!(p.max_rad <= 0.05, "{what}: {p:?}");
        }
        let steady = c.normal_force_steady_error_n;
        if law == "impedance" {
            // Positive: pressing harder than asked, the surface being higher than believed.
            let expected = offset * K_N * K_C / (K_N + K_C);
            assert!(
                (steady - expected).abs() <= 0.05 * expected.abs() + 0.05,
                "{what}: steady-state error {steady} N, the series spring gives {expected} N"
            );
        } else {
            assert!(steady.abs() <= 0.1, "{what}: {c:?}");
            assert!(c.normal_force_rms_error_last3s_n <= 0.5, "{what}: {c:?}");
        }
        out.push(r);
    }
    out
}

#[test]
fn the_four_laws_run_on_the_ur5_on_a_tilted_plane() {
    let down = orientation::from_rpy(0.0, core::f64::consts::FRAC_PI_2, 0.0);
    let n = UnitQuaternion::from_scaled_axis(Vector3::new(1.0, -1.0, 0.0).normalize() * 0.3)
        * Vector3::z();
    let offset = 0.004;
    let text = plane_task(
        "ur5",
        "seed = [0.0, -1.5708, 1.5708, -1.5708, -1.5708, 0.0]",
        down,
        Vector3::x(),
        Vector3::new(0.42, 0.05, 0.24),
        n,
        Vector3::new(1.0, 1.0, 0.0),
        0.15,
        3.0,
        25.0,
        offset,
    );
    let runs = four_laws(&text, offset, "UR5, 17 degrees");
    assert_eq!(runs[2].controller_name, "task-space-impedance");
    assert_eq!(runs[3].controller_name, "task-space-admittance");
}

#[test]
fn the_four_laws_run_on_the_panda_and_hold_its_posture() {
    let down = orientation::from_rpy(core::f64::consts::PI, 0.0, 0.0);
    let n = UnitQuaternion::from_scaled_axis(Vector3::y() * (-10f64).to_radians()) * Vector3::z();
    let offset = -0.003;
    let text = plane_task(
        "panda",
        "posture = [0.0, -0.7853981633974483, 0.0, -2.356194490192345, 0.0, 1.5707963267948966, 0.7853981633974483]",
        down,
        Vector3::z(),
        Vector3::new(0.38, -0.05, 0.38),
        n,
        Vector3::y(),
        0.12,
        3.0,
        18.0,
        offset,
    );
    let runs = four_laws(&text, offset, "Panda, 10 degrees");
    assert!(runs.iter().all(|r| r.posture.is_some()));
}

#[test]
fn the_force_design_uses_each_arms_apparent_mass_at_its_contact_pose() {
    // `gains = "design"` and `design force --scenario` on the UR5 and the Panda: the apparent
    // mass along the normal at the contact pose is 1 / (n^T J M^-1 J^T n) at those joints,
    // computed here from the model directly (the Cholesky factor of M, the linear rows of J).
    use armdyn::model::{Panda, RobotModel, Ur5};
    use armdyn::scenario::contact_model;
    fn direct<const N: usize, R: RobotModel<N>>(robot: R, q: &[f64], n: &Vector3<f64>) -> f64 {
        let q = nalgebra::SVector::<f64, N>::from_column_slice(q);
        let j = robot.jacobian(&q);
        let c = nalgebra::SVector::<f64, N>::from_fn(|i, _| {
            n.x * j[(0, i)] + n.y * j[(1, i)] + n.z * j[(2, i)]
        });
        1.0 / c.dot(&robot.mass_matrix(&q).cholesky().unwrap().solve(&c))
    }
    let root = super::six_d::root().join("scenarios");
    for file in [
        "ur5-press-table.toml",
        "ur5-oblique.toml",
        "panda-wipe.toml",
        "panda-cylinder.toml",
    ] {
        let s = Scenario::load(&root.join(file)).unwrap();
        let m = contact_model(&s).unwrap();
        let expected = if file.starts_with("ur5") {
            direct(Ur5, &m.q, &m.normal)
        } else {
            direct(Panda, &m.q, &m.normal)
        };
        assert!(
            (m.mass_kg - expected).abs() <= 1e-9 * expected,
            "{file}: {} kg vs {expected} kg",
            m.mass_kg
        );
        assert!(m.mass_kg > 0.5 && m.mass_kg < 50.0, "{file}: {}", m.mass_kg);
    }
}
