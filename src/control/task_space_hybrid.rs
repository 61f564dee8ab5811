//! Hybrid force/motion control in a full task frame for any arm (operational space, Khatib's
//! unified motion and force control), with the tool held to the surface's normal and a
//! null-space posture for a redundant arm.
//!
//! The task frame's first axis is the outward surface normal `n` at the point of the
//! (nominal) surface closest to the tool ([`TaskFrame`]). With `s = [n; 0]` the normal
//! direction of the 6-D task and `P = I - s s^T` the motion directions (the tangent plane and
//! all three rotations):
//!
//! ```text
//! R_d     = Rot(R_ref a -> -n) R_ref                 the orientation target: the tool axis a
//!                                                    (tool frame) turned onto the inward
//!                                                    normal, the rotation about it the
//!                                                    reference's (in free space, blended
//!                                                    from R_ref as the reference comes down:
//!                                                    ToolOrientation::target_at)
//! e       = P [p_d - p; log(R_d R^T)]                 motion error (task frame's motion part)
//! a*      = P (a_d + Kd e' + Kp e + Ki int(e)) - Jdot qd
//! F_m     = Lambda a*                                 Lambda = (J M^-1 J^T)^-1
//! F       = F_m - s (s . F_m) + s f_f + f_friction    the normal row replaced by the force law
//! tau     = J^T F + (I - J^T Lambda J M^-1) M (Kp0 (q_d - q) + Kd0 (qd_d - qd)) + c + g
//! ```
//!
//! `f_f` is the force law along `n` ([`ForcePi`]: the thesis's PI + feedforward + velocity
//! damping, eq. 5.11, with its or designed gains); `f_friction = mu |f_n| t_d` the optional
//! friction feedforward along the reference's tangential direction. Before force control
//! (and without a force table) the law is [`TaskSpaceInverseDynamics`](super::task_space)
//! with the orientation target above. When force is controlled comes from the
//! [`SelectionPolicy`] (a time, or detected contact with an approach, a ramp and bumpless
//! transfer, as in [`HybridForcePosition`](super::hybrid::HybridForcePosition)): at the
//! switch the normal command equals the motion law's last one, and the difference fades
//! out over the force reference's ramp. The gravity along the normal is compensated with the
//! rest (`c + g` in joint space), so the force integral starts from the contact force alone.
//!
//! Every matrix is fixed-size; the step never allocates.

use nalgebra::{Vector3, Vector6};

use super::force::ForcePi;
use super::normal_reading::{linear, NormalSelector};
use super::selection::{Decision, ModeSelector, SelectionPolicy};
use super::task_frame::TaskFrame;
use super::task_space::{task_rows, OperationalSpace, TaskSpaceGains};
use super::tool_orientation::ToolOrientation;
use super::{Controller, ControllerInput};
use crate::model::{JointVector, RobotModel};
use crate::surface::sliding_friction;
use crate::target::{orientation, Task};

/// Hybrid force/motion control in a 6-D task frame (see the [module documentation](self)).
#[derive(Clone, Debug)]
pub struct TaskSpaceHybrid<const N: usize, R> {
    robot: R,
    gains: TaskSpaceGains,
    task: Task,
    force: ForcePi,
    tool: ToolOrientation,
    switch: NormalSelector,
    friction_feedforward: f64,
    anti_windup: bool,
    reference_stiffness: Option<f64>,
    last_f_ref: Option<f64>,
    integral: Vector6<f64>,
    last_normal_command: f64,
    transfer_offset: f64,
    last_tool: Option<super::ToolState>,
}

