//! The force loop along the contact normal as a discrete-time system: the robot's apparent
//! mass along the normal pressing on an elastic, damped contact, the PI + feedforward (+
//! velocity damping) law of thesis eq. 5.10-5.11 sampled every `dt` with a zero-order hold,
//! and optionally one period of computation delay.
//!
//! ```text
//! plant (along n, deviation from the contact point):  Lambda x'' = u - f,  f = k x + c x'
//! law (eq. 5.11, sampled):   e_k = f_d - f_k,   I_k = I_{k-1} + dt e_k
//!                            u_k = f_d + Kfp e_k + Kfi I_k - Kvd x'_k
//! ```
//!
//! `f` is the force the tool exerts on the surface along its outward normal `n` (negative
//! = pressing), `x` the tool's position along `n` (negative = inside), `u` the force the
//! actuators exert through the tool along `n`. The law is the sampled form of
//! [`ForcePi`](crate::control::force::ForcePi), step for step (the integral is updated
//! before it is used). In continuous time the loop is the cubic of `docs/control.md`
//! `Lambda s^3 + (Kvd + (1 + Kfp) c) s^2 + ((1 + Kfp) k + Kfi c) s + Kfi k`.

use nalgebra::{Complex, Matrix2, Matrix3, Matrix4, Vector2, Vector3, Vector4};

use super::DesignError;
use crate::model::{JointVector, RobotModel};

/// Force-law gains: `kfp` (1), `kfi` (1/s), `kvd` (N s/m), as in eq. 5.10-5.11.
///
/// ```
/// use armdyn::control::design::ForceGains;
/// let g = ForceGains::THESIS_DAMPED;
/// assert_eq!((g.kfp, g.kfi, g.kvd), (20.0, 5.0, 2000.0));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ForceGains {
    /// Proportional gain on the force error, 1.
    pub kfp: f64,
    /// Integral gain, 1/s.
    pub kfi: f64,
    /// Velocity damping along the normal, N s/m (0: the law of eq. 5.10).
    pub kvd: f64,
}

impl ForceGains {
    /// The thesis's PI + feedforward (Section 5.3.1): 20, 5, 0.
    pub const THESIS: Self = Self {
        kfp: 20.0,
        kfi: 5.0,
        kvd: 0.0,
    };
    /// The thesis's PI + feedforward + velocity damping (Section 5.3.2): 20, 5, 2000.
    pub const THESIS_DAMPED: Self = Self {
        kfp: 20.0,
        kfi: 5.0,
        kvd: 2000.0,
    };
}

/// The apparent mass of a robot along a unit direction `n` at `q`, kg:
/// `Lambda_n = 1 / (n^T J_v M^-1 J_v^T n)`, with `J_v` the linear rows of the geometric
/// Jacobian (the mass a force along `n` at the tool accelerates when nothing else holds
/// the arm). For the SCARA and `n = z` it is `m3 + m4` = 4.94 kg at any pose.
///
/// ```
/// use armdyn::control::design::apparent_mass;
/// use armdyn::model::Scara;
/// use nalgebra::{Vector3, Vector4};
/// let m = apparent_mass(&Scara, &Vector4::new(0.3, 1.0, 0.2, 0.0), &Vector3::z()).unwrap();
/// assert!((m - 4.94).abs() < 0.01);
/// ```
///
/// # Errors
///
/// [`DesignError::Model`] if `M(q)` is not positive definite or `n` cannot be moved along
/// (a singular pose).
pub fn apparent_mass<const N: usize, R: RobotModel<N>>(
    robot: &R,
    q: &JointVector<N>,
    n: &Vector3<f64>,
) -> Result<f64, DesignError> {
    Ok(DirectionalMass::new(robot, q, n)?.mass_kg)
}

/// The joint-space view of a unit direction `n` at `q`: `c = J_v^T n` (joint torques per
/// newton along `n`), `M^-1 c` and the apparent mass `1 / (c^T M^-1 c)`, kg.
pub(super) struct DirectionalMass<const N: usize> {
    pub(super) c: JointVector<N>,
    pub(super) m_inv_c: JointVector<N>,
    pub(super) mass_kg: f64,
}

impl<const N: usize> DirectionalMass<N> {
    /// # Errors
    ///
    /// As [`apparent_mass`].
    pub(super) fn new<R: RobotModel<N>>(
        robot: &R,
        q: &JointVector<N>,
        n: &Vector3<f64>,
    ) -> Result<Self, DesignError> {
        let j = robot.jacobian(q);
        let c =
            JointVector::<N>::from_fn(|i, _| n.x * j[(0, i)] + n.y * j[(1, i)] + n.z * j[(2, i)]);
        let chol = robot.mass_matrix(q).cholesky().ok_or(DesignError::Model(
            "the mass matrix is not positive definite",
        ))?;
        let m_inv_c = chol.solve(&c);
        let inv_mass = c.dot(&m_inv_c);
        if !(inv_mass.is_finite() && inv_mass > 0.0) {
            return Err(DesignError::Model(
                "the tool cannot move along the normal at this pose (singular)",
            ));
        }
        Ok(Self {
            c,
            m_inv_c,
            mass_kg: 1.0 / inv_mass,
        })
    }
}

