//! A scenario checked key by key: every value in range and in its unit, every kind-specific
//! key where it belongs, every joint list of the robot's length, every file it names
//! readable. What [`super::prepare`] builds a run from.
//!
//! The keys of each table are checked in their own file: [`super::reference_spec`],
//! [`super::surface_spec`], [`super::force_spec`], [`super::plant`] and
//! [`super::law_spec`].

use std::path::Path;

use super::check::Checker;
use super::controllers::{PositionController, PositionSettings};
use super::error::ScenarioError;
use super::file::{field_names, ScenarioFile};
pub use super::force_spec::{ForceReferenceSpec, ForceSpec, SensorSpec};
pub use super::law_spec::{AdmittanceSettings, DesignSettings, ImpedanceSettings, LawSettings};
use super::plant::{ControllerModel, PlantSpec};
use super::reference_spec::{facts_of, robot_facts, RobotFacts};
pub use super::reference_spec::{IkSettings, ReferenceSpec};
use super::toml_table::{key_list, TomlTable};
use super::vocabulary::RobotVocabulary;
use crate::contact::ContactSurface;
use crate::control::selection::SelectionPolicy;

/// The format version this reader knows.
pub const FORMAT: i64 = 1;
/// Largest controller or plant step accepted, s (a larger one is most likely milliseconds).
pub const MAX_STEP_S: f64 = 0.1;
/// Default start of the pose tracking metrics' window, s (the thesis's 2 s).
pub const POSE_METRICS_AFTER_S: f64 = 2.0;

/// A checked scenario, for any robot of the registry.
#[derive(Clone, Debug, PartialEq)]
pub struct Scenario {
    /// Where it came from (for messages).
    pub file: String,
    /// The file's text (for line numbers in later messages).
    pub source: String,
    /// Short name.
    pub name: String,
    /// One line.
    pub description: String,
    /// Robot name (a robot of [`crate::model::ROBOTS`]).
    pub robot: String,
    /// Its joint count.
    pub dof: usize,
    /// Length of the run, s (`None`: the reference's).
    pub duration_s: Option<f64>,
    /// Controller period, s.
    pub control_dt_s: f64,
    /// Plant step, s.
    pub plant_dt_s: f64,
    /// Initial joint positions, one per joint (`None`: all zero).
    pub q0: Option<Vec<f64>>,
    /// End stops in the plant.
    pub end_stops: bool,
    /// Start on the reference's first point instead of `q0`.
    pub start_on_reference: bool,
    /// The motion reference.
    pub reference: ReferenceSpec,
    /// The robot's own `[reference]` keys (a SCARA's elbow switch), as the file gives them,
    /// checked by the robot ([`RobotVocabulary::check_reference_keys`]).
    ///
    /// [`RobotVocabulary::check_reference_keys`]: super::RobotVocabulary::check_reference_keys
    pub reference_robot_keys: toml::Table,
    /// The inverse kinematics' settings.
    pub ik: IkSettings,
    /// The real surfaces.
    pub surfaces: Vec<ContactSurface>,
    /// The position loop.
    pub position: PositionController,
    /// Its settings.
    pub position_settings: PositionSettings,
    /// The force loop.
    pub force: Option<ForceSpec>,
    /// When force is controlled.
    pub selection: Option<SelectionPolicy>,
    /// The sensor.
    pub sensor: SensorSpec,
    /// The plant's parameters and friction (`[plant]`; the description's by default).
    pub plant: PlantSpec,
    /// The controller's model.
    pub controller_model: ControllerModel,
    /// Rotor inertia the controller's model adds at each joint, kg m^2 or kg
    /// (`controller_armature`; `None`: none).
    pub controller_armature: Option<Vec<f64>>,
    /// Start of the pose tracking metrics' window, s (`[metrics] after_s`).
    pub pose_metrics_after_s: f64,
    /// The safety supervisor (`[safety]`).
    pub safety: super::safety_spec::SafetySpec,
    /// The faults injected (`[[faults]]`).
    pub faults: Vec<super::fault_spec::FaultSpec>,
    /// Top-level tables of other tools kept as written (see [`Scenario::parse_with`]).
    pub extensions: toml::Table,
}

