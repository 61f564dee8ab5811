//! The SCARA's closed-form inverse kinematics behind the generic interface
//! ([`InverseKinematics`]): the seed chooses the elbow.

use super::geometry::{Elbow, IkError as ScaraIkError, ScaraGeometry};
use crate::kinematics::{IkError, IkSolution, InverseKinematics};
use crate::model::{JointVector, RobotModel, Scara};
use crate::target::{wrap_angle, CartesianTarget};

/// [`ScaraGeometry::inverse`] as an [`InverseKinematics`]: the elbow of the seed (`q2 >= 0`:
/// up), or the other one if the seed's puts a joint outside its limits.
///
/// ```
/// use armdyn::kinematics::InverseKinematics;
/// use armdyn::model::Scara;
/// use armdyn::robots::scara::ClosedFormIk;
/// use armdyn::target::{orientation, CartesianTarget};
/// use nalgebra::{Vector3, Vector4};
///
/// let ik = ClosedFormIk::new(&Scara);
/// let target = CartesianTarget::at_rest(Vector3::new(0.4, 0.4, 0.2), orientation::from_yaw(0.1));
/// let up = ik.solve(&target, &Vector4::new(0.0, 1.0, 0.2, 0.0)).unwrap();
/// let down = ik.solve(&target, &Vector4::new(0.0, -1.0, 0.2, 0.0)).unwrap();
/// assert!(up.q[1] > 0.0 && down.q[1] < 0.0 && up.position_error_m < 1e-15);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ClosedFormIk {
    geometry: ScaraGeometry,
}

impl ClosedFormIk {
    /// The closed form of the generated model's geometry.
    #[must_use]
    pub fn new(robot: &Scara) -> Self {
        Self {
            geometry: ScaraGeometry::from_model(robot),
        }
    }

    /// The geometry.
    #[must_use]
    pub fn geometry(&self) -> &ScaraGeometry {
        &self.geometry
    }
}

impl InverseKinematics<4> for ClosedFormIk {
    fn solve(
        &self,
        target: &CartesianTarget,
        seed: &JointVector<4>,
    ) -> Result<IkSolution<4>, IkError> {
        let yaw = target.yaw();
        let first = if seed[1] >= 0.0 {
            Elbow::Up
        } else {
            Elbow::Down
        };
        let mut outside = None;
        for elbow in [first, first.other()] {
            let q = match self.geometry.inverse(&target.position, yaw, elbow) {
                Ok(q) => q,
                Err(ScaraIkError::NonFinite { .. }) => return Err(IkError::NonFinite),
                Err(ScaraIkError::TooFar { radius, max, .. }) => {
                    return Err(IkError::NotReached {
                        position_error_m: radius - max,
                        orientation_error_rad: 0.0,
                        iterations: 0,
                    })
                }
                Err(ScaraIkError::TooClose { radius, min, .. }) => {
                    return Err(IkError::NotReached {
                        position_error_m: min - radius,
                        orientation_error_rad: 0.0,
                        iterations: 0,
                    })
                }
            };
            match self.geometry.check_limits(&q) {
                Ok(()) => {
                    let pose = Scara.end_effector_pose(&q);
                    let p = pose.fixed_view::<3, 1>(0, 3).into_owned();
                    return Ok(IkSolution {
                        q,
                        position_error_m: (p - target.position).norm(),
                        orientation_error_rad: wrap_angle(
                            libm::atan2(pose[(1, 0)], pose[(0, 0)]) - yaw,
                        )
                        .abs(),
                        iterations: 0,
                    });
                }
                Err(v) => {
                    outside.get_or_insert(IkError::OutsideLimits {
                        joint: v.joint,
                        value: v.value,
                        lower: v.lower,
                        upper: v.upper,
                    });
                }
            }
        }
        Err(outside.unwrap_or(IkError::NonFinite))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::target::orientation;
    use nalgebra::{Vector3, Vector4};

    #[test]
    fn unreachable_and_outside_limits_say_so() {
        let ik = ClosedFormIk::new(&Scara);
        let far = CartesianTarget::at_rest(Vector3::new(1.0, 0.0, 0.2), orientation::from_yaw(0.0));
        match ik.solve(&far, &Vector4::zeros()) {
            Err(IkError::NotReached {
                position_error_m, ..
            }) => assert!((position_error_m - 0.2).abs() < 1e-12),
            other => panic!("{other:?}"),
        }
        // Too low: d3 past its stroke whatever the elbow.
        let low =
            CartesianTarget::at_rest(Vector3::new(0.5, 0.1, -0.5), orientation::from_yaw(0.0));
        assert!(matches!(
            ik.solve(&low, &Vector4::zeros()),
            Err(IkError::OutsideLimits { joint: 2, .. })
        ));
    }
}
