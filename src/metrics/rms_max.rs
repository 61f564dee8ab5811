//! The RMS and the largest value of a non-negative scalar series, accumulated without
//! allocation: `rms = sqrt(sum x_k^2 / n)`, `max = max_k x_k`.

/// Running sum of squares, count and maximum of a series of non-negative values.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct RmsMax {
    sum_sq: f64,
    n: usize,
    max: f64,
}

impl RmsMax {
    /// Adds one value (`x >= 0`: the maximum starts at zero).
    pub(crate) fn push(&mut self, x: f64) {
        self.sum_sq += x * x;
        self.n += 1;
        self.max = self.max.max(x);
    }

    /// `sqrt(sum x^2 / n)`, zero without a value.
    pub(crate) fn rms(&self) -> f64 {
        if self.n == 0 {
            0.0
        } else {
            libm::sqrt(self.sum_sq / self.n as f64)
        }
    }

    /// The largest value, zero without a value.
    pub(crate) fn max(&self) -> f64 {
        self.max
    }

    /// How many values were added.
    pub(crate) fn count(&self) -> usize {
        self.n
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rms_and_max_of_a_series_and_zeros_without_one() {
        let mut a = RmsMax::default();
        assert_eq!((a.rms(), a.max(), a.count()), (0.0, 0.0, 0));
        for x in [3.0, 4.0, 0.0] {
            a.push(x);
        }
        assert!((a.rms() - (25.0_f64 / 3.0).sqrt()).abs() < 1e-15);
        assert_eq!((a.max(), a.count()), (4.0, 3));
    }
}
