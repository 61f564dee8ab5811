//! From a recorded joint log to the states and torques an identification fits: segments,
//! uniform resampling, zero-phase low-pass filtering, differentiation and trimming.
//!
//! 1. The log is cut into segments where an interval is longer than the largest gap bridged
//!    (default 10 median intervals); each segment is resampled on a uniform grid at the rate
//!    (default the log's median rate) by linear interpolation.
//! 2. Positions, measured velocities (if logged) and torques pass through the same zero-phase
//!    Butterworth low-pass ([`super::filter`], forward and backward: no delay between them, the
//!    "parallel filtering" of identification). The cutoff is given, or `CUTOFF_PER_BANDWIDTH`
//!    times the positions' bandwidth: the lowest frequency `f_b` (on a grid of ratios
//!    `2^(1/4)`) whose low-pass keeps all but [`BANDWIDTH_ENERGY`] of every joint's position
//!    energy (the position with its straight-line trend removed), away from the ends where
//!    that filter has not settled (a segment too short for a cutoff rules it out).
//! 3. Velocities are the filtered positions' central differences (or the filtered measured
//!    velocities), accelerations the velocities' central differences.
//! 4. Each segment loses [`Butterworth::settling_samples`] at both ends (the forward-backward
//!    impulse response above `SETTLING_TOLERANCE` of its peak): there the filter has not
//!    settled. Segments too short for that are dropped and reported.

use super::error::IdentificationError;
use super::filter::Butterworth;
use super::log::JointLog;
use super::resample::{derivative, interpolate_linear, uniform_grid};
use crate::model::JointVector;

/// Energy of the positions a bandwidth may leave out (relative).
pub const BANDWIDTH_ENERGY: f64 = 1e-4;
/// Default cutoff over the positions' bandwidth.
pub const CUTOFF_PER_BANDWIDTH: f64 = 5.0;
/// Relative level of the impulse response below which the filter counts as settled.
pub const SETTLING_TOLERANCE: f64 = 1e-3;
/// Default largest interval bridged by interpolation, in median intervals.
pub const GAP_INTERVALS: f64 = 10.0;

/// How a log is processed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ProcessSettings {
    /// Uniform rate, Hz (default: the log's median rate).
    pub rate_hz: Option<f64>,
    /// Low-pass cutoff, Hz (default: from the positions' bandwidth).
    pub cutoff_hz: Option<f64>,
    /// Butterworth order.
    pub order: usize,
    /// Largest interval bridged, s (default [`GAP_INTERVALS`] median intervals).
    pub max_gap_s: Option<f64>,
}

impl Default for ProcessSettings {
    fn default() -> Self {
        Self {
            rate_hz: None,
            cutoff_hz: None,
            order: 4,
            max_gap_s: None,
        }
    }
}

/// What the processing did.
#[derive(Clone, Debug, PartialEq)]
pub struct ProcessReport {
    /// Uniform rate, Hz.
    pub rate_hz: f64,
    /// Cutoff used, Hz.
    pub cutoff_hz: f64,
    /// The positions' bandwidth when the cutoff was derived from it, Hz.
    pub bandwidth_hz: Option<f64>,
    /// Filter order.
    pub order: usize,
    /// Samples trimmed at each end of each segment.
    pub trim_samples: usize,
    /// Largest interval bridged, s.
    pub max_gap_s: f64,
    /// Segments used: `(start s, end s)` of the kept samples.
    pub segments: Vec<(f64, f64)>,
    /// Segments dropped as too short: `(start s, end s)` of the raw segment.
    pub dropped_segments: Vec<(f64, f64)>,
    /// Whether the velocities are the log's own (filtered) rather than differentiated.
    pub measured_velocities: bool,
}

impl core::fmt::Display for ProcessReport {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        let origin = match self.bandwidth_hz {
            Some(b) => format!("{CUTOFF_PER_BANDWIDTH} x the positions' bandwidth {b:.3} Hz"),
            None => "given".into(),
        };
        writeln!(
            f,
            "processing: resampled at {:.1} Hz; Butterworth order {} zero-phase low-pass at {:.3} Hz ({origin}); {} samples trimmed at each segment end",
            self.rate_hz, self.order, self.cutoff_hz, self.trim_samples
        )?;
        write!(
            f,
            "  velocities {}; {} segment(s) kept (gaps over {:.4} s split the log)",
            if self.measured_velocities {
                "from the log, filtered"
            } else {
                "differentiated from the filtered positions"
            },
            self.segments.len(),
            self.max_gap_s
        )?;
        for (a, b) in &self.dropped_segments {
            write!(
                f,
                "\n  segment {a:.4} s to {b:.4} s dropped: shorter than the filter's settling"
            )?;
        }
        Ok(())
    }
}

