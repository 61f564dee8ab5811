//! The scenario file format (`scenarios/*.toml`, `format = 1`) as written: serde structures
//! that refuse unknown keys and wrong types, with the key names and SI units of the format.
//! The checking stage (`spec`) checks the values and turns them into a runnable [`super::Scenario`].
//!
//! Every key ends in its unit where it has one (`_s`, `_m`, `_n`, `_hz`, `_m_s`), except the
//! surface and force keys whose names the format fixes (`stiffness` N/m, `damping` N s/m,
//! `friction` 1, `point`/`radius`/`half_extent` m, `value` N).

use serde::Deserialize;

/// A whole scenario file. Its nested tables refuse unknown keys; the reader checks the
/// top-level keys against its [`field_names`] itself, so that tools of their own (a sweep's
/// `[sweep]`) can keep a table in the same file.
#[derive(Debug, Clone, Deserialize)]
pub struct ScenarioFile {
    /// Format version: 1.
    pub format: i64,
    /// Short name (used in reports).
    pub name: String,
    /// One line saying what the scenario shows.
    #[serde(default)]
    pub description: String,
    /// Robot: the name of any generated robot (`robots/<name>.toml`).
    pub robot: String,
    /// Length of the run, s (default: the reference's length).
    pub duration_s: Option<f64>,
    /// Controller sample period, s (default 0.001).
    pub control_dt_s: Option<f64>,
    /// RK4 plant step, s (default 0.001).
    pub plant_dt_s: Option<f64>,
    /// Initial joint positions, one per joint, rad or m (default all zero).
    pub q0: Option<Vec<f64>>,
    /// Start at rest on the reference's first point (its inverse kinematics), instead of `q0`.
    pub start_on_reference: Option<bool>,
    /// Joint end stops in the plant (default true; the thesis reproductions say false).
    pub end_stops: Option<bool>,
    /// The motion reference.
    pub reference: ReferenceTable,
    /// Contact surfaces (none: free space), each a table with its `kind` (a shape of
    /// [`SurfaceGeometry::KINDS`](crate::contact::SurfaceGeometry::KINDS)), the shape's own
    /// keys and `stiffness` (N/m), `damping` (N s/m, default 0) and `friction` (Coulomb,
    /// default 0); checked by `surface_spec`.
    #[serde(default)]
    pub surfaces: Vec<toml::Table>,
    /// The position loop: its `law` and that law's keys; checked by `spec`.
    pub position: toml::Table,
    /// The force loop (absent: a position-only trial).
    pub force: Option<ForceTable>,
    /// When force is controlled (required with `[force]`): its `mode` and that mode's keys;
    /// checked by `force_spec`.
    pub selection: Option<toml::Table>,
    /// The force sensor the controller reads (default: ideal).
    pub sensor: Option<SensorTable>,
    /// The plant's own inertial parameters and joint friction (default: the description's,
    /// no friction).
    pub plant: Option<super::plant::PlantTable>,
    /// The controller's model: `"nominal"` (default) or an `identification.json` of the
    /// scenario's robot (relative to the scenario file).
    pub controller_model: Option<String>,
    /// Rotor inertia the controller's model adds at each joint (`M + diag(a)`), kg m^2 or kg
    /// (default none): a drive's armature the description of the links leaves out.
    pub controller_armature: Option<Vec<f64>>,
    /// The metrics' settings.
    pub metrics: Option<MetricsTable>,
    /// The safety supervisor (default: on, with its defaults).
    pub safety: Option<super::safety_spec::SafetyTable>,
    /// Faults injected into the run (default: none), each a table with its `kind` and that
    /// kind's keys; checked by `fault_spec`.
    #[serde(default)]
    pub faults: Vec<toml::Table>,
}

/// `[metrics]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MetricsTable {
    /// Start of the window of the pose tracking metrics, s (default 2, the thesis's).
    pub after_s: Option<f64>,
}

