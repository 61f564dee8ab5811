//! The force laws in the full task frame, for an arm that controls all three rotations: the
//! hybrid law ([`TaskSpaceHybrid`], under the task-space position law), the impedance
//! ([`CartesianImpedance`], any position law: it has none; built here for every task) and the
//! admittance (the hybrid law with the mass-damper along the normal, the task-space position
//! law's gains). Each holds the tool axis along the inward normal ([`ToolOrientation`], chosen
//! once per run from `[force] tool_axis`).

use super::super::controllers::ForceController;
use super::super::controllers::{task_space_gains, GainReport};
use super::super::error::ScenarioError;
use super::super::force_spec::ToolAxis;
use super::super::robot::ScenarioRobot;
use super::super::spec::{ForceSpec, Scenario};
use super::force_design::{designed_gains, impedance_gains, ContactModel};
use super::reference::ReferenceStage;
use crate::control::admittance::{AdmittanceGains, NormalAdmittance};
use crate::control::force::ForcePi;
use crate::control::hybrid::{HybridForcePosition, TaskSpaceHybrid};
use crate::control::impedance::{CartesianImpedance, PostureGains};
use crate::control::selection::SelectionPolicy;
use crate::control::task_frame::TaskFrame;
use crate::control::task_space::TaskSpaceGains;
use crate::control::tool_orientation::ToolOrientation;
use crate::control::Controller;
use crate::model::RobotModel;
use crate::target::Rotations;
use nalgebra::Vector3;

/// What every force-law builder takes: the scenario, its `[force]`, the robot, the
/// reference, the task frame and the switching.
pub(super) struct ForceLawContext<'a, const N: usize, R> {
    pub(super) scenario: &'a Scenario,
    pub(super) f: &'a ForceSpec,
    pub(super) robot: &'a R,
    pub(super) reference: &'a ReferenceStage<N>,
    pub(super) frame: TaskFrame,
    pub(super) selection: SelectionPolicy,
    pub(super) switching: &'a str,
    /// The contact pose, planned once before any law is built, where the law needs it
    /// ([`needs_contact`]).
    pub(super) contact: Option<ContactModel>,
}

/// Whether the force law of `f` needs the contact pose: for designed PI gains, the
/// impedance's damping, or the tool axis nearest the inward normal there (`full_frame`: the
/// law runs in the full task frame, which holds a tool axis).
pub(super) fn needs_contact(f: &ForceSpec, full_frame: bool) -> bool {
    let nearest_axis = full_frame && f.tool_axis == ToolAxis::Nearest;
    match f.law {
        ForceController::Impedance => true,
        ForceController::PiFf | ForceController::PiFfVd => f.laws.design_gains || nearest_axis,
        ForceController::Admittance => nearest_axis,
    }
}

/// A full-frame controller and the tool axis it holds along the inward normal (tool frame).
pub(super) type Built<const N: usize> = (Box<dyn Controller<N>>, Option<Vector3<f64>>);

