//! A torque history for open-loop simulation, read from CSV (feature `std`).
//!
//! # CSV format
//!
//! The first non-blank line names the columns `t,tau1,...,tauN` (N = the robot's joints, in
//! any order; spaces around names are ignored); every other non-blank line holds one sample:
//! time in s (strictly increasing), then joint torques in N m (revolute) or forces in N
//! (prismatic). The text is UTF-8; a leading byte-order mark (as spreadsheet programs save
//! it) is ignored, and lines may end in LF or CRLF. See [`super::open_loop`] for how the
//! samples are applied.

use std::io::Read;

pub use crate::csv_text::CsvError;
use crate::csv_text::{check_times, CsvText};
use crate::model::JointVector;

/// Torques at strictly increasing times, each held until the next (zero-order hold).
///
/// # Example
///
/// ```
/// use armdyn::sim::torque_history::TorqueHistory;
///
/// // A byte-order mark and CRLF line ends, as a spreadsheet program saves the file.
/// let csv = "\u{feff}t,tau1,tau2\r\n0,1,0\r\n0.5,0,-1\r\n";
/// let history = TorqueHistory::<2>::from_csv_reader(csv.as_bytes()).unwrap();
/// assert_eq!(history.times(), &[0.0, 0.5]);
/// assert_eq!(history.torques()[1][1], -1.0);
///
/// let bad = "t,tau1,tau2\n0,1,0\n0.5,0,x\n";
/// let err = TorqueHistory::<2>::from_csv_reader(bad.as_bytes()).unwrap_err();
/// assert_eq!(err.to_string(), "line 3, column 3 (`tau2`): `x` is not a number");
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct TorqueHistory<const N: usize> {
    times: Vec<f64>,
    torques: Vec<JointVector<N>>,
}

impl<const N: usize> TorqueHistory<N> {
    /// The column names `t, tau1, ..., tauN`.
    #[must_use]
    pub fn columns() -> Vec<String> {
        std::iter::once("t".to_string())
            .chain((1..=N).map(|i| format!("tau{i}")))
            .collect()
    }

    /// Reads a torque history (see the [module documentation](self) for the format).
    ///
    /// # Errors
    ///
    /// [`CsvError`], naming the line (and column) at fault: unreadable or non-UTF-8
    /// input, a header without the columns `t,tau1,...,tauN`, a row with another number of
    /// fields, a field that is not a finite number, times that do not increase strictly, no
    /// rows.
    pub fn from_csv_reader<R: Read>(reader: R) -> Result<Self, CsvError> {
        let columns = Self::columns();
        let expected = columns.join(",");
        let described = format!("`{expected}` (in any order)");
        // index[k]: the field holding column k (t, tau1, ...).
        let (index, rows) = CsvText::read(reader)?.number_table(&described, |line, names| {
            let index = columns
                .iter()
                .map(|name| {
                    names
                        .iter()
                        .position(|h| h == name)
                        .ok_or_else(|| CsvError::MissingColumn {
                            line,
                            name: name.clone(),
                            expected: expected.clone(),
                        })
                })
                .collect::<Result<Vec<usize>, CsvError>>()?;
            if names.len() != columns.len() {
                return Err(CsvError::Header {
                    line,
                    expected: format!("exactly the columns {described}"),
                    found: names.join(","),
                });
            }
            Ok(index)
        })?;
        check_times(&rows, index[0], false)?;
        if rows.is_empty() {
            return Err(CsvError::TooFewRows { rows: 0, min: 1 });
        }
        let times = rows.iter().map(|r| r.values[index[0]]).collect();
        let torques = rows
            .iter()
            .map(|r| JointVector::<N>::from_fn(|j, _| r.values[index[j + 1]]))
            .collect();
        Ok(Self { times, torques })
    }

    /// Sample times, s, strictly increasing.
    #[must_use]
    pub fn times(&self) -> &[f64] {
        &self.times
    }

