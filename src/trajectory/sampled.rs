//! A reference given as samples, e.g. read from a CSV file (feature `std`).
//!
//! # Interpolation
//!
//! The position is interpolated linearly between samples, the orientation along the geodesic
//! of SO(3) (slerp, the short way round). Velocity and acceleration are estimated once, at
//! construction, at every sample by finite differences of the samples (second order, valid
//! for uneven spacing: the derivatives of the parabola through the sample and its two
//! neighbours; at the first and last sample the parabola through the first or last three),
//! and are then interpolated linearly too. For the orientation the differences are taken of
//! the rotation vectors `log(R_k R_b^T)` of the three samples relative to the middle one,
//! which gives the angular velocity and acceleration (base frame) to second order. They
//! estimate the derivatives of the smooth motion the samples come from, so they are what a
//! controller should feed forward; they are *not* the derivatives of the piecewise-linear
//! position (whose velocity would step at every sample and whose acceleration would be zero).
//! With two samples only, the velocity is their slope and the acceleration zero.
//!
//! Consecutive samples must differ by less than half a turn in orientation (the slerp takes
//! the short way).
//!
//! The CSV format is in [`pose_csv`](super::pose_csv).

use nalgebra::{UnitQuaternion, Vector3};

use crate::target::{orientation, CartesianTarget, PoseSample};

use super::CartesianTrajectory;

/// Why a list of samples is not a valid reference.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SampledError {
    /// Fewer than two samples.
    #[error("a sampled reference needs at least 2 samples, got {count}")]
    TooFewSamples {
        /// Number of samples given.
        count: usize,
    },
    /// A time, coordinate or yaw is NaN or infinite.
    #[error("sample {index}: {name} = {value} is not finite")]
    NonFinite {
        /// Index of the sample (from 0).
        index: usize,
        /// Which value: `t`, `x`, `y`, `z` or `orientation`.
        name: &'static str,
        /// The value.
        value: f64,
    },
    /// The first time is negative.
    #[error("sample 0: time {t} s is negative; references start at t = 0 or later")]
    NegativeStart {
        /// The first time, s.
        t: f64,
    },
    /// A time is not after the previous one.
    #[error("sample {index}: time {t} s is not after the previous sample's {previous} s (times must increase strictly)")]
    NotIncreasing {
        /// Index of the sample (from 0).
        index: usize,
        /// Its time, s.
        t: f64,
        /// The previous sample's time, s.
        previous: f64,
    },
}

/// Per-sample derivative estimates, stored alongside the samples.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Knot {
    t: f64,
    /// `[x, y, z]`, m.
    position: [f64; 3],
    orientation: UnitQuaternion<f64>,
    /// `[vx, vy, vz, wx, wy, wz]`, m/s and rad/s.
    velocity: [f64; 6],
    /// `[ax, ay, az, alpha_x, alpha_y, alpha_z]`, m/s^2 and rad/s^2.
    acceleration: [f64; 6],
}

/// A reference through given samples, interpolated linearly (see the [module
/// documentation](self) for how velocity and acceleration are estimated).
///
/// Validated on construction: at least two samples, finite values, times from 0 or later
/// and strictly increasing. [`CartesianTrajectory::duration`] is the last sample's time;
/// before the first sample the reference holds the first one, after the last the last one.
///
/// # Example
///
/// ```
/// use armdyn::trajectory::{CartesianTrajectory, SampledTrajectory};
///
/// let csv = "t,x,y,z,yaw\n0,0.5,0.0,0.2,0\n1,0.5,0.1,0.2,0\n2,0.5,0.2,0.2,0\n";
/// let reference = SampledTrajectory::from_csv_reader(csv.as_bytes()).unwrap();
/// assert_eq!(reference.duration(), 2.0);
/// let r = reference.at(0.5);
/// assert!((r.position.y - 0.05).abs() < 1e-15);
/// assert!((r.velocity.y - 0.1).abs() < 1e-15); // 0.1 m/s
///
/// let bad = "t,x,y,z,yaw\n0,0.5,0.0,0.2,0\n1,0.5,oops,0.2,0\n";
/// let err = SampledTrajectory::from_csv_reader(bad.as_bytes()).unwrap_err();
/// assert_eq!(err.to_string(), "line 3, column 3 (`y`): `oops` is not a number");
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct SampledTrajectory {
    knots: Vec<Knot>,
}

