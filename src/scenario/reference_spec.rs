//! `[reference]` checked: the motion reference (a robot's named reference, waypoints with
//! full poses, a CSV of poses or of joints), the inverse kinematics' settings, and the keys
//! the robot reads itself (a SCARA's elbow switch), which no other robot has.

use std::path::{Path, PathBuf};

use nalgebra::Vector3;

use super::check::Checker;
use super::error::ScenarioError;
use super::file::{field_names, ReferenceTable};
use super::vocabulary::{KeyError, RobotVocabulary};
use crate::target::{orientation, PoseSample};
use crate::trajectory::waypoints::{Interpolation, Waypoints};
use crate::trajectory::{JointReference, SampledTrajectory};

/// The motion reference.
#[derive(Clone, Debug, PartialEq)]
pub enum ReferenceSpec {
    /// A named reference of the robot (`kind = "thesis"`: the SCARA's thesis references).
    Named {
        /// Its name.
        name: String,
        /// The height of a contact reference's on-surface part, m, where it has one.
        surface_z_m: Option<f64>,
    },
    /// Waypoints.
    Waypoints(Waypoints),
    /// A CSV file of poses (its path, as resolved, and its samples).
    Csv(PathBuf, SampledTrajectory),
    /// A CSV file of joints `t,q1..qN` (its path, as resolved, and its text, checked).
    Joints(PathBuf, String),
}

/// The inverse kinematics' settings (`[reference]` keys).
#[derive(Clone, Debug, PartialEq)]
pub struct IkSettings {
    /// Position tolerance, m.
    pub tolerance_m: f64,
    /// Orientation tolerance, rad.
    pub tolerance_rad: f64,
    /// Iteration cap per start.
    pub max_iterations: usize,
    /// Joints the first point's solve starts from.
    pub seed: Option<Vec<f64>>,
    /// The posture a redundant arm is drawn to.
    pub posture: Option<Vec<f64>>,
    /// The joints' weights in the distance to the posture.
    pub posture_weights: Option<Vec<f64>>,
}

/// Default position tolerance of a scenario's inverse kinematics, m.
pub const IK_TOLERANCE_M: f64 = 1e-10;
/// Default orientation tolerance, rad.
pub const IK_TOLERANCE_RAD: f64 = 1e-10;
/// Default iteration cap.
pub const IK_MAX_ITERATIONS: usize = 100;

impl Default for IkSettings {
    fn default() -> Self {
        Self {
            tolerance_m: IK_TOLERANCE_M,
            tolerance_rad: IK_TOLERANCE_RAD,
            max_iterations: IK_MAX_ITERATIONS,
            seed: None,
            posture: None,
            posture_weights: None,
        }
    }
}

/// What reading a scenario file needs of its robot: its facts, and the checks that need its
/// type, as functions of that type (so the reader itself is not generic).
pub(super) struct RobotFacts {
    pub(super) name: String,
    pub(super) dof: usize,
    pub(super) named: &'static [&'static str],
    /// The robot's own `[reference]` keys, and their check.
    pub(super) reference_keys: &'static [&'static str],
    pub(super) check_reference_keys: fn(&toml::Table) -> Result<(), KeyError>,
    /// Joint limits `[lower, upper]` and names, base to tip.
    pub(super) limits: Vec<[f64; 2]>,
    pub(super) joint_names: Vec<&'static str>,
    /// Whether the named reference exists for the robot (built to be sure).
    pub(super) named_reference_exists: fn(&str, Option<f64>) -> bool,
    /// A joint CSV read for the robot's joint count, or the reader's message.
    pub(super) check_joint_csv: fn(&str) -> Result<(), String>,
    /// An identification file read for the robot: its standard parameters.
    pub(super) read_identified: fn(&Path) -> Result<Vec<f64>, String>,
}

/// The facts of robot `R`.
pub(super) fn facts_of<const N: usize, R: RobotVocabulary<N>>() -> RobotFacts {
    RobotFacts {
        name: R::NAME.to_string(),
        dof: N,
        named: R::named_references(),
        reference_keys: R::reference_keys(),
        check_reference_keys: R::check_reference_keys,
        limits: R::JOINT_LIMITS.to_vec(),
        joint_names: R::JOINT_NAMES.to_vec(),
        named_reference_exists: |name, z| R::named_reference(name, z).is_some(),
        check_joint_csv: |text| {
            JointReference::<N>::from_csv_reader_named(text.as_bytes(), &R::JOINT_NAMES)
                .map(|_| ())
                .map_err(|e| e.to_string())
        },
        read_identified: |file| {
            crate::identification::file::read_model(file, R::default())
                .map(|m| m.parameters().as_ref().to_vec())
                .map_err(|e| e.to_string())
        },
    }
}

