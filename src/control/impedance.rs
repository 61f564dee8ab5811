//! Cartesian impedance control (Hogan's stiffness and damping, model-based), the first
//! baseline force-control users reach for: the tool behaves as a spring and damper to a
//! virtual point, and a force is obtained by putting that point inside the surface. One law
//! for every arm, in the robot's task (the SCARA's `x y z yaw` is its four-row case), with a
//! null-space posture on a redundant arm.
//!
//! With `n` the outward normal at the point of the (nominal) surface closest to the tool,
//! `e = x_d - x`, `e' = xdot_d - xdot`:
//!
//! ```text
//! F_lin = k_t (e - n e_n) + d_t (e' - n e'_n) + n F_n        (translation)
//! F_n   = k_n e_n + d_n e'_n                                  (position control)
//! F_n   = K_n (h_d - h) - D_n v_n                             (force control: the virtual point
//!                                                             h_d = f_d (1 / K_n + 1 / k_c) above
//!                                                             the expected surface, NormalImpedance)
//! F_rot = k_yaw wrap(yaw_d - yaw) + d_yaw (w_d - w)           (a task with the yaw alone, about z)
//! F_rot = K_r log(R_d R^T) + D_r (w_d - w),  K_r = k_tilt I + (k_yaw - k_tilt) n n^T
//!                                                             (all three rotations; R_d holds the
//!                                                             tool to the normal, ToolOrientation)
//! tau   = J^T F + c + g  (+ (I - J^T Lambda J M^-1) M (Kp0 (q_d - q) + Kd0 (qd_d - qd)))
//! ```
//!
//! No force is fed back: the virtual point gives `f_d` at rest when the surface is where it
//! is expected and as stiff as assumed (`k_c`). A surface `delta` m off its expected place
//! changes the force by `delta K_n k / (K_n + k)`: the series stiffness of the impedance and
//! the contact times the height error, and it stays. The tangent plane is isotropic (a
//! surface has no preferred tangent axis). Every matrix is fixed-size; the step never
//! allocates.

use nalgebra::{Vector3, Vector6};

use super::normal_law::{NormalCommand, NormalLaw, NormalSample};
use super::normal_reading::NormalSelector;
use super::selection::{Decision, SelectionPolicy};
use super::task_frame::TaskFrame;
use super::task_space::{task_rows, OperationalSpace};
use super::tool_orientation::ToolOrientation;
use super::{Controller, ControllerInput};
use crate::model::{JointVector, Pose, RobotModel, Wrench};
use crate::target::{orientation, wrap_angle, Rotations, Task};

/// Stiffness and damping of the impedance in the task frame, and the contact stiffness
/// the controller assumes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ImpedanceGains {
    /// Along the normal, N/m.
    pub normal_stiffness: f64,
    /// Along the normal, N s/m.
    pub normal_damping: f64,
    /// In the tangent plane, N/m.
    pub tangential_stiffness: f64,
    /// In the tangent plane, N s/m.
    pub tangential_damping: f64,
    /// About base z for a task with the yaw alone, about the normal for a task of all three
    /// rotations, N m/rad.
    pub yaw_stiffness: f64,
    /// Likewise, N m s/rad.
    pub yaw_damping: f64,
    /// About the tangent axes (the tool's tilt off the normal) for a task of all three
    /// rotations, N m/rad.
    pub tilt_stiffness: f64,
    /// About the tangent axes, N m s/rad.
    pub tilt_damping: f64,
    /// The contact stiffness assumed when placing the virtual point, N/m (> 0).
    pub contact_stiffness: f64,
}

impl ImpedanceGains {
    /// How far inside the expected surface the virtual point goes for a normal force
    /// `f_d` (N, negative = pressing): `f_d (1 / K_n + 1 / k_c)`, m (negative = inside).
    #[must_use]
    pub fn virtual_gap(&self, f_d: f64) -> f64 {
        f_d * (1.0 / self.normal_stiffness + 1.0 / self.contact_stiffness)
    }

