//! Hybrid force/position control (thesis Section 5.2, eq. 5.4):
//!
//! ```text
//! tau = J^T ( S J^-T tau_p  +  (I - S) f_f )
//! ```
//!
//! `tau_p` is the joint-space position loop's torque (the thesis uses PID with feedback
//! linearization), mapped to Cartesian space by `J^-T`; `f_f` is the force loop's command
//! ([`ForcePi`]); `S` selects position control in the tangent directions of a task frame
//! and force control along its normal ([`TaskFrame`]), from a time or from detected contact
//! on ([`SelectionPolicy`]).
//!
//! `J` is the 6 x N geometric Jacobian reduced to the N task rows the robot can act in
//! (rows `vx vy vz wz` for the SCARA, whose rows `wx wy` are zero), so that it is square.
//! Singularities are handled explicitly, see [`reduced_transpose_solve`].

use super::force::ForcePi;
pub use super::jacobian_factor::{
    reduced_transpose_solve, JacobianFactor, JacobianSolve, MAX_DAMPING, SINGULARITY_THRESHOLD,
};
use super::normal_reading::NormalSelector;
use super::selection::{Decision, ModeSelector, SelectionPolicy};
use super::task_frame::TaskFrame;
use super::task_rows::TaskRows;
use super::{Controller, ControllerInput};
use crate::model::{JointVector, RobotModel};
use crate::surface::sliding_friction;
use nalgebra::Vector3;

/// Hybrid force/position controller for an N-joint robot acting in N task directions, three
/// of them the linear velocity (rows 0, 1, 2 of the Jacobian).
///
/// Eq. 5.4 in a task frame whose first axis is the contact normal `n` ([`TaskFrame`]):
///
/// ```text
/// f_cmd = (I - n n^T) J^-T tau_p  +  n (f_f + g_n)  +  f_friction     (linear rows)
/// f_cmd = J^-T tau_p                                            (other task rows, e.g. wz)
/// tau   = J^T f_cmd
/// ```
///
/// with `f_f` the force law along `n` ([`ForcePi`]), `g_n = n . J^-T g(q)` the model's
/// gravity along the normal (optional, off in the thesis's law) and `f_friction = mu_nom |f_n| t_d`
/// the optional friction feedforward along the reference's tangential direction `t_d`. While
/// force is controlled the position loop's target is moved along `n` onto the tool (to first
/// order, through `J^-1`), so the joint-space position loop only sees tangential errors. When
/// force is controlled comes from the [`SelectionPolicy`]: at a fixed time (the thesis's
/// `S = diag(1, 1, 0, 1, 1, 1)` from 2 s is `TaskFrame::Fixed(z)` with
/// `SelectionPolicy::Time { switch_s: 2 }`, and equals it up to rounding), or on
/// detected contact with an approach, a ramp and bumpless transfer ([`ModeSelector`]): at the
/// switch the normal command equals the position loop's last one, and the difference to the
/// force law's fades out linearly over the force reference's ramp.
///
/// One solve per step serves all of it: `a = J^-1 n` (the joint motion per metre along `n`)
/// moves the target, gives the position loop's force along the normal as
/// `n . J^-T tau_p = a . tau_p` and `g_n = a . g`, and
/// `tau = J^T J^-T tau_p + J^T (n (f_f + g_n - a . tau_p) + f_friction)`, where
/// `J^T J^-T tau_p = tau_p` unless the solve is damped ([`JacobianFactor::wrench_torque`]).
#[derive(Clone, Debug)]
pub struct HybridForcePosition<const N: usize, R, P> {
    robot: R,
    position: P,
    force: ForcePi,
    switch: NormalSelector,
    rows: TaskRows<N>,
    friction_feedforward: f64,
    normal_gravity: bool,
    anti_windup: bool,
    last_solve: JacobianSolve,
    last_normal_command: f64,
    transfer_offset: f64,
    tool: Option<super::ToolState>,
}

