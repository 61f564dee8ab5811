//! A normal-force reference given as samples in a CSV file (feature `std`): header `t,f`
//! (s, N: the magnitude the tool is to press with), interpolated linearly, the first value
//! held before the first time and the last after the last.

use std::io::Read;

use crate::csv_text::{CsvText, TextError};

/// Why a force CSV was refused; every variant names the line (from 1), except a failed read
/// and too few rows.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ForceCsvError {
    /// The input could not be read.
    #[error("cannot read the force reference: {0}")]
    Read(String),
    /// The input is not UTF-8 text.
    #[error("line {line}: not UTF-8 text (byte {offset} of the line is 0x{byte:02X}); save the file as UTF-8")]
    NotUtf8 {
        /// Line number.
        line: usize,
        /// Position of the offending byte in the line (from 1).
        offset: usize,
        /// The byte.
        byte: u8,
    },
    /// The first non-blank line is not `t,f`.
    #[error("line {line}: the header must be `t,f` (s, N), got `{found}`")]
    Header {
        /// Line number.
        line: usize,
        /// The header as read.
        found: String,
    },
    /// A row does not have two fields.
    #[error("line {line}: expected 2 fields `t,f`, got {count}")]
    Fields {
        /// Line number.
        line: usize,
        /// Fields found.
        count: usize,
    },
    /// A field is not a finite number.
    #[error("line {line}, column {column}: `{text}` is not a finite number")]
    Number {
        /// Line number.
        line: usize,
        /// Column (1 or 2).
        column: usize,
        /// The text.
        text: String,
    },
    /// A negative first time, or times that do not increase strictly.
    #[error("line {line}: time {t} s must be >= 0 and after the previous one")]
    Time {
        /// Line number.
        line: usize,
        /// The time, s.
        t: f64,
    },
    /// A negative force.
    #[error("line {line}: force {f} N is negative; give the magnitude of the push")]
    Negative {
        /// Line number.
        line: usize,
        /// The force, N.
        f: f64,
    },
    /// Fewer than two rows.
    #[error("the force reference needs at least 2 rows, got {0}")]
    TooFew(usize),
}

/// A sampled force magnitude over time.
///
/// ```
/// use armdyn::trajectory::force_csv::SampledForce;
/// let f = SampledForce::from_csv_reader("\u{feff}t,f\r\n0,0\r\n1,100\r\n".as_bytes()).unwrap();
/// assert_eq!(f.at(0.25), 25.0);
/// assert_eq!(f.at(5.0), 100.0);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct SampledForce {
    t: Vec<f64>,
    f: Vec<f64>,
}

impl SampledForce {
    /// Reads `t,f` CSV text (a leading byte-order mark, LF, CRLF or CR line ends, blank lines
    /// and spaces around fields are accepted).
    ///
    /// # Errors
    ///
    /// [`ForceCsvError`] naming the line and the rule.
    pub fn from_csv_reader<R: Read>(reader: R) -> Result<Self, ForceCsvError> {
        let input = CsvText::read(reader).map_err(|e| match e {
            TextError::Io(e) => ForceCsvError::Read(e.to_string()),
            TextError::NotUtf8 { line, offset, byte } => ForceCsvError::NotUtf8 {
                line: usize::try_from(line).unwrap_or(usize::MAX),
                offset: usize::try_from(offset).unwrap_or(usize::MAX),
                byte,
            },
        })?;
        let mut lines = input
            .lines()
            .enumerate()
            .map(|(i, l)| (i + 1, l))
            .filter(|(_, l)| !l.trim().is_empty());
        match lines.next() {
            Some((_, h)) if h.split(',').map(str::trim).eq(["t", "f"]) => {}
            Some((line, h)) => {
                return Err(ForceCsvError::Header {
                    line,
                    found: h.to_string(),
                })
            }
            None => return Err(ForceCsvError::TooFew(0)),
        }
        let (mut t, mut f) = (Vec::new(), Vec::new());
        for (line, l) in lines {
            let fields: Vec<&str> = l.split(',').map(str::trim).collect();
            if fields.len() != 2 {
                return Err(ForceCsvError::Fields {
                    line,
                    count: fields.len(),
                });
            }
            let mut v = [0.0; 2];
            for (k, text) in fields.iter().enumerate() {
                v[k] = text
                    .parse::<f64>()
                    .ok()
                    .filter(|x| x.is_finite())
                    .ok_or_else(|| ForceCsvError::Number {
                        line,
                        column: k + 1,
                        text: (*text).to_string(),
                    })?;
            }
            if v[0] < 0.0 || t.last().is_some_and(|p| v[0] <= *p) {
                return Err(ForceCsvError::Time { line, t: v[0] });
            }
            if v[1] < 0.0 {
                return Err(ForceCsvError::Negative { line, f: v[1] });
            }
            t.push(v[0]);
            f.push(v[1]);
        }
        if t.len() < 2 {
            return Err(ForceCsvError::TooFew(t.len()));
        }
        Ok(Self { t, f })
    }

    /// The force magnitude at `t`, N.
    #[must_use]
    pub fn at(&self, t: f64) -> f64 {
        let n = self.t.len();
        if t <= self.t[0] {
            return self.f[0];
        }
        if t >= self.t[n - 1] {
            return self.f[n - 1];
        }
        let k = self.t.partition_point(|x| *x <= t) - 1;
        let u = (t - self.t[k]) / (self.t[k + 1] - self.t[k]);
        self.f[k] + (self.f[k + 1] - self.f[k]) * u
    }

    /// The largest value, N.
    #[must_use]
    pub fn max(&self) -> f64 {
        self.f.iter().copied().fold(0.0, f64::max)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn refuses_with_the_line() {
        let e = |s: &str| {
            SampledForce::from_csv_reader(s.as_bytes())
                .unwrap_err()
                .to_string()
        };
        assert!(e("t,x\n").contains("header"));
        assert!(e("\n\r\nt,x\n").starts_with("line 3: the header must be `t,f`"));
        assert!(e("t,f\r0,1\r1,x\r").starts_with("line 3, column 2"));
        let bad = SampledForce::from_csv_reader(&b"t,f\n0,1\n1,\xFF\n"[..]).unwrap_err();
        assert_eq!(
            bad.to_string(),
            "line 3: not UTF-8 text (byte 3 of the line is 0xFF); save the file as UTF-8"
        );
        assert!(e("t,f\n0,1\n\n1,x\n").starts_with("line 4, column 2"));
        assert!(e("t,f\n0,1\n0,2\n").starts_with("line 3"));
        assert!(e("t,f\n0,-1\n1,2\n").contains("negative"));
        assert!(e("t,f\n0,1,2\n").contains("expected 2 fields"));
        assert!(e("t,f\n0,1\n").contains("at least 2"));
    }
}