    /// The series stiffness of the impedance and a contact of stiffness `k`, N/m: the
    /// force error per metre of surface height error.
    #[must_use]
    pub fn series_stiffness(&self, k: f64) -> f64 {
        self.normal_stiffness * k / (self.normal_stiffness + k)
    }
}

/// The impedance along the normal as a [`NormalLaw`]: `F_n = K_n (h_d - h) - D_n v`, the
/// virtual point `h_d = f_d (1 / K_n + 1 / k_c)` above the expected surface (negative:
/// inside); the measured force is not used.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NormalImpedance {
    gains: ImpedanceGains,
}

impl NormalImpedance {
    /// The normal part of `gains`.
    #[must_use]
    pub fn new(gains: ImpedanceGains) -> Self {
        Self { gains }
    }
}

impl NormalLaw for NormalImpedance {
    fn name(&self) -> &'static str {
        "impedance"
    }

    fn controller_names(&self) -> (&'static str, &'static str) {
        ("hybrid-impedance", "task-space-hybrid-impedance")
    }

    fn reset(&mut self) {}

    fn step(&mut self, s: &NormalSample, _dt: f64) -> NormalCommand {
        let g = &self.gains;
        NormalCommand::Force(
            g.normal_stiffness * (g.virtual_gap(s.f_d) - s.height_m) - g.normal_damping * s.v,
        )
    }
}

/// The null-space posture's stiffness (1/s^2) and damping (1/s), as in
/// [`TaskSpaceGains`](super::task_space::TaskSpaceGains).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PostureGains {
    /// Stiffness, 1/s^2.
    pub kp: f64,
    /// Damping, 1/s.
    pub kd: f64,
}

/// Cartesian impedance in the robot's task (see the [module documentation](self)), with the
/// selection (time or contact, with a force ramp) of the hybrid law.
#[derive(Clone, Debug)]
pub struct CartesianImpedance<const N: usize, R> {
    robot: R,
    gains: ImpedanceGains,
    posture: PostureGains,
    task: Task,
    normal: NormalImpedance,
    tool: ToolOrientation,
    switch: NormalSelector,
}

/// `a I + (b - a) n n^T` applied to `v`: `b` along `n`, `a` across it.
fn along_across(n: &Vector3<f64>, along: f64, across: f64, v: &Vector3<f64>) -> Vector3<f64> {
    v * across + n * ((along - across) * n.dot(v))
}

impl<const N: usize, R: RobotModel<N>> CartesianImpedance<N, R> {
    /// The impedance for `robot`'s task ([`RobotModel::TASK`], which must control all three
    /// translations) with `gains`, the `posture` gains in the null space of a redundant arm,
    /// the orientation rule `tool` (for a task of all three rotations), switching by
    /// `selection`. `None` if the task lacks a translation.
    #[must_use]
    pub fn new(
        robot: R,
        gains: ImpedanceGains,
        posture: PostureGains,
        frame: TaskFrame,
        tool: ToolOrientation,
        selection: SelectionPolicy,
    ) -> Option<Self> {
        let task = R::TASK;
        let mask = task.mask();
        if mask[0] != 1.0 || mask[1] != 1.0 || mask[2] != 1.0 {
            return None;
        }
        Some(Self {
            robot,
            gains,
            posture,
            task,
            normal: NormalImpedance::new(gains),
            tool,
            switch: NormalSelector::new(frame, selection),
        })
    }

    /// The gains.
    #[must_use]
    pub fn gains(&self) -> &ImpedanceGains {
        &self.gains
    }

