//! A scenario checked key by key: every value in range and in its unit, every kind-specific
//! key where it belongs, every file it names readable. What [`super::prepare`] builds a run
//! from.

use std::path::{Path, PathBuf};

use nalgebra::Vector3;

use super::controllers::{ForceController, PositionController};
use super::error::ScenarioError;
use super::file::{ForceTable, ReferenceTable, ScenarioFile, SelectionTable, SurfaceTable};
pub use super::law_spec::{AdmittanceSettings, DesignSettings, ImpedanceSettings, LawSettings};
use super::plant::{ControllerModel, PlantSpec, PlantTable};
use crate::contact::{ContactSurface, SurfaceGeometry};
use crate::control::selection::{ContactSwitch, SelectionPolicy};
use crate::robots::scara::elbow_flip::FlipOptions;
use crate::target::PoseSample;
use crate::trajectory::force_csv::SampledForce;
use crate::trajectory::waypoints::{Interpolation, Waypoints};
use crate::trajectory::SampledTrajectory;

/// The format version this reader knows.
pub const FORMAT: i64 = 1;
/// Largest controller or plant step accepted, s (a larger one is most likely milliseconds).
pub const MAX_STEP_S: f64 = 0.1;
/// Largest normal force accepted, N (a larger one is most likely in the wrong unit).
pub const MAX_FORCE_N: f64 = 1e5;
/// Largest Coulomb coefficient accepted.
pub const MAX_FRICTION: f64 = 2.0;

/// A thesis reference by name.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ThesisReference {
    /// Position test, eq. 4.16.
    Position,
    /// Contact test, Appendix B.3, on-surface part at `surface_z_m`.
    Contact {
        /// m.
        surface_z_m: f64,
    },
    /// The three-zone workspace trial, Section 4.4.
    ThreeZone,
}

/// The motion reference.
#[derive(Clone, Debug, PartialEq)]
pub enum ReferenceSpec {
    /// A thesis reference.
    Thesis(ThesisReference),
    /// Waypoints.
    Waypoints(Waypoints),
    /// A CSV file (its path, as resolved, and its samples).
    Csv(PathBuf, SampledTrajectory),
}

/// The desired normal force over time.
#[derive(Clone, Debug, PartialEq)]
pub enum ForceReferenceSpec {
    /// `value`.
    Constant,
    /// `value (1 + sin(t))`: the thesis's variable profile, Appendix B.3.
    ThesisVariable,
    /// Samples from a CSV file.
    Csv(SampledForce),
}

/// The force loop.
#[derive(Clone, Debug, PartialEq)]
pub struct ForceSpec {
    /// The law (for its name).
    pub law: ForceController,
    /// Gains `Kfp` (1), `Kfi` (1/s), `Kvd` (N s/m).
    pub gains: (f64, f64, f64),
    /// The reference's shape.
    pub reference: ForceReferenceSpec,
    /// Magnitude, N.
    pub value_n: f64,
    /// Nominal Coulomb coefficient of the friction feedforward (0: none).
    pub friction_feedforward: f64,
    /// Gravity along the normal kept in the force command.
    pub gravity_compensation: bool,
    /// Conditional integration of the PI law's integral while an actuator saturates.
    pub anti_windup: bool,
    /// Index of the surface that defines the task frame.
    pub surface: usize,
    /// Shift of the controller's belief of that surface along its normal, m.
    pub expected_shift_m: f64,
    /// Settings of the designed gains, the impedance and the admittance.
    pub laws: LawSettings,
}

/// What to do where the reference needs the other elbow.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ElbowSwitchSpec {
    /// The thesis's: the joint reference jumps to the other solution.
    Step,
    /// A planned flip ([`crate::robots::scara::elbow_flip`]).
    Planned(FlipOptions),
}

/// The force sensor.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SensorSpec {
    /// White noise per force axis, N (1 sigma).
    pub noise_n: f64,
    /// Bias on base z, N.
    pub bias_n: f64,
    /// Low-pass cutoff, Hz.
    pub cutoff_hz: Option<f64>,
    /// Seed.
    pub seed: u64,
}

