//! `[safety]`: the supervisor every run's controller runs inside, as written and as checked.
//!
//! Every key is optional; the defaults (see [`SafetySpec`]) never trip on the shipped
//! nominal scenarios (`tests/scenario/faults.rs` runs them all). A limit of `0` turns the
//! checks that have an "off" (`frozen_s`, `spike_filter_n`, `oscillation_rms_n`,
//! `contact_loss_fraction`) off.

use serde::Deserialize;

use super::check::{numbers, Checker};
use super::error::ScenarioError;
use crate::control::safety::limits::defaults;
use crate::control::safety::Reaction;
use nalgebra::Vector3;

/// `[safety]` as written.
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SafetyTable {
    /// Run the controller inside the supervisor (default true).
    pub enabled: Option<bool>,
    /// `"hold"` (default), `"retract"` or `"compliant"`.
    pub reaction: Option<String>,
    /// Hold and retract: natural frequency of the joint tracking, rad/s (default 30).
    pub hold_omega_rad_s: Option<f64>,
    /// Retract: speed, m/s (default 0.05).
    pub retract_speed_m_s: Option<f64>,
    /// Retract: distance, m (default 0.05).
    pub retract_distance_m: Option<f64>,
    /// Compliant: translational stiffness, N/m (default 200).
    pub compliant_stiffness_n_m: Option<f64>,
    /// Largest measured force, N (default `max(3 |f_d|, |f_d| + 150 N)`, `|f_d|` the force
    /// reference's largest value; 300 N without force control).
    pub max_force_n: Option<f64>,
    /// Largest force rate over 10 ms, N/s (default 100 000).
    pub max_force_rate_n_s: Option<f64>,
    /// Sensor range per force axis, N (default 2500).
    pub sensor_range_n: Option<f64>,
    /// Sensor range per torque axis, N m (default 250).
    pub sensor_range_nm: Option<f64>,
    /// Stale after, s (default 0.02).
    pub stale_s: Option<f64>,
    /// Frozen after, s (default 0.02 for a sensor with noise; off, 0, for a noise-free one).
    pub frozen_s: Option<f64>,
    /// Spike filter threshold, N (default 200; 0: off).
    pub spike_filter_n: Option<f64>,
    /// Oscillation: largest RMS of the high-passed force error, N (default
    /// `max(5 N, 0.2 |f_d|) + 3 noise`; 0: off).
    pub oscillation_rms_n: Option<f64>,
    /// Oscillation: the high-pass corner, Hz (default 5).
    pub oscillation_hz: Option<f64>,
    /// Contact lost below this share of the force reference (default 0.2; 0: off).
    pub contact_loss_fraction: Option<f64>,
    /// Contact lost after, s (default 0.002).
    pub contact_loss_s: Option<f64>,
    /// Largest tool speed, m/s (default: not checked; a description carries no speed limits).
    pub max_tool_speed_m_s: Option<f64>,
    /// The workspace box's lower corner, m (default: the reference's box less the margin).
    pub workspace_min_m: Option<Vec<f64>>,
    /// Its upper corner, m.
    pub workspace_max_m: Option<Vec<f64>>,
    /// Margin of the default box around the reference and the start, m (default 0.75: the
    /// SCARA's planned elbow flip in `three-zone.toml` swings the tool 0.51 m outside the
    /// reference's box).
    pub workspace_margin_m: Option<f64>,
    /// Closest approach to a joint limit, one per joint, rad or m (negative: past it; default
    /// -0.001, just into the end stop, for a plant with end stops whose run starts inside
    /// the limits; else not checked).
    pub joint_margin: Option<Vec<f64>>,
    /// Largest joint speed, one per joint, rad/s or m/s (default: not checked).
    pub max_joint_speed: Option<Vec<f64>>,
    /// Largest rate of the applied torque, one per joint, N m/s or N/s (default: not
    /// limited; the shipped SCARA trials swing their 1000 N m actuators by up to 1800 N m in
    /// one period).
    pub max_torque_rate: Option<Vec<f64>>,
}

