//! The thesis's controller line-up on the SCARA: its force-reference profiles (Appendix B.3)
//! and the hybrid controller of Chapter 5 as the thesis built it.

use super::thesis_setup::{thesis_force_law, thesis_position_loop, THESIS_SELECTION};
use crate::control::hybrid::HybridForcePosition;
use crate::control::mass_split::SplitKind;
use crate::control::task_frame::TaskFrame;
use crate::control::Controller;
use crate::model::Scara;
use crate::scenario::{
    pid_report, ForceController, GainReport, PositionController, PositionSettings, UnknownName,
};
use crate::trajectory::ForceProfile;

/// The thesis's position laws, in its order (Chapter 4).
pub const THESIS_POSITION_LAWS: [PositionController; 6] = [
    PositionController::Pid,
    PositionController::PidFl,
    PositionController::FsfPlace,
    PositionController::FsfLqr,
    PositionController::PidFlCentral,
    PositionController::ComputedTorque,
];

/// The thesis's two force laws, in its order (Section 5.3; `armdyn run hybrid --all`).
pub const THESIS_FORCE_LAWS: [ForceController; 2] =
    [ForceController::PiFf, ForceController::PiFfVd];

/// Builds a position controller of the thesis's line-up for the SCARA with the gains the
/// thesis computes from the model.
///
/// # Errors
///
/// A message if a gain design fails (not for the committed robot).
pub fn position_controller(
    law: PositionController,
) -> Result<(Box<dyn Controller<4>>, GainReport), String> {
    law.build_with(Scara, &PositionSettings::default())
}

/// The desired-force profiles of Appendix B.3.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ForceReference {
    /// -200 N from 2 s.
    Const,
    /// -200 - 200 sin(10 t / T) N from 2 s.
    Var,
}

impl ForceReference {
    /// Both.
    pub const ALL: [Self; 2] = [Self::Const, Self::Var];

    /// Command-line name.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Const => "const",
            Self::Var => "var",
        }
    }

    /// Parses a command-line name.
    ///
    /// # Errors
    ///
    /// [`UnknownName`] listing the known names.
    pub fn parse(name: &str) -> Result<Self, UnknownName> {
        UnknownName::find(&Self::ALL, Self::name, "force reference", name)
    }

    /// The profile.
    #[must_use]
    pub fn profile(self) -> ForceProfile {
        match self {
            Self::Const => super::thesis::constant_force(),
            Self::Var => super::thesis::variable_force(),
        }
    }
}

/// The hybrid controller of Chapter 5 for the SCARA: decentralized PID with feedback
/// linearization as the position loop, the chosen force law, the thesis's selection.
pub struct HybridSetup;

impl HybridSetup {
    /// Task rows of the SCARA's Jacobian: `vx vy vz wz`.
    pub const ROWS: [usize; 4] = super::TASK_ROWS;

    /// Builds it.
    ///
    /// # Errors
    ///
    /// A message if a gain design fails (not for the committed robot).
    pub fn build(force: ForceController) -> Result<(Box<dyn Controller<4>>, GainReport), String> {
        let position =
            thesis_position_loop(SplitKind::ConstantPart).ok_or("M_linear is singular")?;
        let mut report = pid_report(
            position.gains(),
            "position loop: PID with feedback linearization (eq. 4.22)",
        );
        let law = thesis_force_law(force == ForceController::PiFfVd);
        report.force = Some((law.kfp(), law.kfi(), law.kvd()));
        let c = HybridForcePosition::new(
            Scara,
            position,
            law,
            TaskFrame::along_z(),
            THESIS_SELECTION,
            Self::ROWS,
        )
        .ok_or("bad task rows")?;
        Ok((Box::new(c), report))
    }
}
