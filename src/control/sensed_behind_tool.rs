//! A force/torque sensor mounted before a tool ([`SensorMount`]): it reports the contact and
//! the tool's weight in its own frame, with its bias, noise and filter ([`ForceSensor`], in the
//! sensor frame), and the controller receives that reading in base axes, about the sensor
//! origin. Undoing it (the weight, the tared bias, the lever to the tool point) is the
//! controller's job: [`ToolCompensation`](super::tool_compensation::ToolCompensation).

use nalgebra::Vector3;

use super::sensed::{Sensed, SensorPlacement};
use crate::contact::ForceSensor;
use crate::model::{rotate_wrench, tool_rotation, JointVector, RobotModel, SensorMount, Wrench};

/// A sensor mounted as `mount` on the robot `model` (see the [module documentation](self)).
#[derive(Clone, Debug)]
pub struct BehindTool<M> {
    model: M,
    mount: SensorMount,
    /// The robot's gravity, m/s^2 (the tool's weight).
    gravity: Vector3<f64>,
}

/// `inner` behind a sensor mounted before a tool; the simulator still records the true
/// contact wrench.
pub type SensedBehindTool<C, M> = Sensed<C, BehindTool<M>>;

impl<C, M> Sensed<C, BehindTool<M>> {
    /// `inner` reading `sensor` (its bias in the sensor frame) mounted as `mount` on the
    /// robot `model` (for the tool frame's pose; its gravity is the tool's).
    #[must_use]
    pub fn behind_tool<const N: usize>(
        inner: C,
        model: M,
        mount: SensorMount,
        sensor: ForceSensor,
    ) -> Self
    where
        M: RobotModel<N>,
    {
        let gravity = Vector3::from(M::GRAVITY);
        Self::placed(
            inner,
            BehindTool {
                model,
                mount,
                gravity,
            },
            sensor,
        )
    }
}

impl<const N: usize, M: RobotModel<N>> SensorPlacement<N> for BehindTool<M> {
    /// The sensor's reading of the contact and the tool's weight in its own frame
    /// ([`SensorMount::reading`]), through `sensor`, turned to base axes.
    fn reading(
        &self,
        sensor: &mut ForceSensor,
        wrench: &Wrench,
        q: &JointVector<N>,
        dt: f64,
    ) -> Wrench {
        let r = tool_rotation(&self.model, q);
        let truth = self.mount.reading(wrench, &r, &self.gravity);
        rotate_wrench(&r, &sensor.measure(&truth, dt))
    }
}
