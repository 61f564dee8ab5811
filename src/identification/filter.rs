//! Zero-phase Butterworth low-pass filtering of recorded signals (feature `std`).
//!
//! Joint positions and torques logged at about 1 kHz are filtered before they are
//! differentiated; the same filter is applied to both ("parallel filtering"), so the
//! regressor built from the positions and the measured torques see the same attenuation and
//! no relative delay.
//!
//! # Design
//!
//! The analog Butterworth prototype of order `N` has its poles on the unit circle,
//! `p_m = -exp(j π m / (2N))` for `m = -N+1, -N+3, …, N-1`. The cutoff is pre-warped,
//! `ω_a = 2 f_s tan(π f_c / f_s)`, and the bilinear transform
//! `z = (1 + s/(2 f_s)) / (1 - s/(2 f_s))` maps each pole with `c = tan(π f_c / f_s)`: a
//! conjugate pair at angle `φ = π m / (2N)` gives the section
//!
//! `H(z) = g (1 + 2 z⁻¹ + z⁻²) / (1 + a1 z⁻¹ + a2 z⁻²)`,
//! `D = 1 + 2 c cos φ + c²`, `a1 = -2 (1 - c²) / D`, `a2 = (1 - 2 c cos φ + c²) / D`,
//! `g = c² / D`,
//!
//! and the real pole of an odd order the first-order section
//! `g (1 + z⁻¹) / (1 + a1 z⁻¹)`, `a1 = -(1 - c) / (1 + c)`, `g = c / (1 + c)`. Every
//! section has unit gain at DC; the cascade is `scipy.signal.butter(N, f_c, fs=f_s,
//! output='sos')` up to the order of the sections and how the gain is spread over them.
//!
//! # Zero-phase filtering
//!
//! [`Butterworth::filtfilt`] is `scipy.signal.sosfiltfilt` with its defaults: the signal is
//! extended at both ends by odd reflection (`2 x[0] - x[n]`, …), filtered forward from the
//! steady state of a step of the first extended sample, reversed, filtered again the same
//! way, reversed and cut back. The magnitude response is squared (`|H|²`, so -6 dB at the
//! cutoff) and the phase is zero.

/// The largest order [`Butterworth::low_pass`] designs.
const MAX_ORDER: usize = 12;

/// A digital Butterworth low-pass filter as second-order sections.
#[derive(Clone, Debug, PartialEq)]
pub struct Butterworth {
    /// `[b0, b1, b2, a0 (= 1), a1, a2]` per section, like scipy's `sos`.
    sections: Vec<[f64; 6]>,
    order: usize,
    cutoff_hz: f64,
    rate_hz: f64,
}

/// A filter that cannot be designed or a signal it cannot filter.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum FilterError {
    /// The order is 0 or above 12.
    #[error("Butterworth order {order} is not in 1..={max}")]
    Order {
        /// The order asked for.
        order: usize,
        /// The largest order designed, 12.
        max: usize,
    },
    /// The sample rate is not finite and positive.
    #[error("sample rate {rate_hz} Hz is not finite and positive")]
    Rate {
        /// The rate asked for, Hz.
        rate_hz: f64,
    },
    /// The cutoff is not finite or not strictly between 0 and the Nyquist frequency.
    #[error("cutoff {cutoff_hz} Hz is not in (0, {nyquist_hz}) Hz (0 to half the sample rate)")]
    Cutoff {
        /// The cutoff asked for, Hz.
        cutoff_hz: f64,
        /// Half the sample rate, Hz.
        nyquist_hz: f64,
    },
    /// The signal is not longer than the padding of [`Butterworth::filtfilt`].
    #[error(
        "zero-phase filtering needs at least {needed} samples (padding {padding} + 1), got {count}"
    )]
    TooShort {
        /// Samples needed.
        needed: usize,
        /// Padding at each end, samples.
        padding: usize,
        /// Samples given.
        count: usize,
    },
}