impl SampledTrajectory {
    /// A reference through `samples` (times in s, positions in m).
    ///
    /// # Errors
    ///
    /// [`SampledError`] if there are fewer than two samples, a value is not finite, the first
    /// time is negative or the times do not increase strictly.
    ///
    /// # Example
    ///
    /// ```
    /// use armdyn::trajectory::{CartesianTrajectory, SampledTrajectory};
    /// use armdyn::target::PoseSample;
    /// use nalgebra::Vector3;
    ///
    /// let samples: Vec<PoseSample> = (0..=10)
    ///     .map(|k| {
    ///         let t = 0.1 * k as f64;
    ///         PoseSample::with_yaw(t, Vector3::new(0.5, t * t, 0.2), 0.0)
    ///     })
    ///     .collect();
    /// let reference = SampledTrajectory::new(&samples).unwrap();
    /// // y = t^2: second-order differences are exact for a parabola.
    /// let r = reference.at(0.3);
    /// assert!((r.velocity.y - 0.6).abs() < 1e-12);
    /// assert!((r.acceleration.y - 2.0).abs() < 1e-9);
    /// ```
    pub fn new(samples: &[PoseSample]) -> Result<Self, SampledError> {
        if samples.len() < 2 {
            return Err(SampledError::TooFewSamples {
                count: samples.len(),
            });
        }
        for (index, s) in samples.iter().enumerate() {
            let o = s.orientation.quaternion();
            let values = [
                s.t,
                s.position.x,
                s.position.y,
                s.position.z,
                o.w,
                o.i,
                o.j,
                o.k,
            ];
            if let Some(k) = values.iter().position(|v| !v.is_finite()) {
                return Err(SampledError::NonFinite {
                    index,
                    name: ["t", "x", "y", "z", "orientation"][k.min(4)],
                    value: values[k],
                });
            }
            if index == 0 && s.t < 0.0 {
                return Err(SampledError::NegativeStart { t: s.t });
            }
            if index > 0 && s.t <= samples[index - 1].t {
                return Err(SampledError::NotIncreasing {
                    index,
                    t: s.t,
                    previous: samples[index - 1].t,
                });
            }
        }
        Ok(Self::from_valid(samples))
    }

    /// Number of samples.
    ///
    /// ```
    /// use armdyn::trajectory::SampledTrajectory;
    /// let csv = "t,x,y,z,yaw\n0,0.5,0,0.2,0\n1,0.5,0.1,0.2,0\n";
    /// assert_eq!(SampledTrajectory::from_csv_reader(csv.as_bytes()).unwrap().len(), 2);
    /// ```
    #[allow(clippy::len_without_is_empty)] // never empty: at least two samples
    pub fn len(&self) -> usize {
        self.knots.len()
    }

