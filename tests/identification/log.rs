//! Property tests of the joint-log reader (`JointLog::from_csv_reader`): random and mutated
//! input never panics and every error names a line that exists; rows with NaN or infinite
//! values, duplicated time stamps and times out of order, inserted into a valid log, are
//! dropped and counted exactly, and the samples kept are the original ones.
//!
//! The seed is fixed so that every run checks the same cases; set `PROPTEST_RNG_SEED` (and
//! `PROPTEST_CASES`) to explore others.

use proptest::prelude::*;

use armdyn::identification::log::{CsvError, JointLog, LogReport, LogSettings};
use armdyn::model::JointVector;

use crate::properties::{config, line_count, named_line};

/// What a successful read must satisfy whatever the input.
fn check_log<const N: usize>(
    log: &JointLog<N>,
    report: &LogReport,
    settings: &LogSettings,
    lines: usize,
) -> Result<(), TestCaseError> {
    let n = log.len();
    prop_assert!(n >= settings.min_samples);
    prop_assert_eq!(log.q.len(), n);
    prop_assert_eq!(log.tau.len(), n);
    prop_assert_eq!(log.lines.len(), n);
    prop_assert_eq!(
        log.qd.as_ref().map(Vec::len),
        report.velocities.then_some(n)
    );
    prop_assert!(
        log.t.windows(2).all(|w| w[0] < w[1]),
        "times not increasing"
    );
    prop_assert!(
        log.lines.windows(2).all(|w| w[0] < w[1]),
        "lines not increasing"
    );
    prop_assert!(log.lines.iter().all(|l| (1..=lines).contains(l)));
    let finite = |v: &[JointVector<N>]| v.iter().all(|x| x.iter().all(|y| y.is_finite()));
    prop_assert!(log.t.iter().all(|t| t.is_finite()));
    prop_assert!(finite(&log.q) && finite(&log.tau));
    prop_assert!(log.qd.as_deref().is_none_or(finite));
    prop_assert_eq!(report.rows_kept, n);
    prop_assert_eq!(report.rows_read, n + report.dropped());
    prop_assert!(report.median_interval > 0.0 && report.median_interval.is_finite());
    prop_assert!(report.min_interval <= report.median_interval);
    prop_assert!(report.median_interval <= report.max_interval);
    prop_assert!(report.jumps.len() <= report.jump_count.min(20));
    for d in [
        &report.non_finite,
        &report.duplicate_time,
        &report.backward_time,
    ] {
        prop_assert_eq!(d.lines.len(), d.count.min(5));
    }
    let _ = report.to_string();
    Ok(())
}

/// Reads `bytes`; an error must name a line of the input.
fn read<const N: usize>(
    bytes: &[u8],
    settings: &LogSettings,
) -> Result<Result<(JointLog<N>, LogReport), CsvError>, TestCaseError> {
    let result = JointLog::<N>::from_csv_reader(bytes, settings);
    match &result {
        Ok((log, report)) => check_log(log, report, settings, line_count(bytes))?,
        Err(e) => {
            let message = e.to_string();
            prop_assert!(
                !matches!(e, CsvError::Read { .. }),
                "only an I/O error has no line: {message}"
            );
            prop_assert!(message.contains("line "), "error without a line: {message}");
            let line = named_line(&message);
            prop_assert!(line.is_some(), "error without a line: {message}");
            let line = line.unwrap_or(0);
            prop_assert!(
                (1..=line_count(bytes)).contains(&line),
                "line {line} of {}: {message}",
                line_count(bytes)
            );
        }
    }
    Ok(result)
}

/// Reads `bytes` for the checks of [`read`] only.
fn check<const N: usize>(bytes: &[u8], settings: &LogSettings) -> Result<(), TestCaseError> {
    read::<N>(bytes, settings).map(|_| ())
}

fn loose() -> LogSettings {
    LogSettings {
        min_samples: 2,
        ..LogSettings::default()
    }
}

/// One sample of a 3-joint robot.
#[derive(Clone, Debug)]
struct Sample {
    t: f64,
    q: [f64; 3],
    qd: [f64; 3],
    tau: [f64; 3],
}

/// `rows` samples at strictly increasing times (from a random start, random steps).
fn samples(rows: std::ops::Range<usize>) -> impl Strategy<Value = Vec<Sample>> {
    (
        -100.0f64..100.0,
        prop::collection::vec(
            (
                1e-4f64..1e-2,
                prop::array::uniform3(-3.0f64..3.0),
                prop::array::uniform3(-10.0f64..10.0),
                prop::array::uniform3(-200.0f64..200.0),
            ),
            rows,
        ),
    )
        .prop_map(|(start, rows)| {
            let mut t = start;
            rows.into_iter()
                .map(|(dt, q, qd, tau)| {
                    t += dt;
                    Sample { t, q, qd, tau }
                })
                .collect()
        })
}

