//! A reference given as samples, e.g. read from a CSV file (feature `std`).
//!
//! # Interpolation
//!
//! The position and yaw are interpolated linearly between samples. Velocity and
//! acceleration are estimated once, at construction, at every sample by finite differences
//! of the samples (second order, valid for uneven spacing: the derivatives of the parabola
//! through the sample and its two neighbours; at the first and last sample the parabola
//! through the first or last three), and are then interpolated linearly too. They estimate
//! the derivatives of the smooth motion the samples come from, so they are what a
//! controller should feed forward; they are *not* the derivatives of the piecewise-linear
//! position (whose velocity would step at every sample and whose acceleration would be zero).
//! With two samples only, the velocity is their slope and the acceleration zero.
//!
//! The yaw is interpolated as a plain number: give it unwrapped (continuous), not folded into
//! `(-pi, pi]`, or an interpolation across the fold sweeps the long way round.
//!
//! # CSV format
//!
//! [`SampledTrajectory::from_csv_reader`] reads comma-separated text whose first line is
//! exactly
//!
//! ```text
//! t,x,y,z,yaw
//! ```
//!
//! (spaces around a name or value are ignored; nothing else is accepted in the header), then
//! one sample per line: time in s, position of the end effector in the base frame in m, yaw
//! about the base z axis in rad. Times start at 0 or later and increase strictly. Empty lines
//! are skipped; there are no comment lines. The text is UTF-8; a leading byte-order mark (as
//! spreadsheet programs save it) is ignored, and lines may end in LF or CRLF.

use std::io::Read;

use nalgebra::Vector3;

use crate::csv_text::{is_blank, CsvText, TextError};

use super::{CartesianTarget, CartesianTrajectory, PoseSample};

/// The exact header of a reference CSV file.
pub const CSV_HEADER: [&str; 5] = ["t", "x", "y", "z", "yaw"];

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
        /// Which value: `t`, `x`, `y`, `z` or `yaw`.
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

/// Why a CSV reference could not be read. Lines and columns count from 1; the header is
/// line 1.
#[derive(Debug, thiserror::Error)]
pub enum CsvError {
    /// The input could not be read or is not valid CSV (e.g. not UTF-8).
    #[error("line {line}: cannot read the CSV: {source}")]
    Read {
        /// Line where reading failed (0 if unknown).
        line: u64,
        /// What the CSV reader reported.
        #[source]
        source: csv::Error,
    },
    /// The input is not UTF-8 text.
    #[error("line {line}: not UTF-8 text (byte {offset} of the line is 0x{byte:02X}); save the file as UTF-8")]
    NotUtf8 {
        /// Line number.
        line: u64,
        /// Position of the offending byte in the line (from 1).
        offset: u64,
        /// The byte.
        byte: u8,
    },
    /// The input is empty.
    #[error("empty input: expected the header `t,x,y,z,yaw` and at least 2 samples")]
    Empty,
    /// The first line is not exactly `t,x,y,z,yaw`.
    #[error(
        "line {line}: the header must be exactly `t,x,y,z,yaw` (s, m, m, m, rad), found `{found}`"
    )]
    Header {
        /// Line of the header (1).
        line: u64,
        /// The header as read.
        found: String,
    },
    /// A data line has fewer than five fields.
    #[error("line {line}, column {column}: missing column `{name}` (expected 5 columns `t,x,y,z,yaw`, found {found})")]
    MissingColumn {
        /// Line number.
        line: u64,
        /// First missing column (1-based).
        column: usize,
        /// Its name in the header.
        name: &'static str,
        /// Number of fields found on the line.
        found: usize,
    },
    /// A data line has more than five fields.
    #[error("line {line}: {found} columns, expected 5 (`t,x,y,z,yaw`)")]
    ExtraColumns {
        /// Line number.
        line: u64,
        /// Number of fields found on the line.
        found: usize,
    },
    /// A field is not a number.
    #[error("line {line}, column {column} (`{name}`): `{text}` is not a number")]
    NotNumeric {
        /// Line number.
        line: u64,
        /// Column (1-based).
        column: usize,
        /// Its name in the header.
        name: &'static str,
        /// The field as read.
        text: String,
    },
    /// A field is NaN or infinite.
    #[error("line {line}, column {column} (`{name}`): {value} is not finite")]
    NonFinite {
        /// Line number.
        line: u64,
        /// Column (1-based).
        column: usize,
        /// Its name in the header.
        name: &'static str,
        /// The value.
        value: f64,
    },
    /// The first time is negative.
    #[error(
        "line {line}, column 1 (`t`): time {t} s is negative; references start at t = 0 or later"
    )]
    NegativeStart {
        /// Line number.
        line: u64,
        /// The time, s.
        t: f64,
    },
    /// A time is not after the previous line's.
    #[error("line {line}, column 1 (`t`): time {t} s is not after the previous line's {previous} s (times must increase strictly)")]
    NotIncreasing {
        /// Line number.
        line: u64,
        /// The time, s.
        t: f64,
        /// The previous line's time, s.
        previous: f64,
    },
    /// Fewer than two data lines.
    #[error("{rows} data row(s) after the header; a reference needs at least 2")]
    TooFewRows {
        /// Number of data rows read.
        rows: usize,
    },
}

