//! Stage 4: the force loop. With a `[force]` table: the task frame from the controller's
//! belief of the force surface, the check that the reference comes near it, the desired
//! force over time, and the force law (hybrid PI + feedforward, impedance or admittance)
//! around the position law; gains designed at the contact pose where asked.

use super::super::controllers::{ForceController, GainReport, PositionController};
use super::super::desired_force::{DesiredForce, ForceShape};
use super::super::error::ScenarioError;
use super::super::robot::ScenarioRobot;
use super::super::spec::{ForceReferenceSpec, ForceSpec, Scenario};
use super::force_design::contact_model_of;
use super::full_frame_laws::{friction_note, needs_contact, Built, ForceLawContext};
use super::reference::ReferenceStage;
use crate::control::admittance::{AdmittanceGains, NormalAdmittance};
use crate::control::force::ForcePi;
use crate::control::hybrid::HybridForcePosition;
use crate::control::selection::SelectionPolicy;
use crate::control::task_frame::TaskFrame;
use crate::control::task_rows::TaskRows;
use crate::control::Controller;
use crate::model::RobotModel;
use crate::target::Rotations;
use crate::trajectory::{sample, CartesianTrajectory, ForceProfile};

/// How far the reference must come to a force-controlled surface (its nominal position), m:
/// a reference that never gets this close is refused ("a surface the reference never
/// reaches").
pub const MAX_REACH_GAP_M: f64 = 0.02;

/// Stage 4 (see the [module documentation](self)): the controller, and the desired force
/// (`None` without a `[force]` table, when the position law is returned as it is).
///
/// # Errors
///
/// [`ScenarioError`] naming the key at fault: a surface the reference never reaches, a
/// switch time after the run, a force law the robot's task cannot run, a failed design.
pub fn force_law<const N: usize, R: ScenarioRobot<N>, M: RobotModel<N> + Copy + 'static>(
    scenario: &Scenario,
    robot: &R,
    model: M,
    reference: &ReferenceStage<N>,
    position: Box<dyn Controller<N>>,
    gains: &mut GainReport,
) -> Result<(Box<dyn Controller<N>>, Option<DesiredForce>), ScenarioError> {
    let (Some(f), Some(selection)) = (&scenario.force, &scenario.selection) else {
        return Ok((position, None));
    };
    let duration = reference.duration;
    let key = format!("surfaces[{}]", f.surface);
    let nominal = scenario.surfaces[f.surface]
        .geometry
        .shifted(f.expected_shift_m);
    let frame = TaskFrame::Surface(nominal);
    check_reach(
        scenario,
        reference.planned.trajectory(),
        duration,
        &frame,
        &key,
    )?;
    let start_s = match selection {
        SelectionPolicy::Time { switch_s } => {
            if *switch_s >= duration {
                return Err(scenario.error(
                    "selection.switch_s",
                    format!("{switch_s} s is not before the end of the run ({duration} s)"),
                ));
            }
            *switch_s
        }
        SelectionPolicy::Contact(_) => 0.0,
    };
    let profile = match &f.reference {
        ForceReferenceSpec::Constant => {
            ForceShape::Profile(ForceProfile::constant(-f.value_n, start_s))
        }
        ForceReferenceSpec::ThesisVariable => ForceShape::Profile(ForceProfile::Variable {
            magnitude: -f.value_n,
            amplitude: -f.value_n,
            omega: 10.0 / THESIS_VARIABLE_PERIOD_S,
            switch_time: start_s,
        }),
        ForceReferenceSpec::Csv(samples) => ForceShape::Sampled {
            samples: samples.clone(),
            start_s,
        },
    };
    let (controller, tool_axis) = build(
        scenario, f, robot, model, reference, position, frame, *selection, gains,
    )?;
    Ok((
        controller,
        Some(DesiredForce {
            profile,
            frame,
            tool_axis,
        }),
    ))
}

/// The variable profile's time scale: `value (1 + sin(10 t / T))` with the thesis's run of
/// `T = 10 s`, so one radian per second.
pub const THESIS_VARIABLE_PERIOD_S: f64 = 10.0;

