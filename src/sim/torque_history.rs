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
