//! The values each trial of a sweep gets, drawn before any trial runs, and a scenario with
//! them applied.

use rand::rngs::Xoshiro256PlusPlus;
use rand::{RngExt, SeedableRng};
use rand_distr::{Distribution as _, Normal};

use super::spec::{Distribution, SweepKey, SweepSpec};
use crate::scenario::Scenario;

/// One trial's draws.
#[derive(Clone, Debug, PartialEq)]
pub struct Draw {
    /// Trial number, from 0.
    pub index: usize,
    /// The drawn values, in the order of [`SweepSpec::columns`].
    pub values: Vec<f64>,
    /// Seed of the trial's sensor noise.
    pub sensor_seed: u64,
}

fn sample(d: Distribution, rng: &mut Xoshiro256PlusPlus, (lo, hi): (f64, f64)) -> f64 {
    let x = match d {
        Distribution::Uniform { low, high } if low == high => low,
        Distribution::Uniform { low, high } => rng.random_range(low..=high),
        Distribution::Normal { mean, std } => match Normal::new(mean, std) {
            Ok(n) => n.sample(rng),
            Err(_) => mean,
        },
    };
    x.clamp(lo, hi)
}

/// The draws of `samples` trials from one generator seeded with `seed`, trial after trial
/// and column after column: the same seed gives the same draws whatever runs them.
#[must_use]
pub fn draw_all(spec: &SweepSpec, samples: usize, seed: u64) -> Vec<Draw> {
    let mut rng = Xoshiro256PlusPlus::seed_from_u64(seed);
    (0..samples)
        .map(|index| {
            let mut values = Vec::new();
            for (key, d) in &spec.entries {
                let (lo, hi, _) = key.domain();
                for _ in key.columns(spec.dof) {
                    values.push(sample(*d, &mut rng, (lo, hi)));
                }
            }
            Draw {
                index,
                values,
                sensor_seed: rng.random::<u64>(),
            }
        })
        .collect()
}

/// `base` with trial `d`'s values in place.
#[must_use]
pub fn apply(base: &Scenario, spec: &SweepSpec, d: &Draw) -> Scenario {
    let mut s = base.clone();
    let mut v = d.values.iter().copied();
    let mut next = || v.next().unwrap_or(0.0);
    let n = spec.dof;
    for (key, _) in &spec.entries {
        match key {
            SweepKey::LinkMassScale => s.plant.mass_scale = (0..n).map(|_| next()).collect(),
            SweepKey::LinkInertiaScale => {
                s.plant.inertia_scale = (0..n).map(|_| next()).collect();
            }
            SweepKey::LinkComOffset => {
                s.plant.com_offset_m = (0..n).map(|_| [next(), next(), next()]).collect();
            }
            SweepKey::Payload => s.plant.payload_kg = next(),
            SweepKey::FrictionViscous => {
                s.plant.friction_viscous = (0..n).map(|_| next()).collect();
            }
            SweepKey::FrictionCoulomb => {
                s.plant.friction_coulomb = (0..n).map(|_| next()).collect();
            }
            SweepKey::Stiffness => {
                let k = next();
                s.surfaces.iter_mut().for_each(|c| c.stiffness = k);
            }
            SweepKey::SurfaceOffset => {
                let shift = next();
                for c in &mut s.surfaces {
                    c.geometry = crate::scenario::shifted(&c.geometry, shift);
                }
                // The controller's belief stays where the file puts the surface.
                if let Some(f) = s.force.as_mut() {
                    f.expected_shift_m -= shift;
                }
            }
            SweepKey::SensorNoise => s.sensor.noise_n = next(),
            SweepKey::SensorBias => s.sensor.bias_n = next(),
        }
    }
    s.sensor.seed = d.sensor_seed;
    s
}
