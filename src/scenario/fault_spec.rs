//! `[[faults]]`: what goes wrong in a run, as written and as checked.
//!
//! ```toml
//! [[faults]]
//! kind = "dropout"      # no new sensor reading
//! start_s = 3.0
//! duration_s = 0.05
//! ```
//!
//! Kinds and their keys (`start_s` always; times in s, forces in N):
//!
//! | kind | keys |
//! | --- | --- |
//! | `dropout`, `frozen`, `noise-burst` | `duration_s`; `noise-burst`: `std_n`, `seed` |
//! | `nan`, `infinite` | `duration_s` (default one control period) |
//! | `out-of-range` | `force_n`, `axis` (default `[0, 0, 1]`, the sensor's axes), `duration_s` (one period) |
//! | `spike` | `force_n`, `axis` (one control period) |
//! | `bias-jump` | `force_n`, `axis`, `duration_s` (default: to the end) |
//! | `surface-ends` | `surface` (default 0): an edge across it where the reference is at `start_s`, square to its motion |
//! | `stiffness-step` | `surface`, `factor` |
//! | `actuator` | `scale` (in `[0, 1]`), `joints` (1-based, default all), `duration_s` (default: to the end) |
//! | `delay` | `periods` or `plant_steps`, `duration_s` |
//! | `jitter` | `max_s` (less than half the control period; resolved to the plant step), `seed` |
//! | `payload-drop` | `mass_kg`: held by the tool from the start, dropped at `start_s` |

use toml::{Table, Value};

use super::check::Checker;
use super::error::ScenarioError;
use super::toml_table::{key_list, TomlTable};
use crate::sim::faults::{
    ActuatorFault, DelayFault, JitterFault, SensorFault, SensorFaultKind, Window, MAX_DELAY_STEPS,
    MAX_SENSOR_FAULTS,
};
use nalgebra::Vector3;

/// One checked fault.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FaultSpec {
    /// Of the sensor's readings.
    Sensor(SensorFault),
    /// An edge across `surface` where the reference is at `start_s`.
    SurfaceEnds {
        /// Index.
        surface: usize,
        /// s.
        start_s: f64,
    },
    /// `surface`'s stiffness times `factor` from `start_s` on.
    StiffnessStep {
        /// Index.
        surface: usize,
        /// s.
        start_s: f64,
        /// Factor.
        factor: f64,
    },
    /// A weak actuator.
    Actuator(ActuatorFault),
    /// Delayed torques.
    Delay(DelayFault),
    /// Sampling jitter (from the start).
    Jitter(JitterFault),
    /// A payload dropped at `start_s`.
    PayloadDrop {
        /// kg.
        mass_kg: f64,
        /// s.
        start_s: f64,
    },
}

impl FaultSpec {
    /// When it starts acting, s.
    #[must_use]
    pub fn start_s(&self) -> f64 {
        match self {
            Self::Sensor(f) => f.window.start_s,
            Self::SurfaceEnds { start_s, .. }
            | Self::StiffnessStep { start_s, .. }
            | Self::PayloadDrop { start_s, .. } => *start_s,
            Self::Actuator(a) => a.window.start_s,
            Self::Delay(d) => d.window.start_s,
            Self::Jitter(_) => 0.0,
        }
    }

    /// Its kind's name, as in the file.
    #[must_use]
    pub fn kind(&self) -> &'static str {
        match self {
            Self::Sensor(f) => match f.kind {
                SensorFaultKind::Dropout => "dropout",
                SensorFaultKind::Frozen => "frozen",
                SensorFaultKind::Nan => "nan",
                SensorFaultKind::Infinite => "infinite",
                SensorFaultKind::OutOfRange { .. } => "out-of-range",
                SensorFaultKind::Spike { .. } => "spike",
                SensorFaultKind::BiasJump { .. } => "bias-jump",
                SensorFaultKind::NoiseBurst { .. } => "noise-burst",
            },
            Self::SurfaceEnds { .. } => "surface-ends",
            Self::StiffnessStep { .. } => "stiffness-step",
            Self::Actuator(_) => "actuator",
            Self::Delay(_) => "delay",
            Self::Jitter(_) => "jitter",
            Self::PayloadDrop { .. } => "payload-drop",
        }
    }
}