impl<const N: usize, R: ScenarioRobot<N>> ForceLawContext<'_, N, R> {
    /// The contact pose ([`needs_contact`] says when the stage plans it).
    pub(super) fn contact(&self) -> Result<&ContactModel, ScenarioError> {
        self.contact.as_ref().ok_or_else(|| {
            self.scenario
                .error("force", "this force law was built without its contact pose")
        })
    }

    /// The tool orientation `[force] tool_axis` asks for: a stated axis, the reference's
    /// orientation, or (the default) the tool-frame axis nearest the inward normal at the
    /// contact pose `contact`.
    fn tool_orientation(&self, contact: Option<&ContactModel>) -> ToolOrientation {
        match (self.f.tool_axis, contact) {
            (ToolAxis::Given(a), _) => ToolOrientation::AlongNormal(a),
            (ToolAxis::Nearest, Some(c)) => {
                let r = self.reference.planned.trajectory().at(c.t_s).orientation;
                ToolOrientation::AlongNormal(nearest_axis(&(r.inverse() * -c.normal)))
            }
            // `Reference` (and, not reached, `Nearest` without a contact pose).
            _ => ToolOrientation::Reference,
        }
    }

    /// The task-space law's gains of `[position]` on the controller's model `M`.
    fn motion_gains<M: RobotModel<N>>(&self) -> Result<TaskSpaceGains, ScenarioError> {
        task_space_gains::<N, M>(&self.scenario.position_settings)
            .map(|(gains, _)| gains)
            .map_err(|e| self.scenario.error("position.omega_rad_s", e))
    }

    /// The PI gains `kfp, kfi, kvd` of the file, or designed at the contact pose
    /// (`[force.design]`), and the note's words for the design (empty for the file's).
    pub(super) fn pi_gains(&self) -> Result<(f64, f64, f64, String), ScenarioError> {
        let f = self.f;
        if f.laws.design_gains {
            let (g, note) = designed_gains(self.scenario, f, self.contact()?)?;
            Ok((g.kfp, g.kfi, g.kvd, format!(", gains {note}")))
        } else {
            Ok((f.gains.0, f.gains.1, f.gains.2, String::new()))
        }
    }

    /// The hybrid law in the full task frame ([`TaskSpaceHybrid`]): the motion gains of
    /// `[position]`, the force law's (given or designed).
    pub(super) fn hybrid<M: RobotModel<N> + Copy + 'static>(
        &self,
        model: M,
        gains: &mut GainReport,
    ) -> Result<Built<N>, ScenarioError> {
        let (scenario, f) = (self.scenario, self.f);
        let motion = self.motion_gains::<M>()?;
        let (kfp, kfi, kvd, design_note) = self.pi_gains()?;
        let tool = self.tool_orientation(self.contact.as_ref());
        let law = TaskSpaceHybrid::in_task_frame(
            model,
            motion,
            ForcePi::new(kfp, kfi, kvd),
            self.frame,
            tool,
            self.selection,
        )
        .ok_or_else(|| scenario.error("force", "the task lacks a translation"))?
        .with_friction_feedforward(f.friction_feedforward)
        .with_anti_windup(f.anti_windup)
        .with_reference_motion(
            f.damp_reference_motion
                .then_some(scenario.surfaces[f.surface].stiffness),
        );
        gains.force = Some((kfp, kfi, kvd));
        gains.note = format!(
            "{}; force loop: {} along the surface normal in the full task frame (the normal row of F = Lambda a* replaced by the force law, gravity compensated in joint space, velocity damping {}){}, {}, {} switching{}{}",
            gains.note,
            f.law.name(),
            if f.damp_reference_motion {
                "against the force reference's own motion"
            } else {
                "on the normal velocity"
            },
            if f.anti_windup { ", anti-windup" } else { "" },
            describe(tool),
            self.switching,
            friction_note(f),
            design_note
        );
        Ok((Box::new(law), tool.axis()))
    }

    /// Cartesian impedance over the robot's task ([`CartesianImpedance`]): the file's
    /// stiffnesses, each damping critical (times the ratio) on its apparent inertia at the
    /// contact pose; an arm with all three rotations holds the tool axis along the normal and
    /// its posture with the gains of `[position]`, a square task without them (the SCARA's x,
    /// y, z, yaw) follows the reference's orientation and has no posture.
    pub(super) fn impedance<M: RobotModel<N> + Copy + 'static>(
        &self,
        model: M,
        gains: &mut GainReport,
    ) -> Result<Built<N>, ScenarioError> {
        let scenario = self.scenario;
        let full = R::TASK.rotations() == Rotations::Full;
        let posture = if full {
            let motion = self.motion_gains::<M>()?;
            PostureGains {
                kp: motion.posture_kp,
                kd: motion.posture_kd,
            }
        } else {
            PostureGains { kp: 0.0, kd: 0.0 }
        };
        let contact = self.contact()?;
        let g = impedance_gains(scenario, self.f, self.robot, contact)?;
        let tool = if full {
            self.tool_orientation(Some(contact))
        } else {
            ToolOrientation::Reference
        };
        let law = CartesianImpedance::new(model, g, posture, self.frame, tool, self.selection)
            .ok_or_else(|| scenario.error("force", "the task lacks a translation"))?;
        gains.note = format!(
            "Cartesian impedance{}, tau = J^T F + g + c{} (no position loop, no force feedback): normal {} N/m, {:.1} N s/m; tangential {} N/m, {:.1} N s/m; {} {} N m/rad, {:.2} N m s/rad{}; virtual point |f_d| (1/K + 1/{} N/m) inside the expected surface; {}{} switching",
            if full { " in the full task frame" } else { "" },
            if R::TASK.redundancy(N) > 0 {
                " + the posture in the null space"
            } else {
                ""
            },
            g.normal_stiffness,
            g.normal_damping,
            g.tangential_stiffness,
            g.tangential_damping,
            if full { "about the normal" } else { "yaw" },
            g.yaw_stiffness,
            g.yaw_damping,
            if full {
                format!(
                    "; tilt {} N m/rad, {:.2} N m s/rad",
                    g.tilt_stiffness, g.tilt_damping
                )
            } else {
                String::new()
            },
            g.contact_stiffness,
            if full {
                format!("{}, ", describe(tool))
            } else {
                String::new()
            },
            self.switching
        );
        gains.kp = None;
        gains.ki = None;
        gains.kd = None;
        gains.poles.clear();
        Ok((Box::new(law), tool.axis()))
    }

    /// Admittance in the full task frame: the hybrid law with the mass-damper along the
    /// normal, the motion gains of `[position]` (the task-space law's).
    pub(super) fn admittance<M: RobotModel<N> + Copy + 'static>(
        &self,
        model: M,
        gains: &mut GainReport,
    ) -> Result<Built<N>, ScenarioError> {
        let scenario = self.scenario;
        let motion = self.motion_gains::<M>()?;
        let a = self.f.laws.admittance;
        let tool = self.tool_orientation(self.contact.as_ref());
        gains.note = format!(
            "admittance in the full task frame: virtual mass {} kg and damping {} N s/m move the Cartesian reference along the normal; position loop: {} ({}); {}, {} switching",
            a.mass_kg,
            a.damping,
            self.scenario.position.name(),
            gains.note,
            describe(tool),
            self.switching
        );
        let law = HybridForcePosition::in_task_frame(
            model,
            motion,
            NormalAdmittance::new(AdmittanceGains {
                mass_kg: a.mass_kg,
                damping: a.damping,
            }),
            self.frame,
            tool,
            self.selection,
        )
        .ok_or_else(|| scenario.error("force", "the task lacks a translation"))?;
        Ok((Box::new(law), tool.axis()))
    }
}

/// The orientation rule in words, for the gain note.
fn describe(tool: ToolOrientation) -> String {
    match tool {
        ToolOrientation::AlongNormal(a) => format!(
            "tool axis [{:.3}, {:.3}, {:.3}] (tool frame) held along the inward normal",
            a.x, a.y, a.z
        ),
        ToolOrientation::Reference => "the reference's orientation".into(),
    }
}

/// The friction feedforward in words (empty without it).
pub(super) fn friction_note(f: &ForceSpec) -> String {
    if f.friction_feedforward > 0.0 {
        format!(", friction feedforward mu = {}", f.friction_feedforward)
    } else {
        String::new()
    }
}

/// The tool frame's signed unit axis (`+-x`, `+-y`, `+-z`) nearest the direction `d`.
fn nearest_axis(d: &Vector3<f64>) -> Vector3<f64> {
    let k = d.iamax();
    let mut a = Vector3::zeros();
    a[k] = d[k].signum();
    a
}
