//! What a set of force gains does on a [`ForceLoop`]: its poles, gain and phase margins,
//! the range of contact stiffness it stays stable over, and its step response's overshoot
//! and settling, all from the discrete model (no simulation of the robot).

use nalgebra::Complex;

use super::loop_model::{ForceGains, ForceLoop, Poles};

/// Smallest damping ratio accepted inside the stiffness range: every closed-loop pole
/// inside the unit circle and, if oscillatory, with `zeta = -Re(s) / |s| >= 0.1`
/// (`s = ln(z) / dt`), so that a run at either end of the range settles (an oscillation at
/// `w` decays e-fold within `1 / (0.1 w)`), not merely "eventually". Real poles, however
/// slow (the integral's), pass.
pub const MIN_DAMPING_RATIO: f64 = 0.1;

/// Points per decade of the stiffness and gain sweeps (then refined by bisection).
const SWEEP_PER_DECADE: usize = 40;

/// The stiffness interval around the design's over which the loop stays stable.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StiffnessRange {
    /// Lowest stiffness, N/m.
    pub k_min: f64,
    /// Highest stiffness, N/m.
    pub k_max: f64,
    /// `k_min` is the sweep's lower end (the loop may stay stable below it).
    pub k_min_is_sweep_end: bool,
    /// `k_max` is the sweep's upper end.
    pub k_max_is_sweep_end: bool,
}

/// Gain and phase margins at the actuator force (all `None` for an unstable loop).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Margins {
    /// Factor by which all three gains can grow before instability (`None`: beyond 1000).
    pub gain_up: Option<f64>,
    /// Factor by which they can shrink (`None`: stable down to 1/1000).
    pub gain_down: Option<f64>,
    /// Smallest angle between the loop transfer and -1 where `|L| = 1`, degrees (`None`:
    /// `|L|` never crosses 1 below the Nyquist frequency).
    pub phase_deg: Option<f64>,
    /// Frequency of that crossing, Hz.
    pub crossover_hz: Option<f64>,
}

/// The response to a step of the force reference, from the discrete model.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StepMetrics {
    /// Largest excess over the reference, % of the step.
    pub overshoot_pct: f64,
    /// Time until the force stays within 5 % of the step, s (`None`: not within the
    /// horizon).
    pub settling_s: Option<f64>,
}

/// Everything [`analyse`] finds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Analysis {
    /// The loop analysed.
    pub model: ForceLoop,
    /// The gains.
    pub gains: ForceGains,
    /// Closed-loop poles.
    pub poles: Poles,
    /// Every pole inside the unit circle.
    pub stable: bool,
    /// Margins (meaningful when stable).
    pub margins: Margins,
    /// The stiffness range containing the model's stiffness (`None`: not stable at it).
    pub range: Option<StiffnessRange>,
    /// Step response over 10 s.
    pub step: StepMetrics,
}

/// Analyses `gains` on `model`, sweeping the stiffness over `sweep = [lo, hi]` N/m.
#[must_use]
pub fn analyse(model: &ForceLoop, gains: &ForceGains, sweep: [f64; 2]) -> Analysis {
    let poles = model.poles(gains);
    Analysis {
        model: *model,
        gains: *gains,
        poles,
        stable: poles.stable(),
        margins: margins(model, gains),
        range: stiffness_range(model, gains, sweep),
        step: step_metrics(model, gains, 10.0),
    }
}

/// The default stiffness sweep around a design stiffness `k`: `[k / 10, 1000 k]`.
#[must_use]
pub fn default_sweep(k: f64) -> [f64; 2] {
    [k / 10.0, 1000.0 * k]
}

/// Whether every pole of `poles` is inside the unit circle and damped by at least
/// [`MIN_DAMPING_RATIO`].
#[must_use]
pub fn well_damped(poles: &Poles) -> bool {
    poles.stable()
        && poles.s().all(|s| {
            let oscillatory = s.im.abs() > 1e-9 * s.norm();
            !oscillatory || -s.re >= MIN_DAMPING_RATIO * s.norm()
        })
}

/// Bisection in `ln x` between `good` (the predicate holds) and `bad`.
fn edge(mut good: f64, mut bad: f64, ok: impl Fn(f64) -> bool) -> f64 {
    for _ in 0..60 {
        let mid = libm::sqrt(good * bad);
        if ok(mid) {
            good = mid;
        } else {
            bad = mid;
        }
        if (bad / good - 1.0).abs() < 1e-6 {
            break;
        }
    }
    good
}

