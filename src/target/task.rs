//! A robot's task: the task-space directions its end effector can be controlled in.

use nalgebra::{UnitQuaternion, Vector3, Vector6};

use super::{angle::wrap_angle, orientation};

/// The names of the six task directions, in the order of the geometric Jacobian's rows:
/// translation along base x, y, z (`vx vy vz`), rotation about base x, y, z (`wx wy wz`).
pub const DIRECTION_NAMES: [&str; 6] = ["x", "y", "z", "rx", "ry", "rz"];

/// Which rotations a task controls (the task's rows 3 to 5).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Rotations {
    /// None: a positioning task.
    None,
    /// The rotation about base z alone (a SCARA's yaw); its error is the wrapped yaw
    /// difference `wrap(yaw_d - yaw)`, yaw = `atan2(R10, R00)`.
    Yaw,
    /// All three; the error is the SO(3) logarithm [`orientation::error`].
    Full,
}

/// The task-space directions a robot's end effector is controlled in: a set of rows of the
/// 6 x N geometric Jacobian (`vx vy vz wx wy wz`, named `x y z rx ry rz`): any translations,
/// and then no rotation, the rotation about base z alone, or all three rotations.
///
/// Each robot states its task in its description (`task = ["x", "y", "z", "rz"]` for the
/// SCARA; all six by default for six joints or more); the generator checks that the task's
/// rows of the Jacobian have full rank and writes them beside the model (`TASK_ROWS`), and
/// [`RobotModel::TASK`](crate::model::RobotModel::TASK) gives the task. A 6-joint arm
/// controls all six directions; a 7-joint arm all six with one redundant degree of freedom
/// ([`Self::redundancy`]).
///
/// ```
/// use armdyn::target::{Rotations, Task};
/// let scara = Task::from_rows(&[0, 1, 2, 5]).unwrap();
/// assert_eq!((scara.len(), scara.rotations()), (4, Rotations::Yaw));
/// assert_eq!(scara.names(), vec!["x", "y", "z", "rz"]);
/// assert_eq!(Task::FULL.redundancy(7), 1);
/// assert!(Task::from_rows(&[0, 1, 2, 3]).is_none()); // rotation about x alone
/// assert_eq!(Task::from_rows(&[0, 1]).unwrap().len(), 2); // a planar arm's x, y
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Task {
    /// Bit `r` set: Jacobian row `r` is a task direction.
    mask: u8,
}

impl Task {
    /// Position and orientation: all six directions.
    pub const FULL: Self = Self { mask: 0b11_1111 };
    /// Position and yaw: `x, y, z, rz` (a SCARA's).
    pub const POSITION_AND_YAW: Self = Self { mask: 0b10_0111 };
    /// Position only: `x, y, z`.
    pub const POSITION: Self = Self { mask: 0b00_0111 };

    /// The task of the given Jacobian rows (any order, no repeats): `None` for an empty set, a
    /// row outside 0..6, a repeated row, or rotations other than none, `rz` alone, or all
    /// three.
    #[must_use]
    pub const fn from_rows(rows: &[usize]) -> Option<Self> {
        let mut mask = 0u8;
        let mut i = 0;
        while i < rows.len() {
            if rows[i] >= 6 || mask & (1 << rows[i]) != 0 {
                return None;
            }
            mask |= 1 << rows[i];
            i += 1;
        }
        match mask >> 3 {
            _ if mask == 0 => None,
            0b000 | 0b100 | 0b111 => Some(Self { mask }),
            _ => None,
        }
    }