/// A scenario file's name as shown, its text and its folder.
fn read_file(path: &Path) -> Result<(String, String, std::path::PathBuf), ScenarioError> {
    let file = path.display().to_string();
    let source = std::fs::read_to_string(path).map_err(|e| ScenarioError {
        file: file.clone(),
        key: String::new(),
        line: None,
        rule: format!("cannot read: {e}"),
    })?;
    let dir = path.parent().unwrap_or(Path::new(".")).to_path_buf();
    Ok((file, source, dir))
}

impl Scenario {
    /// Reads and checks a scenario file; relative file names in it are relative to its folder.
    ///
    /// # Errors
    ///
    /// [`ScenarioError`] naming the file, the key (and line) and the rule.
    pub fn load(path: &Path) -> Result<Self, ScenarioError> {
        Self::load_with(path, &[])
    }

    /// [`Self::load`], keeping the top-level tables `extensions` (another tool's, such as a
    /// sweep's) in [`Self::extensions`] instead of refusing them.
    ///
    /// # Errors
    ///
    /// As [`Self::load`].
    pub fn load_with(path: &Path, extensions: &[&str]) -> Result<Self, ScenarioError> {
        let (file, source, dir) = read_file(path)?;
        Self::parse_with(&file, &source, &dir, extensions)
    }

    /// Checks scenario text `source` named `file`; relative file names resolve in `dir`.
    ///
    /// # Errors
    ///
    /// [`ScenarioError`] naming the file, the key (and line) and the rule.
    pub fn parse(file: &str, source: &str, dir: &Path) -> Result<Self, ScenarioError> {
        Self::parse_with(file, source, dir, &[])
    }

    /// [`Self::parse`], keeping the top-level tables named in `extensions` as written.
    ///
    /// # Errors
    ///
    /// As [`Self::parse`].
    pub fn parse_with(
        file: &str,
        source: &str,
        dir: &Path,
        extensions: &[&str],
    ) -> Result<Self, ScenarioError> {
        Self::parse_robots(file, source, dir, extensions, None, robot_facts)
    }

    /// Reads and checks a scenario file for robot `R` (a user's own arm, made by
    /// [`robot_type!`](crate::robot_type), that is not in the registry): its `robot` key may
    /// name `R` (by its `NAME`) or any robot of the registry.
    ///
    /// ```no_run
    /// use armdyn::model::Ur5;
    /// use armdyn::scenario::{prepare_for, Scenario};
    /// let scenario = Scenario::load_for(&Ur5, "scenarios/ur5-square.toml".as_ref())?;
    /// let outcome = prepare_for(&scenario, Ur5)?.execute(&scenario, |_| {})?;
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    ///
    /// As [`Self::load`].
    pub fn load_for<const N: usize, R: RobotVocabulary<N>>(
        robot: &R,
        path: &Path,
    ) -> Result<Self, ScenarioError> {
        let _ = robot;
        let (file, source, dir) = read_file(path)?;
        Self::parse_robots(&file, &source, &dir, &[], Some(R::NAME), |name| {
            (name == R::NAME)
                .then(facts_of::<N, R>)
                .or_else(|| robot_facts(name))
        })
    }

    /// [`Self::parse`] for robot `R` (see [`Self::load_for`]).
    ///
    /// # Errors
    ///
    /// As [`Self::parse`].
    pub fn parse_for<const N: usize, R: RobotVocabulary<N>>(
        robot: &R,
        file: &str,
        source: &str,
        dir: &Path,
    ) -> Result<Self, ScenarioError> {
        let _ = robot;
        Self::parse_robots(file, source, dir, &[], Some(R::NAME), |name| {
            (name == R::NAME)
                .then(facts_of::<N, R>)
                .or_else(|| robot_facts(name))
        })
    }

