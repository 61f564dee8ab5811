//! When the control samples are taken (on their grid, or jittered) and when their torques
//! reach the plant (at once, or delayed), in plant steps.

use super::faults::MAX_DELAY_STEPS;
use super::SimConfig;
use crate::model::JointVector;
use rand::rngs::Xoshiro256PlusPlus;
use rand::{RngExt, SeedableRng};

/// The plant step of each control sample: `k substeps`, or that plus a jitter draw rounded
/// to the plant step, kept after the previous sample and within the run.
pub(crate) struct Schedule {
    next_k: usize,
    next_at: usize,
    steps: usize,
    substeps: usize,
    jitter: Option<(Xoshiro256PlusPlus, f64)>,
}

impl Schedule {
    pub(crate) fn new<const N: usize>(
        config: &SimConfig<N>,
        steps: usize,
        substeps: usize,
        h: f64,
    ) -> Self {
        Self {
            next_k: 0,
            next_at: 0,
            steps,
            substeps,
            jitter: config
                .faults
                .jitter
                .map(|j| (Xoshiro256PlusPlus::seed_from_u64(j.seed), j.max_s / h)),
        }
    }

    /// Whether a sample is due at plant step `i` (then the next one is scheduled).
    pub(crate) fn due(&mut self, i: usize) -> bool {
        if self.next_k > self.steps || i != self.next_at {
            return false;
        }
        self.next_k += 1;
        let nominal = self.next_k * self.substeps;
        let at = match self.jitter.as_mut() {
            None => nominal,
            Some((rng, max_steps)) => {
                let u: f64 = rng.random_range(-1.0..=1.0);
                let offset = libm::round(u * *max_steps);
                // Whole and small: the casts are exact.
                (nominal as i64 + offset as i64).max(0) as usize
            }
        };
        let total = self.steps * self.substeps;
        self.next_at = at.clamp(i + 1, total.max(i + 1));
        true
    }
}

/// Torques on their way to the plant: each with the plant step it arrives at, in order; a
/// newer torque that arrives no later than older ones supersedes them.
pub(crate) struct Pending<const N: usize> {
    queue: [(usize, JointVector<N>); MAX_DELAY_STEPS + 1],
    len: usize,
}

impl<const N: usize> Default for Pending<N> {
    fn default() -> Self {
        Self {
            queue: [(0, JointVector::zeros()); MAX_DELAY_STEPS + 1],
            len: 0,
        }
    }
}

impl<const N: usize> Pending<N> {
    /// `tau` arriving at plant step `at`.
    pub(crate) fn push(&mut self, at: usize, tau: JointVector<N>) {
        while self.len > 0 && self.queue[self.len - 1].0 >= at {
            self.len -= 1;
        }
        if self.len == self.queue.len() {
            self.queue.copy_within(1.., 0);
            self.len -= 1;
        }
        self.queue[self.len] = (at, tau);
        self.len += 1;
    }

    /// The newest torque arrived by plant step `i`, if any arrived since the last call.
    pub(crate) fn take(&mut self, i: usize) -> Option<JointVector<N>> {
        let arrived = self.queue[..self.len]
            .iter()
            .take_while(|(at, _)| *at <= i)
            .count();
        if arrived == 0 {
            return None;
        }
        let tau = self.queue[arrived - 1].1;
        self.queue.copy_within(arrived..self.len, 0);
        self.len -= arrived;
        Some(tau)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_delayed_torque_arrives_late_and_a_newer_one_supersedes_it() {
        let tau = |x: f64| JointVector::<2>::repeat(x);
        let mut p = Pending::<2>::default();
        p.push(0, tau(1.0));
        assert_eq!(p.take(0), Some(tau(1.0)));
        p.push(3, tau(2.0));
        p.push(4, tau(3.0));
        assert_eq!((p.take(1), p.take(2)), (None, None));
        assert_eq!(p.take(3), Some(tau(2.0)));
        p.push(4, tau(4.0));
        assert_eq!(p.take(5), Some(tau(4.0)));
        assert_eq!(p.take(6), None);
    }
}
