//! `trajectory.csv` read back for the viewer: the header checked against the robot's, every
//! record parsed, errors naming the line and column.

use crate::model::JointKind;
use crate::report::trajectory_csv_header;

/// Why a viewer could not be made.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum ViewError {
    /// The text has no header line.
    #[error("trajectory.csv is empty (no header line)")]
    Empty,
    /// The header is not the robot's.
    #[error(
        "trajectory.csv line 1, column {column}: `{found}` where robot `{robot}` has `{expected}`"
    )]
    Header {
        /// Column, from 1.
        column: usize,
        /// What the file has (empty past its end).
        found: String,
        /// What the robot's trajectory has (empty past its end).
        expected: String,
        /// The robot's name.
        robot: String,
    },
    /// A record with the wrong number of fields.
    #[error("trajectory.csv line {line}: {found} fields, the header has {expected}")]
    Fields {
        /// Line, from 1.
        line: usize,
        /// Fields on it.
        found: usize,
        /// Columns of the header.
        expected: usize,
    },
    /// A field that is not a number, or time not increasing.
    #[error("trajectory.csv line {line}, column {column} (`{name}`): {why}")]
    Value {
        /// Line, from 1.
        line: usize,
        /// Column, from 1.
        column: usize,
        /// The column's name.
        name: String,
        /// What is wrong.
        why: String,
    },
    /// A header and no sample.
    #[error("trajectory.csv has no sample")]
    NoSample,
    /// `metrics.json` or `scene.json` is not what a run writes.
    #[error("{file}: {why}")]
    File {
        /// The file.
        file: &'static str,
        /// What is wrong.
        why: String,
    },
}

/// Where the viewer's columns are in a record of an `N`-joint trajectory.
pub(super) struct Columns {
    /// The first joint position.
    pub q: usize,
    /// `x_m`, then `y_m`, `z_m`.
    pub position: usize,
    /// `x_ref_m`.
    pub reference: usize,
    /// `fx_N`.
    pub force: usize,
    /// `fx_ref_N`.
    pub force_ref: usize,
}

impl Columns {
    pub(super) fn new(n: usize) -> Self {
        // t, then six blocks of N (q, q_ref, qd, qd_ref, tau, tau_cmd), then the pose.
        let pose = 1 + 6 * n;
        Self {
            q: 1,
            position: pose,
            reference: pose + 6,
            force: pose + 12,
            force_ref: pose + 15,
        }
    }
}

/// The records of `text`, a trajectory of the robot with `names` and `kinds`, each as its
/// numbers; time strictly increasing and every value a number (NaN kept: the page skips it).
pub(super) fn read<const N: usize>(
    text: &str,
    names: &[&str; N],
    kinds: &[JointKind; N],
) -> Result<Vec<Vec<f64>>, ViewError> {
    let mut lines = text.lines().enumerate();
    let (_, header) = lines.next().ok_or(ViewError::Empty)?;
    let expected = trajectory_csv_header(names, kinds);
    let want: Vec<&str> = expected.split(',').collect();
    let have: Vec<&str> = header
        .trim_start_matches('\u{feff}')
        .split(',')
        .map(str::trim)
        .collect();
    if let Some(k) = (0..want.len().max(have.len())).find(|&k| want.get(k) != have.get(k)) {
        return Err(ViewError::Header {
            column: k + 1,
            found: have.get(k).unwrap_or(&"").to_string(),
            expected: want.get(k).unwrap_or(&"").to_string(),
            robot: names.join(" "),
        });
    }
    let mut rows: Vec<Vec<f64>> = Vec::new();
    for (i, line) in lines {
        let line_no = i + 1;
        if line.trim().is_empty() {
            continue;
        }
        let fields: Vec<&str> = line.split(',').collect();
        if fields.len() != want.len() {
            return Err(ViewError::Fields {
                line: line_no,
                found: fields.len(),
                expected: want.len(),
            });
        }
        let mut row = Vec::with_capacity(want.len());
        for (k, f) in fields.iter().enumerate() {
            let v: f64 = f.trim().parse().map_err(|e| ViewError::Value {
                line: line_no,
                column: k + 1,
                name: want[k].to_string(),
                why: format!("`{}` is not a number ({e})", f.trim()),
            })?;
            row.push(v);
        }
        let t = row[0];
        let previous = rows.last().map(|r| r[0]);
        if !t.is_finite() || previous.is_some_and(|p| t <= p) {
            return Err(ViewError::Value {
                line: line_no,
                column: 1,
                name: want[0].to_string(),
                why: format!("time {t} does not follow the previous line's"),
            });
        }
        rows.push(row);
    }
    if rows.is_empty() {
        return Err(ViewError::NoSample);
    }
    Ok(rows)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{RobotModel, Scara};
    use proptest::prelude::*;

    fn header() -> String {
        trajectory_csv_header(&Scara::JOINT_NAMES, &Scara::JOINT_KINDS)
    }

    fn record(t: f64) -> String {
        let cols = header().split(',').count();
        let mut r = vec![t.to_string()];
        r.extend((1..cols).map(|k| (k as f64 * 0.01).to_string()));
        r.join(",")
    }

    fn parse(text: &str) -> Result<Vec<Vec<f64>>, ViewError> {
        read(text, &Scara::JOINT_NAMES, &Scara::JOINT_KINDS)
    }

    #[test]
    fn a_trajectory_reads_back_and_bad_ones_name_their_line_and_column() {
        let good = format!("{}\n{}\n{}\n", header(), record(0.0), record(0.001));
        let rows = parse(&good).unwrap();
        assert_eq!(rows.len(), 2);
        assert_eq!(rows[1][0], 0.001);
        assert_eq!(parse(""), Err(ViewError::Empty));
        assert_eq!(parse(&format!("{}\n", header())), Err(ViewError::NoSample));
        let e = parse(&good.replacen("q2_rad", "q2_deg", 1)).unwrap_err();
        assert!(e.to_string().contains("line 1, column 3: `q2_deg`"), "{e}");
        let e = parse(&format!("{}\n{}\n1,2\n", header(), record(0.0))).unwrap_err();
        assert!(
            e.to_string().starts_with("trajectory.csv line 3: 2 fields"),
            "{e}"
        );
        let bad = format!("{}\n{}\n", header(), record(0.0).replacen("0.01", "x", 1));
        let e = parse(&bad).unwrap_err();
        assert!(
            e.to_string().contains("line 2, column 2 (`q1_rad`): `x`"),
            "{e}"
        );
        let e = parse(&format!("{}\n{}\n{}\n", header(), record(0.1), record(0.1))).unwrap_err();
        assert!(e.to_string().contains("line 3, column 1 (`t_s`)"), "{e}");
    }

    proptest! {
        // A stated seed: every run checks the same cases; no failure file in the source tree.
        #![proptest_config(ProptestConfig {
            rng_seed: proptest::test_runner::RngSeed::Fixed(32),
            failure_persistence: None,
            ..ProptestConfig::default()
        })]

        // Any text: a trajectory or an error, never a panic.
        #[test]
        fn any_text_reads_or_is_refused(body in "[-0-9.,a-z\\n]{0,400}", cut in 0usize..2000) {
            let good = format!("{}\n{}\n{}\n", header(), record(0.0), record(0.001));
            let _ = parse(&format!("{}\n{body}", header()));
            let _ = parse(&good[..cut.min(good.len())]);
            let _ = parse(&body);
        }
    }
}