    /// The reader, with the robots a `robot` key may name given by `robots`: the registry's,
    /// and `own` if given.
    fn parse_robots(
        file: &str,
        source: &str,
        dir: &Path,
        extensions: &[&str],
        own: Option<&str>,
        robots: impl FnOnce(&str) -> Option<RobotFacts>,
    ) -> Result<Self, ScenarioError> {
        let text = source.strip_prefix('\u{feff}').unwrap_or(source);
        let c = Checker { file, source: text };
        // The top-level keys first (a misspelt table is named as such, not as the table it
        // leaves missing), then every table by its own type.
        let table: toml::Table =
            toml::from_str(text).map_err(|e| ScenarioError::parse(file, text, &e))?;
        let reference_table = table.get("reference").and_then(|r| r.as_table()).cloned();
        let safety_table = table.get("safety").and_then(|r| r.as_table()).cloned();
        let top_keys = field_names::<ScenarioFile>();
        let mut kept = toml::Table::new();
        for (key, value) in table {
            if top_keys.contains(&key.as_str()) {
                continue;
            }
            if extensions.contains(&key.as_str()) {
                kept.insert(key, value);
                continue;
            }
            let mut known: Vec<&str> = top_keys.to_vec();
            known.extend(extensions);
            return Err(c.err(
                &key,
                format!(
                    "unknown field `{key}`, expected one of {}",
                    known.join(", ")
                ),
            ));
        }
        let raw: ScenarioFile =
            toml::from_str(text).map_err(|e| ScenarioError::parse(file, text, &e))?;
        if raw.format != FORMAT {
            return Err(c.err(
                "format",
                format!(
                    "format {} is not known; this reader reads format {FORMAT}",
                    raw.format
                ),
            ));
        }
        let robot = robots(&raw.robot).ok_or_else(|| {
            c.err(
                "robot",
                format!(
                    "unknown robot `{}`; known: {}",
                    raw.robot,
                    own.iter()
                        .chain(crate::model::ROBOTS)
                        .copied()
                        .collect::<Vec<_>>()
                        .join(", ")
                ),
            )
        })?;
        let step = |key: &str, v: Option<f64>| {
            c.range(
                key,
                v.unwrap_or(1e-3),
                0.0,
                MAX_STEP_S,
                true,
                "a step in s must be > 0 and <= 0.1 s (is it in ms?)",
            )
        };
        let control_dt_s = step("control_dt_s", raw.control_dt_s)?;
        let plant_dt_s = step("plant_dt_s", raw.plant_dt_s)?;
        let ratio = control_dt_s / plant_dt_s;
        if (ratio - ratio.round()).abs() > 1e-9 * ratio || ratio.round() < 1.0 {
            return Err(c.err("control_dt_s", "must be a whole multiple of plant_dt_s"));
        }
        let duration_s = raw
            .duration_s
            .map(|d| c.range("duration_s", d, 0.0, 1e5, true, "a duration in s, > 0"))
            .transpose()?;
        let q0 = raw
            .q0
            .as_ref()
            .map(|v| c.joints("q0", v, robot.dof, &robot.name, "the initial joints"))
            .transpose()?;
        let end_stops = raw.end_stops.unwrap_or(true);
        let start_on_reference = raw.start_on_reference.unwrap_or(false);
        if start_on_reference && raw.q0.is_some() {
            return Err(c.err(
                "q0",
                "give either q0 or start_on_reference = true, not both",
            ));
        }
        if end_stops && !start_on_reference {
            check_q0_inside(&c, &robot, q0.as_deref())?;
        }
        let reference = super::reference_spec::reference(
            &c,
            &raw.reference,
            reference_table.as_ref(),
            dir,
            &robot,
        )?;
        let reference_robot_keys =
            super::reference_spec::robot_keys(&c, reference_table.as_ref(), &robot)?;
        let ik = super::reference_spec::ik_settings(&c, &raw.reference, &robot)?;
        let surfaces = raw
            .surfaces
            .iter()
            .enumerate()
            .map(|(i, s)| super::surface_spec::surface(&c, &format!("surfaces[{i}]"), s))
            .collect::<Result<Vec<_>, _>>()?;
        let (position, position_settings) = position_law(&c, &raw.position)?;
        let sensor = super::force_spec::sensor(&c, raw.sensor.as_ref())?;
        let (force, selection) = match (&raw.force, &raw.selection) {
            (None, None) => (None, None),
            (Some(_), None) => {
                return Err(c.err(
                    "force",
                    "needs a [selection] table (mode = \"time\" or \"contact\")",
                ))
            }
            (None, Some(_)) => {
                return Err(c.err(
                    "selection",
                    "without a [force] table there is nothing to select",
                ))
            }
            (Some(f), Some(s)) => {
                let force = super::force_spec::force(&c, f, surfaces.len(), dir)?;
                let selection = super::force_spec::selection(&c, s, &sensor)?;
                (Some(force), Some(selection))
            }
        };
        let plant = super::plant::plant(&c, raw.plant.as_ref(), robot.dof)?;
        let controller_model = controller_model(&c, raw.controller_model.as_deref(), dir, &robot)?;
        let controller_armature = raw
            .controller_armature
            .as_ref()
            .map(|v| {
                let v = c.joints(
                    "controller_armature",
                    v,
                    robot.dof,
                    &robot.name,
                    "the rotor inertia the controller's model adds at each joint, kg m^2 or kg",
                )?;
                for (i, x) in v.iter().enumerate() {
                    if *x < 0.0 {
                        return Err(c.err(
                            "controller_armature",
                            format!("joint {}: {x} is negative; an inertia is >= 0", i + 1),
                        ));
                    }
                }
                Ok(v)
            })
            .transpose()?;
        let pose_metrics_after_s = raw
            .metrics
            .as_ref()
            .and_then(|m| m.after_s)
            .map(|t| c.range("metrics.after_s", t, 0.0, 1e5, false, "a time in s, >= 0"))
            .transpose()?
            .unwrap_or(POSE_METRICS_AFTER_S);
        let safety =
            super::safety_spec::safety(&c, raw.safety.as_ref(), safety_table.as_ref(), robot.dof)?;
        let faults = super::fault_spec::faults(
            &c,
            &raw.faults,
            robot.dof,
            surfaces.len(),
            control_dt_s,
            plant_dt_s,
        )?;
        Ok(Self {
            safety,
            faults,
            plant,
            controller_model,
            controller_armature,
            file: file.to_string(),
            source: text.to_string(),
            name: raw.name,
            description: raw.description,
            robot: raw.robot,
            dof: robot.dof,
            duration_s,
            control_dt_s,
            plant_dt_s,
            q0,
            end_stops,
            start_on_reference,
            reference,
            reference_robot_keys,
            ik,
            surfaces,
            position,
            position_settings,
            force,
            selection,
            sensor,
            pose_metrics_after_s,
            extensions: kept,
        })
    }

