//! Tests of `armdyn::trajectory`: the waypoint, sampled and paused references, the force
//! references, and the pose, joint and force CSV readers. A file here tests the file of the
//! same name in `src/trajectory/`.

mod force;
mod force_csv;
mod joint_csv;
mod pause;
mod pose_csv;
mod sampled;
mod waypoints;