/// The kinds and the keys each may have besides `kind` and `start_s`: the one list of a kind's
/// keys (any other key of its table is refused, naming these).
const KINDS: [(&str, &[&str]); 14] = [
    ("dropout", &["duration_s"]),
    ("frozen", &["duration_s"]),
    ("nan", &["duration_s"]),
    ("infinite", &["duration_s"]),
    ("out-of-range", &["duration_s", "force_n", "axis"]),
    ("spike", &["force_n", "axis"]),
    ("bias-jump", &["duration_s", "force_n", "axis"]),
    ("noise-burst", &["duration_s", "std_n", "seed"]),
    ("surface-ends", &["surface"]),
    ("stiffness-step", &["surface", "factor"]),
    ("actuator", &["duration_s", "scale", "joints"]),
    ("delay", &["duration_s", "periods", "plant_steps"]),
    ("jitter", &["max_s", "seed"]),
    ("payload-drop", &["mass_kg"]),
];

/// The kinds' names (from the table of their keys, in its order).
pub const KIND_NAMES: [&str; KINDS.len()] = {
    let mut names = [""; KINDS.len()];
    let mut i = 0;
    while i < KINDS.len() {
        names[i] = KINDS[i].0;
        i += 1;
    }
    names
};

/// The key a kind's drawn size goes to (`None`: it has none).
#[must_use]
pub fn size_key(kind: &str) -> Option<&'static str> {
    match kind {
        "out-of-range" | "spike" | "bias-jump" => Some("force_n"),
        "noise-burst" => Some("std_n"),
        "stiffness-step" => Some("factor"),
        "actuator" => Some("scale"),
        "delay" => Some("periods"),
        "jitter" => Some("max_s"),
        "payload-drop" => Some("mass_kg"),
        _ => None,
    }
}

/// A fault of `kind` drawn by a sweep for `scenario`: from `start_s`, of `size` (the kind's
/// size key) and `duration_s` where the kind takes them, checked as a `[[faults]]` entry.
///
/// # Errors
///
/// [`ScenarioError`] naming `sweep.fault_kinds` and the rule the drawn fault breaks.
pub fn drawn(
    scenario: &super::Scenario,
    kind: &str,
    start_s: f64,
    size: Option<f64>,
    duration_s: Option<f64>,
) -> Result<FaultSpec, ScenarioError> {
    let mut t = Table::new();
    t.insert("kind".into(), Value::String(kind.into()));
    t.insert("start_s".into(), Value::Float(start_s));
    if let Some(d) = duration_s.filter(|_| keys_of(kind).contains(&"duration_s")) {
        t.insert("duration_s".into(), Value::Float(d));
    }
    if let (Some(key), Some(x)) = (size_key(kind), size) {
        let value = if key == "periods" {
            Value::Integer(x.round().max(0.0) as i64)
        } else {
            Value::Float(x)
        };
        t.insert(key.into(), value);
    }
    let c = Checker {
        file: &scenario.file,
        source: &scenario.source,
    };
    fault(
        &c,
        "sweep.fault",
        &t,
        scenario.dof,
        scenario.surfaces.len(),
        scenario.control_dt_s,
        scenario.plant_dt_s,
    )
}

/// Checks the `[[faults]]` of a scenario of `dof` joints, `surfaces` surfaces, control
/// period `control_dt` and plant step `plant_dt` (s).
///
/// # Errors
///
/// [`ScenarioError`] naming `faults[i].key`.
pub(super) fn faults(
    c: &Checker<'_>,
    tables: &[Table],
    dof: usize,
    surfaces: usize,
    control_dt: f64,
    plant_dt: f64,
) -> Result<Vec<FaultSpec>, ScenarioError> {
    let mut out = Vec::new();
    for (i, t) in tables.iter().enumerate() {
        out.push(fault(
            c,
            &format!("faults[{i}]"),
            t,
            dof,
            surfaces,
            control_dt,
            plant_dt,
        )?);
    }
    let sensor = out
        .iter()
        .filter(|f| matches!(f, FaultSpec::Sensor(_)))
        .count();
    if sensor > MAX_SENSOR_FAULTS {
        return Err(c.err(
            "faults",
            format!("{sensor} sensor faults; at most {MAX_SENSOR_FAULTS}"),
        ));
    }
    for kind in [
        "surface-ends",
        "stiffness-step",
        "actuator",
        "delay",
        "jitter",
        "payload-drop",
    ] {
        let n = out.iter().filter(|f| f.kind() == kind).count();
        if n > 1 {
            return Err(c.err(
                "faults",
                format!("{n} faults of kind `{kind}`; at most one"),
            ));
        }
    }
    Ok(out)
}

