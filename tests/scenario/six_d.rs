//! Force control on six- and seven-joint arms in the full task frame: the shipped UR5 and
//! Panda contact files meet what each must show, and so do tables, tilted planes, heights,
//! lines and forces other than the shipped ones (generated here), with the tool held along
//! the normal and a redundant arm's posture held in the null space.

use std::path::{Path, PathBuf};

use crate::scratch::Scratch;

use armdyn::metrics::{AlignmentSummary, ContactSummary};
use armdyn::model::{Panda, Ur5};
use armdyn::scenario::{execute, prepare, prepare_for, Outcome, Recorded, Scenario, ScenarioRobot};
use armdyn::target::orientation;
use nalgebra::{UnitQuaternion, Vector3};

pub(crate) fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn load_file(file: &str) -> Scenario {
    Scenario::load(&root().join("scenarios").join(file)).unwrap()
}

fn parse_text(name: &str, text: &str) -> Scenario {
    Scenario::parse(name, text, Path::new(".")).unwrap_or_else(|e| panic!("{e}\n{text}"))
}

fn run_file(file: &str) -> Outcome {
    let s = load_file(file);
    execute(&s, prepare(&s).unwrap(), |_| {}).unwrap()
}

fn run_text(name: &str, text: &str) -> Outcome {
    let s = parse_text(name, text);
    execute(&s, prepare(&s).unwrap(), |_| {}).unwrap()
}

/// A run of `s` on its robot `robot`, with every sample.
pub(crate) fn recorded<const N: usize, R: ScenarioRobot<N>>(s: &Scenario, robot: R) -> Recorded<N> {
    prepare_for(s, robot).unwrap().execute(s, |_| {}).unwrap()
}

pub(crate) fn contact(r: &Outcome) -> ContactSummary {
    r.contact.expect("contact metrics")
}

pub(crate) fn alignment(r: &Outcome) -> AlignmentSummary {
    let a = r.alignment.expect("the tool axis is held to the normal");
    assert!(a.samples > 1000, "{a:?}");
    a
}

pub(crate) fn saturated(r: &Outcome) -> usize {
    r.stats.saturated_samples.iter().sum()
}

fn end_stops(r: &Outcome) -> usize {
    r.stats.end_stop_samples.iter().sum()
}

/// The bars of `ur5-press-table.toml` and `ur5-oblique.toml`.
fn ur5_bars(r: &Outcome, what: &str) {
    let c = contact(r);
    let a = alignment(r);
    assert!(c.force_start_s.is_some(), "{what}: {c:?}");
    assert!(c.normal_force_overshoot_pct <= 5.0, "{what}: {c:?}");
    assert!(c.normal_force_rms_error_last3s_n <= 0.5, "{what}: {c:?}");
    assert!(c.path_rms_error_contact_mm <= 1.0, "{what}: {c:?}");
    assert_eq!(c.contact_losses, 0, "{what}: {c:?}");
    assert!(a.rms_deg <= 0.5, "{what}: {a:?}");
    assert_eq!(saturated(r), 0, "{what}");
    assert_eq!(end_stops(r), 0, "{what}");
}

#[test]
fn ur5_presses_on_a_table_and_on_a_tilted_plane() {
    for file in ["ur5-press-table.toml", "ur5-oblique.toml"] {
        let r = run_file(file);
        ur5_bars(&r, file);
        assert_eq!(r.controller_name, "task-space-hybrid-pi-ff-vd");
    }
}

#[test]
fn panda_wipes_with_friction_and_holds_its_posture() {
    let r = run_file("panda-wipe.toml");
    let c = contact(&r);
    assert!(c.normal_force_rms_error_last5s_n <= 0.5, "{c:?}");
    assert!(c.path_rms_error_contact_mm <= 1.5, "{c:?}");
    // The friction was there to overcome: 0.3 of 15 N.
    assert!(c.max_tangential_force_n > 4.0, "{c:?}");
    let p = r
        .posture
        .expect("a redundant arm reports its posture error");
    assert!(p.max_rad <= 0.05, "{p:?}");
    assert_eq!(saturated(&r), 0);
    alignment(&r);
}

