//! The force loop of a scenario at its contact pose: where the reference first meets the
//! force surface (as the controller believes it to be), the robot's apparent mass along
//! the normal there, and the gains built from it: designed PI gains (`gains = "design"`)
//! and the impedance's damping. For any robot: the contact pose's joints come from the
//! reference's own planner ([`PlannedReference::joints_at`]).

use nalgebra::Vector3;

use super::super::error::ScenarioError;
use super::super::planned::PlannedReference;
use super::super::spec::{ForceSpec, Scenario};
use crate::control::design::{
    apparent_mass, design, push_limit, DesignError, ForceGains, ForceLoop, PushLimit,
};
use crate::control::impedance::ImpedanceGains;
use crate::control::task_frame::TaskFrame;
use crate::model::{JointVector, RobotModel};
use crate::target::Rotations;
use crate::trajectory::sample;

/// The contact pose of a scenario and the loop model's numbers there.
#[derive(Clone, Debug, PartialEq)]
pub struct ContactModel {
    /// When the reference first reaches the expected surface (or comes closest), s.
    pub t_s: f64,
    /// The joints there (rad or m), from the reference's planner.
    pub q: Vec<f64>,
    /// The expected surface's outward normal there.
    pub normal: Vector3<f64>,
    /// The robot's apparent mass along it, kg.
    pub mass_kg: f64,
    /// The force surface's stiffness, N/m.
    pub stiffness: f64,
    /// Its damping, N s/m.
    pub damping: f64,
    /// What the actuators allow pushing into the surface (along `-normal`) there.
    push: Result<PushLimit, DesignError>,
}

/// The contact pose along a planned reference, with the joints as a vector of the robot.
pub(super) struct ContactPose<const N: usize> {
    pub(super) t_s: f64,
    pub(super) q: JointVector<N>,
    pub(super) normal: Vector3<f64>,
}

/// Where `planned` first reaches the force surface of `f` (as the controller believes it).
pub(super) fn contact_pose<const N: usize>(
    scenario: &Scenario,
    f: &ForceSpec,
    planned: &dyn PlannedReference<N>,
    duration: f64,
) -> Result<ContactPose<N>, ScenarioError> {
    let surface = &scenario.surfaces[f.surface];
    let frame = TaskFrame::Surface(surface.geometry.shifted(f.expected_shift_m));
    let key = format!("surfaces[{}]", f.surface);
    let mut best: Option<(f64, f64, Vector3<f64>)> = None;
    for s in sample(planned.trajectory(), 0.005)
        .into_iter()
        .filter(|s| s.t <= duration)
    {
        if let Some(gap) = frame.signed_distance(&s.position) {
            if best.is_none_or(|(g, ..)| gap < g.max(1e-6)) {
                best = Some((gap, s.t, s.position));
            }
            if gap <= 1e-6 {
                break;
            }
        }
    }
    let (gap, t_s, position) = best.ok_or_else(|| {
        scenario.error(
            &key,
            "the reference never passes over this surface's extent",
        )
    })?;
    let normal = frame.normal_at(&position);
    let on_surface = position - normal * gap;
    let q = planned
        .joints_at(t_s, &on_surface)
        .map_err(|e| scenario.error(&key, format!("the contact pose is out of reach: {e}")))?;
    Ok(ContactPose { t_s, q, normal })
}

/// The contact model of a prepared reference (see [`contact_model`]).
pub(super) fn contact_model_of<const N: usize, R: RobotModel<N>>(
    scenario: &Scenario,
    robot: &R,
    planned: &dyn PlannedReference<N>,
    duration: f64,
) -> Result<ContactModel, ScenarioError> {
    let f = scenario
        .force
        .as_ref()
        .ok_or_else(|| scenario.error("force", "a force loop needs a [force] table"))?;
    let pose = contact_pose(scenario, f, planned, duration)?;
    let key = format!("surfaces[{}]", f.surface);
    let surface = &scenario.surfaces[f.surface];
    let mass_kg = apparent_mass(robot, &pose.q, &pose.normal)
        .map_err(|e| scenario.error(&key, e.to_string()))?;
    Ok(ContactModel {
        t_s: pose.t_s,
        q: pose.q.iter().copied().collect(),
        normal: pose.normal,
        mass_kg,
        stiffness: surface.stiffness,
        damping: surface.damping,
        push: push_limit(robot, &pose.q, &(-pose.normal)),
    })
}

/// The contact pose of a force-controlled scenario.
///
/// # Errors
///
/// [`ScenarioError`] if the scenario has no `[force]` table, its reference leaves the
/// workspace, never passes over the surface, or the pose is singular.
pub fn contact_model(scenario: &Scenario) -> Result<ContactModel, ScenarioError> {
    crate::with_robot_named!(scenario.robot.as_str(), |robot: R, N, _module| {
        let reference = super::reference::reference(scenario, &robot)?;
        contact_model_of(
            scenario,
            &robot,
            reference.planned.as_ref(),
            reference.duration,
        )
    })
    .unwrap_or_else(|| Err(scenario.error("robot", "unknown robot")))
}