impl<const N: usize, R: RobotModel<N>> TaskSpaceHybrid<N, R> {
    /// The law for `robot`'s task ([`RobotModel::TASK`], which must control all three
    /// translations) with the motion `gains`, the force law `force` along the normal of
    /// `frame`, the orientation rule `tool`, switching by `selection`.
    ///
    /// Returns `None` if the robot's task lacks a translation.
    #[must_use]
    pub fn new(
        robot: R,
        gains: TaskSpaceGains,
        force: ForcePi,
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
            task,
            force,
            tool,
            switch: NormalSelector::new(frame, selection),
            friction_feedforward: 0.0,
            anti_windup: false,
            reference_stiffness: None,
            last_f_ref: None,
            integral: Vector6::zeros(),
            last_normal_command: 0.0,
            transfer_offset: 0.0,
            last_tool: None,
        })
    }

    /// Adds the friction feedforward with nominal Coulomb coefficient `mu` (0: none).
    #[must_use]
    pub fn with_friction_feedforward(mut self, mu: f64) -> Self {
        self.friction_feedforward = mu;
        self
    }

    /// Conditional integration of the force law's integral: a period whose integral
    /// increment would drive an actuator further past its limit is not integrated, and its
    /// increment is taken out of that period's command.
    #[must_use]
    pub fn with_anti_windup(mut self, on: bool) -> Self {
        self.anti_windup = on;
        self
    }

    /// Velocity damping against the force reference's own motion: with the contact's
    /// stiffness `k` (N/m, the controller's belief), the tool must move along `n` at
    /// `v_ref = (d f_ref / dt) / k` for the force to follow the reference `f_ref` (a ramp or a
    /// profile of the scenario's; the switching ramp from the measured force stays damped), and the damping
    /// acts on `v_n - v_ref` instead of `v_n` (`f_f = ... - Kvd (v_n - v_ref)`), so a moving
    /// force reference does not lag. `None` (the default): damping on `v_n`, the thesis's law.
    #[must_use]
    pub fn with_reference_motion(mut self, stiffness: Option<f64>) -> Self {
        self.reference_stiffness = stiffness.filter(|k| k.is_finite() && *k > 0.0);
        self
    }

    /// The force law.
    #[must_use]
    pub fn force_law(&self) -> &ForcePi {
        &self.force
    }

    /// The switching state machine.
    #[must_use]
    pub fn selector(&self) -> &ModeSelector {
        self.switch.selector()
    }

    /// The orientation rule.
    #[must_use]
    pub fn tool(&self) -> ToolOrientation {
        self.tool
    }
}

