//! The task rows a Cartesian controller keeps of the 6 x N geometric Jacobian (rows
//! `vx vy vz wx wy wz`): N of them, so that the reduced Jacobian `J_r` is square, three of
//! them the linear velocity (rows 0, 1, 2). Shared by the hybrid, impedance and admittance
//! laws, which all act on the linear rows (the contact normal) and leave the others (e.g.
//! the SCARA's `wz`, row 5) to their own rule.

use super::jacobian_factor::JacobianFactor;
use crate::model::{Jacobian, JointMatrix, JointVector};
use crate::target::Task;
use nalgebra::Vector3;

/// N validated task rows of the 6 x N Jacobian: each in 0..6, distinct, including 0, 1
/// and 2 (the linear velocity), e.g. `[0, 1, 2, 5]` for a SCARA.
///
/// A task-space vector (a reduced twist or wrench: m/s and rad/s, or N and N m) has one
/// entry per kept row, in the order of the rows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TaskRows<const N: usize> {
    rows: [usize; N],
}

impl<const N: usize> TaskRows<N> {
    /// `None` if `rows` repeats a row, names one outside 0..6 or lacks a linear row (0, 1
    /// or 2).
    #[must_use]
    pub fn new(rows: [usize; N]) -> Option<Self> {
        for (i, r) in rows.iter().enumerate() {
            if *r >= 6 || rows[..i].contains(r) {
                return None;
            }
        }
        if ![0, 1, 2].iter().all(|row| rows.contains(row)) {
            return None;
        }
        Some(Self { rows })
    }

    /// The rows of a robot's task ([`Task`]), when it has exactly `N` directions including
    /// the three translations (a square reduced Jacobian); `None` otherwise (a redundant
    /// arm, or a planar one).
    ///
    /// ```
    /// use armdyn::control::task_rows::TaskRows;
    /// use armdyn::target::Task;
    /// assert_eq!(TaskRows::<4>::of_task(Task::POSITION_AND_YAW).unwrap().rows(), &[0, 1, 2, 5]);
    /// assert!(TaskRows::<7>::of_task(Task::FULL).is_none());
    /// ```
    #[must_use]
    pub fn of_task(task: Task) -> Option<Self> {
        if task.len() != N {
            return None;
        }
        let mut rows = [0usize; N];
        for (slot, r) in rows.iter_mut().zip(task.rows()) {
            *slot = r;
        }
        Self::new(rows)
    }

    /// The rows of the Jacobian kept, in task-space order.
    #[must_use]
    pub fn rows(&self) -> &[usize; N] {
        &self.rows
    }

    /// The task-space index of Jacobian row `row` (0..6), if it is kept.
    #[must_use]
    pub fn index_of(&self, row: usize) -> Option<usize> {
        self.rows.iter().position(|r| *r == row)
    }

    /// A task-space vector whose linear rows are `v` (m/s or N, or any 3-vector in the base
    /// frame) and the others zero.
    ///
    /// Each entry is chosen by comparing its row with 0, 1 and 2 (selects on values in
    /// registers), not written at an index known only at run time: an indexed store read
    /// back as a vector stalls store forwarding (about 10 ns of the SCARA's hybrid step).
    #[must_use]
    #[inline(always)]
    pub fn lift(&self, v: &Vector3<f64>) -> JointVector<N> {
        JointVector::<N>::from_fn(|i, _| match self.rows[i] {
            0 => v[0],
            1 => v[1],
            2 => v[2],
            _ => 0.0,
        })
    }

    /// The reduced Jacobian `J_r`, N x N: the kept rows of `j` (m/s and rad/s per unit
    /// joint velocity).
    #[must_use]
    #[inline(always)]
    pub fn reduce(&self, j: &Jacobian<N>) -> JointMatrix<N> {
        JointMatrix::<N>::from_fn(|r, c| j[(self.rows[r], c)])
    }

    /// The factorisation of the reduced Jacobian `J_r` ([`JacobianFactor::from_rows`]: read
    /// from `j` entry by entry, no copy of `J_r` in memory).
    #[must_use]
    #[inline(always)]
    pub fn factor(&self, j: &Jacobian<N>) -> JacobianFactor<f64, N> {
        JacobianFactor::from_rows(j, &self.rows)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rows_are_validated() {
        assert!(TaskRows::new([0, 1, 2, 5]).is_some());
        assert!(TaskRows::new([5, 2, 0, 1]).is_some());
        assert!(TaskRows::new([0, 1, 2]).is_some());
        assert!(TaskRows::new([0, 1, 1, 2]).is_none(), "repeated row");
        assert!(TaskRows::new([0, 1, 2, 6]).is_none(), "row outside 0..6");
        assert!(
            TaskRows::new([0, 1, 3, 5]).is_none(),
            "linear row 2 missing"
        );
    }

    #[test]
    fn lift_places_the_linear_rows() {
        let rows = TaskRows::new([5, 2, 0, 1]).unwrap();
        let v = Vector3::new(1.0, 2.0, 3.0);
        let x = rows.lift(&v);
        assert_eq!(x, JointVector::<4>::new(0.0, 3.0, 1.0, 2.0));
        assert_eq!(rows.index_of(5), Some(0));
        assert_eq!(rows.index_of(4), None);
    }

    #[test]
    fn reduce_keeps_the_rows_in_order() {
        let rows = TaskRows::new([0, 1, 2, 5]).unwrap();
        let j = Jacobian::<4>::from_fn(|r, c| (10 * r + c) as f64);
        let jr = rows.reduce(&j);
        for (i, &r) in rows.rows().iter().enumerate() {
            assert_eq!(jr.row(i), j.row(r));
        }
    }

    #[test]
    fn factor_is_that_of_the_reduced_jacobian() {
        let rows = TaskRows::new([0, 1, 2, 5]).unwrap();
        let j = Jacobian::<4>::from_fn(|r, c| if r == c + 1 { 2.0 } else { 0.1 * (r * c) as f64 } + 1.0);
        let dx = JointVector::<4>::new(0.3, -0.2, 0.1, 0.05);
        let by_rows = rows.factor(&j);
        let by_matrix = JacobianFactor::new(&rows.reduce(&j));
        assert_eq!(by_rows.how(), by_matrix.how());
        assert_eq!(by_rows.solve(&dx), by_matrix.solve(&dx));
        assert_eq!(by_rows.transpose_solve(&dx), by_matrix.transpose_solve(&dx));
    }
}
