//! Gains by pole placement: the discrete closed-loop poles of a [`ForceLoop`] put where a
//! requested bandwidth and damping say, and `Kfp`, `Kfi`, `Kvd` read off.
//!
//! The requested continuous poles are a pair with natural frequency
//! `w = 2 pi bandwidth_hz` and damping ratio `zeta`, `s = -zeta w +- j w sqrt(1 - zeta^2)`
//! (two real poles when `zeta >= 1`), and the integral's real pole `s = -2 pi integral_hz`;
//! each maps to `z = exp(s dt)`. The characteristic polynomial of `A_o - B_o K` is affine
//! in `(Kp', Kfi, Kvd)` (one input, so `K` enters with rank one), and matching its
//! coefficients to the requested ones is a linear system. With a period of delay the loop
//! has a fourth pole: the system then also solves for where it falls, `(z - z4)` times
//! the requested cubic, still linear.
//!
//! Why the integral pole is slow: with the force feedforward the response to a reference
//! step is `F / F_d = w^2 / (s^2 + 2 zeta w s + w^2) + 2 zeta w a s / ((s^2 + 2 zeta w s +
//! w^2)(s + a))` (continuous, `a` the integral pole): the second term overshoots by about
//! `2 zeta a / w`. [`DesignSpec::new`] puts it at a hundredth of the bandwidth unless told.

use nalgebra::{Complex, Matrix3, Matrix4, SMatrix, Vector3, Vector4};

use super::loop_model::{ForceGains, ForceLoop, Poles};
use super::DesignError;

/// What is asked of the design.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DesignSpec {
    bandwidth_hz: f64,
    damping: f64,
    integral_hz: f64,
}

/// Default ratio of the integral pole to the bandwidth.
pub const DEFAULT_INTEGRAL_RATIO: f64 = 0.01;

impl DesignSpec {
    /// Natural frequency of the dominant pair (Hz, > 0), its damping ratio (> 0), and the
    /// integral pole (Hz, > 0; `None`: [`DEFAULT_INTEGRAL_RATIO`] of the bandwidth).
    ///
    /// # Errors
    ///
    /// [`DesignError::Input`] naming the value out of range.
    pub fn new(
        bandwidth_hz: f64,
        damping: f64,
        integral_hz: Option<f64>,
    ) -> Result<Self, DesignError> {
        let check = |what, v: f64| {
            if v.is_finite() && v > 0.0 {
                Ok(v)
            } else {
                Err(DesignError::Input {
                    what,
                    value: v,
                    rule: "must be finite and > 0",
                })
            }
        };
        Ok(Self {
            bandwidth_hz: check("bandwidth (Hz)", bandwidth_hz)?,
            damping: check("damping ratio", damping)?,
            integral_hz: check(
                "integral pole (Hz)",
                integral_hz.unwrap_or(DEFAULT_INTEGRAL_RATIO * bandwidth_hz),
            )?,
        })
    }

    /// Natural frequency of the dominant pair, Hz.
    #[must_use]
    pub fn bandwidth_hz(&self) -> f64 {
        self.bandwidth_hz
    }

    /// Damping ratio of the dominant pair.
    #[must_use]
    pub fn damping(&self) -> f64 {
        self.damping
    }

    /// The integral pole, Hz.
    #[must_use]
    pub fn integral_hz(&self) -> f64 {
        self.integral_hz
    }

    /// The three requested continuous poles, 1/s.
    #[must_use]
    pub fn continuous_poles(&self) -> [Complex<f64>; 3] {
        let w = 2.0 * core::f64::consts::PI * self.bandwidth_hz;
        let z = self.damping;
        let pair = if z < 1.0 {
            let wd = w * libm::sqrt(1.0 - z * z);
            [Complex::new(-z * w, wd), Complex::new(-z * w, -wd)]
        } else {
            let r = w * libm::sqrt(z * z - 1.0);
            [Complex::new(-z * w + r, 0.0), Complex::new(-z * w - r, 0.0)]
        };
        let a = -2.0 * core::f64::consts::PI * self.integral_hz;
        [pair[0], pair[1], Complex::new(a, 0.0)]
    }
}

/// Coefficients `[c0, .., c_{N-1}]` of the monic characteristic polynomial
/// `w^N + c_{N-1} w^{N-1} + ... + c0` of an N x N matrix, N <= 4 (Faddeev-LeVerrier).
fn char_poly<const N: usize>(a: &SMatrix<f64, N, N>) -> Vector4<f64> {
    let mut c = [0.0; 5];
    c[N] = 1.0;
    let mut m = SMatrix::<f64, N, N>::zeros();
    for k in 1..=N {
        m = a * m + SMatrix::<f64, N, N>::identity() * c[N + 1 - k];
        c[N - k] = -(a * m).trace() / k as f64;
    }
    Vector4::new(c[0], c[1], c[2], c[3])
}

