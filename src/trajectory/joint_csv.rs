//! A joint-space reference from samples `t, q1 .. qn` (a CSV file with that header, s and rad
//! or m), interpolated by a natural cubic spline per joint, so that positions, velocities and
//! accelerations are continuous (what computed torque needs).
//!
//! A plan written by `armdyn plan --csv` (header `t, q_<joint>.., qd_<joint>.., ...`, the
//! robot's joint names) is read as well: with its velocities, each interval is the cubic
//! Hermite polynomial through both knots' positions and velocities, so the reference passes
//! through the plan's own states (its accelerations, linear in each interval, may step at a
//! knot, as the plan's torque does). Further columns (`qdd_`, `tau_`) are not used.

use std::io::Read;

pub use crate::csv_text::CsvError;
use crate::csv_text::{check_times, CsvText};
use crate::model::JointVector;
use crate::target::JointTarget;

/// Natural cubic spline through `(t_k, q_k)` per joint; held constant outside `[t_0, t_end]`.
#[derive(Clone, Debug, PartialEq)]
pub struct JointReference<const N: usize> {
    t: Vec<f64>,
    q: Vec<JointVector<N>>,
    /// Second derivatives at the knots (natural spline), or the knots' velocities (Hermite).
    m: Vec<JointVector<N>>,
    /// Whether `m` holds velocities: cubic Hermite interpolation.
    hermite: bool,
}

impl<const N: usize> JointReference<N> {
    /// From samples (times strictly increasing, starting at 0, at least two).
    ///
    /// # Errors
    ///
    /// [`CsvError::TooFewRows`], [`CsvError::StartNotZero`], [`CsvError::NotIncreasing`] or
    /// [`CsvError::Samples`] for unusable samples.
    ///
    /// ```
    /// use armdyn::trajectory::JointReference;
    /// use nalgebra::Vector2;
    ///
    /// let r = JointReference::<2>::new(vec![0.0, 1.0, 2.0],
    ///     vec![Vector2::new(0.0, 0.0), Vector2::new(1.0, 2.0), Vector2::new(2.0, 4.0)]).unwrap();
    /// let target = r.at(0.5);
    /// assert!((target.q[1] - 1.0).abs() < 1e-12);
    /// assert!((target.qd[0] - 1.0).abs() < 1e-12);
    /// ```
    pub fn new(t: Vec<f64>, q: Vec<JointVector<N>>) -> Result<Self, CsvError> {
        if t.len() != q.len() {
            return Err(CsvError::Samples(
                "a joint reference needs one position per time",
            ));
        }
        if t.len() < 2 {
            return Err(CsvError::TooFewRows {
                rows: t.len(),
                min: 2,
            });
        }
        // Lines as in a file with the header on line 1.
        if t[0] != 0.0 {
            return Err(CsvError::StartNotZero {
                line: 2,
                column: 1,
                t: t[0],
            });
        }
        for k in 1..t.len() {
            if t[k].partial_cmp(&t[k - 1]) != Some(core::cmp::Ordering::Greater) {
                return Err(CsvError::NotIncreasing {
                    line: k as u64 + 2,
                    column: 1,
                    t: t[k],
                    previous: t[k - 1],
                });
            }
        }
        // Tridiagonal system of the natural spline (Thomas algorithm), all joints at once.
        let n = t.len();
        let mut m = vec![JointVector::<N>::zeros(); n];
        let mut c_prime = vec![0.0; n];
        let mut d_prime = vec![JointVector::<N>::zeros(); n];
        for k in 1..n - 1 {
            let (h0, h1) = (t[k] - t[k - 1], t[k + 1] - t[k]);
            let rhs = ((q[k + 1] - q[k]) / h1 - (q[k] - q[k - 1]) / h0) * 6.0;
            let (a, b, c) = (h0, 2.0 * (h0 + h1), h1);
            let denom = b - a * c_prime[k - 1];
            c_prime[k] = c / denom;
            d_prime[k] = (rhs - d_prime[k - 1] * a) / denom;
        }
        for k in (1..n - 1).rev() {
            m[k] = d_prime[k] - m[k + 1] * c_prime[k];
        }
        Ok(Self {
            t,
            q,
            m,
            hermite: false,
        })
    }

    /// From samples of positions and velocities (times strictly increasing, starting at 0, at
    /// least two): each interval the cubic Hermite polynomial through both ends' `q` and `qd`.
    ///
    /// # Errors
    ///
    /// As [`Self::new`]; [`CsvError::Samples`] if `qd` is not as long as `q`.
    pub fn with_velocities(
        t: Vec<f64>,
        q: Vec<JointVector<N>>,
        qd: Vec<JointVector<N>>,
    ) -> Result<Self, CsvError> {
        if qd.len() != q.len() {
            return Err(CsvError::Samples(
                "a joint reference needs one velocity per sample",
            ));
        }
        let spline = Self::new(t, q)?;
        Ok(Self {
            m: qd,
            hermite: true,
            ..spline
        })
    }

