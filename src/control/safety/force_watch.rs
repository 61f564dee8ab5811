//! The contact force over time: its rate, its oscillation and the loss of contact.
//!
//! The oscillation detector is a band-limited amplitude, not an energy: the force error
//! `e = |f| - |f_d|` through a second-order Butterworth high-pass (corner `f_hp`, bilinear
//! transform at the control period), and the RMS of that over a first-order window
//! (`ms += a (e_hp^2 - ms)`, `a = dt / (tau + dt)`). A contact oscillation is a sustained
//! component of the force error above the force loop's bandwidth; a constant error (a bias,
//! a slow approach) is not one, and the high-pass removes it. Unlike an energy observer it
//! needs no model of the contact (its stiffness is what changes when a surface is softer or
//! harder than assumed) and no mode frequency, which moves with the stiffness (sqrt(10) for
//! a tenfold step).

use super::limits::{ForceLimits, OSCILLATION_SWINGS};
use super::trip::{Trip, TripCause};
use nalgebra::RealField;

/// Samples of the rate's window ring (the window is at most this many periods).
pub const RATE_RING: usize = 64;

/// State of the force checks (no allocation).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ForceWatch<T> {
    ring: [T; RATE_RING],
    filled: usize,
    head: usize,
    hp: [T; 4],
    derived: Derived<T>,
    ms: T,
    armed: bool,
    controlled_for_s: T,
    swings: [T; OSCILLATION_SWINGS],
    swing_count: usize,
    swing_sign: i8,
    established: bool,
    low_for_s: T,
    peak_rate: T,
    peak_rms: T, // a mean square until read
}

/// What the checks derive from the limits and the period, computed when the period changes.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Derived<T> {
    /// The period they are for, s (NaN: none yet).
    dt: T,
    /// The limits they are for: `[rate_window_s, oscillation_hz, oscillation_window_s,
    /// oscillation_arm_s, loss_s]`.
    from: [T; 5],
    /// The rate's window in periods, and `1 / (w dt)`, 1/s.
    window: usize,
    inverse_window_s: T,
    /// The high-pass's `[b0, b1, a1, a2]` (`b2 = b0`).
    high_pass: [T; 4],
    /// The RMS window's gain `dt / (tau + dt)`.
    rms_gain: T,
    /// The time under force control from which the detector runs, s.
    arm_s: T,
    /// The time below the loss fraction that trips, s.
    loss_s: T,
}

impl<T: RealField + Copy> Derived<T> {
    /// None yet: its period is NaN, equal to none.
    fn none() -> Self {
        Self {
            dt: T::zero() / T::zero(),
            from: [T::zero(); 5],
            window: 1,
            inverse_window_s: T::zero(),
            high_pass: [T::zero(); 4],
            rms_gain: T::zero(),
            arm_s: T::zero(),
            loss_s: T::zero(),
        }
    }

    /// The limits the derived values depend on.
    fn key(limits: &ForceLimits<T>) -> [T; 5] {
        [
            limits.rate_window_s,
            limits.oscillation_hz,
            limits.oscillation_window_s,
            limits.oscillation_arm_s,
            limits.loss_s,
        ]
    }

    /// Whether they are those of `limits` at the period `dt`.
    #[inline(always)]
    fn is_for(&self, limits: &ForceLimits<T>, dt: T) -> bool {
        let key = Self::key(limits);
        (0..5).fold(dt == self.dt, |same, i| same & (key[i] == self.from[i]))
    }

    /// For `limits` at the period `dt` (s).
    fn new(limits: &ForceLimits<T>, dt: T) -> Self {
        let periods =
            nalgebra::try_convert::<T, f64>((limits.rate_window_s / dt).round()).unwrap_or(1.0);
        // Saturating and in [1, RATE_RING - 1] (NaN: 1).
        let window = if periods.is_nan() {
            1
        } else {
            (periods as usize).clamp(1, RATE_RING - 1)
        };
        // Second-order Butterworth high-pass at `oscillation_hz`, bilinear at `dt`.
        let two: T = nalgebra::convert(2.0);
        let sqrt2 = two.sqrt();
        let k = (T::pi() * limits.oscillation_hz * dt).tan();
        let norm = T::one() / (T::one() + sqrt2 * k + k * k);
        // Within a part in 10^6 of a period: a sum of periods is not exact.
        let tolerance = dt * nalgebra::convert(1e-6);
        Self {
            dt,
            from: Self::key(limits),
            window,
            inverse_window_s: T::one() / (dt * nalgebra::convert(window as f64)),
            high_pass: [
                norm,
                -two * norm,
                two * (k * k - T::one()) * norm,
                (T::one() - sqrt2 * k + k * k) * norm,
            ],
            rms_gain: dt / (limits.oscillation_window_s + dt),
            arm_s: limits.oscillation_arm_s - tolerance,
            loss_s: limits.loss_s - tolerance,
        }
    }
}