#[test]
fn panda_goes_round_a_cylinder_with_the_tool_normal_to_it() {
    let Recorded {
        outcome: r,
        samples,
    } = recorded(&load_file("panda-cylinder.toml"), Panda);
    let c = contact(&r);
    let a = alignment(&r);
    assert!(c.normal_force_rms_error_last5s_n <= 0.5, "{c:?}");
    assert!(a.rms_deg <= 1.0 && a.max_deg <= 1.0, "{a:?}");
    assert_eq!(c.contact_losses, 0, "{c:?}");
    // The normal turned by 90 degrees under the tool: its axis (z, tool frame) at the first
    // and the last force-controlled sample are 90 degrees apart.
    let axis = |s: &armdyn::sim::Sample<7>| s.orientation * Vector3::z();
    let forced: Vec<_> = samples.iter().filter(|s| s.force_controlled).collect();
    let turned = axis(forced[0])
        .angle(&axis(forced[forced.len() - 1]))
        .to_degrees();
    assert!((turned - 90.0).abs() < 1.0, "{turned} degrees");
    assert_eq!(saturated(&r), 0);
}

/// The file, and variants it does not ship: the tube 8 mm thicker than believed at 30 N, 5 mm
/// thicker at 30 N on 20 kN/m, and 3 mm thinner (the tool comes down onto it) at 15 N; the
/// controller always believes the file's tube of 0.05 m.
#[test]
fn ur5_follows_a_pipe_bend_on_top_of_its_tube() {
    let shipped = std::fs::read_to_string(root().join("scenarios/ur5-pipe-bend.toml")).unwrap();
    let (tube, shift) = ("tube_radius = 0.055", "expected_shift_m = -0.005");
    let variant = |tube_radius: f64, force: f64, stiffness: f64| {
        assert!(shipped.contains(tube) && shipped.contains(shift));
        shipped
            .replace(tube, &format!("tube_radius = {tube_radius}"))
            .replace(shift, &format!("expected_shift_m = {}", 0.05 - tube_radius))
            .replace("value = 20.0", &format!("value = {force}"))
            .replace("stiffness = 10000.0", &format!("stiffness = {stiffness}"))
    };
    for (what, text) in [
        ("ur5-pipe-bend.toml", shipped.clone()),
        ("8 mm thicker, 30 N", variant(0.058, 30.0, 10000.0)),
        ("5 mm thicker, 30 N, 20 kN/m", variant(0.055, 30.0, 20000.0)),
        ("3 mm thinner, 15 N", variant(0.047, 15.0, 10000.0)),
    ] {
        let s = Scenario::parse(what, &text, &root().join("scenarios")).unwrap();
        let Recorded {
            outcome: r,
            samples,
        } = recorded(&s, Ur5);
        ur5_bars(&r, what);
        // It went 90 degrees round the bend, pressing, its tool on the top of the real tube.
        let centre = Vector3::new(0.40, -0.25, 0.10);
        let bearing = |s: &armdyn::sim::Sample<6>| {
            let r = s.position - centre;
            r.y.atan2(r.x).to_degrees()
        };
        let forced: Vec<_> = samples.iter().filter(|s| s.force_controlled).collect();
        let turned = bearing(forced[forced.len() - 1]) - bearing(forced[0]);
        assert!((turned - 90.0).abs() < 0.5, "{what}: {turned} degrees");
        for s in &forced {
            let r = s.position - centre;
            let off_ridge = (r.x.hypot(r.y) - 0.25).abs();
            assert!(
                off_ridge < 1e-3,
                "{what}: {off_ridge} m off the ridge at {} s",
                s.t
            );
        }
    }
}

/// Roll, pitch and yaw (fixed axes) of the orientation that turns `tool_down` so that its
/// tool axis `axis` (tool frame) points along `-n`.
fn along(tool_down: UnitQuaternion<f64>, axis: Vector3<f64>, n: &Vector3<f64>) -> (f64, f64, f64) {
    let turn = UnitQuaternion::rotation_between(&(tool_down * axis), &(-n)).unwrap();
    orientation::rpy(&(turn * tool_down))
}

