//! The controller line-up of the thesis, by command-line name, with the gains each one
//! computed from the model.

use crate::control::computed_torque::ComputedTorque;
use crate::control::force::ForcePi;
use crate::control::fsf::{FullStateFeedback, LqrWeights, THESIS_FSF_POLES};
use crate::control::gains::{MassRounding, PidGains, THESIS_PID_POLES};
use crate::control::hybrid::HybridForcePosition;
use crate::control::mass_split::{constant_part, SplitKind};
use crate::control::pid::Pid;
use crate::control::pid_fl::PidFeedbackLinearization;
use crate::control::selection::SelectionPolicy;
use crate::control::task_frame::TaskFrame;
use crate::control::Controller;
use crate::model::{JointVector, RobotModel, Scara};
use crate::trajectory::ForceProfile;

/// A name that is not one of the known ones.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("unknown {what} `{name}`; known: {known}")]
pub struct UnknownName {
    /// What kind of name.
    pub what: &'static str,
    /// The name given.
    pub name: String,
    /// The accepted names, comma-separated.
    pub known: String,
}

/// Finds `name` among `all` by `name_of`, or says which names are known.
fn parse_named<T: Copy>(
    all: &[T],
    name_of: fn(T) -> &'static str,
    what: &'static str,
    name: &str,
) -> Result<T, UnknownName> {
    all.iter()
        .copied()
        .find(|c| name_of(*c) == name)
        .ok_or_else(|| UnknownName {
            what,
            name: name.to_string(),
            known: all
                .iter()
                .map(|c| name_of(*c))
                .collect::<Vec<_>>()
                .join(", "),
        })
}

/// The gains a controller was built with, for reports (`metrics.json`).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct GainReport {
    /// PID proportional gains per joint (N m/rad or N/m).
    pub kp: Option<[f64; 4]>,
    /// PID integral gains per joint.
    pub ki: Option<[f64; 4]>,
    /// PID derivative gains per joint.
    pub kd: Option<[f64; 4]>,
    /// Full-state feedback position block K1, rows = joints (torque units).
    pub k1: Option<[[f64; 4]; 4]>,
    /// Full-state feedback velocity block K2.
    pub k2: Option<[[f64; 4]; 4]>,
    /// Requested closed-loop poles, rad/s.
    pub poles: Vec<f64>,
    /// Relative residual of the Riccati equation (LQR only).
    pub riccati_residual: Option<f64>,
    /// Force loop gains `(Kfp, Kfi 1/s, Kvd N s/m)` (hybrid only).
    pub force: Option<(f64, f64, f64)>,
    /// One line on how the gains were chosen.
    pub note: String,
}

fn arr(v: &JointVector<4>) -> [f64; 4] {
    [v[0], v[1], v[2], v[3]]
}

fn mat(m: &nalgebra::Matrix4<f64>) -> [[f64; 4]; 4] {
    core::array::from_fn(|i| core::array::from_fn(|j| m[(i, j)]))
}

fn pid_report(g: &PidGains<4>, note: &str) -> GainReport {
    GainReport {
        kp: Some(arr(&g.kp)),
        ki: Some(arr(&g.ki)),
        kd: Some(arr(&g.kd)),
        poles: THESIS_PID_POLES.to_vec(),
        note: note.to_string(),
        ..GainReport::default()
    }
}

/// The position controllers of Chapter 4 plus computed torque.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PositionController {
    /// Decentralized PID (Section 4.1).
    Pid,
    /// Decentralized PID with feedback linearization (Section 4.2).
    PidFl,
    /// Full-state feedback with feedback linearization, pole placement (Section 4.3).
    FsfPlace,
    /// Full-state feedback with feedback linearization, LQR (Section 4.3).
    FsfLqr,
    /// Centralized PID with feedback linearization (Section 4.3, eq. 4.38).
    PidFlCentral,
    /// Computed torque (textbook reference).
    ComputedTorque,
}

/// Natural frequency of the computed-torque reference design, rad/s.
pub const COMPUTED_TORQUE_OMEGA: f64 = 10.0;
/// Natural frequency of the LQR design's critically damped poles, rad/s (mean of -8.0..-8.7).
pub const LQR_OMEGA: f64 = 8.35;

impl PositionController {
    /// Every controller, in the thesis's order.
    pub const ALL: [Self; 6] = [
        Self::Pid,
        Self::PidFl,
        Self::FsfPlace,
        Self::FsfLqr,
        Self::PidFlCentral,
        Self::ComputedTorque,
    ];

