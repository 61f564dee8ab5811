//! The SCARA's own keys of a scenario's `[reference]`: what to do where the reference needs
//! the other elbow (`elbow_switch`), and the planned flip's settings (`max_effort_share`,
//! `clearance_z_m`, `pause_ramp_s`). The generic reader refuses them for other robots.

use crate::scenario::vocabulary::{number_in, string, KeyError};

/// The SCARA's own `[reference]` keys.
pub const REFERENCE_KEYS: [&str; 4] = [
    "elbow_switch",
    "max_effort_share",
    "clearance_z_m",
    "pause_ramp_s",
];

/// The keys of a planned or optimal flip.
const PLANNED_KEYS: [&str; 3] = ["max_effort_share", "clearance_z_m", "pause_ramp_s"];

/// What to do where a SCARA's reference needs the other elbow.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ElbowSwitchSpec {
    /// The thesis's (`elbow_switch = "step"`): the joint reference jumps to the other
    /// solution.
    Step,
    /// A planned flip (`"planned"`, the default, or `"optimal"`); each setting `None` for the
    /// default.
    Planned {
        /// Largest share of each actuator's effort limit for the planned moves.
        max_effort_share: Option<f64>,
        /// Lowest tool height during the swing, m.
        clearance_z_m: Option<f64>,
        /// Length of the reference's smooth stop and start, s.
        ramp_s: Option<f64>,
        /// Each move optimised (`elbow_switch = "optimal"`) instead of a quintic.
        optimal: bool,
    },
}

impl ElbowSwitchSpec {
    /// Reads the SCARA's `[reference]` keys `keys` (those of [`REFERENCE_KEYS`] a file gives).
    ///
    /// # Errors
    ///
    /// [`KeyError`] naming the key at fault: an unknown switch, a value out of range, or a
    /// planned flip's setting with `elbow_switch = "step"`.
    pub fn from_keys(keys: &toml::Table) -> Result<Self, KeyError> {
        match string(keys, "elbow_switch")?.unwrap_or("planned") {
            "step" => match PLANNED_KEYS.iter().find(|k| keys.contains_key(**k)) {
                Some(k) => Err(KeyError::new(
                    k,
                    "does not belong here: a key of elbow_switch = \"planned\" or \"optimal\"",
                )),
                None => Ok(Self::Step),
            },
            kind @ ("planned" | "optimal") => Ok(Self::Planned {
                optimal: kind == "optimal",
                max_effort_share: number_in(
                    keys,
                    "max_effort_share",
                    (0.0, 1.0, true),
                    "a share of the effort limits, > 0 and <= 1",
                )?,
                clearance_z_m: number_in(
                    keys,
                    "clearance_z_m",
                    (f64::NEG_INFINITY, f64::INFINITY, false),
                    "a height in m",
                )?,
                ramp_s: number_in(
                    keys,
                    "pause_ramp_s",
                    (0.0, 10.0, true),
                    "a time in s, > 0 and <= 10",
                )?,
            }),
            other => Err(KeyError::new(
                "elbow_switch",
                format!("unknown elbow switch `{other}`; known: planned, optimal, step"),
            )),
        }
    }
}
