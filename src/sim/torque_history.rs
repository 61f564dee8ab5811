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

use crate::csv_text::{is_blank, CsvText, TextError};
use crate::model::JointVector;

/// Why a torque CSV could not be read. Lines count from 1, blank lines included; columns
/// count from 1 as they appear in the file.
#[derive(Debug, thiserror::Error)]
pub enum TorqueCsvError {
    /// The input could not be read.
    #[error("cannot read the CSV: {0}")]
    Read(#[source] std::io::Error),
    /// The CSV reader failed at a line.
    #[error("line {line}: cannot read the CSV: {source}")]
    Csv {
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
    /// Nothing but blank lines.
    #[error("empty input: expected the header `{expected}` and at least one row")]
    Empty {
        /// The expected header.
        expected: String,
    },
    /// The header lacks a column.
    #[error("line {line}: missing column `{name}` (the header must name the columns `{expected}`, in any order)")]
    MissingColumn {
        /// Line of the header.
        line: u64,
        /// The missing column.
        name: String,
        /// The expected header.
        expected: String,
    },
    /// The header has other or repeated columns.
    #[error("line {line}: expected exactly the columns `{expected}`, found `{found}`")]
    Header {
        /// Line of the header.
        line: u64,
        /// The header as read.
        found: String,
        /// The expected header.
        expected: String,
    },
    /// A row has the wrong number of fields.
    #[error("line {line}: {found} columns, expected {expected}")]
    FieldCount {
        /// Line number.
        line: u64,
        /// Fields found on the line.
        found: usize,
        /// Columns in the header.
        expected: usize,
    },
    /// A field is not a number.
    #[error("line {line}, column {column} (`{name}`): `{text}` is not a number")]
    NotNumeric {
        /// Line number.
        line: u64,
        /// Column (from 1).
        column: usize,
        /// Its name in the header.
        name: String,
        /// The field as read.
        text: String,
    },
    /// A field is NaN or infinite.
    #[error("line {line}, column {column} (`{name}`): {value} is not finite")]
    NonFinite {
        /// Line number.
        line: u64,
        /// Column (from 1).
        column: usize,
        /// Its name in the header.
        name: String,
        /// The value.
        value: f64,
    },
    /// A time is not after the previous row's.
    #[error("line {line}, column {column} (`t`): time {t} s is not after the previous row's {previous} s (times must increase strictly)")]
    NotIncreasing {
        /// Line number.
        line: u64,
        /// Column of `t` (from 1).
        column: usize,
        /// The time, s.
        t: f64,
        /// The previous row's time, s.
        previous: f64,
    },
    /// A header but no rows.
    #[error("line {line}: no rows after the header")]
    NoRows {
        /// Line of the header.
        line: u64,
    },
}

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
    /// [`TorqueCsvError`], naming the line (and column) at fault: unreadable or non-UTF-8
    /// input, a header without the columns `t,tau1,...,tauN`, a row with another number of
    /// fields, a field that is not a finite number, times that do not increase strictly, no
    /// rows.
    pub fn from_csv_reader<R: Read>(reader: R) -> Result<Self, TorqueCsvError> {
        let input = CsvText::read(reader).map_err(|e| match e {
            TextError::Io(e) => TorqueCsvError::Read(e),
            TextError::NotUtf8 { line, offset, byte } => {
                TorqueCsvError::NotUtf8 { line, offset, byte }
            }
        })?;
        let columns = Self::columns();
        let expected = columns.join(",");
        let mut csv = input.reader();
        let mut records = csv.records().filter(|r| !matches!(r, Ok(r) if is_blank(r)));
        let read_error = |source: csv::Error| TorqueCsvError::Csv {
            line: input.error_line(&source),
            source,
        };

        let header = records
            .next()
            .ok_or_else(|| TorqueCsvError::Empty {
                expected: expected.clone(),
            })?
            .map_err(read_error)?;
        let header_line = input.line_of(&header);
        // index[k]: the field holding column k (t, tau1, ...).
        let mut index = Vec::with_capacity(columns.len());
        for name in &columns {
            match header.iter().position(|h| h == name) {
                Some(i) => index.push(i),
                None => {
                    return Err(TorqueCsvError::MissingColumn {
                        line: header_line,
                        name: name.clone(),
                        expected,
                    })
                }
            }
        }
        if header.len() != columns.len() {
            return Err(TorqueCsvError::Header {
                line: header_line,
                found: header.iter().collect::<Vec<_>>().join(","),
                expected,
            });
        }

        let (mut times, mut torques) = (Vec::new(), Vec::new());
        for record in records {
            let record = record.map_err(read_error)?;
            let line = input.line_of(&record);
            if record.len() != columns.len() {
                return Err(TorqueCsvError::FieldCount {
                    line,
                    found: record.len(),
                    expected: columns.len(),
                });
            }
            let mut values = vec![0.0; columns.len()];
            for (k, &i) in index.iter().enumerate() {
                let text = &record[i];
                let value: f64 = text.parse().map_err(|_| TorqueCsvError::NotNumeric {
                    line,
                    column: i + 1,
                    name: columns[k].clone(),
                    text: text.to_owned(),
                })?;
                if !value.is_finite() {
                    return Err(TorqueCsvError::NonFinite {
                        line,
                        column: i + 1,
                        name: columns[k].clone(),
                        value,
                    });
                }
                values[k] = value;
            }
            if let Some(&previous) = times.last() {
                if values[0] <= previous {
                    return Err(TorqueCsvError::NotIncreasing {
                        line,
                        column: index[0] + 1,
                        t: values[0],
                        previous,
                    });
                }
            }
            times.push(values[0]);
            torques.push(JointVector::<N>::from_fn(|j, _| values[j + 1]));
        }
        if times.is_empty() {
            return Err(TorqueCsvError::NoRows { line: header_line });
        }
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

    fn read(text: &str) -> Result<TorqueHistory<4>, TorqueCsvError> {
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
                "empty input: expected the header `t,tau1,tau2,tau3,tau4`",
            ),
            (
                "\n t,tau1,tau2,tau3\n0,0,0,0\n",
                "line 2: missing column `tau4`",
            ),
            (
                "t,tau1,tau2,tau3,tau4,x\n",
                "line 1: expected exactly the columns",
            ),
            (
                "t,tau1,tau2,tau3,tau4\n",
                "line 1: no rows after the header",
            ),
            (
                "t,tau1,tau2,tau3,tau4\n0,0,0,0\n",
                "line 2: 4 columns, expected 5",
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
