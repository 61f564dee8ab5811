//! A joint log recorded on a real robot, read from CSV for dynamic identification (feature
//! `std`).
//!
//! # CSV format
//!
//! The first line that is neither blank nor a comment (a line starting with `#`) names the
//! columns; every other such line is one sample. Required columns: `t` (s), `q1..qN` (rad or
//! m) and `tau1..tauN` (N m or N: the measured joint torques, gravity included); optional:
//! `qd1..qdN` (rad/s or m/s, all N or none). Columns come in any order; names are trimmed of
//! spaces and matched case-sensitively; a joint column past the robot's joints (`q8` for a
//! 7-joint robot, or `q0`) is refused as the log of another robot; other columns are ignored
//! (not read, not checked) and named in the report. The text is UTF-8; a leading byte-order mark is dropped, and lines may
//! end in LF, CRLF or CR (the same line endings as the other CSV readers). Fields are split on commas (no quoting).
//!
//! # What is repaired and what is refused
//!
//! Real logs are not clean. [`JointLog::from_csv_reader`] refuses a malformed file (a row with
//! another number of fields than the header, a used field that is not a number, a header
//! without a required column or with a repeated one) with a [`CsvError`] naming the line and
//! column. It repairs what it can and says so in the [`LogReport`]:
//!
//! - a row with a NaN or infinite value in a used column is dropped;
//! - a row whose time equals the previous kept one is dropped (the first is kept);
//! - a row whose time is before the previous kept one (out of order, a clock jump back) is
//!   dropped;
//! - gaps (an interval between kept samples over 1.5 times the median interval) are reported
//!   with the number of samples missing in them, `round(interval / median) - 1`;
//! - jumps (a position change between consecutive kept samples over
//!   [`LogSettings::jump_threshold`] on a joint) are reported, not dropped: the
//!   identification decides.
//!
//! It refuses a log with fewer than [`LogSettings::min_samples`] samples left, or whose median
//! interval is not positive and finite.
//!
//! ```
//! use armdyn::identification::log::{JointLog, LogSettings};
//!
//! let mut csv = String::from("t,q1,tau1,temperature\n");
//! for k in 0..200 {
//!     let t = k as f64 * 0.001;
//!     if k == 50 {
//!         csv.push_str("0.05,NaN,0.1,30\n"); // a sensor glitch
//!     } else if k != 120 && k != 121 { // two samples lost
//!         csv.push_str(&format!("{t},{},{},30\n", (t * 3.0).sin(), 0.1));
//!     }
//! }
//! let (log, report) = JointLog::<1>::from_csv_reader(csv.as_bytes(), &LogSettings::default()).unwrap();
//! assert_eq!(log.len(), 197);
//! assert_eq!(report.non_finite.count, 1);
//! assert_eq!(report.non_finite.lines, [52]);
//! // The dropped NaN row leaves a gap too: two gaps, three samples missing.
//! assert_eq!(report.gaps.len(), 2);
//! assert_eq!(report.gap_samples, 3);
//! assert_eq!(report.extra_columns, ["temperature"]);
//! println!("{report}");
//! ```

use std::collections::HashMap;
use std::io::{Read, Write};

pub use crate::csv_text::CsvError;
use crate::csv_text::{check_field_count, CsvText};
use crate::model::JointVector;

pub use super::log_report::{
    Dropped, Gap, Jump, LogReport, GAP_FACTOR, REPORTED_JUMPS, REPORTED_LINES,
};

/// What the reader accepts.
#[derive(Clone, Debug, PartialEq)]
pub struct LogSettings {
    /// Fewest samples left after the repairs (default 100); fewer is refused.
    pub min_samples: usize,
    /// A position change between consecutive kept samples over this on any joint is reported
    /// as a jump, rad or m per sample (default 0.2). NaN reports none.
    pub jump_threshold: f64,
}

impl Default for LogSettings {
    fn default() -> Self {
        Self {
            min_samples: 100,
            jump_threshold: 0.2,
        }
    }
}

/// What a column of the file holds.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Role {
    Time,
    Position(usize),
    Velocity(usize),
    Torque(usize),
}

