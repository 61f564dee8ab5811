//! `[force]`, `[selection]` and `[sensor]` checked: the force loop, when force is controlled,
//! and the force sensor the controller reads.

use std::path::Path;

use nalgebra::Vector3;
use toml::Table;

use super::check::Checker;
use super::check::MAX_FORCE_N;
use super::controllers::ForceController;
use super::error::ScenarioError;
use super::file::{ForceTable, ToolAxisValue};
pub use super::law_spec::LawSettings;
use super::toml_table::{key_list, TomlTable};
use crate::control::selection::{ContactSwitch, SelectionPolicy};
use crate::control::tool_compensation::TareWindow;
use crate::model::SensorMount;
use crate::trajectory::force_csv::SampledForce;

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
    /// In the full task frame, the damping against the force reference's own motion.
    pub damp_reference_motion: bool,
    /// Index of the surface that defines the task frame.
    pub surface: usize,
    /// Shift of the controller's belief of that surface along its normal, m.
    pub expected_shift_m: f64,
    /// Settings of the designed gains, the impedance and the admittance.
    pub laws: LawSettings,
    /// An arm controlling all three rotations: what holds the tool's orientation in contact.
    pub tool_axis: ToolAxis,
}

/// `force.tool_axis`: what the orientation target of an arm controlling all three rotations
/// is near the surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ToolAxis {
    /// The tool frame's axis nearest the inward normal at the reference's contact pose,
    /// held along the inward normal (the default).
    Nearest,
    /// This unit vector of the tool frame, held along the inward normal.
    Given(nalgebra::Vector3<f64>),
    /// The reference's orientation, unchanged.
    Reference,
}

/// The force sensor.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SensorSpec {
    /// White noise per force axis, N (1 sigma).
    pub noise_n: f64,
    /// Bias on the sensor's z axis, N: base z for a sensor at the tool point without a tare,
    /// the tool frame's z once mounted or tared (the sensor frame is the tool frame's).
    pub bias_n: f64,
    /// Low-pass cutoff, Hz.
    pub cutoff_hz: Option<f64>,
    /// Seed.
    pub seed: u64,
    /// The sensor mounted before a tool (`frame`, `tool_mass_kg`, `tool_com_m`); `None`: at
    /// the tool point, in base axes.
    pub mount: Option<SensorMount>,
    /// Whether the controller takes the tool's weight out of the reading.
    pub compensate_tool: bool,
    /// The tare window.
    pub tare: Option<TareWindow>,
}

impl SensorSpec {
    /// Whether the sensor reports the true wrench.
    #[must_use]
    pub fn is_ideal(&self) -> bool {
        self.noise_n == 0.0
            && self.bias_n == 0.0
            && self.cutoff_hz.is_none()
            && self.mount.is_none()
            && self.tare.is_none()
    }

    /// The bias the contact detection must tolerate, N: none once tared, the bias's otherwise.
    #[must_use]
    pub fn untared_bias_n(&self) -> f64 {
        if self.tare.is_some() {
            0.0
        } else {
            self.bias_n
        }
    }
}

pub(super) fn force(
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
        friction_feedforward: c.coulomb(
            "force.friction_feedforward",
            f.friction_feedforward.unwrap_or(0.0),
        )?,
        gravity_compensation: f.gravity_compensation.unwrap_or(true),
        anti_windup: f.anti_windup.unwrap_or(true),
        damp_reference_motion: f.damp_reference_motion.unwrap_or(true),
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
        tool_axis: tool_axis(c, f.tool_axis.as_ref())?,
    })
}

fn tool_axis(c: &Checker<'_>, v: Option<&ToolAxisValue>) -> Result<ToolAxis, ScenarioError> {
    const KEY: &str = "force.tool_axis";
    match v {
        None => Ok(ToolAxis::Nearest),
        Some(ToolAxisValue::Word(w)) if w == "reference" => Ok(ToolAxis::Reference),
        Some(ToolAxisValue::Word(w)) => Err(c.err(
            KEY,
            format!("`{w}`: expected a direction [x, y, z] in the tool frame or \"reference\""),
        )),
        Some(ToolAxisValue::Axis(a)) => {
            let [x, y, z] = a.as_slice() else {
                return Err(c.err(
                    KEY,
                    format!(
                        "{} values; a direction has 3 ([x, y, z], tool frame)",
                        a.len()
                    ),
                ));
            };
            let v = nalgebra::Vector3::new(*x, *y, *z);
            if !(v.iter().all(|e| e.is_finite()) && v.norm() > 1e-9) {
                return Err(c.err(
                    KEY,
                    "the direction must be finite and not zero ([x, y, z], tool frame)",
                ));
            }
            Ok(ToolAxis::Given(v.normalize()))
        }
    }
}

/// The modes of `[selection]` and the keys each takes besides `mode`: `time` switches to force
/// control at `switch_s` (s); `contact` on a measured push of `threshold_n` (N) lasting
/// `debounce_s` (s), ramps the force reference over `ramp_s` (s), approaches along the
/// expected normal at `approach_speed_m_s` (m/s) and tolerates a lost contact for `loss_s` (s).
const MODES: [(&str, &[&str]); 2] = [
    ("time", &["switch_s"]),
    (
        "contact",
        &[
            "threshold_n",
            "debounce_s",
            "ramp_s",
            "approach_speed_m_s",
            "loss_s",
        ],
    ),
];