    /// Torques (N m) or forces (N) of each sample, held until the next sample.
    #[must_use]
    pub fn torques(&self) -> &[JointVector<N>] {
        &self.torques
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn read(text: &str) -> Result<TorqueHistory<4>, CsvError> {
        TorqueHistory::from_csv_reader(text.as_bytes())
    }

    const GOOD: &str = "t,tau1,tau2,tau3,tau4\n0,1,2,3,4\n0.5,5,6,7,8\n";

    #[test]
    fn reads_rows_in_header_order() {
        let h = read("tau4, t ,tau3,tau2,tau1\n4,0,3,2,1\n\n8,0.5,7,6,5\n").unwrap();
        assert_eq!(h.times(), &[0.0, 0.5]);
        assert_eq!(h.torques()[0], JointVector::<4>::new(1.0, 2.0, 3.0, 4.0));
        assert_eq!(h.torques()[1], JointVector::<4>::new(5.0, 6.0, 7.0, 8.0));
    }

    #[test]
    fn byte_order_mark_and_crlf_are_accepted() {
        let plain = read(GOOD).unwrap();
        let crlf = GOOD.replace('\n', "\r\n");
        assert_eq!(read(&crlf).unwrap(), plain);
        assert_eq!(read(&format!("\u{feff}{GOOD}")).unwrap(), plain);
        assert_eq!(read(&format!("\u{feff}{crlf}")).unwrap(), plain);
        // Lines are still counted right.
        let bad = "\u{feff}t,tau1,tau2,tau3,tau4\r\n0,1,2,3,4\r\n\r\n0.5,5,x,7,8\r\n";
        assert_eq!(
            read(bad).unwrap_err().to_string(),
            "line 4, column 3 (`tau2`): `x` is not a number"
        );
    }

    #[test]
    fn errors_name_line_and_column() {
        let cases = [
            (
                "",
                "line 1: the input ends before the header (expected `t,tau1,tau2,tau3,tau4` (in any order))",
            ),
            (
                "\n t,tau1,tau2,tau3\n0,0,0,0\n",
                "line 2: missing column `tau4`",
            ),
            (
                "t,tau1,tau2,tau3,tau4,x\n",
                "line 1: the header must be exactly the columns `t,tau1,tau2,tau3,tau4`",
            ),
            (
                "t,tau1,tau2,tau3,tau4\n",
                "0 data row(s) after the header; the file needs at least 1",
            ),
            (
                "t,tau1,tau2,tau3,tau4\n0,0,0,0\n",
                "line 2, column 5: missing column `tau4` (expected 5 columns",
            ),
            (
                "t,tau1,tau2,tau3,tau4\n0,0,0,inf,0\n",
                "line 2, column 4 (`tau3`): inf is not finite",
            ),
            (
                "t,tau1,tau2,tau3,tau4\n0,0,0,0,0\n0,0,0,0,0\n",
                "line 3, column 1 (`t`): time 0 s is not after the previous row's 0 s",
            ),
            (
                "t,tau1,tau2,tau3,tau4\n0,0,0,0,0\n1,\u{0}0,0,0,0\n",
                "line 3, column 2 (`tau1`)",
            ),
            (
                "t,tau1,tau2,tau3,tau4\n0,0,0,0,0\n1,\u{e9}0,0,0,0\n",
                "line 3, column 2 (`tau1`): `\u{e9}0` is not a number",
            ),
        ];
        for (text, needle) in cases {
            let err = read(text).unwrap_err().to_string();
            assert!(err.starts_with(needle), "{text:?}: {err}");
        }
        let err =
            TorqueHistory::<4>::from_csv_reader(&b"t,tau1,tau2,tau3,tau4\n0,\xFF,0,0,0\n"[..])
                .unwrap_err();
        assert_eq!(
            err.to_string(),
            "line 2: not UTF-8 text (byte 3 of the line is 0xFF); save the file as UTF-8"
        );
    }
}