/// The closed-loop poles of a [`ForceLoop`] (3 without delay, 4 with), in the z plane.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Poles {
    z: [Complex<f64>; 4],
    len: usize,
    dt: f64,
}

impl Poles {
    /// The discrete poles `z`.
    #[must_use]
    pub fn z(&self) -> &[Complex<f64>] {
        &self.z[..self.len]
    }

    /// The equivalent continuous poles `s = ln(z) / dt`, 1/s (a pole at `z = 0`, the
    /// delay's when no gain moves it, maps to a real part of minus infinity).
    pub fn s(&self) -> impl Iterator<Item = Complex<f64>> + '_ {
        let dt = self.dt;
        self.z().iter().map(move |z| z.ln() / dt)
    }

    /// The largest `|z|`; the loop is stable when it is below 1.
    #[must_use]
    pub fn spectral_radius(&self) -> f64 {
        self.z().iter().map(|z| z.norm()).fold(0.0, f64::max)
    }

    /// Whether every pole is strictly inside the unit circle.
    #[must_use]
    pub fn stable(&self) -> bool {
        self.spectral_radius() < 1.0
    }
}

/// The force loop along the normal: apparent mass, contact stiffness and damping, period,
/// and whether one period of computation delay sits between measurement and actuation.
///
/// ```
/// use armdyn::control::design::{ForceGains, ForceLoop};
/// // The thesis's loop: 4.94 kg on 10 kN/m at 1 ms.
/// let l = ForceLoop::new(4.94, 1e4, 0.0, 1e-3, false).unwrap();
/// assert!(!l.poles(&ForceGains::THESIS).stable()); // PI + FF: unstable
/// assert!(l.poles(&ForceGains::THESIS_DAMPED).stable()); // + velocity damping: stable
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ForceLoop {
    mass_kg: f64,
    stiffness: f64,
    damping: f64,
    dt: f64,
    delay: bool,
}

impl ForceLoop {
    /// Apparent mass (kg, > 0), contact stiffness (N/m, > 0) and damping (N s/m, >= 0),
    /// controller period (s, > 0), one period of computation delay or not.
    ///
    /// # Errors
    ///
    /// [`DesignError::Input`] naming the value out of range.
    pub fn new(
        mass_kg: f64,
        stiffness: f64,
        damping: f64,
        dt: f64,
        delay: bool,
    ) -> Result<Self, DesignError> {
        positive("apparent mass (kg)", mass_kg)?;
        positive("contact stiffness (N/m)", stiffness)?;
        positive("controller period (s)", dt)?;
        if !(damping.is_finite() && damping >= 0.0) {
            return Err(DesignError::Input {
                what: "contact damping (N s/m)",
                value: damping,
                rule: "must be finite and >= 0",
            });
        }
        Ok(Self {
            mass_kg,
            stiffness,
            damping,
            dt,
            delay,
        })
    }

    /// The same loop on a contact of another stiffness, N/m (> 0, not checked).
    #[must_use]
    pub fn with_stiffness(&self, stiffness: f64) -> Self {
        Self { stiffness, ..*self }
    }

    /// Apparent mass, kg.
    #[must_use]
    pub fn mass_kg(&self) -> f64 {
        self.mass_kg
    }

    /// Contact stiffness, N/m.
    #[must_use]
    pub fn stiffness(&self) -> f64 {
        self.stiffness
    }

    /// Contact damping, N s/m.
    #[must_use]
    pub fn damping(&self) -> f64 {
        self.damping
    }

    /// Controller period, s.
    #[must_use]
    pub fn dt(&self) -> f64 {
        self.dt
    }

    /// Whether one period of computation delay is modelled.
    #[must_use]
    pub fn delay(&self) -> bool {
        self.delay
    }

    /// Order of the closed loop: 3 (position, velocity, integral), 4 with the delay.
    #[must_use]
    pub fn order(&self) -> usize {
        if self.delay {
            4
        } else {
            3
        }
    }

    /// The plant `[x, x']_{k+1} = Ad [x, x']_k + Bd u_k` under a zero-order hold: the
    /// exponential of `[[A, B], [0, 0]] dt` (nalgebra's Pade `exp`).
    #[must_use]
    pub fn zoh(&self) -> (Matrix2<f64>, Vector2<f64>) {
        let (m, k, c) = (self.mass_kg, self.stiffness, self.damping);
        let a = Matrix3::new(0.0, 1.0, 0.0, -k / m, -c / m, 1.0 / m, 0.0, 0.0, 0.0) * self.dt;
        let e = a.exp();
        (
            Matrix2::new(e[(0, 0)], e[(0, 1)], e[(1, 0)], e[(1, 1)]),
            Vector2::new(e[(0, 2)], e[(1, 2)]),
        )
    }

    /// The state feedback `u = -K z` the law is on the state `z = [x, x', I_{k-1}]`:
    /// `K = [Kp' k, Kp' c + Kvd, -Kfi]` with `Kp' = Kfp + Kfi dt` (the integral is
    /// updated with this sample's error before it is used).
    #[must_use]
    pub fn feedback(&self, g: &ForceGains) -> Vector3<f64> {
        let kp = g.kfp + g.kfi * self.dt;
        Vector3::new(kp * self.stiffness, kp * self.damping + g.kvd, -g.kfi)
    }