/// `[reference]`: the keys of every robot. A robot's own keys (a SCARA's elbow switch,
/// [`RobotVocabulary::reference_keys`](super::RobotVocabulary::reference_keys)) are read by
/// the robot; any other key is refused by the reader, against [`field_names`] of this table.
#[derive(Debug, Clone, Deserialize)]
pub struct ReferenceTable {
    /// `"thesis"`, `"waypoints"`, `"csv"` or `"joints"`.
    pub kind: String,
    /// Thesis reference: `"position"` (eq. 4.16), `"contact"` (B.3) or `"three-zone"`.
    pub name: Option<String>,
    /// Thesis contact reference: the height its on-surface part runs at, m (default 0.13).
    pub surface_z_m: Option<f64>,
    /// Waypoints: `[t, x, y, z, roll, pitch, yaw]` rows (s, m, m, m, rad, rad, rad; fixed
    /// axes x-y-z, REP-103), or `[t, x, y, z, yaw]` for a rotation about base z.
    pub points: Option<Vec<Vec<f64>>>,
    /// Waypoints: `"linear"` (constant velocity per segment) or `"quintic"` (rest at every
    /// waypoint, continuous acceleration).
    pub interpolation: Option<String>,
    /// CSV reference, relative to the scenario file: poses (header `t,x,y,z,roll,pitch,yaw`
    /// or `t,x,y,z,yaw`) or, for `kind = "joints"`, joints (`t,q1,...,qN`, or a plan as
    /// `armdyn plan --csv` writes it: `t,q_<joint>..,qd_<joint>..,...`).
    pub file: Option<String>,
    /// Joints the inverse kinematics of the first point starts from (default: the posture,
    /// else `q0`, else the middle of the limits), rad or m.
    pub seed: Option<Vec<f64>>,
    /// The posture a redundant arm's solutions are drawn to, and the null-space target of the
    /// task-space law, rad or m.
    pub posture: Option<Vec<f64>>,
    /// Weight of each joint in the distance to the posture (default all 1; > 0): a joint with
    /// a large weight is held nearer its posture value.
    pub posture_weights: Option<Vec<f64>>,
    /// Position tolerance of the inverse kinematics, m (default 1e-10).
    pub ik_tolerance_m: Option<f64>,
    /// Orientation tolerance of the inverse kinematics, rad (default 1e-10).
    pub ik_tolerance_rad: Option<f64>,
    /// Iteration cap of the inverse kinematics per start (default 100).
    pub ik_max_iterations: Option<usize>,
}

/// `[force]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ForceTable {
    /// `"pi-ff"` (eq. 5.10), `"pi-ff-vd"` (eq. 5.11), `"impedance"` or `"admittance"`.
    pub law: String,
    /// `"constant"`, `"thesis-variable"` (`value (1 + sin(t))`, Appendix B.3) or `"csv"`.
    pub reference: String,
    /// Magnitude of the normal force the tool is to exert, N (> 0).
    pub value: Option<f64>,
    /// CSV force reference (header `t,f`: s, N), relative to the scenario file.
    pub file: Option<String>,
    /// Proportional gain (default: the thesis's 20).
    pub kfp: Option<f64>,
    /// Integral gain, 1/s (default: the thesis's 5).
    pub kfi: Option<f64>,
    /// Velocity damping, N s/m (default: 2000 for `pi-ff-vd`, 0 for `pi-ff`).
    pub kvd: Option<f64>,
    /// Nominal Coulomb coefficient of the friction feedforward (default 0: none).
    pub friction_feedforward: Option<f64>,
    /// Keep the model's gravity along the normal in the force command (default true; the
    /// thesis's law, false, leaves it to the force integral).
    pub gravity_compensation: Option<bool>,
    /// Conditional integration of the PI law's integral while an actuator saturates
    /// (default true; the thesis's law, false, integrates through saturation).
    pub anti_windup: Option<bool>,
    /// The velocity damping against the force reference's own motion, in the full task
    /// frame (default true; false: damping on the normal velocity alone, the thesis's).
    pub damp_reference_motion: Option<bool>,
    /// Index of the surface whose normal is the task frame's (default 0).
    pub surface: Option<usize>,
    /// Where the controller believes that surface is: shifted by this along its outward
    /// normal from where it really is, m (default 0; negative: believed lower).
    pub expected_shift_m: Option<f64>,
    /// `"design"`: `kfp`, `kfi`, `kvd` designed at the contact pose from `[force.design]`
    /// (then `kfp`, `kfi`, `kvd` are not given).
    pub gains: Option<String>,
    /// An arm controlling all three rotations: the tool axis (tool frame) held along the
    /// inward normal, or `"reference"` to track the reference's orientation (default: the
    /// tool frame's axis nearest the inward normal at the reference's contact pose).
    pub tool_axis: Option<ToolAxisValue>,
    /// `[force.design]`: the requested force loop.
    pub design: Option<DesignTable>,
    /// `[force.impedance]`: the impedance's stiffness and damping (`law = "impedance"`).
    pub impedance: Option<ImpedanceTable>,
    /// `[force.admittance]`: the virtual mass-damper (`law = "admittance"`).
    pub admittance: Option<AdmittanceTable>,
}

