//! The `[force]` keys of the force laws beyond the thesis's gains: `gains = "design"` with
//! `[force.design]`, `[force.impedance]` and `[force.admittance]`, checked key by key.
//!
//! Each table configures its law whenever that law runs: the file's own `law`, or another
//! named on the command line (`armdyn run scenario FILE --force-law NAME`).

use super::check::Checker;
use super::controllers::ForceController;
use super::error::ScenarioError;
use super::file::ForceTable;
use crate::control::design::DesignSpec;

/// Bandwidth of the design when a file gives none, Hz (natural frequency of the dominant
/// closed-loop pair).
pub const DEFAULT_BANDWIDTH_HZ: f64 = 20.0;
/// Damping ratio of the design when a file gives none.
pub const DEFAULT_DAMPING: f64 = 1.0;

/// `[force.design]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DesignSettings {
    /// The requested poles.
    pub spec: DesignSpec,
    /// Contact stiffness designed for, N/m (`None`: the force surface's).
    pub stiffness: Option<f64>,
    /// One period of computation delay in the model.
    pub delay: bool,
}

/// `[force.impedance]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ImpedanceSettings {
    /// Normal stiffness, N/m.
    pub stiffness: f64,
    /// Damping ratio of every direction on its apparent mass at the contact pose.
    pub damping_ratio: f64,
    /// Tangential stiffness, N/m.
    pub tangential_stiffness: f64,
    /// Yaw stiffness (about base z; about the normal for an arm that controls all three
    /// rotations), N m/rad.
    pub yaw_stiffness: f64,
    /// Stiffness about the tangent axes (the tool's tilt off the normal), N m/rad.
    pub tilt_stiffness: f64,
    /// Contact stiffness assumed, N/m (`None`: the force surface's).
    pub contact_stiffness: Option<f64>,
}

/// `[force.admittance]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AdmittanceSettings {
    /// Virtual mass, kg.
    pub mass_kg: f64,
    /// Virtual damping, N s/m.
    pub damping: f64,
}

/// The settings of every law a scenario's force loop may run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LawSettings {
    /// `gains = "design"`: the PI law's gains are designed before the run.
    pub design_gains: bool,
    /// The design asked for (defaults: [`DEFAULT_BANDWIDTH_HZ`], [`DEFAULT_DAMPING`]).
    pub design: DesignSettings,
    /// The impedance.
    pub impedance: ImpedanceSettings,
    /// The admittance.
    pub admittance: AdmittanceSettings,
}

impl Default for LawSettings {
    fn default() -> Self {
        Self {
            design_gains: false,
            design: DesignSettings {
                // The defaults are in range.
                spec: DesignSpec::new(DEFAULT_BANDWIDTH_HZ, DEFAULT_DAMPING, None)
                    .unwrap_or_else(|_| unreachable!()),
                stiffness: None,
                delay: false,
            },
            impedance: ImpedanceSettings {
                stiffness: 2000.0,
                damping_ratio: 1.0,
                tangential_stiffness: 20_000.0,
                yaw_stiffness: 50.0,
                tilt_stiffness: 100.0,
                contact_stiffness: None,
            },
            admittance: AdmittanceSettings {
                mass_kg: 1.0,
                damping: 400.0,
            },
        }
    }
}