    /// Command-line name.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Pid => "pid",
            Self::PidFl => "pid-fl",
            Self::FsfPlace => "fsf-place",
            Self::FsfLqr => "fsf-lqr",
            Self::PidFlCentral => "pid-fl-central",
            Self::ComputedTorque => "computed-torque",
        }
    }

    /// Parses a command-line name.
    ///
    /// # Errors
    ///
    /// [`UnknownName`] listing the known names.
    pub fn parse(name: &str) -> Result<Self, UnknownName> {
        parse_named(&Self::ALL, Self::name, "controller", name)
    }

    /// Builds the controller for the SCARA with gains computed from the model as the thesis
    /// does (masses rounded to three significant figures, as printed, for the PID designs).
    ///
    /// # Errors
    ///
    /// A message if a gain design fails (singular `M_linear`, Riccati not converging): not
    /// for the committed robot.
    pub fn build(self) -> Result<(Box<dyn Controller<4>>, GainReport), String> {
        self.build_with(Scara)
    }

    /// The position loop as the typed PID with feedback linearization it is (`pid-fl`:
    /// `M_linear` the constant part of `M`; `pid-fl-central`: its constant diagonal), gains
    /// for poles -8, -9, -10 with the thesis's rounding; `None` for the other laws.
    ///
    /// # Errors
    ///
    /// A message if `M_linear` is singular (not for a physical robot).
    pub fn feedback_linearization<R: RobotModel<4>>(
        self,
        robot: R,
    ) -> Option<Result<PidFeedbackLinearization<4, R>, String>> {
        let kind = match self {
            Self::PidFl => SplitKind::ConstantPart,
            Self::PidFlCentral => SplitKind::ConstantDiagonal,
            _ => return None,
        };
        Some(
            PidFeedbackLinearization::thesis(robot, kind, MassRounding::Thesis)
                .ok_or_else(|| "M_linear is singular".to_string()),
        )
    }

    /// As [`Self::build`], with gains and linearisation from `robot`'s model (an identified
    /// one, for instance) instead of the description's.
    ///
    /// # Errors
    ///
    /// A message if a gain design fails (a singular `M_linear`, Riccati not converging).
    pub fn build_with<R: RobotModel<4> + Copy + 'static>(
        self,
        robot: R,
    ) -> Result<(Box<dyn Controller<4>>, GainReport), String> {
        Ok(match self {
            Self::Pid => {
                let masses = MassRounding::Thesis
                    .apply(&robot.mass_matrix(&JointVector::zeros()).diagonal());
                let g = PidGains::from_poles(&masses, THESIS_PID_POLES);
                let report = pid_report(
                    &g,
                    "poles -8, -9, -10 on diag M(q2 = 0), 3 significant figures (eq. 4.15)",
                );
                (Box::new(Pid::new(g)), report)
            }
            Self::PidFl | Self::PidFlCentral => {
                let c = self
                    .feedback_linearization(robot)
                    .ok_or("not a PID with feedback linearization")??;
                let note = if self == Self::PidFl {
                    "poles -8, -9, -10 on diag M_linear (eq. 4.18, 4.22); qdd_cmd = M_linear^-1 u"
                } else {
                    "poles -8, -9, -10 on diag M_linear = diag of eq. 4.38; qdd_cmd = M_linear^-1 u"
                };
                let report = pid_report(c.gains(), note);
                (Box::new(c), report)
            }
            Self::FsfPlace => {
                let c = FullStateFeedback::place(robot, &THESIS_FSF_POLES)
                    .map_err(|e| e.to_string())?;
                let report = GainReport {
                    k1: Some(mat(c.k1())),
                    k2: Some(mat(c.k2())),
                    poles: THESIS_FSF_POLES.to_vec(),
                    note: "decoupled placement of -8.0 ... -8.7, tracking law u = M_linear qdd_d + K (x_d - x)".into(),
                    ..GainReport::default()
                };
                (Box::new(c), report)
            }
            Self::FsfLqr => {
                let m_lin = constant_part(&robot);
                let w = LqrWeights::acceleration_penalty(&m_lin, LQR_OMEGA)
                    .ok_or("M_linear is singular")?;
                let (c, sol) = FullStateFeedback::lqr(robot, &w).map_err(|e| e.to_string())?;
                let report = GainReport {
                    k1: Some(mat(c.k1())),
                    k2: Some(mat(c.k2())),
                    poles: vec![-LQR_OMEGA; 8],
                    riccati_residual: Some(sol.residual),
                    note: format!(
                        "LQR, Q = diag({:.1} I, {:.2} I), R = M_linear^-T M_linear^-1 (critically damped at -{LQR_OMEGA})",
                        LQR_OMEGA.powi(4),
                        2.0 * LQR_OMEGA * LQR_OMEGA
                    ),
                    ..GainReport::default()
                };
                (Box::new(c), report)
            }
            Self::ComputedTorque => {
                let c = ComputedTorque::critically_damped(robot, COMPUTED_TORQUE_OMEGA);
                let report = GainReport {
                    kp: Some(arr(c.kp())),
                    kd: Some(arr(c.kd())),
                    poles: vec![-COMPUTED_TORQUE_OMEGA; 8],
                    note: "tau = M (qdd_d + Kp e + Kd e') + c + g, Kp in 1/s^2, Kd in 1/s".into(),
                    ..GainReport::default()
                };
                (Box::new(c), report)
            }
        })
    }
}

