//! Reading CSV input files (feature `std`): the one layer under every CSV reader of the crate
//! ([`crate::trajectory::SampledTrajectory::from_csv_reader`],
//! [`crate::trajectory::force_csv::SampledForce::from_csv_reader`],
//! [`crate::sim::torque_history::TorqueHistory::from_csv_reader`],
//! [`crate::identification::log::JointLog::from_csv_reader`]), and its one error type,
//! [`CsvError`].
//!
//! The whole input is read once, a leading UTF-8 byte-order mark (as spreadsheet programs
//! write it) is dropped, the text must be UTF-8, and lines may end in LF, CRLF or CR (what the
//! `csv` crate splits records on). Records are trimmed of spaces; blank lines are skipped.
//! Lines count from 1, blank ones included; columns count from 1 as they appear in the file.

use std::io::Read;

const BOM: &[u8] = b"\xEF\xBB\xBF";

/// Why a CSV input could not be read: each case names the line (and the column) at fault.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum CsvError {
    /// The input could not be read, or is not valid CSV.
    #[error("{}cannot read the CSV: {message}", at_line(*.line))]
    Read {
        /// Line where reading failed (0 if unknown).
        line: u64,
        /// What the reader reported.
        message: String,
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
    /// Nothing but blank (and, where the format has them, comment) lines.
    #[error("line {line}: the input ends before the header (expected {expected})")]
    NoHeader {
        /// The last line of the input.
        line: u64,
        /// The expected header, in words.
        expected: String,
    },
    /// The header is not the expected one.
    #[error("line {line}: the header must be {expected}, found `{found}`")]
    Header {
        /// Line of the header.
        line: u64,
        /// The expected header, in words.
        expected: String,
        /// The header as read.
        found: String,
    },
    /// The header lacks a column.
    #[error("line {line}: missing column `{name}` (required: {expected})")]
    MissingColumn {
        /// Line of the header.
        line: u64,
        /// The missing column.
        name: String,
        /// The required columns, in words.
        expected: String,
    },
    /// The header names a column twice.
    #[error("line {line}, column {column} (`{name}`): duplicated column (also column {first})")]
    DuplicateColumn {
        /// Line of the header.
        line: u64,
        /// The second occurrence (from 1).
        column: usize,
        /// The first occurrence (from 1).
        first: usize,
        /// The name.
        name: String,
    },
    /// The header names a joint column beyond the robot's joints (`q7` for a 6-joint robot):
    /// a file of another robot.
    #[error("line {line}, column {column} (`{name}`): joint {joint} of a robot with {joints} joints; is this the log of another robot?")]
    ExtraJoint {
        /// Line of the header.
        line: u64,
        /// The column (from 1).
        column: usize,
        /// The name.
        name: String,
        /// The joint it names (from 1).
        joint: usize,
        /// The robot's joints.
        joints: usize,
    },
    /// A row has fewer fields than the header.
    #[error("line {line}, column {column}: missing column `{name}` (expected {expected} columns `{header}`, found {found})")]
    MissingField {
        /// Line number.
        line: u64,
        /// First missing column (from 1).
        column: usize,
        /// Its name in the header.
        name: String,
        /// Fields found on the line.
        found: usize,
        /// Columns of the header.
        expected: usize,
        /// The header, comma-separated.
        header: String,
    },
    /// A row has more fields than the header.
    #[error("line {line}: {found} columns, expected {expected} (`{header}`)")]
    ExtraFields {
        /// Line number.
        line: u64,
        /// Fields found on the line.
        found: usize,
        /// Columns of the header.
        expected: usize,
        /// The header, comma-separated.
        header: String,
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
    /// The first time is negative.
    #[error("line {line}, column {column} (`t`): time {t} s is negative; the samples start at t = 0 or later")]
    NegativeStart {
        /// Line number.
        line: u64,
        /// Column of `t` (from 1).
        column: usize,
        /// The time, s.
        t: f64,
    },
    /// The first time is not 0 (a format whose samples start at 0).
    #[error("line {line}, column {column} (`t`): the first time is {t} s; the samples must start at t = 0")]
    StartNotZero {
        /// Line number.
        line: u64,
        /// Column of `t` (from 1).
        column: usize,
        /// The time, s.
        t: f64,
    },
    /// Samples given in memory that do not fit together (their lengths differ).
    #[error("{0}")]
    Samples(&'static str),
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
    /// A value that must not be negative (a magnitude) is.
    #[error("line {line}, column {column} (`{name}`): {value} is negative; give a magnitude")]
    Negative {
        /// Line number.
        line: u64,
        /// Column (from 1).
        column: usize,
        /// Its name in the header.
        name: String,
        /// The value.
        value: f64,
    },
    /// Too few samples left of a log after its repairs (rows with a NaN or infinite value,
    /// a repeated or a backward time stamp dropped).
    #[error("line {line}: the log ends with {kept} usable samples of {read} rows read ({dropped} dropped: {non_finite} not finite, {duplicate} duplicated time stamps, {backward} out of order); at least {min} are needed")]
    TooFewSamples {
        /// The last line of the input.
        line: u64,
        /// Data rows read.
        read: usize,
        /// Samples kept.
        kept: usize,
        /// Rows dropped.
        dropped: usize,
        /// Of which with a NaN or infinite value.
        non_finite: usize,
        /// Of which with a duplicated time stamp.
        duplicate: usize,
        /// Of which with a time before the previous kept one.
        backward: usize,
        /// The least number of samples asked for.
        min: usize,
    },
    /// The median interval between samples is not positive and finite (fewer than two
    /// samples, or times too far apart to subtract).
    #[error("line {line}: the median interval between the samples from here on is {median} s; it must be positive and finite")]
    Interval {
        /// Line of the first kept sample (the header's if none).
        line: u64,
        /// The median interval, s (NaN if there is no interval).
        median: f64,
    },
    /// Too few rows after the header.
    #[error("{rows} data row(s) after the header; the file needs at least {min}")]
    TooFewRows {
        /// Rows read.
        rows: usize,
        /// Rows needed.
        min: usize,
    },
}

/// `"line N: "`, or nothing for line 0 (unknown).
fn at_line(line: u64) -> String {
    if line == 0 {
        String::new()
    } else {
        format!("line {line}: ")
    }
}

/// A row of a [`CsvText::number_table`]: its line and its values in the file's column order.
pub(crate) struct NumberRow {
    /// Line number.
    pub(crate) line: u64,
    /// The values, as many as the header's columns.
    pub(crate) values: Vec<f64>,
}

/// The bytes of a CSV input, checked to be UTF-8, without a leading byte-order mark.
pub(crate) struct CsvText {
    bytes: Vec<u8>,
}

impl CsvText {
    /// Reads all of `reader`.
    pub(crate) fn read<R: Read>(mut reader: R) -> Result<Self, CsvError> {
        let mut bytes = Vec::new();
        reader.read_to_end(&mut bytes).map_err(|e| CsvError::Read {
            line: 0,
            message: e.to_string(),
        })?;
        if bytes.starts_with(BOM) {
            bytes.drain(..BOM.len());
        }
        let text = Self { bytes };
        if let Err(e) = std::str::from_utf8(&text.bytes) {
            let at = e.valid_up_to();
            let line_start = text.bytes[..at]
                .iter()
                .rposition(|&b| b == b'\n' || b == b'\r')
                .map_or(0, |p| p + 1);
            return Err(CsvError::NotUtf8 {
                line: text.line_at(at as u64),
                offset: (at - line_start + 1) as u64,
                byte: text.bytes[at],
            });
        }
        Ok(text)
    }

    /// A CSV reader over the text: no header handling (the callers check it), records of any
    /// length, spaces around fields trimmed.
    pub(crate) fn reader(&self) -> csv::Reader<&[u8]> {
        csv::ReaderBuilder::new()
            .has_headers(false)
            .flexible(true)
            .trim(csv::Trim::All)
            .from_reader(self.bytes.as_slice())
    }

    /// The lines of the text, without their ends (LF, CRLF or a lone CR), blank ones
    /// included, for a reader that splits fields itself.
    pub(crate) fn lines(&self) -> impl Iterator<Item = &str> + '_ {
        // Checked to be UTF-8 in `read`.
        let text = std::str::from_utf8(&self.bytes).unwrap_or_default();
        let mut rest = Some(text);
        std::iter::from_fn(move || {
            let s = rest?;
            match s.find(['\n', '\r']) {
                Some(i) => {
                    let skip = if s[i..].starts_with("\r\n") { 2 } else { 1 };
                    rest = Some(&s[i + skip..]);
                    Some(&s[..i])
                }
                None => {
                    rest = None;
                    Some(s)
                }
            }
        })
    }

    /// The line (from 1) of a record that the reader started at byte `byte`: a record's
    /// position is where the reader started on it, before the blank lines it skipped, so
    /// move past them to the record itself. LF, CRLF and a lone CR each end a line.
    pub(crate) fn line_at(&self, byte: u64) -> u64 {
        let bytes = &self.bytes;
        let mut end = usize::try_from(byte).map_or(bytes.len(), |b| b.min(bytes.len()));
        while end < bytes.len() && (bytes[end] == b'\n' || bytes[end] == b'\r') {
            end += 1;
        }
        let breaks = bytes[..end]
            .iter()
            .enumerate()
            .filter(|&(i, &b)| b == b'\n' || (b == b'\r' && bytes.get(i + 1) != Some(&b'\n')))
            .count();
        1 + breaks as u64
    }

    /// The line of a record (0 if it has no position).
    pub(crate) fn line_of(&self, record: &csv::StringRecord) -> u64 {
        record.position().map_or(0, |p| self.line_at(p.byte()))
    }

    /// The line of a reader error (0 if it has no position).
    pub(crate) fn error_line(&self, error: &csv::Error) -> u64 {
        error.position().map_or(0, |p| self.line_at(p.byte()))
    }
}

impl CsvText {
    /// Reads a table of finite numbers: the first non-blank record is the header, given to
    /// `header` with its line and its names (which returns what the caller keeps of it, or the
    /// error); every other non-blank record is a row with as many fields as the header, each a
    /// finite number. `expected` describes the header for an empty input.
    ///
    /// # Errors
    ///
    /// [`CsvError`]: [`CsvError::NoHeader`], `header`'s, a record the reader cannot split
    /// ([`CsvError::Read`]), [`CsvError::MissingField`], [`CsvError::ExtraFields`],
    /// [`CsvError::NotNumeric`], [`CsvError::NonFinite`].
    pub(crate) fn number_table<H>(
        &self,
        expected: &str,
        header: impl FnOnce(u64, &[&str]) -> Result<H, CsvError>,
    ) -> Result<(H, Vec<NumberRow>), CsvError> {
        let read_error = |e: csv::Error| CsvError::Read {
            line: self.error_line(&e),
            message: e.to_string(),
        };
        let mut csv = self.reader();
        let mut records = csv.records().filter(|r| !matches!(r, Ok(r) if is_blank(r)));
        let names_record = records
            .next()
            .ok_or_else(|| CsvError::NoHeader {
                line: self.line_at(u64::MAX),
                expected: expected.to_string(),
            })?
            .map_err(read_error)?;
        let names: Vec<&str> = names_record.iter().collect();
        let kept = header(self.line_of(&names_record), &names)?;
        let mut rows = Vec::new();
        for record in records {
            let record = record.map_err(read_error)?;
            let line = self.line_of(&record);
            check_field_count(line, record.len(), &names)?;
            let mut values = Vec::with_capacity(names.len());
            for (k, text) in record.iter().enumerate() {
                let value: f64 = text.parse().map_err(|_| CsvError::NotNumeric {
                    line,
                    column: k + 1,
                    name: names[k].to_string(),
                    text: text.to_owned(),
                })?;
                if !value.is_finite() {
                    return Err(CsvError::NonFinite {
                        line,
                        column: k + 1,
                        name: names[k].to_string(),
                        value,
                    });
                }
                values.push(value);
            }
            rows.push(NumberRow { line, values });
        }
        Ok((kept, rows))
    }
}

/// The header check of a format with fixed headers: `names` (the header read on `line`) must
/// be one of `choices`, each with what the caller keeps of it.
///
/// # Errors
///
/// [`CsvError::Header`] naming `expected` (the headers in words) otherwise.
pub(crate) fn one_of<T: Copy>(
    line: u64,
    names: &[&str],
    choices: &[(&[&str], T)],
    expected: &str,
) -> Result<T, CsvError> {
    choices
        .iter()
        .find(|(header, _)| *header == names)
        .map(|&(_, kept)| kept)
        .ok_or_else(|| CsvError::Header {
            line,
            expected: expected.to_string(),
            found: names.join(","),
        })
}

/// Checks that the row on `line` has as many fields (`found`) as the header has `names`.
///
/// # Errors
///
/// [`CsvError::MissingField`] naming the first missing column, or [`CsvError::ExtraFields`].
pub(crate) fn check_field_count(line: u64, found: usize, names: &[&str]) -> Result<(), CsvError> {
    if let Some(name) = names.get(found) {
        return Err(CsvError::MissingField {
            line,
            column: found + 1,
            name: (*name).to_string(),
            found,
            expected: names.len(),
            header: names.join(","),
        });
    }
    if found > names.len() {
        return Err(CsvError::ExtraFields {
            line,
            found,
            expected: names.len(),
            header: names.join(","),
        });
    }
    Ok(())
}

/// Checks that the times in column `column` (from 0) of `rows` increase strictly, and with
/// `from_zero` that the first is not negative.
///
/// # Errors
///
/// [`CsvError::NegativeStart`] or [`CsvError::NotIncreasing`] naming the row.
pub(crate) fn check_times(
    rows: &[NumberRow],
    column: usize,
    from_zero: bool,
) -> Result<(), CsvError> {
    let mut previous: Option<f64> = None;
    for row in rows {
        let t = row.values[column];
        match previous {
            None if from_zero && t < 0.0 => {
                return Err(CsvError::NegativeStart {
                    line: row.line,
                    column: column + 1,
                    t,
                })
            }
            Some(previous) if t <= previous => {
                return Err(CsvError::NotIncreasing {
                    line: row.line,
                    column: column + 1,
                    t,
                    previous,
                })
            }
            _ => {}
        }
        previous = Some(t);
    }
    Ok(())
}

/// `true` for a record that is a blank line (nothing but spaces).
pub(crate) fn is_blank(record: &csv::StringRecord) -> bool {
    record.len() == 1 && record[0].is_empty()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn lines(text: &[u8]) -> Vec<u64> {
        let t = CsvText::read(text).unwrap();
        let mut reader = t.reader();
        reader.records().map(|r| t.line_of(&r.unwrap())).collect()
    }

    #[test]
    fn lines_count_lf_crlf_and_cr_and_skip_blank_lines() {
        assert_eq!(lines(b"a\nb\n\nc\n"), [1, 2, 4]);
        assert_eq!(lines(b"a\r\nb\r\n\r\nc\r\n"), [1, 2, 4]);
        assert_eq!(lines(b"a\rb\r\rc"), [1, 2, 4]);
        assert_eq!(lines(b"\xEF\xBB\xBFa\r\n\r\nb"), [1, 3]);
    }

    #[test]
    fn lines_split_like_the_reader() {
        let t = CsvText::read(&b"\xEF\xBB\xBFa\r\nb\rc\n\nd"[..]).unwrap();
        assert_eq!(t.lines().collect::<Vec<_>>(), ["a", "b", "c", "", "d"]);
        let t = CsvText::read(&b"a\n"[..]).unwrap();
        assert_eq!(t.lines().collect::<Vec<_>>(), ["a", ""]);
    }

    #[test]
    fn byte_order_mark_is_dropped() {
        let t = CsvText::read(&b"\xEF\xBB\xBFt,x\n"[..]).unwrap();
        let mut reader = t.reader();
        let header = reader.records().next().unwrap().unwrap();
        assert_eq!(&header[0], "t");
    }

    #[test]
    fn invalid_utf8_names_line_and_byte() {
        match CsvText::read(&b"t,x\r\n0,1\r\n1,\xFF\n"[..]) {
            Err(CsvError::NotUtf8 { line, offset, byte }) => {
                assert_eq!((line, offset, byte), (3, 3, 0xFF));
            }
            other => panic!("expected NotUtf8, got {:?}", other.map(|_| ())),
        }
    }
}
