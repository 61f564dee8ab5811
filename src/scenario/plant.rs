//! Model mismatch: a plant with its own inertial parameters and joint friction (`[plant]`),
//! and the model the controller uses (`controller_model`).

use std::path::PathBuf;

use nalgebra::Vector3;
use serde::Deserialize;

use crate::model::{LinkInertia, Parametric, Scara};
type ParametricScara = Parametric<4, Scara>;
type ScaraParameters = [f64; 40];
use crate::sim::friction::DEFAULT_SMOOTHING;
use crate::sim::JointFriction;

/// `[plant]` as written: every key optional, the description's values by default.
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PlantTable {
    /// Scale factor of each link's mass, links 1 to 4 (default 1).
    pub mass_scale: Option<Vec<f64>>,
    /// Offset of each link's centre of mass, m, link frame: `[[dx, dy, dz]; 4]` (default 0).
    pub com_offset_m: Option<Vec<Vec<f64>>>,
    /// Scale factor of each link's inertia about its centre of mass (default 1).
    pub inertia_scale: Option<Vec<f64>>,
    /// A point mass carried by the tool, kg (default 0).
    pub payload_kg: Option<f64>,
    /// Where the payload sits in link 4's frame, m (default: the frame's origin, the tool
    /// point).
    pub payload_offset_m: Option<Vec<f64>>,
    /// Viscous joint friction, N m s/rad (N s/m for d3), per joint (default 0).
    pub friction_viscous: Option<Vec<f64>>,
    /// Coulomb joint friction, N m (N for d3), per joint (default 0).
    pub friction_coulomb: Option<Vec<f64>>,
    /// Width of the Coulomb term's smooth sign, rad/s or m/s (default 0.05).
    pub friction_smoothing: Option<f64>,
}

/// A checked plant: perturbations of the description's parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlantSpec {
    /// Mass scale per link.
    pub mass_scale: [f64; 4],
    /// Centre-of-mass offset per link, m.
    pub com_offset_m: [[f64; 3]; 4],
    /// Inertia scale per link.
    pub inertia_scale: [f64; 4],
    /// Payload at the tool, kg.
    pub payload_kg: f64,
    /// Payload position in link 4's frame, m.
    pub payload_offset_m: [f64; 3],
    /// Viscous friction per joint.
    pub friction_viscous: [f64; 4],
    /// Coulomb friction per joint.
    pub friction_coulomb: [f64; 4],
    /// Coulomb smoothing, rad/s or m/s.
    pub friction_smoothing: f64,
}

impl Default for PlantSpec {
    fn default() -> Self {
        Self {
            mass_scale: [1.0; 4],
            com_offset_m: [[0.0; 3]; 4],
            inertia_scale: [1.0; 4],
            payload_kg: 0.0,
            payload_offset_m: [0.0; 3],
            friction_viscous: [0.0; 4],
            friction_coulomb: [0.0; 4],
            friction_smoothing: DEFAULT_SMOOTHING,
        }
    }
}

impl PlantSpec {
    /// Whether the plant is the description's (no perturbation, no friction).
    #[must_use]
    pub fn is_nominal(&self) -> bool {
        self.rigid_body_nominal() && self.friction().is_none()
    }

    fn rigid_body_nominal(&self) -> bool {
        let d = Self::default();
        self.mass_scale == d.mass_scale
            && self.com_offset_m == d.com_offset_m
            && self.inertia_scale == d.inertia_scale
            && self.payload_kg == 0.0
    }

    /// The plant's standard parameters.
    #[must_use]
    pub fn parameters(&self) -> ScaraParameters {
        let nominal = ParametricScara::nominal(Scara);
        let mut p = *nominal.parameters();
        for j in 0..4 {
            let block: [f64; 10] = core::array::from_fn(|k| p[10 * j + k]);
            let mut link = LinkInertia::from_standard(&block).perturbed(
                self.mass_scale[j],
                Vector3::from(self.com_offset_m[j]),
                self.inertia_scale[j],
            );
            if j == 3 && self.payload_kg > 0.0 {
                link = link.with_point_mass(self.payload_kg, Vector3::from(self.payload_offset_m));
            }
            p[10 * j..10 * j + 10].copy_from_slice(&link.to_standard());
        }
        p
    }

    /// The plant model, or `None` for the description's rigid body (then the plant runs on
    /// the generated nominal functions, bit for bit as without `[plant]`).
    #[must_use]
    pub fn model(&self) -> Option<ParametricScara> {
        (!self.rigid_body_nominal()).then(|| ParametricScara::new(Scara, self.parameters()))
    }

    /// The plant's joint friction, `None` if all zero.
    #[must_use]
    pub fn friction(&self) -> Option<JointFriction<4>> {
        if self.friction_viscous == [0.0; 4] && self.friction_coulomb == [0.0; 4] {
            return None;
        }
        JointFriction::new(
            self.friction_viscous.into(),
            self.friction_coulomb.into(),
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
        /// The model (boxed: 320 bytes of parameters).
        model: Box<ParametricScara>,
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