/// Processed samples, all on uniform grids (one per segment, concatenated).
#[derive(Clone, Debug, PartialEq)]
pub struct Processed<const N: usize> {
    /// Time, s.
    pub t: Vec<f64>,
    /// Filtered positions.
    pub q: Vec<JointVector<N>>,
    /// Velocities.
    pub qd: Vec<JointVector<N>>,
    /// Accelerations.
    pub qdd: Vec<JointVector<N>>,
    /// Filtered torques.
    pub tau: Vec<JointVector<N>>,
    /// Torques as logged, resampled but not filtered.
    pub tau_raw: Vec<JointVector<N>>,
}

impl<const N: usize> Processed<N> {
    /// Samples.
    #[must_use]
    pub fn len(&self) -> usize {
        self.t.len()
    }

    /// Whether there are none.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.t.is_empty()
    }
}

fn median_interval(t: &[f64]) -> f64 {
    let mut d: Vec<f64> = t.windows(2).map(|w| w[1] - w[0]).collect();
    if d.is_empty() {
        return f64::NAN;
    }
    d.sort_by(f64::total_cmp);
    d[d.len() / 2]
}

fn err(s: String) -> IdentificationError {
    IdentificationError::Setting(s)
}

/// The lowest cutoff (on a grid of ratios `2^(1/4)` from 0.01 Hz) whose low-pass keeps all but
/// [`BANDWIDTH_ENERGY`] of every joint's detrended position energy, Hz.
fn bandwidth(columns: &[Vec<f64>], rate: f64, order: usize) -> Result<f64, IdentificationError> {
    let detrended: Vec<Vec<f64>> = columns
        .iter()
        .map(|x| {
            let n = x.len() as f64;
            let mean_k = (n - 1.0) / 2.0;
            let mean_x = x.iter().sum::<f64>() / n;
            let (mut sxy, mut sxx) = (0.0, 0.0);
            for (k, v) in x.iter().enumerate() {
                sxy += (k as f64 - mean_k) * (v - mean_x);
                sxx += (k as f64 - mean_k).powi(2);
            }
            let slope = if sxx > 0.0 { sxy / sxx } else { 0.0 };
            x.iter()
                .enumerate()
                .map(|(k, v)| v - mean_x - slope * (k as f64 - mean_k))
                .collect()
        })
        .collect();
    let mut f = 0.01;
    while f < rate / 10.0 {
        let filter = Butterworth::low_pass(order, f, rate).map_err(|e| err(e.to_string()))?;
        // Only where this filter has settled: its transients at the ends are not bandwidth.
        let edge = filter.settling_samples(SETTLING_TOLERANCE);
        let mut all = true;
        for x in &detrended {
            if x.len() <= 2 * edge + 3 {
                all = false;
                break;
            }
            let inner = edge..x.len() - edge;
            let energy: f64 = x[inner.clone()].iter().map(|v| v * v).sum();
            if energy == 0.0 {
                continue;
            }
            let y = filter.filtfilt(x).map_err(|e| err(e.to_string()))?;
            let left: f64 = x[inner.clone()]
                .iter()
                .zip(&y[inner])
                .map(|(a, b)| (a - b).powi(2))
                .sum();
            if left > BANDWIDTH_ENERGY * energy {
                all = false;
                break;
            }
        }
        if all {
            return Ok(f);
        }
        f *= libm::pow(2.0, 0.25);
    }
    Ok(rate / 10.0 / CUTOFF_PER_BANDWIDTH)
}

fn column<const N: usize>(v: &[JointVector<N>], i: usize) -> Vec<f64> {
    v.iter().map(|x| x[i]).collect()
}

