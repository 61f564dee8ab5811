//! Identification from a recorded log end to end: the shipped simulated Panda log (friction on,
//! 1 % torque noise, jittered and defective sampling) identified with the last 25 % held out
//! gives physically consistent parameters and a held-out RMS torque error within 1.5 times the
//! noise on every joint; a SCARA log simulated here, written as CSV and read back, is identified
//! consistently and far better than the description's nominal model; the description written
//! from a fit carries the identified inertias.

use std::path::Path;

use armdyn::identification::description_out::describe;
use armdyn::identification::excitation::{design, ExcitationLimits, ExcitationSettings};
use armdyn::identification::friction_model::FrictionModel;
use armdyn::identification::from_log::{identify_log, LogIdentification, LogIdentifySettings};
use armdyn::identification::log::{JointLog, LogSettings};
use armdyn::identification::measurement::measure;
use armdyn::identification::sim_log::{defective_log, LogDefects};
use armdyn::identification::{plant_friction, BaseParameters, Identifiable, BASE_STATES};
use armdyn::model::{Panda, RobotModel, Scara};

/// The held-out fraction, as `armdyn identify --log` defaults to.
const HOLDOUT: f64 = 0.25;

fn split<const N: usize>(log: &JointLog<N>) -> (JointLog<N>, JointLog<N>) {
    let (t0, t1) = (log.t[0], log.t[log.len() - 1]);
    let at = t1 - HOLDOUT * (t1 - t0);
    (log.slice_time(t0, at), log.slice_time(at, f64::INFINITY))
}

fn identify<const N: usize, R: Identifiable<N>>(
    robot: &R,
    log: &JointLog<N>,
) -> LogIdentification<N> {
    let (estimation, validation) = split(log);
    identify_log(
        robot,
        &estimation,
        &validation,
        &LogIdentifySettings::default(),
    )
    .unwrap()
}

fn assert_consistent<const N: usize>(id: &LogIdentification<N>) {
    let fit = id.consistent.as_ref().expect("a consistent fit was asked");
    assert_eq!(fit.smallest_eigenvalues.len(), N);
    for (i, e) in fit.smallest_eigenvalues.iter().enumerate() {
        assert!(
            *e > 0.0,
            "link {}: smallest pseudo-inertia eigenvalue {e}",
            i + 1
        );
    }
    for l in 0..N {
        assert!(id.standard[10 * l] > 0.0, "link {}: mass", l + 1);
    }
}

#[test]
fn the_shipped_panda_log_is_identified_within_one_and_a_half_times_its_noise() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("logs/panda_simulated.csv");
    let file = std::fs::File::open(&path).unwrap();
    let (log, report) = JointLog::<7>::from_csv_reader(file, &LogSettings::default()).unwrap();
    // The defects it was made with are found.
    assert!(report.non_finite.count > 0 && report.duplicate_time.count > 0);
    assert!(!report.gaps.is_empty());
    let id = identify(&Panda, &log);
    assert_consistent(&id);
    // The log was made with 1 % noise of each joint's RMS torque (logs/README.md).
    for i in 0..7 {
        let (got, nominal) = (id.error.pct[i], id.error_nominal.pct[i]);
        assert!(got <= 1.5, "joint {}: {got:.2} % held-out error", i + 1);
        assert!(
            got < nominal,
            "joint {}: {got:.2} % vs nominal {nominal:.2} %",
            i + 1
        );
    }
}

/// A SCARA log simulated as `armdyn identify --write-log` makes it, with another seed.
fn simulated_scara_log(seed: u64) -> JointLog<4> {
    let friction = plant_friction(&Scara);
    let base =
        BaseParameters::of_robot(&Scara, Some(friction.smoothing()), BASE_STATES, seed).unwrap();
    let settings = ExcitationSettings {
        evaluations: 300,
        seed,
        ..ExcitationSettings::default()
    };
    let e = design(
        &Scara,
        &base,
        Some(friction.smoothing()),
        &ExcitationLimits::default_for::<Scara>(),
        &settings,
    );
    let m = measure(&Scara, Some(friction), &e.trajectory, 1, 1.0, seed + 1).unwrap();
    defective_log(&m, &LogDefects::default(), seed + 4)
}

#[test]
fn a_simulated_scara_log_round_trips_through_csv_and_is_identified_consistently() {
    let log = simulated_scara_log(11);
    let mut csv = Vec::new();
    log.write_csv(&mut csv).unwrap();
    let (read, report) = JointLog::<4>::from_csv_reader(&csv[..], &LogSettings::default()).unwrap();
    // NaN rows and duplicated stamps are dropped; the rest is read back as written.
    assert!(report.non_finite.count > 0);
    assert_eq!(
        read.len() + report.non_finite.count + report.duplicate_time.count,
        log.len()
    );
    let id = identify(&Scara, &read);
    assert_consistent(&id);
    for i in 0..4 {
        let (got, nominal) = (id.error.pct[i], id.error_nominal.pct[i]);
        // A tenth of the nominal model's error at most, and a few times the 1 % noise: the
        // SCARA's last joint carries 0.01 N m, where friction-model and resolution errors show.
        assert!(
            got < 0.1 * nominal,
            "joint {}: {got:.2} % vs nominal {nominal:.2} %",
            i + 1
        );
        assert!(got < 4.0, "joint {}: {got:.2} %", i + 1);
    }
    // The friction fitted is the plant's kind: viscous and Coulomb coefficients positive.
    assert_eq!(id.settings.friction, FrictionModel::Smooth);
    assert!(
        id.friction.iter().take(8).all(|f| *f > 0.0),
        "{:?}",
        id.friction
    );
}

#[test]
fn the_written_description_carries_the_identified_inertias() {
    // As written the log holds duplicated stamps, which processing refuses: the reader drops
    // them.
    let log = simulated_scara_log(5);
    let (estimation, validation) = split(&log);
    let err = identify_log(
        &Scara,
        &estimation,
        &validation,
        &LogIdentifySettings::default(),
    )
    .unwrap_err()
    .to_string();
    assert!(err.contains("is not after the previous one"), "{err}");
    let mut csv = Vec::new();
    log.write_csv(&mut csv).unwrap();
    let (log, _) = JointLog::<4>::from_csv_reader(&csv[..], &LogSettings::default()).unwrap();
    let id = identify(&Scara, &log);
    let urdf = armdyn_generated::scara::URDF;
    let d = describe(
        &Scara,
        urdf,
        "scara_identified",
        id.standard.as_slice(),
        None,
        "test",
    )
    .unwrap();
    assert!(d.toml.contains("convention = \"urdf\""), "{}", d.toml);
    assert!(d.toml.contains("scara_identified.urdf"), "{}", d.toml);
    let parsed = urdf_rs::read_from_string(&d.urdf).unwrap();
    // Every moving link's mass is the identified one (the generator reads them from here).
    let masses: Vec<f64> = (0..Scara::DOF).map(|l| id.standard[10 * l]).collect();
    for m in masses {
        assert!(
            parsed
                .links
                .iter()
                .any(|l| (l.inertial.mass.value - m).abs() <= 1e-12 * m.abs().max(1.0)),
            "no link with mass {m}"
        );
    }
    // A bad name is refused, naming it.
    let err = describe(&Scara, urdf, "Scara-2", id.standard.as_slice(), None, "")
        .unwrap_err()
        .to_string();
    assert!(err.contains("Scara-2"), "{err}");
}