    /// The open loop `(A_o, B_o)` of order 4, broken at the actuator force `u`: state
    /// `[x, x', I_{k-1}, u_{k-1}]`. Without delay the last state is unused (its row and
    /// column are zero) and `B_o` drives the plant directly; with delay `u` enters the last
    /// state and the plant sees it one period later.
    #[must_use]
    pub fn open_loop(&self) -> (Matrix4<f64>, Vector4<f64>) {
        let (ad, bd) = self.zoh();
        let (k, c, t) = (self.stiffness, self.damping, self.dt);
        let mut a = Matrix4::zeros();
        a[(0, 0)] = ad[(0, 0)];
        a[(0, 1)] = ad[(0, 1)];
        a[(1, 0)] = ad[(1, 0)];
        a[(1, 1)] = ad[(1, 1)];
        // The integral of the error: e = -(k x + c x') when f_d = 0.
        a[(2, 0)] = -t * k;
        a[(2, 1)] = -t * c;
        a[(2, 2)] = 1.0;
        let mut b = Vector4::zeros();
        if self.delay {
            a[(0, 3)] = bd[0];
            a[(1, 3)] = bd[1];
            b[3] = 1.0;
        } else {
            b[0] = bd[0];
            b[1] = bd[1];
        }
        (a, b)
    }

    /// The closed-loop matrix `A_o - B_o K` (order 4; without delay its last state is
    /// decoupled and left out of [`Self::poles`]).
    #[must_use]
    pub fn closed_loop(&self, g: &ForceGains) -> Matrix4<f64> {
        let (a, b) = self.open_loop();
        let k = self.feedback(g);
        a - b * Vector4::new(k[0], k[1], k[2], 0.0).transpose()
    }

    /// The closed-loop poles, by nalgebra's Schur decomposition.
    #[must_use]
    pub fn poles(&self, g: &ForceGains) -> Poles {
        let a = self.closed_loop(g);
        let mut z = [Complex::new(0.0, 0.0); 4];
        if self.delay {
            let ev = a.complex_eigenvalues();
            z.copy_from_slice(ev.as_slice());
        } else {
            let ev = a
                .fixed_view::<3, 3>(0, 0)
                .into_owned()
                .complex_eigenvalues();
            z[..3].copy_from_slice(ev.as_slice());
        }
        Poles {
            z,
            len: self.order(),
            dt: self.dt,
        }
    }

    /// The loop transfer at the actuator force, `L(z) = K (z I - A_o)^-1 B_o`, at
    /// `z = exp(j w dt)` (`w` in rad/s); the closed loop is stable iff `1 + L` has its
    /// zeros inside the unit circle.
    #[must_use]
    pub fn loop_transfer(&self, g: &ForceGains, w: f64) -> Complex<f64> {
        let (a, b) = self.open_loop();
        let k = self.feedback(g);
        let z = Complex::from_polar(1.0, w * self.dt);
        let n = self.order();
        let m = Matrix4::<Complex<f64>>::from_fn(|i, j| {
            let d = if i == j { z } else { Complex::new(0.0, 0.0) };
            if i < n && j < n {
                d - Complex::new(a[(i, j)], 0.0)
            } else if i == j {
                Complex::new(1.0, 0.0)
            } else {
                Complex::new(0.0, 0.0)
            }
        });
        let rhs = Vector4::<Complex<f64>>::from_fn(|i, _| Complex::new(b[i], 0.0));
        let x = m.lu().solve(&rhs).unwrap_or_else(Vector4::zeros);
        (0..3).map(|i| x[i] * k[i]).sum()
    }

    /// The response of the force `f` (N) to a step of `f_d` from 0 to `step_n` (N),
    /// starting at rest on the surface, sampled every period; `out` receives `f` at the
    /// samples `0, 1, ...` (as many as it holds).
    pub fn step_response(&self, g: &ForceGains, step_n: f64, out: &mut [f64]) {
        let a = self.closed_loop(g);
        // The reference enters as u's feedforward (1 + Kp') f_d and the integral's dt f_d.
        let kp = g.kfp + g.kfi * self.dt;
        let (_, bd) = self.zoh();
        let u_ff = (1.0 + kp) * step_n;
        let mut r = Vector4::new(0.0, 0.0, self.dt * step_n, 0.0);
        if self.delay {
            r[3] = u_ff;
        } else {
            r[0] = bd[0] * u_ff;
            r[1] = bd[1] * u_ff;
        }
        let mut z = Vector4::<f64>::zeros();
        for f in out.iter_mut() {
            *f = self.stiffness * z[0] + self.damping * z[1];
            z = a * z + r;
        }
    }
}

fn positive(what: &'static str, v: f64) -> Result<(), DesignError> {
    if v.is_finite() && v > 0.0 {
        Ok(())
    } else {
        Err(DesignError::Input {
            what,
            value: v,
            rule: "must be finite and > 0",
        })
    }
}