impl<const N: usize, R: RobotModel<N>> Controller<N> for TaskSpaceHybrid<N, R> {
    fn name(&self) -> &'static str {
        if self.force.kvd() == 0.0 {
            "task-space-hybrid-pi-ff"
        } else {
            "task-space-hybrid-pi-ff-vd"
        }
    }

    /// The integral of the task error per task row (m s, rad s), the force integral (N s),
    /// then the previous normal force reference (N) and whether there is one (1 or 0; it
    /// gives the reference's rate, `v_ref`).
    fn state_len(&self) -> usize {
        9
    }

    fn write_state(&self, out: &mut [f64]) {
        out[..6].copy_from_slice(self.integral.as_slice());
        out[6] = self.force.integral();
        out[7] = self.last_f_ref.unwrap_or(0.0);
        out[8] = if self.last_f_ref.is_some() { 1.0 } else { 0.0 };
    }

    fn read_state(&mut self, x: &[f64]) {
        self.integral = Vector6::from_column_slice(&x[..6]);
        self.force.set_integral(x[6]);
        self.last_f_ref = (x[8] > 0.5).then_some(x[7]);
    }

    fn reset(&mut self) {
        self.force.reset();
        self.switch.reset();
        self.integral = Vector6::zeros();
        self.last_normal_command = 0.0;
        self.transfer_offset = 0.0;
        self.last_f_ref = None;
        self.last_tool = None;
    }

    fn report(&self) -> super::StepReport<N> {
        self.switch.report(self.last_tool)
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
        self.last_tool = Some(super::ToolState {
            position: p,
            velocity: j_full.fixed_rows::<3>(0) * qd,
        });
        let reading = self.switch.read(input, &p, dt);
        let (n, decision) = (reading.n, reading.decision);
        let v_n = n.dot(&v);
        let c = input.cartesian;
        // The motion target: the reference, moved along -n during an approach.
        let (mut p_d, mut v_d) = (c.position, c.velocity);
        if let Decision::Position {
            offset_m,
            offset_rate_m_s,
        } = decision
        {
            p_d -= n * offset_m;
            v_d -= n * offset_rate_m_s;
        }
        let forcing = reading.forcing();
        let gap = if forcing { None } else { reading.reference_gap };
        let r_d = self.tool.target_at(&c.orientation, &n, gap, forcing);
        let mut e = self
            .task
            .pose_error(&p_d, &r_d, &p, &orientation::of_pose(&pose));
        let mut ed = c.twist() - twist;
        ed[0] = v_d.x - twist[0];
        ed[1] = v_d.y - twist[1];
        ed[2] = v_d.z - twist[2];
        if forcing {
            // Only the motion directions: the normal component of the linear errors is the
            // force law's.
            let e_n = n.dot(&Vector3::new(e[0], e[1], e[2]));
            let ed_n = n.dot(&Vector3::new(ed[0], ed[1], ed[2]));
            for k in 0..3 {
                e[k] -= n[k] * e_n;
                ed[k] -= n[k] * ed_n;
            }
        }
        self.integral += e.component_mul(&mask) * dt;
        let bias_acc = self.robot.jdot_qd(q, qd);
        let a_d = c.acceleration_twist();
        let a_star = Vector6::from_fn(|r, _| {
            mask[r]
                * (a_d[r]
                    + self.gains.kd[r] * ed[r]
                    + self.gains.kp[r] * e[r]
                    + self.gains.ki[r] * self.integral[r]
                    - bias_acc[r])
        });
        let Some(space) = OperationalSpace::new(&self.robot, q, qd, j, &mask, self.task.len())
        else {
            return self.robot.mass_matrix_and_bias(q, qd).1;
        };
        let mut f = space.task_force(&a_star);
        let f_m_n = n.dot(&linear(&f));
        let mut integral_before = None;
        match decision {
            Decision::Position { .. } => {
                self.force.reset();
                self.last_normal_command = f_m_n;
                self.last_f_ref = None;
            }
            Decision::Force {
                just_switched,
                ramp,
                ..
            } => {
                let target_n = reading.reference_n;
                integral_before = Some(self.force.integral());
                // The normal velocity the force reference itself asks for: from the motion of
                // the scenario's reference (a ramp, a profile), not from the switching ramp,
                // which starts at rest and must stay damped (zero at the switch and for a
                // constant reference).
                let v_ref = match (self.reference_stiffness, self.last_f_ref) {
                    (Some(k), Some(last)) if dt > 0.0 => (target_n - last) / dt / k,
                    _ => 0.0,
                };
                self.last_f_ref = Some(target_n);
                let mut f_f = self.force.step(reading.f_d, reading.f_n, v_n - v_ref, dt);
                if just_switched {
                    self.transfer_offset = self.last_normal_command - f_f;
                }
                if ramp < 1.0 {
                    f_f += self.transfer_offset * (1.0 - ramp);
                }
                let mut df = n * (f_f - f_m_n);
                if self.friction_feedforward > 0.0 {
                    let vt = c.velocity - n * n.dot(&c.velocity);
                    df += sliding_friction(self.friction_feedforward, (-reading.f_n).max(0.0), &vt);
                }
                for k in 0..3 {
                    f[k] += df[k];
                }
            }
        }
        let mut tau = space.j.transpose() * f + space.bias;
        if self.task.redundancy(N) > 0 {
            let target = input.target;
            let acc0 =
                (target.q - q) * self.gains.posture_kp + (target.qd - qd) * self.gains.posture_kd;
            tau += space.null_space_torque(&acc0);
        }
        match integral_before {
            Some(before) if self.anti_windup => self.force.without_windup(
                &j.fixed_rows::<3>(0).into_owned(),
                &n,
                tau,
                before,
                &R::EFFORT_LIMITS,
            ),
            _ => tau,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{forward_dynamics, Panda, Ur5};
    use crate::target::{CartesianTarget, JointTarget};
    use nalgebra::UnitQuaternion;

    fn input<'a, const N: usize>(
        t: f64,
        q: &'a JointVector<N>,
        qd: &'a JointVector<N>,
        target: &'a JointTarget<N>,
        cartesian: &'a CartesianTarget,
        w: &'a Vector6<f64>,
        w_ref: &'a Vector6<f64>,
    ) -> ControllerInput<'a, N> {
        ControllerInput {
            t,
            q,
            qd,
            target,
            cartesian,
            wrench: w,
            wrench_ref: w_ref,
            wrench_age_s: 0.0,
        }
    }

    fn law<const N: usize, R: RobotModel<N>>(
        robot: R,
        tool: Vector3<f64>,
    ) -> TaskSpaceHybrid<N, R> {
        let g = TaskSpaceGains::critically_damped::<N, R>(&[30.0; 6], 1.0, 10.0, true);
        TaskSpaceHybrid::new(
            robot,
            g,
            ForcePi::new(2.0, 20.0, 50.0),
            TaskFrame::Fixed(Vector3::z()),
            ToolOrientation::AlongNormal(tool),
            SelectionPolicy::Time { switch_s: 1.0 },
        )
        .unwrap()
    }

    /// A UR5 configuration, its tool position and orientation, and the tool-frame axis that
    /// points along -z there (held along the inward normal of a table).
    fn ur5_pose() -> (
        JointVector<6>,
        Vector3<f64>,
        UnitQuaternion<f64>,
        Vector3<f64>,
    ) {
        let q = JointVector::<6>::from([0.0, -1.2, 1.6, -1.97, -core::f64::consts::FRAC_PI_2, 0.0]);
        let pose = Ur5.end_effector_pose(&q);
        let r = orientation::of_pose(&pose);
        (
            q,
            pose.fixed_view::<3, 1>(0, 3).into_owned(),
            r,
            r.inverse() * -Vector3::z(),
        )
    }

    #[test]
    fn the_force_row_commands_the_force_and_the_other_rows_their_motion() {
        // UR5 at rest on its reference, after the switch: the tool exerts the force law's
        // command along n (no motion error, so no other wrench), and at rest the commanded
        // torque is J^T F + g.
        let robot = Ur5;
        let (q, p, r, axis) = ur5_pose();
        let mut law = law(robot, axis);
        let c = CartesianTarget::at_rest(p, r);
        let qd = JointVector::<6>::zeros();
        let z = JointTarget::at_rest(q);
        let w = Vector6::new(0.0, 0.0, -30.0, 0.0, 0.0, 0.0);
        let tau = law.step(&input(2.0, &q, &qd, &z, &c, &w, &w), 1e-3);
        // Measured = desired: f_f = f_d = -30 N (plus the integral of one period's zero error).
        let expected = robot.jacobian(&q).transpose() * w + robot.gravity(&q);
        assert!(
            (tau - expected).norm() < 1e-9 * expected.norm(),
            "{tau} vs {expected}"
        );
    }

    #[test]
    fn before_the_switch_a_redundant_arm_moves_only_as_the_motion_law_asks() {
        // Panda at rest on its reference and aligned to the normal: the task acceleration is
        // zero, whatever the posture term does.
        let robot = Panda;
        let q = JointVector::<7>::from([0.0, -0.4, 0.0, -2.2, 0.0, 1.8, 0.785]);
        let pose = robot.end_effector_pose(&q);
        let p = pose.fixed_view::<3, 1>(0, 3).into_owned();
        let r = orientation::of_pose(&pose);
        let axis = r.inverse() * -Vector3::z();
        let mut law = law(robot, axis);
        let c = CartesianTarget::at_rest(p, r);
        let qd = JointVector::<7>::zeros();
        let posture =
            JointTarget::at_rest(q + JointVector::<7>::from([0.2, 0.0, -0.2, 0.0, 0.1, 0.0, 0.0]));
        let w = Vector6::zeros();
        let tau = law.step(&input(0.0, &q, &qd, &posture, &c, &w, &w), 1e-3);
        let qdd = forward_dynamics(&robot, &q, &qd, &tau, &JointVector::zeros()).unwrap();
        assert!(qdd.norm() > 1e-3);
        assert!((robot.jacobian(&q) * qdd).norm() < 1e-9);
    }

    #[test]
    fn the_damping_acts_against_the_force_references_own_motion() {
        // UR5 on its reference after the switch, the force reference ramping by 1 N per
        // period on a 10 kN/m contact: the reference asks for v_n = (df_d/dt) / k = -0.1 m/s,
        // and the tool moves at exactly that. With the reference's motion the damping sees no
        // error; without it, it brakes with Kvd * 0.1 m/s = 5 N along n.
        let robot = Ur5;
        let (q, p, r, axis) = ur5_pose();
        let j = robot.jacobian(&q);
        // Joint velocities moving the tool at -0.1 m/s along z, nothing else.
        let twist = nalgebra::Vector6::new(0.0, 0.0, -0.1, 0.0, 0.0, 0.0);
        let qd = j.lu().solve(&twist).unwrap();
        let z = JointTarget::at_rest(q);
        let mut c = CartesianTarget::at_rest(p, r);
        c.velocity = Vector3::new(0.0, 0.0, -0.1);
        let torques = |reference_motion: Option<f64>| {
            let mut law = law(robot, axis).with_reference_motion(reference_motion);
            let mut tau = JointVector::<6>::zeros();
            for (k, f) in [-20.0, -21.0].iter().enumerate() {
                let w = Vector6::new(0.0, 0.0, *f, 0.0, 0.0, 0.0);
                tau = law.step(&input(2.0 + 1e-3 * k as f64, &q, &qd, &z, &c, &w, &w), 1e-3);
            }
            tau
        };
        let (with, without) = (torques(Some(1e4)), torques(None));
        // The difference is J^T n (Kvd v_ref) = J^T (0, 0, 50 * -0.1): 5 N pushing down more.
        let expected = j.transpose() * Vector6::new(0.0, 0.0, -5.0, 0.0, 0.0, 0.0);
        assert!(
            ((with - without) - expected).norm() < 1e-9 * expected.norm(),
            "{}",
            with - without
        );
    }
}