/// Samples of an N-joint robot: time, positions, optional velocities and measured torques.
#[derive(Clone, Debug, PartialEq)]
pub struct JointLog<const N: usize> {
    /// Times, s, strictly increasing (as read).
    pub t: Vec<f64>,
    /// Joint positions, rad or m.
    pub q: Vec<JointVector<N>>,
    /// Joint velocities, rad/s or m/s, if the log has them.
    pub qd: Option<Vec<JointVector<N>>>,
    /// Measured joint torques (N m) or forces (N), gravity included.
    pub tau: Vec<JointVector<N>>,
    /// The file line of each sample (from 1).
    pub lines: Vec<usize>,
}

impl<const N: usize> JointLog<N> {
    /// The required columns `t, q1..qN, tau1..tauN`.
    fn required() -> Vec<(String, Role)> {
        std::iter::once(("t".to_string(), Role::Time))
            .chain((1..=N).map(|i| (format!("q{i}"), Role::Position(i - 1))))
            .chain((1..=N).map(|i| (format!("tau{i}"), Role::Torque(i - 1))))
            .collect()
    }

    /// Reads a log of an N-joint robot (see the [module documentation](self) for the format
    /// and the repairs).
    ///
    /// # Errors
    ///
    /// [`CsvError`], naming the line (and column) at fault: unreadable or non-UTF-8 input, a
    /// header without a required column or with a repeated one, a row with another number of
    /// fields than the header, a used field that is not a number, fewer than
    /// [`LogSettings::min_samples`] samples left, a median interval that is not positive.
    pub fn from_csv_reader<R: Read>(
        reader: R,
        settings: &LogSettings,
    ) -> Result<(Self, LogReport), CsvError> {
        let input = CsvText::read(reader)?;
        let mut last_line = 1;
        let mut lines = input
            .lines()
            .enumerate()
            .map(|(i, l)| (i.saturating_add(1), l))
            .inspect(|&(n, _)| last_line = n)
            .filter(|(_, l)| {
                let l = l.trim();
                !l.is_empty() && !l.starts_with('#')
            });
        let required = Self::required();
        let expected = required
            .iter()
            .map(|(n, _)| n.as_str())
            .collect::<Vec<_>>()
            .join(",");

        // The header: the role of each field.
        let Some((header_line, header)) = lines.next() else {
            drop(lines);
            return Err(CsvError::NoHeader {
                line: last_line as u64,
                expected: format!("the columns `{expected}`"),
            });
        };
        let names: Vec<&str> = header.split(',').map(str::trim).collect();
        let mut first_of: HashMap<&str, usize> = HashMap::new();
        for (i, name) in names.iter().enumerate() {
            if let Some(&first) = first_of.get(name) {
                return Err(CsvError::DuplicateColumn {
                    line: header_line as u64,
                    column: i.saturating_add(1),
                    first: first.saturating_add(1),
                    name: (*name).to_string(),
                });
            }
            first_of.insert(name, i);
        }
        for (i, name) in names.iter().enumerate() {
            let joint = ["qd", "tau", "q"]
                .iter()
                .find_map(|p| name.strip_prefix(p))
                .filter(|k| !k.is_empty() && k.bytes().all(|b| b.is_ascii_digit()))
                .and_then(|k| k.parse::<usize>().ok());
            if let Some(joint) = joint.filter(|j| *j > N || *j == 0) {
                return Err(CsvError::ExtraJoint {
                    line: header_line as u64,
                    column: i.saturating_add(1),
                    name: (*name).to_string(),
                    joint,
                    joints: N,
                });
            }
        }
        let mut roles: Vec<Option<Role>> = vec![None; names.len()];
        let missing = |name: &str| CsvError::MissingColumn {
            line: header_line as u64,
            name: name.to_string(),
            expected: format!("`{expected}` in any order, optionally with all of `qd1..qd{N}`"),
        };
        for (name, role) in &required {
            let i = *first_of.get(name.as_str()).ok_or_else(|| missing(name))?;
            if let Some(r) = roles.get_mut(i) {
                *r = Some(*role);
            }
        }
        let velocity_names: Vec<String> = (1..=N).map(|i| format!("qd{i}")).collect();
        let found: Vec<Option<usize>> = velocity_names
            .iter()
            .map(|n| first_of.get(n.as_str()).copied())
            .collect();
        let velocities = N > 0 && found.iter().all(Option::is_some);
        if !velocities {
            if let Some(k) = found.iter().position(Option::is_none) {
                if found.iter().any(Option::is_some) {
                    return Err(missing(velocity_names.get(k).map_or("qd", String::as_str)));
                }
            }
        } else {
            for (j, i) in found.iter().enumerate() {
                if let Some(r) = i.and_then(|i| roles.get_mut(i)) {
                    *r = Some(Role::Velocity(j));
                }
            }
        }
        let extra_columns: Vec<String> = names
            .iter()
            .zip(&roles)
            .filter(|(_, r)| r.is_none())
            .map(|(n, _)| (*n).to_string())
            .collect();

        // The rows.
        let mut log = Self {
            t: Vec::new(),
            q: Vec::new(),
            qd: velocities.then(Vec::new),
            tau: Vec::new(),
            lines: Vec::new(),
        };
        let (mut non_finite, mut duplicate_time, mut backward_time) =
            (Dropped::default(), Dropped::default(), Dropped::default());
        let mut rows_read: usize = 0;
        for (line, text) in lines.by_ref() {
            rows_read = rows_read.saturating_add(1);
            let fields: Vec<&str> = text.split(',').map(str::trim).collect();
            check_field_count(line as u64, fields.len(), &names)?;
            let mut t = 0.0;
            let (mut q, mut qd, mut tau) = (
                JointVector::<N>::zeros(),
                JointVector::<N>::zeros(),
                JointVector::<N>::zeros(),
            );
            let mut finite = true;
            for (i, (field, role)) in fields.iter().zip(&roles).enumerate() {
                let Some(role) = role else { continue };
                let value: f64 = field.parse().map_err(|_| CsvError::NotNumeric {
                    line: line as u64,
                    column: i.saturating_add(1),
                    name: names.get(i).map_or_else(String::new, |n| (*n).to_string()),
                    text: (*field).to_string(),
                })?;
                finite &= value.is_finite();
                let slot = match *role {
                    Role::Time => Some(&mut t),
                    Role::Position(j) => q.get_mut(j),
                    Role::Velocity(j) => qd.get_mut(j),
                    Role::Torque(j) => tau.get_mut(j),
                };
                if let Some(slot) = slot {
                    *slot = value;
                }
            }
            if !finite {
                non_finite.add(line);
                continue;
            }
            match log.t.last() {
                Some(&previous) if t == previous => {
                    duplicate_time.add(line);
                    continue;
                }
                Some(&previous) if t < previous => {
                    backward_time.add(line);
                    continue;
                }
                _ => {}
            }
            log.t.push(t);
            log.q.push(q);
            if let Some(v) = log.qd.as_mut() {
                v.push(qd);
            }
            log.tau.push(tau);
            log.lines.push(line);
        }
        drop(lines);

        let kept = log.t.len();
        if kept < settings.min_samples {
            let dropped = non_finite
                .count
                .saturating_add(duplicate_time.count)
                .saturating_add(backward_time.count);
            return Err(CsvError::TooFewSamples {
                line: last_line as u64,
                read: rows_read,
                kept,
                dropped,
                non_finite: non_finite.count,
                duplicate: duplicate_time.count,
                backward: backward_time.count,
                min: settings.min_samples,
            });
        }

        // Intervals, gaps and jumps.
        let intervals: Vec<f64> = log.t.windows(2).map(|w| w[1] - w[0]).collect();
        let median = median(&intervals);
        if !(median.is_finite() && median > 0.0) {
            return Err(CsvError::Interval {
                line: log.lines.first().copied().unwrap_or(header_line) as u64,
                median,
            });
        }
        let mut gaps = Vec::new();
        let mut gap_samples: usize = 0;
        let mut regular = Vec::with_capacity(intervals.len());
        for ((dt, t0), line) in intervals.iter().zip(&log.t).zip(log.lines.iter().skip(1)) {
            if *dt > GAP_FACTOR * median {
                // A float-to-integer `as` saturates (and an infinite ratio is huge).
                let missing = ((dt / median).round() as usize).saturating_sub(1);
                gap_samples = gap_samples.saturating_add(missing);
                gaps.push(Gap {
                    line: *line,
                    start: *t0,
                    length: *dt,
                    missing,
                });
            } else {
                regular.push(*dt);
            }
        }
        let mut jumps = Vec::new();
        let mut jump_count: usize = 0;
        for (pair, line) in log.q.windows(2).zip(log.lines.iter().skip(1)) {
            let (before, after) = (&pair[0], &pair[1]);
            for (j, (a, b)) in before.iter().zip(after.iter()).enumerate() {
                let size = b - a;
                if size.abs() > settings.jump_threshold {
                    jump_count = jump_count.saturating_add(1);
                    if jumps.len() < REPORTED_JUMPS {
                        jumps.push(Jump {
                            line: *line,
                            joint: j.saturating_add(1),
                            size,
                        });
                    }
                }
            }
        }
        let report = LogReport {
            rows_read,
            rows_kept: kept,
            median_interval: median,
            rate: 1.0 / median,
            min_interval: intervals.iter().copied().fold(f64::INFINITY, f64::min),
            max_interval: intervals.iter().copied().fold(0.0, f64::max),
            jitter: standard_deviation(&regular),
            gaps,
            gap_samples,
            non_finite,
            duplicate_time,
            backward_time,
            jumps,
            jump_count,
            jump_threshold: settings.jump_threshold,
            extra_columns,
            velocities,
        };
        Ok((log, report))
    }