/// The columns of a 3-joint log, in the standard order.
fn columns(velocities: bool) -> Vec<String> {
    let mut c = vec!["t".to_string()];
    c.extend((1..=3).map(|i| format!("q{i}")));
    if velocities {
        c.extend((1..=3).map(|i| format!("qd{i}")));
    }
    c.extend((1..=3).map(|i| format!("tau{i}")));
    c
}

/// The fields of a sample in the standard column order.
fn fields(s: &Sample, velocities: bool) -> Vec<String> {
    let mut f = vec![s.t.to_string()];
    f.extend(s.q.iter().map(f64::to_string));
    if velocities {
        f.extend(s.qd.iter().map(f64::to_string));
    }
    f.extend(s.tau.iter().map(f64::to_string));
    f
}

/// `fields` put in the file's column order: field i of the file holds column `order[i]`.
fn ordered(fields: &[String], order: &[usize]) -> String {
    order
        .iter()
        .map(|&c| fields.get(c).map_or("", String::as_str))
        .collect::<Vec<_>>()
        .join(",")
}

/// A field of a random row: mostly a number.
fn field() -> impl Strategy<Value = String> {
    prop_oneof![
        12 => (-1e3f64..1e3).prop_map(|x| x.to_string()),
        6 => (0u32..50).prop_map(|x| (f64::from(x) * 0.01).to_string()),
        1 => Just("NaN".to_string()),
        1 => Just("-inf".to_string()),
        1 => Just("1e999".to_string()),
        1 => Just("x".to_string()),
        1 => Just(String::new()),
        1 => Just("1e-320".to_string()),
        1 => Just("-1e308".to_string()),
        1 => Just("1e308".to_string()),
    ]
}

/// An edit of a log's text.
#[derive(Clone, Debug)]
enum Edit {
    DeleteChar(prop::sample::Index),
    InsertChar(prop::sample::Index, char),
    SwapLines(prop::sample::Index, prop::sample::Index),
    DuplicateLine(prop::sample::Index),
    NanField(prop::sample::Index, prop::sample::Index),
}

fn edit() -> impl Strategy<Value = Edit> {
    let inserted = prop::sample::select(",.-e0123456789naNinf \n#".chars().collect::<Vec<_>>());
    prop_oneof![
        any::<prop::sample::Index>().prop_map(Edit::DeleteChar),
        (any::<prop::sample::Index>(), inserted).prop_map(|(i, c)| Edit::InsertChar(i, c)),
        (any::<prop::sample::Index>(), any::<prop::sample::Index>())
            .prop_map(|(a, b)| Edit::SwapLines(a, b)),
        any::<prop::sample::Index>().prop_map(Edit::DuplicateLine),
        (any::<prop::sample::Index>(), any::<prop::sample::Index>())
            .prop_map(|(l, f)| Edit::NanField(l, f)),
    ]
}

/// Applies `edit` to `text` (ASCII, so bytes are characters).
fn apply(text: &str, edit: &Edit) -> String {
    let mut lines: Vec<String> = text.split('\n').map(str::to_string).collect();
    match edit {
        Edit::DeleteChar(at) => {
            let mut s = text.to_string();
            if !s.is_empty() {
                s.remove(at.index(s.len()));
            }
            return s;
        }
        Edit::InsertChar(at, c) => {
            let mut s = text.to_string();
            s.insert(at.index(s.len() + 1), *c);
            return s;
        }
        Edit::SwapLines(a, b) => {
            let (a, b) = (a.index(lines.len()), b.index(lines.len()));
            lines.swap(a, b);
        }
        Edit::DuplicateLine(at) => {
            let at = at.index(lines.len());
            let copy = lines[at].clone();
            lines.insert(at, copy);
        }
        Edit::NanField(line, field) => {
            let at = line.index(lines.len());
            let mut f: Vec<String> = lines[at].split(',').map(str::to_string).collect();
            let k = field.index(f.len());
            f[k] = "NaN".to_string();
            lines[at] = f.join(",");
        }
    }
    lines.join("\n")
}

/// A row inserted into a valid log.
#[derive(Clone, Debug)]
enum Defect {
    /// NaN or an infinity in one used column (its time may be anything).
    NonFinite {
        column: prop::sample::Index,
        value: f64,
        t: f64,
    },
    /// The time of the previous original sample again, other values.
    Duplicate,
    /// A time before the previous original sample's: `t - (|t| + 1) * back`.
    Backward { back: f64 },
}