/// Per-sample derivative estimates, stored alongside the samples.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Knot {
    t: f64,
    /// `[x, y, z, yaw]`.
    value: [f64; 4],
    velocity: [f64; 4],
    acceleration: [f64; 4],
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
/// use scara::trajectory::{CartesianTrajectory, SampledTrajectory};
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
    /// A reference through `samples` (times in s, positions in m, yaw in rad).
    ///
    /// # Errors
    ///
    /// [`SampledError`] if there are fewer than two samples, a value is not finite, the first
    /// time is negative or the times do not increase strictly.
    ///
    /// # Example
    ///
    /// ```
    /// use scara::trajectory::{CartesianTrajectory, PoseSample, SampledTrajectory};
    /// use nalgebra::Vector3;
    ///
    /// let samples: Vec<PoseSample> = (0..=10)
    ///     .map(|k| {
    ///         let t = 0.1 * k as f64;
    ///         PoseSample::new(t, Vector3::new(0.5, t * t, 0.2), 0.0)
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
            let values = [s.t, s.position.x, s.position.y, s.position.z, s.yaw];
            if let Some(k) = values.iter().position(|v| !v.is_finite()) {
                return Err(SampledError::NonFinite {
                    index,
                    name: CSV_HEADER[k],
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

    /// Reads a reference from CSV text with the header `t,x,y,z,yaw` (see the [module
    /// documentation](self) for the format).
    ///
    /// # Errors
    ///
    /// [`CsvError`], naming the line (and column) at fault: unreadable input, a wrong header,
    /// a missing or extra column, a field that is not a number or not finite, a negative
    /// first time, times that do not increase strictly, fewer than two data rows.
    ///
    /// # Example
    ///
    /// ```
    /// use scara::trajectory::SampledTrajectory;
    ///
    /// let csv = "t,x,y,z,yaw\n0,0.5,0,0.2,0\n0,0.5,0.1,0.2,0\n";
    /// let err = SampledTrajectory::from_csv_reader(csv.as_bytes()).unwrap_err();
    /// assert!(err.to_string().starts_with("line 3, column 1 (`t`): time 0 s is not after"));
    /// ```
    pub fn from_csv_reader<R: Read>(reader: R) -> Result<Self, CsvError> {
        // The whole text is kept to name lines: the reader's own line count skips blank
        // lines, its byte offsets do not.
        let input = CsvText::read(reader).map_err(|e| match e {
            TextError::Io(e) => CsvError::Read {
                line: 0,
                source: csv::Error::from(e),
            },
            TextError::NotUtf8 { line, offset, byte } => CsvError::NotUtf8 { line, offset, byte },
        })?;
        let line_of = |record: &csv::StringRecord| input.line_of(record);
        let mut csv = input.reader();
        let mut records = csv.records().filter(|r| !matches!(r, Ok(r) if is_blank(r)));
        let read_error = |source: csv::Error| CsvError::Read {
            line: input.error_line(&source),
            source,
        };

        let header = records.next().ok_or(CsvError::Empty)?.map_err(read_error)?;
        let header_line = line_of(&header);
        if header.len() != CSV_HEADER.len() || header.iter().zip(CSV_HEADER).any(|(a, b)| a != b) {
            return Err(CsvError::Header {
                line: header_line,
                found: header.iter().collect::<Vec<_>>().join(","),
            });
        }

        let mut samples: Vec<PoseSample> = Vec::new();
        for record in records {
            let record = record.map_err(read_error)?;
            let line = line_of(&record);
            if record.len() < CSV_HEADER.len() {
                return Err(CsvError::MissingColumn {
                    line,
                    column: record.len() + 1,
                    name: CSV_HEADER[record.len()],
                    found: record.len(),
                });
            }
            if record.len() > CSV_HEADER.len() {
                return Err(CsvError::ExtraColumns {
                    line,
                    found: record.len(),
                });
            }
            let mut values = [0.0; 5];
            for (k, text) in record.iter().enumerate() {
                let value: f64 = text.parse().map_err(|_| CsvError::NotNumeric {
                    line,
                    column: k + 1,
                    name: CSV_HEADER[k],
                    text: text.to_owned(),
                })?;
                if !value.is_finite() {
                    return Err(CsvError::NonFinite {
                        line,
                        column: k + 1,
                        name: CSV_HEADER[k],
                        value,
                    });
                }
                values[k] = value;
            }
            let t = values[0];
            match samples.last() {
                None if t < 0.0 => return Err(CsvError::NegativeStart { line, t }),
                Some(previous) if t <= previous.t => {
                    return Err(CsvError::NotIncreasing {
                        line,
                        t,
                        previous: previous.t,
                    })
                }
                _ => {}
            }
            samples.push(PoseSample::new(
                t,
                Vector3::new(values[1], values[2], values[3]),
                values[4],
            ));
        }
        if samples.len() < 2 {
            return Err(CsvError::TooFewRows {
                rows: samples.len(),
            });
        }
        Ok(Self::from_valid(&samples))
    }

    /// Number of samples.
    ///
    /// ```
    /// use scara::trajectory::SampledTrajectory;
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
    /// use scara::trajectory::SampledTrajectory;
    /// let csv = "t,x,y,z,yaw\n0,0.5,0,0.2,0\n1,0.5,0.1,0.2,0\n";
    /// let reference = SampledTrajectory::from_csv_reader(csv.as_bytes()).unwrap();
    /// let times: Vec<f64> = reference.samples().map(|s| s.t).collect();
    /// assert_eq!(times, [0.0, 1.0]);
    /// ```
    pub fn samples(&self) -> impl ExactSizeIterator<Item = PoseSample> + '_ {
        self.knots.iter().map(|k| {
            PoseSample::new(
                k.t,
                Vector3::new(k.value[0], k.value[1], k.value[2]),
                k.value[3],
            )
        })
    }

    /// Builds the knots from checked samples (at least two, finite, strictly increasing).
    fn from_valid(samples: &[PoseSample]) -> Self {
        let values: Vec<[f64; 4]> = samples
            .iter()
            .map(|s| [s.position.x, s.position.y, s.position.z, s.yaw])
            .collect();
        let n = samples.len();
        let t = |i: usize| samples[i].t;
        let mut knots = Vec::with_capacity(n);
        for i in 0..n {
            let (velocity, acceleration) = if n == 2 {
                let slope = core::array::from_fn(|k| (values[1][k] - values[0][k]) / (t(1) - t(0)));
                (slope, [0.0; 4])
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
                let v = core::array::from_fn(|k| {
                    da * values[a][k] + db * values[b][k] + dc * values[c][k]
                });
                let acc = core::array::from_fn(|k| {
                    sa * values[a][k] + sb * values[b][k] + sc * values[c][k]
                });
                (v, acc)
            };
            knots.push(Knot {
                t: t(i),
                value: values[i],
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
        let lerp = |p: &[f64; 4], q: &[f64; 4], k: usize| p[k] + w * (q[k] - p[k]);
        let v =
            |p: &[f64; 4], q: &[f64; 4]| -> [f64; 4] { core::array::from_fn(|k| lerp(p, q, k)) };
        let (x, xd, xdd) = (
            v(&a.value, &b.value),
            v(&a.velocity, &b.velocity),
            v(&a.acceleration, &b.acceleration),
        );
        CartesianTarget {
            position: Vector3::new(x[0], x[1], x[2]),
            yaw: x[3],
            velocity: Vector3::new(xd[0], xd[1], xd[2]),
            yaw_rate: xd[3],
            acceleration: Vector3::new(xdd[0], xdd[1], xdd[2]),
            yaw_acceleration: xdd[3],
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::trajectory::{sample, PositionTest};

    fn read(text: &str) -> Result<SampledTrajectory, CsvError> {
        SampledTrajectory::from_csv_reader(text.as_bytes())
    }

    #[test]
    fn interpolates_positions_linearly_and_hits_samples() {
        let r = read("t,x,y,z,yaw\n0,0.5,0,0.2,0\n1,0.6,0.1,0.1,1\n3,0.6,0.3,0.1,1\n").unwrap();
        assert_eq!(r.at(1.0).position, Vector3::new(0.6, 0.1, 0.1));
        let mid = r.at(0.25);
        assert!((mid.position - Vector3::new(0.525, 0.025, 0.175)).norm() < 1e-15);
        assert!((mid.yaw - 0.25).abs() < 1e-15);
        assert_eq!(r.at(-1.0).position, r.at(0.0).position);
        assert_eq!(r.at(5.0).position, Vector3::new(0.6, 0.3, 0.1));
        assert_eq!(r.duration(), 3.0);
    }

    #[test]
    fn derivatives_are_exact_for_a_parabola_with_uneven_spacing() {
        // y = 1 + 2 t - 3 t^2 on an uneven grid: three-point differences are exact.
        let times = [0.0, 0.1, 0.25, 0.3, 0.7, 1.0];
        let samples: Vec<PoseSample> = times
            .iter()
            .map(|&t| PoseSample::new(t, Vector3::new(0.0, 1.0 + 2.0 * t - 3.0 * t * t, 0.0), t))
            .collect();
        let r = SampledTrajectory::new(&samples).unwrap();
        for &t in &times {
            let target = r.at(t);
            assert!(
                (target.velocity.y - (2.0 - 6.0 * t)).abs() < 1e-12,
                "t = {t}"
            );
            assert!((target.acceleration.y + 6.0).abs() < 1e-10, "t = {t}");
            assert!((target.yaw_rate - 1.0).abs() < 1e-12);
            assert!(target.yaw_acceleration.abs() < 1e-10);
        }
    }

    #[test]
    fn a_sampled_thesis_reference_matches_the_analytic_one() {
        let analytic = PositionTest::new();
        let samples = sample(&analytic, 0.005);
        let sampled = SampledTrajectory::new(&samples).unwrap();
        for k in 0..=1000 {
            let t = 0.01 * k as f64 + 0.0013;
            let (a, s) = (analytic.at(t), sampled.at(t));
            // Linear interpolation: error ~ h^2/8 |x''|; differences: ~ h^2 |x'''|/6.
            assert!((a.position - s.position).norm() < 1e-5, "t = {t}");
            assert!((a.velocity - s.velocity).norm() < 2e-4, "t = {t}");
            assert!((a.acceleration - s.acceleration).norm() < 2e-2, "t = {t}");
        }
    }

    #[test]
    fn two_samples_give_their_slope() {
        let r = read("t,x,y,z,yaw\n1,0,0,0,0\n3,2,0,0,0\n").unwrap();
        assert_eq!(r.at(2.0).velocity.x, 1.0);
        assert_eq!(r.at(2.0).acceleration.x, 0.0);
    }

    #[test]
    fn header_must_be_exact() {
        let err = read("time,x,y,z,yaw\n0,0,0,0,0\n1,0,0,0,0\n").unwrap_err();
        assert!(matches!(err, CsvError::Header { line: 1, .. }), "{err}");
        let err = read("t,x,y,z\n0,0,0,0\n").unwrap_err();
        assert!(matches!(err, CsvError::Header { .. }), "{err}");
        let err = read("0,0,0,0,0\n1,0,0,0,0\n").unwrap_err();
        assert!(matches!(err, CsvError::Header { .. }), "{err}");
        assert!(matches!(read("").unwrap_err(), CsvError::Empty));
        // Spaces around names are fine.
        assert!(read(" t , x , y , z , yaw \n0,0,0,0,0\n1,0,0,0,0\n").is_ok());
    }

    #[test]
    fn errors_name_line_and_column() {
        let err = read("t,x,y,z,yaw\n0,0,0,0,0\n1,0,0\n").unwrap_err();
        assert_eq!(
            err.to_string(),
            "line 3, column 4: missing column `z` (expected 5 columns `t,x,y,z,yaw`, found 3)"
        );
        let err = read("t,x,y,z,yaw\n0,0,0,0,0\n1,0,0,0,0,9\n").unwrap_err();
        assert!(
            matches!(err, CsvError::ExtraColumns { line: 3, found: 6 }),
            "{err}"
        );
        let err = read("t,x,y,z,yaw\n0,0,0,0,0\n1,0,0,inf,0\n").unwrap_err();
        assert_eq!(err.to_string(), "line 3, column 4 (`z`): inf is not finite");
        let err = read("t,x,y,z,yaw\n0,0,0,0,0\n1,0,0,0,NaN\n").unwrap_err();
        assert!(
            matches!(
                err,
                CsvError::NonFinite {
                    line: 3,
                    column: 5,
                    ..
                }
            ),
            "{err}"
        );
        let err = read("t,x,y,z,yaw\n0,0,0,0,0\n2,0,0,0,0\n1,0,0,0,0\n").unwrap_err();
        assert!(
            matches!(err, CsvError::NotIncreasing { line: 4, .. }),
            "{err}"
        );
        let err = read("t,x,y,z,yaw\n-1,0,0,0,0\n2,0,0,0,0\n").unwrap_err();
        assert!(
            matches!(err, CsvError::NegativeStart { line: 2, .. }),
            "{err}"
        );
        let err = read("t,x,y,z,yaw\n0,0,0,0,0\n").unwrap_err();
        assert_eq!(
            err.to_string(),
            "1 data row(s) after the header; a reference needs at least 2"
        );
        let err = read("t,x,y,z,yaw\n0,0,0,0,0\n\n1,0,0,0,x\n").unwrap_err();
        assert!(
            matches!(
                err,
                CsvError::NotNumeric {
                    line: 4,
                    column: 5,
                    ..
                }
            ),
            "{err}"
        );
    }

    #[test]
    fn byte_order_mark_and_crlf_are_accepted() {
        let plain = "t,x,y,z,yaw\n0,0.5,0,0.2,0\n1,0.6,0.1,0.1,1\n";
        let expected = read(plain).unwrap();
        let crlf = plain.replace('\n', "\r\n");
        assert_eq!(read(&crlf).unwrap(), expected);
        assert_eq!(read(&format!("\u{feff}{plain}")).unwrap(), expected);
        assert_eq!(read(&format!("\u{feff}{crlf}")).unwrap(), expected);
        // Lines are still counted right, blank ones included.
        let err = read("\u{feff}t,x,y,z,yaw\r\n0,0,0,0,0\r\n\r\n1,0,0,0,x\r\n").unwrap_err();
        assert_eq!(
            err.to_string(),
            "line 4, column 5 (`yaw`): `x` is not a number"
        );
        // A byte-order mark anywhere else is not ignored.
        let err = read("t,x,y,z,yaw\n\u{feff}0,0,0,0,0\n1,0,0,0,0\n").unwrap_err();
        assert!(
            matches!(
                err,
                CsvError::NotNumeric {
                    line: 2,
                    column: 1,
                    ..
                }
            ),
            "{err}"
        );
    }

    #[test]
    fn text_that_is_not_utf8_names_its_line() {
        let err = SampledTrajectory::from_csv_reader(
            &b"t,x,y,z,yaw\r\n0,0,0,0,0\r\n1,0,\xC3(,0,0\r\n"[..],
        )
        .unwrap_err();
        assert_eq!(
            err.to_string(),
            "line 3: not UTF-8 text (byte 5 of the line is 0xC3); save the file as UTF-8"
        );
    }

    #[test]
    fn sample_list_errors() {
        let p = Vector3::zeros();
        let one = [PoseSample::new(0.0, p, 0.0)];
        assert_eq!(
            SampledTrajectory::new(&one),
            Err(SampledError::TooFewSamples { count: 1 })
        );
        let nan = [
            PoseSample::new(0.0, p, 0.0),
            PoseSample::new(1.0, p, f64::NAN),
        ];
        assert!(matches!(
            SampledTrajectory::new(&nan),
            Err(SampledError::NonFinite {
                index: 1,
                name: "yaw",
                ..
            })
        ));
        let same = [PoseSample::new(0.0, p, 0.0), PoseSample::new(0.0, p, 0.0)];
        assert!(matches!(
            SampledTrajectory::new(&same),
            Err(SampledError::NotIncreasing { index: 1, .. })
        ));
    }
}
