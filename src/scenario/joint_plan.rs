//! A joint-space reference (`[reference] kind = "joints"`, a CSV `t,q1..qN`): the joints
//! follow it directly; the Cartesian setpoint of each sample is its forward kinematics.

use nalgebra::Vector3;

use super::planned::{PlannedReference, ReferenceReport};
use crate::kinematics::{IkOptions, InverseKinematics, NumericalIk};
use crate::model::{JointVector, RobotModel, Wrench};
use crate::sim::{ReferenceSource, Sample, Setpoint};
use crate::target::{orientation, CartesianTarget};
use crate::trajectory::{CartesianTrajectory, JointReference};

/// The tool's path of a joint reference: forward kinematics of `q(t)`, with the twist
/// `J qd` and the acceleration `J qdd + Jdot qd`.
#[derive(Clone, Debug)]
pub struct JointPath<const N: usize, R> {
    robot: R,
    reference: JointReference<N>,
}

impl<const N: usize, R: RobotModel<N>> JointPath<N, R> {
    /// The path of `reference` for `robot`.
    #[must_use]
    pub fn new(robot: R, reference: JointReference<N>) -> Self {
        Self { robot, reference }
    }
}

impl<const N: usize, R: RobotModel<N>> CartesianTrajectory for JointPath<N, R> {
    fn duration(&self) -> f64 {
        self.reference.duration()
    }

    fn at(&self, t: f64) -> CartesianTarget {
        let j = self.reference.at(t);
        let pose = self.robot.end_effector_pose(&j.q);
        let jac = self.robot.jacobian(&j.q);
        let twist = jac * j.qd;
        let acc = jac * j.qdd + self.robot.jdot_qd(&j.q, &j.qd);
        CartesianTarget {
            position: pose.fixed_view::<3, 1>(0, 3).into_owned(),
            orientation: orientation::of_pose(&pose),
            velocity: Vector3::new(twist[0], twist[1], twist[2]),
            angular_velocity: Vector3::new(twist[3], twist[4], twist[5]),
            acceleration: Vector3::new(acc[0], acc[1], acc[2]),
            angular_acceleration: Vector3::new(acc[3], acc[4], acc[5]),
        }
    }
}

/// A joint-space reference as a planned reference.
pub struct JointPlan<const N: usize, R> {
    path: JointPath<N, R>,
}

impl<const N: usize, R: RobotModel<N>> JointPlan<N, R> {
    /// The plan of `reference` for `robot`.
    #[must_use]
    pub fn new(robot: R, reference: JointReference<N>) -> Self {
        Self {
            path: JointPath::new(robot, reference),
        }
    }
}

impl<const N: usize, R: RobotModel<N>> ReferenceSource<N> for JointPlan<N, R> {
    fn at(&mut self, t: f64) -> Setpoint<N> {
        Setpoint {
            joint: self.path.reference.at(t),
            cartesian: self.path.at(t),
            wrench: Wrench::zeros(),
        }
    }
}

impl<const N: usize, R: RobotModel<N> + Copy> PlannedReference<N> for JointPlan<N, R> {
    fn trajectory(&self) -> &dyn CartesianTrajectory {
        &self.path
    }

    fn start(&self) -> JointVector<N> {
        self.path.reference.at(0.0).q
    }

    fn joints_at(&self, t: f64, position: &Vector3<f64>) -> Result<JointVector<N>, String> {
        let mut target = self.path.at(t);
        target.position = *position;
        NumericalIk::new(self.path.robot, IkOptions::default())
            .solve(&target, &self.path.reference.at(t).q)
            .map(|s| s.q)
            .map_err(|e| e.to_string())
    }

    fn report(&self, _samples: &[Sample<N>], _effort_limits: &JointVector<N>) -> ReferenceReport {
        ReferenceReport::default()
    }
}