    /// Writes the log as CSV: header `t,q1..qN[,qd1..qdN],tau1..tauN`, numbers in Rust's
    /// shortest round-trip form (`{}`), so that [`Self::from_csv_reader`] reads back the same
    /// values. Only as many rows as the shortest of the vectors are written.
    ///
    /// # Errors
    ///
    /// Those of `out`.
    pub fn write_csv<W: Write>(&self, out: W) -> std::io::Result<()> {
        let mut out = std::io::BufWriter::new(out);
        let mut header = vec!["t".to_string()];
        header.extend((1..=N).map(|i| format!("q{i}")));
        if self.qd.is_some() {
            header.extend((1..=N).map(|i| format!("qd{i}")));
        }
        header.extend((1..=N).map(|i| format!("tau{i}")));
        writeln!(out, "{}", header.join(","))?;
        let rows = self.rows();
        let mut row = String::new();
        for k in 0..rows {
            row.clear();
            let (Some(t), Some(q), Some(tau)) = (self.t.get(k), self.q.get(k), self.tau.get(k))
            else {
                break;
            };
            row.push_str(&t.to_string());
            let qd = self.qd.as_ref().and_then(|v| v.get(k));
            for v in q
                .iter()
                .chain(qd.into_iter().flat_map(|v| v.iter()))
                .chain(tau.iter())
            {
                row.push(',');
                row.push_str(&v.to_string());
            }
            writeln!(out, "{row}")?;
        }
        out.flush()
    }