    /// The rotational wrench: the yaw's about base z for a task with the yaw alone, about the
    /// normal and the tangent axes for one of all three rotations, N m.
    fn rotational(
        &self,
        input: &ControllerInput<'_, N>,
        pose: &Pose,
        twist: &Vector6<f64>,
        n: &Vector3<f64>,
        reference_gap: Option<f64>,
    ) -> Vector3<f64> {
        let (g, c) = (&self.gains, input.cartesian);
        match self.task.rotations() {
            Rotations::None => Vector3::zeros(),
            Rotations::Yaw => {
                let yaw = libm::atan2(pose[(1, 0)], pose[(0, 0)]);
                Vector3::new(
                    0.0,
                    0.0,
                    g.yaw_stiffness * wrap_angle(c.yaw() - yaw)
                        + g.yaw_damping * (c.angular_velocity.z - twist[5]),
                )
            }
            Rotations::Full => {
                let forcing = self.switch.force_active();
                let r_d = self
                    .tool
                    .target_at(&c.orientation, n, reference_gap, forcing);
                let e_o = orientation::error(&r_d, &orientation::of_pose(pose));
                let e_w = c.angular_velocity - Vector3::new(twist[3], twist[4], twist[5]);
                along_across(n, g.yaw_stiffness, g.tilt_stiffness, &e_o)
                    + along_across(n, g.yaw_damping, g.tilt_damping, &e_w)
            }
        }
    }
}

impl<const N: usize, R: RobotModel<N>> Controller<N> for CartesianImpedance<N, R> {
    fn name(&self) -> &'static str {
        if self.task.rotations() == Rotations::Full {
            "task-space-impedance"
        } else {
            "impedance"
        }
    }

    fn reset(&mut self) {
        self.switch.reset();
    }

    fn report(&self) -> super::StepReport<N> {
        self.switch.report(None)
    }

    fn step(&mut self, input: &ControllerInput<'_, N>, dt: f64) -> JointVector<N> {
        let (q, qd) = (input.q, input.qd);
        let mask = self.task.mask();
        let j = task_rows(&self.task, self.robot.jacobian(q));
        let twist: Wrench = j * qd;
        let v = Vector3::new(twist[0], twist[1], twist[2]);
        let pose = self.robot.end_effector_pose(q);
        let p = Vector3::new(pose[(0, 3)], pose[(1, 3)], pose[(2, 3)]);
        let reading = self.switch.read(input, &p, dt);
        let n = reading.n;
        let c = input.cartesian;
        let (mut x_d, mut v_d) = (c.position, c.velocity);
        let normal_force = match reading.decision {
            Decision::Position {
                offset_m,
                offset_rate_m_s,
            } => {
                x_d -= n * offset_m;
                v_d -= n * offset_rate_m_s;
                None
            }
            Decision::Force { .. } => {
                // The tool's height above the expected surface (or, for a frame that knows no
                // surface, above the reference along n).
                let sample = NormalSample {
                    f_d: reading.f_d,
                    f: reading.f_n,
                    v: n.dot(&v),
                    height_m: reading.tool_gap.unwrap_or_else(|| n.dot(&(p - c.position))),
                };
                match self.normal.step(&sample, dt) {
                    NormalCommand::Force(f) => Some(f),
                    NormalCommand::Height { .. } => None,
                }
            }
        };
        let e = x_d - p;
        let ev = v_d - v;
        let g = &self.gains;
        let (e_n, ev_n) = (n.dot(&e), n.dot(&ev));
        let f_lin = (e - n * e_n) * g.tangential_stiffness
            + (ev - n * ev_n) * g.tangential_damping
            + n * normal_force.unwrap_or(e_n * g.normal_stiffness + ev_n * g.normal_damping);
        let f_rot = self.rotational(input, &pose, &twist, &n, reading.reference_gap);
        let f =
            Vector6::new(f_lin.x, f_lin.y, f_lin.z, f_rot.x, f_rot.y, f_rot.z).component_mul(&mask);
        if self.task.redundancy(N) == 0 {
            return j.transpose() * f + self.robot.gravity(q) + self.robot.coriolis(q, qd);
        }
        let Some(space) = OperationalSpace::new(&self.robot, q, qd, j, &mask, self.task.len())
        else {
            return self.robot.mass_matrix_and_bias(q, qd).1;
        };
        let target = input.target;
        let acc0 = (target.q - q) * self.posture.kp + (target.qd - qd) * self.posture.kd;
        j.transpose() * f + space.bias + space.null_space_torque(&acc0)
    }
}