/// A contact task on a plane through `centre` with outward normal `n`: down along the
/// normal from 0.05 m above onto where the controller believes the plane, a rest, then
/// `length` m along the in-plane direction `dir` in `move_s` s, pressing `force` N; the real
/// plane is `offset` m along the normal from the believed one.
#[allow(clippy::too_many_arguments)]
pub(crate) fn plane_task(
    robot: &str,
    seed_or_posture: &str,
    tool_down: UnitQuaternion<f64>,
    axis: Vector3<f64>,
    centre: Vector3<f64>,
    n: Vector3<f64>,
    dir: Vector3<f64>,
    length: f64,
    move_s: f64,
    force: f64,
    offset: f64,
) -> String {
    let n = n.normalize();
    let dir = (dir - n * n.dot(&dir)).normalize();
    let (roll, pitch, yaw) = along(tool_down, axis, &n);
    let a = centre - dir * (0.5 * length);
    let b = centre + dir * (0.5 * length);
    let above = a + n * 0.05;
    let real = centre + n * offset;
    let point = |t: f64, p: &Vector3<f64>| {
        format!(
            "  [{t}, {}, {}, {}, {roll}, {pitch}, {yaw}],\n",
            p.x, p.y, p.z
        )
    };
    let end = 2.0 + move_s;
    format!(
        "format = 1\nname = \"generated\"\nrobot = \"{robot}\"\nstart_on_reference = true\nend_stops = true\n\n\
         [reference]\nkind = \"waypoints\"\ninterpolation = \"quintic\"\n{seed_or_posture}\npoints = [\n{}{}{}{}{}]\n\n\
         [[surfaces]]\nkind = \"plane\"\npoint = [{}, {}, {}]\nnormal = [{}, {}, {}]\nhalf_extent = [0.4, 0.4]\nstiffness = 10000.0\n\n\
         [position]\nlaw = \"task-space\"\n\n\
         [force]\nlaw = \"pi-ff-vd\"\nreference = \"constant\"\nvalue = {force}\ngains = \"design\"\nexpected_shift_m = {}\n\n\
         [force.design]\nbandwidth_hz = 10.0\ndamping = 1.0\n\n[selection]\nmode = \"contact\"\n",
        point(0.0, &above),
        point(1.0, &a),
        point(2.0, &a),
        point(end, &b),
        point(end + 1.0, &b),
        real.x,
        real.y,
        real.z,
        n.x,
        n.y,
        n.z,
        -offset,
    )
}

#[test]
fn the_ur5_meets_its_bars_on_other_planes_heights_lines_and_forces() {
    // The UR5's tool x axis (ee_link) down.
    let down = orientation::from_rpy(0.0, core::f64::consts::FRAC_PI_2, 0.0);
    let seed = "seed = [0.0, -1.5708, 1.5708, -1.5708, -1.5708, 0.0]";
    let tilt = |deg: f64, about: Vector3<f64>| {
        UnitQuaternion::from_scaled_axis(about.normalize() * deg.to_radians()) * Vector3::z()
    };
    let cases = [
        // A lower table, really 5 mm lower than believed (an approach), a line along x.
        (
            Vector3::new(0.45, 0.05, 0.20),
            Vector3::z(),
            Vector3::x(),
            20.0,
            -0.005,
        ),
        // A plane tilted 15 degrees about base y, 40 N, a line across the slope.
        (
            Vector3::new(0.40, 0.0, 0.28),
            tilt(15.0, Vector3::y()),
            Vector3::y(),
            40.0,
            0.003,
        ),
        // Tilted 20 degrees about a diagonal, a line down the slope.
        (
            Vector3::new(0.42, -0.05, 0.26),
            tilt(20.0, Vector3::new(1.0, 1.0, 0.0)),
            Vector3::new(1.0, -1.0, 0.0),
            25.0,
            0.004,
        ),
    ];
    for (centre, n, dir, force, offset) in cases {
        let text = plane_task(
            "ur5",
            seed,
            down,
            Vector3::x(),
            centre,
            n,
            dir,
            0.2,
            4.0,
            force,
            offset,
        );
        let r = run_text("generated.toml", &text);
        ur5_bars(&r, &text);
    }
}