impl Butterworth {
    /// Order `order`, cutoff `cutoff_hz` (-3 dB), for samples at `rate_hz`.
    ///
    /// The sections are those of the [module documentation](self), with
    /// `c = tan(π cutoff_hz / rate_hz)`.
    ///
    /// # Errors
    ///
    /// [`FilterError::Order`] for order 0 or above 12, [`FilterError::Rate`] for a
    /// rate that is not finite and positive, [`FilterError::Cutoff`] for a cutoff outside
    /// `(0, rate_hz / 2)`.
    pub fn low_pass(order: usize, cutoff_hz: f64, rate_hz: f64) -> Result<Self, FilterError> {
        if order == 0 || order > MAX_ORDER {
            return Err(FilterError::Order {
                order,
                max: MAX_ORDER,
            });
        }
        if !(rate_hz.is_finite() && rate_hz > 0.0) {
            return Err(FilterError::Rate { rate_hz });
        }
        let nyquist_hz = 0.5 * rate_hz;
        if !(cutoff_hz > 0.0 && cutoff_hz < nyquist_hz) {
            return Err(FilterError::Cutoff {
                cutoff_hz,
                nyquist_hz,
            });
        }
        let c = libm::tan(core::f64::consts::PI * cutoff_hz / rate_hz);
        let c2 = c * c;
        let mut sections = Vec::with_capacity(order.div_ceil(2));
        if order % 2 == 1 {
            let g = c / (1.0 + c);
            let a1 = -(1.0 - c) / (1.0 + c);
            sections.push([g, g, 0.0, 1.0, a1, 0.0]);
        }
        // Conjugate pairs at m = N-1, N-3, … > 0.
        let mut m = order - 1;
        while m > 0 {
            let cos_phi = libm::cos(core::f64::consts::PI * m as f64 / (2 * order) as f64);
            let d = 1.0 + 2.0 * c * cos_phi + c2;
            let g = c2 / d;
            let a1 = -2.0 * (1.0 - c2) / d;
            let a2 = (1.0 - 2.0 * c * cos_phi + c2) / d;
            sections.push([g, 2.0 * g, g, 1.0, a1, a2]);
            m = m.saturating_sub(2);
        }
        Ok(Self {
            sections,
            order,
            cutoff_hz,
            rate_hz,
        })
    }

    /// The order.
    #[must_use]
    pub fn order(&self) -> usize {
        self.order
    }

    /// The cutoff (-3 dB of one pass), Hz.
    #[must_use]
    pub fn cutoff_hz(&self) -> f64 {
        self.cutoff_hz
    }

    /// The sample rate, Hz.
    #[must_use]
    pub fn rate_hz(&self) -> f64 {
        self.rate_hz
    }

    /// The second-order sections, `[b0, b1, b2, 1, a1, a2]` each (scipy's `sos` layout).
    #[must_use]
    pub fn sections(&self) -> &[[f64; 6]] {
        &self.sections
    }

    /// Magnitude response of one causal pass at `f_hz`:
    /// `|H(e^{jω})| = Π |b0 + b1 e^{-jω} + b2 e^{-2jω}| / |1 + a1 e^{-jω} + a2 e^{-2jω}|`,
    /// `ω = 2π f_hz / rate_hz`. 1 at DC, `1/√2` at the cutoff.
    #[must_use]
    pub fn gain(&self, f_hz: f64) -> f64 {
        let w = 2.0 * core::f64::consts::PI * f_hz / self.rate_hz;
        let (c1, s1) = (libm::cos(w), libm::sin(w));
        let (c2, s2) = (libm::cos(2.0 * w), libm::sin(2.0 * w));
        self.sections.iter().fold(1.0, |g, s| {
            let num = libm::hypot(s[0] + s[1] * c1 + s[2] * c2, s[1] * s1 + s[2] * s2);
            let den = libm::hypot(s[3] + s[4] * c1 + s[5] * c2, s[4] * s1 + s[5] * s2);
            g * num / den
        })
    }

