//! Uniform resampling and differentiation of recorded signals (feature `std`).
//!
//! A log's time stamps are seldom exactly uniform. [`uniform_grid`] lays the grid
//! `t0 + k / rate`, [`interpolate_linear`] brings each recorded channel onto it (linear
//! interpolation between the two samples around each time), and [`derivative`] takes the
//! first derivative of a uniformly sampled channel by second-order finite differences:
//! central differences inside, one-sided three-point differences at the ends. Applied twice
//! (to a filtered position, see [`filter`](super::filter)) it gives velocity and acceleration.

/// The most points [`uniform_grid`] lays out (2^28, 2 GiB of `f64`).
const MAX_GRID_POINTS: usize = 1 << 28;

/// Samples or settings that cannot be resampled or differentiated.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ResampleError {
    /// Too few samples.
    #[error("at least {needed} samples are needed, got {count}")]
    TooFewSamples {
        /// Samples needed.
        needed: usize,
        /// Samples given.
        count: usize,
    },
    /// The times and the values are not as many.
    #[error("{times} times but {values} values: one value per time is needed")]
    LengthMismatch {
        /// Number of times.
        times: usize,
        /// Number of values.
        values: usize,
    },
    /// A sample time is NaN or infinite.
    #[error("sample {index}: time {t} s is not finite")]
    NonFiniteTime {
        /// Index of the sample (from 0).
        index: usize,
        /// Its time, s.
        t: f64,
    },
    /// A sample time is not after the previous one.
    #[error("sample {index}: time {t} s is not after the previous one, {previous} s")]
    NotIncreasing {
        /// Index of the sample (from 0).
        index: usize,
        /// Its time, s.
        t: f64,
        /// The previous sample's time, s.
        previous: f64,
    },
    /// The sample rate is not finite and positive.
    #[error("sample rate {rate_hz} Hz is not finite and positive")]
    Rate {
        /// The rate given, Hz.
        rate_hz: f64,
    },
    /// The sample period is not finite and positive.
    #[error("sample period {dt_s} s is not finite and positive")]
    Period {
        /// The period given, s.
        dt_s: f64,
    },
    /// The grid's start or end is NaN or infinite, or the end is before the start.
    #[error("grid from {t0} s to {t_end} s: both must be finite and the end not before the start")]
    BadRange {
        /// Start, s.
        t0: f64,
        /// End, s.
        t_end: f64,
    },
    /// The grid would have too many points.
    #[error("grid of {points} points is longer than the {max} allowed")]
    GridTooLong {
        /// Points the grid would have (saturated at `usize::MAX`).
        points: usize,
        /// The most allowed.
        max: usize,
    },
    /// A time to interpolate at is outside the samples' time range (or NaN).
    #[error("time {time} s (query {index}) is outside the samples' range [{first}, {last}] s")]
    OutOfRange {
        /// Index of the query (from 0).
        index: usize,
        /// The time asked for, s.
        time: f64,
        /// First sample time, s.
        first: f64,
        /// Last sample time, s.
        last: f64,
    },
}

/// The uniform grid t0, t0 + 1/rate, ... up to the last time (inclusive when it falls on the
/// grid within 1e-9 of a period): `t_k = t0 + k / rate_hz` for
/// `k = 0 ..= floor((t_end - t0) rate_hz + 1e-9)`, s.
///
/// # Errors
///
/// [`ResampleError::Rate`] for a rate that is not finite and positive,
/// [`ResampleError::BadRange`] for a non-finite start or end or an end before the start,
/// [`ResampleError::GridTooLong`] beyond 2^28 points.
pub fn uniform_grid(t0: f64, t_end: f64, rate_hz: f64) -> Result<Vec<f64>, ResampleError> {
    if !(rate_hz.is_finite() && rate_hz > 0.0) {
        return Err(ResampleError::Rate { rate_hz });
    }
    if !(t0.is_finite() && t_end.is_finite() && t_end >= t0) {
        return Err(ResampleError::BadRange { t0, t_end });
    }
    let periods = libm::floor((t_end - t0) * rate_hz + 1e-9);
    // `as` saturates (and the bound is checked before allocating).
    let points = (periods as usize).saturating_add(1);
    if !periods.is_finite() || points > MAX_GRID_POINTS {
        return Err(ResampleError::GridTooLong {
            points,
            max: MAX_GRID_POINTS,
        });
    }
    Ok((0..points).map(|k| t0 + k as f64 / rate_hz).collect())
}