impl<const N: usize, R: RobotModel<N>, P: Controller<N>> HybridForcePosition<N, R, P> {
    /// `rows`: the task rows of the 6 x N Jacobian kept (each in 0..6, distinct, including
    /// 0, 1 and 2), e.g. `[0, 1, 2, 5]` for a SCARA ([`TaskRows`]).
    ///
    /// Returns `None` if `rows` repeats a row, names one outside 0..6 or lacks a linear row.
    #[must_use]
    pub fn new(
        robot: R,
        position: P,
        force: ForcePi,
        frame: TaskFrame,
        selection: SelectionPolicy,
        rows: [usize; N],
    ) -> Option<Self> {
        Some(Self {
            robot,
            position,
            force,
            switch: NormalSelector::new(frame, selection),
            rows: TaskRows::new(rows)?,
            friction_feedforward: 0.0,
            normal_gravity: false,
            anti_windup: false,
            last_solve: JacobianSolve::NotNeeded,
            last_normal_command: 0.0,
            transfer_offset: 0.0,
            tool: None,
        })
    }

    /// Adds the friction feedforward with nominal Coulomb coefficient `mu` (0: none).
    #[must_use]
    pub fn with_friction_feedforward(mut self, mu: f64) -> Self {
        self.friction_feedforward = mu;
        self
    }

    /// Keeps the model's gravity along the normal in the force command (`g_n` below): the
    /// thesis's law drops it with the position loop's normal row, and the force integral has
    /// to take it up slowly (the 48 N of d3's weight decaying with `(1 + Kfp) / Kfi = 4.2 s`).
    #[must_use]
    pub fn with_normal_gravity_compensation(mut self, on: bool) -> Self {
        self.normal_gravity = on;
        self
    }

    /// Conditional integration of the force law's integral (anti-windup): a period whose
    /// integral increment would drive an actuator further past its limit
    /// (`RobotModel::EFFORT_LIMITS`) is not integrated, and its increment is taken out of
    /// that period's command. Off in the thesis's law.
    #[must_use]
    pub fn with_anti_windup(mut self, on: bool) -> Self {
        self.anti_windup = on;
        self
    }

    /// How `J^-T` was obtained at the last step.
    #[must_use]
    pub fn last_solve(&self) -> JacobianSolve {
        self.last_solve
    }

    /// The force law.
    #[must_use]
    pub fn force_law(&self) -> &ForcePi {
        &self.force
    }

    /// The position controller.
    #[must_use]
    pub fn position_controller(&self) -> &P {
        &self.position
    }

    /// The switching state machine.
    #[must_use]
    pub fn selector(&self) -> &ModeSelector {
        self.switch.selector()
    }
}

