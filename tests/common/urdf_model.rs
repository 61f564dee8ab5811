//! An independent reading of a URDF-based description (`convention = "urdf"`): the URDF is
//! parsed with `urdf-rs` (not the generator's Python parser), the forward kinematics walks the
//! whole link tree, and every link that moves with the arm keeps its own mass and inertia (no
//! lumping), so energies summed over them check the generator's lumping too.
//!
//! The one rule shared with the generator, because it is the documented meaning of a URDF angle
//! here: an angle within 1e-9 rad of a multiple of pi/2 is that multiple.

use std::collections::HashMap;
use std::f64::consts::FRAC_PI_2;
use std::path::Path;

use nalgebra::{Matrix3, Matrix4, Rotation3, Unit, Vector3};
use serde::Deserialize;

const RIGHT_ANGLE_SNAP: f64 = 1e-9;

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawOverride {
    pub limits: Option<[f64; 2]>,
    pub effort: Option<f64>,
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawUrdfDescription {
    pub format: u32,
    pub name: String,
    pub description: String,
    pub convention: String,
    pub urdf: String,
    pub base_link: String,
    pub tip_link: String,
    pub gravity: Option<[f64; 3]>,
    #[serde(default)]
    pub locked: HashMap<String, f64>,
    #[serde(default)]
    pub joints: HashMap<String, RawOverride>,
}

/// One link's inertial data, in its own link frame.
#[derive(Debug, Clone)]
pub struct LinkInertia {
    pub mass: f64,
    /// Pose of the inertial frame (COM, principal axes as written) in the link frame.
    pub origin: Matrix4<f64>,
    /// Inertia about the COM, in the inertial frame's axes.
    pub inertia: Matrix3<f64>,
}

/// One rigid body that moves: (body index 1..=n, mass, COM in the base frame, rotation of the
/// axes its inertia is given in, inertia about the COM in those axes).
pub type Body = (usize, f64, Vector3<f64>, Matrix3<f64>, Matrix3<f64>);

/// The URDF tree as read, with the chain from the base to the tip.
#[derive(Debug, Clone)]
pub struct UrdfChain {
    pub joints: Vec<urdf_rs::Joint>,
    /// The moving joints of the chain, base to tip.
    pub chain: Vec<urdf_rs::Joint>,
    pub inertias: HashMap<String, LinkInertia>,
    pub base: String,
    pub tip: String,
    pub locked: HashMap<String, f64>,
    pub overrides: HashMap<String, RawOverride>,
}

fn snap(angle: f64) -> f64 {
    let k = (angle / FRAC_PI_2).round();
    if (angle - k * FRAC_PI_2).abs() <= RIGHT_ANGLE_SNAP {
        // Exact sin/cos below.
        k * FRAC_PI_2
    } else {
        angle
    }
}

/// sin and cos, exact (0, +-1) at multiples of pi/2.
fn sin_cos(angle: f64) -> (f64, f64) {
    let k = (angle / FRAC_PI_2).round();
    if k * FRAC_PI_2 == angle {
        match (k as i64).rem_euclid(4) {
            0 => (0.0, 1.0),
            1 => (1.0, 0.0),
            2 => (0.0, -1.0),
            _ => (-1.0, 0.0),
        }
    } else {
        angle.sin_cos()
    }
}

/// `Rz(yaw) Ry(pitch) Rx(roll)` with snapped angles.
fn rpy_matrix(rpy: &[f64; 3]) -> Matrix3<f64> {
    let (sr, cr) = sin_cos(snap(rpy[0]));
    let (sp, cp) = sin_cos(snap(rpy[1]));
    let (sy, cy) = sin_cos(snap(rpy[2]));
    let rx = Matrix3::new(1.0, 0.0, 0.0, 0.0, cr, -sr, 0.0, sr, cr);
    let ry = Matrix3::new(cp, 0.0, sp, 0.0, 1.0, 0.0, -sp, 0.0, cp);
    let rz = Matrix3::new(cy, -sy, 0.0, sy, cy, 0.0, 0.0, 0.0, 1.0);
    rz * ry * rx
}

fn pose(p: &urdf_rs::Pose) -> Matrix4<f64> {
    let mut t = Matrix4::identity();
    t.fixed_view_mut::<3, 3>(0, 0)
        .copy_from(&rpy_matrix(&p.rpy.0));
    t.fixed_view_mut::<3, 1>(0, 3)
        .copy_from(&Vector3::from(p.xyz.0));
    t
}

impl UrdfChain {
    /// Reads the description's URDF (path relative to the description).
    pub fn load(description: &Path, raw: &RawUrdfDescription) -> UrdfChain {
        let path = description.parent().unwrap().join(&raw.urdf);
        let robot =
            urdf_rs::read_file(&path).unwrap_or_else(|e| panic!("reading {}: {e}", path.display()));
        let by_child: HashMap<&str, &urdf_rs::Joint> = robot
            .joints
            .iter()
            .map(|j| (j.child.link.as_str(), j))
            .collect();
        let mut path_joints = Vec::new();
        let mut link = raw.tip_link.as_str();
        while link != raw.base_link {
            let j = by_child[link];
            path_joints.push(j.clone());
            link = j.parent.link.as_str();
        }
        path_joints.reverse();
        let chain = path_joints
            .into_iter()
            .filter(|j| {
                matches!(
                    j.joint_type,
                    urdf_rs::JointType::Revolute
                        | urdf_rs::JointType::Continuous
                        | urdf_rs::JointType::Prismatic
                ) && !raw.locked.contains_key(&j.name)
            })
            .collect();
        let inertias = robot
            .links
            .iter()
            .map(|l| {
                let i = &l.inertial.inertia;
                (
                    l.name.clone(),
                    LinkInertia {
                        mass: l.inertial.mass.value,
                        origin: pose(&l.inertial.origin),
                        inertia: Matrix3::new(
                            i.ixx, i.ixy, i.ixz, i.ixy, i.iyy, i.iyz, i.ixz, i.iyz, i.izz,
                        ),
                    },
                )
            })
            .collect();
        UrdfChain {
            joints: robot.joints,
            chain,
            inertias,
            base: raw.base_link.clone(),
            tip: raw.tip_link.clone(),
            locked: raw.locked.clone(),
            overrides: raw.joints.clone(),
        }
    }

    pub fn is_prismatic(j: &urdf_rs::Joint) -> bool {
        j.joint_type == urdf_rs::JointType::Prismatic
    }

    /// `[lower, upper]` and effort of chain joint `k`, overrides first.
    pub fn limits(&self, k: usize) -> ([f64; 2], f64) {
        let j = &self.chain[k];
        let o = self.overrides.get(&j.name);
        let limits = match (o.and_then(|o| o.limits), &j.joint_type) {
            (Some(l), _) => l,
            (None, urdf_rs::JointType::Continuous) => [-std::f64::consts::PI, std::f64::consts::PI],
            (None, _) => [j.limit.lower, j.limit.upper],
        };
        let effort = o.and_then(|o| o.effort).unwrap_or(j.limit.effort);
        (limits, effort)
    }

    /// The value of a joint at `q`: a chain joint's coordinate, a locked joint's value, a mimic
    /// joint's `multiplier * leader + offset`, 0 for a fixed joint.
    fn value(&self, j: &urdf_rs::Joint, q: &[f64]) -> f64 {
        if let Some(k) = self.chain.iter().position(|c| c.name == j.name) {
            return q[k];
        }
        if let Some(v) = self.locked.get(&j.name) {
            return *v;
        }
        if let Some(m) = &j.mimic {
            let leader = self.joints.iter().find(|l| l.name == m.joint).unwrap();
            return m.multiplier.unwrap_or(1.0) * self.value(leader, q) + m.offset.unwrap_or(0.0);
        }
        0.0
    }

    /// Pose of every link below the base (base frame), and for the moving ones the index of the
    /// last chain joint above them (1-based; 0 for links that do not move).
    pub fn link_poses(&self, q: &[f64]) -> HashMap<String, (Matrix4<f64>, usize)> {
        let mut out = HashMap::new();
        out.insert(self.base.clone(), (Matrix4::identity(), 0));
        let mut todo = vec![self.base.clone()];
        while let Some(link) = todo.pop() {
            let (t, body) = out[&link];
            for j in self.joints.iter().filter(|j| j.parent.link == link) {
                let value = self.value(j, q);
                let axis = Unit::new_normalize(Vector3::from(j.axis.xyz.0));
                let mut motion = Matrix4::identity();
                match j.joint_type {
                    urdf_rs::JointType::Revolute | urdf_rs::JointType::Continuous => {
                        motion = Rotation3::from_axis_angle(&axis, value).to_homogeneous();
                    }
                    urdf_rs::JointType::Prismatic => {
                        motion
                            .fixed_view_mut::<3, 1>(0, 3)
                            .copy_from(&(axis.into_inner() * value));
                    }
                    _ => {}
                }
                let child_body = match self.chain.iter().position(|c| c.name == j.name) {
                    Some(k) => k + 1,
                    None => body,
                };
                out.insert(
                    j.child.link.clone(),
                    (t * pose(&j.origin) * motion, child_body),
                );
                todo.push(j.child.link.clone());
            }
        }
        out
    }

    /// Poses of the chain joints' child links (the model's link frames), base frame.
    pub fn frame_poses(&self, q: &[f64]) -> Vec<Matrix4<f64>> {
        let poses = self.link_poses(q);
        self.chain.iter().map(|j| poses[&j.child.link].0).collect()
    }

    pub fn end_effector(&self, q: &[f64]) -> Matrix4<f64> {
        self.link_poses(q)[&self.tip].0
    }

    /// Every link that moves with the arm: (body index, mass, COM, rotation of its inertial
    /// frame, inertia about the COM in that frame), base frame.
    pub fn bodies(&self, q: &[f64]) -> Vec<Body> {
        let mut names: Vec<_> = self.link_poses(q).into_iter().collect();
        names.sort_by(|a, b| a.0.cmp(&b.0));
        names
            .into_iter()
            .filter(|(_, (_, body))| *body > 0)
            .map(|(name, (t, body))| {
                let li = &self.inertias[&name];
                let x = t * li.origin;
                (
                    body,
                    li.mass,
                    x.fixed_view::<3, 1>(0, 3).into_owned(),
                    x.fixed_view::<3, 3>(0, 0).into_owned(),
                    li.inertia,
                )
            })
            .collect()
    }
}
