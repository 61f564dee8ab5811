//! An identified robot as a robot description the generator reads: a URDF with the identified
//! inertias (and the friction as each joint's `<dynamics damping friction>`) and the TOML
//! description that names it (`convention = "urdf"`), so `bash codegen/regenerate.sh` turns it
//! into a generated model.
//!
//! The URDF is the robot's own generated one (`armdyn_generated::<robot>::URDF`: its links in
//! their joint frames `G_i`), with every moving link's `<inertial>` replaced. The standard
//! parameters are expressed in the model's link frames `F_i` ([`RobotModel::frame_poses`]);
//! both frames move with joint `i`, so `X_i = G_i^-1 F_i` at `q = 0` is constant and moves
//! them: `c_G = R c_F + p`, `I_G = R I_F R^T` (about the centre of mass). For a URDF robot
//! `X_i` is the identity; for a DH robot it is the DH link's placement.

use nalgebra::{Matrix4, Rotation3, Vector3};

use super::error::IdentificationError;
use super::robots::PER_LINK;
use crate::model::{JointVector, LinkInertia, RobotModel};

/// Robot names the generator accepts: lower-case letters, digits and `_`, a letter first.
#[must_use]
pub fn valid_name(name: &str) -> bool {
    let mut c = name.chars();
    matches!(c.next(), Some('a'..='z'))
        && c.all(|ch| ch.is_ascii_lowercase() || ch.is_ascii_digit() || ch == '_')
}

fn pose_of(origin: &urdf_rs::Pose) -> Matrix4<f64> {
    let r = Rotation3::from_euler_angles(origin.rpy[0], origin.rpy[1], origin.rpy[2]);
    let mut m = Matrix4::identity();
    m.fixed_view_mut::<3, 3>(0, 0).copy_from(r.matrix());
    for k in 0..3 {
        m[(k, 3)] = origin.xyz[k];
    }
    m
}

fn inverse(m: &Matrix4<f64>) -> Matrix4<f64> {
    let r = m.fixed_view::<3, 3>(0, 0).transpose();
    let p = -(r * m.fixed_view::<3, 1>(0, 3));
    let mut out = Matrix4::identity();
    out.fixed_view_mut::<3, 3>(0, 0).copy_from(&r);
    out.fixed_view_mut::<3, 1>(0, 3).copy_from(&p);
    out
}

/// The written description.
#[derive(Clone, Debug, PartialEq)]
pub struct Description {
    /// `<name>.toml`.
    pub toml: String,
    /// `<name>.urdf`.
    pub urdf: String,
}

