//! A [`ReferenceSource`] for the SCARA: Cartesian reference -> elbow plan -> inverse
//! kinematics -> joint target, plus the desired contact wrench.

use crate::control::JointTarget;
use crate::kinematics::{ElbowPlan, ScaraGeometry};
use crate::model::Wrench;
use crate::sim::{ReferenceSource, Setpoint};
use crate::trajectory::{CartesianTrajectory, ForceProfile};

/// Joint targets from a Cartesian reference, with the elbow chosen by a plan made before the
/// run (thesis Section 4.4). Inverse kinematics runs at every control sample; near the
/// stretched-arm singularity the joint velocity is damped (see
/// [`ScaraGeometry::joint_target`]) and the sample is counted in
/// [`ScaraReference::singular_samples`].
pub struct ScaraReference<'a, T: ?Sized> {
    geometry: ScaraGeometry,
    trajectory: &'a T,
    plan: ElbowPlan,
    force: Option<ForceProfile>,
    last: Option<JointTarget<4>>,
    singular_samples: usize,
    failed_samples: usize,
}

impl<'a, T: CartesianTrajectory + ?Sized> ScaraReference<'a, T> {
    /// A reference following `trajectory` with the elbows of `plan`; `force` gives the desired
    /// contact wrench (zero if `None`).
    #[must_use]
    pub fn new(
        geometry: ScaraGeometry,
        trajectory: &'a T,
        plan: ElbowPlan,
        force: Option<ForceProfile>,
    ) -> Self {
        Self {
            geometry,
            trajectory,
            plan,
            force,
            last: None,
            singular_samples: 0,
            failed_samples: 0,
        }
    }

    /// The elbow plan.
    #[must_use]
    pub fn plan(&self) -> &ElbowPlan {
        &self.plan
    }

    /// Samples at which the Jacobian inverse was damped (near `q2 = 0`).
    #[must_use]
    pub fn singular_samples(&self) -> usize {
        self.singular_samples
    }

    /// Samples at which inverse kinematics failed and the previous target was held (zero
    /// after a successful plan: the plan checks every sample at its own rate first).
    #[must_use]
    pub fn failed_samples(&self) -> usize {
        self.failed_samples
    }
}

impl<T: CartesianTrajectory + ?Sized> ReferenceSource<4> for ScaraReference<'_, T> {
    fn at(&mut self, t: f64) -> Setpoint<4> {
        let cartesian = self.trajectory.at(t);
        let joint = match self
            .geometry
            .joint_target(&cartesian, self.plan.elbow_at(t))
        {
            Ok(r) => {
                if r.conditioning.is_singular() {
                    self.singular_samples += 1;
                }
                r.target
            }
            Err(_) => {
                self.failed_samples += 1;
                self.last.unwrap_or(JointTarget {
                    q: Default::default(),
                    qd: Default::default(),
                    qdd: Default::default(),
                })
            }
        };
        self.last = Some(joint);
        let wrench = self.force.map_or_else(Wrench::zeros, |f| f.wrench(t));
        Setpoint {
            joint,
            cartesian,
            wrench,
        }
    }
}
