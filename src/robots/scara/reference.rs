//! A [`ReferenceSource`] for the SCARA: Cartesian reference -> elbow plan -> inverse
//! kinematics -> joint target, plus the desired contact wrench.

use crate::control::task_frame::TaskFrame;
use crate::model::Wrench;
use crate::robots::scara::elbow_flip::JointMove;
use crate::robots::scara::{ElbowPlan, ScaraGeometry};
use crate::sim::{ReferenceSource, Setpoint};
use crate::target::JointTarget;
use crate::trajectory::force_csv::SampledForce;
use crate::trajectory::{CartesianTrajectory, ForceProfile};

/// The desired contact force: a signed magnitude over time along the inward normal of the
/// controller's (nominal) surface at the reference point.
#[derive(Clone, Debug, PartialEq)]
pub struct DesiredForce {
    /// The magnitude as the thesis's profiles give it (negative = pressing).
    pub profile: ForceShape,
    /// Where the normal comes from.
    pub frame: TaskFrame,
}

/// The shape of a desired force over time.
#[derive(Clone, Debug, PartialEq)]
pub enum ForceShape {
    /// A thesis profile (constant or variable, zero before its start).
    Profile(ForceProfile),
    /// Sampled magnitudes (N, positive pressing), zero before `start_s`.
    Sampled {
        /// The samples.
        samples: SampledForce,
        /// Start time, s.
        start_s: f64,
    },
}

impl DesiredForce {
    /// The desired force along base z (the thesis's `fz_d`, negative pushing down).
    #[must_use]
    pub fn thesis(profile: ForceProfile) -> Self {
        Self {
            profile: ForceShape::Profile(profile),
            frame: TaskFrame::thesis(),
        }
    }

    /// The signed magnitude at `t` (N, negative pressing).
    #[must_use]
    pub fn signed(&self, t: f64) -> f64 {
        match &self.profile {
            ForceShape::Profile(p) => p.fz(t),
            ForceShape::Sampled { samples, start_s } => {
                if t < *start_s {
                    0.0
                } else {
                    -samples.at(t)
                }
            }
        }
    }

    /// The desired wrench of the tool on the surface at `t` with the reference at
    /// `position` (m): the signed magnitude along the outward normal there.
    #[must_use]
    pub fn wrench(&self, t: f64, position: &nalgebra::Vector3<f64>) -> Wrench {
        let f = self.frame.normal_at(position) * self.signed(t);
        // `+ 0.0` turns the -0.0 of `0 * negative` into 0.0.
        Wrench::new(f.x + 0.0, f.y + 0.0, f.z + 0.0, 0.0, 0.0, 0.0)
    }
}

/// Joint targets from a Cartesian reference, with the elbow chosen by a plan made before the
/// run (thesis Section 4.4). Inverse kinematics runs at every control sample; near the
/// stretched-arm singularity the joint velocity is damped (see
/// [`ScaraGeometry::joint_target`]) and the sample is counted in
/// [`ScaraReference::singular_samples`].
pub struct ScaraReference<'a, T: ?Sized> {
    geometry: ScaraGeometry,
    trajectory: &'a T,
    plan: ElbowPlan,
    force: Option<DesiredForce>,
    last: Option<JointTarget<4>>,
    moves: Vec<JointMove>,
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
        force: Option<DesiredForce>,
    ) -> Self {
        Self {
            geometry,
            trajectory,
            plan,
            force,
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
        let planned = self
            .moves
            .iter()
            .find(|m| m.start_s <= t && t < m.end_s())
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
        let wrench = self
            .force
            .as_ref()
            .map_or_else(Wrench::zeros, |f| f.wrench(t, &cartesian.position));
        Setpoint {
            joint,
            cartesian,
            wrench,
        }
    }
}
