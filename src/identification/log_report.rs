//! What the joint-log reader found: [`LogReport`] (rate, gaps, jumps, rows dropped and why), for
//! [`super::log::JointLog`] (feature `std`).

use std::fmt;

/// How many line numbers of dropped rows the report keeps per reason.
pub const REPORTED_LINES: usize = 5;
/// How many jumps the report keeps (it counts them all).
pub const REPORTED_JUMPS: usize = 20;
/// An interval over this many median intervals is a gap.
pub const GAP_FACTOR: f64 = 1.5;
/// How many gaps and jumps [`LogReport`]'s `Display` lists (it counts them all).
const DISPLAYED: usize = 5;

/// Rows dropped for one reason.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Dropped {
    /// How many.
    pub count: usize,
    /// The lines of the first [`REPORTED_LINES`].
    pub lines: Vec<usize>,
}

impl Dropped {
    pub(super) fn add(&mut self, line: usize) {
        self.count = self.count.saturating_add(1);
        if self.lines.len() < REPORTED_LINES {
            self.lines.push(line);
        }
    }
}

/// An interval between kept samples over [`GAP_FACTOR`] times the median.
#[derive(Clone, Debug, PartialEq)]
pub struct Gap {
    /// Line of the sample after the gap.
    pub line: usize,
    /// Time of the sample before the gap, s.
    pub start: f64,
    /// The interval, s.
    pub length: f64,
    /// Samples missing in it: `round(length / median) - 1`.
    pub missing: usize,
}

/// A position change between consecutive kept samples over [`super::log::LogSettings::jump_threshold`].
#[derive(Clone, Debug, PartialEq)]
pub struct Jump {
    /// Line of the sample after the jump.
    pub line: usize,
    /// The joint (from 1).
    pub joint: usize,
    /// The change, rad or m (signed).
    pub size: f64,
}

/// What the reader found, repaired and kept.
#[derive(Clone, Debug, PartialEq)]
pub struct LogReport {
    /// Data rows read (neither header, blank nor comment).
    pub rows_read: usize,
    /// Samples kept.
    pub rows_kept: usize,
    /// Median interval between kept samples, s.
    pub median_interval: f64,
    /// `1 / median_interval`, Hz.
    pub rate: f64,
    /// Shortest interval between kept samples, s.
    pub min_interval: f64,
    /// Longest interval between kept samples (gaps included), s.
    pub max_interval: f64,
    /// Standard deviation of the intervals that are not gaps, s.
    pub jitter: f64,
    /// Every gap, in time order.
    pub gaps: Vec<Gap>,
    /// Samples missing in the gaps, in all.
    pub gap_samples: usize,
    /// Rows dropped for a NaN or infinite value in a used column.
    pub non_finite: Dropped,
    /// Rows dropped for a time equal to the previous kept one.
    pub duplicate_time: Dropped,
    /// Rows dropped for a time before the previous kept one.
    pub backward_time: Dropped,
    /// The first [`REPORTED_JUMPS`] jumps, in time order (joint order within a sample).
    pub jumps: Vec<Jump>,
    /// Jumps in all (one per joint and pair of samples).
    pub jump_count: usize,
    /// The threshold the jumps were found with, rad or m per sample.
    pub jump_threshold: f64,
    /// Columns of the header that were not read, in file order.
    pub extra_columns: Vec<String>,
    /// Whether the log has the velocities `qd1..qdN`.
    pub velocities: bool,
}

impl LogReport {
    /// Rows dropped, for every reason.
    #[must_use]
    pub fn dropped(&self) -> usize {
        self.non_finite
            .count
            .saturating_add(self.duplicate_time.count)
            .saturating_add(self.backward_time.count)
    }
}

/// A number with about four significant digits, without trailing zeros.
fn short(x: f64) -> String {
    if !x.is_finite() || x == 0.0 {
        return format!("{x}");
    }
    let magnitude = x.abs().log10().floor();
    let decimals = (3.0 - magnitude).clamp(0.0, 15.0) as usize;
    let s = format!("{x:.decimals$}");
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

/// `lines 3, 5, 9, ...` for the dropped rows of one reason.
fn line_list(d: &Dropped) -> String {
    let list: Vec<String> = d.lines.iter().map(ToString::to_string).collect();
    let more = if d.count > d.lines.len() { ", ..." } else { "" };
    let word = if d.count == 1 { "line" } else { "lines" };
    format!("{word} {}{more}", list.join(", "))
}

impl fmt::Display for LogReport {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(
            f,
            "joint log: {} rows read, {} kept, {} dropped; velocities {}",
            self.rows_read,
            self.rows_kept,
            self.dropped(),
            if self.velocities { "present" } else { "absent" }
        )?;
        write!(
            f,
            "sampling: median interval {} s ({} Hz), min {} s, max {} s, jitter {} s (gaps excluded)",
            short(self.median_interval),
            short(self.rate),
            short(self.min_interval),
            short(self.max_interval),
            short(self.jitter)
        )?;
        let reasons = [
            (&self.non_finite, "with NaN or infinite values"),
            (&self.duplicate_time, "with a duplicated time stamp"),
            (
                &self.backward_time,
                "out of order (time before the previous)",
            ),
        ];
        for (d, why) in reasons {
            if d.count > 0 {
                write!(f, "\ndropped: {} {why} ({})", d.count, line_list(d))?;
            }
        }
        if self.gaps.is_empty() {
            write!(f, "\ngaps: none")?;
        } else {
            let list: Vec<String> = self
                .gaps
                .iter()
                .take(DISPLAYED)
                .map(|g| {
                    format!(
                        "line {} at {} s for {} s ({} missing)",
                        g.line,
                        short(g.start),
                        short(g.length),
                        g.missing
                    )
                })
                .collect();
            let more = self.gaps.len().saturating_sub(DISPLAYED);
            write!(
                f,
                "\ngaps: {} ({} samples missing): {}",
                self.gaps.len(),
                self.gap_samples,
                list.join("; ")
            )?;
            if more > 0 {
                write!(f, "; and {more} more")?;
            }
        }
        if self.jump_count == 0 {
            write!(
                f,
                "\njumps over {} per sample: none",
                short(self.jump_threshold)
            )?;
        } else {
            let list: Vec<String> = self
                .jumps
                .iter()
                .take(DISPLAYED)
                .map(|j| format!("line {} joint {} by {}", j.line, j.joint, short(j.size)))
                .collect();
            let more = self.jump_count.saturating_sub(list.len());
            write!(
                f,
                "\njumps over {} per sample: {} (not dropped): {}",
                short(self.jump_threshold),
                self.jump_count,
                list.join("; ")
            )?;
            if more > 0 {
                write!(f, "; and {more} more")?;
            }
        }
        if !self.extra_columns.is_empty() {
            let names: Vec<String> = self
                .extra_columns
                .iter()
                .map(|c| format!("`{c}`"))
                .collect();
            write!(f, "\nextra columns (ignored): {}", names.join(", "))?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn short_numbers() {
        assert_eq!(short(0.001), "0.001");
        assert_eq!(short(1.2e-5), "0.000012");
        assert_eq!(short(1000.0000001), "1000");
        assert_eq!(short(123456.7), "123457");
        assert_eq!(short(-0.25), "-0.25");
        assert_eq!(short(f64::NAN), "NaN");
        assert_eq!(short(1e-300), "0");
    }
}
