//! The shipped contact scenarios meet what each must show (ideal sensor, 1 ms controller and
//! plant), the unknown-height one also with the surface lower than assumed, friction acts as
//! Coulomb's law says, and end stops hold a diverging law.

use std::path::PathBuf;

use approx::abs_diff_eq;
use armdyn::contact::{Scene, SurfaceGeometry, FRICTION_REGULARISATION_SPEED};
use armdyn::metrics::ContactSummary;
use armdyn::model::{RobotModel, Scara};
use armdyn::scenario::{
    execute, prepare, prepare_for, ForceController, Outcome, Recorded, Scenario,
};
use nalgebra::Vector3;

fn load(file: &str) -> Scenario {
    Scenario::load(
        &PathBuf::from(env!("CARGO_MANIFEST_DIR"))
            .join("scenarios")
            .join(file),
    )
    .unwrap()
}

fn run(s: &Scenario) -> Outcome {
    execute(s, prepare(s).unwrap(), |_| {}).unwrap()
}

/// [`run`] with every sample (the SCARA's scenarios).
fn recorded(s: &Scenario) -> Recorded<4> {
    prepare_for(s, Scara).unwrap().execute(s, |_| {}).unwrap()
}

fn contact(r: &Outcome) -> ContactSummary {
    r.contact.expect("contact metrics")
}

fn saturated(r: &Outcome) -> usize {
    r.stats.saturated_samples.iter().sum()
}

#[test]
fn oblique_plane_meets_its_bar() {
    let Recorded {
        outcome: r,
        samples,
    } = recorded(&load("oblique-plane.toml"));
    let c = contact(&r);
    assert!(c.normal_force_overshoot_pct <= 5.0, "{c:?}");
    assert!(
        c.normal_force_settling_time_s.is_some_and(|t| t <= 0.1),
        "{c:?}"
    );
    assert!(c.normal_force_rms_error_last5s_n <= 2.0, "{c:?}");
    assert!(c.path_rms_error_contact_mm <= 2.0, "{c:?}");
    // The force is along the tilted normal: the tool pushes in -x as well as -z.
    let last = samples.last().unwrap();
    let a = 20_f64.to_radians();
    assert!(
        abs_diff_eq!(last.wrench[0] / last.wrench[2], a.tan(), epsilon = 1e-9),
        "{}",
        last.wrench
    );
}

#[test]
fn sphere_patch_holds_the_force_and_never_loses_contact() {
    let Recorded {
        outcome: r,
        samples,
    } = recorded(&load("sphere-patch.toml"));
    let c = contact(&r);
    assert!(c.normal_force_rms_error_last5s_n <= 3.0, "{c:?}");
    assert_eq!(c.contact_losses, 0, "{c:?}");
    // The task frame followed the surface: at the end the normal is tilted about 17 degrees.
    let last = samples.last().unwrap();
    let f = Vector3::new(last.wrench[0], last.wrench[1], last.wrench[2]);
    let n = (last.position - Vector3::new(0.5, 0.0, -0.87)).normalize();
    assert!(f.normalize().dot(&-n) > 0.999_99, "{f} vs {n}");
    assert!(n.y > 0.25, "{n}");
}

/// A shape added as one file (`src/surface/torus.rs`) runs from a scenario file: the Panda's
/// cylinder given as a pipe bend of 100 m whose tube, where the tool goes round it, is that
/// cylinder (the bend's circle crosses the tool's plane x = 0.35 at right angles there) gives
/// the cylinder's run (its contact metrics to 1e-6 N and mm; measured: 3e-8 at most).
#[test]
fn a_pipe_bend_where_the_tool_goes_round_it_is_the_cylinder() {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("scenarios");
    let text = std::fs::read_to_string(dir.join("panda-cylinder.toml")).unwrap();
    let cylinder =
        "kind = \"cylinder\"\npoint = [0.35, 0.0, 0.25]\naxis = [1.0, 0.0, 0.0]\nradius = 0.15";
    let bend = "kind = \"torus\"\npoint = [0.35, -100.0, 0.25]\naxis = [0.0, 0.0, 1.0]\nradius = 100.0\ntube_radius = 0.15";
    assert!(text.contains(cylinder));
    let run_text = |t: &str| run(&Scenario::parse("bend.toml", t, &dir).unwrap());
    let (a, b) = (run_text(&text), run_text(&text.replace(cylinder, bend)));
    let (a, b) = (contact(&a), contact(&b));
    assert_eq!(b.contact_losses, 0, "{b:?}");
    assert!(
        abs_diff_eq!(
            a.first_touch_s.unwrap(),
            b.first_touch_s.unwrap(),
            epsilon = 1e-9
        ),
        "{a:?}\n{b:?}"
    );
    for (x, y, tol) in [
        (
            a.normal_force_rms_error_last5s_n,
            b.normal_force_rms_error_last5s_n,
            1e-6,
        ),
        (a.peak_normal_force_n, b.peak_normal_force_n, 1e-6),
        (
            a.path_rms_error_contact_mm,
            b.path_rms_error_contact_mm,
            1e-6,
        ),
        (
            a.normal_force_steady_error_n,
            b.normal_force_steady_error_n,
            1e-6,
        ),
    ] {
        assert!(
            abs_diff_eq!(x, y, epsilon = tol),
            "{x} vs {y}\n{a:?}\n{b:?}"
        );
    }
}