/// The description of `robot` (generated URDF `urdf`) with the standard parameters `standard`
/// and, per joint, viscous and Coulomb friction `friction` (written to `<dynamics>`), named
/// `name`; `note` goes into both files' header comments.
///
/// # Errors
///
/// [`IdentificationError::Setting`] for a bad name or a URDF that is not the robot's chain.
pub fn describe<const N: usize, R: RobotModel<N>>(
    robot: &R,
    urdf: &str,
    name: &str,
    standard: &[f64],
    friction: Option<(&[f64], &[f64])>,
    note: &str,
) -> Result<Description, IdentificationError> {
    let bad = |m: String| IdentificationError::Setting(m);
    if !valid_name(name) {
        return Err(bad(format!(
            "robot name {name:?}: lower-case letters, digits and _, starting with a letter"
        )));
    }
    if standard.len() != PER_LINK * N {
        return Err(bad(format!(
            "{} standard parameters for {N} links",
            standard.len()
        )));
    }
    let mut doc = urdf_rs::read_from_string(urdf)
        .map_err(|e| bad(format!("the generated URDF of {}: {e}", R::NAME)))?;
    // The chain from the root link: each moving joint's pose at q = 0.
    let children: Vec<&str> = doc.joints.iter().map(|j| j.child.link.as_str()).collect();
    let root = doc
        .links
        .iter()
        .find(|l| !children.contains(&l.name.as_str()))
        .map(|l| l.name.clone())
        .ok_or_else(|| bad("the URDF has no root link".into()))?;
    let mut at = root.clone();
    let mut pose = Matrix4::identity();
    let mut moving = Vec::new();
    let mut tip = root.clone();
    while let Some(j) = doc.joints.iter().position(|j| j.parent.link == at) {
        let joint = &doc.joints[j];
        pose *= pose_of(&joint.origin);
        if !matches!(joint.joint_type, urdf_rs::JointType::Fixed) {
            moving.push((j, joint.child.link.clone(), pose));
        }
        at = joint.child.link.clone();
        tip = at.clone();
    }
    if moving.len() != N {
        return Err(bad(format!(
            "the generated URDF of {} has {} moving joints on its chain, the model {N}",
            R::NAME,
            moving.len()
        )));
    }
    let frames = robot.frame_poses(&JointVector::<N>::zeros());
    for (i, (j, link, g)) in moving.iter().enumerate() {
        let x = inverse(g) * frames[i];
        let r = x.fixed_view::<3, 3>(0, 0).into_owned();
        let p = Vector3::new(x[(0, 3)], x[(1, 3)], x[(2, 3)]);
        let mut s = [0.0; PER_LINK];
        s.copy_from_slice(&standard[i * PER_LINK..(i + 1) * PER_LINK]);
        let body = LinkInertia::from_standard(&s);
        let com = r * body.com + p;
        let inertia = r * body.inertia * r.transpose();
        let l = doc
            .links
            .iter_mut()
            .find(|l| &l.name == link)
            .ok_or_else(|| bad(format!("URDF link {link} is missing")))?;
        l.inertial.origin = urdf_rs::Pose {
            xyz: urdf_rs::Vec3([com[0] + 0.0, com[1] + 0.0, com[2] + 0.0]),
            rpy: urdf_rs::Vec3([0.0; 3]),
        };
        l.inertial.mass.value = body.mass;
        l.inertial.inertia = urdf_rs::Inertia {
            ixx: inertia[(0, 0)],
            ixy: 0.5 * (inertia[(0, 1)] + inertia[(1, 0)]),
            ixz: 0.5 * (inertia[(0, 2)] + inertia[(2, 0)]),
            iyy: inertia[(1, 1)],
            iyz: 0.5 * (inertia[(1, 2)] + inertia[(2, 1)]),
            izz: inertia[(2, 2)],
        };
        if let Some((fv, fc)) = friction {
            doc.joints[*j].dynamics = Some(urdf_rs::Dynamics {
                damping: fv[i],
                friction: fc[i],
            });
        }
    }
    doc.name = name.to_string();
    let body = urdf_rs::write_to_string(&doc)
        .map_err(|e| bad(format!("writing the URDF of {name}: {e}")))?;
    let comment = note.replace("--", "- -");
    let urdf = format!(
        "<?xml version=\"1.0\" ?>\n<!-- {comment}\n     Gravity (base frame, m/s^2): {:?}. -->\n{body}\n",
        R::GRAVITY
    );
    let task: Vec<String> = R::TASK.names().iter().map(|n| format!("\"{n}\"")).collect();
    let toml = format!(
        "# {}\n# Regenerate the model after any change: bash codegen/regenerate.sh\nformat = 1\nname = \"{name}\"\ndescription = \"{} identified from a log\"\nconvention = \"urdf\"\nurdf = \"{name}.urdf\"\nbase_link = \"{root}\"\ntip_link = \"{tip}\"\ngravity = [{:?}, {:?}, {:?}]\ntask = [{}]\n",
        note.replace('\n', "\n# "),
        R::NAME,
        R::GRAVITY[0],
        R::GRAVITY[1],
        R::GRAVITY[2],
        task.join(", ")
    );
    Ok(Description { toml, urdf })
}