impl SensorSpec {
    /// Whether the sensor reports the true wrench.
    #[must_use]
    pub fn is_ideal(&self) -> bool {
        self.noise_n == 0.0 && self.bias_n == 0.0 && self.cutoff_hz.is_none()
    }
}

/// A checked scenario.
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
    /// Robot name.
    pub robot: String,
    /// Length of the run, s (`None`: the reference's).
    pub duration_s: Option<f64>,
    /// Controller period, s.
    pub control_dt_s: f64,
    /// Plant step, s.
    pub plant_dt_s: f64,
    /// Initial joint positions.
    pub q0: [f64; 4],
    /// End stops in the plant.
    pub end_stops: bool,
    /// Start on the reference's first point instead of `q0`.
    pub start_on_reference: bool,
    /// The motion reference.
    pub reference: ReferenceSpec,
    /// Elbow switches: stepped or planned.
    pub elbow_switch: ElbowSwitchSpec,
    /// The real surfaces.
    pub surfaces: Vec<ContactSurface>,
    /// The position loop.
    pub position: PositionController,
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
    /// The Monte Carlo distributions (`[sweep]`), if any.
    pub sweep: Option<crate::sweep::SweepSpec>,
}

pub(super) struct Checker<'a> {
    file: &'a str,
    source: &'a str,
}

impl Checker<'_> {
    pub(super) fn err(&self, key: &str, rule: impl Into<String>) -> ScenarioError {
        ScenarioError::at(self.file, self.source, key, rule)
    }

    pub(super) fn finite(&self, key: &str, v: f64) -> Result<f64, ScenarioError> {
        if v.is_finite() {
            Ok(v)
        } else {
            Err(self.err(key, format!("{v} is not a finite number")))
        }
    }

    /// `v` within `[lo, hi]` (bounds inclusive unless `open_lo`), else the rule `what`.
    pub(super) fn range(
        &self,
        key: &str,
        v: f64,
        lo: f64,
        hi: f64,
        open_lo: bool,
        what: &str,
    ) -> Result<f64, ScenarioError> {
        let v = self.finite(key, v)?;
        let above = if open_lo { v > lo } else { v >= lo };
        if above && v <= hi {
            Ok(v)
        } else {
            Err(self.err(key, format!("{v} is out of range: {what}")))
        }
    }

    fn vec3(&self, key: &str, v: &[f64]) -> Result<Vector3<f64>, ScenarioError> {
        if v.len() != 3 {
            return Err(self.err(key, format!("needs 3 numbers [x, y, z], got {}", v.len())));
        }
        for x in v {
            self.finite(key, *x)?;
        }
        Ok(Vector3::new(v[0], v[1], v[2]))
    }

    fn unit(&self, key: &str, v: &[f64]) -> Result<Vector3<f64>, ScenarioError> {
        let v = self.vec3(key, v)?;
        let n = v.norm();
        if n.is_nan() || n <= 1e-9 {
            return Err(self.err(
                key,
                "is zero; a direction needs a non-zero vector (it is normalised if not unit)",
            ));
        }
        Ok(v / n)
    }

    pub(super) fn forbid(&self, key: &str, present: bool, why: &str) -> Result<(), ScenarioError> {
        if present {
            Err(self.err(key, format!("does not belong here: {why}")))
        } else {
            Ok(())
        }
    }

    fn need<T: Clone>(&self, key: &str, v: &Option<T>, why: &str) -> Result<T, ScenarioError> {
        v.clone()
            .ok_or_else(|| self.err(key, format!("is missing: {why}")))
    }
}

impl Scenario {
    /// Reads and checks a scenario file; relative file names in it are relative to its folder.
    ///
    /// # Errors
    ///
    /// [`ScenarioError`] naming the file, the key (and line) and the rule.
    pub fn load(path: &Path) -> Result<Self, ScenarioError> {
        let file = path.display().to_string();
        let source = std::fs::read_to_string(path).map_err(|e| ScenarioError {
            file: file.clone(),
            key: String::new(),
            line: None,
            rule: format!("cannot read: {e}"),
        })?;
        Self::parse(&file, &source, path.parent().unwrap_or(Path::new(".")))
    }

