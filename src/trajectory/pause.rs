//! A Cartesian reference that stops smoothly at given instants, holds still, and resumes
//! where it stopped, shifted in time (feature `std`): the reference side of a planned
//! manoeuvre such as an elbow flip.
//!
//! Each pause at reference time `tau_p` slows the reference's clock `tau(t)` from 1 to 0 over
//! `ramp` seconds with the quintic blend `S(u) = 10 u^3 - 15 u^4 + 6 u^5` (`tau' = 1 - S`),
//! holds `tau = tau_p` for `hold` seconds, and brings it back to 1 the same way. Position,
//! velocity (`x'(tau) tau'`) and acceleration (`x''(tau) tau'^2 + x'(tau) tau''`) stay
//! continuous, and are exactly zero during the hold. Each pause shifts the rest of the
//! reference by `ramp + hold`.

use super::CartesianTrajectory;
use crate::target::CartesianTarget;

/// One pause.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pause {
    /// Reference time at which the reference stands still, s.
    pub at_s: f64,
    /// Length of the stop and of the start, s (> 0).
    pub ramp_s: f64,
    /// How long it stands still, s (>= 0).
    pub hold_s: f64,
}

impl Pause {
    /// How much later everything after the pause happens, s.
    #[must_use]
    pub fn shift_s(&self) -> f64 {
        self.ramp_s + self.hold_s
    }
}

/// `inner` with pauses (sorted by `at_s`, each after the previous one's end).
#[derive(Clone, Debug)]
pub struct Paused<T> {
    inner: T,
    pauses: Vec<Pause>,
}

/// The blend, its integral and its derivative at `u` in `[0, 1]`.
fn blend(u: f64) -> (f64, f64, f64) {
    let u = u.clamp(0.0, 1.0);
    let (u2, u3) = (u * u, u * u * u);
    let s = u3 * (10.0 - 15.0 * u + 6.0 * u2);
    let integral = u2 * u2 * (2.5 - 3.0 * u + u2);
    let ds = 30.0 * u2 * (1.0 - u) * (1.0 - u);
    (s, integral, ds)
}

impl<T: CartesianTrajectory> Paused<T> {
    /// `inner` with `pauses` (sorted by reference time, not overlapping: each pause's start
    /// ramp ends before the next one's stop ramp begins).
    ///
    /// # Errors
    ///
    /// A message naming the pause if they are unsorted, overlap, or have a non-positive ramp
    /// or a negative hold.
    pub fn new(inner: T, pauses: Vec<Pause>) -> Result<Self, String> {
        for (i, p) in pauses.iter().enumerate() {
            if !(p.ramp_s > 0.0 && p.hold_s >= 0.0 && p.at_s.is_finite()) {
                return Err(format!("pause {i}: needs a ramp > 0 s and a hold >= 0 s"));
            }
            if i > 0 && p.at_s - p.ramp_s / 2.0 < pauses[i - 1].at_s + pauses[i - 1].ramp_s / 2.0 {
                return Err(format!("pause {i} overlaps the previous one"));
            }
        }
        Ok(Self { inner, pauses })
    }

    /// The pauses.
    #[must_use]
    pub fn pauses(&self) -> &[Pause] {
        &self.pauses
    }

    /// The wall-clock interval `[start, end]` (s) of pause `i`'s hold.
    #[must_use]
    pub fn hold_interval(&self, i: usize) -> (f64, f64) {
        let before: f64 = self.pauses[..i].iter().map(Pause::shift_s).sum();
        let p = &self.pauses[i];
        let start = p.at_s + before + p.ramp_s / 2.0;
        (start, start + p.hold_s)
    }

    /// The reference clock at wall time `t`: `(tau, tau', tau'')`.
    #[must_use]
    pub fn clock(&self, t: f64) -> (f64, f64, f64) {
        let mut shift = 0.0;
        for p in &self.pauses {
            let a = p.at_s + shift - p.ramp_s / 2.0;
            if t < a {
                break;
            }
            let d = p.ramp_s;
            let b = a + d + p.hold_s;
            if t <= a + d {
                let (s, integral, ds) = blend((t - a) / d);
                let u = (t - a) / d;
                return (a - shift + d * (u - integral), 1.0 - s, -ds / d);
            }
            if t <= b {
                return (p.at_s, 0.0, 0.0);
            }
            if t <= b + d {
                let (s, integral, ds) = blend((t - b) / d);
                return (p.at_s + d * integral, s, ds / d);
            }
            shift += p.shift_s();
        }
        (t - shift, 1.0, 0.0)
    }
}

impl<T: CartesianTrajectory> CartesianTrajectory for Paused<T> {
    fn duration(&self) -> f64 {
        self.inner.duration() + self.pauses.iter().map(Pause::shift_s).sum::<f64>()
    }

    fn at(&self, t: f64) -> CartesianTarget {
        let (tau, rate, accel) = self.clock(t);
        let x = self.inner.at(tau);
        if rate == 1.0 && accel == 0.0 {
            return x;
        }
        CartesianTarget {
            position: x.position,
            orientation: x.orientation,
            velocity: x.velocity * rate,
            angular_velocity: x.angular_velocity * rate,
            acceleration: x.acceleration * (rate * rate) + x.velocity * accel,
            angular_acceleration: x.angular_acceleration * (rate * rate)
                + x.angular_velocity * accel,
        }
    }
}
