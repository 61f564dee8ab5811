//! `metrics/pose.rs`: the tool's position and orientation tracking in the task's directions.

use super::{at, times};
use armdyn::metrics::PoseMetrics;
use armdyn::target::Task;
use nalgebra::{UnitQuaternion, Vector3};

/// 2 s of a tool 3 mm, 4 mm off its reference in x-y (12 mm in z) and turned 0.1 rad about x
/// and 0.2 rad about z from it; the first second is force controlled.
fn run(task: Task, after_s: f64) -> armdyn::metrics::PoseSummary {
    let mut m = PoseMetrics::new(task, after_s);
    for t in times(0.01, 2.0) {
        let mut s = at(t);
        s.force_controlled = t < 1.0 - 1e-12;
        s.setpoint.cartesian.position = Vector3::new(0.003, 0.004, 0.012);
        s.setpoint.cartesian.orientation = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), 0.2)
            * UnitQuaternion::from_axis_angle(&Vector3::x_axis(), 0.1);
        m.push(&s);
    }
    m.summary()
}

#[test]
fn a_full_task_counts_the_whole_position_and_rotation() {
    let r = run(Task::FULL, 0.0);
    // The force-controlled half is left to the contact metrics.
    assert_eq!(r.samples, 100);
    assert!((r.position_rms_m - 0.013).abs() < 1e-15 && (r.position_max_m - 0.013).abs() < 1e-15);
    // The angle of R_d R^T: the composition of 0.1 rad and 0.2 rad about orthogonal axes.
    let angle = (UnitQuaternion::from_axis_angle(&Vector3::z_axis(), 0.2)
        * UnitQuaternion::from_axis_angle(&Vector3::x_axis(), 0.1))
    .angle();
    assert!((r.orientation_rms_rad - angle).abs() < 1e-12, "{r:?}");
    assert!((r.orientation_max_rad - angle).abs() < 1e-12, "{r:?}");
}

#[test]
fn a_task_counts_only_its_directions() {
    let yaw = run(Task::POSITION_AND_YAW, 0.0);
    assert!((yaw.orientation_rms_rad - 0.2).abs() < 1e-12, "{yaw:?}");
    let planar = run(Task::from_rows(&[0, 1]).unwrap(), 0.0);
    assert!((planar.position_rms_m - 0.005).abs() < 1e-15, "{planar:?}");
    assert_eq!(planar.orientation_rms_rad, 0.0);
}

#[test]
fn the_window_starts_at_after_s() {
    let r = run(Task::POSITION, 1.5);
    assert_eq!((r.samples, r.after_s), (50, 1.5));
    let empty = run(Task::POSITION, 5.0);
    assert_eq!(
        (empty.samples, empty.position_rms_m, empty.position_max_m),
        (0, 0.0, 0.0)
    );
}