    /// An error about `key` of this scenario, with its line.
    #[must_use]
    pub fn error(&self, key: &str, rule: impl Into<String>) -> ScenarioError {
        ScenarioError::at(&self.file, &self.source, key, rule)
    }

    /// The initial joints as given (`q0`, all zero if absent).
    #[must_use]
    pub fn q0_or_zero(&self) -> Vec<f64> {
        self.q0.clone().unwrap_or_else(|| vec![0.0; self.dof])
    }
}

fn check_q0_inside(
    c: &Checker<'_>,
    robot: &RobotFacts,
    q0: Option<&[f64]>,
) -> Result<(), ScenarioError> {
    let (limits, names) = (&robot.limits, &robot.joint_names);
    let zeros = vec![0.0; robot.dof];
    let q0 = q0.unwrap_or(&zeros);
    for (i, [lo, hi]) in limits.iter().enumerate() {
        if !(*lo <= q0[i] && q0[i] <= *hi) {
            return Err(c.err("q0", format!(
                "joint {} = {} is outside its limits [{lo:.4}, {hi:.4}]; with end_stops = true the run must start inside them (or set end_stops = false)",
                names[i], q0[i]
            )));
        }
    }
    Ok(())
}

/// `[position]`, its table `table`: the law and its settings.
fn position_law(
    c: &Checker<'_>,
    table: &toml::Table,
) -> Result<(PositionController, PositionSettings), ScenarioError> {
    let p = TomlTable {
        c,
        at: "position",
        table,
    };
    let name = p.tag("law", "the position law")?;
    let law = PositionController::parse(name).map_err(|e| p.err("law", e.to_string()))?;
    if let Some(k) = p.other_key("law", law.keys()) {
        let takes: Vec<&str> = PositionController::NAMED
            .iter()
            .filter(|l| l.keys().contains(&k))
            .map(|l| l.name())
            .collect();
        return Err(if takes.is_empty() {
            p.err(
                k,
                format!(
                    "unknown field `{k}`: law = \"{name}\" takes {}",
                    key_list(law.keys())
                ),
            )
        } else {
            p.err(
                k,
                format!(
                    "does not belong here: a key of law = \"{}\"",
                    takes.join("\", \"")
                ),
            )
        });
    }
    let d = PositionSettings::default();
    let omega_rad_s = p
        .optional_numbers("omega_rad_s")?
        .map(|w| {
            for x in &w {
                c.range(
                    "position.omega_rad_s",
                    *x,
                    0.0,
                    1e4,
                    true,
                    "a natural frequency in rad/s, > 0",
                )?;
            }
            Ok::<_, ScenarioError>(w)
        })
        .transpose()?;
    let settings = PositionSettings {
        acceleration_feedforward: p
            .optional_bool("acceleration_feedforward")?
            .unwrap_or(d.acceleration_feedforward),
        omega_rad_s,
        damping_ratio: c.range(
            "position.damping_ratio",
            p.optional_number("damping_ratio")?
                .unwrap_or(d.damping_ratio),
            0.0,
            10.0,
            true,
            "a damping ratio, > 0 and <= 10",
        )?,
        integral: p.optional_bool("integral")?.unwrap_or(d.integral),
        posture_omega_rad_s: c.range(
            "position.posture_omega_rad_s",
            p.optional_number("posture_omega_rad_s")?
                .unwrap_or(d.posture_omega_rad_s),
            0.0,
            1e4,
            false,
            "a natural frequency in rad/s, >= 0",
        )?,
    };
    Ok((law, settings))
}

fn controller_model(
    c: &Checker<'_>,
    v: Option<&str>,
    dir: &Path,
    robot: &RobotFacts,
) -> Result<ControllerModel, ScenarioError> {
    match v {
        None | Some("nominal") => Ok(ControllerModel::Nominal),
        Some(name) => {
            let file = dir.join(name);
            let parameters =
                (robot.read_identified)(&file).map_err(|e| c.err("controller_model", e))?;
            Ok(ControllerModel::Identified { file, parameters })
        }
    }
}

/// The controller model named on a command line (`nominal` or an `identification.json`) for
/// the robot of `scenario`.
///
/// # Errors
///
/// A message naming the file and what is wrong in it.
pub fn controller_model_for(scenario: &Scenario, arg: &str) -> Result<ControllerModel, String> {
    if arg == "nominal" {
        return Ok(ControllerModel::Nominal);
    }
    let file = std::path::PathBuf::from(arg);
    let robot = robot_facts(&scenario.robot).ok_or_else(|| "unknown robot".to_string())?;
    let parameters = (robot.read_identified)(&file)?;
    Ok(ControllerModel::Identified { file, parameters })
}
