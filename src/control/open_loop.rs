//! Open-loop torques: a given torque history held between its samples, or zero.

use super::{Controller, ControllerInput};
use crate::model::JointVector;

/// Plays back `torques[k]` from `times[k]` until `times[k + 1]` (zero-order hold; the last
/// sample is held to the end; before `times[0]` the first is used). Borrowed slices: no
/// allocation. `times` must be strictly increasing (checked by [`OpenLoop::new`]).
#[derive(Clone, Debug)]
pub struct OpenLoop<'a, const N: usize> {
    times: &'a [f64],
    torques: &'a [JointVector<N>],
    index: usize,
}

/// Why a torque history was refused.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
pub enum OpenLoopError {
    /// No samples, or `times` and `torques` differ in length.
    #[error("torque history needs as many times as torque rows, at least one (got {times} and {torques})")]
    Length {
        /// Number of times.
        times: usize,
        /// Number of torque rows.
        torques: usize,
    },
    /// Times not strictly increasing or not finite at this index.
    #[error("torque history: time {index} is not finite or not after the previous one")]
    Times {
        /// Row index (from 0).
        index: usize,
    },
}

impl<'a, const N: usize> OpenLoop<'a, N> {
    /// Validates and wraps a torque history.
    ///
    /// # Errors
    ///
    /// [`OpenLoopError`] if lengths differ, it is empty, or times are not increasing.
    pub fn new(times: &'a [f64], torques: &'a [JointVector<N>]) -> Result<Self, OpenLoopError> {
        if times.is_empty() || times.len() != torques.len() {
            return Err(OpenLoopError::Length {
                times: times.len(),
                torques: torques.len(),
            });
        }
        for (i, t) in times.iter().enumerate() {
            if !t.is_finite() || (i > 0 && *t <= times[i - 1]) {
                return Err(OpenLoopError::Times { index: i });
            }
        }
        Ok(Self {
            times,
            torques,
            index: 0,
        })
    }
}

impl<const N: usize> Controller<N> for OpenLoop<'_, N> {
    fn name(&self) -> &'static str {
        "open-loop"
    }

    fn reset(&mut self) {
        self.index = 0;
    }

    fn step(&mut self, input: &ControllerInput<'_, N>, _dt: f64) -> JointVector<N> {
        // Times are visited in order: advance while the next sample has started. A tiny
        // tolerance absorbs the rounding of k * dt against times written in decimal.
        while self.index + 1 < self.times.len() && self.times[self.index + 1] <= input.t + 1e-9 {
            self.index += 1;
        }
        self.torques[self.index]
    }
}

/// Zero torque at every sample (free motion under gravity and contact only).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ZeroTorque;

impl<const N: usize> Controller<N> for ZeroTorque {
    fn name(&self) -> &'static str {
        "zero"
    }

    fn reset(&mut self) {}

    fn step(&mut self, _input: &ControllerInput<'_, N>, _dt: f64) -> JointVector<N> {
        JointVector::zeros()
    }
}