    /// Checks scenario text `source` named `file`; relative file names resolve in `dir`.
    ///
    /// # Errors
    ///
    /// [`ScenarioError`] naming the file, the key (and line) and the rule.
    pub fn parse(file: &str, source: &str, dir: &Path) -> Result<Self, ScenarioError> {
        let text = source.strip_prefix('\u{feff}').unwrap_or(source);
        let raw: ScenarioFile =
            toml::from_str(text).map_err(|e| ScenarioError::parse(file, text, &e))?;
        let c = Checker { file, source: text };
        if raw.format != FORMAT {
            return Err(c.err(
                "format",
                format!(
                    "format {} is not known; this reader reads format {FORMAT}",
                    raw.format
                ),
            ));
        }
        if raw.robot != "scara" {
            return Err(c.err(
                "robot",
                format!("unknown robot `{}`; scenarios run on: scara", raw.robot),
            ));
        }
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
        let q0 = match &raw.q0 {
            None => [0.0; 4],
            Some(v) if v.len() == 4 => {
                for x in v {
                    c.finite("q0", *x)?;
                }
                [v[0], v[1], v[2], v[3]]
            }
            Some(v) => {
                return Err(c.err(
                    "q0",
                    format!("needs 4 joint values (rad, rad, m, rad), got {}", v.len()),
                ))
            }
        };
        let end_stops = raw.end_stops.unwrap_or(true);
        let start_on_reference = raw.start_on_reference.unwrap_or(false);
        if start_on_reference && raw.q0.is_some() {
            return Err(c.err(
                "q0",
                "give either q0 or start_on_reference = true, not both",
            ));
        }
        if end_stops && !start_on_reference {
            check_q0_inside(&c, &q0)?;
        }
        let reference = reference(&c, &raw.reference, dir)?;
        let elbow_switch = elbow_switch(&c, &raw.reference)?;
        let surfaces = raw
            .surfaces
            .iter()
            .enumerate()
            .map(|(i, s)| surface(&c, &format!("surfaces[{i}]"), s))
            .collect::<Result<Vec<_>, _>>()?;
        let position = PositionController::parse(&raw.position.law)
            .map_err(|e| c.err("position.law", e.to_string()))?;
        let sensor = sensor(&c, raw.sensor.as_ref())?;
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
                let force = force(&c, f, surfaces.len(), dir)?;
                let selection = selection(&c, s, &sensor)?;
                (Some(force), Some(selection))
            }
        };
        let plant = plant(&c, raw.plant.as_ref())?;
        let controller_model = controller_model(&c, raw.controller_model.as_deref(), dir)?;
        let sweep = raw
            .sweep
            .as_ref()
            .map(|t| crate::sweep::SweepSpec::check(t, &mut |key, rule| c.err(key, rule)))
            .transpose()?;
        Ok(Self {
            plant,
            controller_model,
            sweep,
            file: file.to_string(),
            source: text.to_string(),
            name: raw.name,
            description: raw.description,
            robot: raw.robot,
            duration_s,
            control_dt_s,
            plant_dt_s,
            q0,
            end_stops,
            start_on_reference,
            reference,
            elbow_switch,
            surfaces,
            position,
            force,
            selection,
            sensor,
        })
    }

    /// An error about `key` of this scenario, with its line.
    #[must_use]
    pub fn error(&self, key: &str, rule: impl Into<String>) -> ScenarioError {
        ScenarioError::at(&self.file, &self.source, key, rule)
    }
}

fn check_q0_inside(c: &Checker<'_>, q0: &[f64; 4]) -> Result<(), ScenarioError> {
    use crate::model::{RobotModel, Scara};
    let (lo, hi) = (Scara.lower_limits(), Scara.upper_limits());
    for i in 0..4 {
        if !(lo[i] <= q0[i] && q0[i] <= hi[i]) {
            return Err(c.err("q0", format!(
                "joint {} = {} is outside its limits [{:.4}, {:.4}]; with end_stops = true the run must start inside them (or set end_stops = false)",
                <Scara as RobotModel<4>>::JOINT_NAMES[i], q0[i], lo[i], hi[i]
            )));
        }
    }
    Ok(())
}

