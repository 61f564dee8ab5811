//! The `[sweep]` table of a scenario: which quantities vary and how they are distributed.
//!
//! ```toml
//! [sweep]
//! link_mass_scale = { uniform = [0.8, 1.2] }   # drawn per link
//! payload_kg = { uniform = [0.0, 2.0] }
//! sensor_bias_n = { normal = [0.0, 2.0] }       # [mean, standard deviation]
//! fault_kinds = ["nan", "dropout", "spike"]       # one fault per trial, its kind drawn
//! fault_start_s = { uniform = [3.0, 8.0] }        # when
//! fault_size = { uniform = [500.0, 3000.0] }      # how large (see `fault_kinds`)
//! fault_duration_s = { uniform = [0.01, 0.1] }    # how long, for a kind that lasts
//! ```
//!
//! A drawn fault's size is the key its kind takes (`scenario::fault_spec`): `force_n` of a
//! spike, bias jump or out-of-range reading, `std_n` of a noise burst, `factor` of a
//! stiffness step, `scale` of an actuator, `periods` of a delay (rounded), `max_s` of jitter,
//! `mass_kg` of a payload; the drawn kind is the `fault_kind` column (its index in the list).

use toml::{Table, Value};

use crate::scenario::toml_table::as_number;
use crate::scenario::{Scenario, ScenarioError};

/// The keys of `[sweep]` that are not distributions: `fault_kinds`, the kinds a trial's fault is
/// drawn from (none: no fault), and `max_position_error_mm`, the tool position error beyond
/// which a trial fails for tracking, mm.
const OTHER_KEYS: [&str; 2] = ["fault_kinds", "max_position_error_mm"];

/// A checked distribution.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Distribution {
    /// Uniform on `[low, high]`.
    Uniform {
        /// Lower end.
        low: f64,
        /// Upper end.
        high: f64,
    },
    /// Normal.
    Normal {
        /// Mean.
        mean: f64,
        /// Standard deviation (>= 0).
        std: f64,
    },
}

/// A quantity a sweep can vary.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SweepKey {
    /// `link_mass_scale`: scale of each link's mass in the plant (one draw per link).
    LinkMassScale,
    /// `link_inertia_scale`: scale of each link's inertia about its centre of mass (one draw
    /// per link).
    LinkInertiaScale,
    /// `link_com_offset_m`: offset of each link's centre of mass, m (one draw per link and
    /// axis).
    LinkComOffset,
    /// `payload_kg`: payload at the tool, kg.
    Payload,
    /// `friction_viscous`: viscous joint friction, N m s/rad or N s/m (one draw per joint).
    FrictionViscous,
    /// `friction_coulomb`: Coulomb joint friction, N m or N (one draw per joint).
    FrictionCoulomb,
    /// `stiffness_n_m`: stiffness of every surface, N/m.
    Stiffness,
    /// `surface_offset_m`: shift of every real surface along its outward normal, m, the
    /// controller's belief staying where the file puts the surface (a height offset for a
    /// horizontal plane).
    SurfaceOffset,
    /// `sensor_noise_n`: force sensor noise, N (1 sigma per force axis).
    SensorNoise,
    /// `sensor_bias_n`: force sensor bias on fz, N.
    SensorBias,
    /// The fault's kind, drawn uniformly from `fault_kinds` (an index into it; not a key of the
    /// file).
    FaultKind,
    /// `fault_start_s`: when the fault starts, s.
    FaultStart,
    /// `fault_size`: its size, in the unit of its kind's size key.
    FaultSize,
    /// `fault_duration_s`: its duration, s, for a kind that lasts.
    FaultDuration,
}

impl SweepKey {
    /// Every key, in the order of the `trials.csv` columns.
    pub const ALL: [Self; 14] = [
        Self::LinkMassScale,
        Self::LinkInertiaScale,
        Self::LinkComOffset,
        Self::Payload,
        Self::FrictionViscous,
        Self::FrictionCoulomb,
        Self::Stiffness,
        Self::SurfaceOffset,
        Self::SensorNoise,
        Self::SensorBias,
        Self::FaultKind,
        Self::FaultStart,
        Self::FaultSize,
        Self::FaultDuration,
    ];