/// The force laws: the two of Section 5.3 inside the hybrid law, and the impedance and
/// admittance baselines.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ForceController {
    /// PI + feedforward (eq. 5.10).
    PiFf,
    /// PI + feedforward + velocity damping (eq. 5.11).
    PiFfVd,
    /// Cartesian impedance ([`CartesianImpedance`](crate::control::impedance::CartesianImpedance)).
    Impedance,
    /// Admittance around the position loop ([`Admittance`](crate::control::admittance::Admittance)).
    Admittance,
}

impl ForceController {
    /// The thesis's two, in its order (`scara run hybrid --all`).
    pub const ALL: [Self; 2] = [Self::PiFf, Self::PiFfVd];
    /// Every law a scenario can name.
    pub const NAMED: [Self; 4] = [Self::PiFf, Self::PiFfVd, Self::Impedance, Self::Admittance];

    /// Command-line name.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::PiFf => "pi-ff",
            Self::PiFfVd => "pi-ff-vd",
            Self::Impedance => "impedance",
            Self::Admittance => "admittance",
        }
    }

    /// Parses a command-line name.
    ///
    /// # Errors
    ///
    /// [`UnknownName`] listing the known names.
    pub fn parse(name: &str) -> Result<Self, UnknownName> {
        parse_named(&Self::NAMED, Self::name, "force controller", name)
    }

    /// The thesis's gains `(Kfp, Kfi 1/s, Kvd N s/m)` (those of `pi-ff-vd` for the laws
    /// without them, where the hybrid law's gains are not used).
    #[must_use]
    pub fn thesis_gains(self) -> (f64, f64, f64) {
        let l = self.law();
        (l.kfp(), l.kfi(), l.kvd())
    }

    /// The thesis's law (`pi-ff-vd` for the laws without one).
    #[must_use]
    pub fn law(self) -> ForcePi {
        match self {
            Self::PiFf => ForcePi::thesis(),
            _ => ForcePi::thesis_damped(),
        }
    }

    /// Whether it is one of the hybrid law's PI laws.
    #[must_use]
    pub fn is_pi(self) -> bool {
        matches!(self, Self::PiFf | Self::PiFfVd)
    }
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
        parse_named(&Self::ALL, Self::name, "force reference", name)
    }

    /// The profile.
    #[must_use]
    pub fn profile(self) -> ForceProfile {
        match self {
            Self::Const => crate::robots::scara::thesis::constant_force(),
            Self::Var => crate::robots::scara::thesis::variable_force(),
        }
    }
}

/// The hybrid controller of Chapter 5 for the SCARA: decentralized PID with feedback
/// linearization as the position loop, the chosen force law, the thesis's selection.
pub struct HybridSetup;

impl HybridSetup {
    /// Task rows of the SCARA's Jacobian: `vx vy vz wz`.
    pub const ROWS: [usize; 4] = crate::robots::scara::TASK_ROWS;

    /// Builds it.
    ///
    /// # Errors
    ///
    /// A message if a gain design fails (not for the committed robot).
    pub fn build(force: ForceController) -> Result<(Box<dyn Controller<4>>, GainReport), String> {
        let position =
            PidFeedbackLinearization::thesis(Scara, SplitKind::ConstantPart, MassRounding::Thesis)
                .ok_or("M_linear is singular")?;
        let mut report = pid_report(
            position.gains(),
            "position loop: PID with feedback linearization (eq. 4.22)",
        );
        let law = force.law();
        report.force = Some((law.kfp(), law.kfi(), law.kvd()));
        let c = HybridForcePosition::new(
            Scara,
            position,
            law,
            TaskFrame::thesis(),
            SelectionPolicy::thesis(),
            Self::ROWS,
        )
        .ok_or("bad task rows")?;
        Ok((Box::new(c), report))
    }
}
