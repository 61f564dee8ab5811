//! A force/torque sensor model: what the controller measures of the contact wrench
//! (thesis Chapter 6: measurement noise, and the 6-axis sensor after joint 4).

use crate::model::Wrench;
use rand::rngs::Xoshiro256PlusPlus;
use rand::{RngExt, SeedableRng};
use rand_distr::StandardNormal;

/// Bias, white Gaussian noise and a first-order low-pass filter, per wrench axis.
///
/// `measure(f, dt)` returns `lowpass(f + bias + n)` with `n ~ N(0, noise_std^2)` drawn
/// independently per axis and sample from a seeded generator (`rand`'s xoshiro256++, seeded
/// by [`SeedableRng::seed_from_u64`]; normal draws by `rand_distr`: runs are reproducible), and the
/// filter `y += (dt / (tau + dt)) (x - y)`, `tau = 1 / (2 pi cutoff)`, started at its first
/// input. No allocation.
///
/// ```
/// use armdyn::contact::ForceSensor;
/// use armdyn::model::Wrench;
/// let mut s = ForceSensor::new(Wrench::zeros(), Wrench::repeat(2.0), Some(50.0), 7).unwrap();
/// let f = Wrench::new(0.0, 0.0, -200.0, 0.0, 0.0, 0.0);
/// let mean = (0..20_000).map(|_| s.measure(&f, 1e-3)[2]).sum::<f64>() / 20_000.0;
/// assert!((mean + 200.0).abs() < 0.1);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct ForceSensor {
    bias: Wrench,
    noise_std: Wrench,
    cutoff_hz: Option<f64>,
    seed: u64,
    rng: Xoshiro256PlusPlus,
    filtered: Option<Wrench>,
}

/// Invalid sensor parameters.
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
pub enum SensorError {
    /// A bias or noise entry is not finite, or a noise entry is negative.
    #[error("force sensor: bias and noise must be finite, noise >= 0 (axis {0})")]
    Value(usize),
    /// The cutoff is not finite and positive.
    #[error("force sensor: the filter cutoff must be finite and > 0 Hz")]
    Cutoff,
}

impl ForceSensor {
    /// A sensor with the given bias (N, N m), noise standard deviation per axis, optional
    /// low-pass cutoff (Hz) and random seed.
    ///
    /// # Errors
    ///
    /// [`SensorError`] naming the bad parameter.
    pub fn new(
        bias: Wrench,
        noise_std: Wrench,
        cutoff_hz: Option<f64>,
        seed: u64,
    ) -> Result<Self, SensorError> {
        for i in 0..6 {
            if !bias[i].is_finite() || !noise_std[i].is_finite() || noise_std[i] < 0.0 {
                return Err(SensorError::Value(i));
            }
        }
        if let Some(c) = cutoff_hz {
            if !(c.is_finite() && c > 0.0) {
                return Err(SensorError::Cutoff);
            }
        }
        Ok(Self {
            bias,
            noise_std,
            cutoff_hz,
            seed,
            rng: Xoshiro256PlusPlus::seed_from_u64(seed),
            filtered: None,
        })
    }

    /// A perfect sensor: the true wrench.
    #[must_use]
    pub fn ideal() -> Self {
        Self {
            bias: Wrench::zeros(),
            noise_std: Wrench::zeros(),
            cutoff_hz: None,
            seed: 0,
            rng: Xoshiro256PlusPlus::seed_from_u64(0),
            filtered: None,
        }
    }

    /// How many numbers the low-pass filter's state takes: 6 with a cutoff, else 0.
    #[must_use]
    pub fn state_len(&self) -> usize {
        if self.cutoff_hz.is_some() {
            6
        } else {
            0
        }
    }

    /// Writes the filter's state (its last output, N and N m; 0 before the first reading)
    /// into `out[..self.state_len()]`.
    pub fn write_state(&self, out: &mut [f64]) {
        if self.cutoff_hz.is_some() {
            let y = self.filtered.unwrap_or_else(Wrench::zeros);
            out[..6].copy_from_slice(y.as_slice());
        }
    }

    /// Sets the filter's state from `x[..self.state_len()]`.
    pub fn read_state(&mut self, x: &[f64]) {
        if self.cutoff_hz.is_some() {
            self.filtered = Some(Wrench::from_column_slice(&x[..6]));
        }
    }

    /// Restarts the noise sequence and the filter.
    pub fn reset(&mut self) {
        self.rng = Xoshiro256PlusPlus::seed_from_u64(self.seed);
        self.filtered = None;
    }

    /// One measurement of the true wrench `f`, `dt` seconds after the previous one.
    pub fn measure(&mut self, f: &Wrench, dt: f64) -> Wrench {
        let mut x = f + self.bias;
        for i in 0..6 {
            if self.noise_std[i] > 0.0 {
                let n: f64 = self.rng.sample(StandardNormal);
                x[i] += self.noise_std[i] * n;
            }
        }
        let y = match (self.cutoff_hz, self.filtered) {
            (Some(fc), Some(prev)) => {
                let tau = 1.0 / (2.0 * core::f64::consts::PI * fc);
                prev + (x - prev) * (dt / (tau + dt))
            }
            _ => x,
        };
        self.filtered = Some(y);
        y
    }
}
