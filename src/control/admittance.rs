//! Admittance control: the normal force error moves the motion loop's target along the
//! normal through a virtual mass and damper, and the loop (the thesis's PID with feedback
//! linearization through the task rows, or task-space inverse dynamics in the full task
//! frame) tracks the moved reference. It is the hybrid law
//! ([`HybridForcePosition`](super::hybrid::HybridForcePosition)) with the mass-damper
//! ([`NormalAdmittance`]) as its force law: a law that commands a height rather than a force.
//!
//! ```text
//! M_a d'' + D_a d' = f_d - f        (d: the target's height above the expected surface, m)
//! p_t = p_ref + n (d - h_ref),  v_t = v_ref + n (d' - n . v_ref)    (h_ref: the reference's height)
//! ```
//!
//! `f`, `f_d` are normal forces of the tool on the surface (negative = pressing); a push
//! short of the target moves the reference further in. At rest `f = f_d` whatever the
//! surface's height or stiffness: the damper integrates the error. At the switch the
//! mass-damper starts from the target's height and rate (bumpless).

use super::hybrid::{JointHybrid, TaskSpaceHybrid};
use super::normal_law::{NormalCommand, NormalLaw, NormalSample};

/// Admittance around a joint-space position controller `P` through the task rows.
pub type Admittance<const N: usize, R, P> = JointHybrid<N, R, P, NormalAdmittance>;

/// Admittance in the full task frame.
pub type TaskSpaceAdmittance<const N: usize, R> = TaskSpaceHybrid<N, R, NormalAdmittance>;

/// The virtual mass-damper.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AdmittanceGains {
    /// Virtual mass, kg (> 0).
    pub mass_kg: f64,
    /// Virtual damping, N s/m (> 0).
    pub damping: f64,
}

/// The admittance's virtual mass-damper as a [`NormalLaw`]: its state is the position
/// loop's target height above the expected surface, driven by the force error.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NormalAdmittance {
    gains: AdmittanceGains,
    height_m: f64,
    rate_m_s: f64,
}

impl NormalAdmittance {
    /// At rest on the surface.
    #[must_use]
    pub fn new(gains: AdmittanceGains) -> Self {
        Self {
            gains,
            height_m: 0.0,
            rate_m_s: 0.0,
        }
    }

    /// One period of `dt` s: `M_a d'' + D_a d' = f_d - f` with the error held (exact, stable
    /// for any period; `d'` relaxes towards `(f_d - f) / D_a`). Returns the height `d` (m)
    /// and its rate (m/s).
    pub fn advance(&mut self, s: &NormalSample, dt: f64) -> (f64, f64) {
        let g = &self.gains;
        let decay = libm::exp(-g.damping * dt / g.mass_kg);
        let goal = (s.f_d - s.f) / g.damping;
        self.height_m += goal * dt + (self.rate_m_s - goal) * (1.0 - decay) * g.mass_kg / g.damping;
        self.rate_m_s = goal + (self.rate_m_s - goal) * decay;
        (self.height_m, self.rate_m_s)
    }
}

impl NormalLaw for NormalAdmittance {
    fn name(&self) -> &'static str {
        "admittance"
    }

    fn controller_names(&self) -> (&'static str, &'static str) {
        ("admittance", "task-space-admittance")
    }

    fn reset(&mut self) {
        self.height_m = 0.0;
        self.rate_m_s = 0.0;
    }

    fn start(&mut self, _sample: &NormalSample, height_m: f64, rate_m_s: f64) {
        self.height_m = height_m;
        self.rate_m_s = rate_m_s;
    }

    fn step(&mut self, s: &NormalSample, dt: f64) -> NormalCommand {
        let (height_m, rate_m_s) = self.advance(s, dt);
        NormalCommand::Height { height_m, rate_m_s }
    }

    /// The height (m) and its rate (m/s).
    fn state_len(&self) -> usize {
        2
    }

    fn write_state(&self, out: &mut [f64]) {
        out[0] = self.height_m;
        out[1] = self.rate_m_s;
    }

    fn read_state(&mut self, x: &[f64]) {
        self.height_m = x[0];
        self.rate_m_s = x[1];
    }
}
