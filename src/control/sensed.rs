//! A controller that reads the contact through a force/torque sensor ([`ForceSensor`]: bias,
//! noise and filter), placed at the tool point ([`AtToolPoint`]) or before a tool
//! ([`BehindTool`](super::sensed_behind_tool::BehindTool)); everything else passes through.

use crate::contact::ForceSensor;
use crate::control::{Controller, ControllerInput};
use crate::model::{JointVector, Wrench};

/// Where the sensor sits: what it reads of the contact wrench at the tool point.
pub trait SensorPlacement<const N: usize> {
    /// The reading the controller receives for the contact wrench `wrench` (base axes, at the
    /// tool point, N and N m) at the joint positions `q`, through `sensor` over `dt` s.
    fn reading(
        &self,
        sensor: &mut ForceSensor,
        wrench: &Wrench,
        q: &JointVector<N>,
        dt: f64,
    ) -> Wrench;
}

/// A sensor at the tool point, in base axes: it reads the contact wrench itself.
#[derive(Clone, Copy, Debug, Default)]
pub struct AtToolPoint;

impl<const N: usize> SensorPlacement<N> for AtToolPoint {
    fn reading(
        &self,
        sensor: &mut ForceSensor,
        wrench: &Wrench,
        _q: &JointVector<N>,
        dt: f64,
    ) -> Wrench {
        sensor.measure(wrench, dt)
    }
}

/// A controller that sees the contact wrench through a [`ForceSensor`] placed as `P` says;
/// everything else is passed through. The simulator still records the true wrench.
#[derive(Clone, Debug)]
pub struct Sensed<C, P = AtToolPoint> {
    inner: C,
    placement: P,
    sensor: ForceSensor,
    /// The last reading.
    measured: Option<Wrench>,
}

impl<C> Sensed<C> {
    /// Wraps `inner` with `sensor` at the tool point.
    #[must_use]
    pub fn new(inner: C, sensor: ForceSensor) -> Self {
        Self::placed(inner, AtToolPoint, sensor)
    }
}

impl<C, P> Sensed<C, P> {
    /// Wraps `inner` with `sensor` placed as `placement`.
    #[must_use]
    pub fn placed(inner: C, placement: P, sensor: ForceSensor) -> Self {
        Self {
            inner,
            placement,
            sensor,
            measured: None,
        }
    }

    /// The controller behind the sensor.
    #[must_use]
    pub fn inner(&self) -> &C {
        &self.inner
    }
}

impl<const N: usize, C: Controller<N>, P: SensorPlacement<N>> Controller<N> for Sensed<C, P> {
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
        let measured = self
            .placement
            .reading(&mut self.sensor, input.wrench, input.q, dt);
        self.measured = Some(measured);
        let seen = ControllerInput {
            wrench: &measured,
            ..*input
        };
        self.inner.step(&seen, dt)
    }
}
