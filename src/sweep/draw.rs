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
///
/// # Errors
///
/// A message if the drawn fault is not one its kind accepts (a size out of its range).
pub fn apply(base: &Scenario, spec: &SweepSpec, d: &Draw) -> Result<Scenario, String> {
    let mut s = base.clone();
    let (mut kind, mut start, mut size, mut duration) = (None, 0.0, None, None);
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
                    c.geometry = c.geometry.shifted(shift);
                }
                // The controller's belief stays where the file puts the surface.
                if let Some(f) = s.force.as_mut() {
                    f.expected_shift_m -= shift;
                }
            }
            SweepKey::SensorNoise => s.sensor.noise_n = next(),
            SweepKey::SensorBias => s.sensor.bias_n = next(),
            SweepKey::FaultKind => {
                // `[0, n]` drawn: the index is its floor (n itself, probability 0, the last).
                let i = (next().floor().max(0.0) as usize)
                    .min(spec.fault_kinds.len().saturating_sub(1));
                kind = spec.fault_kinds.get(i).cloned();
            }
            SweepKey::FaultStart => start = next(),
            SweepKey::FaultSize => size = Some(next()),
            SweepKey::FaultDuration => duration = Some(next()),
        }
    }
    s.sensor.seed = d.sensor_seed;
    if let Some(kind) = kind {
        let f = crate::scenario::fault_spec::drawn(&s, &kind, start, size, duration)
            .map_err(|e| e.to_string())?;
        s.faults.push(f);
    }
    Ok(s)
}