/// The keys of fault `kind` besides `kind` and `start_s` (none for an unknown kind).
fn keys_of(kind: &str) -> &'static [&'static str] {
    KINDS
        .iter()
        .find(|(k, _)| *k == kind)
        .map_or(&[], |(_, keys)| *keys)
}

#[allow(clippy::too_many_lines)]
fn fault(
    c: &Checker<'_>,
    at: &str,
    table: &Table,
    dof: usize,
    surfaces: usize,
    control_dt: f64,
    plant_dt: f64,
) -> Result<FaultSpec, ScenarioError> {
    let t = TomlTable { c, at, table };
    let key = |k: &str| t.path(k);
    let kind = t.tag(
        "kind",
        &format!("the fault, one of {}", KIND_NAMES.join(", ")),
    )?;
    if !KIND_NAMES.contains(&kind) {
        return Err(t.err(
            "kind",
            format!("unknown fault `{kind}`; known: {}", KIND_NAMES.join(", ")),
        ));
    }
    let allowed = [&["start_s"], keys_of(kind)].concat();
    if let Some(k) = t.other_key("kind", &allowed) {
        let takes = format!("a fault of kind `{kind}` takes {}", key_list(&allowed));
        return Err(if KINDS.iter().any(|(_, keys)| keys.contains(&k)) {
            t.err(k, format!("does not belong here: {takes}"))
        } else {
            t.err(k, format!("unknown field `{k}`: {takes}"))
        });
    }
    let number = |k: &str| t.optional_number(k);
    // A whole number at `k` as an index or a count (a larger one than the machine's is refused
    // by the range checks below as the largest).
    let count = |k: &str| -> Result<Option<usize>, ScenarioError> {
        Ok(t.optional_count(k)?
            .map(|n| usize::try_from(n).unwrap_or(usize::MAX)))
    };
    let start_s = c.need(
        &key("start_s"),
        &number("start_s")?,
        "when the fault starts, s",
    )?;
    let start_s = c.range(
        &key("start_s"),
        start_s,
        0.0,
        1e5,
        false,
        "a time in s, >= 0",
    )?;
    let duration = |default: Option<f64>| -> Result<f64, ScenarioError> {
        match (number("duration_s")?, default) {
            (Some(d), _) => c.range(&key("duration_s"), d, 0.0, 1e5, true, "a time in s, > 0"),
            (None, Some(d)) => Ok(d),
            (None, None) => Err(c.err(
                &key("duration_s"),
                format!("is missing: a fault of kind `{kind}` lasts a stated time"),
            )),
        }
    };
    let window = |duration_s| Window {
        start_s,
        duration_s,
    };
    let force = || -> Result<(f64, Vector3<f64>), ScenarioError> {
        let f = c.need(&key("force_n"), &number("force_n")?, "the fault's force, N")?;
        let f = c.range(&key("force_n"), f, -1e6, 1e6, false, "a force in N")?;
        let axis = t
            .optional_numbers("axis")?
            .map_or(Ok(Vector3::z()), |a| c.unit(&key("axis"), &a))?;
        Ok((f, axis))
    };
    let surface = || -> Result<usize, ScenarioError> {
        let s = count("surface")?.unwrap_or(0);
        if s >= surfaces {
            return Err(c.err(
                &key("surface"),
                format!("is {s}; the scenario has {surfaces} surfaces"),
            ));
        }
        Ok(s)
    };
    let sensor = |kind, duration_s| {
        Ok(FaultSpec::Sensor(SensorFault {
            kind,
            window: window(duration_s),
        }))
    };
    match kind {
        "dropout" => sensor(SensorFaultKind::Dropout, duration(None)?),
        "frozen" => sensor(SensorFaultKind::Frozen, duration(None)?),
        "nan" => sensor(SensorFaultKind::Nan, duration(Some(control_dt))?),
        "infinite" => sensor(SensorFaultKind::Infinite, duration(Some(control_dt))?),
        "out-of-range" => {
            let (force_n, axis) = force()?;
            sensor(
                SensorFaultKind::OutOfRange { force_n, axis },
                duration(Some(control_dt))?,
            )
        }
        "spike" => {
            let (force_n, axis) = force()?;
            sensor(SensorFaultKind::Spike { force_n, axis }, control_dt)
        }
        "bias-jump" => {
            let (force_n, axis) = force()?;
            sensor(
                SensorFaultKind::BiasJump { force_n, axis },
                duration(Some(f64::INFINITY))?,
            )
        }
        "noise-burst" => {
            let std_n = c.need(&key("std_n"), &number("std_n")?, "the noise, N (1 sigma)")?;
            let std_n = c.range(&key("std_n"), std_n, 0.0, 1e5, false, "N, >= 0")?;
            sensor(
                SensorFaultKind::NoiseBurst {
                    std_n,
                    seed: t.optional_count("seed")?.unwrap_or(0),
                },
                duration(None)?,
            )
        }
        "surface-ends" => Ok(FaultSpec::SurfaceEnds {
            surface: surface()?,
            start_s,
        }),
        "stiffness-step" => {
            let f = c.need(&key("factor"), &number("factor")?, "the stiffness factor")?;
            Ok(FaultSpec::StiffnessStep {
                surface: surface()?,
                start_s,
                factor: c.range(&key("factor"), f, 0.0, 1e4, true, "a factor, > 0")?,
            })
        }
        "actuator" => {
            let s = c.need(
                &key("scale"),
                &number("scale")?,
                "the share of the torque delivered",
            )?;
            let scale = c.range(&key("scale"), s, 0.0, 1.0, false, "a share in [0, 1]")?;
            let mut joints = 0u32;
            match t.optional_counts("joints")? {
                None => joints = (1u32 << dof) - 1,
                Some(list) => {
                    for j in list {
                        if j < 1 || j > dof as u64 {
                            return Err(c.err(
                                &key("joints"),
                                format!("joint {j} is not one of 1 to {dof}"),
                            ));
                        }
                        joints |= 1 << (j - 1);
                    }
                }
            }
            Ok(FaultSpec::Actuator(ActuatorFault {
                window: window(duration(Some(f64::INFINITY))?),
                scale,
                joints,
            }))
        }
        "delay" => {
            let substeps = (control_dt / plant_dt).round() as usize;
            let steps = match (count("periods")?, count("plant_steps")?) {
                (Some(p), None) => p.saturating_mul(substeps),
                (None, Some(s)) => s,
                _ => return Err(c.err(&key("periods"), "give either periods or plant_steps")),
            };
            if steps == 0 || steps > MAX_DELAY_STEPS {
                return Err(c.err(
                    &key("periods"),
                    format!("a delay of {steps} plant steps; 1 to {MAX_DELAY_STEPS}"),
                ));
            }
            Ok(FaultSpec::Delay(DelayFault {
                window: window(duration(None)?),
                plant_steps: steps,
            }))
        }
        "jitter" => {
            let m = c.need(&key("max_s"), &number("max_s")?, "the largest offset, s")?;
            let max_s = c.range(
                &key("max_s"),
                m,
                0.0,
                0.5 * control_dt,
                true,
                "s, > 0 and below half the control period",
            )?;
            if max_s < 0.5 * plant_dt {
                return Err(c.err(&key("max_s"), format!("{max_s} s is below half the plant step ({plant_dt} s): it would round to nothing; use a smaller plant_dt_s")));
            }
            Ok(FaultSpec::Jitter(JitterFault {
                max_s,
                seed: t.optional_count("seed")?.unwrap_or(0),
            }))
        }
        "payload-drop" => {
            let m = c.need(
                &key("mass_kg"),
                &number("mass_kg")?,
                "the payload's mass, kg",
            )?;
            Ok(FaultSpec::PayloadDrop {
                mass_kg: c.range(&key("mass_kg"), m, 0.0, 1e4, true, "kg, > 0")?,
                start_s,
            })
        }
        other => Err(c.err(&key("kind"), format!("unknown fault `{other}`"))),
    }
}