    /// The key's name in `[sweep]`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::LinkMassScale => "link_mass_scale",
            Self::LinkInertiaScale => "link_inertia_scale",
            Self::LinkComOffset => "link_com_offset_m",
            Self::Payload => "payload_kg",
            Self::FrictionViscous => "friction_viscous",
            Self::FrictionCoulomb => "friction_coulomb",
            Self::Stiffness => "stiffness_n_m",
            Self::SurfaceOffset => "surface_offset_m",
            Self::SensorNoise => "sensor_noise_n",
            Self::SensorBias => "sensor_bias_n",
            Self::FaultKind => "fault_kind",
            Self::FaultStart => "fault_start_s",
            Self::FaultSize => "fault_size",
            Self::FaultDuration => "fault_duration_s",
        }
    }

    /// Column names of its draws for a robot of `dof` joints (one per link, joint or axis
    /// where it is drawn so).
    #[must_use]
    pub fn columns(self, dof: usize) -> Vec<String> {
        let n = self.name();
        match self {
            Self::LinkMassScale
            | Self::LinkInertiaScale
            | Self::FrictionViscous
            | Self::FrictionCoulomb => (1..=dof).map(|j| format!("{n}_{j}")).collect(),
            Self::LinkComOffset => (1..=dof)
                .flat_map(|j| ["x", "y", "z"].map(|a| format!("{n}_{j}{a}")))
                .collect(),
            _ => vec![n.to_string()],
        }
    }

    /// The values a draw may take, `(low, high, rule)`.
    #[must_use]
    pub fn domain(self) -> (f64, f64, &'static str) {
        match self {
            Self::LinkMassScale | Self::LinkInertiaScale => {
                (1e-3, 10.0, "a scale factor in [0.001, 10]")
            }
            Self::LinkComOffset => (-0.1, 0.1, "an offset in m within +-0.1"),
            Self::Payload => (0.0, 100.0, "a mass in kg in [0, 100]"),
            Self::FrictionViscous => (0.0, 1e5, "a viscous coefficient >= 0"),
            Self::FrictionCoulomb => (0.0, 1e4, "a Coulomb coefficient >= 0"),
            Self::Stiffness => (1.0, 1e9, "a stiffness in N/m in [1, 1e9]"),
            Self::SurfaceOffset => (-0.1, 0.1, "an offset in m within +-0.1"),
            Self::SensorNoise => (0.0, 1e5, "a standard deviation in N >= 0"),
            Self::SensorBias => (-1e5, 1e5, "a bias in N within +-1e5"),
            Self::FaultKind => (0.0, 1e6, "an index into fault_kinds"),
            Self::FaultStart => (0.0, 1e5, "a time in s in [0, 1e5]"),
            Self::FaultSize => (-1e6, 1e6, "a size within +-1e6"),
            Self::FaultDuration => (0.0, 1e5, "a duration in s in [0, 1e5]"),
        }
    }
}

/// The keys `[sweep]` may have: every drawn key but the fault's kind (drawn from
/// `fault_kinds`), then [`OTHER_KEYS`].
fn file_keys() -> Vec<&'static str> {
    SweepKey::ALL
        .iter()
        .filter(|k| **k != SweepKey::FaultKind)
        .map(|k| k.name())
        .chain(OTHER_KEYS)
        .collect()
}

