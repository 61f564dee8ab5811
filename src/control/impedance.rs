//! Cartesian impedance control (Hogan's stiffness and damping, model-based), the first
//! baseline force-control users reach for: the tool behaves as a spring and damper to a
//! virtual point, and a force is obtained by putting that point inside the surface.
//!
//! ```text
//! tau = J_r^T F + g(q) + c(q, qd)
//! F   = K (x_d - x) + D (xdot_d - xdot)        in the task frame [n, t1, t2, yaw]
//! ```
//!
//! No force is fed back: along the normal, once force is controlled, the virtual point is
//! put `|f_d| (1 / K_n + 1 / k_c)` inside the expected surface (`k_c` the contact
//! stiffness the controller assumes), which gives `f_d` at rest when the surface is where
//! it is expected and as stiff as assumed. A surface `delta` m off its expected place
//! changes the force by `delta K_n k / (K_n + k)`: the series stiffness of the impedance
//! and the contact times the height error, and it stays.

use nalgebra::Vector3;

use super::normal_law::{NormalCommand, NormalLaw, NormalSample};
use super::normal_reading::NormalSelector;
use super::selection::{Decision, SelectionPolicy};
use super::task_frame::TaskFrame;
use super::task_rows::TaskRows;
use super::{Controller, ControllerInput};
use crate::model::{JointVector, RobotModel, Wrench};
use crate::target::wrap_angle;

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
    /// About base z, N m/rad.
    pub yaw_stiffness: f64,
    /// About base z, N m s/rad.
    pub yaw_damping: f64,
    /// About the tangent axes (the tool's tilt off the normal), N m/rad: used by the law in
    /// the full task frame ([`TaskSpaceImpedance`](super::task_space_impedance)), where the
    /// yaw's are about the normal.
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

    fn reset(&mut self) {}

    fn step(&mut self, s: &NormalSample, _dt: f64) -> NormalCommand {
        let g = &self.gains;
        NormalCommand::Force(
            g.normal_stiffness * (g.virtual_gap(s.f_d) - s.height_m) - g.normal_damping * s.v,
        )
    }
}

/// Cartesian impedance control with a task frame from the contact normal and the same
/// selection (time or contact, with a force ramp) as the hybrid law.
///
/// `rows`: as for [`HybridForcePosition`](super::hybrid::HybridForcePosition), the task
/// rows of the Jacobian kept (the linear ones and, for the SCARA, `wz` = row 5, which
/// gets the yaw impedance; any other row gets none).
#[derive(Clone, Debug)]
pub struct CartesianImpedance<const N: usize, R> {
    robot: R,
    gains: ImpedanceGains,
    normal: NormalImpedance,
    switch: NormalSelector,
    rows: TaskRows<N>,
}

impl<const N: usize, R: RobotModel<N>> CartesianImpedance<N, R> {
    /// `None` if `rows` repeats a row, names one outside 0..6 or lacks a linear row.
    #[must_use]
    pub fn new(
        robot: R,
        gains: ImpedanceGains,
        frame: TaskFrame,
        selection: SelectionPolicy,
        rows: [usize; N],
    ) -> Option<Self> {
        Some(Self {
            robot,
            gains,
            normal: NormalImpedance::new(gains),
            switch: NormalSelector::new(frame, selection),
            rows: TaskRows::new(rows)?,
        })
    }

    /// The gains.
    #[must_use]
    pub fn gains(&self) -> &ImpedanceGains {
        &self.gains
    }
}

impl<const N: usize, R: RobotModel<N>> Controller<N> for CartesianImpedance<N, R> {
    fn name(&self) -> &'static str {
        "impedance"
    }

    fn reset(&mut self) {
        self.switch.reset();
    }

    fn report(&self) -> super::StepReport<N> {
        self.switch.report(None)
    }

    fn step(&mut self, input: &ControllerInput<'_, N>, dt: f64) -> JointVector<N> {
        let j = self.robot.jacobian(input.q);
        let jr = self.rows.reduce(&j);
        let twist: Wrench = j * input.qd;
        let v = Vector3::new(twist[0], twist[1], twist[2]);
        let pose = self.robot.end_effector_pose(input.q);
        let p = Vector3::new(pose[(0, 3)], pose[(1, 3)], pose[(2, 3)]);
        let yaw = libm::atan2(pose[(1, 0)], pose[(0, 0)]);
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
        let mut f = self.rows.lift(&f_lin);
        if let Some(r) = self.rows.index_of(5) {
            f[r] = g.yaw_stiffness * wrap_angle(c.yaw() - yaw)
                + g.yaw_damping * (c.angular_velocity.z - twist[5]);
        }
        jr.transpose() * f + self.robot.gravity(input.q) + self.robot.coriolis(input.q, input.qd)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_virtual_point_gives_the_force_in_series() {
        let g = ImpedanceGains {
            normal_stiffness: 2000.0,
            normal_damping: 0.0,
            tangential_stiffness: 0.0,
            tangential_damping: 0.0,
            yaw_stiffness: 0.0,
            yaw_damping: 0.0,
            tilt_stiffness: 0.0,
            tilt_damping: 0.0,
            contact_stiffness: 1e4,
        };
        // At rest: K_n (x_d - x) = k x (x < 0 inside) and f = k x.
        let x_d = g.virtual_gap(-200.0);
        let x = g.normal_stiffness * x_d / (g.normal_stiffness + 1e4);
        assert!((1e4 * x + 200.0).abs() < 1e-9);
        // 5 mm higher surface: 5 mm more penetration through the series spring.
        assert!((g.series_stiffness(1e4) * 0.005 - 8.333_333_333).abs() < 1e-6);
    }
}
