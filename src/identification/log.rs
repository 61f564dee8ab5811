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
//! without a required column or with a repeated one) with a [`LogError`] naming the line and
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

use crate::csv_text::{CsvText, TextError};
use crate::model::JointVector;

pub use super::log_report::{
    Dropped, Gap, Jump, LogError, LogReport, GAP_FACTOR, REPORTED_JUMPS, REPORTED_LINES,
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
    /// [`LogError`], naming the line (and column) at fault: unreadable or non-UTF-8 input, a
    /// header without a required column or with a repeated one, a row with another number of
    /// fields than the header, a used field that is not a number, fewer than
    /// [`LogSettings::min_samples`] samples left, a median interval that is not positive.
    pub fn from_csv_reader<R: Read>(
        reader: R,
        settings: &LogSettings,
    ) -> Result<(Self, LogReport), LogError> {
        let input = CsvText::read(reader).map_err(|e| match e {
            TextError::Io(e) => LogError::Read(e.to_string()),
            TextError::NotUtf8 { line, offset, byte } => LogError::NotUtf8 {
                line: usize::try_from(line).unwrap_or(usize::MAX),
                offset: usize::try_from(offset).unwrap_or(usize::MAX),
                byte,
            },
        })?;
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
            return Err(LogError::NoHeader {
                line: last_line,
                expected,
            });
        };
        let names: Vec<&str> = header.split(',').map(str::trim).collect();
        let mut first_of: HashMap<&str, usize> = HashMap::new();
        for (i, name) in names.iter().enumerate() {
            if let Some(&first) = first_of.get(name) {
                return Err(LogError::DuplicateColumn {
                    line: header_line,
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
                return Err(LogError::ExtraJoint {
                    line: header_line,
                    column: i.saturating_add(1),
                    name: (*name).to_string(),
                    joint,
                    joints: N,
                });
            }
        }
        let mut roles: Vec<Option<Role>> = vec![None; names.len()];
        let missing = |name: &str| LogError::MissingColumn {
            line: header_line,
            name: name.to_string(),
            expected: expected.clone(),
            joints: N,
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
            if fields.len() != names.len() {
                return Err(LogError::FieldCount {
                    line,
                    column: fields.len().min(names.len()).saturating_add(1),
                    found: fields.len(),
                    expected: names.len(),
                });
            }
            let mut t = 0.0;
            let (mut q, mut qd, mut tau) = (
                JointVector::<N>::zeros(),
                JointVector::<N>::zeros(),
                JointVector::<N>::zeros(),
            );
            let mut finite = true;
            for (i, (field, role)) in fields.iter().zip(&roles).enumerate() {
                let Some(role) = role else { continue };
                let value: f64 = field.parse().map_err(|_| LogError::NotNumber {
                    line,
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
            return Err(LogError::TooFew {
                line: last_line,
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
            return Err(LogError::Interval {
                line: log.lines.first().copied().unwrap_or(header_line),
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

#[cfg(test)]
mod tests {
    use super::*;

    fn settings(min_samples: usize) -> LogSettings {
        LogSettings {
            min_samples,
            ..LogSettings::default()
        }
    }

    fn read<const N: usize>(text: &str, min: usize) -> Result<(JointLog<N>, LogReport), LogError> {
        JointLog::<N>::from_csv_reader(text.as_bytes(), &settings(min))
    }

    fn error(text: &str, min: usize) -> String {
        read::<2>(text, min).unwrap_err().to_string()
    }

    /// A clean 2-joint log of `n` rows at 1 kHz (header `t,q1,q2,tau1,tau2`).
    fn clean(n: usize) -> String {
        let mut s = String::from("t,q1,q2,tau1,tau2\n");
        for k in 0..n {
            s.push_str(&row(k));
        }
        s
    }

    fn row(k: usize) -> String {
        let t = k as f64 * 1e-3;
        format!(
            "{t},{},{},{},{}\n",
            (3.0 * t).sin(),
            -0.5 * t,
            1.0 + t,
            (2.0 * t).cos()
        )
    }

    #[test]
    fn default_settings() {
        let s = LogSettings::default();
        assert_eq!((s.min_samples, s.jump_threshold), (100, 0.2));
    }

    #[test]
    fn clean_log_round_trips_exactly() {
        let text = clean(150);
        let (log, report) = read::<2>(&text, 100).unwrap();
        assert_eq!(log.len(), 150);
        assert!(!log.is_empty());
        assert_eq!(log.lines, (2..152).collect::<Vec<_>>());
        assert_eq!(log.t[7], 7.0 * 1e-3);
        assert_eq!(log.q[7][0], (3.0 * (7.0 * 1e-3f64)).sin());
        assert!(log.qd.is_none());
        assert_eq!(
            (report.rows_read, report.rows_kept, report.dropped()),
            (150, 150, 0)
        );
        assert!((report.median_interval - 1e-3).abs() < 1e-12);
        assert!((report.rate - 1000.0).abs() < 1e-6);
        assert!(report.jitter < 1e-12);
        assert!(report.gaps.is_empty() && report.jumps.is_empty());
        assert!(!report.velocities && report.extra_columns.is_empty());
        let mut written = Vec::new();
        log.write_csv(&mut written).unwrap();
        let written = String::from_utf8(written).unwrap();
        assert_eq!(written, text);
        let (again, _) = read::<2>(&written, 100).unwrap();
        assert_eq!(again, log);
    }

    #[test]
    fn velocities_and_columns_in_another_order_with_extras() {
        let mut text = String::from(" tau2 , mode,qd2,q1,t,qd1,tau1,q2 ,temp\n");
        for k in 0..5 {
            let t = k as f64 * 0.01;
            text.push_str(&format!(
                "{},idle,{},{},{t},{},{},{},x\n",
                20 + k,
                10 + k,
                k,
                30 + k,
                40 + k,
                50 + k
            ));
        }
        let (log, report) = read::<2>(&text, 5).unwrap();
        assert_eq!(log.t, [0.0, 0.01, 0.02, 0.03, 0.04]);
        assert_eq!(log.q[1], JointVector::<2>::new(1.0, 51.0));
        assert_eq!(
            log.qd.as_ref().unwrap()[1],
            JointVector::<2>::new(31.0, 11.0)
        );
        assert_eq!(log.tau[1], JointVector::<2>::new(41.0, 21.0));
        assert!(report.velocities);
        assert_eq!(report.extra_columns, ["mode", "temp"]);
        // Written back in the standard order, with velocities.
        let mut out = Vec::new();
        log.write_csv(&mut out).unwrap();
        let out = String::from_utf8(out).unwrap();
        assert!(out.starts_with("t,q1,q2,qd1,qd2,tau1,tau2\n0,0,50,30,10,40,20\n"));
        assert_eq!(read::<2>(&out, 5).unwrap().0.qd, log.qd);
        // Some velocities but not all: refused.
        let e = error("t,q1,q2,tau1,tau2,qd1\n", 0);
        assert!(e.starts_with("line 1: missing column `qd2`"), "{e}");
    }

    #[test]
    fn non_finite_rows_are_dropped_and_reported() {
        let mut text = clean(120);
        text.push_str("0.5,NaN,0,0,0\n0.6,0,0,inf,0\n0.7,0,0,0,-infinity\nnan,0,0,0,0\n");
        text.push_str("0.8,0,0,0,1e999\n0.9,0,0,0,NAN\n");
        let (log, report) = read::<2>(&text, 100).unwrap();
        assert_eq!(log.len(), 120);
        assert_eq!(report.non_finite.count, 6);
        assert_eq!(report.non_finite.lines, [122, 123, 124, 125, 126]);
        assert_eq!(report.rows_read, 126);
        assert!(report
            .to_string()
            .contains("6 with NaN or infinite values (lines 122, 123, 124, 125, 126, ...)"));
    }

    #[test]
    fn duplicate_and_backward_stamps_are_dropped() {
        let mut text = String::from("t,q1,q2,tau1,tau2\n");
        for k in 0..110 {
            text.push_str(&row(k));
            let t = k as f64 * 1e-3;
            if k == 10 {
                text.push_str(&format!("{t},9,9,9,9\n")); // line 13: the same stamp again
            }
            if k == 20 {
                text.push_str(&format!("0.005,9,9,9,9\n{t},8,8,8,8\n")); // lines 24, 25
            }
        }
        let (log, report) = read::<2>(&text, 100).unwrap();
        assert_eq!(log.len(), 110);
        assert_eq!(log.t, (0..110).map(|k| k as f64 * 1e-3).collect::<Vec<_>>());
        let t10 = 10.0f64 * 1e-3;
        assert_eq!(
            log.q[10],
            JointVector::<2>::new((3.0 * t10).sin(), -0.5 * t10)
        );
        assert_eq!(report.duplicate_time.count, 2);
        assert_eq!(report.duplicate_time.lines, [13, 25]);
        assert_eq!(report.backward_time.count, 1);
        assert_eq!(report.backward_time.lines, [24]);
        assert_eq!(report.dropped(), 3);
        assert!(report.jumps.is_empty(), "dropped rows make no jumps");
    }

    #[test]
    fn gaps_are_reported_with_the_missing_samples() {
        let mut text = String::from("t,q1,q2,tau1,tau2\n");
        for k in (0..200).filter(|k| !(50..53).contains(k) && *k != 100) {
            text.push_str(&row(k));
        }
        let (log, report) = read::<2>(&text, 100).unwrap();
        assert_eq!(log.len(), 196);
        assert_eq!(report.gaps.len(), 2);
        let g = &report.gaps[0];
        assert_eq!(g.line, 52); // sample 53 follows sample 49 (line 51)
        assert_eq!(g.start, 49.0 * 1e-3);
        assert!((g.length - 4e-3).abs() < 1e-12);
        assert_eq!(g.missing, 3);
        assert_eq!(report.gaps[1].missing, 1);
        assert_eq!(report.gap_samples, 4);
        assert!((report.max_interval - 4e-3).abs() < 1e-12);
        assert!(
            report.jitter < 1e-12,
            "gaps are not jitter: {}",
            report.jitter
        );
        assert!(report
            .to_string()
            .contains("gaps: 2 (4 samples missing): line 52 at 0.049 s"));
    }

    #[test]
    fn jumps_are_reported_not_dropped() {
        let mut text = String::from("t,q1,q2,tau1,tau2\n");
        for k in 0..100 {
            let q2 = if k >= 40 { 0.5 } else { 0.0 };
            text.push_str(&format!("{},0,{q2},0,0\n", k as f64 * 0.01));
        }
        let (log, report) = read::<2>(&text, 100).unwrap();
        assert_eq!(log.len(), 100);
        assert_eq!(report.jump_count, 1);
        assert_eq!(
            report.jumps,
            [Jump {
                line: 42,
                joint: 2,
                size: 0.5
            }]
        );
        let tight = LogSettings {
            min_samples: 100,
            jump_threshold: 0.6,
        };
        let (_, report) = JointLog::<2>::from_csv_reader(text.as_bytes(), &tight).unwrap();
        assert_eq!(report.jump_count, 0);
        // Many jumps: 20 kept, all counted.
        let mut text = String::from("t,q1,tau1\n");
        for k in 0..100 {
            text.push_str(&format!("{k},{},0\n", k % 2));
        }
        let (_, report) = read::<1>(&text, 100).unwrap();
        assert_eq!((report.jumps.len(), report.jump_count), (20, 99));
        assert!(report.to_string().contains("; and 94 more"));
    }

    #[test]
    fn header_errors_name_the_line_and_column() {
        let e = error("t,q1,tau1,tau2\n0,0,0,0\n", 0);
        assert!(e.starts_with("line 1: missing column `q2`"), "{e}");
        let e = error("# from the controller\n\nt,q1,q2,tau1,tau2\n", 0);
        assert!(!e.contains("missing"), "{e}");
        let e = error("# comment\nt,q1,q2,tau1\n", 0);
        assert!(e.starts_with("line 2: missing column `tau2`"), "{e}");
        let e = error("t,q1,q2,q1,tau1,tau2\n", 0);
        assert_eq!(
            e,
            "line 1, column 4 (`q1`): duplicated column (also column 2)"
        );
        let e = error("t,q1,q2,tau1,tau2,x, x \n", 0);
        assert!(e.starts_with("line 1, column 7 (`x`): duplicated"), "{e}");
        // Names are case-sensitive.
        let e = error("T,q1,q2,tau1,tau2\n", 0);
        assert!(e.starts_with("line 1: missing column `t`"), "{e}");
        assert!(error("", 0).starts_with("line 1: the input ends before the header"));
        assert!(error("# a\n\n#b\n", 0).starts_with("line 4: the input ends before the header"));
    }

    #[test]
    fn row_errors_name_the_line_and_column() {
        let mut text = clean(10);
        text.push_str("0.5,0,x,0,0\n");
        assert_eq!(
            error(&text, 0),
            "line 12, column 3 (`q2`): `x` is not a number"
        );
        let mut text = clean(10);
        text.push_str("\n0.5,0,,0,0\n");
        assert_eq!(
            error(&text, 0),
            "line 13, column 3 (`q2`): `` is not a number"
        );
        let mut text = clean(3);
        text.push_str("0.5,0,0,0\n");
        assert_eq!(
            error(&text, 0),
            "line 5, column 5: 4 fields, expected 5 as in the header"
        );
        let mut text = clean(3);
        text.push_str("0.5,0,0,0,0,0\n");
        assert_eq!(
            error(&text, 0),
            "line 5, column 6: 6 fields, expected 5 as in the header"
        );
        // Extra columns are not read.
        let (log, _) = read::<1>("t,q1,tau1,note\n0,1,2,ok\n1,1,2,-\n", 2).unwrap();
        assert_eq!(log.len(), 2);
        let bad =
            JointLog::<2>::from_csv_reader(&b"t,q1,q2,tau1,tau2\n0,0,\xFF,0,0\n"[..], &settings(0));
        assert_eq!(
            bad.unwrap_err().to_string(),
            "line 2: not UTF-8 text (byte 5 of the line is 0xFF); save the file as UTF-8"
        );
    }

    #[test]
    fn too_few_samples_are_refused() {
        let mut text = clean(99);
        text.push_str("1,NaN,0,0,0\n0.05,0,0,0,0\n");
        let e = error(&text, 100);
        assert_eq!(
            e,
            "line 103: the log ends with 99 usable samples of 101 rows read (2 dropped: 1 not \
             finite, 0 duplicated time stamps, 1 out of order); at least 100 are needed"
        );
        assert!(read::<2>(&clean(100), 100).is_ok());
        // One sample: no interval.
        let e = error(&clean(1), 1);
        assert!(e.starts_with("line 2: the median interval"), "{e}");
        let e = error("t,q1,q2,tau1,tau2\n", 0);
        assert!(e.starts_with("line 1: the median interval"), "{e}");
        // Times too far apart to subtract.
        let e = error("t,q1,q2,tau1,tau2\n-1e308,0,0,0,0\n1e308,0,0,0,0\n", 2);
        assert!(e.contains("is inf s"), "{e}");
    }

    #[test]
    fn comments_and_blank_lines_are_skipped() {
        let plain = read::<2>(&clean(100), 100).unwrap().0;
        let mut text = String::from("# robot: test\n\n");
        for (k, l) in clean(100).lines().enumerate() {
            text.push_str(l);
            text.push('\n');
            if k % 10 == 3 {
                text.push_str("   \n  # a comment, with commas\n");
            }
        }
        let (log, report) = read::<2>(&text, 100).unwrap();
        assert_eq!((log.t, log.q, log.tau), (plain.t, plain.q, plain.tau));
        assert_eq!(report.rows_read, 100);
        assert_eq!(log.lines[0], 4);
    }

    #[test]
    fn byte_order_mark_and_crlf_are_accepted() {
        let plain = read::<2>(&clean(100), 100).unwrap().0;
        let crlf = clean(100).replace('\n', "\r\n");
        assert_eq!(read::<2>(&crlf, 100).unwrap().0, plain);
        assert_eq!(read::<2>(&format!("\u{feff}{crlf}"), 100).unwrap().0, plain);
        assert_eq!(
            read::<2>(&clean(100).replace('\n', "\r"), 100).unwrap().0,
            plain
        );
        let mut bad = format!("\u{feff}{crlf}");
        bad.push_str("\r\n0.5,0,0,x,0\r\n");
        assert!(error(&bad, 0).starts_with("line 103, column 4 (`tau1`)"));
    }

    #[test]
    fn slice_time_keeps_the_lines() {
        let (log, _) = read::<2>(&clean(100), 100).unwrap();
        let part = log.slice_time(0.0105, 0.0195);
        assert_eq!(part.len(), 9);
        assert_eq!(part.t[0], log.t[11]);
        assert_eq!(part.lines, (13..22).collect::<Vec<_>>());
        assert_eq!(part.tau[0], log.tau[11]);
        assert!(log.slice_time(1.0, 0.0).is_empty());
        assert!(log.slice_time(f64::NAN, 1.0).is_empty());
        assert_eq!(log.slice_time(f64::NEG_INFINITY, f64::INFINITY), log);
        // Inconsistent public fields: no panic.
        let mut odd = log.clone();
        odd.q.truncate(3);
        odd.qd = Some(vec![]);
        assert!(odd.slice_time(0.0, 1.0).is_empty());
        let mut out = Vec::new();
        odd.write_csv(&mut out).unwrap();
        assert_eq!(out, b"t,q1,q2,qd1,qd2,tau1,tau2\n");
    }

    #[test]
    fn report_display() {
        let mut text = String::from("t,q1,tau1,temp\n");
        for k in 0..120 {
            let t = k as f64 * 0.002;
            if k == 30 {
                text.push_str("0.06,NaN,0,40\n");
                continue;
            }
            if (60..64).contains(&k) {
                continue;
            }
            let q = if k >= 90 { 1.0 } else { 0.0 };
            text.push_str(&format!("{t},{q},0.5,40\n"));
            if k == 10 {
                text.push_str(&format!("{t},{q},0.5,40\n"));
            }
        }
        let (_, report) = read::<1>(&text, 100).unwrap();
        let shown = report.to_string();
        assert_eq!(
            shown,
            "joint log: 117 rows read, 115 kept, 2 dropped; velocities absent\n\
             sampling: median interval 0.002 s (500 Hz), min 0.002 s, max 0.01 s, jitter 0 s (gaps excluded)\n\
             dropped: 1 with NaN or infinite values (line 33)\n\
             dropped: 1 with a duplicated time stamp (line 13)\n\
             gaps: 2 (5 samples missing): line 34 at 0.058 s for 0.004 s (1 missing); line 63 at 0.118 s for 0.01 s (4 missing)\n\
             jumps over 0.2 per sample: 1 (not dropped): line 89 joint 1 by 1\n\
             extra columns (ignored): `temp`"
        );
    }
}
