//! The controller line-up of the thesis, by command-line name, with the gains each one
//! computed from the model.

use crate::control::computed_torque::ComputedTorque;
use crate::control::fsf::{fsf_poles, FullStateFeedback, LqrWeights};
use crate::control::gains::{MassRounding, PidGains};
use crate::control::mass_split::{constant_part, SplitKind};
use crate::control::pid::Pid;
use crate::control::pid_fl::PidFeedbackLinearization;
use crate::control::task_space::{TaskSpaceGains, TaskSpaceInverseDynamics};
use crate::control::Controller;
use crate::model::{JointMatrix, JointVector, RobotModel};

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

impl UnknownName {
    /// Finds `name` among `all` by `name_of`, or says which names are known; `what` names
    /// the kind of thing looked up in the error ("controller", "force reference").
    ///
    /// # Errors
    ///
    /// [`UnknownName`] when no element of `all` is called `name`.
    pub fn find<T: Copy>(
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
}

/// The gains a controller was built with, for reports (`metrics.json`).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct GainReport {
    /// PID proportional gains per joint (N m/rad or N/m); computed torque's in 1/s^2; the
    /// task-space law's per task direction (1/s^2).
    pub kp: Option<Vec<f64>>,
    /// PID integral gains per joint.
    pub ki: Option<Vec<f64>>,
    /// PID derivative gains per joint (computed torque's and the task-space law's in 1/s).
    pub kd: Option<Vec<f64>>,
    /// Full-state feedback position block K1, rows = joints (torque units).
    pub k1: Option<Vec<Vec<f64>>>,
    /// Full-state feedback velocity block K2.
    pub k2: Option<Vec<Vec<f64>>>,
    /// Requested closed-loop poles, rad/s.
    pub poles: Vec<f64>,
    /// Relative residual of the Riccati equation (LQR only).
    pub riccati_residual: Option<f64>,
    /// Force loop gains `(Kfp, Kfi 1/s, Kvd N s/m)` (hybrid only).
    pub force: Option<(f64, f64, f64)>,
    /// One line on how the gains were chosen.
    pub note: String,
}

fn arr<const N: usize>(v: &JointVector<N>) -> Vec<f64> {
    v.iter().copied().collect()
}

fn mat<const N: usize>(m: &JointMatrix<N>) -> Vec<Vec<f64>> {
    (0..N)
        .map(|i| (0..N).map(|j| m[(i, j)]).collect())
        .collect()
}

/// The closed-loop poles of the scenario's PID designs (`pid`, `pid-fl`, `pid-fl-central`),
/// rad/s, on every robot: the thesis's (eq. 4.13; the preset
/// `robots::scara::thesis_setup::THESIS_PID_POLES`, checked by a test there).
pub const PID_POLES: [f64; 3] = [-8.0, -9.0, -10.0];

