//! Workspace classification (thesis Section 3.1.5), and an overview of elbow planning for a
//! whole reference (Section 4.4; in [`elbow_plan`](super::elbow_plan)).
//!
//! Every position in reach has two inverse-kinematics solutions, elbow up (`q2 > 0`) and
//! elbow down (`q2 < 0`); the joint limits (`docs/thesis.md` section 1: `q1` in `[-pi/2, pi/2]`,
//! `q2` in `[-7pi/8, 7pi/8]`, `d3` in `[0.1, 0.35] m`, `q4` in `[-pi, pi]`) cut the workspace
//! into zones reachable by both, by one only, or by neither ([`Reachability`], the red,
//! blue and purple areas of thesis Figure 3.4). Before a run, the planner
//! ([`ScaraGeometry::plan_elbows`](super::ScaraGeometry::plan_elbows), feature `std`) classifies every sample of the reference
//! and picks the configurations:
//!
//! - an unreachable sample is an error, reported before anything is simulated, naming the
//!   first few such samples ([`WorkspaceError::Unreachable`](super::WorkspaceError::Unreachable));
//! - if one configuration works for every sample, it is kept for the whole run: elbow up
//!   when both do (the thesis's arbitrary choice, Section 4.4, and the one its code makes),
//!   otherwise the one that does;
//! - otherwise the run starts in the configuration that works longest from the start and
//!   switches only when it must: each [`ElbowSwitch`](super::ElbowSwitch) says when, and the window of samples
//!   over which the switch could be made. [`SwitchPolicy`](super::SwitchPolicy) picks the time within the window:
//!   the last possible sample (default: "switch when the current elbow stops being
//!   feasible"), the first (what the thesis's code does: it takes the elbow-up solution
//!   wherever it is feasible) or the sample where the two solutions are closest in joint
//!   space (the smallest jump for the controller). Every policy gives the fewest switches.
//!
//! A switch is a jump of the joint reference (the thesis's Figure 4.14 shows the large
//! correction it causes); the planner only says where it is needed.

use nalgebra::Vector3;

use super::geometry::{Elbow, IkError, LimitViolation, ScaraGeometry};

/// Why a pose is reachable by neither elbow configuration.
///
/// # Example
///
/// ```
/// use armdyn::robots::scara::{Reachability, Reason, ScaraGeometry};
/// use nalgebra::Vector3;
///
/// let ik = ScaraGeometry::thesis();
/// match ik.classify(&Vector3::new(-0.5, 0.0, 0.1), 0.0) {
///     Reachability::Unreachable(Reason::JointLimits { up, down }) => {
///         assert_eq!((up.name, down.name), ("q1", "q1")); // behind the base
///     }
///     other => panic!("{other:?}"),
/// }
/// ```
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
pub enum Reason {
    /// No inverse-kinematics solution at all (outside the annulus the arm sweeps, or not
    /// finite).
    #[error("{}", Why(.0))]
    OutOfReach(IkError),
    /// Both solutions exist but each breaks a joint limit.
    #[error("elbow up: {up}; elbow down: {down}")]
    JointLimits {
        /// The first limit the elbow-up solution breaks.
        up: LimitViolation,
        /// The first limit the elbow-down solution breaks.
        down: LimitViolation,
    },
}

/// The reason of an [`IkError`] without the position (which the sample report states).
struct Why<'a>(&'a IkError);

impl core::fmt::Display for Why<'_> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match *self.0 {
            IkError::TooFar { radius, max, .. } => write!(
                f,
                "out of reach, {radius} m from the joint-1 axis, beyond l1 + l2 = {max} m"
            ),
            IkError::TooClose { radius, min, .. } => write!(
                f,
                "out of reach, {radius} m from the joint-1 axis, inside |l1 - l2| = {min} m"
            ),
            IkError::NonFinite { yaw, .. } => write!(f, "not finite (yaw {yaw} rad)"),
        }
    }
}

/// Which elbow configurations reach a pose within the joint limits.
///
/// # Example
///
/// ```
/// use armdyn::robots::scara::{Elbow, Reachability, ScaraGeometry};
/// use nalgebra::Vector3;
///
/// let ik = ScaraGeometry::thesis();
/// let middle = ik.classify(&Vector3::new(0.6, 0.0, 0.1), 0.0);
/// assert_eq!(middle, Reachability::Both);
/// assert!(middle.allows(Elbow::Down));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Reachability {
    /// Both elbow-up and elbow-down solutions are within the limits (with the arm exactly
    /// stretched the two coincide).
    Both,
    /// Only the elbow-up solution (`q2 > 0`) is within the limits.
    UpOnly,
    /// Only the elbow-down solution (`q2 < 0`) is within the limits.
    DownOnly,
    /// Neither.
    Unreachable(Reason),
}

impl Reachability {
    /// Whether the configuration `elbow` reaches the pose within the limits.
    ///
    /// ```
    /// use armdyn::robots::scara::{Elbow, Reachability};
    /// assert!(!Reachability::UpOnly.allows(Elbow::Down));
    /// ```
    pub fn allows(&self, elbow: Elbow) -> bool {
        matches!(
            (self, elbow),
            (Reachability::Both, _)
                | (Reachability::UpOnly, Elbow::Up)
                | (Reachability::DownOnly, Elbow::Down)
        )
    }

    /// Whether at least one configuration reaches the pose.
    ///
    /// ```
    /// use armdyn::robots::scara::Reachability;
    /// assert!(Reachability::DownOnly.is_reachable());
    /// ```
    pub fn is_reachable(&self) -> bool {
        !matches!(self, Reachability::Unreachable(_))
    }
}

impl ScaraGeometry {
    /// Classifies a pose (position in m, yaw in rad) by the elbow configurations that reach
    /// it within the joint limits ([`ScaraGeometry::inverse`] then
    /// [`ScaraGeometry::check_limits`] for each).
    ///
    /// # Example
    ///
    /// ```
    /// use armdyn::robots::scara::{Reachability, ScaraGeometry};
    /// use nalgebra::Vector3;
    ///
    /// let ik = ScaraGeometry::thesis();
    /// // The three zones of the thesis's workspace trial, along x = 0.25 m.
    /// assert_eq!(ik.classify(&Vector3::new(0.25, -0.4, 0.1), 0.0), Reachability::DownOnly);
    /// assert_eq!(ik.classify(&Vector3::new(0.25, 0.0, 0.1), 0.0), Reachability::Both);
    /// assert_eq!(ik.classify(&Vector3::new(0.25, 0.4, 0.1), 0.0), Reachability::UpOnly);
    /// ```
    pub fn classify(&self, position: &Vector3<f64>, yaw: f64) -> Reachability {
        let solve = |elbow| -> Result<Result<(), LimitViolation>, IkError> {
            let q = self.inverse(position, yaw, elbow)?;
            Ok(self.check_limits(&q))
        };
        match (solve(Elbow::Up), solve(Elbow::Down)) {
            (Err(e), _) | (_, Err(e)) => Reachability::Unreachable(Reason::OutOfReach(e)),
            (Ok(Ok(())), Ok(Ok(()))) => Reachability::Both,
            (Ok(Ok(())), Ok(Err(_))) => Reachability::UpOnly,
            (Ok(Err(_)), Ok(Ok(()))) => Reachability::DownOnly,
            (Ok(Err(up)), Ok(Err(down))) => {
                Reachability::Unreachable(Reason::JointLimits { up, down })
            }
        }
    }
}