/// The distribution at `key` as written, `{ uniform = [low, high] }` or `{ normal = [mean,
/// std] }`, checked against its key's `(low, high, rule)` domain.
fn distribution(
    v: &Value,
    key: &str,
    (lo, hi, rule): (f64, f64, &str),
    err: &mut dyn FnMut(&str, String) -> ScenarioError,
) -> Result<Distribution, ScenarioError> {
    let Some(t) = v.as_table() else {
        return Err(err(
            key,
            format!(
                "invalid type: {}, expected a table `{{ uniform = [low, high] }}` or `{{ normal = [mean, std] }}`",
                v.type_str()
            ),
        ));
    };
    if let Some(k) = t.keys().find(|k| *k != "uniform" && *k != "normal") {
        return Err(err(
            &format!("{key}.{k}"),
            format!("unknown field `{k}`, expected `uniform` or `normal`"),
        ));
    }
    let mut entry = |name: &str| match t.get(name) {
        None => Ok(None),
        Some(v) => v
            .as_array()
            .and_then(|a| a.iter().map(as_number).collect::<Option<Vec<f64>>>())
            .map(Some)
            .ok_or_else(|| err(key, format!("{name}: expected an array of numbers"))),
    };
    let pair = |v: &Vec<f64>, what: &str| {
        if v.len() != 2 || v.iter().any(|x| !x.is_finite()) {
            Err(format!("{what} needs two finite numbers, got {v:?}"))
        } else {
            Ok((v[0], v[1]))
        }
    };
    let (uniform, normal) = (entry("uniform")?, entry("normal")?);
    Ok(match (&uniform, &normal) {
        (Some(u), None) => {
            let (low, high) = pair(u, "uniform = [low, high]").map_err(|r| err(key, r))?;
            if low > high {
                return Err(err(
                    key,
                    format!("uniform = [{low}, {high}]: low must not exceed high"),
                ));
            }
            if low < lo || high > hi {
                return Err(err(
                    key,
                    format!("uniform = [{low}, {high}] leaves the key's range: {rule}"),
                ));
            }
            Distribution::Uniform { low, high }
        }
        (None, Some(n)) => {
            let (mean, std) =
                pair(n, "normal = [mean, standard deviation]").map_err(|r| err(key, r))?;
            if std < 0.0 {
                return Err(err(
                    key,
                    format!("normal = [{mean}, {std}]: the standard deviation must be >= 0"),
                ));
            }
            if mean - NORMAL_SIGMAS * std < lo || mean + NORMAL_SIGMAS * std > hi {
                return Err(err(key, format!("normal = [{mean}, {std}]: mean +- {NORMAL_SIGMAS} standard deviations must stay in the key's range: {rule}")));
            }
            Distribution::Normal { mean, std }
        }
        _ => {
            return Err(err(
                key,
                "needs exactly one of `uniform = [low, high]` or `normal = [mean, std]`".into(),
            ))
        }
    })
}

/// Standard deviations a normal distribution must keep inside its key's domain (draws
/// beyond are clamped to it, with probability below 2e-9).
pub const NORMAL_SIGMAS: f64 = 6.0;

/// The name of the sweep's table in a scenario file.
pub const TABLE: &str = "sweep";

/// A checked `[sweep]`: the keys that vary, in [`SweepKey::ALL`] order, for a robot of
/// `dof` joints.
#[derive(Clone, Debug, PartialEq)]
pub struct SweepSpec {
    /// `(key, distribution)`.
    pub entries: Vec<(SweepKey, Distribution)>,
    /// The scenario's robot's joint count (the per-link and per-joint draws).
    pub dof: usize,
    /// The tracking bound of a trial, mm (`max_position_error_mm`).
    pub max_position_error_mm: Option<f64>,
    /// The kinds a trial's fault is drawn from (empty: no fault).
    pub fault_kinds: Vec<String>,
}

