//! A force/torque sensor mounted before a tool: where the sensor sits, what the tool weighs,
//! and what the sensor therefore reports of a contact at the tool point.
//!
//! The sensor frame's axes are the tool frame's; its origin `o` (tool frame, m) is before the
//! tool point. With the tool frame at `p` with rotation `R`, the sensor origin at
//! `p_s = p + R o`, the tool's mass `m` with its centre of mass at `c` (sensor frame), gravity
//! `g` (base frame, m/s^2) and the contact wrench `[f_c; t_c]` of the tool on the environment at
//! the tool point (base frame), the sensor reports, in its own frame and about its origin, with
//! the same sign (what the tool side pushes on the world):
//!
//! ```text
//! f_s = R^T (f_c - m g)
//! t_s = R^T (t_c + (p - p_s) x f_c - (R c) x m g)
//! ```
//!
//! In free space a hanging tool reads `-R^T m g`: as if it pulled away from a surface below
//! it, and more so along the tool axis the more that axis points down. The tool's own
//! inertial forces (`m a`, a few hundredths of a newton at the shipped tasks' accelerations)
//! are left out, here and in the compensation that undoes this
//! ([`SensorMount::contact_wrench`]).

use nalgebra::{Rotation3, Vector3};

use super::{JointVector, RobotModel, Wrench};

/// Where the sensor sits before the tool, and the tool behind it (see the
/// [module documentation](self)).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SensorMount {
    /// The sensor frame's origin in the tool frame, m (its axes are the tool frame's).
    pub origin_m: Vector3<f64>,
    /// The tool's mass between the sensor and the tool point, kg (>= 0).
    pub tool_mass_kg: f64,
    /// The tool's centre of mass in the sensor frame, m.
    pub tool_com_m: Vector3<f64>,
}

/// The tool frame's rotation at `q`.
#[must_use]
pub fn tool_rotation<const N: usize, M: RobotModel<N>>(
    model: &M,
    q: &JointVector<N>,
) -> Rotation3<f64> {
    let pose = model.end_effector_pose(q);
    Rotation3::from_matrix_unchecked(pose.fixed_view::<3, 3>(0, 0).into_owned())
}

/// `w`'s force and moment rotated by `r` (the moment about the same point).
#[must_use]
pub fn rotate_wrench(r: &Rotation3<f64>, w: &Wrench) -> Wrench {
    let (f, t) = parts(w);
    wrench(&(r * f), &(r * t))
}

/// `[f; t]` of a wrench.
fn parts(w: &Wrench) -> (Vector3<f64>, Vector3<f64>) {
    (
        Vector3::new(w[0], w[1], w[2]),
        Vector3::new(w[3], w[4], w[5]),
    )
}

/// The wrench `[f; t]`.
fn wrench(f: &Vector3<f64>, t: &Vector3<f64>) -> Wrench {
    Wrench::new(f.x, f.y, f.z, t.x, t.y, t.z)
}

impl SensorMount {
    /// A sensor at the tool point with no tool behind it: it reports the contact wrench in
    /// the tool frame.
    #[must_use]
    pub fn at_tool_point() -> Self {
        Self {
            origin_m: Vector3::zeros(),
            tool_mass_kg: 0.0,
            tool_com_m: Vector3::zeros(),
        }
    }

    /// What the sensor reports of the tool's weight alone (sensor frame, about its origin),
    /// the tool frame rotated by `r`, gravity `g` (base frame, m/s^2):
    /// `[-R^T m g; -c x R^T m g]`.
    #[must_use]
    pub fn weight_reading(&self, r: &Rotation3<f64>, g: &Vector3<f64>) -> Wrench {
        let w = r.inverse() * (g * self.tool_mass_kg);
        wrench(&-w, &-self.tool_com_m.cross(&w))
    }