/// `force.tool_axis`: a vector or `"reference"`.
#[derive(Debug, Clone, Deserialize, PartialEq)]
#[serde(untagged)]
pub enum ToolAxisValue {
    /// A direction in the tool frame.
    Axis(Vec<f64>),
    /// A word (`"reference"`).
    Word(String),
}

/// `[force.design]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DesignTable {
    /// Natural frequency of the dominant closed-loop pair, Hz.
    pub bandwidth_hz: f64,
    /// Its damping ratio.
    pub damping: f64,
    /// The integral pole, Hz (default: a hundredth of the bandwidth).
    pub integral_hz: Option<f64>,
    /// Contact stiffness designed for, N/m (default: the force surface's).
    pub stiffness: Option<f64>,
    /// Model one period of computation delay (default false).
    pub delay: Option<bool>,
}

/// `[force.impedance]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ImpedanceTable {
    /// Along the normal, N/m (default 2000).
    pub stiffness: Option<f64>,
    /// Damping ratio of every direction on its apparent mass at the contact pose (the
    /// normal's on `stiffness + contact_stiffness`; default 1).
    pub damping_ratio: Option<f64>,
    /// In the tangent plane, N/m (default 20000).
    pub tangential_stiffness: Option<f64>,
    /// About the vertical (about the normal for an arm that controls all three rotations),
    /// N m/rad (default 50).
    pub yaw_stiffness: Option<f64>,
    /// About the tangent axes (the tool's tilt off the normal), N m/rad, for an arm that
    /// controls all three rotations (default 100).
    pub tilt_stiffness: Option<f64>,
    /// The contact stiffness assumed when placing the virtual point, N/m (default: the
    /// force surface's).
    pub contact_stiffness: Option<f64>,
}

/// `[force.admittance]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AdmittanceTable {
    /// Virtual mass, kg (default 1).
    pub mass: Option<f64>,
    /// Virtual damping, N s/m (default 400).
    pub damping: Option<f64>,
}

/// `[sensor]`.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SensorTable {
    /// White noise on each force axis, N (1 sigma).
    pub noise_n: Option<f64>,
    /// Bias on the z force axis of the sensor (base z for a sensor at the tool point without a
    /// tare; the sensor frame's, the tool frame's axes, with `frame`, a tool or `tare_s`), N.
    pub bias_n: Option<f64>,
    /// First-order low-pass cutoff, Hz.
    pub cutoff_hz: Option<f64>,
    /// Seed of the noise generator.
    pub seed: Option<u64>,
    /// The sensor frame's origin in the tool frame, m (its axes are the tool frame's): a
    /// sensor mounted before a tool.
    pub frame: Option<Vec<f64>>,
    /// The tool's mass between the sensor and the tool point, kg.
    pub tool_mass_kg: Option<f64>,
    /// The tool's centre of mass in the sensor frame, m.
    pub tool_com_m: Option<Vec<f64>>,
    /// Whether the controller takes the tool's weight out of the reading (default true).
    pub compensate_tool: Option<bool>,
    /// The tare window `[start, end]`, s: the bias is measured in free space at rest.
    pub tare_s: Option<Vec<f64>>,
}

/// The field names serde's derive gives `T`, in their order: what `T`'s
/// `deserialize_struct` is asked for (the reader's list of a table's known keys). The same
/// trick as `serde-aux`'s `serde_introspect`, written here (twenty lines) rather than taking
/// that crate for one function.
#[must_use]
pub fn field_names<T: serde::de::DeserializeOwned>() -> &'static [&'static str] {
    use serde::de::{Error, Visitor};
    use serde::forward_to_deserialize_any;
    struct Names(&'static [&'static str]);
    impl<'de> serde::Deserializer<'de> for &mut Names {
        type Error = serde::de::value::Error;
        fn deserialize_any<V: Visitor<'de>>(self, _: V) -> Result<V::Value, Self::Error> {
            Err(Error::custom("a struct's names only"))
        }
        fn deserialize_struct<V: Visitor<'de>>(
            self,
            _name: &'static str,
            fields: &'static [&'static str],
            _visitor: V,
        ) -> Result<V::Value, Self::Error> {
            self.0 = fields;
            Err(Error::custom("a struct's names only"))
        }
        forward_to_deserialize_any! {
            bool i8 i16 i32 i64 i128 u8 u16 u32 u64 u128 f32 f64 char str string bytes
            byte_buf option unit unit_struct newtype_struct seq tuple tuple_struct map enum
            identifier ignored_any
        }
    }
    let mut names = Names(&[]);
    let _ = T::deserialize(&mut names);
    names.0
}
