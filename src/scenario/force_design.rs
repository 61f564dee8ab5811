//! The force loop of a scenario at its contact pose: where the reference first meets the
//! force surface (as the controller believes it to be), the robot's apparent mass along
//! the normal there, and the gains built from it: designed PI gains (`gains = "design"`)
//! and the impedance's damping.

use nalgebra::Vector3;

use super::controllers::{ForceController, GainReport, HybridSetup};
use super::error::ScenarioError;
use super::spec::{ForceSpec, Scenario};
use crate::control::admittance::{Admittance, AdmittanceGains};
use crate::control::design::{
    apparent_mass, design, push_limit, DesignError, ForceGains, ForceLoop, PushLimit,
};
use crate::control::force::ForcePi;
use crate::control::hybrid::HybridForcePosition;
use crate::control::impedance::{CartesianImpedance, ImpedanceGains};
use crate::control::selection::SelectionPolicy;
use crate::control::task_frame::TaskFrame;
use crate::control::Controller;
use crate::model::{JointVector, RobotModel, Scara};
use crate::robots::scara::{ScaraGeometry, SwitchPolicy};
use crate::trajectory::sample;

/// The contact pose of a scenario and the loop model's numbers there.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactModel {
    /// When the reference first reaches the expected surface (or comes closest), s.
    pub t_s: f64,
    /// The joints there (inverse kinematics with the run's elbow).
    pub q: JointVector<4>,
    /// The expected surface's outward normal there.
    pub normal: Vector3<f64>,
    /// The robot's apparent mass along it, kg.
    pub mass_kg: f64,
    /// The force surface's stiffness, N/m.
    pub stiffness: f64,
    /// Its damping, N s/m.
    pub damping: f64,
}

/// The contact pose of a force-controlled scenario.
///
/// # Errors
///
/// [`ScenarioError`] if the scenario has no `[force]` table, its reference leaves the
/// workspace, never passes over the surface, or the pose is singular.
pub fn contact_model(scenario: &Scenario) -> Result<ContactModel, ScenarioError> {
    let f = scenario
        .force
        .as_ref()
        .ok_or_else(|| scenario.error("force", "a force loop needs a [force] table"))?;
    let trajectory = super::trial::trajectory(scenario);
    let duration = scenario.duration_s.unwrap_or_else(|| trajectory.duration());
    let geometry = ScaraGeometry::from_model(&Scara);
    let plan = geometry
        .plan_trajectory(
            trajectory.as_ref(),
            0.005_f64.min(scenario.control_dt_s),
            SwitchPolicy::Latest,
        )
        .map_err(|e| {
            scenario.error(
                "reference",
                format!("the reference leaves the workspace: {e}"),
            )
        })?;
    let surface = &scenario.surfaces[f.surface];
    let frame = TaskFrame::Surface(super::trial::shifted(&surface.geometry, f.expected_shift_m));
    let key = format!("surfaces[{}]", f.surface);
    let mut best: Option<(f64, f64, Vector3<f64>, f64)> = None;
    for s in sample(trajectory.as_ref(), 0.005)
        .into_iter()
        .filter(|s| s.t <= duration)
    {
        if let Some(gap) = frame.signed_distance(&s.position) {
            if best.is_none_or(|(g, ..)| gap < g.max(1e-6)) {
                best = Some((gap, s.t, s.position, s.yaw()));
            }
            if gap <= 1e-6 {
                break;
            }
        }
    }
    let (gap, t_s, position, yaw) = best.ok_or_else(|| {
        scenario.error(
            &key,
            "the reference never passes over this surface's extent",
        )
    })?;
    let normal = frame.normal_at(&position);
    let on_surface = position - normal * gap;
    let q = geometry
        .inverse(&on_surface, yaw, plan.elbow_at(t_s))
        .map_err(|e| scenario.error(&key, format!("the contact pose is out of reach: {e}")))?;
    let mass_kg =
        apparent_mass(&Scara, &q, &normal).map_err(|e| scenario.error(&key, e.to_string()))?;
    Ok(ContactModel {
        t_s,
        q,
        normal,
        mass_kg,
        stiffness: surface.stiffness,
        damping: surface.damping,
    })
}