/// Checks that `t` has at least 2 finite, strictly increasing times.
fn check_times(t: &[f64]) -> Result<(), ResampleError> {
    if t.len() < 2 {
        return Err(ResampleError::TooFewSamples {
            needed: 2,
            count: t.len(),
        });
    }
    if let Some(index) = t.iter().position(|v| !v.is_finite()) {
        return Err(ResampleError::NonFiniteTime { index, t: t[index] });
    }
    match t.windows(2).position(|w| w[1] <= w[0]) {
        Some(i) => Err(ResampleError::NotIncreasing {
            index: i + 1,
            t: t[i + 1],
            previous: t[i],
        }),
        None => Ok(()),
    }
}

/// Linear interpolation of samples `(t[k], x[k])` (strictly increasing `t`) at the times `at`:
/// `x(a) = (1 - w) x[j] + w x[j+1]`, `w = (a - t[j]) / (t[j+1] - t[j])`, for the segment
/// `t[j] <= a <= t[j+1]`. Every `at` must lie within `[t[0], t[last]]`. O(len) for sorted
/// `at` (the segment is searched from the previous one; a step back is a binary search).
///
/// # Errors
///
/// [`ResampleError::LengthMismatch`] when `t` and `x` differ in length,
/// [`ResampleError::TooFewSamples`] below 2 samples, [`ResampleError::NonFiniteTime`] or
/// [`ResampleError::NotIncreasing`] for bad times, [`ResampleError::OutOfRange`] naming the
/// first `at` outside `[t[0], t[last]]`.
pub fn interpolate_linear(t: &[f64], x: &[f64], at: &[f64]) -> Result<Vec<f64>, ResampleError> {
    if t.len() != x.len() {
        return Err(ResampleError::LengthMismatch {
            times: t.len(),
            values: x.len(),
        });
    }
    check_times(t)?;
    let (first, last) = (t[0], t[t.len() - 1]);
    let last_segment = t.len() - 2;
    let mut j = 0;
    at.iter()
        .enumerate()
        .map(|(index, &a)| {
            if !(a >= first && a <= last) {
                return Err(ResampleError::OutOfRange {
                    index,
                    time: a,
                    first,
                    last,
                });
            }
            if a < t[j] {
                // The last sample at or before `a` (t[0] <= a, so the count is at least 1).
                j = (t.partition_point(|v| *v <= a) - 1).min(last_segment);
            }
            while j < last_segment && t[j + 1] <= a {
                j += 1;
            }
            let w = (a - t[j]) / (t[j + 1] - t[j]);
            Ok((1.0 - w) * x[j] + w * x[j + 1])
        })
        .collect()
}

/// First derivative of uniformly sampled x (period `dt_s`, s) by central differences
/// `(x[k+1] - x[k-1]) / (2 dt)`, and one-sided second-order differences at the two ends,
/// `(-3 x[0] + 4 x[1] - x[2]) / (2 dt)` and `(3 x[n-1] - 4 x[n-2] + x[n-3]) / (2 dt)`.
/// Exact for quadratics. Units of x per second.
///
/// # Errors
///
/// [`ResampleError::TooFewSamples`] below 3 samples, [`ResampleError::Period`] for a period
/// that is not finite and positive.
pub fn derivative(x: &[f64], dt_s: f64) -> Result<Vec<f64>, ResampleError> {
    if !(dt_s.is_finite() && dt_s > 0.0) {
        return Err(ResampleError::Period { dt_s });
    }
    let n = x.len();
    if n < 3 {
        return Err(ResampleError::TooFewSamples {
            needed: 3,
            count: n,
        });
    }
    let scale = 0.5 / dt_s;
    let mut d = Vec::with_capacity(n);
    d.push((-3.0 * x[0] + 4.0 * x[1] - x[2]) * scale);
    d.extend(x.windows(3).map(|w| (w[2] - w[0]) * scale));
    d.push((3.0 * x[n - 1] - 4.0 * x[n - 2] + x[n - 3]) * scale);
    Ok(d)
}