fn defect() -> impl Strategy<Value = Defect> {
    prop_oneof![
        (
            any::<prop::sample::Index>(),
            prop_oneof![Just(f64::NAN), Just(f64::INFINITY), Just(f64::NEG_INFINITY)],
            prop_oneof![Just(f64::NAN), -1e3f64..1e3],
        )
            .prop_map(|(column, value, t)| Defect::NonFinite { column, value, t }),
        Just(Defect::Duplicate),
        (0.01f64..10.0).prop_map(|back| Defect::Backward { back }),
    ]
}

proptest! {
    #![proptest_config(config(256, 15))]

    #[test]
    fn random_bytes_never_panic(bytes in prop::collection::vec(any::<u8>(), 0..400)) {
        check::<2>(&bytes, &LogSettings::default())?;
        check::<2>(&bytes, &loose())?;
        check::<2>(&bytes, &LogSettings { min_samples: 0, jump_threshold: f64::NAN })?;
    }

    #[test]
    fn random_text_never_panics(text in "[ -~\r\n\t\u{feff}]{0,300}") {
        check::<2>(text.as_bytes(), &LogSettings::default())?;
        check::<2>(text.as_bytes(), &loose())?;
    }

    /// A valid header, then rows of random number-like text: the header rules are reached.
    #[test]
    fn random_rows_never_panic(
        header in prop::sample::select(vec![
            "t,q1,q2,tau1,tau2",
            "tau2,q1,t,qd1,tau1,qd2,q2,x",
            "t,q1,q2,tau1,tau2,qd1",
        ]),
        body in "[0-9.,e\\-naNif# \n\r]{0,400}",
    ) {
        let text = format!("{header}\n{body}");
        check::<2>(text.as_bytes(), &LogSettings { min_samples: 0, ..LogSettings::default() })?;
        check::<2>(text.as_bytes(), &loose())?;
    }

    /// A valid header, then rows of random fields (mostly numbers, some NaN, infinities,
    /// words, empty fields; mostly the right count; comments and blank lines): the row rules
    /// and the statistics are reached.
    #[test]
    fn random_fields_never_panic(
        header in prop::sample::select(vec![
            "t,q1,q2,tau1,tau2",
            "tau2,q1,t,qd1,tau1,qd2,q2,x",
        ]),
        rows in prop::collection::vec(
            (prop::collection::vec(field(), 10), prop::sample::select(vec![0i32, 0, 0, 0, 0, 0, 0, 0, 0, -1, 1, 3])),
            0..60,
        ),
        threshold in prop_oneof![Just(0.2), -1.0f64..1e3, Just(f64::NAN), Just(f64::INFINITY)],
        min_samples in 0usize..10,
        well_formed in any::<bool>(),
    ) {
        let count = header.split(',').count();
        let mut text = format!("{header}\n");
        for (fields, delta) in &rows {
            match delta {
                3 => text.push_str("# a comment\n\n"),
                _ => {
                    // Half the cases have only numbers (NaN and infinities included) and the
                    // right field count, so that the repairs and the statistics are reached.
                    let delta = if well_formed { 0 } else { *delta };
                    let n = usize::try_from(count as i32 + delta).unwrap_or(0);
                    let fields: Vec<&str> = fields
                        .iter()
                        .take(n)
                        .map(|f| if well_formed && f.parse::<f64>().is_err() { "0" } else { f })
                        .collect();
                    text.push_str(&fields.join(","));
                    text.push('\n');
                }
            }
        }
        let settings = LogSettings { min_samples, jump_threshold: threshold };
        check::<2>(text.as_bytes(), &settings)?;
    }

    /// A valid 3-joint log edited at random (characters deleted or inserted, lines swapped or
    /// duplicated, fields replaced by NaN): read, or refused by an error naming a line.
    #[test]
    fn edited_logs_are_read_or_refused_with_a_line(
        rows in samples(100..140),
        velocities in any::<bool>(),
        crlf in any::<bool>(),
        edits in prop::collection::vec(edit(), 1..6),
    ) {
        let mut text = columns(velocities).join(",");
        text.push('\n');
        for s in &rows {
            text.push_str(&fields(s, velocities).join(","));
            text.push('\n');
        }
        prop_assert!(read::<3>(text.as_bytes(), &LogSettings::default())?.is_ok());
        for e in &edits {
            text = apply(&text, e);
        }
        if crlf {
            text = text.replace('\n', "\r\n");
        }
        check::<3>(text.as_bytes(), &LogSettings::default())?;
        check::<3>(text.as_bytes(), &loose())?;
    }

    /// Rows with NaN or infinite values, duplicated time stamps and times out of order
    /// inserted into a valid log (columns in any order, with or without velocities): each is
    /// dropped and counted for its reason, and the samples kept are the original ones, on
    /// their lines.
    #[test]
    fn inserted_defects_are_dropped_and_counted(
        rows in samples(100..160),
        velocities in any::<bool>(),
        shuffle in any::<bool>(),
        order in Just((0..10).collect::<Vec<usize>>()).prop_shuffle(),
        defects in prop::collection::vec((any::<prop::sample::Index>(), defect()), 0..30),
        noise in prop::array::uniform10(-5.0f64..5.0),
    ) {
        let names = columns(velocities);
        let order: Vec<usize> = if shuffle {
            order.into_iter().filter(|&c| c < names.len()).collect()
        } else {
            (0..names.len()).collect()
        };
        // defects[i] goes after original row `at` (a non-finite row may also come first).
        let mut after: Vec<Vec<&Defect>> = vec![Vec::new(); rows.len() + 1];
        for (at, d) in &defects {
            let at = match d {
                Defect::NonFinite { .. } => at.index(rows.len() + 1),
                _ => 1 + at.index(rows.len()),
            };
            after[at].push(d);
        }
        let mut text = ordered(&names, &order);
        text.push('\n');
        let mut line = 1;
        let (mut lines, mut nan_lines, mut dup_lines, mut back_lines) =
            (Vec::new(), Vec::new(), Vec::new(), Vec::new());
        for k in 0..=rows.len() {
            if k > 0 {
                let s = &rows[k - 1];
                text.push_str(&ordered(&fields(s, velocities), &order));
                text.push('\n');
                line += 1;
                lines.push(line);
            }
            for d in &after[k] {
                let previous = if k > 0 { rows[k - 1].t } else { 0.0 };
                let mut values: Vec<String> = noise.iter().take(names.len()).map(f64::to_string).collect();
                match d {
                    Defect::NonFinite { column, value, t } => {
                        values[0] = t.to_string();
                        values[column.index(names.len())] = value.to_string();
                        nan_lines.push(line + 1);
                    }
                    Defect::Duplicate => {
                        values[0] = previous.to_string();
                        dup_lines.push(line + 1);
                    }
                    Defect::Backward { back } => {
                        values[0] = (previous - (previous.abs() + 1.0) * back).to_string();
                        back_lines.push(line + 1);
                    }
                }
                text.push_str(&ordered(&values, &order));
                text.push('\n');
                line += 1;
            }
        }
        let result = read::<3>(text.as_bytes(), &LogSettings::default())?;
        prop_assert!(result.is_ok(), "{:?}", result.as_ref().err());
        let Ok((log, report)) = result else { unreachable!() };
        prop_assert_eq!(report.non_finite.count, nan_lines.len());
        prop_assert_eq!(report.duplicate_time.count, dup_lines.len());
        prop_assert_eq!(report.backward_time.count, back_lines.len());
        prop_assert_eq!(&report.non_finite.lines[..], &nan_lines[..nan_lines.len().min(5)]);
        prop_assert_eq!(&report.duplicate_time.lines[..], &dup_lines[..dup_lines.len().min(5)]);
        prop_assert_eq!(&report.backward_time.lines[..], &back_lines[..back_lines.len().min(5)]);
        prop_assert_eq!(report.rows_read, rows.len() + defects.len());
        prop_assert_eq!(report.velocities, velocities);
        prop_assert!(report.extra_columns.is_empty());
        prop_assert_eq!(log.len(), rows.len());
        prop_assert_eq!(&log.lines, &lines);
        for (k, s) in rows.iter().enumerate() {
            prop_assert_eq!(log.t[k], s.t);
            prop_assert_eq!(log.q[k].as_slice(), &s.q[..]);
            prop_assert_eq!(log.tau[k].as_slice(), &s.tau[..]);
            if let Some(qd) = &log.qd {
                prop_assert_eq!(qd[k].as_slice(), &s.qd[..]);
            }
        }
        // Written back and read again: the same samples (on the lines of the new file).
        let mut written = Vec::new();
        log.write_csv(&mut written).map_err(|e| TestCaseError::fail(e.to_string()))?;
        let again = read::<3>(&written, &LogSettings::default())?;
        prop_assert!(again.is_ok());
        let Ok((again, _)) = again else { unreachable!() };
        prop_assert_eq!(&again.t, &log.t);
        prop_assert_eq!(&again.q, &log.q);
        prop_assert_eq!(&again.qd, &log.qd);
        prop_assert_eq!(&again.tau, &log.tau);
    }
}
