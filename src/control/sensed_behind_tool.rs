//! A controller that reads the contact through a force/torque sensor mounted before a tool
//! ([`SensorMount`]): the sensor reports the contact and the tool's weight in its own frame,
//! with its bias, noise and filter ([`ForceSensor`], in the sensor frame), and the controller
//! receives that reading in base axes, about the sensor origin. Undoing it (the weight, the
//! tared bias, the lever to the tool point) is the controller's job:
//! [`ToolCompensation`](super::tool_compensation::ToolCompensation).

use nalgebra::Vector3;

use crate::contact::ForceSensor;
use crate::control::{Controller, ControllerInput};
use crate::model::{rotate_wrench, tool_rotation, JointVector, RobotModel, SensorMount};

/// `inner` behind a sensor mounted before a tool (see the [module documentation](self)).
/// The simulator still records the true contact wrench.
#[derive(Clone, Debug)]
pub struct SensedBehindTool<C, M> {
    inner: C,
    model: M,
    mount: SensorMount,
    sensor: ForceSensor,
    gravity: Vector3<f64>,
    /// The last reading, base axes.
    measured: Option<crate::model::Wrench>,
}

impl<C, M> SensedBehindTool<C, M> {
    /// `inner` reading `sensor` (its bias in the sensor frame) mounted as `mount` on the
    /// robot `model` (for the tool frame's pose; its gravity is the tool's).
    #[must_use]
    pub fn new<const N: usize>(inner: C, model: M, mount: SensorMount, sensor: ForceSensor) -> Self
    where
        M: RobotModel<N>,
    {
        Self {
            inner,
            model,
            mount,
            sensor,
            gravity: Vector3::from(M::GRAVITY),
            measured: None,
        }
    }
}

impl<C, M> SensedBehindTool<C, M> {
    /// The controller behind the sensor.
    #[must_use]
    pub fn inner(&self) -> &C {
        &self.inner
    }
}

impl<const N: usize, C: Controller<N>, M: RobotModel<N>> Controller<N> for SensedBehindTool<C, M> {
    fn name(&self) -> &'static str {
        self.inner.name()
    }

    fn reset(&mut self) {
        self.inner.reset();
        self.sensor.reset();
        self.measured = None;
    }

    fn report(&self) -> crate::control::StepReport<N> {
        let mut r = self.inner.report();
        r.measured_wrench = r.measured_wrench.or(self.measured);
        r
    }

    fn state_len(&self) -> usize {
        self.inner.state_len() + self.sensor.state_len()
    }

    fn write_state(&self, out: &mut [f64]) {
        let k = self.inner.state_len();
        self.inner.write_state(&mut out[..k]);
        self.sensor.write_state(&mut out[k..]);
    }

    fn read_state(&mut self, x: &[f64]) {
        let k = self.inner.state_len();
        self.inner.read_state(&x[..k]);
        self.sensor.read_state(&x[k..]);
    }

    fn step(&mut self, input: &ControllerInput<'_, N>, dt: f64) -> JointVector<N> {
        let r = tool_rotation(&self.model, input.q);
        let truth = self.mount.reading(input.wrench, &r, &self.gravity);
        let measured = rotate_wrench(&r, &self.sensor.measure(&truth, dt));
        self.measured = Some(measured);
        self.inner.step(
            &ControllerInput {
                wrench: &measured,
                ..*input
            },
            dt,
        )
    }
}
