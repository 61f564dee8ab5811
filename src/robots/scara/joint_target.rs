//! The joint-space reference (positions, velocities, accelerations) for a Cartesian target:
//! closed-form positions, then velocities and accelerations through the reduced Jacobian,
//! damped near the stretched or folded arm ([`singularity`](super::singularity)).

use nalgebra::Vector4;

use super::geometry::{Elbow, IkError, ScaraGeometry};
use super::singularity::{reduced_jacobian, Conditioning, DampedSolver};
use crate::model::{RobotModel, Scara};
use crate::target::{CartesianTarget, JointTarget};

/// A joint-space reference from a Cartesian one, and how it was obtained.
///
/// # Example
///
/// ```
/// use armdyn::robots::scara::{Elbow, ScaraGeometry};
/// use armdyn::trajectory::CartesianTrajectory;
/// use armdyn::robots::scara::thesis::PositionTest;
///
/// let ik = ScaraGeometry::from_model(&armdyn::model::Scara);
/// let start = ik.joint_target(&PositionTest::new().at(0.0), Elbow::Up).unwrap();
/// assert!(start.conditioning.is_singular()); // eq. 4.16 starts with the arm stretched
/// assert!(start.target.qd.iter().all(|v| v.is_finite()));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JointReference {
    /// Joint positions, velocities and accelerations.
    pub target: JointTarget<4>,
    /// Whether the Jacobian inverse was damped.
    pub conditioning: Conditioning,
}

impl ScaraGeometry {
    /// The joint-space reference for a Cartesian one: `q` by [`ScaraGeometry::inverse`],
    /// then velocity and acceleration through the reduced Jacobian `Jr` (rows `vx, vy, vz,
    /// wz` of the generated geometric Jacobian of [`Scara`]) and the generated `Jdot qd`:
    ///
    /// ```text
    /// qd  = Jr^-1 [v; yaw_rate]
    /// qdd = Jr^-1 ([a; yaw_acceleration] - (Jdot qd)_r)
    /// ```
    ///
    /// (from `d/dt (Jr qd) = Jr qdd + (Jdot qd)_r`; the yaw rate is `wz` since yaw is the
    /// rotation about the fixed base z axis). Near the singularity (`|sin q2| <`
    /// [`SINGULARITY_THRESHOLD`](super::SINGULARITY_THRESHOLD)) `Jr^-1` is the damped least-squares inverse of
    /// [`singularity`](super::singularity), and the result is flagged
    /// [`Conditioning::Damped`]. Joint limits are not checked.
    ///
    /// The geometry should be [`ScaraGeometry::from_model`]'s: the Jacobian comes from the
    /// generated [`Scara`] model whatever the geometry's numbers.
    ///
    /// # Errors
    ///
    /// As [`ScaraGeometry::inverse`]. Non-finite velocities or accelerations are not
    /// checked: they give non-finite `qd`, `qdd`.
    ///
    /// # Example
    ///
    /// ```
    /// use armdyn::robots::scara::{Elbow, ScaraGeometry};
    /// use armdyn::model::{RobotModel, Scara};
    /// use armdyn::trajectory::CartesianTrajectory;
    /// use armdyn::robots::scara::thesis::ThreeZone;
    ///
    /// let ik = ScaraGeometry::from_model(&Scara);
    /// let target = ThreeZone::new().at(5.0);
    /// let reference = ik.joint_target(&target, Elbow::Up).unwrap();
    /// assert!(!reference.conditioning.is_singular());
    /// // The joint velocity reproduces the Cartesian one.
    /// let v = Scara.jacobian(&reference.target.q) * reference.target.qd;
    /// assert!((v.fixed_rows::<3>(0) - target.velocity).norm() < 1e-12);
    /// ```
    pub fn joint_target(
        &self,
        target: &CartesianTarget,
        elbow: Elbow,
    ) -> Result<JointReference, IkError> {
        let q = self.inverse(&target.position, target.yaw(), elbow)?;
        let jr = reduced_jacobian(&q);
        let sin_q2 = libm::sin(q[1]);
        let velocity = Vector4::new(
            target.velocity.x,
            target.velocity.y,
            target.velocity.z,
            target.angular_velocity.z,
        );
        // One factorisation for the velocity and the acceleration.
        let solver = DampedSolver::new(&jr, sin_q2);
        let qd = solver.solve(&velocity);
        let bias = Scara.jdot_qd(&q, &qd);
        let acceleration = Vector4::new(
            target.acceleration.x - bias[0],
            target.acceleration.y - bias[1],
            target.acceleration.z - bias[2],
            target.angular_acceleration.z - bias[5],
        );
        let qdd = solver.solve(&acceleration);
        Ok(JointReference {
            target: JointTarget { q, qd, qdd },
            conditioning: solver.conditioning(),
        })
    }
}