    /// What the sensor reports (sensor frame, about its origin) of the contact wrench
    /// `contact` (base frame, at the tool point), the tool frame rotated by `r`, gravity `g`.
    ///
    /// ```
    /// use armdyn::model::SensorMount;
    /// use armdyn::model::Wrench;
    /// use nalgebra::{Rotation3, Vector3};
    /// let mount = SensorMount {
    ///     origin_m: Vector3::new(0.0, 0.0, -0.1),
    ///     tool_mass_kg: 1.2,
    ///     tool_com_m: Vector3::new(0.0, 0.0, 0.05),
    /// };
    /// // The tool z axis straight down, pressing 15 N on a table: the sensor's z axis reads
    /// // the contact's 15 N pushing back along +z_tool and the tool's 11.8 N of weight, pulling.
    /// let r = Rotation3::from_axis_angle(&Vector3::x_axis(), std::f64::consts::PI);
    /// let g = Vector3::new(0.0, 0.0, -9.81);
    /// let s = mount.reading(&Wrench::new(0.0, 0.0, -15.0, 0.0, 0.0, 0.0), &r, &g);
    /// assert!((s[2] - (15.0 - 1.2 * 9.81)).abs() < 1e-12);
    /// let back = mount.contact_wrench(&s, &Wrench::zeros(), &r, &g);
    /// assert!((back - Wrench::new(0.0, 0.0, -15.0, 0.0, 0.0, 0.0)).norm() < 1e-12);
    /// ```
    #[must_use]
    pub fn reading(&self, contact: &Wrench, r: &Rotation3<f64>, g: &Vector3<f64>) -> Wrench {
        let (f_c, t_c) = parts(contact);
        let lever = -(r * self.origin_m);
        let f = r.inverse() * f_c;
        let t = r.inverse() * (t_c + lever.cross(&f_c));
        wrench(&f, &t) + self.weight_reading(r, g)
    }

    /// The contact wrench at the tool point (base frame) from a sensor reading `reading`
    /// (sensor frame, about its origin), taking out the sensor's `bias` (sensor frame) and the
    /// tool's weight: the inverse of [`reading`](Self::reading).
    #[must_use]
    pub fn contact_wrench(
        &self,
        reading: &Wrench,
        bias: &Wrench,
        r: &Rotation3<f64>,
        g: &Vector3<f64>,
    ) -> Wrench {
        let (f_s, t_s) = parts(&(reading - bias - self.weight_reading(r, g)));
        let f_c = r * f_s;
        let lever = -(r * self.origin_m);
        let t_c = r * t_s - lever.cross(&f_c);
        wrench(&f_c, &t_c)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_reading_is_the_static_balance_of_the_tool_and_inverts() {
        let mount = SensorMount {
            origin_m: Vector3::new(0.01, -0.02, -0.12),
            tool_mass_kg: 1.2,
            tool_com_m: Vector3::new(0.005, 0.0, 0.06),
        };
        let r = Rotation3::from_euler_angles(2.9, 0.3, -0.7);
        let p = Vector3::new(0.4, 0.1, 0.3);
        let g = Vector3::new(0.0, 0.0, -9.81);
        let contact = Wrench::new(1.0, -2.0, -15.0, 0.05, 0.0, -0.02);
        let s = mount.reading(&contact, &r, &g);
        // The sensor's wrench on the tool, `s` in base axes about p_s, balances the contact's
        // reaction and the weight: forces and moments about p_s sum to zero.
        let p_s = p + r * mount.origin_m;
        let p_com = p_s + r * mount.tool_com_m;
        let f_on_tool = r * Vector3::new(s[0], s[1], s[2]);
        let t_on_tool = r * Vector3::new(s[3], s[4], s[5]);
        let (f_c, t_c) = parts(&contact);
        let m_g = g * mount.tool_mass_kg;
        assert!((f_on_tool - f_c + m_g).norm() < 1e-12);
        let moments = t_on_tool - t_c + (p - p_s).cross(&-f_c) + (p_com - p_s).cross(&m_g);
        assert!(moments.norm() < 1e-12, "{moments}");
        let back = mount.contact_wrench(&s, &Wrench::zeros(), &r, &g);
        assert!((back - contact).norm() < 1e-12);
    }
}