#[test]
fn the_panda_holds_force_tool_and_posture_on_a_tilted_plane() {
    // The Panda's tool z axis (panda_hand_tcp) down.
    let down = orientation::from_rpy(core::f64::consts::PI, 0.0, 0.0);
    let posture = "posture = [0.0, -0.7853981633974483, 0.0, -2.356194490192345, 0.0, 1.5707963267948966, 0.7853981633974483]";
    let n = UnitQuaternion::from_scaled_axis(Vector3::x() * 12f64.to_radians()) * Vector3::z();
    let text = plane_task(
        "panda",
        posture,
        down,
        Vector3::z(),
        Vector3::new(0.42, 0.0, 0.35),
        n,
        Vector3::new(1.0, 1.0, 0.0),
        0.15,
        4.0,
        12.0,
        -0.004,
    );
    let r = run_text("generated.toml", &text);
    let c = contact(&r);
    let a = alignment(&r);
    assert!(c.normal_force_rms_error_last3s_n <= 0.5, "{c:?}");
    assert!(c.normal_force_overshoot_pct <= 5.0, "{c:?}");
    assert!(c.path_rms_error_contact_mm <= 1.5, "{c:?}");
    assert!(a.rms_deg <= 0.5, "{a:?}");
    assert!(r.posture.unwrap().max_rad <= 0.05, "{:?}", r.posture);
    assert_eq!(saturated(&r), 0);
}

#[test]
fn the_tool_axis_key_is_checked() {
    let base = std::fs::read_to_string(root().join("scenarios/ur5-press-table.toml")).unwrap();
    for (value, message) in [
        ("[1.0, 0.0]", "2 values; a direction has 3"),
        ("[0.0, 0.0, 0.0]", "must be finite and not zero"),
        ("\"sideways\"", "`sideways`: expected a direction"),
    ] {
        let text = base.replace(
            "expected_shift_m = -0.005      # believed at z = 0.25 m",
            &format!("expected_shift_m = -0.005\ntool_axis = {value}"),
        );
        let e = Scenario::parse("t.toml", &text, Path::new(".")).unwrap_err();
        let e = e.to_string();
        assert!(e.contains("force.tool_axis") && e.contains(message), "{e}");
    }
    // Tracking the reference's orientation instead: the tool points down as the reference
    // says, here along the normal too.
    let text = base.replace(
        "expected_shift_m = -0.005      # believed at z = 0.25 m",
        "expected_shift_m = -0.005\ntool_axis = \"reference\"",
    );
    let r = run_text("t.toml", &text);
    assert!(r.alignment.is_none());
    assert!(contact(&r).normal_force_rms_error_last3s_n <= 0.5);
}

