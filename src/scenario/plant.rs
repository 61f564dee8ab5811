//! Model mismatch: a plant with its own inertial parameters and joint friction (`[plant]`),
//! and the model the controller uses (`controller_model`), for any robot: one value per
//! link or joint.

use std::path::PathBuf;

use nalgebra::Vector3;
use serde::Deserialize;

use super::check::{numbers, Checker};
use super::error::ScenarioError;
use crate::model::{LinkInertia, Parametric, ParametricModel, PARAMETERS_PER_LINK};
use crate::sim::friction::DEFAULT_SMOOTHING;
use crate::sim::JointFriction;

/// `[plant]` as written: every key optional, the description's values by default.
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PlantTable {
    /// Scale factor of each link's mass, links 1 to N (default 1).
    pub mass_scale: Option<Vec<f64>>,
    /// Offset of each link's centre of mass, m, link frame: `[[dx, dy, dz]; N]` (default 0).
    pub com_offset_m: Option<Vec<Vec<f64>>>,
    /// Scale factor of each link's inertia about its centre of mass (default 1).
    pub inertia_scale: Option<Vec<f64>>,
    /// A point mass carried by the tool, kg (default 0).
    pub payload_kg: Option<f64>,
    /// Where the payload sits in the last link's frame, m (default: the frame's origin).
    pub payload_offset_m: Option<Vec<f64>>,
    /// Viscous joint friction, N m s/rad (N s/m for a prismatic joint), per joint (default 0).
    pub friction_viscous: Option<Vec<f64>>,
    /// Coulomb joint friction, N m (N for a prismatic joint), per joint (default 0).
    pub friction_coulomb: Option<Vec<f64>>,
    /// Width of the Coulomb term's smooth sign, rad/s or m/s (default 0.05).
    pub friction_smoothing: Option<f64>,
}

/// A checked plant: perturbations of the description's parameters, one entry per link or
/// joint of the scenario's robot.
#[derive(Clone, Debug, PartialEq)]
pub struct PlantSpec {
    /// Mass scale per link.
    pub mass_scale: Vec<f64>,
    /// Centre-of-mass offset per link, m.
    pub com_offset_m: Vec<[f64; 3]>,
    /// Inertia scale per link.
    pub inertia_scale: Vec<f64>,
    /// Payload at the tool, kg.
    pub payload_kg: f64,
    /// Payload position in the last link's frame, m.
    pub payload_offset_m: [f64; 3],
    /// Viscous friction per joint.
    pub friction_viscous: Vec<f64>,
    /// Coulomb friction per joint.
    pub friction_coulomb: Vec<f64>,
    /// Coulomb smoothing, rad/s or m/s.
    pub friction_smoothing: f64,
}

impl PlantSpec {
    /// The description's plant for a robot of `dof` joints.
    #[must_use]
    pub fn nominal(dof: usize) -> Self {
        Self {
            mass_scale: vec![1.0; dof],
            com_offset_m: vec![[0.0; 3]; dof],
            inertia_scale: vec![1.0; dof],
            payload_kg: 0.0,
            payload_offset_m: [0.0; 3],
            friction_viscous: vec![0.0; dof],
            friction_coulomb: vec![0.0; dof],
            friction_smoothing: DEFAULT_SMOOTHING,
        }
    }

    /// Whether the plant is the description's (no perturbation, no friction).
    #[must_use]
    pub fn is_nominal(&self) -> bool {
        self.rigid_body_nominal() && !self.has_friction()
    }

    fn rigid_body_nominal(&self) -> bool {
        self.mass_scale.iter().all(|s| *s == 1.0)
            && self.com_offset_m.iter().all(|o| *o == [0.0; 3])
            && self.inertia_scale.iter().all(|s| *s == 1.0)
            && self.payload_kg == 0.0
    }

    fn has_friction(&self) -> bool {
        self.friction_viscous.iter().any(|x| *x != 0.0)
            || self.friction_coulomb.iter().any(|x| *x != 0.0)
    }

    /// The plant's standard parameters for robot `R` (`10 N`, in the generated order).
    #[must_use]
    pub fn parameters<const N: usize, R: ParametricModel<N>>(&self) -> R::Parameters {
        let mut p = R::standard_parameters();
        for j in 0..N {
            let k = PARAMETERS_PER_LINK * j;
            let slice = &mut p.as_mut()[k..k + PARAMETERS_PER_LINK];
            let block: [f64; PARAMETERS_PER_LINK] = core::array::from_fn(|i| slice[i]);
            let mut link = LinkInertia::from_standard(&block).perturbed(
                self.mass_scale[j],
                Vector3::from(self.com_offset_m[j]),
                self.inertia_scale[j],
            );
            if j == N - 1 && self.payload_kg > 0.0 {
                link = link.with_point_mass(self.payload_kg, Vector3::from(self.payload_offset_m));
            }
            slice.copy_from_slice(&link.to_standard());
        }
        p
    }