/// The characteristic polynomial of the closed loop in the delta operator
/// `w = (z - 1) / dt` (so that its coefficients stay of order one and tend to the
/// continuous ones as `dt -> 0`; in `z` they crowd around those of `(z - 1)^n` and the
/// integral's column vanishes like `dt^3`): `[c0..c3]` for an order-4 loop, `[c0..c2, 0]`
/// for an order-3 one (its unused fourth state left out).
fn closed_loop_poly(l: &ForceLoop, kp: f64, kfi: f64, kvd: f64) -> Vector4<f64> {
    // Gains from (Kp', Kfi, Kvd): Kfp = Kp' - Kfi dt.
    let g = ForceGains {
        kfp: kp - kfi * l.dt(),
        kfi,
        kvd,
    };
    let delta = (l.closed_loop(&g) - Matrix4::identity()) / l.dt();
    if l.delay() {
        char_poly(&delta)
    } else {
        char_poly(&delta.fixed_view::<3, 3>(0, 0).into_owned())
    }
}

/// The gains that place the poles `spec` asks for, and the poles they give.
///
/// ```
/// use armdyn::control::design::{design, DesignSpec, ForceLoop};
/// let l = ForceLoop::new(4.94, 1e4, 0.0, 1e-3, false).unwrap();
/// let (g, poles) = design(&l, &DesignSpec::new(20.0, 1.0, None).unwrap()).unwrap();
/// assert!(poles.stable() && g.kvd > 0.0);
/// ```
///
/// # Errors
///
/// [`DesignError::Unplaceable`] if the linear system is singular (the loop is not
/// controllable from the three gains) or gives non-finite gains.
pub fn design(l: &ForceLoop, spec: &DesignSpec) -> Result<(ForceGains, Poles), DesignError> {
    let dt = l.dt();
    let [p1, p2, p3] = spec.continuous_poles().map(|s| ((s * dt).exp() - 1.0) / dt);
    // Requested monic cubic (w - p1)(w - p2)(w - p3) in the delta operator.
    let q2 = -(p1 + p2 + p3).re;
    let q1 = (p1 * p2 + p1 * p3 + p2 * p3).re;
    let q0 = -(p1 * p2 * p3).re;
    let base = closed_loop_poly(l, 0.0, 0.0, 0.0);
    let cols = [
        closed_loop_poly(l, 1.0, 0.0, 0.0) - base,
        closed_loop_poly(l, 0.0, 1.0, 0.0) - base,
        closed_loop_poly(l, 0.0, 0.0, 1.0) - base,
    ];
    let (kp, kfi, kvd) = if l.delay() {
        // c(theta) = (w - w4)(w^3 + q2 w^2 + q1 w + q0): unknowns theta and w4.
        // c0 = -w4 q0, c1 = q0 - w4 q1, c2 = q1 - w4 q2, c3 = q2 - w4.
        let target = Vector4::new(0.0, q0, q1, q2) - base;
        let m = Matrix4::from_fn(|i, j| match j {
            0..=2 => cols[j][i],
            _ => [q0, q1, q2, 1.0][i],
        });
        let x = m.lu().solve(&target).ok_or(DesignError::Unplaceable(
            "the delayed loop's system is singular",
        ))?;
        (x[0], x[1], x[2])
    } else {
        let target = Vector3::new(q0 - base[0], q1 - base[1], q2 - base[2]);
        let m = Matrix3::from_fn(|i, j| cols[j][i]);
        let x = m
            .lu()
            .solve(&target)
            .ok_or(DesignError::Unplaceable("the loop's system is singular"))?;
        (x[0], x[1], x[2])
    };
    let g = ForceGains {
        kfp: kp - kfi * dt,
        kfi,
        kvd,
    };
    if !(g.kfp.is_finite() && g.kfi.is_finite() && g.kvd.is_finite()) {
        return Err(DesignError::Unplaceable("the gains are not finite"));
    }
    Ok((g, l.poles(&g)))
}

/// The continuous-time limit of [`design`] (no delay): matching
/// `Lambda s^3 + (Kvd + (1 + Kfp) c) s^2 + ((1 + Kfp) k + Kfi c) s + Kfi k` to
/// `Lambda (s^2 + 2 zeta w s + w^2)(s + a)`.
#[must_use]
pub fn design_continuous(l: &ForceLoop, spec: &DesignSpec) -> ForceGains {
    let (m, k, c) = (l.mass_kg(), l.stiffness(), l.damping());
    let w = 2.0 * core::f64::consts::PI * spec.bandwidth_hz();
    let a = 2.0 * core::f64::consts::PI * spec.integral_hz();
    let z = spec.damping();
    let kfi = m * w * w * a / k;
    let one_kfp = (m * (w * w + 2.0 * z * w * a) - kfi * c) / k;
    ForceGains {
        kfp: one_kfp - 1.0,
        kfi,
        kvd: m * (2.0 * z * w + a) - one_kfp * c,
    }
}