/// `[selection]`, its table `table`, for the force sensor `sensor`.
pub(super) fn selection(
    c: &Checker<'_>,
    table: &Table,
    sensor: &SensorSpec,
) -> Result<SelectionPolicy, ScenarioError> {
    let s = TomlTable {
        c,
        at: "selection",
        table,
    };
    let mode = s.tag("mode", "the switching rule, \"time\" or \"contact\"")?;
    let Some((_, keys)) = MODES.iter().find(|(m, _)| *m == mode) else {
        return Err(s.err(
            "mode",
            format!("unknown mode `{mode}`; known: time, contact"),
        ));
    };
    if let Some(k) = s.other_key("mode", keys) {
        return Err(match MODES.iter().find(|(_, ks)| ks.contains(&k)) {
            Some((other, _)) => s.err(
                k,
                format!("does not belong here: a key of mode = \"{other}\""),
            ),
            None => s.err(
                k,
                format!(
                    "unknown field `{k}`: mode = \"{mode}\" takes {}",
                    key_list(keys)
                ),
            ),
        });
    }
    let number = |k: &str| s.optional_number(k);
    if mode == "time" {
        let t = c.need(
            "selection.switch_s",
            &number("switch_s")?,
            "the switch time in s",
        )?;
        return Ok(SelectionPolicy::Time {
            switch_s: c.range(
                "selection.switch_s",
                t,
                0.0,
                1e5,
                false,
                "a time in s, >= 0",
            )?,
        });
    }
    let d = ContactSwitch::for_sensor(sensor.noise_n, sensor.untared_bias_n());
    Ok(SelectionPolicy::Contact(ContactSwitch {
        threshold_n: c.range(
            "selection.threshold_n",
            number("threshold_n")?.unwrap_or(d.threshold_n),
            0.0,
            MAX_FORCE_N,
            true,
            "a force in N, > 0",
        )?,
        debounce_s: c.range(
            "selection.debounce_s",
            number("debounce_s")?.unwrap_or(d.debounce_s),
            0.0,
            1.0,
            false,
            "a time in s, >= 0 and <= 1",
        )?,
        ramp_s: c.range(
            "selection.ramp_s",
            number("ramp_s")?.unwrap_or(d.ramp_s),
            0.0,
            10.0,
            false,
            "a time in s, >= 0 and <= 10",
        )?,
        approach_speed_m_s: c.range(
            "selection.approach_speed_m_s",
            number("approach_speed_m_s")?.unwrap_or(d.approach_speed_m_s),
            0.0,
            1.0,
            true,
            "a speed in m/s, > 0 and <= 1",
        )?,
        loss_s: c.range(
            "selection.loss_s",
            number("loss_s")?.unwrap_or(d.loss_s),
            0.0,
            10.0,
            false,
            "a time in s, >= 0 and <= 10",
        )?,
    }))
}

pub(super) fn sensor(
    c: &Checker<'_>,
    s: Option<&super::file::SensorTable>,
) -> Result<SensorSpec, ScenarioError> {
    let Some(s) = s else {
        return Ok(SensorSpec {
            noise_n: 0.0,
            bias_n: 0.0,
            cutoff_hz: None,
            seed: 1,
            mount: None,
            compensate_tool: true,
            tare: None,
        });
    };
    let metres = |key: &str, v: &Option<Vec<f64>>| -> Result<Option<Vector3<f64>>, ScenarioError> {
        v.as_deref()
            .map(|v| {
                let x = c.vec3(key, v)?;
                if x.amax() > MAX_MOUNT_M {
                    return Err(c.err(
                        key,
                        format!(
                            "{x:?} m: each coordinate within {MAX_MOUNT_M} m of the tool point"
                        ),
                    ));
                }
                Ok(x)
            })
            .transpose()
    };
    let origin = metres("sensor.frame", &s.frame)?;
    let com = metres("sensor.tool_com_m", &s.tool_com_m)?;
    let mass = s
        .tool_mass_kg
        .map(|m| {
            c.range(
                "sensor.tool_mass_kg",
                m,
                0.0,
                MAX_TOOL_MASS_KG,
                false,
                "a mass in kg, >= 0",
            )
        })
        .transpose()?;
    let mount = (origin.is_some() || com.is_some() || mass.is_some()).then(|| SensorMount {
        origin_m: origin.unwrap_or_else(Vector3::zeros),
        tool_mass_kg: mass.unwrap_or(0.0),
        tool_com_m: com.unwrap_or_else(Vector3::zeros),
    });
    let tare = match s.tare_s.as_deref() {
        None => None,
        Some([a, b]) => {
            let a = c.range("sensor.tare_s", *a, 0.0, 1e6, false, "a time in s, >= 0")?;
            let b = c.range("sensor.tare_s", *b, 0.0, 1e6, false, "a time in s, >= 0")?;
            if b <= a {
                return Err(c.err(
                    "sensor.tare_s",
                    format!("[{a}, {b}]: the window must end after it starts"),
                ));
            }
            Some(TareWindow {
                start_s: a,
                end_s: b,
            })
        }
        Some(v) => {
            return Err(c.err(
                "sensor.tare_s",
                format!("{} values; the window is [start, end] in s", v.len()),
            ))
        }
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
        mount,
        compensate_tool: s.compensate_tool.unwrap_or(true),
        tare,
    })
}

/// The largest sensor offset and tool centre of mass accepted, m from the tool point.
pub const MAX_MOUNT_M: f64 = 2.0;
/// The largest tool mass accepted, kg.
pub const MAX_TOOL_MASS_KG: f64 = 200.0;