/// Refuses a force-controlled surface that the reference never comes near.
fn check_reach(
    scenario: &Scenario,
    trajectory: &dyn CartesianTrajectory,
    duration: f64,
    frame: &TaskFrame,
    key: &str,
) -> Result<(), ScenarioError> {
    let mut closest: Option<(f64, f64)> = None;
    for s in sample(trajectory, 0.005)
        .into_iter()
        .filter(|s| s.t <= duration)
    {
        if let Some(gap) = frame.signed_distance(&s.position) {
            if closest.is_none_or(|(g, _)| gap < g) {
                closest = Some((gap, s.t));
            }
        }
    }
    match closest {
        Some((gap, _)) if gap <= MAX_REACH_GAP_M => Ok(()),
        Some((gap, t)) => Err(scenario.error(key, format!(
            "the reference never reaches this surface: it comes no closer than {:.1} mm (at t = {t:.3} s); it must come within {:.0} mm",
            gap * 1e3,
            MAX_REACH_GAP_M * 1e3
        ))),
        None => Err(scenario.error(key, "the reference never passes over this surface's extent")),
    }
}

/// The force-controlled controller a scenario's `[force]` table names, around the position
/// loop `position`; fills in `gains` (the PI gains used, and the note).
#[allow(clippy::too_many_arguments)]
fn build<const N: usize, R: ScenarioRobot<N>, M: RobotModel<N> + Copy + 'static>(
    scenario: &Scenario,
    f: &ForceSpec,
    robot: &R,
    model: M,
    reference: &ReferenceStage<N>,
    position: Box<dyn Controller<N>>,
    frame: TaskFrame,
    selection: SelectionPolicy,
    gains: &mut GainReport,
) -> Result<Built<N>, ScenarioError> {
    let switching = match selection {
        SelectionPolicy::Time { .. } => "time",
        SelectionPolicy::Contact(_) => "contact",
    };
    let full_frame = R::TASK.rotations() == Rotations::Full
        && scenario.position == PositionController::TaskSpace
        && f.law != ForceController::Impedance;
    // The contact pose: planned once, before any law, where the law needs it.
    let contact = if needs_contact(f, full_frame) {
        Some(contact_model_of(
            scenario,
            robot,
            reference.planned.as_ref(),
            reference.duration,
        )?)
    } else {
        None
    };
    let laws = ForceLawContext {
        scenario,
        f,
        robot,
        reference,
        frame,
        selection,
        switching,
        contact,
    };
    match f.law {
        ForceController::PiFf | ForceController::PiFfVd if full_frame => {
            return laws.hybrid(model, gains)
        }
        ForceController::Admittance if full_frame => return laws.admittance(model, gains),
        _ => {}
    }
    let rows = || {
        TaskRows::<N>::of_task(R::TASK).ok_or_else(|| {
            scenario.error(
                "force",
                format!(
                    "the force laws act on a square task (one direction per joint, x, y and z among them); robot `{}` has {N} joints and the task {}: with [position] law = \"task-space\" the PI laws and the admittance run in the full task frame instead",
                    R::NAME,
                    R::TASK.names().join(", ")
                ),
            )
        })
    };
    let controller: Box<dyn Controller<N>> = match f.law {
        ForceController::PiFf | ForceController::PiFfVd => {
            let (kfp, kfi, kvd, design_note) = laws.pi_gains()?;
            let hybrid = HybridForcePosition::new(
                model,
                position,
                ForcePi::new(kfp, kfi, kvd),
                frame,
                selection,
                *rows()?.rows(),
            )
            .ok_or_else(|| scenario.error("force", "bad task rows"))?
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
                friction_note(f),
                design_note
            );
            Box::new(hybrid)
        }
        ForceController::Impedance => return laws.impedance(model, gains),
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
                HybridForcePosition::new(
                    model,
                    position,
                    NormalAdmittance::new(AdmittanceGains {
                        mass_kg: a.mass_kg,
                        damping: a.damping,
                    }),
                    frame,
                    selection,
                    *rows()?.rows(),
                )
                .ok_or_else(|| scenario.error("force", "bad task rows"))?,
            )
        }
    };
    Ok((controller, None))
}
