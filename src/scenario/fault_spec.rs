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

use serde::Deserialize;

use super::check::Checker;
use super::error::ScenarioError;
use crate::sim::faults::{
    ActuatorFault, DelayFault, JitterFault, SensorFault, SensorFaultKind, Window, MAX_DELAY_STEPS,
    MAX_SENSOR_FAULTS,
};
use nalgebra::Vector3;

/// One `[[faults]]` entry as written.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FaultTable {
    /// The kind (see the module's table).
    pub kind: String,
    /// When it starts, s.
    pub start_s: f64,
    /// How long it lasts, s.
    pub duration_s: Option<f64>,
    /// A force, N.
    pub force_n: Option<f64>,
    /// Its direction.
    pub axis: Option<Vec<f64>>,
    /// Noise, N (1 sigma).
    pub std_n: Option<f64>,
    /// A seed.
    pub seed: Option<u64>,
    /// A surface's index.
    pub surface: Option<usize>,
    /// A stiffness factor.
    pub factor: Option<f64>,
    /// A torque share.
    pub scale: Option<f64>,
    /// Joints, 1-based.
    pub joints: Option<Vec<usize>>,
    /// A delay in control periods.
    pub periods: Option<usize>,
    /// A delay in plant steps.
    pub plant_steps: Option<usize>,
    /// Largest jitter, s.
    pub max_s: Option<f64>,
    /// A payload's mass, kg.
    pub mass_kg: Option<f64>,
}

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

/// The kinds and the keys each may have besides `kind` and `start_s`.
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
    let mut t = FaultTable {
        kind: kind.to_string(),
        start_s,
        duration_s: None,
        force_n: None,
        axis: None,
        std_n: None,
        seed: None,
        surface: None,
        factor: None,
        scale: None,
        joints: None,
        periods: None,
        plant_steps: None,
        max_s: None,
        mass_kg: None,
    };
    let allowed = KINDS
        .iter()
        .find(|(k, _)| *k == kind)
        .map_or(&[][..], |(_, a)| *a);
    if allowed.contains(&"duration_s") {
        t.duration_s = duration_s;
    }
    match (size_key(kind), size) {
        (Some("force_n"), Some(x)) => t.force_n = Some(x),
        (Some("std_n"), Some(x)) => t.std_n = Some(x),
        (Some("factor"), Some(x)) => t.factor = Some(x),
        (Some("scale"), Some(x)) => t.scale = Some(x),
        (Some("periods"), Some(x)) => t.periods = Some(x.round().max(0.0) as usize),
        (Some("max_s"), Some(x)) => t.max_s = Some(x),
        (Some("mass_kg"), Some(x)) => t.mass_kg = Some(x),
        _ => {}
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
    tables: &[FaultTable],
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

#[allow(clippy::too_many_lines)]
fn fault(
    c: &Checker<'_>,
    at: &str,
    t: &FaultTable,
    dof: usize,
    surfaces: usize,
    control_dt: f64,
    plant_dt: f64,
) -> Result<FaultSpec, ScenarioError> {
    let key = |k: &str| format!("{at}.{k}");
    let Some((_, allowed)) = KINDS.iter().find(|(k, _)| *k == t.kind) else {
        let known = KIND_NAMES;
        return Err(c.err(
            &key("kind"),
            format!("unknown fault `{}`; known: {}", t.kind, known.join(", ")),
        ));
    };
    for (k, present) in [
        ("duration_s", t.duration_s.is_some()),
        ("force_n", t.force_n.is_some()),
        ("axis", t.axis.is_some()),
        ("std_n", t.std_n.is_some()),
        ("seed", t.seed.is_some()),
        ("surface", t.surface.is_some()),
        ("factor", t.factor.is_some()),
        ("scale", t.scale.is_some()),
        ("joints", t.joints.is_some()),
        ("periods", t.periods.is_some()),
        ("plant_steps", t.plant_steps.is_some()),
        ("max_s", t.max_s.is_some()),
        ("mass_kg", t.mass_kg.is_some()),
    ] {
        c.forbid(
            &key(k),
            present && !allowed.contains(&k),
            &format!("a fault of kind `{}` takes {}", t.kind, allowed.join(", ")),
        )?;
    }
    let start_s = c.range(
        &key("start_s"),
        t.start_s,
        0.0,
        1e5,
        false,
        "a time in s, >= 0",
    )?;
    let duration = |default: Option<f64>| -> Result<f64, ScenarioError> {
        match (t.duration_s, default) {
            (Some(d), _) => c.range(&key("duration_s"), d, 0.0, 1e5, true, "a time in s, > 0"),
            (None, Some(d)) => Ok(d),
            (None, None) => Err(c.err(
                &key("duration_s"),
                format!(
                    "is missing: a fault of kind `{}` lasts a stated time",
                    t.kind
                ),
            )),
        }
    };
    let window = |duration_s| Window {
        start_s,
        duration_s,
    };
    let force = || -> Result<(f64, Vector3<f64>), ScenarioError> {
        let f = c.need(&key("force_n"), &t.force_n, "the fault's force, N")?;
        let f = c.range(&key("force_n"), f, -1e6, 1e6, false, "a force in N")?;
        let axis = t
            .axis
            .as_ref()
            .map_or(Ok(Vector3::z()), |a| c.unit(&key("axis"), a))?;
        Ok((f, axis))
    };
    let surface = || -> Result<usize, ScenarioError> {
        let s = t.surface.unwrap_or(0);
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
    match t.kind.as_str() {
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
            let std_n = c.need(&key("std_n"), &t.std_n, "the noise, N (1 sigma)")?;
            let std_n = c.range(&key("std_n"), std_n, 0.0, 1e5, false, "N, >= 0")?;
            sensor(
                SensorFaultKind::NoiseBurst {
                    std_n,
                    seed: t.seed.unwrap_or(0),
                },
                duration(None)?,
            )
        }
        "surface-ends" => Ok(FaultSpec::SurfaceEnds {
            surface: surface()?,
            start_s,
        }),
        "stiffness-step" => {
            let f = c.need(&key("factor"), &t.factor, "the stiffness factor")?;
            Ok(FaultSpec::StiffnessStep {
                surface: surface()?,
                start_s,
                factor: c.range(&key("factor"), f, 0.0, 1e4, true, "a factor, > 0")?,
            })
        }
        "actuator" => {
            let s = c.need(&key("scale"), &t.scale, "the share of the torque delivered")?;
            let scale = c.range(&key("scale"), s, 0.0, 1.0, false, "a share in [0, 1]")?;
            let mut joints = 0u32;
            match &t.joints {
                None => joints = (1u32 << dof) - 1,
                Some(list) => {
                    for j in list {
                        if *j < 1 || *j > dof {
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
            let steps = match (t.periods, t.plant_steps) {
                (Some(p), None) => p * substeps,
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
            let m = c.need(&key("max_s"), &t.max_s, "the largest offset, s")?;
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
                seed: t.seed.unwrap_or(0),
            }))
        }
        "payload-drop" => {
            let m = c.need(&key("mass_kg"), &t.mass_kg, "the payload's mass, kg")?;
            Ok(FaultSpec::PayloadDrop {
                mass_kg: c.range(&key("mass_kg"), m, 0.0, 1e4, true, "kg, > 0")?,
                start_s,
            })
        }
        other => Err(c.err(&key("kind"), format!("unknown fault `{other}`"))),
    }
}