fn reference(
    c: &Checker<'_>,
    r: &ReferenceTable,
    dir: &Path,
) -> Result<ReferenceSpec, ScenarioError> {
    let only = |keys: &[(&str, bool)], kind: &str| -> Result<(), ScenarioError> {
        for (k, present) in keys {
            c.forbid(
                &format!("reference.{k}"),
                *present,
                &format!("not a key of kind = \"{kind}\""),
            )?;
        }
        Ok(())
    };
    match r.kind.as_str() {
        "thesis" => {
            only(
                &[
                    ("points", r.points.is_some()),
                    ("interpolation", r.interpolation.is_some()),
                    ("file", r.file.is_some()),
                ],
                "thesis",
            )?;
            let name = c.need(
                "reference.name",
                &r.name,
                "a thesis reference: position, contact or three-zone",
            )?;
            if name != "contact" {
                c.forbid(
                    "reference.surface_z_m",
                    r.surface_z_m.is_some(),
                    "only the contact reference has it",
                )?;
            }
            Ok(ReferenceSpec::Thesis(match name.as_str() {
                "position" => ThesisReference::Position,
                "three-zone" => ThesisReference::ThreeZone,
                "contact" => ThesisReference::Contact {
                    surface_z_m: c
                        .finite("reference.surface_z_m", r.surface_z_m.unwrap_or(0.13))?,
                },
                other => {
                    return Err(c.err(
                        "reference.name",
                        format!(
                        "unknown thesis reference `{other}`; known: position, contact, three-zone"
                    ),
                    ))
                }
            }))
        }
        "waypoints" => {
            only(
                &[
                    ("name", r.name.is_some()),
                    ("surface_z_m", r.surface_z_m.is_some()),
                    ("file", r.file.is_some()),
                ],
                "waypoints",
            )?;
            let how = c.need(
                "reference.interpolation",
                &r.interpolation,
                "\"linear\" or \"quintic\"",
            )?;
            let interpolation = Interpolation::parse(&how).ok_or_else(|| {
                c.err(
                    "reference.interpolation",
                    format!("unknown interpolation `{how}`; known: linear, quintic"),
                )
            })?;
            let rows = c.need(
                "reference.points",
                &r.points,
                "rows [t, x, y, z, yaw] (s, m, m, m, rad)",
            )?;
            let mut points = Vec::with_capacity(rows.len());
            for (i, row) in rows.iter().enumerate() {
                if row.len() != 5 {
                    return Err(c.err("reference.points", format!("row {i} has {} numbers; each row is [t, x, y, z, yaw] (s, m, m, m, rad)", row.len())));
                }
                points.push(PoseSample::with_yaw(
                    row[0],
                    Vector3::new(row[1], row[2], row[3]),
                    row[4],
                ));
            }
            Waypoints::new(&points, interpolation)
                .map(ReferenceSpec::Waypoints)
                .map_err(|e| c.err("reference.points", e.to_string()))
        }
        "csv" => {
            only(
                &[
                    ("name", r.name.is_some()),
                    ("surface_z_m", r.surface_z_m.is_some()),
                    ("points", r.points.is_some()),
                    ("interpolation", r.interpolation.is_some()),
                ],
                "csv",
            )?;
            let name = c.need(
                "reference.file",
                &r.file,
                "a CSV file with header t,x,y,z,yaw",
            )?;
            let path = dir.join(&name);
            let f = std::fs::File::open(&path).map_err(|e| {
                c.err(
                    "reference.file",
                    format!("cannot open {}: {e}", path.display()),
                )
            })?;
            let t = SampledTrajectory::from_csv_reader(std::io::BufReader::new(f))
                .map_err(|e| c.err("reference.file", format!("{}: {e}", path.display())))?;
            Ok(ReferenceSpec::Csv(path, t))
        }
        other => Err(c.err(
            "reference.kind",
            format!("unknown kind `{other}`; known: thesis, waypoints, csv"),
        )),
    }
}

