//! Finite Fourier series per joint: the excitation trajectories of identification
//! (Swevers et al.), periodic, with closed-form velocity and acceleration. `no_std`.

/// Harmonics per joint.
pub const HARMONICS: usize = 5;

/// `q_i(t) = c_i + s_i sum_l (a_il / (l w)) sin(l w t) - (b_il / (l w)) cos(l w t)`,
/// `w = 2 pi / period`: `c` in rad or m, `a` and `b` in rad/s or m/s (they are the velocity's
/// Fourier coefficients), `s` a dimensionless scale.
///
/// ```
/// use armdyn::identification::FourierExcitation;
/// let mut f = FourierExcitation::<1>::new(10.0, [0.5]);
/// f.set_coefficients(0, [1.0, 0.0, 0.0, 0.0, 0.0], [0.0; 5]);
/// let (q, qd, _) = f.state(0.0);
/// assert!((q[0] - 0.5).abs() < 1e-15 && (qd[0] - 1.0).abs() < 1e-15);
/// // Periodic.
/// let (q10, qd10, _) = f.state(10.0);
/// assert!((q10[0] - q[0]).abs() < 1e-12 && (qd10[0] - qd[0]).abs() < 1e-12);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FourierExcitation<const N: usize> {
    period_s: f64,
    offset: [f64; N],
    a: [[f64; HARMONICS]; N],
    b: [[f64; HARMONICS]; N],
    scale: [f64; N],
}

impl<const N: usize> FourierExcitation<N> {
    /// A still trajectory at `offset` with period `period_s` (s); add motion with
    /// [`Self::set_coefficients`].
    #[must_use]
    pub fn new(period_s: f64, offset: [f64; N]) -> Self {
        Self {
            period_s,
            offset,
            a: [[0.0; HARMONICS]; N],
            b: [[0.0; HARMONICS]; N],
            scale: [1.0; N],
        }
    }

    /// Sets joint `i`'s sine (`a`) and cosine (`b`) velocity coefficients.
    pub fn set_coefficients(&mut self, i: usize, a: [f64; HARMONICS], b: [f64; HARMONICS]) {
        self.a[i] = a;
        self.b[i] = b;
    }

    /// Sets joint `i`'s amplitude scale.
    pub fn set_scale(&mut self, i: usize, s: f64) {
        self.scale[i] = s;
    }

    /// Period, s.
    #[must_use]
    pub fn period_s(&self) -> f64 {
        self.period_s
    }

    /// Offsets `c`.
    #[must_use]
    pub fn offset(&self) -> &[f64; N] {
        &self.offset
    }

    /// Coefficients `(a, b)` of joint `i`, scale applied.
    #[must_use]
    pub fn coefficients(&self, i: usize) -> ([f64; HARMONICS], [f64; HARMONICS]) {
        let s = self.scale[i];
        (self.a[i].map(|x| x * s), self.b[i].map(|x| x * s))
    }

    /// Fundamental angular frequency, rad/s.
    #[must_use]
    pub fn omega(&self) -> f64 {
        2.0 * core::f64::consts::PI / self.period_s
    }

    /// Joint `i`'s motion without offset and scale: `(f, f', f'')` at `t` (s).
    #[must_use]
    pub fn unscaled(&self, i: usize, t: f64) -> (f64, f64, f64) {
        let w = self.omega();
        let (mut q, mut qd, mut qdd) = (0.0, 0.0, 0.0);
        for l in 0..HARMONICS {
            let wl = w * (l + 1) as f64;
            let (s, c) = (libm::sin(wl * t), libm::cos(wl * t));
            let (a, b) = (self.a[i][l], self.b[i][l]);
            q += (a * s - b * c) / wl;
            qd += a * c + b * s;
            qdd += wl * (b * c - a * s);
        }
        (q, qd, qdd)
    }

    /// Positions, velocities and accelerations at `t` (s).
    #[must_use]
    pub fn state(&self, t: f64) -> ([f64; N], [f64; N], [f64; N]) {
        let mut out = ([0.0; N], [0.0; N], [0.0; N]);
        for i in 0..N {
            let (q, qd, qdd) = self.unscaled(i, t);
            let s = self.scale[i];
            out.0[i] = self.offset[i] + s * q;
            out.1[i] = s * qd;
            out.2[i] = s * qdd;
        }
        out
    }
}
