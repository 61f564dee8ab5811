//! Faults of the force sensor's readings, between the sensor and the controller.

use super::Window;
use crate::control::{Controller, ControllerInput};
use crate::model::{JointVector, Wrench};
use nalgebra::Vector3;
use rand::rngs::Xoshiro256PlusPlus;
use rand::{RngExt, SeedableRng};
use rand_distr::StandardNormal;

/// What goes wrong with the readings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SensorFaultKind {
    /// No new reading: the last one is passed again, ageing.
    Dropout,
    /// Fresh readings all equal to the one at the fault's start.
    Frozen,
    /// Every axis NaN.
    Nan,
    /// The force axes infinite.
    Infinite,
    /// The reading replaced by `force_n` along `axis` (beyond the sensor's range).
    OutOfRange {
        /// Force, N, along `axis`.
        force_n: f64,
        /// Unit direction, the sensor's axes.
        axis: Vector3<f64>,
    },
    /// `force_n` along `axis` added (a spike: one period long).
    Spike {
        /// Force, N.
        force_n: f64,
        /// Unit direction.
        axis: Vector3<f64>,
    },
    /// `force_n` along `axis` added from the start on (a bias jump).
    BiasJump {
        /// Force, N.
        force_n: f64,
        /// Unit direction.
        axis: Vector3<f64>,
    },
    /// White Gaussian noise of `std_n` (1 sigma) added per force axis.
    NoiseBurst {
        /// Standard deviation, N.
        std_n: f64,
        /// Seed.
        seed: u64,
    },
}

/// One fault of the readings and when it acts.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SensorFault {
    /// What.
    pub kind: SensorFaultKind,
    /// When.
    pub window: Window,
}

/// Most sensor faults of a run.
pub const MAX_SENSOR_FAULTS: usize = 8;

/// A controller that reads the wrench through faulty readings; everything else is passed
/// through. Additive faults (bias jump, noise, spike) act first, then the replacing ones
/// (NaN, infinite, out of range, frozen), then a dropout.
#[derive(Clone, Debug)]
pub struct FaultySensor<C> {
    inner: C,
    faults: [Option<SensorFault>; MAX_SENSOR_FAULTS],
    frozen: [Option<Wrench>; MAX_SENSOR_FAULTS],
    rngs: [Option<Xoshiro256PlusPlus>; MAX_SENSOR_FAULTS],
    delivered: Option<Wrench>,
    age_s: f64,
}

impl<C> FaultySensor<C> {
    /// `inner` behind `faults`.
    ///
    /// # Errors
    ///
    /// The count, if more than [`MAX_SENSOR_FAULTS`].
    pub fn new(inner: C, faults: &[SensorFault]) -> Result<Self, usize> {
        if faults.len() > MAX_SENSOR_FAULTS {
            return Err(faults.len());
        }
        let mut s = Self {
            inner,
            faults: [None; MAX_SENSOR_FAULTS],
            frozen: [None; MAX_SENSOR_FAULTS],
            rngs: [const { None }; MAX_SENSOR_FAULTS],
            delivered: None,
            age_s: 0.0,
        };
        for (slot, f) in s.faults.iter_mut().zip(faults) {
            *slot = Some(*f);
        }
        s.reset_state();
        Ok(s)
    }

    fn reset_state(&mut self) {
        self.frozen = [None; MAX_SENSOR_FAULTS];
        self.delivered = None;
        self.age_s = 0.0;
        for (rng, f) in self.rngs.iter_mut().zip(&self.faults) {
            *rng = match f.map(|f| f.kind) {
                Some(SensorFaultKind::NoiseBurst { seed, .. }) => {
                    Some(Xoshiro256PlusPlus::seed_from_u64(seed))
                }
                _ => None,
            };
        }
    }