fn elbow_switch(c: &Checker<'_>, r: &ReferenceTable) -> Result<ElbowSwitchSpec, ScenarioError> {
    let planned_keys = [
        ("max_effort_share", r.max_effort_share.is_some()),
        ("clearance_z_m", r.clearance_z_m.is_some()),
        ("pause_ramp_s", r.pause_ramp_s.is_some()),
    ];
    match r.elbow_switch.as_deref().unwrap_or("planned") {
        "step" => {
            for (k, present) in planned_keys {
                c.forbid(
                    &format!("reference.{k}"),
                    present,
                    "a key of elbow_switch = \"planned\"",
                )?;
            }
            Ok(ElbowSwitchSpec::Step)
        }
        "planned" => {
            let d = FlipOptions::default();
            Ok(ElbowSwitchSpec::Planned(FlipOptions {
                max_effort_share: c.range(
                    "reference.max_effort_share",
                    r.max_effort_share.unwrap_or(d.max_effort_share),
                    0.0,
                    1.0,
                    true,
                    "a share of the effort limits, > 0 and <= 1",
                )?,
                clearance_z_m: r
                    .clearance_z_m
                    .map(|z| c.finite("reference.clearance_z_m", z))
                    .transpose()?,
                ramp_s: c.range(
                    "reference.pause_ramp_s",
                    r.pause_ramp_s.unwrap_or(d.ramp_s),
                    0.0,
                    10.0,
                    true,
                    "a time in s, > 0 and <= 10",
                )?,
                clearance_margin_m: d.clearance_margin_m,
                min_move_s: d.min_move_s,
                sample_dt_s: d.sample_dt_s,
            }))
        }
        other => Err(c.err(
            "reference.elbow_switch",
            format!("unknown elbow switch `{other}`; known: planned, step"),
        )),
    }
}

fn surface(c: &Checker<'_>, key: &str, s: &SurfaceTable) -> Result<ContactSurface, ScenarioError> {
    let k = |name: &str| format!("{key}.{name}");
    let point = c.vec3(&k("point"), &c.need(&k("point"), &s.point, "a point in m")?)?;
    let radius = |c: &Checker<'_>| -> Result<f64, ScenarioError> {
        let r = c.need(&k("radius"), &s.radius, "a radius in m")?;
        c.range(
            &k("radius"),
            r,
            0.0,
            100.0,
            true,
            "a radius in m, > 0 and <= 100",
        )
    };
    let geometry = match s.kind.as_str() {
        "plane" => {
            c.forbid(
                &k("axis"),
                s.axis.is_some(),
                "a plane has a normal, not an axis",
            )?;
            c.forbid(&k("radius"), s.radius.is_some(), "a plane has no radius")?;
            let normal = c.unit(
                &k("normal"),
                &c.need(&k("normal"), &s.normal, "the outward normal")?,
            )?;
            let he = c.need(
                &k("half_extent"),
                &s.half_extent,
                "the patch's half sizes [a, b] in m",
            )?;
            if he.len() != 2 {
                return Err(c.err(
                    &k("half_extent"),
                    format!("needs 2 half sizes [a, b] in m, got {}", he.len()),
                ));
            }
            for v in &he {
                c.range(
                    &k("half_extent"),
                    *v,
                    0.0,
                    100.0,
                    true,
                    "half sizes in m, > 0",
                )?;
            }
            SurfaceGeometry::plane(point, normal, [he[0], he[1]])
        }
        "sphere" => {
            for (name, present) in [
                ("normal", s.normal.is_some()),
                ("axis", s.axis.is_some()),
                ("half_extent", s.half_extent.is_some()),
            ] {
                c.forbid(
                    &k(name),
                    present,
                    "a sphere has a centre (`point`) and a radius only",
                )?;
            }
            SurfaceGeometry::Sphere {
                centre: point,
                radius: radius(c)?,
            }
        }
        "cylinder" => {
            c.forbid(
                &k("normal"),
                s.normal.is_some(),
                "a cylinder has an axis, not a normal",
            )?;
            c.forbid(
                &k("half_extent"),
                s.half_extent.is_some(),
                "a cylinder is infinitely long",
            )?;
            let axis = c.unit(
                &k("axis"),
                &c.need(&k("axis"), &s.axis, "the axis direction")?,
            )?;
            SurfaceGeometry::Cylinder {
                point,
                axis,
                radius: radius(c)?,
            }
        }
        other => {
            return Err(c.err(
                &k("kind"),
                format!("unknown surface kind `{other}`; known: plane, sphere, cylinder"),
            ))
        }
    };
    Ok(ContactSurface {
        geometry,
        stiffness: c.range(
            &k("stiffness"),
            s.stiffness,
            0.0,
            1e9,
            true,
            "a stiffness in N/m, > 0",
        )?,
        damping: c.range(
            &k("damping"),
            s.damping.unwrap_or(0.0),
            0.0,
            1e7,
            false,
            "a damping in N s/m, >= 0",
        )?,
        friction: c.range(
            &k("friction"),
            s.friction.unwrap_or(0.0),
            0.0,
            MAX_FRICTION,
            false,
            "a Coulomb coefficient, >= 0 and <= 2",
        )?,
    })
}

