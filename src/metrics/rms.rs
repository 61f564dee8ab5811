//! The RMS of a scalar series, and its largest value, accumulated without allocation:
//! `rms = sqrt(sum x_k^2 / n)`, `max = max_k x_k`.

/// Running sum of squares and count of a series.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Rms {
    sum_sq: f64,
    n: usize,
}

impl Rms {
    /// Adds one value `x` (its square `x^2` to the sum).
    pub fn push(&mut self, x: f64) {
        self.push_squared(x * x);
    }

    /// Adds one value given by its square `x2 = |x|^2` (a vector's `norm_squared`, so that
    /// no square root is taken and squared again).
    pub fn push_squared(&mut self, x2: f64) {
        self.sum_sq += x2;
        self.n += 1;
    }

    /// `sqrt(sum x^2 / n)`, zero without a value.
    #[must_use]
    pub fn rms(&self) -> f64 {
        if self.n == 0 {
            0.0
        } else {
            crate::math::sqrt(self.sum_sq / self.n as f64)
        }
    }

    /// How many values were added.
    #[must_use]
    pub fn count(&self) -> usize {
        self.n
    }
}

/// [`Rms`] of a series of non-negative values, and their largest.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RmsMax {
    rms: Rms,
    max: f64,
}

impl RmsMax {
    /// Adds one value (`x >= 0`: the maximum starts at zero).
    pub fn push(&mut self, x: f64) {
        self.rms.push(x);
        self.max = self.max.max(x);
    }

    /// `sqrt(sum x^2 / n)`, zero without a value.
    #[must_use]
    pub fn rms(&self) -> f64 {
        self.rms.rms()
    }

    /// The largest value, zero without a value.
    #[must_use]
    pub fn max(&self) -> f64 {
        self.max
    }

    /// How many values were added.
    #[must_use]
    pub fn count(&self) -> usize {
        self.rms.count()
    }
}