/// A positive quantity of `[force]`: how its error names it, and the largest value accepted.
type Quantity = (&'static str, f64);
const FREQUENCY: Quantity = ("a frequency in Hz", 1e4);
const DAMPING_RATIO: Quantity = ("a damping ratio", 100.0);
const STIFFNESS: Quantity = ("a stiffness in N/m", 1e9);
const TORSION: Quantity = ("a stiffness in N m/rad", 1e9);
const MASS: Quantity = ("a mass in kg", 1e6);
const DAMPING: Quantity = ("a damping in N s/m", 1e9);

/// Checks the law keys of `[force]`.
pub(super) fn parse(
    c: &Checker<'_>,
    f: &ForceTable,
    law: ForceController,
) -> Result<LawSettings, ScenarioError> {
    let mut s = LawSettings::default();
    if let Some(g) = &f.gains {
        if g != "design" {
            return Err(c.err(
                "force.gains",
                format!("unknown gains `{g}`; known: design (or give kfp, kfi, kvd)"),
            ));
        }
        if law != ForceController::PiFfVd {
            return Err(c.err(
                "force.gains",
                format!(
                    "gains = \"design\" places three poles with Kfp, Kfi and Kvd: it needs law = \"pi-ff-vd\", not \"{}\"",
                    law.name()
                ),
            ));
        }
        for (k, present) in [("kfp", f.kfp), ("kfi", f.kfi), ("kvd", f.kvd)] {
            c.forbid(
                &format!("force.{k}"),
                present.is_some(),
                "gains = \"design\" computes it",
            )?;
        }
        s.design_gains = true;
    }
    let positive = |key: &str, v: f64, (unit, max): Quantity| {
        c.range(
            key,
            v,
            0.0,
            max,
            true,
            &format!("{unit}, > 0 and <= {max:e}"),
        )
    };
    if let Some(d) = &f.design {
        let key = |k: &str| format!("force.design.{k}");
        let bw = positive(&key("bandwidth_hz"), d.bandwidth_hz, FREQUENCY)?;
        let z = positive(&key("damping"), d.damping, DAMPING_RATIO)?;
        let optional =
            |k: &str, v: Option<f64>, q: Quantity| v.map(|v| positive(&key(k), v, q)).transpose();
        s.design = DesignSettings {
            spec: DesignSpec::new(bw, z, optional("integral_hz", d.integral_hz, FREQUENCY)?)
                .map_err(|e| c.err("force.design", e.to_string()))?,
            stiffness: optional("stiffness", d.stiffness, STIFFNESS)?,
            delay: d.delay.unwrap_or(false),
        };
    }
    if let Some(i) = &f.impedance {
        let d = s.impedance;
        let key = |k: &str| format!("force.impedance.{k}");
        // The file's value, or the default, checked.
        let or = |k: &str, v: Option<f64>, default: f64, q: Quantity| {
            positive(&key(k), v.unwrap_or(default), q)
        };
        s.impedance = ImpedanceSettings {
            stiffness: or("stiffness", i.stiffness, d.stiffness, STIFFNESS)?,
            damping_ratio: or(
                "damping_ratio",
                i.damping_ratio,
                d.damping_ratio,
                DAMPING_RATIO,
            )?,
            tangential_stiffness: or(
                "tangential_stiffness",
                i.tangential_stiffness,
                d.tangential_stiffness,
                STIFFNESS,
            )?,
            yaw_stiffness: or("yaw_stiffness", i.yaw_stiffness, d.yaw_stiffness, TORSION)?,
            tilt_stiffness: or(
                "tilt_stiffness",
                i.tilt_stiffness,
                d.tilt_stiffness,
                TORSION,
            )?,
            contact_stiffness: i
                .contact_stiffness
                .map(|v| positive(&key("contact_stiffness"), v, STIFFNESS))
                .transpose()?,
        };
    }
    if let Some(a) = &f.admittance {
        let d = s.admittance;
        let key = |k: &str| format!("force.admittance.{k}");
        s.admittance = AdmittanceSettings {
            mass_kg: positive(&key("mass"), a.mass.unwrap_or(d.mass_kg), MASS)?,
            damping: positive(&key("damping"), a.damping.unwrap_or(d.damping), DAMPING)?,
        };
    }
    Ok(s)
}

/// Where a PI law's gains come from when a law is chosen on the command line.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GainChoice {
    /// The file's (its `kfp`, `kfi`, `kvd` or its design; the thesis's if the file names
    /// another law).
    File,
    /// The thesis's: 20, 5, 2000 (`pi-ff`: 0).
    Thesis,
    /// Designed from `[force.design]` (or its defaults) at the contact pose.
    Design,
}

/// A force law named on the command line: `pi-ff`, `pi-ff-vd`, `impedance`, `admittance`,
/// and for the PI laws an optional `:thesis` or `:design` for their gains.
///
/// ```
/// use armdyn::scenario::{ForceController, LawChoice};
/// let c = LawChoice::parse("pi-ff-vd:design").unwrap();
/// assert_eq!(c.law, ForceController::PiFfVd);
/// assert!(LawChoice::parse("impedance:design").is_err());
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LawChoice {
    /// The law.
    pub law: ForceController,
    /// Its gains.
    pub gains: GainChoice,
}

impl LawChoice {
    /// Parses `NAME` or `NAME:thesis` / `NAME:design`.
    ///
    /// # Errors
    ///
    /// A message naming the part not understood.
    pub fn parse(text: &str) -> Result<Self, String> {
        let (name, gains) = match text.split_once(':') {
            None => (text, GainChoice::File),
            Some((n, "thesis")) => (n, GainChoice::Thesis),
            Some((n, "design")) => (n, GainChoice::Design),
            Some((_, other)) => {
                return Err(format!(
                    "unknown gains `{other}` in `{text}`; known: thesis, design"
                ))
            }
        };
        let law = ForceController::parse(name).map_err(|e| e.to_string())?;
        if gains == GainChoice::Design && law != ForceController::PiFfVd {
            return Err(format!(
                "`{text}`: only pi-ff-vd has designed gains (three poles need Kfp, Kfi and Kvd)"
            ));
        }
        if gains == GainChoice::Thesis && !law.is_pi() {
            return Err(format!(
                "`{text}`: only the PI laws have the thesis's gains"
            ));
        }
        Ok(Self { law, gains })
    }

    /// How it is written.
    #[must_use]
    pub fn label(&self) -> String {
        match self.gains {
            GainChoice::File => self.law.name().to_string(),
            GainChoice::Thesis => format!("{}:thesis", self.law.name()),
            GainChoice::Design => format!("{}:design", self.law.name()),
        }
    }

    /// Puts this law into `scenario`'s force loop.
    ///
    /// # Errors
    ///
    /// [`ScenarioError`] on `force` if the scenario has no force loop.
    pub fn apply(&self, scenario: &mut super::Scenario) -> Result<(), ScenarioError> {
        let Some(f) = scenario.force.as_mut() else {
            return Err(scenario.error(
                "force",
                "has no [force] table: a force law needs a force loop",
            ));
        };
        let file_is_pi = f.law.is_pi();
        f.law = self.law;
        match self.gains {
            GainChoice::File if file_is_pi => {}
            GainChoice::File | GainChoice::Thesis => {
                f.gains = self.law.thesis_gains();
                f.laws.design_gains = false;
            }
            GainChoice::Design => {
                // The design is of the loop with the model's gravity compensated.
                f.laws.design_gains = true;
                f.gravity_compensation = true;
            }
        }
        if self.law == ForceController::PiFf && f.laws.design_gains {
            f.laws.design_gains = false;
            f.gains = self.law.thesis_gains();
        }
        Ok(())
    }
}