fn force(
    c: &Checker<'_>,
    f: &ForceTable,
    surfaces: usize,
    dir: &Path,
) -> Result<ForceSpec, ScenarioError> {
    let law = ForceController::parse(&f.law).map_err(|e| c.err("force.law", e.to_string()))?;
    let default_kvd = match law {
        ForceController::PiFf => 0.0,
        _ => 2000.0,
    };
    let laws = super::law_spec::parse(c, f, law)?;
    let gain = |key: &str, v: Option<f64>, default: f64, unit: &str| {
        c.range(
            key,
            v.unwrap_or(default),
            0.0,
            1e7,
            false,
            &format!("a gain in {unit}, >= 0"),
        )
    };
    let gains = (
        gain("force.kfp", f.kfp, 20.0, "1")?,
        gain("force.kfi", f.kfi, 5.0, "1/s")?,
        gain("force.kvd", f.kvd, default_kvd, "N s/m")?,
    );
    if surfaces == 0 {
        return Err(c.err(
            "force",
            "force control needs at least one [[surfaces]] entry to press on",
        ));
    }
    let surface = f.surface.unwrap_or(0);
    if surface >= surfaces {
        return Err(c.err(
            "force.surface",
            format!("surface {surface} does not exist; there are {surfaces} (from 0)"),
        ));
    }
    let reference = match f.reference.as_str() {
        "constant" => ForceReferenceSpec::Constant,
        "thesis-variable" => ForceReferenceSpec::ThesisVariable,
        "csv" => {
            let name = c.need("force.file", &f.file, "a CSV file with header t,f (s, N)")?;
            let path = dir.join(&name);
            let file = std::fs::File::open(&path)
                .map_err(|e| c.err("force.file", format!("cannot open {}: {e}", path.display())))?;
            ForceReferenceSpec::Csv(
                SampledForce::from_csv_reader(std::io::BufReader::new(file))
                    .map_err(|e| c.err("force.file", format!("{}: {e}", path.display())))?,
            )
        }
        other => {
            return Err(c.err(
                "force.reference",
                format!("unknown force reference `{other}`; known: constant, thesis-variable, csv"),
            ))
        }
    };
    if !matches!(reference, ForceReferenceSpec::Csv(_)) {
        c.forbid(
            "force.file",
            f.file.is_some(),
            "only reference = \"csv\" reads a file",
        )?;
    }
    let value_n = match (&reference, f.value) {
        (ForceReferenceSpec::Csv(s), None) => s.max(),
        (_, v) => {
            let v = c.need("force.value", &v, "the magnitude of the normal force in N")?;
            c.range("force.value", v, 0.0, MAX_FORCE_N, true, "a force magnitude in N, > 0 and <= 100 kN (more is most likely a wrong unit; the push's direction comes from the surface normal)")?
        }
    };
    Ok(ForceSpec {
        law,
        gains,
        reference,
        value_n,
        friction_feedforward: c.range(
            "force.friction_feedforward",
            f.friction_feedforward.unwrap_or(0.0),
            0.0,
            MAX_FRICTION,
            false,
            "a Coulomb coefficient, >= 0 and <= 2",
        )?,
        gravity_compensation: f.gravity_compensation.unwrap_or(true),
        anti_windup: f.anti_windup.unwrap_or(true),
        surface,
        expected_shift_m: c.range(
            "force.expected_shift_m",
            f.expected_shift_m.unwrap_or(0.0),
            -0.1,
            0.1,
            false,
            "a shift in m, within +-0.1 m",
        )?,
        laws,
    })
}

