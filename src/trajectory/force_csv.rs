//! A normal-force reference given as samples in a CSV file (feature `std`): header `t,f`
//! (s, N: the magnitude the tool is to press with), interpolated linearly, the first value
//! held before the first time and the last after the last.

use std::io::Read;

use crate::csv_text::{check_times, one_of, CsvError, CsvText};

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
    /// and spaces around fields are accepted): times from 0 on, increasing strictly; forces
    /// not negative; at least two rows.
    ///
    /// # Errors
    ///
    /// [`CsvError`] naming the line and the rule.
    pub fn from_csv_reader<R: Read>(reader: R) -> Result<Self, CsvError> {
        const EXPECTED: &str = "`t,f` (s, N)";
        let (_, rows) = CsvText::read(reader)?.number_table(EXPECTED, |line, names| {
            one_of(line, names, &[(&["t", "f"], ())], EXPECTED)
        })?;
        check_times(&rows, 0, true)?;
        if let Some(row) = rows.iter().find(|r| r.values[1] < 0.0) {
            return Err(CsvError::Negative {
                line: row.line,
                column: 2,
                name: "f".to_string(),
                value: row.values[1],
            });
        }
        if rows.len() < 2 {
            return Err(CsvError::TooFewRows {
                rows: rows.len(),
                min: 2,
            });
        }
        Ok(Self {
            t: rows.iter().map(|r| r.values[0]).collect(),
            f: rows.iter().map(|r| r.values[1]).collect(),
        })
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