    /// The samples with `t` in `[t0, t1)` as a new log (with their lines).
    #[must_use]
    pub fn slice_time(&self, t0: f64, t1: f64) -> Self {
        fn pick<T: Clone>(v: &[T], keep: &[usize]) -> Vec<T> {
            keep.iter().filter_map(|&k| v.get(k).cloned()).collect()
        }
        let keep: Vec<usize> = (0..self.rows())
            .filter(|&k| self.t.get(k).is_some_and(|&t| t >= t0 && t < t1))
            .collect();
        Self {
            t: pick(&self.t, &keep),
            q: pick(&self.q, &keep),
            qd: self.qd.as_ref().map(|v| pick(v, &keep)),
            tau: pick(&self.tau, &keep),
            lines: pick(&self.lines, &keep),
        }
    }

    /// Samples in the log.
    #[must_use]
    pub fn len(&self) -> usize {
        self.t.len()
    }

    /// Whether the log has no samples.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.t.is_empty()
    }

    /// Complete samples: the length of the shortest vector (the fields are public).
    fn rows(&self) -> usize {
        let mut n = self.t.len().min(self.q.len()).min(self.tau.len());
        if let Some(qd) = &self.qd {
            n = n.min(qd.len());
        }
        n
    }
}

/// The median (NaN for none).
fn median(values: &[f64]) -> f64 {
    let mut sorted = values.to_vec();
    sorted.sort_by(f64::total_cmp);
    let mid = sorted.len() / 2;
    let upper = sorted.get(mid).copied().unwrap_or(f64::NAN);
    if sorted.len() % 2 == 1 {
        upper
    } else {
        let lower = mid
            .checked_sub(1)
            .and_then(|i| sorted.get(i))
            .copied()
            .unwrap_or(f64::NAN);
        0.5 * lower + 0.5 * upper
    }
}

/// The population standard deviation (0 for none).
fn standard_deviation(values: &[f64]) -> f64 {
    if values.is_empty() {
        return 0.0;
    }
    let n = values.len() as f64;
    let mean = values.iter().sum::<f64>() / n;
    (values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / n).sqrt()
}
