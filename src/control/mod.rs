//! Controllers (thesis Chapters 4 and 5) behind one trait.
//!
//! A controller is sampled by the simulator every control period: it reads the measured
//! joint state, the reference and the measured contact wrench, and returns joint torques
//! (before actuator saturation). `step` never allocates and never fails.

use crate::model::{JointVector, Wrench};
use crate::target::{CartesianTarget, JointTarget};

/// What a controller sees at one sample.
#[derive(Clone, Copy, Debug)]
pub struct ControllerInput<'a, const N: usize> {
    /// Time, s.
    pub t: f64,
    /// Measured joint positions, rad or m.
    pub q: &'a JointVector<N>,
    /// Measured joint velocities, rad/s or m/s.
    pub qd: &'a JointVector<N>,
    /// Joint-space reference (from inverse kinematics of the Cartesian one).
    pub target: &'a JointTarget<N>,
    /// Cartesian reference.
    pub cartesian: &'a CartesianTarget,
    /// Measured wrench the tool exerts on the environment, base frame `[fx fy fz tx ty tz]`.
    pub wrench: &'a Wrench,
    /// Desired wrench, same frame and sign.
    pub wrench_ref: &'a Wrench,
    /// Age of `wrench`, s: the time since the sensor delivered it (0 for a sample of this
    /// period; it grows while no new sample arrives, and the last one is passed again).
    pub wrench_age_s: f64,
}

/// The tool point's position (m) and linear velocity (m/s), base frame, at the state of a
/// controller's last step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ToolState {
    /// Position, m.
    pub position: nalgebra::Vector3<f64>,
    /// Linear velocity, m/s.
    pub velocity: nalgebra::Vector3<f64>,
}

/// What a controller's last step did, for the loop that runs it (the simulator, a robot's
/// driver, a Python loop): one value, which each wrapper passes outward with what it knows
/// added. Copy, no allocation.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct StepReport<const N: usize> {
    /// Whether the step controlled a contact force (a hybrid controller after its switch,
    /// and its supervisor not tripped); `false` for position controllers.
    pub force_controlled: bool,
    /// The force sensor's bias as the controller tared it (sensor frame, N and N m), once the
    /// tare is done; `None` for a controller that tares nothing.
    pub sensor_bias_estimate: Option<Wrench>,
    /// The tool's position and velocity at the step's state, if the step computed them (the
    /// supervisor then need not compute them again).
    pub tool: Option<ToolState>,
    /// The contact wrench the force law read, base frame (N, N m), when a wrapper inside the
    /// supervisor changed the reading on its way (a tool's weight and the sensor's bias taken
    /// out); `None` when the law read the reading itself. The supervisor judges the contact
    /// force by it.
    pub law_wrench: Option<Wrench>,
    /// The force-sensor reading the controller received, base frame (N, N m): the true
    /// wrench through the sensor model and any injected sensor fault; `None` for a controller
    /// that reads the true wrench.
    pub measured_wrench: Option<Wrench>,
    /// What the safety supervisor around the controller saw in the run so far; `None`
    /// without one.
    pub safety: Option<safety::SafetyReport<N>>,
}

/// A feedback controller producing joint torques (N m or N).
pub trait Controller<const N: usize> {
    /// Short name, as used on the command line.
    fn name(&self) -> &'static str;
    /// Clears the internal state (integrators, filters) for a new run.
    fn reset(&mut self);
    /// One control period of `dt` seconds: the joint torques to hold until the next sample.
    fn step(&mut self, input: &ControllerInput<'_, N>, dt: f64) -> JointVector<N>;
    /// What the last step did ([`StepReport`]): whether it controlled a force, what it
    /// measured and estimated, what the supervisor saw. By default a position controller's
    /// (nothing controlled in force, nothing measured). A wrapper returns its inner
    /// controller's report with what it knows added.
    fn report(&self) -> StepReport<N> {
        StepReport::default()
    }
    /// How many numbers [`Self::write_state`] writes: the controller's internal state that
    /// carries from one step to the next and changes with it (integrators, filter states), for
    /// the linearisation of a closed loop ([`crate::sim::linearize`]). 0 by default: a
    /// stateless law. A wrapper's state is its inner controller's followed by its own.
    fn state_len(&self) -> usize {
        0
    }
    /// Writes the internal state into `out[..self.state_len()]`.
    fn write_state(&self, out: &mut [f64]) {
        let _ = out;
    }
    /// Sets the internal state from `x[..self.state_len()]` (as [`Self::write_state`] wrote
    /// it).
    fn read_state(&mut self, x: &[f64]) {
        let _ = x;
    }
}

pub mod admittance;
pub mod computed_torque;
#[cfg(feature = "std")]
pub mod design;
pub mod force;
pub mod fsf;
pub mod gains;
pub mod hybrid;
pub mod impedance;
pub mod jacobian_factor;
pub mod joint_loop;
#[cfg(feature = "std")]
pub mod lqr;
pub mod mass_split;
pub mod motion_loop;
pub mod normal_law;
pub mod normal_reading;
pub mod open_loop;
pub mod pid;
pub mod pid_fl;
pub mod safety;
pub mod selection;
pub mod sensed;
pub mod sensed_behind_tool;
pub mod task_frame;
pub mod task_frame_loop;
pub mod task_rows;
pub mod task_space;
pub mod tool_compensation;
pub mod tool_orientation;

#[cfg(feature = "std")]
impl<const N: usize, C: Controller<N> + ?Sized> Controller<N> for std::boxed::Box<C> {
    fn name(&self) -> &'static str {
        (**self).name()
    }

    fn reset(&mut self) {
        (**self).reset();
    }

    fn step(&mut self, input: &ControllerInput<'_, N>, dt: f64) -> JointVector<N> {
        (**self).step(input, dt)
    }

    fn report(&self) -> StepReport<N> {
        (**self).report()
    }

    fn state_len(&self) -> usize {
        (**self).state_len()
    }

    fn write_state(&self, out: &mut [f64]) {
        (**self).write_state(out);
    }

    fn read_state(&mut self, x: &[f64]) {
        (**self).read_state(x);
    }
}

/// Inside `impl Controller<N> for Wrapper`: the internal state of a wrapper that holds none
/// of its own is its field `$inner`'s (`state_len`, `write_state`, `read_state`).
macro_rules! pass_on_state {
    ($inner:ident) => {
        fn state_len(&self) -> usize {
            self.$inner.state_len()
        }

        fn write_state(&self, out: &mut [f64]) {
            self.$inner.write_state(out);
        }

        fn read_state(&mut self, x: &[f64]) {
            self.$inner.read_state(x);
        }
    };
}
pub(crate) use pass_on_state;