    /// The samples the reference was built from, in time order.
    ///
    /// ```
    /// use armdyn::trajectory::SampledTrajectory;
    /// let csv = "t,x,y,z,yaw\n0,0.5,0,0.2,0\n1,0.5,0.1,0.2,0\n";
    /// let reference = SampledTrajectory::from_csv_reader(csv.as_bytes()).unwrap();
    /// let times: Vec<f64> = reference.samples().map(|s| s.t).collect();
    /// assert_eq!(times, [0.0, 1.0]);
    /// ```
    pub fn samples(&self) -> impl ExactSizeIterator<Item = PoseSample> + '_ {
        self.knots
            .iter()
            .map(|k| PoseSample::new(k.t, Vector3::from(k.position), k.orientation))
    }

    /// Builds the knots from checked samples (at least two, finite, strictly increasing).
    pub(super) fn from_valid(samples: &[PoseSample]) -> Self {
        let positions: Vec<[f64; 3]> = samples
            .iter()
            .map(|s| [s.position.x, s.position.y, s.position.z])
            .collect();
        let n = samples.len();
        let t = |i: usize| samples[i].t;
        // The rotation vector of sample k relative to sample b, base frame.
        let relative = |k: usize, b: usize| {
            orientation::error(&samples[k].orientation, &samples[b].orientation)
        };
        let mut knots = Vec::with_capacity(n);
        for i in 0..n {
            let (velocity, acceleration) = if n == 2 {
                let dt = t(1) - t(0);
                let w = relative(1, 0) / dt;
                let v: [f64; 3] =
                    core::array::from_fn(|k| (positions[1][k] - positions[0][k]) / dt);
                ([v[0], v[1], v[2], w.x, w.y, w.z], [0.0; 6])
            } else {
                // The parabola through three consecutive samples a, b, c (the centred triple,
                // or the first/last three at the ends), evaluated at sample i.
                let b = i.clamp(1, n - 2);
                let (a, c) = (b - 1, b + 1);
                let (h1, h2) = (t(b) - t(a), t(c) - t(b));
                let ti = t(i);
                // Lagrange basis derivatives at ti.
                let (ta, tb, tc) = (t(a), t(b), t(c));
                let da = ((ti - tb) + (ti - tc)) / ((ta - tb) * (ta - tc));
                let db = ((ti - ta) + (ti - tc)) / ((tb - ta) * (tb - tc));
                let dc = ((ti - ta) + (ti - tb)) / ((tc - ta) * (tc - tb));
                let (sa, sb, sc) = (
                    2.0 / (h1 * (h1 + h2)),
                    -2.0 / (h1 * h2),
                    2.0 / (h2 * (h1 + h2)),
                );
                let v: [f64; 3] = core::array::from_fn(|k| {
                    da * positions[a][k] + db * positions[b][k] + dc * positions[c][k]
                });
                let acc: [f64; 3] = core::array::from_fn(|k| {
                    sa * positions[a][k] + sb * positions[b][k] + sc * positions[c][k]
                });
                // Rotation vectors relative to b (b's own is zero).
                let (ra, rc) = (relative(a, b), relative(c, b));
                let w = ra * da + rc * dc;
                let alpha = ra * sa + rc * sc;
                (
                    [v[0], v[1], v[2], w.x, w.y, w.z],
                    [acc[0], acc[1], acc[2], alpha.x, alpha.y, alpha.z],
                )
            };
            knots.push(Knot {
                t: t(i),
                position: positions[i],
                orientation: samples[i].orientation,
                velocity,
                acceleration,
            });
        }
        SampledTrajectory { knots }
    }
}

impl CartesianTrajectory for SampledTrajectory {
    fn duration(&self) -> f64 {
        self.knots[self.knots.len() - 1].t
    }

    fn at(&self, t: f64) -> CartesianTarget {
        let first = &self.knots[0];
        let last = &self.knots[self.knots.len() - 1];
        let t = t.clamp(first.t, last.t);
        // Index of the interval [k_i, k_{i+1}] holding t (NaN lands in the first one).
        let i = self
            .knots
            .partition_point(|k| k.t <= t)
            .clamp(1, self.knots.len() - 1)
            - 1;
        let (a, b) = (&self.knots[i], &self.knots[i + 1]);
        let w = (t - a.t) / (b.t - a.t);
        let lerp = |p: &[f64], q: &[f64], k: usize| p[k] + w * (q[k] - p[k]);
        let x: [f64; 3] = core::array::from_fn(|k| lerp(&a.position, &b.position, k));
        let xd: [f64; 6] = core::array::from_fn(|k| lerp(&a.velocity, &b.velocity, k));
        let xdd: [f64; 6] = core::array::from_fn(|k| lerp(&a.acceleration, &b.acceleration, k));
        let phi = orientation::error(&b.orientation, &a.orientation);
        let orientation = orientation::along(&a.orientation, &phi, w);
        CartesianTarget {
            position: Vector3::new(x[0], x[1], x[2]),
            orientation,
            velocity: Vector3::new(xd[0], xd[1], xd[2]),
            angular_velocity: Vector3::new(xd[3], xd[4], xd[5]),
            acceleration: Vector3::new(xdd[0], xdd[1], xdd[2]),
            angular_acceleration: Vector3::new(xdd[3], xdd[4], xdd[5]),
        }
    }
}
