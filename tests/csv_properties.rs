//! Property tests of the CSV readers (`SampledTrajectory::from_csv_reader`,
//! `TorqueHistory::from_csv_reader`, `SampledForce::from_csv_reader`,
//! `JointReference::from_csv_reader_named`): random and mutated
//! input never panics; a bad line is named by the error, with its column where there is one;
//! well-formed files, written with or without a byte-order mark, with LF or CRLF line ends,
//! blank lines and spaces, read back to exactly the values written.
//!
//! The seed is fixed so that every run checks the same cases; set `PROPTEST_RNG_SEED` (and
//! `PROPTEST_CASES`) to explore others.

use proptest::prelude::*;

#[path = "common/properties.rs"]
mod properties;
use properties::{config, line_count, named_line};

use armdyn::sim::torque_history::TorqueHistory;
use armdyn::trajectory::force_csv::SampledForce;
use armdyn::trajectory::{CartesianTrajectory, CsvError, JointReference, SampledTrajectory};

/// Every error names a line that exists (from 1), except those about the whole input.
fn check_error(bytes: &[u8], message: &str, whole_input: &[&str]) -> Result<(), TestCaseError> {
    if whole_input.iter().any(|w| message.starts_with(w)) {
        return Ok(());
    }
    let line = named_line(message);
    prop_assert!(line.is_some(), "error without a line: {message}");
    let line = line.unwrap_or(0);
    prop_assert!(
        (1..=line_count(bytes)).contains(&line),
        "line {line} of {}: {message}",
        line_count(bytes)
    );
    Ok(())
}

fn read_reference(bytes: &[u8]) -> Result<Option<SampledTrajectory>, TestCaseError> {
    match SampledTrajectory::from_csv_reader(bytes) {
        Ok(r) => Ok(Some(r)),
        Err(e) => {
            if let CsvError::Read { .. } = e {
                prop_assert!(false, "only an I/O error has no line: {e}");
            }
            check_error(bytes, &e.to_string(), &["0 data row", "1 data row"])?;
            Ok(None)
        }
    }
}

fn read_torques(bytes: &[u8]) -> Result<Option<TorqueHistory<4>>, TestCaseError> {
    match TorqueHistory::<4>::from_csv_reader(bytes) {
        Ok(h) => Ok(Some(h)),
        Err(e) => {
            if let CsvError::Read { .. } = e {
                prop_assert!(false, "only an I/O error has no line: {e}");
            }
            check_error(bytes, &e.to_string(), &["0 data row"])?;
            Ok(None)
        }
    }
}

fn read_force(bytes: &[u8]) -> Result<Option<SampledForce>, TestCaseError> {
    match SampledForce::from_csv_reader(bytes) {
        Ok(f) => Ok(Some(f)),
        Err(e) => {
            if let CsvError::Read { .. } = e {
                prop_assert!(false, "only an I/O error has no line: {e}");
            }
            check_error(bytes, &e.to_string(), &["0 data row", "1 data row"])?;
            Ok(None)
        }
    }
}

/// How a well-formed file is written.
#[derive(Clone, Debug)]
struct Layout {
    bom: bool,
    crlf: bool,
    /// Blank lines before each line (header first), 0 to 2.
    blanks: Vec<usize>,
    /// Spaces around every field.
    padded: bool,
    final_newline: bool,
}

fn layout(lines: usize) -> impl Strategy<Value = Layout> {
    (
        any::<bool>(),
        any::<bool>(),
        prop::collection::vec(0usize..3, lines),
        any::<bool>(),
        any::<bool>(),
    )
        .prop_map(|(bom, crlf, blanks, padded, final_newline)| Layout {
            bom,
            crlf,
            blanks,
            padded,
            final_newline,
        })
}