    /// The task from direction names ([`DIRECTION_NAMES`]).
    ///
    /// # Errors
    ///
    /// A message naming an unknown name, or a set of directions that is not a task.
    #[cfg(feature = "std")]
    pub fn from_names(names: &[&str]) -> Result<Self, std::string::String> {
        let mut rows = [0usize; 6];
        if names.len() > 6 {
            return Err(format!("{} directions; a task has at most 6", names.len()));
        }
        for (i, name) in names.iter().enumerate() {
            rows[i] = DIRECTION_NAMES
                .iter()
                .position(|d| d == name)
                .ok_or_else(|| {
                    format!(
                        "unknown task direction `{name}`; known: {}",
                        DIRECTION_NAMES.join(", ")
                    )
                })?;
        }
        Self::from_rows(&rows[..names.len()]).ok_or_else(|| {
            format!(
                "`{}` is not a task: distinct directions, with no rotation, rz alone, or rx, ry and rz",
                names.join(", ")
            )
        })
    }

    /// Which rotations it controls.
    #[must_use]
    pub const fn rotations(&self) -> Rotations {
        match self.mask >> 3 {
            0b000 => Rotations::None,
            0b100 => Rotations::Yaw,
            _ => Rotations::Full,
        }
    }

    /// How many directions, 1 to 6.
    #[must_use]
    #[allow(clippy::len_without_is_empty)] // never empty
    pub const fn len(&self) -> usize {
        self.mask.count_ones() as usize
    }

    /// Whether Jacobian row `row` (0..6) is a task direction.
    #[must_use]
    pub const fn controls(&self, row: usize) -> bool {
        row < 6 && self.mask & (1 << row) != 0
    }

    /// The task's rows as a mask over the six rows (1 for a task row, 0 otherwise).
    #[must_use]
    pub fn mask(&self) -> Vector6<f64> {
        Vector6::from_fn(|r, _| if self.controls(r) { 1.0 } else { 0.0 })
    }

    /// The rows, in order.
    pub fn rows(&self) -> impl Iterator<Item = usize> + '_ {
        (0..6).filter(|r| self.controls(*r))
    }

    /// The direction names, in order.
    #[must_use]
    #[cfg(feature = "std")]
    pub fn names(&self) -> std::vec::Vec<&'static str> {
        self.rows().map(|r| DIRECTION_NAMES[r]).collect()
    }

    /// Degrees of freedom left over by a robot of `dof` joints: `dof - len` (0 if it has
    /// fewer joints than directions, which the generator refuses).
    #[must_use]
    pub const fn redundancy(&self, dof: usize) -> usize {
        dof.saturating_sub(self.len())
    }

    /// The pose error in the task's directions, `[e_p; e_o]` (m, rad), zero in the others:
    /// `e_p = p_d - p` (its task rows); `e_o` the SO(3) logarithm `log(R_d R^T)` for a full task, the wrapped
    /// yaw difference about z for a yaw task, zero for a positioning task.
    ///
    /// ```
    /// use armdyn::target::{orientation::from_yaw, Task};
    /// use nalgebra::Vector3;
    /// let e = Task::POSITION_AND_YAW.pose_error(
    ///     &Vector3::new(1.0, 0.0, 0.0), &from_yaw(3.0),
    ///     &Vector3::zeros(), &from_yaw(-3.0),
    /// );
    /// assert!((e[5] - (6.0 - 2.0 * std::f64::consts::PI)).abs() < 1e-15 && e[0] == 1.0);
    /// ```
    #[must_use]
    pub fn pose_error(
        &self,
        desired_position: &Vector3<f64>,
        desired: &UnitQuaternion<f64>,
        position: &Vector3<f64>,
        actual: &UnitQuaternion<f64>,
    ) -> Vector6<f64> {
        let d = desired_position - position;
        let e_p = Vector3::from_fn(|r, _| if self.controls(r) { d[r] } else { 0.0 });
        let e_o = match self.rotations() {
            Rotations::None => Vector3::zeros(),
            Rotations::Yaw => Vector3::new(
                0.0,
                0.0,
                wrap_angle(orientation::yaw(desired) - orientation::yaw(actual)),
            ),
            Rotations::Full => orientation::error(desired, actual),
        };
        Vector6::new(e_p.x, e_p.y, e_p.z, e_o.x, e_o.y, e_o.z)
    }
}