/// `[safety]` checked; the values the scenario derives are `None` here and filled in by the
/// run's preparation (`stages::safety`).
#[derive(Clone, Debug, PartialEq)]
pub struct SafetySpec {
    /// Whether the supervisor runs.
    pub enabled: bool,
    /// The reaction.
    pub reaction: Reaction<f64>,
    /// Largest force, N (`None`: derived).
    pub max_force_n: Option<f64>,
    /// Largest force rate, N/s.
    pub max_force_rate_n_s: f64,
    /// Sensor ranges, N and N m.
    pub sensor_range: (f64, f64),
    /// Stale after, s.
    pub stale_s: f64,
    /// Frozen after, s (`None`: derived; `Some(None)`: off).
    pub frozen_s: Option<Option<f64>>,
    /// Spike filter, N (`None`: off).
    pub spike_filter_n: Option<f64>,
    /// Oscillation RMS, N (`None`: derived; `Some(None)`: off).
    pub oscillation_rms_n: Option<Option<f64>>,
    /// Oscillation corner, Hz.
    pub oscillation_hz: f64,
    /// Contact loss share (`None`: off) and time, s.
    pub contact_loss: (Option<f64>, f64),
    /// Largest tool speed, m/s (`None`: not checked).
    pub max_tool_speed_m_s: Option<f64>,
    /// The box (`None`: derived from the reference with `workspace_margin_m`).
    pub workspace: Option<(Vector3<f64>, Vector3<f64>)>,
    /// Margin of the derived box, m.
    pub workspace_margin_m: f64,
    /// Per joint (`None`: the defaults).
    pub joint_margin: Option<Vec<f64>>,
    /// Per joint.
    pub max_joint_speed: Option<Vec<f64>>,
    /// Per joint.
    pub max_torque_rate: Option<Vec<f64>>,
}

impl Default for SafetySpec {
    fn default() -> Self {
        Self {
            enabled: true,
            reaction: Reaction::hold(),
            max_force_n: None,
            max_force_rate_n_s: defaults::MAX_FORCE_RATE_N_S,
            sensor_range: (defaults::SENSOR_RANGE_N, defaults::SENSOR_RANGE_NM),
            stale_s: defaults::STALE_S,
            frozen_s: None,
            spike_filter_n: Some(defaults::SPIKE_N),
            oscillation_rms_n: None,
            oscillation_hz: defaults::OSCILLATION_HZ,
            contact_loss: (Some(defaults::LOSS_FRACTION), defaults::LOSS_S),
            max_tool_speed_m_s: None,
            workspace: None,
            workspace_margin_m: DEFAULT_WORKSPACE_MARGIN_M,
            joint_margin: None,
            max_joint_speed: None,
            max_torque_rate: None,
        }
    }
}

/// Default margin of the workspace box around the reference, m.
pub const DEFAULT_WORKSPACE_MARGIN_M: f64 = 0.75;

/// Each value of `[safety] reaction`, with the keys that only it takes.
const REACTIONS: [(&str, &[&str]); 3] = [
    ("hold", &[]),
    ("retract", &["retract_speed_m_s", "retract_distance_m"]),
    ("compliant", &["compliant_stiffness_n_m"]),
];