    /// One causal pass (`scipy.signal.sosfilt`) from zero initial state, each section in
    /// Direct Form II transposed: `y = b0 x + z0`, `z0 ← b1 x - a1 y + z1`, `z1 ← b2 x - a2 y`.
    #[must_use]
    pub fn filter(&self, x: &[f64]) -> Vec<f64> {
        let mut state = vec![[0.0; 2]; self.sections.len()];
        let mut y = x.to_vec();
        self.run(&mut y, &mut state);
        y
    }

    /// One causal pass in place, from (and leaving) the state `state` of each section.
    fn run(&self, y: &mut [f64], state: &mut [[f64; 2]]) {
        for (s, z) in self.sections.iter().zip(state.iter_mut()) {
            for v in y.iter_mut() {
                let x = *v;
                let out = s[0] * x + z[0];
                z[0] = s[1] * x - s[4] * out + z[1];
                z[1] = s[2] * x - s[5] * out;
                *v = out;
            }
        }
    }

    /// The steady state of each section for a unit step into the cascade
    /// (`scipy.signal.sosfilt_zi`): per section the solution of
    /// `[[1 + a1, -1], [a2, 1]] zi = [b1 - a1 b0, b2 - a2 b0]` (`lfilter_zi`), scaled by the
    /// DC gain `Σb / Σa` of the sections before it.
    fn step_state(&self) -> Vec<[f64; 2]> {
        let mut scale = 1.0;
        self.sections
            .iter()
            .map(|s| {
                let (b0, b1, b2, a1, a2) = (s[0], s[1], s[2], s[4], s[5]);
                let (r0, r1) = (b1 - a1 * b0, b2 - a2 * b0);
                let det = 1.0 + a1 + a2;
                let zi = [
                    scale * (r0 + r1) / det,
                    scale * ((1.0 + a1) * r1 - a2 * r0) / det,
                ];
                scale *= (b0 + b1 + b2) / (s[3] + a1 + a2);
                zi
            })
            .collect()
    }

    /// The padding of [`filtfilt`](Self::filtfilt) at each end, scipy's default
    /// `3 (2 n_sections + 1 - min(#{b2 = 0}, #{a2 = 0}))`.
    fn padding(&self) -> usize {
        let b2_zero = self.sections.iter().filter(|s| s[2] == 0.0).count();
        let a2_zero = self.sections.iter().filter(|s| s[5] == 0.0).count();
        3 * (2 * self.sections.len() + 1 - b2_zero.min(a2_zero))
    }

    /// Zero-phase filtering: forward then backward, identical to
    /// `scipy.signal.sosfiltfilt(sos, x)` with its defaults (`padtype='odd'`, padding
    /// `3 (2 n_sections + 1 - min(#{b2 = 0}, #{a2 = 0}))` samples at each end, initial
    /// conditions from `sosfilt_zi` scaled by the first (padded) sample on each pass).
    /// Overall response `|H(f)|²`, zero phase.
    ///
    /// # Errors
    ///
    /// [`FilterError::TooShort`] when `x` has no more samples than the padding.
    pub fn filtfilt(&self, x: &[f64]) -> Result<Vec<f64>, FilterError> {
        let pad = self.padding();
        let n = x.len();
        if n <= pad {
            return Err(FilterError::TooShort {
                needed: pad + 1,
                padding: pad,
                count: n,
            });
        }
        let (first, last) = (x[0], x[n - 1]);
        let mut ext = Vec::with_capacity(n + 2 * pad);
        ext.extend((1..=pad).rev().map(|i| 2.0 * first - x[i]));
        ext.extend_from_slice(x);
        ext.extend((1..=pad).map(|i| 2.0 * last - x[n - 1 - i]));

        let zi = self.step_state();
        let scaled = |v: f64| zi.iter().map(|z| [z[0] * v, z[1] * v]).collect::<Vec<_>>();
        let mut state = scaled(ext[0]);
        self.run(&mut ext, &mut state);
        ext.reverse();
        let mut state = scaled(ext[0]);
        self.run(&mut ext, &mut state);
        ext.reverse();
        Ok(ext[pad..pad + n].to_vec())
    }