/// The report of PID gains designed for the scenario's poles ([`PID_POLES`]).
pub fn pid_report<const N: usize>(g: &PidGains<N>, note: &str) -> GainReport {
    GainReport {
        kp: Some(arr(&g.kp)),
        ki: Some(arr(&g.ki)),
        kd: Some(arr(&g.kd)),
        poles: PID_POLES.to_vec(),
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
    /// Task-space inverse dynamics (operational-space computed torque, with a null-space
    /// posture for a redundant arm): [`TaskSpaceInverseDynamics`].
    TaskSpace,
}

/// Settings of a position law beyond its name (`[position]`).
#[derive(Clone, Debug, PartialEq)]
pub struct PositionSettings {
    /// `pid-fl`, `pid-fl-central`: feed the reference's joint acceleration forward through
    /// the model, `tau = M (qdd_d + M_linear^-1 u) + c + g` (off in the thesis files).
    pub acceleration_feedforward: bool,
    /// `task-space`: natural frequency (rad/s) of each task direction's error dynamics;
    /// `computed-torque`: of each joint's. One value: the same for all.
    pub omega_rad_s: Option<Vec<f64>>,
    /// `task-space`: damping ratio of every task direction.
    pub damping_ratio: f64,
    /// `task-space`: natural frequency (rad/s) with which a redundant arm's self-motion
    /// follows the reference's joints in the null space.
    pub posture_omega_rad_s: f64,
    /// `task-space`: integral action on the task error (default on).
    pub integral: bool,
}

/// Default natural frequency of the task-space law, rad/s.
pub const TASK_SPACE_OMEGA: f64 = 30.0;
/// Default natural frequency of its null-space posture, rad/s.
pub const POSTURE_OMEGA: f64 = 10.0;

impl Default for PositionSettings {
    fn default() -> Self {
        Self {
            acceleration_feedforward: false,
            omega_rad_s: None,
            damping_ratio: 1.0,
            posture_omega_rad_s: POSTURE_OMEGA,
            integral: true,
        }
    }
}

/// The task-space law's gains from `[position]`: one natural frequency per task direction
/// (or one for all; default [`TASK_SPACE_OMEGA`]), critically damped at the stated damping
/// ratio, with the integral and the null-space posture as set. Also returns the frequencies.
///
/// # Errors
///
/// The message for `omega_rad_s` if its length is neither 1 nor the task's.
pub(crate) fn task_space_gains<const N: usize, R: RobotModel<N>>(
    settings: &PositionSettings,
) -> Result<(TaskSpaceGains, Vec<f64>), String> {
    let task = R::TASK;
    let omega: Vec<f64> = match settings.omega_rad_s.as_deref() {
        Some([w]) => vec![*w; task.len()],
        Some(w) if w.len() == task.len() => w.to_vec(),
        Some(w) => {
            return Err(format!(
                "omega_rad_s has {} values; the task of {} has {} directions ({}), or give one value for all",
                w.len(),
                R::NAME,
                task.len(),
                task.names().join(", ")
            ))
        }
        None => vec![TASK_SPACE_OMEGA; task.len()],
    };
    let gains = TaskSpaceGains::critically_damped::<N, R>(
        &omega,
        settings.damping_ratio,
        settings.posture_omega_rad_s,
        settings.integral,
    );
    Ok((gains, omega))
}

/// Natural frequency of the computed-torque reference design, rad/s.
pub const COMPUTED_TORQUE_OMEGA: f64 = 10.0;
/// Natural frequency of the LQR design's critically damped poles, rad/s (mean of -8.0..-8.7).
pub const LQR_OMEGA: f64 = 8.35;

impl PositionController {
    /// Every law a scenario can name (the thesis's line-up,
    /// `robots::scara::presets::THESIS_POSITION_LAWS`, and the task-space law).
    pub const NAMED: [Self; 7] = [
        Self::Pid,
        Self::PidFl,
        Self::FsfPlace,
        Self::FsfLqr,
        Self::PidFlCentral,
        Self::ComputedTorque,
        Self::TaskSpace,
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
            Self::TaskSpace => "task-space",
        }
    }

    /// Parses a command-line name.
    ///
    /// # Errors
    ///
    /// [`UnknownName`] listing the known names.
    pub fn parse(name: &str) -> Result<Self, UnknownName> {
        UnknownName::find(&Self::NAMED, Self::name, "controller", name)
    }

    /// The keys of `[position]` the law takes besides `law` (their meaning:
    /// [`PositionSettings`]).
    #[must_use]
    pub fn keys(self) -> &'static [&'static str] {
        match self {
            Self::PidFl | Self::PidFlCentral => &["acceleration_feedforward"],
            Self::ComputedTorque => &["omega_rad_s"],
            Self::TaskSpace => &[
                "omega_rad_s",
                "damping_ratio",
                "posture_omega_rad_s",
                "integral",
            ],
            Self::Pid | Self::FsfPlace | Self::FsfLqr => &[],
        }
    }

    /// The position loop as the typed PID with feedback linearization it is (`pid-fl`:
    /// `M_linear` the constant part of `M`; `pid-fl-central`: its constant diagonal), gains
    /// for poles -8, -9, -10 with the thesis's rounding; `None` for the other laws.
    ///
    /// # Errors
    ///
    /// A message if `M_linear` is singular (not for a physical robot).
    pub fn feedback_linearization<const N: usize, R: RobotModel<N>>(
        self,
        robot: R,
    ) -> Option<Result<PidFeedbackLinearization<N, R>, String>> {
        let kind = match self {
            Self::PidFl => SplitKind::ConstantPart,
            Self::PidFlCentral => SplitKind::ConstantDiagonal,
            _ => return None,
        };
        Some(
            PidFeedbackLinearization::with_poles(robot, kind, MassRounding::Thesis, PID_POLES)
                .ok_or_else(|| "M_linear is singular".to_string()),
        )
    }

    /// Builds the controller for `robot` with gains computed from its model (the
    /// description's, or an identified one) as the thesis does: masses rounded to three
    /// significant figures, as printed, for the PID designs; `settings` for the laws that
    /// have them.
    ///
    /// # Errors
    ///
    /// A message if a gain design fails (a singular `M_linear`, Riccati not converging) or a
    /// setting does not fit the robot.
    pub fn build_with<const N: usize, R: RobotModel<N> + Copy + 'static>(
        self,
        robot: R,
        settings: &PositionSettings,
    ) -> Result<(Box<dyn Controller<N>>, GainReport), String> {
        Ok(match self {
            Self::Pid => {
                let masses = MassRounding::Thesis
                    .apply(&robot.mass_matrix(&JointVector::zeros()).diagonal());
                let g = PidGains::from_poles(&masses, PID_POLES);
                let report = pid_report(
                    &g,
                    "poles -8, -9, -10 on diag M(q2 = 0), 3 significant figures (eq. 4.15)",
                );
                (Box::new(Pid::new(g)), report)
            }
            Self::PidFl | Self::PidFlCentral => {
                let c = self
                    .feedback_linearization(robot)
                    .ok_or("not a PID with feedback linearization")??
                    .with_acceleration_feedforward(settings.acceleration_feedforward);
                let note = match (self, settings.acceleration_feedforward) {
                    (Self::PidFl, false) => "poles -8, -9, -10 on diag M_linear (eq. 4.18, 4.22); qdd_cmd = M_linear^-1 u",
                    (Self::PidFl, true) => "poles -8, -9, -10 on diag M_linear (eq. 4.18, 4.22); qdd_cmd = qdd_d + M_linear^-1 u (acceleration feedforward)",
                    (_, false) => "poles -8, -9, -10 on diag M_linear = diag of eq. 4.38; qdd_cmd = M_linear^-1 u",
                    (_, true) => "poles -8, -9, -10 on diag M_linear = diag of eq. 4.38; qdd_cmd = qdd_d + M_linear^-1 u (acceleration feedforward)",
                };
                let report = pid_report(c.gains(), note);
                (Box::new(c), report)
            }
            Self::FsfPlace => {
                let poles = fsf_poles(N);
                let c = FullStateFeedback::place(robot, &poles).map_err(|e| e.to_string())?;
                let report = GainReport {
                    k1: Some(mat(c.k1())),
                    k2: Some(mat(c.k2())),
                    poles,
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
                    poles: vec![-LQR_OMEGA; 2 * N],
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
                let omega = match settings.omega_rad_s.as_deref() {
                    None => vec![COMPUTED_TORQUE_OMEGA; N],
                    Some([w]) => vec![*w; N],
                    Some(w) if w.len() == N => w.to_vec(),
                    Some(w) => {
                        return Err(format!(
                            "omega_rad_s has {} values; robot {} has {N} joints (or give one value for all)",
                            w.len(),
                            R::NAME
                        ))
                    }
                };
                let w = JointVector::<N>::from_fn(|i, _| omega[i]);
                let c = ComputedTorque::new(robot, w.component_mul(&w), w * 2.0);
                let report = GainReport {
                    kp: Some(arr(c.kp())),
                    kd: Some(arr(c.kd())),
                    poles: omega.iter().flat_map(|w| [-w, -w]).collect(),
                    note: "tau = M (qdd_d + Kp e + Kd e') + c + g, Kp in 1/s^2, Kd in 1/s".into(),
                    ..GainReport::default()
                };
                (Box::new(c), report)
            }
            Self::TaskSpace => {
                let task = R::TASK;
                let (gains, omega) = task_space_gains::<N, R>(settings)?;
                let c = TaskSpaceInverseDynamics::new(robot, gains);
                let rows: Vec<usize> = task.rows().collect();
                let report = GainReport {
                    kp: Some(rows.iter().map(|&r| gains.kp[r]).collect()),
                    ki: settings
                        .integral
                        .then(|| rows.iter().map(|&r| gains.ki[r]).collect()),
                    kd: Some(rows.iter().map(|&r| gains.kd[r]).collect()),
                    poles: omega.iter().map(|w| -w).collect(),
                    note: format!(
                        "task-space inverse dynamics in {}: F = Lambda (a_d + Kd e' + Kp e{} - Jdot qd), tau = J^T F + N^T M (Kp0 (q_d - q) + Kd0 (qd_d - qd)) + c + g; natural frequencies {:?} rad/s, damping ratio {}{}",
                        task.names().join(", "),
                        if settings.integral { " + Ki int(e)" } else { "" },
                        omega,
                        settings.damping_ratio,
                        if task.redundancy(N) > 0 {
                            format!(
                                ", the reference's joints (nearest the posture) held in the null space at {} rad/s",
                                settings.posture_omega_rad_s
                            )
                        } else {
                            String::new()
                        }
                    ),
                    ..GainReport::default()
                };
                (Box::new(c), report)
            }
        })
    }
}

