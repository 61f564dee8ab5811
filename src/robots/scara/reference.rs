//! A [`ReferenceSource`] for the SCARA: Cartesian reference -> elbow plan -> closed-form
//! inverse kinematics -> joint target, with planned elbow flips as joint moves.

use crate::model::Wrench;
use crate::robots::scara::elbow_flip::JointMove;
use crate::robots::scara::{ElbowPlan, ScaraGeometry};
use crate::sim::{ReferenceSource, Setpoint};
use crate::target::JointTarget;
use crate::trajectory::CartesianTrajectory;

/// Joint targets from a Cartesian reference, with the elbow chosen by a plan made before the
/// run (thesis Section 4.4). Inverse kinematics runs at every control sample; near the
/// stretched-arm singularity the joint velocity is damped (see
/// [`ScaraGeometry::joint_target`]) and the sample is counted in
/// [`ScaraReference::singular_samples`]. The setpoint's wrench is zero: the desired force
/// is the force loop's.
pub struct ScaraReference<T> {
    geometry: ScaraGeometry,
    trajectory: T,
    plan: ElbowPlan,
    last: Option<JointTarget<4>>,
    moves: Vec<JointMove>,
    singular_samples: usize,
    failed_samples: usize,
}

impl<T: CartesianTrajectory> ScaraReference<T> {
    /// A reference following `trajectory` with the elbows of `plan`.
    #[must_use]
    pub fn new(geometry: ScaraGeometry, trajectory: T, plan: ElbowPlan) -> Self {
        Self {
            geometry,
            trajectory,
            plan,
            last: None,
            moves: Vec::new(),
            singular_samples: 0,
            failed_samples: 0,
        }
    }

    /// Joint moves (planned elbow flips) that replace inverse kinematics while they last.
    #[must_use]
    pub fn with_joint_moves(mut self, moves: Vec<JointMove>) -> Self {
        self.moves = moves;
        self
    }

    /// The elbow plan.
    #[must_use]
    pub fn plan(&self) -> &ElbowPlan {
        &self.plan
    }

    /// The Cartesian reference.
    #[must_use]
    pub fn trajectory(&self) -> &T {
        &self.trajectory
    }

    /// The geometry.
    #[must_use]
    pub fn geometry(&self) -> &ScaraGeometry {
        &self.geometry
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

impl<T: CartesianTrajectory> ReferenceSource<4> for ScaraReference<T> {
    fn at(&mut self, t: f64) -> Setpoint<4> {
        let cartesian = self.trajectory.at(t);
        let planned = self
            .moves
            .iter()
            // A control sample within a nanosecond before a move's start is the move's first
            // (the starts are sums of durations, not exact multiples of the period).
            .find(|m| m.start_s <= t + 1e-9 && t < m.end_s())
            .map(|m| m.at(t));
        let joint = if let Some(j) = planned {
            j
        } else {
            match self
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
            }
        };
        self.last = Some(joint);
        Setpoint {
            joint,
            cartesian,
            wrench: Wrench::zeros(),
        }
    }
}
