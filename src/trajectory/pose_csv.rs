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

pub use crate::csv_text::CsvError;
use crate::csv_text::{check_times, one_of, CsvText};
use crate::target::{orientation, PoseSample};

use super::SampledTrajectory;

/// The header of a reference CSV file with full poses.
pub const CSV_HEADER: [&str; 7] = ["t", "x", "y", "z", "roll", "pitch", "yaw"];
/// The header of a reference CSV file whose orientation is a yaw about base z.
pub const CSV_HEADER_YAW: [&str; 5] = ["t", "x", "y", "z", "yaw"];

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
        const EXPECTED: &str = "exactly `t,x,y,z,roll,pitch,yaw` (s, m, m, m, rad, rad, rad) or `t,x,y,z,yaw` (s, m, m, m, rad)";
        let (full, rows) = CsvText::read(reader)?.number_table(EXPECTED, |line, names| {
            one_of(
                line,
                names,
                &[(&CSV_HEADER, true), (&CSV_HEADER_YAW, false)],
                EXPECTED,
            )
        })?;
        check_times(&rows, 0, true)?;
        if rows.len() < 2 {
            return Err(CsvError::TooFewRows {
                rows: rows.len(),
                min: 2,
            });
        }
        let samples: Vec<PoseSample> = rows
            .iter()
            .map(|row| {
                let v = &row.values;
                let position = Vector3::new(v[1], v[2], v[3]);
                if full {
                    PoseSample::new(v[0], position, orientation::from_rpy(v[4], v[5], v[6]))
                } else {
                    PoseSample::with_yaw(v[0], position, v[4])
                }
            })
            .collect();
        Ok(Self::from_valid(&samples))
    }
}