/// The contiguous stiffness interval around the model's own stiffness, within `sweep`,
/// where the loop is [`well_damped`]; `None` if it is not at its own stiffness.
#[must_use]
pub fn stiffness_range(
    model: &ForceLoop,
    gains: &ForceGains,
    sweep: [f64; 2],
) -> Option<StiffnessRange> {
    let k0 = model.stiffness();
    let ok = |k: f64| well_damped(&model.with_stiffness(k).poles(gains));
    if !ok(k0) {
        return None;
    }
    let step = libm::pow(10.0, 1.0 / SWEEP_PER_DECADE as f64);
    let walk = |toward: f64, end: f64| -> (f64, bool) {
        let mut k = k0;
        loop {
            let next = if toward > 1.0 {
                (k * toward).min(end)
            } else {
                (k * toward).max(end)
            };
            if !ok(next) {
                return (edge(k, next, ok), false);
            }
            if next == end {
                return (end, true);
            }
            k = next;
        }
    };
    let (k_min, lo_end) = walk(1.0 / step, sweep[0].min(k0));
    let (k_max, hi_end) = walk(step, sweep[1].max(k0));
    Some(StiffnessRange {
        k_min,
        k_max,
        k_min_is_sweep_end: lo_end,
        k_max_is_sweep_end: hi_end,
    })
}

/// Gain margins (all three gains scaled together, closed-loop poles checked) and the
/// phase margin (from the loop transfer at the actuator force).
#[must_use]
pub fn margins(model: &ForceLoop, gains: &ForceGains) -> Margins {
    let scaled = |s: f64| ForceGains {
        kfp: gains.kfp * s,
        kfi: gains.kfi * s,
        kvd: gains.kvd * s,
    };
    let stable = |s: f64| model.poles(&scaled(s)).stable();
    let mut m = Margins {
        gain_up: None,
        gain_down: None,
        phase_deg: None,
        crossover_hz: None,
    };
    if !stable(1.0) {
        return m;
    }
    {
        let step = libm::pow(10.0, 1.0 / SWEEP_PER_DECADE as f64);
        let mut s = 1.0;
        while s < 1000.0 {
            if !stable(s * step) {
                m.gain_up = Some(edge(s, s * step, stable));
                break;
            }
            s *= step;
        }
        let mut s = 1.0;
        while s > 1e-3 {
            if !stable(s / step) {
                m.gain_down = Some(edge(s, s / step, stable));
                break;
            }
            s /= step;
        }
    }
    // Phase margin: |L(exp(j w dt))| = 1 crossings, log grid up to Nyquist.
    let nyquist = core::f64::consts::PI / model.dt();
    let (w_lo, points) = (1e-2_f64, 4000);
    let ratio = libm::pow(nyquist * 0.999_999 / w_lo, 1.0 / points as f64);
    let gap = |w: f64| model.loop_transfer(gains, w).norm() - 1.0;
    let mut w = w_lo;
    let mut g = gap(w);
    for _ in 0..points {
        let w2 = w * ratio;
        let g2 = gap(w2);
        if g.is_finite() && g2.is_finite() && (g > 0.0) != (g2 > 0.0) {
            let (mut a, mut b) = (w, w2);
            for _ in 0..60 {
                let mid = libm::sqrt(a * b);
                if (gap(mid) > 0.0) == (g > 0.0) {
                    a = mid;
                } else {
                    b = mid;
                }
            }
            let l: Complex<f64> = model.loop_transfer(gains, a);
            let pm = libm::acos((-l.re / l.norm()).clamp(-1.0, 1.0)).to_degrees();
            if m.phase_deg.is_none_or(|p| pm < p) {
                m.phase_deg = Some(pm);
                m.crossover_hz = Some(a / (2.0 * core::f64::consts::PI));
            }
        }
        w = w2;
        g = g2;
    }
    m
}

/// Overshoot and 5 % settling of the model's response to a force step, over `horizon_s`.
#[must_use]
pub fn step_metrics(model: &ForceLoop, gains: &ForceGains, horizon_s: f64) -> StepMetrics {
    let n = (horizon_s / model.dt()).round().max(1.0) as usize;
    let mut f = vec![0.0; n];
    model.step_response(gains, 1.0, &mut f);
    let overshoot = f.iter().fold(0.0_f64, |m, x| m.max(x - 1.0));
    let last_out = f.iter().rposition(|x| !(x - 1.0).abs().le(&0.05));
    StepMetrics {
        overshoot_pct: if overshoot.is_finite() {
            overshoot * 100.0
        } else {
            f64::INFINITY
        },
        settling_s: match last_out {
            None => Some(0.0),
            Some(i) if i + 1 >= n => None,
            Some(i) => Some((i + 1) as f64 * model.dt()),
        },
    }
}