/// Processes `log` as `settings` say; `fixed` (rate, cutoff) from an earlier processing makes a
/// validation log go through the same filter.
///
/// # Errors
///
/// [`IdentificationError::Setting`] for a bad setting, or a log with no segment long enough.
pub fn process<const N: usize>(
    log: &JointLog<N>,
    settings: &ProcessSettings,
) -> Result<(Processed<N>, ProcessReport), IdentificationError> {
    let median = median_interval(&log.t);
    if !(median.is_finite() && median > 0.0) {
        return Err(err("log: fewer than two distinct time stamps".into()));
    }
    let rate = settings
        .rate_hz
        .unwrap_or_else(|| libm::round(1.0 / median));
    if !(rate.is_finite() && rate > 0.0) {
        return Err(err(format!("--rate-hz {rate}: must be finite and > 0")));
    }
    let max_gap = settings.max_gap_s.unwrap_or(GAP_INTERVALS * median);
    if !(max_gap.is_finite() && max_gap > 0.0) {
        return Err(err(format!(
            "--max-gap-s {max_gap}: must be finite and > 0"
        )));
    }
    // Segments of the raw log.
    let mut bounds = Vec::new();
    let mut start = 0;
    for k in 1..log.t.len() {
        if log.t[k] - log.t[k - 1] > max_gap {
            bounds.push((start, k));
            start = k;
        }
    }
    bounds.push((start, log.t.len()));
    // Resample every segment.
    struct Seg {
        t: Vec<f64>,
        q: Vec<Vec<f64>>,
        qd: Option<Vec<Vec<f64>>>,
        tau: Vec<Vec<f64>>,
    }
    let resample = |a: usize, b: usize| -> Result<Option<Seg>, IdentificationError> {
        if b - a < 2 {
            return Ok(None);
        }
        let t = &log.t[a..b];
        let grid = uniform_grid(t[0], t[t.len() - 1], rate).map_err(|e| err(e.to_string()))?;
        let interp = |v: &[JointVector<N>]| -> Result<Vec<Vec<f64>>, IdentificationError> {
            (0..N)
                .map(|i| {
                    interpolate_linear(t, &column(&v[a..b], i), &grid)
                        .map_err(|e| err(e.to_string()))
                })
                .collect()
        };
        Ok(Some(Seg {
            q: interp(&log.q)?,
            qd: log.qd.as_ref().map(|qd| interp(qd)).transpose()?,
            tau: interp(&log.tau)?,
            t: grid,
        }))
    };
    let mut segments = Vec::new();
    for (a, b) in &bounds {
        segments.push(((log.t[*a], log.t[b - 1]), resample(*a, *b)?));
    }
    let (cutoff, bandwidth_hz) = match settings.cutoff_hz {
        Some(c) => (c, None),
        None => {
            let longest = segments
                .iter()
                .filter_map(|(_, s)| s.as_ref())
                .max_by_key(|s| s.t.len())
                .ok_or_else(|| err("log: no segment of two samples or more".into()))?;
            let b = bandwidth(&longest.q, rate, settings.order)?;
            ((CUTOFF_PER_BANDWIDTH * b).min(rate / 10.0), Some(b))
        }
    };
    let filter = Butterworth::low_pass(settings.order, cutoff, rate)
        .map_err(|e| err(format!("the low-pass filter: {e}")))?;
    let trim = filter.settling_samples(SETTLING_TOLERANCE);
    let dt = 1.0 / rate;
    let mut out = Processed {
        t: Vec::new(),
        q: Vec::new(),
        qd: Vec::new(),
        qdd: Vec::new(),
        tau: Vec::new(),
        tau_raw: Vec::new(),
    };
    let mut report = ProcessReport {
        rate_hz: rate,
        cutoff_hz: cutoff,
        bandwidth_hz,
        order: settings.order,
        trim_samples: trim,
        max_gap_s: max_gap,
        segments: Vec::new(),
        dropped_segments: Vec::new(),
        measured_velocities: log.qd.is_some(),
    };
    for (span, seg) in segments {
        let Some(seg) = seg.filter(|s| s.t.len() > 2 * trim + 3) else {
            report.dropped_segments.push(span);
            continue;
        };
        let f = |x: &Vec<f64>| filter.filtfilt(x).map_err(|e| err(e.to_string()));
        let q: Vec<Vec<f64>> = seg.q.iter().map(f).collect::<Result<_, _>>()?;
        let qd: Vec<Vec<f64>> = match &seg.qd {
            Some(v) => v.iter().map(f).collect::<Result<_, _>>()?,
            None => q
                .iter()
                .map(|x| derivative(x, dt).map_err(|e| err(e.to_string())))
                .collect::<Result<_, _>>()?,
        };
        let qdd: Vec<Vec<f64>> = qd
            .iter()
            .map(|x| derivative(x, dt).map_err(|e| err(e.to_string())))
            .collect::<Result<_, _>>()?;
        let tau: Vec<Vec<f64>> = seg.tau.iter().map(f).collect::<Result<_, _>>()?;
        let keep = trim..seg.t.len() - trim;
        report
            .segments
            .push((seg.t[keep.start], seg.t[keep.end - 1]));
        let pack = |c: &[Vec<f64>], k: usize| JointVector::<N>::from_fn(|i, _| c[i][k]);
        for k in keep {
            out.t.push(seg.t[k]);
            out.q.push(pack(&q, k));
            out.qd.push(pack(&qd, k));
            out.qdd.push(pack(&qdd, k));
            out.tau.push(pack(&tau, k));
            out.tau_raw.push(pack(&seg.tau, k));
        }
    }
    if out.is_empty() {
        return Err(err(format!(
            "log: no segment longer than twice the filter's settling ({trim} samples at {rate} Hz); lower the rate or raise the cutoff"
        )));
    }
    Ok((out, report))
}