/// The facts of the registry's robot `name`, `None` if there is no such robot.
pub(super) fn robot_facts(name: &str) -> Option<RobotFacts> {
    crate::with_robot_named!(name, |_robot: R, N, _module| facts_of::<N, R>())
}

/// Each value of `[reference] kind`, with the keys that only it, among the kinds, takes.
const KINDS: [(&str, &[&str]); 4] = [
    ("thesis", &["name", "surface_z_m"]),
    ("waypoints", &["points", "interpolation"]),
    ("csv", &["file"]),
    ("joints", &["file"]),
];

/// Refuses a key of `[reference]` (`table`, as the file has it) that belongs to other kinds
/// than `kind`, naming the first.
fn forbid_other_kinds_keys(
    c: &Checker<'_>,
    kind: &str,
    table: Option<&toml::Table>,
) -> Result<(), ScenarioError> {
    let Some((_, own)) = KINDS.iter().find(|(k, _)| *k == kind) else {
        return Ok(());
    };
    let of_a_kind = |key: &str| KINDS.iter().any(|(_, keys)| keys.contains(&key));
    for key in table.into_iter().flat_map(toml::Table::keys) {
        c.forbid(
            &format!("reference.{key}"),
            of_a_kind(key) && !own.contains(&key.as_str()),
            &format!("not a key of kind = \"{kind}\""),
        )?;
    }
    Ok(())
}