#[test]
fn a_ramped_force_is_followed_without_lag() {
    // ur5-press-table with the force a ramp from 30 to 60 N over 1.5 s (20 N/s) while the
    // tool follows its line: the damping acts against the reference's own motion, so the
    // force follows the ramp (a damping on the normal velocity alone would brake it by
    // Kvd (20 N/s) / (10 kN/m)).
    let dir = Scratch::new("ramp");
    std::fs::write(dir.join("ramp.csv"), "t,f\n0,30\n3,30\n4.5,60\n8,60\n").unwrap();
    let text = std::fs::read_to_string(root().join("scenarios/ur5-press-table.toml"))
        .unwrap()
        .replace(
            "reference = \"constant\"\nvalue = 30.0",
            "reference = \"csv\"\nfile = \"ramp.csv\"\nvalue = 60.0",
        );
    let lag = |text: &str| {
        let s = Scenario::parse("ramp.toml", text, &dir).unwrap_or_else(|e| panic!("{e}"));
        let samples = recorded(&s, Ur5).samples;
        let errors: Vec<f64> = samples
            .iter()
            .filter(|s| (3.1..=4.5).contains(&s.t))
            .map(|s| s.wrench[2] - s.setpoint.wrench[2])
            .collect();
        assert!(errors.len() > 1000);
        let rms = (errors.iter().map(|e| e * e).sum::<f64>() / errors.len() as f64).sqrt();
        let max = errors.iter().fold(0.0f64, |m, e| m.max(e.abs()));
        let end = samples.last().unwrap().wrench[2];
        (rms, max, end)
    };
    let (rms, max, end) = lag(&text);
    // The ramp asks for 30 N more in 1.5 s: the force follows within 0.05 N RMS, 0.1 N at
    // most (measured); damping the normal velocity alone (the thesis's law) lags by 0.39 N
    // RMS, 0.54 N at most.
    assert!(
        rms <= 0.15 && max <= 0.3,
        "RMS {rms} N, max {max} N during the ramp"
    );
    assert!((end + 60.0).abs() < 0.5, "{end}");
    let (rms_v, max_v, _) = lag(&text.replace(
        "gains = \"design\"",
        "gains = \"design\"\ndamp_reference_motion = false",
    ));
    assert!(
        rms_v >= 0.3 && max_v >= 0.45,
        "RMS {rms_v} N, max {max_v} N damping v_n alone"
    );
}

#[test]
fn far_from_the_surface_the_tool_follows_the_reference() {
    // The UR5 held 0.5 s with its tool straight down 50 mm above a plane tilted 30 degrees,
    // then brought down onto it while the reference turns the tool onto the normal: at rest
    // far above, the tool stays as the reference says (it is not thrown round onto the
    // normal), and in contact the bars hold.
    let down = orientation::from_rpy(0.0, core::f64::consts::FRAC_PI_2, 0.0);
    let n = UnitQuaternion::from_scaled_axis(Vector3::y() * 30f64.to_radians()) * Vector3::z();
    let task = plane_task(
        "ur5",
        "seed = [0.0, -1.5708, 1.5708, -1.5708, -1.5708, 0.0]",
        down,
        Vector3::x(),
        Vector3::new(0.42, 0.0, 0.25),
        n,
        Vector3::y(),
        0.1,
        4.0,
        30.0,
        0.0,
    );
    // The first point, 50 mm above along the normal, with the tool straight down instead.
    let (roll, pitch, yaw) = orientation::rpy(&down);
    let mut lines: Vec<String> = task.lines().map(str::to_string).collect();
    let first = lines.iter().position(|l| l.starts_with("  [0,")).unwrap();
    let xyz: Vec<String> = lines[first]
        .trim_start_matches("  [")
        .split(',')
        .skip(1)
        .take(3)
        .map(|v| v.trim().to_string())
        .collect();
    let rest = format!("{}, {}, {}, {roll}, {pitch}, {yaw}", xyz[0], xyz[1], xyz[2]);
    lines[first] = format!("  [0.0, {rest}],\n  [0.5, {rest}],");
    for l in lines.iter_mut().skip(first + 1) {
        if let Some(tail) = l.strip_prefix("  [") {
            let (t, more) = tail.split_once(',').unwrap();
            *l = format!("  [{},{more}", t.trim().parse::<f64>().unwrap() + 0.5);
        }
    }
    let s = parse_text("generated.toml", &(lines.join("\n") + "\n"));
    let Recorded {
        outcome: r,
        samples,
    } = recorded(&s, Ur5);
    let still = samples
        .iter()
        .filter(|s| s.t <= 0.5)
        .map(|s| {
            s.orientation
                .angle_to(&s.setpoint.cartesian.orientation)
                .to_degrees()
        })
        .fold(0.0f64, f64::max);
    assert!(
        still < 0.01,
        "{still} degrees off the reference at rest far above"
    );
    ur5_bars(&r, "a reference turning onto a 30-degree plane");
}
