//! A controller that reads the contact through a force/torque sensor at the tool point
//! ([`ForceSensor`]: bias, noise and filter); everything else passes through.

use crate::contact::ForceSensor;
use crate::control::{Controller, ControllerInput};
use crate::model::{JointVector, Wrench};

/// A controller that sees the contact wrench through a [`ForceSensor`]; everything else is
/// passed through. The simulator still records the true wrench.
#[derive(Clone, Debug)]
pub struct Sensed<C> {
    inner: C,
    sensor: ForceSensor,
    /// The last reading.
    measured: Option<Wrench>,
}

impl<C> Sensed<C> {
    /// Wraps `inner` with `sensor`.
    #[must_use]
    pub fn new(inner: C, sensor: ForceSensor) -> Self {
        Self {
            inner,
            sensor,
            measured: None,
        }
    }
}

impl<const N: usize, C: Controller<N>> Controller<N> for Sensed<C> {
    fn name(&self) -> &'static str {
        self.inner.name()
    }

    fn reset(&mut self) {
        self.inner.reset();
        self.sensor.reset();
        self.measured = None;
    }

    fn report(&self) -> super::StepReport<N> {
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
        let measured = self.sensor.measure(input.wrench, dt);
        self.measured = Some(measured);
        let seen = ControllerInput {
            wrench: &measured,
            ..*input
        };
        self.inner.step(&seen, dt)
    }
}