    /// The plant model, or `None` for the description's rigid body (then the plant runs on
    /// the generated nominal functions, bit for bit as without `[plant]`).
    #[must_use]
    pub fn model<const N: usize, R: ParametricModel<N>>(
        &self,
        robot: R,
    ) -> Option<Parametric<N, R>> {
        (!self.rigid_body_nominal()).then(|| Parametric::new(robot, self.parameters::<N, R>()))
    }

    /// The plant's joint friction, `None` if all zero.
    #[must_use]
    pub fn friction<const N: usize>(&self) -> Option<JointFriction<N>> {
        if !self.has_friction() {
            return None;
        }
        JointFriction::new(
            nalgebra::SVector::<f64, N>::from_fn(|i, _| self.friction_viscous[i]),
            nalgebra::SVector::<f64, N>::from_fn(|i, _| self.friction_coulomb[i]),
            self.friction_smoothing,
        )
        .ok()
    }
}

/// The model the controller designs its gains with and linearises by.
#[derive(Clone, Debug, PartialEq)]
pub enum ControllerModel {
    /// The description's (the generated nominal functions).
    Nominal,
    /// An identified model read from an `identification.json`.
    Identified {
        /// The file.
        file: PathBuf,
        /// Its standard parameters (`10 N`, in the generated order).
        parameters: Vec<f64>,
    },
}

impl ControllerModel {
    /// `"nominal"` or the file name.
    #[must_use]
    pub fn describe(&self) -> String {
        match self {
            Self::Nominal => "nominal".into(),
            Self::Identified { file, .. } => format!("identified ({})", file.display()),
        }
    }
}

/// Checks `[plant]` for a robot of `dof` joints.
pub(super) fn plant(
    c: &Checker<'_>,
    p: Option<&PlantTable>,
    dof: usize,
) -> Result<PlantSpec, ScenarioError> {
    let Some(p) = p else {
        return Ok(PlantSpec::nominal(dof));
    };
    let com_offset_m = match &p.com_offset_m {
        None => vec![[0.0; 3]; dof],
        Some(rows) if rows.len() == dof => {
            let mut out = Vec::with_capacity(dof);
            for row in rows {
                let v = numbers(
                    c,
                    "plant.com_offset_m",
                    Some(row),
                    3,
                    0.0,
                    |x| x.abs() <= 1.0,
                    "an offset in m per axis, within +-1 m",
                )?;
                out.push([v[0], v[1], v[2]]);
            }
            out
        }
        Some(rows) => {
            return Err(c.err(
                "plant.com_offset_m",
                format!(
                    "needs {dof} rows [dx, dy, dz] (m), one per link, got {}",
                    rows.len()
                ),
            ))
        }
    };
    // A factor per link, default 1, in (0, 10].
    let scales = |key: &str, values: Option<&Vec<f64>>| {
        let within = |x: f64| x > 0.0 && x <= 10.0;
        numbers(
            c,
            key,
            values,
            dof,
            1.0,
            within,
            "a scale factor, > 0 and <= 10",
        )
    };
    let payload = numbers(
        c,
        "plant.payload_offset_m",
        p.payload_offset_m.as_ref(),
        3,
        0.0,
        |x| x.abs() <= 1.0,
        "a position in m in the last link's frame, within +-1 m",
    )?;
    Ok(PlantSpec {
        mass_scale: scales("plant.mass_scale", p.mass_scale.as_ref())?,
        com_offset_m,
        inertia_scale: scales("plant.inertia_scale", p.inertia_scale.as_ref())?,
        payload_kg: c.range(
            "plant.payload_kg",
            p.payload_kg.unwrap_or(0.0),
            0.0,
            100.0,
            false,
            "a mass in kg, >= 0 and <= 100",
        )?,
        payload_offset_m: [payload[0], payload[1], payload[2]],
        friction_viscous: numbers(
            c,
            "plant.friction_viscous",
            p.friction_viscous.as_ref(),
            dof,
            0.0,
            |x| (0.0..=1e5).contains(&x),
            "N m s/rad or N s/m, >= 0",
        )?,
        friction_coulomb: numbers(
            c,
            "plant.friction_coulomb",
            p.friction_coulomb.as_ref(),
            dof,
            0.0,
            |x| (0.0..=1e4).contains(&x),
            "N m or N, >= 0",
        )?,
        friction_smoothing: c.range(
            "plant.friction_smoothing",
            p.friction_smoothing.unwrap_or(DEFAULT_SMOOTHING),
            0.0,
            10.0,
            true,
            "a velocity in rad/s or m/s, > 0",
        )?,
    })
}