impl<T: RealField + Copy> Default for ForceWatch<T> {
    fn default() -> Self {
        Self {
            ring: [T::zero(); RATE_RING],
            filled: 0,
            head: 0,
            hp: [T::zero(); 4],
            derived: Derived::none(),
            ms: T::zero(),
            armed: false,
            controlled_for_s: T::zero(),
            swings: [T::zero(); OSCILLATION_SWINGS],
            swing_count: 0,
            swing_sign: 0,
            established: false,
            low_for_s: T::zero(),
            peak_rate: T::zero(),
            peak_rms: T::zero(),
        }
    }
}

impl<T: RealField + Copy> ForceWatch<T> {
    /// Largest force rate seen, N/s.
    #[must_use]
    pub fn peak_rate(&self) -> T {
        self.peak_rate
    }

    /// Largest oscillation RMS seen, N.
    #[must_use]
    pub fn peak_rms(&self) -> T {
        self.peak_rms.sqrt()
    }

    /// One period: the accepted force norm `f` (N), its reference's norm `f_ref` (N),
    /// whether the force is controlled, at time `t`, period `dt` (s) (what the limits give
    /// per period is computed when the period or the limits change).
    ///
    /// # Errors
    ///
    /// The [`Trip`] of the first check that fails: rate, oscillation, contact lost.
    #[inline(always)]
    pub fn step(
        &mut self,
        limits: &ForceLimits<T>,
        t: T,
        f: T,
        f_ref: T,
        force_controlled: bool,
        dt: T,
    ) -> Result<(), Trip<T>> {
        if !self.derived.is_for(limits, dt) {
            self.derived = Derived::new(limits, dt);
        }
        let rate = self.rate(f);
        if rate > self.peak_rate {
            self.peak_rate = rate;
        }
        if rate > limits.max_rate_n_s {
            return Err(Trip {
                cause: TripCause::ForceRate,
                t,
                value: rate,
                limit: limits.max_rate_n_s,
            });
        }
        if !force_controlled {
            self.armed = false;
            self.controlled_for_s = T::zero();
            self.swing_count = 0;
            self.swing_sign = 0;
            self.established = false;
            self.low_for_s = T::zero();
            return Ok(());
        }
        // The mean square, compared with the squared limit (no square root per period).
        let (ms, swing) = if self.controlled_for_s >= self.derived.arm_s {
            self.oscillation(f - f_ref)
        } else {
            (T::zero(), T::zero())
        };
        self.controlled_for_s += dt;
        if ms > self.peak_rms {
            self.peak_rms = ms;
        }
        if let Some(max) = limits.oscillation_rms_n {
            let sign = if swing > max {
                1
            } else if swing < -max {
                -1
            } else {
                0
            };
            if sign != 0 && sign != self.swing_sign {
                self.swing_sign = sign;
                self.swings[self.swing_count % OSCILLATION_SWINGS] = t;
                self.swing_count += 1;
            }
            let oldest = self.swings[self.swing_count % OSCILLATION_SWINGS];
            if ms > max * max
                && self.swing_count >= OSCILLATION_SWINGS
                && t - oldest <= limits.oscillation_swing_window_s
            {
                return Err(Trip {
                    cause: TripCause::Oscillation,
                    t,
                    value: ms.sqrt(),
                    limit: max,
                });
            }
        }
        if let Some(fraction) = limits.loss_fraction {
            let half: T = nalgebra::convert(0.5);
            if f >= half * f_ref && f_ref > T::zero() {
                self.established = true;
            }
            if self.established && f < fraction * f_ref {
                self.low_for_s += dt;
                if self.low_for_s >= self.derived.loss_s {
                    return Err(Trip {
                        cause: TripCause::ContactLost,
                        t,
                        value: self.low_for_s,
                        limit: limits.loss_s,
                    });
                }
            } else {
                self.low_for_s = T::zero();
            }
        }
        Ok(())
    }

    /// `(f(t) - f(t - w)) / w` over the window, 0 until it is full.
    fn rate(&mut self, f: T) -> T {
        let w = self.derived.window;
        self.ring[self.head] = f;
        let back = (self.head + RATE_RING - w) % RATE_RING;
        self.head = (self.head + 1) % RATE_RING;
        self.filled = (self.filled + 1).min(RATE_RING);
        if self.filled <= w {
            return T::zero();
        }
        (f - self.ring[back]) * self.derived.inverse_window_s
    }

    /// The mean square of the high-passed error `e`, and the high-passed error.
    fn oscillation(&mut self, e: T) -> (T, T) {
        let [x1, x2, y1, y2] = if self.armed {
            self.hp
        } else {
            [e, e, T::zero(), T::zero()]
        };
        if !self.armed {
            self.ms = T::zero();
            self.armed = true;
        }
        let [b0, b1, a1, a2] = self.derived.high_pass;
        let y = b0 * e + b1 * x1 + b0 * x2 - a1 * y1 - a2 * y2;
        self.hp = [e, x1, y, y1];
        self.ms += self.derived.rms_gain * (y * y - self.ms);
        (self.ms, y)
    }
}