impl ContactModel {
    /// What the actuators allow pushing into the surface (along `-normal`) at this pose.
    ///
    /// # Errors
    ///
    /// [`DesignError::Model`] at a singular pose.
    pub fn push_limit(&self) -> Result<PushLimit, DesignError> {
        push_limit(&Scara, &self.q, &(-self.normal))
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

/// The gains `[force.design]` asks for, at the scenario's contact pose, and a note saying
/// how they were obtained.
pub(super) fn designed_gains(
    scenario: &Scenario,
    f: &ForceSpec,
) -> Result<(ForceGains, String), ScenarioError> {
    let m = contact_model(scenario)?;
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
/// its apparent inertia at the contact pose (the normal's on its stiffness plus the
/// contact's).
pub(super) fn impedance_gains(
    scenario: &Scenario,
    f: &ForceSpec,
) -> Result<ImpedanceGains, ScenarioError> {
    let m = contact_model(scenario)?;
    let s = &f.laws.impedance;
    let key = "force.impedance";
    let n = m.normal;
    let t1 = if n.x.abs() < 0.9 {
        Vector3::x()
    } else {
        Vector3::y()
    };
    let t1 = (t1 - n * n.dot(&t1)).normalize();
    let t2 = n.cross(&t1);
    let mass = |d: &Vector3<f64>| {
        apparent_mass(&Scara, &m.q, d).map_err(|e| scenario.error(key, e.to_string()))
    };
    let tangential_mass = libm::sqrt(mass(&t1)? * mass(&t2)?);
    // Yaw: 1 / (e^T J M^-1 J^T e) with e the wz row.
    let j = Scara.jacobian(&m.q);
    let row = JointVector::<4>::from_fn(|c, _| j[(5, c)]);
    let inv = Scara
        .mass_matrix(&m.q)
        .cholesky()
        .map(|c| row.dot(&c.solve(&row)))
        .filter(|v| *v > 0.0)
        .ok_or_else(|| {
            scenario.error(key, "the yaw inertia at the contact pose is not positive")
        })?;
    let contact = s.contact_stiffness.unwrap_or(m.stiffness);
    let damping = |k: f64, mass: f64| 2.0 * s.damping_ratio * libm::sqrt(k * mass);
    Ok(ImpedanceGains {
        normal_stiffness: s.stiffness,
        normal_damping: damping(s.stiffness + contact, m.mass_kg),
        tangential_stiffness: s.tangential_stiffness,
        tangential_damping: damping(s.tangential_stiffness, tangential_mass),
        yaw_stiffness: s.yaw_stiffness,
        yaw_damping: damping(s.yaw_stiffness, 1.0 / inv),
        contact_stiffness: contact,
    })
}

/// The force-controlled controller a scenario's `[force]` table names, around the position
/// loop `position`; fills in `gains` (the PI gains used, and the note).
pub(super) fn build<R: RobotModel<4> + Copy + 'static>(
    scenario: &Scenario,
    f: &ForceSpec,
    model: R,
    position: Box<dyn Controller<4>>,
    frame: TaskFrame,
    selection: SelectionPolicy,
    gains: &mut GainReport,
) -> Result<Box<dyn Controller<4>>, ScenarioError> {
    let switching = match selection {
        SelectionPolicy::Time { .. } => "time",
        SelectionPolicy::Contact(_) => "contact",
    };
    let bad_rows = || scenario.error("force", "bad task rows");
    let controller: Box<dyn Controller<4>> = match f.law {
        ForceController::PiFf | ForceController::PiFfVd => {
            let (kfp, kfi, kvd, design_note) = if f.laws.design_gains {
                let (g, note) = designed_gains(scenario, f)?;
                (g.kfp, g.kfi, g.kvd, format!(", gains {note}"))
            } else {
                (f.gains.0, f.gains.1, f.gains.2, String::new())
            };
            let hybrid = HybridForcePosition::new(
                model,
                position,
                ForcePi::new(kfp, kfi, kvd),
                frame,
                selection,
                HybridSetup::ROWS,
            )
            .ok_or_else(bad_rows)?
            .with_friction_feedforward(f.friction_feedforward)
            .with_normal_gravity_compensation(f.gravity_compensation)
            .with_anti_windup(f.anti_windup);
            gains.force = Some((kfp, kfi, kvd));
            gains.note = format!(
                "position loop: {} ({}); force loop: {} along the surface normal{}{}, {} switching{}{}",
                scenario.position.name(),
                gains.note,
                f.law.name(),
                if f.gravity_compensation {
                    " with gravity compensation"
                } else {
                    ""
                },
                if f.anti_windup { ", anti-windup" } else { "" },
                switching,
                if f.friction_feedforward > 0.0 {
                    format!(", friction feedforward mu = {}", f.friction_feedforward)
                } else {
                    String::new()
                },
                design_note
            );
            Box::new(hybrid)
        }
        ForceController::Impedance => {
            let g = impedance_gains(scenario, f)?;
            gains.note = format!(
                "Cartesian impedance, tau = J^T F + g + c (no position loop, no force feedback): normal {} N/m, {:.1} N s/m; tangential {} N/m, {:.1} N s/m; yaw {} N m/rad, {:.2} N m s/rad; virtual point |f_d| (1/K + 1/{} N/m) inside the expected surface; {} switching",
                g.normal_stiffness,
                g.normal_damping,
                g.tangential_stiffness,
                g.tangential_damping,
                g.yaw_stiffness,
                g.yaw_damping,
                g.contact_stiffness,
                switching
            );
            gains.kp = None;
            gains.ki = None;
            gains.kd = None;
            gains.poles.clear();
            Box::new(
                CartesianImpedance::new(model, g, frame, selection, HybridSetup::ROWS)
                    .ok_or_else(bad_rows)?,
            )
        }
        ForceController::Admittance => {
            let a = f.laws.admittance;
            gains.note = format!(
                "admittance: virtual mass {} kg and damping {} N s/m move the reference along the normal; position loop: {} ({}); {} switching",
                a.mass_kg,
                a.damping,
                scenario.position.name(),
                gains.note,
                switching
            );
            Box::new(
                Admittance::new(
                    model,
                    position,
                    AdmittanceGains {
                        mass_kg: a.mass_kg,
                        damping: a.damping,
                    },
                    frame,
                    selection,
                    HybridSetup::ROWS,
                )
                .ok_or_else(bad_rows)?,
            )
        }
    };
    Ok(controller)
}