    /// Samples to discard at each end of a [`filtfilt`](Self::filtfilt) output: the filter's
    /// settling. The smallest `k` such that the zero-phase impulse response `r` (the
    /// forward-backward filter applied to a unit impulse at the centre of a long zero signal,
    /// i.e. the autocorrelation `r[l] = Σ h[n] h[n + l]` of the impulse response `h`) stays
    /// below `tolerance` times its peak, `|r[l]| < tolerance · max |r|` for every lag `l ≥ k`.
    ///
    /// A `tolerance` below `f64::EPSILON` (or NaN) is taken as `f64::EPSILON`. The zero
    /// signal is made longer (doubled, from 64 samples either side of the impulse) until `k`
    /// no longer changes, up to 2^24 samples either side (enough for order 12 down to a
    /// cutoff of about 10^-5 of the rate; beyond, the result is a lower bound).
    #[must_use]
    pub fn settling_samples(&self, tolerance: f64) -> usize {
        const MAX_HALF: usize = 1 << 24;
        let tolerance = tolerance.max(f64::EPSILON);
        let mut half = 64;
        let mut previous = self.settling_with(half, tolerance);
        while half < MAX_HALF {
            half *= 2;
            let k = self.settling_with(half, tolerance);
            if k == previous && 2 * k < half {
                return k;
            }
            previous = k;
        }
        previous
    }

