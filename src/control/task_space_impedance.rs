//! Cartesian impedance in the full task frame for any arm: translational and rotational
//! stiffness and damping per task-frame axis, the tool held to the surface's normal, a
//! null-space posture for a redundant arm.
//!
//! With `n` the outward normal at the point of the (nominal) surface closest to the tool,
//! `e_p = p_d - p`, `e_o = log(R_d R^T)` (the orientation target `R_d` of
//! [`ToolOrientation`]: by default the tool axis turned onto `-n`) and the twist error
//! `[e_v; e_w]`:
//!
//! ```text
//! K_t = k_t I + (k_n - k_t) n n^T     D_t = d_t I + (d_n - d_t) n n^T     (translation)
//! K_r = k_tilt I + (k_yaw - k_tilt) n n^T   D_r likewise                  (rotation)
//! F   = [K_t e_p + D_t e_v; K_r e_o + D_r e_w]
//! F_n = K_n (h_d - h) - D_n v_n       under force control, the normal row: the virtual
//!                                     point h_d = f_d (1 / K_n + 1 / k_c) above the expected
//!                                     surface ([`NormalImpedance`])
//! tau = J^T F + c + g + (I - J^T Lambda J M^-1) M (Kp0 (q_d - q) + Kd0 (qd_d - qd))
//! ```
//!
//! No force is fed back: as for the SCARA's [`CartesianImpedance`](super::impedance), a
//! surface `delta` m off its expected place changes the force by `delta K_n k / (K_n + k)`.
//! The tangent plane is isotropic (a surface has no preferred tangent axis); the rotations
//! split into the one about the normal (`yaw`) and the two that tilt the tool off it. The
//! selection (time or contact, with a force ramp) is the hybrid law's.
//!
//! Every matrix is fixed-size; the step never allocates.

use nalgebra::{Vector3, Vector6};

use super::impedance::{ImpedanceGains, NormalImpedance};
use super::normal_law::{NormalCommand, NormalLaw, NormalSample};
use super::normal_reading::NormalSelector;
use super::selection::{Decision, SelectionPolicy};
use super::task_frame::TaskFrame;
use super::task_space::{task_rows, OperationalSpace};
use super::tool_orientation::ToolOrientation;
use super::{Controller, ControllerInput};
use crate::model::{JointVector, RobotModel};
use crate::target::{orientation, Task};

/// The null-space posture's stiffness (1/s^2) and damping (1/s), as in
/// [`TaskSpaceGains`](super::task_space::TaskSpaceGains).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PostureGains {
    /// Stiffness, 1/s^2.
    pub kp: f64,
    /// Damping, 1/s.
    pub kd: f64,
}

