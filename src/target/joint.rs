//! A joint-space reference at one instant.

use nalgebra::SVector;

/// `N` joint values.
type JointVector<const N: usize> = SVector<f64, N>;

/// A joint-space reference at one instant: positions (rad or m), velocities, accelerations.
///
/// ```
/// use armdyn::target::JointTarget;
/// let t = JointTarget::<3>::at_rest([0.1, -0.2, 0.3].into());
/// assert_eq!(t.qd, nalgebra::Vector3::zeros());
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JointTarget<const N: usize> {
    /// Desired joint positions, rad or m.
    pub q: JointVector<N>,
    /// Desired joint velocities, rad/s or m/s.
    pub qd: JointVector<N>,
    /// Desired joint accelerations, rad/s^2 or m/s^2.
    pub qdd: JointVector<N>,
}

impl<const N: usize> JointTarget<N> {
    /// Positions `q` with zero velocity and acceleration.
    #[must_use]
    pub fn at_rest(q: JointVector<N>) -> Self {
        Self {
            q,
            qd: JointVector::zeros(),
            qdd: JointVector::zeros(),
        }
    }
}
