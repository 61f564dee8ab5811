//! The tool behind the force sensor, taken out of what the force law sees: the sensor's bias
//! tared in free space, the tool's weight compensated as the tool rotates, the moment moved
//! from the sensor origin to the tool point.
//!
//! The sensor's reading arrives in base axes about the sensor origin
//! (`armdyn::control::sensed_behind_tool::SensedBehindTool`); with the tool frame's rotation `R`
//! at the measured joints, in the sensor frame it is `s = R^T reading`. Over the tare window
//! `[t0, t1)` the bias is the mean of the samples taken at rest (tool speed below
//! [`TARE_MAX_SPEED_M_S`] and [`TARE_MAX_RATE_RAD_S`]):
//!
//! ```text
//! b = mean(s - W(R))          W(R) = [-R^T m g; -c x R^T m g], the weight's reading
//! ```
//!
//! and from then on the force law receives [`SensorMount::contact_wrench`]`(s, b)`: `R (s - b -
//! W(R))` with the moment moved back to the tool point. Until the window has ended the force
//! law receives no force at all (zero): it cannot switch on a bias it has not yet measured,
//! and when the compensated reading arrives it is the contact wrench plus noise, so nothing
//! jumps. A window during which the tool would touch a surface or move is refused before
//! the run (the scenario's check). Without weight compensation `W` is left in, which is how
//! a tool reads its own weight as contact force.

use nalgebra::Vector3;

use super::{Controller, ControllerInput};
use crate::model::{rotate_wrench, tool_rotation, JointVector, RobotModel, SensorMount, Wrench};

/// Tool speeds above this do not count for the tare, m/s.
pub const TARE_MAX_SPEED_M_S: f64 = 1e-3;
/// Tool angular rates above this do not count for the tare, rad/s.
pub const TARE_MAX_RATE_RAD_S: f64 = 1e-2;

/// When to tare, s: `[start_s, end_s)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TareWindow {
    /// Start, s.
    pub start_s: f64,
    /// End, s (> start).
    pub end_s: f64,
}

/// The force law `inner` reading a sensor behind a tool (see the [module documentation](self)).
#[derive(Clone, Debug)]
pub struct ToolCompensation<C, M> {
    inner: C,
    model: M,
    mount: SensorMount,
    compensate_weight: bool,
    tare: Option<TareWindow>,
    gravity: Vector3<f64>,
    sum: Wrench,
    count: usize,
    bias: Option<Wrench>,
    seen: Wrench,
}

impl<C, M> ToolCompensation<C, M> {
    /// `inner` with the controller's belief of the `mount`, the weight compensated or not,
    /// and the bias tared over `tare` (none: no bias removed, and the force law reads from the
    /// start).
    #[must_use]
    pub fn new<const N: usize>(
        inner: C,
        model: M,
        mount: SensorMount,
        compensate_weight: bool,
        tare: Option<TareWindow>,
    ) -> Self
    where
        M: RobotModel<N>,
    {
        Self {
            inner,
            model,
            mount,
            compensate_weight,
            tare,
            gravity: Vector3::from(M::GRAVITY),
            sum: Wrench::zeros(),
            count: 0,
            bias: None,
            seen: Wrench::zeros(),
        }
    }

    /// The force law.
    #[must_use]
    pub fn inner(&self) -> &C {
        &self.inner
    }

    /// How many samples the tare averaged (0 before it, or if the tool never was at rest).
    #[must_use]
    pub fn tare_samples(&self) -> usize {
        self.count
    }
}

impl<const N: usize, C: Controller<N>, M: RobotModel<N>> Controller<N> for ToolCompensation<C, M> {
    // The tare's sums are not dynamics: once tared, the bias is a constant.
    crate::control::pass_on_state!(inner);

    fn name(&self) -> &'static str {
        self.inner.name()
    }

    fn reset(&mut self) {
        self.inner.reset();
        self.sum = Wrench::zeros();
        self.count = 0;
        self.bias = None;
        self.seen = Wrench::zeros();
    }

    fn step(&mut self, input: &ControllerInput<'_, N>, dt: f64) -> JointVector<N> {
        let r = tool_rotation(&self.model, input.q);
        let s = rotate_wrench(&r.inverse(), input.wrench);
        let mount = if self.compensate_weight {
            self.mount
        } else {
            SensorMount {
                tool_mass_kg: 0.0,
                ..self.mount
            }
        };
        let seen = match (self.tare, self.bias) {
            (Some(w), None) if input.t < w.end_s => {
                if input.t >= w.start_s {
                    let twist = self.model.jacobian(input.q) * input.qd;
                    let speed = Vector3::new(twist[0], twist[1], twist[2]).norm();
                    let rate = Vector3::new(twist[3], twist[4], twist[5]).norm();
                    if speed <= TARE_MAX_SPEED_M_S && rate <= TARE_MAX_RATE_RAD_S {
                        self.sum += s - mount.weight_reading(&r, &self.gravity);
                        self.count += 1;
                    }
                }
                Wrench::zeros()
            }
            (Some(_), None) => {
                let b = if self.count > 0 {
                    self.sum / self.count as f64
                } else {
                    Wrench::zeros()
                };
                self.bias = Some(b);
                mount.contact_wrench(&s, &b, &r, &self.gravity)
            }
            (_, b) => mount.contact_wrench(&s, &b.unwrap_or_else(Wrench::zeros), &r, &self.gravity),
        };
        self.seen = seen;
        self.inner.step(
            &ControllerInput {
                wrench: &seen,
                ..*input
            },
            dt,
        )
    }

    fn report(&self) -> crate::control::StepReport<N> {
        let mut r = self.inner.report();
        r.sensor_bias_estimate = self.bias;
        // The compensated wrench the force law read (zero until the tare window has ended):
        // the reading with the tool's weight and the tared bias taken out.
        r.law_wrench = Some(self.seen);
        r
    }
}
