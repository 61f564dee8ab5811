//! Reading a [`SampledTrajectory`] from a CSV file of poses (feature `std`).
//!
//! [`SampledTrajectory::from_csv_reader`] reads comma-separated text whose first line is
//! exactly one of
//!
//! ```text
//! t,x,y,z,roll,pitch,yaw
//! t,x,y,z,yaw
//! ```
//!
//! (spaces around a name or value are ignored; nothing else is accepted in the header), then
//! one sample per line: time in s, position of the end effector in the base frame in m, its
//! orientation as roll, pitch and yaw about the fixed base axes x, y, z in rad (REP-103,
//! `R = Rz(yaw) Ry(pitch) Rx(roll)`), or the yaw alone (a rotation about base z, as for a
//! SCARA). Times start at 0 or later and increase strictly. Empty lines are skipped; there
//! are no comment lines. The text is UTF-8; a leading byte-order mark (as spreadsheet
//! programs save it) is ignored, and lines may end in LF or CRLF.

use std::io::Read;

use nalgebra::Vector3;

use crate::csv_text::{is_blank, CsvText, TextError};
use crate::target::{orientation, PoseSample};

use super::SampledTrajectory;

/// The header of a reference CSV file with full poses.
pub const CSV_HEADER: [&str; 7] = ["t", "x", "y", "z", "roll", "pitch", "yaw"];
/// The header of a reference CSV file whose orientation is a yaw about base z.
pub const CSV_HEADER_YAW: [&str; 5] = ["t", "x", "y", "z", "yaw"];

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
    #[error("empty input: expected the header `t,x,y,z,roll,pitch,yaw` (or `t,x,y,z,yaw`) and at least 2 samples")]
    Empty,
    /// The first line is neither `t,x,y,z,roll,pitch,yaw` nor `t,x,y,z,yaw`.
    #[error(
        "line {line}: the header must be exactly `t,x,y,z,roll,pitch,yaw` (s, m, m, m, rad, rad, rad) or `t,x,y,z,yaw` (s, m, m, m, rad), found `{found}`"
    )]
    Header {
        /// Line of the header (1).
        line: u64,
        /// The header as read.
        found: String,
    },
    /// A data line has fewer fields than the header.
    #[error("line {line}, column {column}: missing column `{name}` (expected {expected} columns `{header}`, found {found})")]
    MissingColumn {
        /// Line number.
        line: u64,
        /// First missing column (1-based).
        column: usize,
        /// Its name in the header.
        name: &'static str,
        /// Number of fields found on the line.
        found: usize,
        /// Number of columns of the header.
        expected: usize,
        /// The header, comma-separated.
        header: &'static str,
    },
    /// A data line has more fields than the header.
    #[error("line {line}: {found} columns, expected {expected} (`{header}`)")]
    ExtraColumns {
        /// Line number.
        line: u64,
        /// Number of fields found on the line.
        found: usize,
        /// Number of columns of the header.
        expected: usize,
        /// The header, comma-separated.
        header: &'static str,
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

impl SampledTrajectory {
    /// Reads a reference from CSV text with the header `t,x,y,z,roll,pitch,yaw` or
    /// `t,x,y,z,yaw` (see the [module documentation](self) for the format).
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
    /// use armdyn::trajectory::SampledTrajectory;
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
        let is = |names: &[&str]| {
            header.len() == names.len() && header.iter().zip(names).all(|(a, b)| a == *b)
        };
        let (names, joined): (&'static [&'static str], &'static str) = if is(&CSV_HEADER) {
            (&CSV_HEADER, "t,x,y,z,roll,pitch,yaw")
        } else if is(&CSV_HEADER_YAW) {
            (&CSV_HEADER_YAW, "t,x,y,z,yaw")
        } else {
            return Err(CsvError::Header {
                line: header_line,
                found: header.iter().collect::<Vec<_>>().join(","),
            });
        };

        let mut samples: Vec<PoseSample> = Vec::new();
        for record in records {
            let record = record.map_err(read_error)?;
            let line = line_of(&record);
            if record.len() < names.len() {
                return Err(CsvError::MissingColumn {
                    line,
                    column: record.len() + 1,
                    name: names[record.len()],
                    found: record.len(),
                    expected: names.len(),
                    header: joined,
                });
            }
            if record.len() > names.len() {
                return Err(CsvError::ExtraColumns {
                    line,
                    found: record.len(),
                    expected: names.len(),
                    header: joined,
                });
            }
            let mut values = [0.0; 7];
            for (k, text) in record.iter().enumerate() {
                let value: f64 = text.parse().map_err(|_| CsvError::NotNumeric {
                    line,
                    column: k + 1,
                    name: names[k],
                    text: text.to_owned(),
                })?;
                if !value.is_finite() {
                    return Err(CsvError::NonFinite {
                        line,
                        column: k + 1,
                        name: names[k],
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
            let position = Vector3::new(values[1], values[2], values[3]);
            samples.push(if names.len() == CSV_HEADER.len() {
                PoseSample::new(
                    t,
                    position,
                    orientation::from_rpy(values[4], values[5], values[6]),
                )
            } else {
                PoseSample::with_yaw(t, position, values[4])
            });
        }
        if samples.len() < 2 {
            return Err(CsvError::TooFewRows {
                rows: samples.len(),
            });
        }
        Ok(Self::from_valid(&samples))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn read(text: &str) -> Result<SampledTrajectory, CsvError> {
        SampledTrajectory::from_csv_reader(text.as_bytes())
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
        let err = read("t,x,y,z,roll,pitch,yaw\n0,0,0,0,0,0,0\n1,0,0,0,0\n").unwrap_err();
        assert_eq!(
            err.to_string(),
            "line 3, column 6: missing column `pitch` (expected 7 columns `t,x,y,z,roll,pitch,yaw`, found 5)"
        );
        let err = read("t,x,y,z,yaw\n0,0,0,0,0\n1,0,0,0,0,9\n").unwrap_err();
        assert!(
            matches!(
                err,
                CsvError::ExtraColumns {
                    line: 3,
                    found: 6,
                    ..
                }
            ),
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
}
