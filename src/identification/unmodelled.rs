//! A plant with what a real robot has and the identification does not model, for logs like a
//! real robot's ([`super::sim_log`] adds the logging defects): a link whose true inertia
//! breaks the triangle inequality (a pseudo-inertia with a negative eigenvalue, outside the
//! physically consistent set the consistent fit searches), and friction of a form the fitted
//! model lacks (a Stribeck term and an asymmetric Coulomb level, on top of the viscous and
//! smooth Coulomb friction the model has).

use nalgebra::{Matrix3, SymmetricEigen, Vector3};

use super::error::IdentificationError;
use super::fourier::FourierExcitation;
use super::measurement::{measure_plant, Measurement};
use super::robots::{Identifiable, PER_LINK};
use crate::model::{JointVector, LinkInertia, Parametric, ParametricModel};
use crate::sim::JointFriction;

/// The broken link's largest principal moment about its centre of mass is this many times
/// the sum of the other two, plus one (a rigid body has at most the sum).
pub const TRIANGLE_EXCESS: f64 = 0.3;
/// Stribeck friction at rest over the Coulomb level.
pub const STRIBECK_FRACTION: f64 = 0.5;
/// Stribeck velocity, rad/s or m/s.
pub const STRIBECK_VELOCITY: f64 = 0.1;
/// Asymmetry of the Coulomb level (`fc (1 +- a)` forward and backward), sign alternating from
/// joint to joint.
pub const ASYMMETRY: f64 = 0.2;

/// What the plant has beyond the identification's model.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct Unmodelled {
    /// A link (from 1) whose inertia breaks the triangle inequality ([`break_triangle`]).
    pub broken_link: Option<usize>,
    /// Stribeck friction and an asymmetric Coulomb level ([`unmodelled_friction`]) on top of
    /// the plant's friction.
    pub friction: bool,
}

/// One link's standard parameters with its inertia about the centre of mass changed so that
/// the largest principal moment is `1 + excess` times the sum of the other two (same axes,
/// mass and centre of mass): the moments stay positive (the mass matrix stays positive
/// definite, the plant can be simulated) but no rigid body has them.
#[must_use]
pub fn break_triangle(p: &[f64; PER_LINK], excess: f64) -> [f64; PER_LINK] {
    let mut link = LinkInertia::from_standard(p);
    let eig = SymmetricEigen::new(link.inertia);
    let mut order = [0, 1, 2];
    order.sort_by(|a, b| eig.eigenvalues[*a].total_cmp(&eig.eigenvalues[*b]));
    let mut moments: Vector3<f64> = eig.eigenvalues;
    moments[order[2]] = (1.0 + excess) * (moments[order[0]] + moments[order[1]]);
    let inertia: Matrix3<f64> =
        eig.eigenvectors * Matrix3::from_diagonal(&moments) * eig.eigenvectors.transpose();
    link.inertia = 0.5 * (inertia + inertia.transpose());
    link.to_standard()
}

/// `friction` plus a Stribeck term of [`STRIBECK_FRACTION`] of each joint's Coulomb level
/// over [`STRIBECK_VELOCITY`], and a Coulomb level [`ASYMMETRY`] higher one way than the
/// other (forward on odd joints, backward on even ones).
///
/// # Errors
///
/// [`IdentificationError::Setting`] if the friction's coefficients refuse the terms (they do
/// not for a valid friction).
pub fn unmodelled_friction<const N: usize>(
    friction: JointFriction<N>,
) -> Result<JointFriction<N>, IdentificationError> {
    let fs = friction.coulomb() * STRIBECK_FRACTION;
    let a = JointVector::<N>::from_fn(|i, _| if i % 2 == 0 { ASYMMETRY } else { -ASYMMETRY });
    friction
        .with_stribeck(fs, STRIBECK_VELOCITY)
        .and_then(|f| f.with_asymmetry(a))
        .map_err(|e| IdentificationError::Setting(e.to_string()))
}

/// The plant's standard parameters: `robot`'s, with `unmodelled.broken_link` broken.
///
/// # Errors
///
/// [`IdentificationError::Setting`] naming a link that `robot` does not have.
pub fn plant_parameters<const N: usize, R: Identifiable<N>>(
    robot: &R,
    unmodelled: &Unmodelled,
) -> Result<Vec<f64>, IdentificationError> {
    let mut p = robot.standard_parameters().as_slice().to_vec();
    if let Some(l) = unmodelled.broken_link {
        if !(1..=N).contains(&l) {
            return Err(IdentificationError::Setting(format!(
                "broken link {l}: {} has links 1 to {N}",
                R::NAME
            )));
        }
        let mut link = [0.0; PER_LINK];
        link.copy_from_slice(&p[(l - 1) * PER_LINK..l * PER_LINK]);
        p[(l - 1) * PER_LINK..l * PER_LINK]
            .copy_from_slice(&break_triangle(&link, TRIANGLE_EXCESS));
    }
    Ok(p)
}

/// [`measure_plant`] on `robot` with `unmodelled` effects: the plant runs on the parametric
/// model at [`plant_parameters`] with `friction` (plus [`unmodelled_friction`] if asked),
/// tracked by the computed-torque controller on `robot`'s own (nominal) model, for `duration`
/// s of `excitation` (repeated), torques recorded with `noise_pct` % noise from `seed`.
///
/// # Errors
///
/// [`IdentificationError::Setting`] for a bad link or setting, `Simulation` if the run breaks
/// down.
pub fn measure_unmodelled<const N: usize, R: Identifiable<N> + ParametricModel<N>>(
    robot: &R,
    friction: Option<JointFriction<N>>,
    unmodelled: &Unmodelled,
    excitation: &FourierExcitation<N>,
    duration: f64,
    noise_pct: f64,
    seed: u64,
) -> Result<Measurement<N>, IdentificationError> {
    let p = plant_parameters(robot, unmodelled)?;
    let params = R::parameters_from(&p).ok_or_else(|| {
        IdentificationError::Setting(format!("{}: {} standard parameters", R::NAME, p.len()))
    })?;
    let plant = Parametric::new(*robot, params);
    let friction = match (friction, unmodelled.friction) {
        (Some(f), true) => Some(unmodelled_friction(f)?),
        (None, true) => {
            return Err(IdentificationError::Setting(
                "unmodelled friction: the plant has no friction to add it to".into(),
            ))
        }
        (f, false) => f,
    };
    measure_plant(
        &plant, robot, friction, excitation, duration, noise_pct, seed,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::identification::physical::smallest_eigenvalue;

    #[test]
    fn a_broken_link_has_no_rigid_body_and_keeps_positive_moments() {
        let p = [2.0, 0.1, -0.05, 0.2, 0.09, 0.002, -0.01, 0.1, 0.005, 0.05];
        assert!(smallest_eigenvalue(&p) > 0.0);
        let b = break_triangle(&p, TRIANGLE_EXCESS);
        assert!(smallest_eigenvalue(&b) < 0.0, "{b:?}");
        // Mass and first moments unchanged; the moments about the centre positive, the
        // largest 1.3 times the sum of the others.
        assert_eq!(b[..4], p[..4]);
        let eig = SymmetricEigen::new(LinkInertia::from_standard(&b).inertia);
        let mut m: Vec<f64> = eig.eigenvalues.iter().copied().collect();
        m.sort_by(f64::total_cmp);
        assert!(m[0] > 0.0);
        approx::assert_relative_eq!(m[2], 1.3 * (m[0] + m[1]), epsilon = 1e-12);
    }
}
