//! A self-contained 3-D viewer of a run: `view.html`, one file with its data and its
//! JavaScript inline (plain 2-D canvas drawing with a perspective projection: no library, no
//! network at view time).
//!
//! The data are the recorded samples of `trajectory.csv`, read back from its text so that the
//! viewer shows exactly what the file holds, decimated to at most [`MAX_FRAMES`] frames plus
//! the sample at every event. The robot is drawn as links between its frame origins, which
//! the generated forward kinematics ([`RobotModel::frame_poses`],
//! [`RobotModel::end_effector_pose`]) computes here, in Rust; the page only interpolates
//! between frames and projects.

mod events;
mod page;
mod scene_file;
mod surface_mesh;
mod trajectory_text;

pub use events::{events_from_metrics, ViewEvent};
pub use scene_file::{scene_from_json, scene_json, surface_json};
pub use trajectory_text::ViewError;

use crate::contact::SurfaceGeometry;
use crate::model::RobotModel;
use trajectory_text::Columns;

/// At most this many regular frames (a 10 s run at 1 kHz keeps every second sample); the
/// samples at events come on top.
pub const MAX_FRAMES: usize = 5001;

/// The page of a run: `title` above it, the samples of `trajectory_csv` (the text
/// [`crate::report::trajectory_csv`] writes for `robot`), the scene's `surfaces` and the run's
/// `events`.
///
/// # Errors
///
/// If the text is not a trajectory of `robot` (the header's first differing column, or the
/// line of a malformed record), or holds no sample.
pub fn view_html<const N: usize, R: RobotModel<N>>(
    robot: &R,
    robot_name: &str,
    title: &str,
    trajectory_csv: &str,
    surfaces: &[SurfaceGeometry],
    events: &[ViewEvent],
) -> Result<String, ViewError> {
    let rows = trajectory_text::read::<N>(trajectory_csv, &R::JOINT_NAMES, &R::JOINT_KINDS)?;
    let times: Vec<f64> = rows.iter().map(|r| r[0]).collect();
    let kept = frames(&times, events);
    let c = Columns::new(N);
    let mut data = page::Data::new(title, robot_name, &R::JOINT_NAMES, N + 2);
    let mut tool_path = Vec::with_capacity(kept.len());
    for &i in &kept {
        let row = &rows[i];
        let q = crate::model::JointVector::<N>::from_fn(|j, _| row[c.q + j]);
        let mut points = Vec::with_capacity(N + 2);
        points.push([0.0; 3]);
        for pose in robot.frame_poses(&q) {
            points.push([pose[(0, 3)], pose[(1, 3)], pose[(2, 3)]]);
        }
        let tool = robot.end_effector_pose(&q);
        points.push([tool[(0, 3)], tool[(1, 3)], tool[(2, 3)]]);
        let at = |k: usize| [row[k], row[k + 1], row[k + 2]];
        tool_path.push(at(c.position));
        data.push_frame(
            row[0],
            &points,
            at(c.position),
            at(c.reference),
            at(c.force),
            at(c.force_ref),
        );
    }
    for s in surfaces {
        data.push_surface(surface_mesh::mesh(s, &tool_path));
    }
    for e in events {
        data.push_event(e);
    }
    Ok(page::html(&data))
}

/// The indices of the samples shown: every `stride`-th (at most [`MAX_FRAMES`]), the last,
/// and the first at or after each event's time; ascending, each once.
fn frames(times: &[f64], events: &[ViewEvent]) -> Vec<usize> {
    let n = times.len();
    let stride = n.div_ceil(MAX_FRAMES).max(1);
    let mut kept: Vec<usize> = (0..n).step_by(stride).collect();
    if n > 0 {
        kept.push(n - 1);
    }
    for e in events {
        let i = times.partition_point(|&t| t < e.t_s);
        if i < n {
            kept.push(i);
        }
    }
    kept.sort_unstable();
    kept.dedup();
    kept
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frames_are_strided_and_keep_the_last_sample_and_every_event() {
        let times: Vec<f64> = (0..10_001).map(|i| f64::from(i) * 1e-3).collect();
        let events = [ViewEvent {
            t_s: 5.0205,
            text: "trip".into(),
        }];
        let kept = frames(&times, &events);
        assert!(kept.len() <= MAX_FRAMES + 2, "{}", kept.len());
        assert_eq!(kept[1], 2);
        assert_eq!(*kept.last().unwrap(), 10_000);
        // The first sample at or after the event (5.021 s), not on the stride.
        assert!(kept.contains(&5021));
        assert!(kept.windows(2).all(|w| w[0] < w[1]));
        assert!(frames(&[], &events).is_empty());
    }
}