    /// [`settling_samples`](Self::settling_samples) on an impulse with `half` zeros either side.
    fn settling_with(&self, half: usize, tolerance: f64) -> usize {
        let mut y = vec![0.0; 2 * half + 1];
        y[half] = 1.0;
        for _ in 0..2 {
            // In place, from zero state: forward, then (reversed) backward.
            self.run(&mut y, &mut vec![[0.0; 2]; self.sections.len()]);
            y.reverse();
        }
        let peak = y.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        y[half..]
            .iter()
            .rposition(|v| v.abs() >= tolerance * peak)
            .map_or(0, |l| l + 1)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    /// `x[k] = sin(0.3 k) + 0.5 cos(1.7 k) + 0.01 k²`, k = 0..60
    /// (numpy: `k = np.arange(60); x = np.sin(0.3*k) + 0.5*np.cos(1.7*k) + 0.01*k**2`).
    fn signal() -> Vec<f64> {
        (0..60)
            .map(|k| {
                let k = f64::from(k);
                libm::sin(0.3 * k) + 0.5 * libm::cos(1.7 * k) + 0.01 * k * k
            })
            .collect()
    }

    /// `scipy.signal.sosfiltfilt(scipy.signal.butter(4, 20, fs=1000, output='sos'), x)`
    /// (SciPy 1.17.1).
    #[rustfmt::skip]
    const ORDER4_20HZ_1KHZ: [f64; 60] = [
        0.0647285270631293, 0.1040960479246266, 0.14996087081248202, 0.20360051791233483,
        0.2663813155647874, 0.33974949983013997, 0.42522045082066856, 0.5243660876850831,
        0.6388005045302588, 0.7701639790099037, 0.9201055367127496, 1.090264303068444,
        1.282249914117602, 1.4976222835850204, 1.7378710364939913, 2.0043949190321015,
        2.2984814786971204, 2.6212872799247373, 2.9738188841930437, 3.3569147834922664,
        3.7712284342053977, 4.21721250065282, 4.695104390029184, 5.204913144764959,
        5.746407754991062, 6.319106965652954, 6.922270680150768, 7.554893100402756,
        8.215697787823299, 8.903134878667254, 9.615380734842036, 10.350340349435529,
        11.105652850248816, 11.878700452044525, 12.666621193886066, 13.46632575768746,
        14.274518599214796, 15.087723535725162, 15.90231382557928, 16.714546647836535,
        17.520601751789595, 18.31662390375836, 19.098768614969323, 19.863250496622456,
        20.606393464266684, 21.324681906881935, 22.014811847946564, 22.673741060113894,
        23.298737054536723, 23.887421848023166, 24.43781241381408, 24.948355745607742,
        25.417957508297253, 25.846003308746543, 26.232371695233024, 26.577438087839617,
        26.8820689550814, 27.147605685372113, 27.3758377617634, 27.568965042932895,
    ];

    /// `scipy.signal.sosfiltfilt(scipy.signal.butter(3, 7.5, fs=500, output='sos'), x)`
    /// (SciPy 1.17.1).
    #[rustfmt::skip]
    const ORDER3_7_5HZ_500HZ: [f64; 60] = [
        -0.22859480949263825, -0.13580612134228184, -0.028667319826189377, 0.093664217237664,
        0.23201567160053946, 0.38719239454957566, 0.5599709910381292, 0.7510918143957512,
        0.9612509176502971, 1.191091524868375, 1.4411950950493153, 1.7120721527525227,
        2.0041531326795874, 2.317779450411505, 2.653195002225599, 3.010538353387564,
        3.389835850682583, 3.790995790452991, 4.213803738976928, 4.65791910718575,
        5.122872993144147, 5.608067199172856, 6.112774330934466, 6.636138895601476,
        7.177179244178965, 7.734790176355184, 8.307746106306489, 8.894704731278072,
        9.494211123304906, 10.104702222024104, 10.724511825050365, 11.351876201749638,
        11.984940441695954, 12.621765717853762, 13.260337708676499, 13.898576370585443,
        14.53434719470386, 15.165474101123428, 15.78975408913474, 16.404973629832426,
        17.00892670849129, 17.599434412281564, 18.17436587153721, 18.73166023381502,
        19.269349323837233, 19.785580656687937, 20.278640404147833, 20.74697586180622,
        21.189217024538188, 21.604196924547086, 21.990970348321994, 22.34883056151184,
        22.677323759765848, 22.976260976341766, 23.2457271165493, 23.486086797593476,
        23.697986703518367, 23.88235408391618, 24.040390912393324, 24.173563193142396,
    ];

    fn assert_all_close(y: &[f64], reference: &[f64]) {
        assert_eq!(y.len(), reference.len());
        for (a, b) in y.iter().zip(reference) {
            assert_relative_eq!(*a, *b, epsilon = 1e-10, max_relative = 1e-10);
        }
    }

    fn lp(order: usize, cutoff_hz: f64, rate_hz: f64) -> Butterworth {
        Butterworth::low_pass(order, cutoff_hz, rate_hz).unwrap()
    }

    fn design_error(order: usize, cutoff_hz: f64, rate_hz: f64) -> FilterError {
        Butterworth::low_pass(order, cutoff_hz, rate_hz).unwrap_err()
    }

    #[test]
    fn filtfilt_matches_scipy_order_4() {
        let f = lp(4, 20.0, 1000.0);
        assert_eq!((f.sections().len(), f.padding()), (2, 15));
        assert_all_close(&f.filtfilt(&signal()).unwrap(), &ORDER4_20HZ_1KHZ);
    }

    #[test]
    fn filtfilt_matches_scipy_odd_order_3() {
        let f = lp(3, 7.5, 500.0);
        assert_eq!((f.sections().len(), f.padding()), (2, 12));
        assert_all_close(&f.filtfilt(&signal()).unwrap(), &ORDER3_7_5HZ_500HZ);
    }

    #[test]
    fn causal_pass_matches_scipy_sosfilt() {
        // scipy.signal.sosfilt(scipy.signal.butter(4, 20, fs=1000, output='sos'), x)[:5]
        #[rustfmt::skip]
        let reference = [6.64686444937645e-06, 5.419803425981364e-05, 0.0002196275275904021,
            0.0006188358890317498, 0.0014291423938964304];
        assert_all_close(&lp(4, 20.0, 1000.0).filter(&signal())[..5], &reference);
    }

    #[test]
    fn constant_signal_is_unchanged() {
        for f in [lp(1, 50.0, 1000.0), lp(4, 20.0, 1000.0), lp(7, 3.0, 250.0)] {
            assert_relative_eq!(f.gain(0.0), 1.0, epsilon = 1e-12);
            for v in f.filtfilt(&[2.5; 100]).unwrap() {
                assert_relative_eq!(v, 2.5, epsilon = 1e-12, max_relative = 1e-12);
            }
        }
    }

    #[test]
    fn gain_at_cutoff_is_half_power() {
        use core::f64::consts::{FRAC_1_SQRT_2, PI};
        for order in 1..=MAX_ORDER {
            let f = lp(order, 20.0, 1000.0);
            assert_eq!((f.order(), f.sections().len()), (order, order.div_ceil(2)));
            assert_eq!((f.cutoff_hz(), f.rate_hz()), (20.0, 1000.0));
            assert_relative_eq!(f.gain(20.0), FRAC_1_SQRT_2, epsilon = 1e-12);
            assert!(f.gain(100.0) < f.gain(20.0));
        }
        // Butterworth: |H|² = 1 / (1 + (tan(π f / fs) / tan(π fc / fs))^(2N)).
        let ratio = libm::tan(PI * 0.05) / libm::tan(PI * 0.02);
        let expected = 1.0 / libm::sqrt(1.0 + ratio.powi(8));
        assert_relative_eq!(lp(4, 20.0, 1000.0).gain(50.0), expected, epsilon = 1e-12);
    }

    #[test]
    fn bad_settings_are_rejected() {
        let max = MAX_ORDER;
        assert_eq!(
            design_error(0, 20.0, 1e3),
            FilterError::Order { order: 0, max }
        );
        assert_eq!(
            design_error(13, 20.0, 1e3),
            FilterError::Order { order: 13, max }
        );
        for rate in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            assert!(matches!(
                design_error(4, 20.0, rate),
                FilterError::Rate { .. }
            ));
        }
        for cutoff in [0.0, -5.0, 500.0, 600.0, f64::NAN, f64::INFINITY] {
            assert!(matches!(
                design_error(4, cutoff, 1e3),
                FilterError::Cutoff { .. }
            ));
        }
        let message = design_error(4, 600.0, 1e3).to_string();
        assert!(
            message.contains("600") && message.contains("500"),
            "{message}"
        );
    }