fn selection(
    c: &Checker<'_>,
    s: &SelectionTable,
    sensor: &SensorSpec,
) -> Result<SelectionPolicy, ScenarioError> {
    let contact_keys = [
        ("threshold_n", s.threshold_n.is_some()),
        ("debounce_s", s.debounce_s.is_some()),
        ("ramp_s", s.ramp_s.is_some()),
        ("approach_speed_m_s", s.approach_speed_m_s.is_some()),
        ("loss_s", s.loss_s.is_some()),
    ];
    match s.mode.as_str() {
        "time" => {
            for (k, present) in contact_keys {
                c.forbid(
                    &format!("selection.{k}"),
                    present,
                    "a key of mode = \"contact\"",
                )?;
            }
            let t = c.need("selection.switch_s", &s.switch_s, "the switch time in s")?;
            Ok(SelectionPolicy::Time {
                switch_s: c.range(
                    "selection.switch_s",
                    t,
                    0.0,
                    1e5,
                    false,
                    "a time in s, >= 0",
                )?,
            })
        }
        "contact" => {
            c.forbid(
                "selection.switch_s",
                s.switch_s.is_some(),
                "mode = \"contact\" switches on contact, not at a time",
            )?;
            let d = ContactSwitch::for_sensor(sensor.noise_n, sensor.bias_n);
            Ok(SelectionPolicy::Contact(ContactSwitch {
                threshold_n: c.range(
                    "selection.threshold_n",
                    s.threshold_n.unwrap_or(d.threshold_n),
                    0.0,
                    MAX_FORCE_N,
                    true,
                    "a force in N, > 0",
                )?,
                debounce_s: c.range(
                    "selection.debounce_s",
                    s.debounce_s.unwrap_or(d.debounce_s),
                    0.0,
                    1.0,
                    false,
                    "a time in s, >= 0 and <= 1",
                )?,
                ramp_s: c.range(
                    "selection.ramp_s",
                    s.ramp_s.unwrap_or(d.ramp_s),
                    0.0,
                    10.0,
                    false,
                    "a time in s, >= 0 and <= 10",
                )?,
                approach_speed_m_s: c.range(
                    "selection.approach_speed_m_s",
                    s.approach_speed_m_s.unwrap_or(d.approach_speed_m_s),
                    0.0,
                    1.0,
                    true,
                    "a speed in m/s, > 0 and <= 1",
                )?,
                loss_s: c.range(
                    "selection.loss_s",
                    s.loss_s.unwrap_or(d.loss_s),
                    0.0,
                    10.0,
                    false,
                    "a time in s, >= 0 and <= 10",
                )?,
            }))
        }
        other => Err(c.err(
            "selection.mode",
            format!("unknown mode `{other}`; known: time, contact"),
        )),
    }
}

fn sensor(
    c: &Checker<'_>,
    s: Option<&super::file::SensorTable>,
) -> Result<SensorSpec, ScenarioError> {
    let Some(s) = s else {
        return Ok(SensorSpec {
            noise_n: 0.0,
            bias_n: 0.0,
            cutoff_hz: None,
            seed: 1,
        });
    };
    Ok(SensorSpec {
        noise_n: c.range(
            "sensor.noise_n",
            s.noise_n.unwrap_or(0.0),
            0.0,
            MAX_FORCE_N,
            false,
            "a standard deviation in N, >= 0",
        )?,
        bias_n: c.range(
            "sensor.bias_n",
            s.bias_n.unwrap_or(0.0),
            -MAX_FORCE_N,
            MAX_FORCE_N,
            false,
            "a bias in N",
        )?,
        cutoff_hz: s
            .cutoff_hz
            .map(|v| {
                c.range(
                    "sensor.cutoff_hz",
                    v,
                    0.0,
                    1e6,
                    true,
                    "a frequency in Hz, > 0",
                )
            })
            .transpose()?,
        seed: s.seed.unwrap_or(1),
    })
}