impl ContactModel {
    /// What the actuators allow pushing into the surface (along `-normal`) at this pose.
    ///
    /// # Errors
    ///
    /// [`DesignError::Model`] at a singular pose.
    pub fn push_limit(&self) -> Result<PushLimit, DesignError> {
        self.push.clone()
    }

    /// The loop model for `f`'s design settings (its stiffness, else the surface's).
    ///
    /// # Errors
    ///
    /// [`ScenarioError`] on `force.design` if the model is out of range.
    pub fn force_loop(
        &self,
        scenario: &Scenario,
        f: &ForceSpec,
    ) -> Result<ForceLoop, ScenarioError> {
        let d = &f.laws.design;
        ForceLoop::new(
            self.mass_kg,
            d.stiffness.unwrap_or(self.stiffness),
            self.damping,
            scenario.control_dt_s,
            d.delay,
        )
        .map_err(|e| scenario.error("force.design", e.to_string()))
    }
}

/// The gains `[force.design]` asks for, at the contact pose `m`, and a note saying how they
/// were obtained.
pub(super) fn designed_gains(
    scenario: &Scenario,
    f: &ForceSpec,
    m: &ContactModel,
) -> Result<(ForceGains, String), ScenarioError> {
    let l = m.force_loop(scenario, f)?;
    let spec = f.laws.design.spec;
    let (g, poles) =
        design(&l, &spec).map_err(|e| scenario.error("force.design", e.to_string()))?;
    if !poles.stable() {
        return Err(scenario.error("force.design", "the designed loop is not stable"));
    }
    let note = format!(
        "designed at the contact pose (t = {:.3} s, apparent mass {:.3} kg, k = {} N/m, {} s{}): bandwidth {} Hz, damping {}, integral pole {:.3} Hz",
        m.t_s,
        m.mass_kg,
        l.stiffness(),
        l.dt(),
        if l.delay() { ", one period of delay" } else { "" },
        spec.bandwidth_hz(),
        spec.damping(),
        spec.integral_hz()
    );
    Ok((g, note))
}

/// The impedance's gains: the file's stiffnesses, each direction's damping for its ratio on
/// its apparent inertia at the contact pose `m` (the normal's on its stiffness plus the
/// contact's; the yaw's where the robot's task has the rotation about z, about the normal
/// and the tilt's about the tangent axes for an arm that controls all three rotations).
pub(super) fn impedance_gains<const N: usize, R: RobotModel<N>>(
    scenario: &Scenario,
    f: &ForceSpec,
    robot: &R,
    m: &ContactModel,
) -> Result<ImpedanceGains, ScenarioError> {
    let s = &f.laws.impedance;
    let key = "force.impedance";
    let q = JointVector::<N>::from_fn(|i, _| m.q[i]);
    let n = m.normal;
    let t1 = if n.x.abs() < 0.9 {
        Vector3::x()
    } else {
        Vector3::y()
    };
    let t1 = (t1 - n * n.dot(&t1)).normalize();
    let t2 = n.cross(&t1);
    let mass = |d: &Vector3<f64>| {
        apparent_mass(robot, &q, d).map_err(|e| scenario.error(key, e.to_string()))
    };
    let tangential_mass = libm::sqrt(mass(&t1)? * mass(&t2)?);
    let contact = s.contact_stiffness.unwrap_or(m.stiffness);
    let damping = |k: f64, mass: f64| 2.0 * s.damping_ratio * libm::sqrt(k * mass);
    // A rotation's inertia about the unit axis `a`: 1 / (s^T J M^-1 J^T s), s = [0; a].
    let j = robot.jacobian(&q);
    let chol = robot.mass_matrix(&q).cholesky();
    let inertia = |a: &Vector3<f64>| {
        let row =
            JointVector::<N>::from_fn(|c, _| a.x * j[(3, c)] + a.y * j[(4, c)] + a.z * j[(5, c)]);
        chol.as_ref()
            .map(|c| row.dot(&c.solve(&row)))
            .filter(|v| *v > 0.0)
            .map(|v| 1.0 / v)
            .ok_or_else(|| {
                scenario.error(
                    key,
                    "the rotational inertia at the contact pose is not positive",
                )
            })
    };
    let full = R::TASK.rotations() == Rotations::Full;
    // The yaw: about base z (the SCARA's task row wz), about the normal in the full frame.
    let yaw_damping = if full {
        damping(s.yaw_stiffness, inertia(&n)?)
    } else if R::TASK.controls(5) {
        damping(s.yaw_stiffness, inertia(&Vector3::z())?)
    } else {
        0.0
    };
    let (tilt_stiffness, tilt_damping) = if full {
        let tilt_inertia = libm::sqrt(inertia(&t1)? * inertia(&t2)?);
        (s.tilt_stiffness, damping(s.tilt_stiffness, tilt_inertia))
    } else {
        (0.0, 0.0)
    };
    Ok(ImpedanceGains {
        normal_stiffness: s.stiffness,
        normal_damping: damping(s.stiffness + contact, m.mass_kg),
        tangential_stiffness: s.tangential_stiffness,
        tangential_damping: damping(s.tangential_stiffness, tangential_mass),
        yaw_stiffness: s.yaw_stiffness,
        yaw_damping,
        tilt_stiffness,
        tilt_damping,
        contact_stiffness: contact,
    })
}