/// Cartesian impedance in the full task frame (see the [module documentation](self)).
#[derive(Clone, Debug)]
pub struct TaskSpaceImpedance<const N: usize, R> {
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

impl<const N: usize, R: RobotModel<N>> TaskSpaceImpedance<N, R> {
    /// The impedance for `robot`'s task ([`RobotModel::TASK`], which must control all three
    /// translations) with `gains` (the yaw's about the normal, the tilt's about the tangent
    /// axes), the `posture` gains in the null space, the orientation rule `tool`, switching by
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
}

impl<const N: usize, R: RobotModel<N>> Controller<N> for TaskSpaceImpedance<N, R> {
    fn name(&self) -> &'static str {
        "task-space-impedance"
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
        let pose = self.robot.end_effector_pose(q);
        let p = pose.fixed_view::<3, 1>(0, 3).into_owned();
        let j_full = self.robot.jacobian(q);
        let j = task_rows(&self.task, j_full);
        let twist = j * qd;
        let v = Vector3::new(twist[0], twist[1], twist[2]);
        let reading = self.switch.read(input, &p, dt);
        let n = reading.n;
        let c = input.cartesian;
        let (mut p_d, mut v_d) = (c.position, c.velocity);
        let normal_force = match reading.decision {
            Decision::Position {
                offset_m,
                offset_rate_m_s,
            } => {
                p_d -= n * offset_m;
                v_d -= n * offset_rate_m_s;
                None
            }
            Decision::Force { .. } => {
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
        let r_d = self
            .tool
            .target_at(&c.orientation, &n, reading.reference_gap, reading.forcing());
        let e = self
            .task
            .pose_error(&p_d, &r_d, &p, &orientation::of_pose(&pose));
        let e_p = Vector3::new(e[0], e[1], e[2]);
        let e_o = Vector3::new(e[3], e[4], e[5]);
        let e_v = v_d - v;
        let e_w = c.angular_velocity - Vector3::new(twist[3], twist[4], twist[5]);
        let g = &self.gains;
        let mut f_lin = along_across(&n, g.normal_stiffness, g.tangential_stiffness, &e_p)
            + along_across(&n, g.normal_damping, g.tangential_damping, &e_v);
        if let Some(f) = normal_force {
            f_lin += n * (f - n.dot(&f_lin));
        }
        let f_rot = along_across(&n, g.yaw_stiffness, g.tilt_stiffness, &e_o)
            + along_across(&n, g.yaw_damping, g.tilt_damping, &e_w);
        let f =
            Vector6::new(f_lin.x, f_lin.y, f_lin.z, f_rot.x, f_rot.y, f_rot.z).component_mul(&mask);
        if self.task.redundancy(N) == 0 {
            return j.transpose() * f + self.robot.mass_matrix_and_bias(q, qd).1;
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{forward_dynamics, Panda, Ur5};
    use crate::target::{CartesianTarget, JointTarget};
    use nalgebra::UnitQuaternion;

    fn gains() -> ImpedanceGains {
        ImpedanceGains {
            normal_stiffness: 2000.0,
            normal_damping: 80.0,
            tangential_stiffness: 20_000.0,
            tangential_damping: 300.0,
            yaw_stiffness: 50.0,
            yaw_damping: 2.0,
            tilt_stiffness: 100.0,
            tilt_damping: 4.0,
            contact_stiffness: 1e4,
        }
    }

    #[test]
    fn the_wrench_is_the_stiffness_times_the_error_in_the_task_frame() {
        // UR5 at rest, the reference 1 cm off along x and 0.01 rad about the normal: J^T F
        // with F = [k_t e_p; k_yaw e_o] plus gravity; the tool's x axis held down.
        let robot = Ur5;
        let h = core::f64::consts::FRAC_PI_2;
        let q = JointVector::<6>::from([0.0, -h, h, -h, -h, 0.0]);
        let pose = robot.end_effector_pose(&q);
        let p = pose.fixed_view::<3, 1>(0, 3).into_owned();
        let r = orientation::of_pose(&pose);
        let axis = r.inverse() * -Vector3::z();
        let c = CartesianTarget::at_rest(
            p + Vector3::new(0.01, 0.0, 0.0),
            UnitQuaternion::from_scaled_axis(Vector3::new(0.0, 0.0, 0.01)) * r,
        );
        let mut law = TaskSpaceImpedance::new(
            robot,
            gains(),
            PostureGains { kp: 0.0, kd: 0.0 },
            TaskFrame::Fixed(Vector3::z()),
            ToolOrientation::AlongNormal(axis),
            SelectionPolicy::Time { switch_s: 1.0 },
        )
        .unwrap();
        let qd = JointVector::<6>::zeros();
        let (z, w) = (JointTarget::at_rest(q), Vector6::zeros());
        let input = ControllerInput {
            t: 0.0,
            q: &q,
            qd: &qd,
            target: &z,
            cartesian: &c,
            wrench: &w,
            wrench_ref: &w,
            wrench_age_s: 0.0,
        };
        let tau = law.step(&input, 1e-3);
        let f = Vector6::new(200.0, 0.0, 0.0, 0.0, 0.0, 0.5);
        let expected = robot.jacobian(&q).transpose() * f + robot.gravity(&q);
        assert!((tau - expected).norm() < 1e-6, "{tau} vs {expected}");
        assert!(!law.report().force_controlled);
    }

    #[test]
    fn the_posture_acts_in_the_null_space_only() {
        // Panda at rest on its target pose: only the posture term acts, the tool does not
        // accelerate.
        let robot = Panda;
        let q = JointVector::<7>::from([0.1, -0.6, 0.2, -2.0, 0.1, 1.6, 0.7]);
        let qd = JointVector::<7>::zeros();
        let pose = robot.end_effector_pose(&q);
        let c = CartesianTarget::at_rest(
            pose.fixed_view::<3, 1>(0, 3).into_owned(),
            orientation::of_pose(&pose),
        );
        let mut law = TaskSpaceImpedance::new(
            robot,
            gains(),
            PostureGains {
                kp: 100.0,
                kd: 20.0,
            },
            TaskFrame::Fixed(Vector3::z()),
            ToolOrientation::Reference,
            SelectionPolicy::Time { switch_s: 1.0 },
        )
        .unwrap();
        let posture =
            JointTarget::at_rest(q + JointVector::<7>::from([0.2, 0.0, -0.3, 0.1, 0.0, 0.0, 0.1]));
        let w = Vector6::zeros();
        let input = ControllerInput {
            t: 0.0,
            q: &q,
            qd: &qd,
            target: &posture,
            cartesian: &c,
            wrench: &w,
            wrench_ref: &w,
            wrench_age_s: 0.0,
        };
        let tau = law.step(&input, 1e-3);
        let qdd = forward_dynamics(&robot, &q, &qd, &tau, &JointVector::zeros()).unwrap();
        assert!(qdd.norm() > 1e-3, "the posture moves the joints");
        assert!((robot.jacobian(&q) * qdd).norm() < 1e-9);
    }
}