/// `[reference]` checked (`r` as read, `table` as the file has it), its files read from
/// `dir`.
pub(super) fn reference(
    c: &Checker<'_>,
    r: &ReferenceTable,
    table: Option<&toml::Table>,
    dir: &Path,
    robot: &RobotFacts,
) -> Result<ReferenceSpec, ScenarioError> {
    forbid_other_kinds_keys(c, &r.kind, table)?;
    match r.kind.as_str() {
        "thesis" => {
            if robot.named.is_empty() {
                return Err(c.err(
                    "reference.kind",
                    format!(
                        "robot `{}` has no thesis references (they are the SCARA's); give waypoints, a csv of poses or of joints",
                        robot.name
                    ),
                ));
            }
            let name = c.need(
                "reference.name",
                &r.name,
                &format!("a thesis reference: {}", robot.named.join(", ")),
            )?;
            if name != "contact" {
                c.forbid(
                    "reference.surface_z_m",
                    r.surface_z_m.is_some(),
                    "only the contact reference has it",
                )?;
            }
            let surface_z_m = r
                .surface_z_m
                .map(|z| c.finite("reference.surface_z_m", z))
                .transpose()?;
            if !robot.named.contains(&name.as_str())
                || !(robot.named_reference_exists)(&name, surface_z_m)
            {
                return Err(c.err(
                    "reference.name",
                    format!(
                        "unknown thesis reference `{name}`; known: {}",
                        robot.named.join(", ")
                    ),
                ));
            }
            Ok(ReferenceSpec::Named { name, surface_z_m })
        }
        "waypoints" => {
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
                "rows [t, x, y, z, roll, pitch, yaw] (s, m, m, m, rad, rad, rad) or [t, x, y, z, yaw]",
            )?;
            let mut points = Vec::with_capacity(rows.len());
            for (i, row) in rows.iter().enumerate() {
                let position = |row: &[f64]| Vector3::new(row[1], row[2], row[3]);
                points.push(match row.len() {
                    7 => PoseSample::new(
                        row[0],
                        position(row),
                        orientation::from_rpy(row[4], row[5], row[6]),
                    ),
                    5 => PoseSample::with_yaw(row[0], position(row), row[4]),
                    n => return Err(c.err("reference.points", format!("row {i} has {n} numbers; each row is [t, x, y, z, roll, pitch, yaw] (s, m, m, m, rad, rad, rad; fixed axes x-y-z) or [t, x, y, z, yaw]"))),
                });
            }
            Waypoints::new(&points, interpolation)
                .map(ReferenceSpec::Waypoints)
                .map_err(|e| c.err("reference.points", e.to_string()))
        }
        "csv" => {
            let name = c.need(
                "reference.file",
                &r.file,
                "a CSV file with header t,x,y,z,roll,pitch,yaw (or t,x,y,z,yaw)",
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
        "joints" => {
            let header = (1..=robot.dof)
                .map(|i| format!("q{i}"))
                .collect::<Vec<_>>()
                .join(",");
            let name = c.need(
                "reference.file",
                &r.file,
                &format!("a CSV file with header t,{header} (s, rad or m)"),
            )?;
            let path = dir.join(&name);
            let text = std::fs::read_to_string(&path).map_err(|e| {
                c.err(
                    "reference.file",
                    format!("cannot read {}: {e}", path.display()),
                )
            })?;
            match (robot.check_joint_csv)(&text) {
                Ok(()) => Ok(ReferenceSpec::Joints(path, text)),
                Err(e) => Err(c.err(
                    "reference.file",
                    format!(
                        "{} (robot `{}`, {} joints): {e}",
                        path.display(),
                        robot.name,
                        robot.dof
                    ),
                )),
            }
        }
        other => Err(c.err(
            "reference.kind",
            format!(
                "unknown kind `{other}`; known: {}",
                KINDS.map(|(kind, _)| kind).join(", ")
            ),
        )),
    }
}

/// The robot's own keys of `[reference]` (`table`, as the file has it), checked by the
/// robot; any key that is neither the robot's nor of [`ReferenceTable`] is refused, naming the
/// robots whose key it is.
pub(super) fn robot_keys(
    c: &Checker<'_>,
    table: Option<&toml::Table>,
    robot: &RobotFacts,
) -> Result<toml::Table, ScenarioError> {
    let generic = field_names::<ReferenceTable>();
    let mut own = toml::Table::new();
    for (key, value) in table.into_iter().flatten() {
        if generic.contains(&key.as_str()) {
            continue;
        }
        if robot.reference_keys.contains(&key.as_str()) {
            own.insert(key.clone(), value.clone());
            continue;
        }
        let owners: Vec<&str> = crate::model::ROBOTS
            .iter()
            .copied()
            .filter(|name| {
                crate::with_robot_named!(*name, |_robot: R, N, _module| {
                    R::reference_keys().contains(&key.as_str())
                })
                .unwrap_or(false)
            })
            .collect();
        let whose = if owners.is_empty() {
            String::new()
        } else {
            format!(
                " (`{key}` is robot {}'s, not `{}`'s)",
                owners
                    .iter()
                    .map(|o| format!("`{o}`"))
                    .collect::<Vec<_>>()
                    .join(", "),
                robot.name
            )
        };
        let known: Vec<String> = generic
            .iter()
            .chain(robot.reference_keys)
            .map(|k| format!("`{k}`"))
            .collect();
        return Err(c.err(
            &format!("reference.{key}"),
            format!(
                "unknown field `{key}`, expected one of {}{whose}",
                known.join(", ")
            ),
        ));
    }
    (robot.check_reference_keys)(&own)
        .map_err(|e| c.err(&format!("reference.{}", e.key), e.rule))?;
    Ok(own)
}

pub(super) fn ik_settings(
    c: &Checker<'_>,
    r: &ReferenceTable,
    robot: &RobotFacts,
) -> Result<IkSettings, ScenarioError> {
    let d = IkSettings::default();
    let joints = |key: &str, v: &Option<Vec<f64>>, what: &str| {
        v.as_ref()
            .map(|v| c.joints(key, v, robot.dof, &robot.name, what))
            .transpose()
    };
    Ok(IkSettings {
        tolerance_m: c.range(
            "reference.ik_tolerance_m",
            r.ik_tolerance_m.unwrap_or(d.tolerance_m),
            0.0,
            1e-3,
            true,
            "a distance in m, > 0 and <= 1 mm",
        )?,
        tolerance_rad: c.range(
            "reference.ik_tolerance_rad",
            r.ik_tolerance_rad.unwrap_or(d.tolerance_rad),
            0.0,
            1e-2,
            true,
            "an angle in rad, > 0 and <= 0.01",
        )?,
        max_iterations: match r.ik_max_iterations {
            None => d.max_iterations,
            Some(n) if (1..=100_000).contains(&n) => n,
            Some(n) => {
                return Err(c.err(
                    "reference.ik_max_iterations",
                    format!("{n} is out of range: an iteration cap from 1 to 100000"),
                ))
            }
        },
        seed: joints(
            "reference.seed",
            &r.seed,
            "the joints the first solve starts from",
        )?,
        posture: joints("reference.posture", &r.posture, "the posture")?,
        posture_weights: match &r.posture_weights {
            None => None,
            Some(w) => {
                c.forbid(
                    "reference.posture_weights",
                    r.posture.is_none(),
                    "weights of a posture: give reference.posture too",
                )?;
                let w = c.joints(
                    "reference.posture_weights",
                    w,
                    robot.dof,
                    &robot.name,
                    "the posture's weights",
                )?;
                for x in &w {
                    c.range(
                        "reference.posture_weights",
                        *x,
                        0.0,
                        1e6,
                        true,
                        "a weight, > 0",
                    )?;
                }
                Some(w)
            }
        },
    })
}