impl SweepSpec {
    /// Checks `[sweep]`, its table `t`; `err(key, rule)` makes the error (file, line, key,
    /// rule).
    ///
    /// # Errors
    ///
    /// A [`ScenarioError`] naming `sweep.<key>` and the rule broken.
    pub fn check(
        t: &Table,
        dof: usize,
        err: &mut dyn FnMut(&str, String) -> ScenarioError,
    ) -> Result<Self, ScenarioError> {
        let known = file_keys();
        if let Some(k) = t.keys().find(|k| !known.contains(&k.as_str())) {
            let known = known.iter().map(|n| format!("`{n}`")).collect::<Vec<_>>();
            return Err(err(
                &format!("{TABLE}.{k}"),
                format!("unknown field `{k}`, expected one of {}", known.join(", ")),
            ));
        }
        let mut entries = Vec::new();
        for key in SweepKey::ALL {
            let Some(d) = t.get(key.name()) else { continue };
            let k = format!("sweep.{}", key.name());
            entries.push((key, distribution(d, &k, key.domain(), err)?));
        }
        let fault_kinds = match t.get("fault_kinds") {
            None => Vec::new(),
            Some(v) => v
                .as_array()
                .and_then(|a| {
                    a.iter()
                        .map(|k| k.as_str().map(str::to_string))
                        .collect::<Option<Vec<_>>>()
                })
                .ok_or_else(|| {
                    err(
                        "sweep.fault_kinds",
                        "invalid type: expected an array of fault kinds (strings)".into(),
                    )
                })?,
        };
        for k in &fault_kinds {
            if !crate::scenario::fault_spec::KIND_NAMES.contains(&k.as_str()) {
                return Err(err(
                    "sweep.fault_kinds",
                    format!(
                        "unknown fault `{k}`; known: {}",
                        crate::scenario::fault_spec::KIND_NAMES.join(", ")
                    ),
                ));
            }
        }
        let fault_keys = entries.iter().any(|(k, _)| {
            matches!(
                k,
                SweepKey::FaultStart | SweepKey::FaultSize | SweepKey::FaultDuration
            )
        });
        if fault_keys && fault_kinds.is_empty() {
            return Err(err(
                "sweep.fault_kinds",
                "is missing: fault_start_s, fault_size and fault_duration_s draw a fault of one of fault_kinds".into(),
            ));
        }
        if !fault_kinds.is_empty() {
            if !entries.iter().any(|(k, _)| *k == SweepKey::FaultStart) {
                return Err(err(
                    "sweep.fault_start_s",
                    "is missing: when a drawn fault starts".into(),
                ));
            }
            // The kind's index, drawn uniformly.
            let n = fault_kinds.len() as f64;
            let at = entries
                .iter()
                .position(|(k, _)| SweepKey::ALL.iter().position(|x| x == k) > Some(10))
                .unwrap_or(entries.len());
            entries.insert(
                at,
                (
                    SweepKey::FaultKind,
                    Distribution::Uniform { low: 0.0, high: n },
                ),
            );
        }
        if entries.is_empty() {
            return Err(err(
                "sweep",
                format!("varies nothing; known keys: {}", file_keys().join(", ")),
            ));
        }
        let max_position_error_mm = match t.get("max_position_error_mm").map(as_number) {
            None => None,
            Some(Some(v)) if v.is_finite() && v > 0.0 => Some(v),
            Some(None) => {
                return Err(err(
                    "sweep.max_position_error_mm",
                    "invalid type: expected a number (mm)".into(),
                ))
            }
            Some(Some(v)) => {
                return Err(err(
                    "sweep.max_position_error_mm",
                    format!("{v} is out of range: a distance in mm, > 0"),
                ))
            }
        };
        Ok(Self {
            entries,
            dof,
            max_position_error_mm,
            fault_kinds,
        })
    }

    /// The `[sweep]` table of a scenario read with [`TABLE`] kept
    /// ([`Scenario::load_with`]); `None` if it has none.
    ///
    /// # Errors
    ///
    /// A [`ScenarioError`] naming `sweep` or `sweep.<key>` and the rule broken.
    pub fn of(scenario: &Scenario) -> Result<Option<Self>, ScenarioError> {
        let table = match scenario.extensions.get(TABLE) {
            None => return Ok(None),
            Some(Value::Table(t)) => t,
            Some(v) => {
                return Err(scenario.error(
                    TABLE,
                    format!("invalid type: {}, expected a table", v.type_str()),
                ))
            }
        };
        Self::check(table, scenario.dof, &mut |key, rule| {
            scenario.error(key, rule)
        })
        .map(Some)
    }

    /// Names of every drawn column, in order.
    #[must_use]
    pub fn columns(&self) -> Vec<String> {
        self.entries
            .iter()
            .flat_map(|(k, _)| k.columns(self.dof))
            .collect()
    }
}