    /// Reads a CSV with header `t,q1,...,qN` (s; rad or m).
    ///
    /// # Errors
    ///
    /// A [`CsvError`] naming the line and column of the first problem.
    pub fn from_csv_reader<R: Read>(reader: R) -> Result<Self, CsvError> {
        Self::from_csv_reader_named(reader, &[])
    }

    /// Reads a CSV with header `t,q1,...,qN`, or a plan's `t,q_<name>..,qd_<name>..,...` for
    /// the joints `names` (see the [module documentation](self)).
    ///
    /// # Errors
    ///
    /// A [`CsvError`] naming the line and column of the first problem.
    pub fn from_csv_reader_named<R: Read>(reader: R, names: &[&str]) -> Result<Self, CsvError> {
        let numbered: Vec<String> = core::iter::once("t".to_string())
            .chain((1..=N).map(|i| format!("q{i}")))
            .collect();
        let planned: Vec<String> = if names.len() == N {
            core::iter::once("t".to_string())
                .chain(names.iter().map(|n| format!("q_{n}")))
                .chain(names.iter().map(|n| format!("qd_{n}")))
                .collect()
        } else {
            Vec::new()
        };
        let mut expected = format!("`{}`", numbered.join(","));
        if names.len() == N {
            expected += &format!(" or a plan's `{},...`", planned.join(","));
        }
        let (velocities, rows) = CsvText::read(reader)?.number_table(&expected, |line, got| {
            if got == numbered {
                Ok(false)
            } else if !planned.is_empty()
                && got.len() >= planned.len()
                && got[..planned.len()] == planned[..]
            {
                Ok(true)
            } else {
                Err(CsvError::Header {
                    line,
                    expected: expected.clone(),
                    found: got.join(","),
                })
            }
        })?;
        check_times(&rows, 0, true)?;
        if let Some(first) = rows.first().filter(|r| r.values[0] != 0.0) {
            return Err(CsvError::StartNotZero {
                line: first.line,
                column: 1,
                t: first.values[0],
            });
        }
        let t = rows.iter().map(|r| r.values[0]).collect();
        let q = rows
            .iter()
            .map(|r| JointVector::<N>::from_fn(|i, _| r.values[1 + i]))
            .collect();
        let qd = if velocities {
            rows.iter()
                .map(|r| JointVector::<N>::from_fn(|i, _| r.values[1 + N + i]))
                .collect()
        } else {
            Vec::new()
        };
        if velocities {
            Self::with_velocities(t, q, qd)
        } else {
            Self::new(t, q)
        }
    }

    /// Time of the last sample, s.
    #[must_use]
    pub fn duration(&self) -> f64 {
        self.t[self.t.len() - 1]
    }

    /// Position, velocity and acceleration at `t` (s); at rest at the end values outside
    /// `[0, duration]`.
    #[must_use]
    pub fn at(&self, t: f64) -> JointTarget<N> {
        let last = self.t.len() - 1;
        if t < self.t[0] || t > self.t[last] {
            let k = if t < self.t[0] { 0 } else { last };
            return JointTarget {
                q: self.q[k],
                qd: JointVector::zeros(),
                qdd: JointVector::zeros(),
            };
        }
        let k = (self.t.partition_point(|&x| x <= t) - 1).min(last - 1);
        let h = self.t[k + 1] - self.t[k];
        let (a, b) = ((self.t[k + 1] - t) / h, (t - self.t[k]) / h);
        let (m0, m1, q0, q1) = (self.m[k], self.m[k + 1], self.q[k], self.q[k + 1]);
        if self.hermite {
            // q(s) = h00 q0 + h h10 v0 + h01 q1 + h h11 v1, s = b in [0, 1].
            let (s, s2, s3) = (b, b * b, b * b * b);
            let q = q0 * (2.0 * s3 - 3.0 * s2 + 1.0)
                + m0 * (h * (s3 - 2.0 * s2 + s))
                + q1 * (3.0 * s2 - 2.0 * s3)
                + m1 * (h * (s3 - s2));
            let qd = (q0 - q1) * ((6.0 * s2 - 6.0 * s) / h)
                + m0 * (3.0 * s2 - 4.0 * s + 1.0)
                + m1 * (3.0 * s2 - 2.0 * s);
            let qdd = (q0 - q1) * ((12.0 * s - 6.0) / (h * h))
                + m0 * ((6.0 * s - 4.0) / h)
                + m1 * ((6.0 * s - 2.0) / h);
            return JointTarget { q, qd, qdd };
        }
        let q = q0 * a + q1 * b + (m0 * (a * a * a - a) + m1 * (b * b * b - b)) * (h * h / 6.0);
        let qd = (q1 - q0) / h + (m1 * (3.0 * b * b - 1.0) - m0 * (3.0 * a * a - 1.0)) * (h / 6.0);
        let qdd = m0 * a + m1 * b;
        JointTarget { q, qd, qdd }
    }
}