#[test]
fn friction_is_coulomb_while_sliding_and_the_feedforward_halves_the_path_error() {
    let s = load("friction.toml");
    let with = recorded(&s);
    let mut checked = 0;
    let scene = Scene::new(&s.surfaces).unwrap();
    for x in &with.samples {
        let v = (Scara.jacobian(&x.q) * x.qd)
            .fixed_rows::<3>(0)
            .into_owned();
        let (_, state) = scene.nearest(&x.position, &v).unwrap();
        let n = state.closest.normal;
        let vt = v - n * n.dot(&v);
        if state.normal_force > 0.0 && vt.norm() >= FRICTION_REGULARISATION_SPEED {
            let f = Vector3::new(x.wrench[0], x.wrench[1], x.wrench[2]);
            let fn_ = -n.dot(&f);
            let ft = f + n * fn_;
            assert!(
                abs_diff_eq!(ft.norm(), 0.2 * fn_, epsilon = 1e-9 * fn_),
                "t = {}: {ft} vs {fn_}",
                x.t
            );
            // Against the sliding: the tool drags the surface along its own motion.
            assert!(ft.dot(&vt) > 0.0);
            checked += 1;
        }
    }
    assert!(checked > 7000, "only {checked} sliding samples");
    let mut without = s.clone();
    without.force.as_mut().unwrap().friction_feedforward = 0.0;
    let without = run(&without);
    let (a, b) = (
        contact(&with.outcome).path_rms_error_contact_mm,
        contact(&without).path_rms_error_contact_mm,
    );
    assert!(
        a <= 0.5 * b,
        "path RMS in contact: {a} mm with the feedforward, {b} mm without"
    );
}

#[test]
fn unknown_height_is_found_by_contact_switching_without_saturation() {
    let r = run(&load("unknown-height.toml"));
    let c = contact(&r);
    assert!(c.normal_force_overshoot_pct <= 5.0, "{c:?}");
    let (touch, detected) = (c.first_touch_s.unwrap(), c.force_start_s.unwrap());
    assert!(
        detected - touch <= 0.010 + 1e-9,
        "touch {touch} s, detected {detected} s"
    );
    assert!(
        touch < 1.95,
        "the higher surface is touched before the 2 s of the reference"
    );
    assert_eq!(saturated(&r), 0);
}

#[test]
fn a_surface_lower_than_assumed_is_found_by_the_approach() {
    let mut s = load("unknown-height.toml");
    let surface = &mut s.surfaces[0];
    surface.geometry =
        SurfaceGeometry::plane(Vector3::new(0.4, 0.0, 0.125), Vector3::z(), [0.2, 0.4]);
    s.force.as_mut().unwrap().expected_shift_m = 0.005;
    let r = run(&s);
    let c = contact(&r);
    let touch = c.first_touch_s.expect("touched");
    assert!(
        touch > 2.0,
        "the reference reaches the expected height at 2 s, the surface later"
    );
    let detected = c.force_start_s.expect("detected");
    assert!(detected - touch <= 0.010 + 1e-9, "{c:?}");
    assert!(c.normal_force_overshoot_pct <= 5.0, "{c:?}");
    assert!(c.normal_force_rms_error_last5s_n <= 2.0, "{c:?}");
    assert_eq!(saturated(&r), 0);
}

#[test]
fn end_stops_hold_a_diverging_force_law() {
    // PI + feedforward without damping diverges at 1 ms (docs/control.md): without end stops it
    // drives d3 metres past its 0.35 m limit.
    let mut s = load("thesis-hybrid.toml");
    let f = s.force.as_mut().unwrap();
    f.law = ForceController::PiFf;
    f.gains = ForceController::PiFf.thesis_gains();
    // The end stops are what is judged: unsupervised (supervised, the divergence trips and
    // holds long before d3's limit; tests/control/force_design.rs).
    s.safety.enabled = false;
    let free = recorded(&s);
    let worst = |r: &Recorded<4>| r.samples.iter().map(|x| x.q[2]).fold(f64::MIN, f64::max);
    assert!(
        worst(&free) > 1.0,
        "d3 reached only {} m without end stops",
        worst(&free)
    );
    s.end_stops = true;
    s.q0 = Some(vec![0.0, 0.0, 0.1, 0.0]);
    let held = recorded(&s);
    assert!(
        worst(&held) < 0.36,
        "d3 reached {} m with end stops",
        worst(&held)
    );
    assert!(held.outcome.stats.end_stop_samples[2] > 0);
}