/// `rows` (fields as text) written with `layout`; returns the bytes and the line of each row
/// (header first).
fn write(rows: &[Vec<String>], layout: &Layout) -> (Vec<u8>, Vec<u64>) {
    let end = if layout.crlf { "\r\n" } else { "\n" };
    let mut text = String::new();
    if layout.bom {
        text.push('\u{feff}');
    }
    let mut line = 1;
    let mut lines = Vec::new();
    for (k, row) in rows.iter().enumerate() {
        for _ in 0..layout.blanks[k] {
            text.push_str(if k % 2 == 0 { "" } else { "  " });
            text.push_str(end);
            line += 1;
        }
        let fields: Vec<String> = row
            .iter()
            .map(|f| {
                if layout.padded {
                    format!(" {f} ")
                } else {
                    f.clone()
                }
            })
            .collect();
        text.push_str(&fields.join(","));
        lines.push(line);
        if k + 1 < rows.len() || layout.final_newline {
            text.push_str(end);
        }
        line += 1;
    }
    (text.into_bytes(), lines)
}

/// Strictly increasing times from 0 and finite values.
fn samples(columns: usize) -> impl Strategy<Value = Vec<Vec<f64>>> {
    prop::collection::vec(
        (
            1e-6f64..10.0,
            prop::collection::vec(-1e6f64..1e6, columns - 1),
        ),
        2..8,
    )
    .prop_map(|rows| {
        let mut t = 0.0;
        rows.into_iter()
            .enumerate()
            .map(|(k, (dt, values))| {
                if k > 0 {
                    t += dt;
                }
                std::iter::once(t).chain(values).collect()
            })
            .collect()
    })
}

/// A field that is not a number (`f64::from_str` refuses it) and holds no comma, quote or
/// line end.
fn not_a_number() -> impl Strategy<Value = String> {
    prop_oneof![
        "[a-hj-mo-zA-HJ-MO-Z_]{1,6}",
        Just(String::new()),
        Just("1..2".to_string()),
        Just("0x10".to_string()),
        Just("1e".to_string()),
        Just("--1".to_string()),
        Just("1 2".to_string()),
        Just("\u{feff}0".to_string()),
    ]
}

const REFERENCE_HEADER: [&str; 5] = ["t", "x", "y", "z", "yaw"];
const TORQUE_HEADER: [&str; 5] = ["t", "tau1", "tau2", "tau3", "tau4"];

fn as_rows(header: &[&str], values: &[Vec<f64>]) -> Vec<Vec<String>> {
    std::iter::once(header.iter().map(|h| (*h).to_string()).collect())
        .chain(
            values
                .iter()
                .map(|row| row.iter().map(|x| format!("{x:?}")).collect()),
        )
        .collect()
}

/// The joint reader on `bytes`, for two joints named `a` and `b`: `Ok` or an error, never a
/// panic (a plan's header is tried too).
fn read_joints(bytes: &[u8]) {
    let _ = JointReference::<2>::from_csv_reader_named(bytes, &["a", "b"]);
    let mut planned = b"t,q_a,q_b,qd_a,qd_b\n".to_vec();
    planned.extend_from_slice(bytes);
    let _ = JointReference::<2>::from_csv_reader_named(planned.as_slice(), &["a", "b"]);
}

proptest! {
    #![proptest_config(config(4096, 14))]

    #[test]
    fn random_bytes_never_panic_and_errors_name_a_line(bytes in prop::collection::vec(any::<u8>(), 0..300)) {
        read_reference(&bytes)?;
        read_torques(&bytes)?;
        read_force(&bytes)?;
        read_joints(&bytes);
    }

    #[test]
    fn random_text_with_csv_characters_never_panics(text in "[tf,xyzaw0-9.e\\-+ \r\n\u{feff}\"]{0,200}") {
        read_reference(text.as_bytes())?;
        read_torques(text.as_bytes())?;
        read_force(text.as_bytes())?;
        read_joints(text.as_bytes());
    }

    /// A plan's rows (times increasing from 0) read back: the reference passes through every
    /// sample's position and velocity.
    #[test]
    fn a_plan_passes_through_its_samples(values in samples(5)) {
        let mut text = String::from("t,q_a,q_b,qd_a,qd_b,tau_a,tau_b\n");
        for row in &values {
            text += &format!("{},{},{},{},{},0,0\n", row[0], row[1], row[2], row[3], row[4]);
        }
        match JointReference::<2>::from_csv_reader_named(text.as_bytes(), &["a", "b"]) {
            Ok(r) => {
                for row in &values {
                    let x = r.at(row[0]);
                    for (got, want) in [(x.q[0], row[1]), (x.q[1], row[2]), (x.qd[0], row[3]), (x.qd[1], row[4])] {
                        prop_assert!((got - want).abs() <= 1e-9 * (1.0 + want.abs()), "{got} {want}");
                    }
                }
            }
            Err(e) => prop_assert!(values.len() < 2, "{e}"),
        }
    }
}