    /// The reading at `t` of the true reading `w`, and its age, `dt` after the last.
    fn read(&mut self, t: f64, w: &Wrench, age_s: f64, dt: f64) -> (Wrench, f64) {
        let mut x = *w;
        let mut dropped = false;
        for i in 0..MAX_SENSOR_FAULTS {
            let Some(f) = self.faults[i] else { continue };
            if !f.window.contains(t) {
                continue;
            }
            let add = |x: &mut Wrench, force: f64, axis: &Vector3<f64>| {
                for a in 0..3 {
                    x[a] += force * axis[a];
                }
            };
            match f.kind {
                SensorFaultKind::Spike { force_n, axis }
                | SensorFaultKind::BiasJump { force_n, axis } => add(&mut x, force_n, &axis),
                SensorFaultKind::NoiseBurst { std_n, .. } => {
                    if let Some(rng) = self.rngs[i].as_mut() {
                        for a in 0..3 {
                            let n: f64 = rng.sample(StandardNormal);
                            x[a] += std_n * n;
                        }
                    }
                }
                _ => {}
            }
        }
        for i in 0..MAX_SENSOR_FAULTS {
            let Some(f) = self.faults[i] else { continue };
            if !f.window.contains(t) {
                continue;
            }
            match f.kind {
                SensorFaultKind::Nan => x = Wrench::repeat(f64::NAN),
                SensorFaultKind::Infinite => {
                    for a in 0..3 {
                        x[a] = f64::INFINITY;
                    }
                }
                SensorFaultKind::OutOfRange { force_n, axis } => {
                    x = Wrench::zeros();
                    for a in 0..3 {
                        x[a] = force_n * axis[a];
                    }
                }
                SensorFaultKind::Frozen => x = *self.frozen[i].get_or_insert(x),
                SensorFaultKind::Dropout => dropped = true,
                _ => {}
            }
        }
        match (dropped, self.delivered) {
            (true, Some(last)) => {
                self.age_s += dt;
                (last, self.age_s)
            }
            _ => {
                self.delivered = Some(x);
                self.age_s = age_s;
                (x, age_s)
            }
        }
    }
}

impl<const N: usize, C: Controller<N>> Controller<N> for FaultySensor<C> {
    fn name(&self) -> &'static str {
        self.inner.name()
    }
    crate::control::pass_on_state!(inner);

    fn reset(&mut self) {
        self.inner.reset();
        self.reset_state();
    }

    fn report(&self) -> crate::control::StepReport<N> {
        let mut r = self.inner.report();
        r.measured_wrench = r.measured_wrench.or(self.delivered);
        r
    }

    fn step(&mut self, input: &ControllerInput<'_, N>, dt: f64) -> JointVector<N> {
        let (w, age_s) = self.read(input.t, input.wrench, input.wrench_age_s, dt);
        self.inner.step(
            &ControllerInput {
                wrench: &w,
                wrench_age_s: age_s,
                ..*input
            },
            dt,
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_fault_acts_in_its_window_only() {
        let w = Window {
            start_s: 0.01,
            duration_s: 0.003,
        };
        let z = Vector3::z();
        let f = Wrench::new(0.0, 0.0, -50.0, 0.0, 0.0, 0.0);
        let read = |kind| {
            let mut s = FaultySensor::new((), &[SensorFault { kind, window: w }]).unwrap();
            (0..20)
                .map(|k| s.read(k as f64 * 1e-3, &(f * (1.0 + k as f64 * 1e-3)), 0.0, 1e-3))
                .collect::<Vec<_>>()
        };
        let r = read(SensorFaultKind::Dropout);
        assert_eq!(r[9].1, 0.0);
        assert_eq!((r[10].0, r[12].1), (r[9].0, 0.003));
        approx::assert_abs_diff_eq!(r[12].1, 0.003, epsilon = 1e-15);
        assert_eq!(r[13].1, 0.0);
        let r = read(SensorFaultKind::Nan);
        assert!(r[10].0[2].is_nan() && r[12].0[5].is_nan() && r[13].0[2].is_finite());
        let r = read(SensorFaultKind::Frozen);
        assert_eq!((r[11].0, r[12].0), (r[10].0, r[10].0));
        assert_ne!(r[13].0, r[10].0);
        let r = read(SensorFaultKind::Spike {
            force_n: -2000.0,
            axis: z,
        });
        approx::assert_abs_diff_eq!(r[10].0[2], -2050.5, epsilon = 1e-9);
    }
}