/// `n` numbers at `key`, each checked by `ok` (rule `what`), or `default` when absent.
fn numbers<const N: usize>(
    c: &Checker<'_>,
    key: &str,
    v: Option<&Vec<f64>>,
    default: f64,
    ok: impl Fn(f64) -> bool,
    what: &str,
) -> Result<[f64; N], ScenarioError> {
    let Some(v) = v else {
        return Ok([default; N]);
    };
    if v.len() != N {
        return Err(c.err(key, format!("needs {N} numbers ({what}), got {}", v.len())));
    }
    let mut out = [0.0; N];
    for (i, x) in v.iter().enumerate() {
        if !(x.is_finite() && ok(*x)) {
            return Err(c.err(key, format!("entry {i} = {x} is out of range: {what}")));
        }
        out[i] = *x;
    }
    Ok(out)
}

fn plant(c: &Checker<'_>, p: Option<&PlantTable>) -> Result<PlantSpec, ScenarioError> {
    let Some(p) = p else {
        return Ok(PlantSpec::default());
    };
    let scale = "a scale factor, > 0 and <= 10";
    let com_offset_m = match &p.com_offset_m {
        None => [[0.0; 3]; 4],
        Some(rows) if rows.len() == 4 => {
            let mut out = [[0.0; 3]; 4];
            for (j, row) in rows.iter().enumerate() {
                out[j] = numbers::<3>(
                    c,
                    "plant.com_offset_m",
                    Some(row),
                    0.0,
                    |x| x.abs() <= 1.0,
                    "an offset in m per axis, within +-1 m",
                )?;
            }
            out
        }
        Some(rows) => {
            return Err(c.err(
                "plant.com_offset_m",
                format!(
                    "needs 4 rows [dx, dy, dz] (m), one per link, got {}",
                    rows.len()
                ),
            ))
        }
    };
    let spec = PlantSpec {
        mass_scale: numbers(
            c,
            "plant.mass_scale",
            p.mass_scale.as_ref(),
            1.0,
            |x| x > 0.0 && x <= 10.0,
            scale,
        )?,
        com_offset_m,
        inertia_scale: numbers(
            c,
            "plant.inertia_scale",
            p.inertia_scale.as_ref(),
            1.0,
            |x| x > 0.0 && x <= 10.0,
            scale,
        )?,
        payload_kg: c.range(
            "plant.payload_kg",
            p.payload_kg.unwrap_or(0.0),
            0.0,
            100.0,
            false,
            "a mass in kg, >= 0 and <= 100",
        )?,
        payload_offset_m: numbers(
            c,
            "plant.payload_offset_m",
            p.payload_offset_m.as_ref(),
            0.0,
            |x| x.abs() <= 1.0,
            "a position in m in link 4's frame, within +-1 m",
        )?,
        friction_viscous: numbers(
            c,
            "plant.friction_viscous",
            p.friction_viscous.as_ref(),
            0.0,
            |x| (0.0..=1e5).contains(&x),
            "N m s/rad or N s/m, >= 0",
        )?,
        friction_coulomb: numbers(
            c,
            "plant.friction_coulomb",
            p.friction_coulomb.as_ref(),
            0.0,
            |x| (0.0..=1e4).contains(&x),
            "N m or N, >= 0",
        )?,
        friction_smoothing: c.range(
            "plant.friction_smoothing",
            p.friction_smoothing
                .unwrap_or(crate::sim::friction::DEFAULT_SMOOTHING),
            0.0,
            10.0,
            true,
            "a velocity in rad/s or m/s, > 0",
        )?,
    };
    Ok(spec)
}

fn controller_model(
    c: &Checker<'_>,
    v: Option<&str>,
    dir: &Path,
) -> Result<ControllerModel, ScenarioError> {
    match v {
        None | Some("nominal") => Ok(ControllerModel::Nominal),
        Some(name) => {
            let file = dir.join(name);
            let model = crate::identification::file::read_model(&file, crate::model::Scara)
                .map_err(|e| c.err("controller_model", e.to_string()))?;
            Ok(ControllerModel::Identified {
                file,
                model: Box::new(model),
            })
        }
    }
}