    #[test]
    fn short_signal_is_rejected() {
        let f = lp(4, 20.0, 1000.0);
        let err = f.filtfilt(&[1.0; 15]).unwrap_err();
        let (needed, padding, count) = (16, 15, 15);
        assert_eq!(
            err,
            FilterError::TooShort {
                needed,
                padding,
                count
            }
        );
        assert!(err.to_string().contains("16") && err.to_string().contains("got 15"));
        assert!(f.filtfilt(&[]).is_err());
        assert_eq!(f.filtfilt(&[1.0; 16]).unwrap().len(), 16);
    }

    #[test]
    fn settling_matches_scipy() {
        // numpy/scipy, N = 200001: z = zeros(N); z[N//2] = 1; sos = butter(...);
        // y = sosfilt(sos, sosfilt(sos, z)[::-1])[::-1]; r = abs(y[N//2:]) / abs(y).max();
        // k = last index with r >= tol, plus 1.
        let f = lp(4, 20.0, 1000.0);
        assert_eq!(f.settling_samples(1e-3), 127);
        assert_eq!(f.settling_samples(1e-6), 282);
        assert_eq!(lp(3, 7.5, 500.0).settling_samples(1e-3), 139);
        assert_eq!(lp(2, 1.0, 1000.0).settling_samples(1e-4), 1877);
        // Larger tolerance, shorter settling; anything at or above the peak, none.
        assert!(f.settling_samples(1e-2) < 127);
        assert_eq!(f.settling_samples(2.0), 0);
        let nan = f.settling_samples(f64::NAN);
        assert_eq!(nan, f.settling_samples(f64::EPSILON));
    }
}
