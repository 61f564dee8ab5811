//! Force laws along the contact normal behind one trait: the thesis's PI + feedforward (+
//! velocity damping) ([`ForcePi`], eq. 5.10-5.11), the impedance's spring to a virtual point
//! ([`NormalImpedance`](super::impedance::NormalImpedance)) and the admittance's virtual
//! mass-damper ([`NormalAdmittance`](super::admittance::NormalAdmittance)). A law turns the
//! normal force error into either a force for the actuators to exert along the normal, or a
//! height for the position loop's target above the expected surface.

use super::force::ForcePi;
use nalgebra::{SMatrix, SVector, Vector3};

/// What a force law sees at one sample, along the outward normal `n` of the expected
/// surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NormalSample {
    /// Desired force of the tool on the surface along `n`, N (negative = pressing).
    pub f_d: f64,
    /// Measured force along `n`, N.
    pub f: f64,
    /// Tool velocity along `n`, m/s.
    pub v: f64,
    /// Tool height above the expected surface along `n`, m (negative = inside).
    pub height_m: f64,
}

/// What a force law asks for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum NormalCommand {
    /// A force for the actuators to exert through the tool along `n`, N.
    Force(f64),
    /// A height (m) and its rate (m/s) above the expected surface for the position loop's
    /// target along `n`.
    Height {
        /// m.
        height_m: f64,
        /// m/s.
        rate_m_s: f64,
    },
}

/// A force law along the contact normal (no allocation, no failure in `step`).
///
/// ```
/// use armdyn::control::force::ForcePi;
/// use armdyn::control::normal_law::{NormalCommand, NormalLaw, NormalSample};
/// let mut law = ForcePi::new(20.0, 5.0, 2000.0);
/// let s = NormalSample { f_d: -200.0, f: -200.0, v: 0.0, height_m: -0.02 };
/// assert_eq!(NormalLaw::step(&mut law, &s, 1e-3), NormalCommand::Force(-200.0));
/// assert_eq!(NormalLaw::name(&law), "pi-ff-vd");
/// assert_eq!(law.controller_names().1, "task-space-hybrid-pi-ff-vd");
/// ```
pub trait NormalLaw {
    /// The law's name, as scenarios write it.
    fn name(&self) -> &'static str;
    /// The names of the hybrid controller with this law along the normal, as outputs and
    /// tables show them: through the task rows of a joint-space loop, and in the full task
    /// frame. Default: `hybrid`, `task-space-hybrid`.
    fn controller_names(&self) -> (&'static str, &'static str) {
        ("hybrid", "task-space-hybrid")
    }
    /// Clears the law's state for a new run.
    fn reset(&mut self);
    /// Force control starts: `height_m` and `rate_m_s` are where the position loop's target
    /// is along `n` (for a bumpless start of a law that moves it). Default: nothing.
    fn start(&mut self, _sample: &NormalSample, _height_m: f64, _rate_m_s: f64) {}
    /// One period of `dt` s.
    fn step(&mut self, sample: &NormalSample, dt: f64) -> NormalCommand;
    /// How many numbers of state the law carries from one period to the next (for the
    /// linearisation of a closed loop, [`Controller::state_len`](super::Controller::state_len)).
    fn state_len(&self) -> usize {
        0
    }
    /// Writes the state into `out[..self.state_len()]`.
    fn write_state(&self, out: &mut [f64]) {
        let _ = out;
    }
    /// Sets the state from `x[..self.state_len()]`.
    fn read_state(&mut self, x: &[f64]) {
        let _ = x;
    }
    /// Anti-windup after a [`Self::step`] (see [`Windup`]): a law with an integral that
    /// `was` (the law as it was before the step) shows driving an actuator further past its
    /// limit takes the step's increment back. By default the torque unchanged.
    fn limit_windup<const N: usize>(&mut self, was: &Self, at: Windup<'_, N>) -> SVector<f64, N>
    where
        Self: Sized,
    {
        let _ = was;
        at.tau
    }
}

/// A force-controlled step as the anti-windup sees it: the joint torques `tau` (N m or N) of
/// the force command, exerted along `n` through the linear rows `j_v` of the Jacobian, and the
/// actuators' limits.
#[derive(Clone, Copy, Debug)]
pub struct Windup<'a, const N: usize> {
    /// The step's torque, N m or N.
    pub tau: SVector<f64, N>,
    /// The linear rows of the Jacobian, m/s per unit joint velocity.
    pub j_v: &'a SMatrix<f64, 3, N>,
    /// The outward normal.
    pub n: &'a Vector3<f64>,
    /// The actuators' limits, N m or N.
    pub effort_limits: &'a [f64; N],
}

impl NormalLaw for ForcePi {
    fn name(&self) -> &'static str {
        if self.kvd() == 0.0 {
            "pi-ff"
        } else {
            "pi-ff-vd"
        }
    }

    fn controller_names(&self) -> (&'static str, &'static str) {
        if self.kvd() == 0.0 {
            ("hybrid-pi-ff", "task-space-hybrid-pi-ff")
        } else {
            ("hybrid-pi-ff-vd", "task-space-hybrid-pi-ff-vd")
        }
    }

    fn reset(&mut self) {
        ForcePi::reset(self);
    }

    fn step(&mut self, s: &NormalSample, dt: f64) -> NormalCommand {
        NormalCommand::Force(ForcePi::step(self, s.f_d, s.f, s.v, dt))
    }

    /// The integral of the force error, N s.
    fn state_len(&self) -> usize {
        1
    }

    fn write_state(&self, out: &mut [f64]) {
        out[0] = self.integral();
    }

    fn read_state(&mut self, x: &[f64]) {
        self.set_integral(x[0]);
    }

    fn limit_windup<const N: usize>(&mut self, was: &Self, at: Windup<'_, N>) -> SVector<f64, N> {
        self.without_windup(at.j_v, at.n, at.tau, was.integral(), at.effort_limits)
    }
}