/// The force gains `(Kfp, Kfi 1/s, Kvd N s/m)` a scenario's `:thesis` names: the thesis's PI
/// with feedforward and velocity damping (Section 5.3.2; the preset of
/// `robots::scara::thesis_setup::thesis_force_law`).
pub const THESIS_FORCE_GAINS: (f64, f64, f64) = (20.0, 5.0, 2000.0);

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
        UnknownName::find(&Self::NAMED, Self::name, "force controller", name)
    }

    /// The gains `(Kfp, Kfi 1/s, Kvd N s/m)` the vocabulary's `:thesis` names: the thesis's
    /// (Section 5.3; `THESIS_FORCE_GAINS`, without the damping for `pi-ff`; those of
    /// `pi-ff-vd` for the laws without them, where the hybrid law's gains are not used).
    #[must_use]
    pub fn thesis_gains(self) -> (f64, f64, f64) {
        let (kfp, kfi, kvd) = THESIS_FORCE_GAINS;
        match self {
            Self::PiFf => (kfp, kfi, 0.0),
            _ => (kfp, kfi, kvd),
        }
    }

    /// Whether it is one of the hybrid law's PI laws.
    #[must_use]
    pub fn is_pi(self) -> bool {
        matches!(self, Self::PiFf | Self::PiFfVd)
    }
}
