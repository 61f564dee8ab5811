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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::ForceSensor;
    use crate::control::sensed_behind_tool::SensedBehindTool;
    use crate::model::Panda;
    use crate::target::{CartesianTarget, JointTarget};
    use nalgebra::UnitQuaternion;

    /// Records the wrench it is given.
    #[derive(Clone, Debug, Default)]
    struct Probe {
        seen: Wrench,
    }

    impl Controller<7> for Probe {
        fn name(&self) -> &'static str {
            "probe"
        }
        fn reset(&mut self) {}
        fn step(&mut self, input: &ControllerInput<'_, 7>, _dt: f64) -> JointVector<7> {
            self.seen = *input.wrench;
            JointVector::zeros()
        }
    }

    #[test]
    fn the_tare_finds_the_bias_and_the_weight_comes_out_as_the_tool_turns() {
        let mount = SensorMount {
            origin_m: Vector3::new(0.0, 0.0, -0.1),
            tool_mass_kg: 1.2,
            tool_com_m: Vector3::new(0.0, 0.01, 0.05),
        };
        let bias = Wrench::new(0.4, -0.2, 3.0, 0.01, 0.0, -0.02);
        let sensor = ForceSensor::new(bias, Wrench::zeros(), None, 1).unwrap();
        let compensated = ToolCompensation::new::<7>(
            Probe::default(),
            Panda,
            mount,
            true,
            Some(TareWindow {
                start_s: 0.0,
                end_s: 0.1,
            }),
        );
        let mut c = SensedBehindTool::behind_tool::<7>(compensated, Panda, mount, sensor);
        let qd = JointVector::<7>::zeros();
        let target = JointTarget::at_rest(qd);
        let cart = CartesianTarget::at_rest(Vector3::zeros(), UnitQuaternion::identity());
        let step = |c: &mut SensedBehindTool<ToolCompensation<Probe, Panda>, Panda>,
                    t: f64,
                    q: &JointVector<7>,
                    w: &Wrench| {
            let input = ControllerInput {
                t,
                q,
                qd: &qd,
                target: &target,
                cartesian: &cart,
                wrench: w,
                wrench_ref: w,
                wrench_age_s: 0.0,
            };
            c.step(&input, 1e-3);
        };
        let q0 = JointVector::<7>::from([0.0, -0.6, 0.0, -2.3, 0.0, 1.7, 0.8]);
        for k in 0..100 {
            step(&mut c, k as f64 * 1e-3, &q0, &Wrench::zeros());
        }
        // Nothing reaches the force law during the tare (the sensor reads bias and weight).
        assert_eq!(c.inner().inner().seen, Wrench::zeros());
        // Turned by 0.6 rad at joints 5 and 6, pressing: the force law sees the contact alone.
        let q1 = q0 + JointVector::<7>::from([0.0, 0.0, 0.0, 0.0, 0.6, -0.6, 0.0]);
        let contact = Wrench::new(1.5, -0.5, -15.0, 0.0, 0.0, 0.0);
        step(&mut c, 0.2, &q1, &contact);
        let estimate = c.report().sensor_bias_estimate.unwrap();
        assert!((estimate - bias).norm() < 1e-12, "{estimate}");
        let seen = c.inner().inner().seen;
        assert!((seen - contact).norm() < 1e-9, "{seen}");
        assert_eq!(c.inner().tare_samples(), 100);
    }
}