impl<const N: usize, R: RobotModel<N>, P: Controller<N>> Controller<N>
    for HybridForcePosition<N, R, P>
{
    fn name(&self) -> &'static str {
        if self.force.kvd() == 0.0 {
            "hybrid-pi-ff"
        } else {
            "hybrid-pi-ff-vd"
        }
    }

    /// The position law's state, then the force integral (N s). The bumpless-transfer
    /// offset is set once at the switch and is a constant afterwards, not a state.
    fn state_len(&self) -> usize {
        self.position.state_len() + 1
    }

    fn write_state(&self, out: &mut [f64]) {
        let k = self.position.state_len();
        self.position.write_state(&mut out[..k]);
        out[k] = self.force.integral();
    }

    fn read_state(&mut self, x: &[f64]) {
        let k = self.position.state_len();
        self.position.read_state(&x[..k]);
        self.force.set_integral(x[k]);
    }

    fn reset(&mut self) {
        self.position.reset();
        self.force.reset();
        self.switch.reset();
        self.last_solve = JacobianSolve::NotNeeded;
        self.last_normal_command = 0.0;
        self.transfer_offset = 0.0;
        self.tool = None;
    }

    fn report(&self) -> super::StepReport<N> {
        self.switch.report(self.tool)
    }

    fn step(&mut self, input: &ControllerInput<'_, N>, dt: f64) -> JointVector<N> {
        // J and the tool position p (m) in one call: the generated robots share sin/cos.
        let (j, p) = self.robot.jacobian_and_position(input.q);
        // The tool's linear velocity (rows vx vy vz of J qd), m/s.
        let v: Vector3<f64> = j.fixed_rows::<3>(0) * input.qd;
        self.tool = Some(super::ToolState {
            position: p,
            velocity: v,
        });
        let reading = self.switch.read(input, &p, dt);
        let n = reading.n;
        let v_n = n.dot(&v);
        if !reading.forcing() {
            self.force.reset();
            self.last_solve = JacobianSolve::NotNeeded;
            if !self.switch.contact_switching() {
                return self.position.step(input, dt);
            }
        }
        let factor = self.rows.factor(&j);
        // The joint motion per metre along the normal (one solve serves q and qd).
        let along_n = factor.solve(&self.rows.lift(&n));
        match reading.decision {
            Decision::Position {
                offset_m,
                offset_rate_m_s,
            } => {
                // The approach: the target moved `offset_m` into the surface along -n.
                let mut target = *input.target;
                target.q -= along_n * offset_m;
                target.qd -= along_n * offset_rate_m_s;
                let tau_p = self.position.step(
                    &ControllerInput {
                        target: &target,
                        ..*input
                    },
                    dt,
                );
                // n . J^-T tau_p as (J^-1 n) . tau_p (damped alike: P^T and P).
                self.last_normal_command = along_n.dot(&tau_p);
                tau_p
            }
            Decision::Force {
                just_switched,
                ramp,
                ..
            } => {
                // The position loop sees only tangential errors: its target is moved along
                // n onto the tool.
                let c = input.cartesian;
                let mut target = *input.target;
                target.q += along_n * n.dot(&(p - c.position));
                target.qd += along_n * n.dot(&(v - c.velocity));
                let tau_p = self.position.step(
                    &ControllerInput {
                        target: &target,
                        ..*input
                    },
                    dt,
                );
                self.last_solve = factor.how();
                // The position loop's force along n, n . J^-T tau_p, as (J^-1 n) . tau_p.
                let f_p_n = along_n.dot(&tau_p);
                let g_n = if self.normal_gravity {
                    // n . J^-T g, likewise.
                    along_n.dot(&self.robot.gravity(input.q))
                } else {
                    0.0
                };
                let integral_before = self.force.integral();
                let mut f_f = self.force.step(reading.f_d, reading.f_n, v_n, dt);
                if just_switched {
                    // Bumpless: the normal command starts where the position loop left off;
                    // the difference fades out over the force ramp.
                    self.transfer_offset = self.last_normal_command - g_n - f_f;
                }
                if ramp < 1.0 {
                    f_f += self.transfer_offset * (1.0 - ramp);
                }
                // f_cmd = f_p + df: the position loop's wrench with its normal component
                // replaced by the force command (and the friction feedforward added).
                let mut df = if self.normal_gravity {
                    n * (f_f + g_n - f_p_n)
                } else {
                    n * (f_f - f_p_n)
                };
                if self.friction_feedforward > 0.0 {
                    let vt = c.velocity - n * n.dot(&c.velocity);
                    df += sliding_friction(self.friction_feedforward, (-reading.f_n).max(0.0), &vt);
                }
                // tau = J^T f_cmd = J^T f_p + J^T df, with J^T f_p = tau_p unless damped.
                // The linear rows of J_r are rows 0, 1, 2 of J.
                let mut tau = factor.wrench_torque(&tau_p);
                for k in 0..3 {
                    tau += j.row(k).transpose() * df[k];
                }
                if self.anti_windup {
                    return self.force.without_windup(
                        &j.fixed_rows::<3>(0).into_owned(),
                        &n,
                        tau,
                        integral_before,
                        &R::EFFORT_LIMITS,
                    );
                }
                tau
            }
        }
    }
}