/// Checks `[safety]` (`t` as read, `table` as the file has it; absent: the defaults) for a
/// robot of `dof` joints.
///
/// # Errors
///
/// [`ScenarioError`] naming the key.
pub(super) fn safety(
    c: &Checker<'_>,
    t: Option<&SafetyTable>,
    table: Option<&toml::Table>,
    dof: usize,
) -> Result<SafetySpec, ScenarioError> {
    let d = SafetySpec::default();
    let Some(t) = t else { return Ok(d) };
    let pos = |key: &str, v: Option<f64>, default: f64, what: &str| {
        v.map_or(Ok(default), |x| {
            c.range(&format!("safety.{key}"), x, 0.0, 1e9, true, what)
        })
    };
    let off = |key: &str, v: Option<f64>, what: &str| {
        v.map(|x| {
            c.range(&format!("safety.{key}"), x, 0.0, 1e9, false, what)
                .map(|x| (x > 0.0).then_some(x))
        })
        .transpose()
    };
    let omega = pos("hold_omega_rad_s", t.hold_omega_rad_s, 30.0, "rad/s, > 0")?;
    let reaction = match t.reaction.as_deref() {
        None | Some("hold") => Reaction::Hold { omega_rad_s: omega },
        Some("retract") => Reaction::Retract {
            omega_rad_s: omega,
            speed_m_s: pos("retract_speed_m_s", t.retract_speed_m_s, 0.05, "m/s, > 0")?,
            distance_m: pos("retract_distance_m", t.retract_distance_m, 0.05, "m, > 0")?,
        },
        Some("compliant") => Reaction::Compliant {
            stiffness_n_m: t.compliant_stiffness_n_m.map_or(Ok(200.0), |x| {
                c.range(
                    "safety.compliant_stiffness_n_m",
                    x,
                    0.0,
                    1e9,
                    false,
                    "N/m, >= 0",
                )
            })?,
            damping_rad_s: 5.0,
        },
        Some(other) => {
            return Err(c.err(
                "safety.reaction",
                format!(
                    "unknown reaction `{other}`; known: {}",
                    REACTIONS.map(|(name, _)| name).join(", ")
                ),
            ))
        }
    };
    let reaction_name = reaction.name();
    for key in table.into_iter().flat_map(toml::Table::keys) {
        let other = REACTIONS
            .iter()
            .find(|(name, keys)| *name != reaction_name && keys.contains(&key.as_str()));
        if let Some((which, _)) = other {
            c.forbid(
                &format!("safety.{key}"),
                true,
                &format!("a key of reaction = \"{which}\""),
            )?;
        }
    }
    let workspace = match (&t.workspace_min_m, &t.workspace_max_m) {
        (None, None) => None,
        (Some(lo), Some(hi)) => {
            let lo = c.vec3("safety.workspace_min_m", lo)?;
            let hi = c.vec3("safety.workspace_max_m", hi)?;
            if (0..3).any(|i| lo[i] >= hi[i]) {
                return Err(c.err(
                    "safety.workspace_max_m",
                    "must be above workspace_min_m on every axis",
                ));
            }
            Some((lo, hi))
        }
        (Some(_), None) => return Err(c.err("safety.workspace_min_m", "needs workspace_max_m too")),
        (None, Some(_)) => return Err(c.err("safety.workspace_max_m", "needs workspace_min_m too")),
    };
    let joints = |key: &str, v: Option<&Vec<f64>>, ok: fn(f64) -> bool, what: &str| {
        v.map(|v| numbers(c, &format!("safety.{key}"), Some(v), dof, 0.0, ok, what))
            .transpose()
    };
    Ok(SafetySpec {
        enabled: t.enabled.unwrap_or(true),
        reaction,
        max_force_n: t
            .max_force_n
            .map(|x| c.range("safety.max_force_n", x, 0.0, 1e6, true, "N, > 0"))
            .transpose()?,
        max_force_rate_n_s: pos(
            "max_force_rate_n_s",
            t.max_force_rate_n_s,
            d.max_force_rate_n_s,
            "N/s, > 0",
        )?,
        sensor_range: (
            pos(
                "sensor_range_n",
                t.sensor_range_n,
                d.sensor_range.0,
                "N, > 0",
            )?,
            pos(
                "sensor_range_nm",
                t.sensor_range_nm,
                d.sensor_range.1,
                "N m, > 0",
            )?,
        ),
        stale_s: pos("stale_s", t.stale_s, d.stale_s, "s, > 0")?,
        frozen_s: off("frozen_s", t.frozen_s, "s, >= 0 (0: off)")?,
        spike_filter_n: match off("spike_filter_n", t.spike_filter_n, "N, >= 0 (0: off)")? {
            None => d.spike_filter_n,
            Some(v) => v,
        },
        oscillation_rms_n: off("oscillation_rms_n", t.oscillation_rms_n, "N, >= 0 (0: off)")?,
        oscillation_hz: pos(
            "oscillation_hz",
            t.oscillation_hz,
            d.oscillation_hz,
            "Hz, > 0",
        )?,
        contact_loss: (
            match off(
                "contact_loss_fraction",
                t.contact_loss_fraction,
                "a share, >= 0 (0: off)",
            )? {
                None => d.contact_loss.0,
                Some(v) => v,
            },
            pos(
                "contact_loss_s",
                t.contact_loss_s,
                d.contact_loss.1,
                "s, > 0",
            )?,
        ),
        max_tool_speed_m_s: t
            .max_tool_speed_m_s
            .map(|x| c.range("safety.max_tool_speed_m_s", x, 0.0, 1e6, true, "m/s, > 0"))
            .transpose()?,
        workspace,
        workspace_margin_m: t.workspace_margin_m.map_or(Ok(d.workspace_margin_m), |x| {
            c.range("safety.workspace_margin_m", x, 0.0, 1e3, false, "m, >= 0")
        })?,
        joint_margin: joints(
            "joint_margin",
            t.joint_margin.as_ref(),
            |x| x >= -0.1,
            "rad or m, >= -0.1 (negative: past the limit, into an end stop)",
        )?,
        max_joint_speed: joints(
            "max_joint_speed",
            t.max_joint_speed.as_ref(),
            |x| x > 0.0,
            "rad/s or m/s, > 0",
        )?,
        max_torque_rate: joints(
            "max_torque_rate",
            t.max_torque_rate.as_ref(),
            |x| x > 0.0,
            "N m/s or N/s, > 0",
        )?,
    })
}