proptest! {
    #![proptest_config(config(1024, 14))]

    #[test]
    fn well_formed_references_read_back_exactly(values in samples(5), layout in layout(8)) {
        let (bytes, _) = write(&as_rows(&REFERENCE_HEADER, &values), &layout);
        let read = read_reference(&bytes)?;
        prop_assert!(read.is_some(), "{:?}", String::from_utf8_lossy(&bytes));
        let read = read.unwrap();
        let got: Vec<Vec<f64>> = read
            .samples()
            .map(|s| vec![s.t, s.position.x, s.position.y, s.position.z])
            .collect();
        let expected: Vec<Vec<f64>> = values.iter().map(|v| v[..4].to_vec()).collect();
        prop_assert_eq!(got, expected);
        // The yaw becomes a rotation about z: the same angle up to whole turns and rounding
        // (the rotation of yaw + 2 pi k, for |yaw| up to 1e6 rad, to about 1e-10 rad).
        for (s, v) in read.samples().zip(&values) {
            let gap = armdyn::target::wrap_angle(s.yaw() - v[4]);
            prop_assert!(gap.abs() <= 1e-16 * v[4].abs() * 4.0 + 1e-15, "{} vs {}", s.yaw(), v[4]);
        }
        prop_assert_eq!(read.duration(), values[values.len() - 1][0]);
    }

    #[test]
    fn well_formed_torque_files_read_back_exactly(
        values in samples(5),
        layout in layout(8),
        order in Just((0..5).collect::<Vec<usize>>()).prop_shuffle(),
    ) {
        // Columns in any order: field i holds column order[i].
        let header: Vec<&str> = order.iter().map(|&c| TORQUE_HEADER[c]).collect();
        let shuffled: Vec<Vec<f64>> = values.iter().map(|r| order.iter().map(|&c| r[c]).collect()).collect();
        let (bytes, _) = write(&as_rows(&header, &shuffled), &layout);
        let read = read_torques(&bytes)?;
        prop_assert!(read.is_some(), "{:?}", String::from_utf8_lossy(&bytes));
        let read = read.unwrap();
        let times: Vec<f64> = values.iter().map(|r| r[0]).collect();
        prop_assert_eq!(read.times(), times.as_slice());
        for (tau, row) in read.torques().iter().zip(&values) {
            prop_assert_eq!(tau.as_slice(), &row[1..]);
        }
    }

    /// One field of one row replaced by something that is not a finite number: the error
    /// names that row's line and that field's column.
    #[test]
    fn a_bad_field_is_named_by_line_and_column(
        values in samples(5),
        layout in layout(8),
        row in any::<prop::sample::Index>(),
        column in 0usize..5,
        garbage in prop_oneof![not_a_number(), Just("inf".to_string()), Just("NaN".to_string())],
    ) {
        for header in [REFERENCE_HEADER, TORQUE_HEADER] {
            let mut rows = as_rows(&header, &values);
            let r = 1 + row.index(values.len());
            rows[r][column] = garbage.clone();
            let (bytes, lines) = write(&rows, &layout);
            let message = if header == REFERENCE_HEADER {
                SampledTrajectory::from_csv_reader(bytes.as_slice()).map(|_| ()).unwrap_err().to_string()
            } else {
                TorqueHistory::<4>::from_csv_reader(bytes.as_slice()).map(|_| ()).unwrap_err().to_string()
            };
            let expected = format!("line {}, column {} (`{}`)", lines[r], column + 1, header[column]);
            prop_assert!(message.starts_with(&expected), "{message} (expected {expected})");
        }
    }

    /// A time not after the previous one, a row with a field too few, or a byte that is not
    /// UTF-8: the error names that row's line.
    #[test]
    fn a_bad_row_is_named_by_its_line(
        values in samples(5),
        layout in layout(8),
        row in any::<prop::sample::Index>(),
        fault in 0usize..3,
    ) {
        for header in [REFERENCE_HEADER, TORQUE_HEADER] {
            let mut rows = as_rows(&header, &values);
            let r = 2 + row.index(values.len() - 1); // a data row after the first
            match fault {
                0 => rows[r][0] = rows[r - 1][0].clone(),
                1 => { rows[r].pop(); }
                _ => rows[r][2] = "1\u{fffd}".to_string(), // replaced by an invalid byte below
            }
            let (mut bytes, lines) = write(&rows, &layout);
            if fault == 2 {
                let at = bytes.windows(3).position(|w| w == "\u{fffd}".as_bytes()).unwrap_or(0);
                bytes.splice(at..at + 3, [0xFFu8]);
            }
            let message = if header == REFERENCE_HEADER {
                SampledTrajectory::from_csv_reader(bytes.as_slice()).map(|_| ()).unwrap_err().to_string()
            } else {
                TorqueHistory::<4>::from_csv_reader(bytes.as_slice()).map(|_| ()).unwrap_err().to_string()
            };
            let expected = format!("line {}", lines[r]);
            prop_assert!(
                message.starts_with(&format!("{expected},")) || message.starts_with(&format!("{expected}:")),
                "{message} (expected {expected})"
            );
        }
    }

    /// Well-formed files with random bytes inserted, deleted or replaced: never a panic, and
    /// every error names a line that exists.
    #[test]
    fn mutated_files_never_panic_and_errors_name_a_line(
        values in samples(5),
        layout in layout(8),
        edits in prop::collection::vec((any::<prop::sample::Index>(), 0usize..3, any::<u8>()), 1..4),
    ) {
        for header in [REFERENCE_HEADER, TORQUE_HEADER] {
            let (mut bytes, _) = write(&as_rows(&header, &values), &layout);
            for (at, kind, byte) in &edits {
                let i = at.index(bytes.len() + 1);
                match kind {
                    0 => bytes.insert(i, *byte),
                    1 if i < bytes.len() => { bytes.remove(i); }
                    _ if i < bytes.len() => bytes[i] = *byte,
                    _ => {}
                }
            }
            read_reference(&bytes)?;
            read_torques(&bytes)?;
            read_force(&bytes)?;
        }
    }

    /// Force references in every layout read back exactly; a bad field is named by its line
    /// and column.
    #[test]
    fn force_references_read_back_and_name_bad_fields(
        values in samples(2),
        layout in layout(8),
        row in any::<prop::sample::Index>(),
        column in 0usize..2,
        garbage in not_a_number(),
    ) {
        let values: Vec<Vec<f64>> = values.iter().map(|r| vec![r[0], r[1].abs()]).collect();
        let rows = as_rows(&["t", "f"], &values);
        let (bytes, _) = write(&rows, &layout);
        let read = read_force(&bytes)?;
        prop_assert!(read.is_some(), "{:?}", String::from_utf8_lossy(&bytes));
        let read = read.unwrap();
        for r in &values {
            prop_assert_eq!(read.at(r[0]), r[1]);
        }
        let mut rows = rows;
        let r = 1 + row.index(values.len());
        rows[r][column] = garbage;
        let (bytes, lines) = write(&rows, &layout);
        let message = SampledForce::from_csv_reader(bytes.as_slice()).map(|_| ()).unwrap_err().to_string();
        let expected = format!("line {}, column {}", lines[r], column + 1);
        prop_assert!(message.starts_with(&expected), "{message} (expected {expected})");
    }
}
