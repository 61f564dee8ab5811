//! Tests of the joint-log reader: repairs, refusals and the report.

use armdyn::identification::log::{CsvError, JointLog, LogReport, LogSettings};
use armdyn::identification::log_report::Jump;
use armdyn::model::JointVector;

fn settings(min_samples: usize) -> LogSettings {
    LogSettings {
        min_samples,
        ..LogSettings::default()
    }
}

fn read<const N: usize>(text: &str, min: usize) -> Result<(JointLog<N>, LogReport), CsvError> {
    JointLog::<N>::from_csv_reader(text.as_bytes(), &settings(min))
}

fn error(text: &str, min: usize) -> String {
    read::<2>(text, min).unwrap_err().to_string()
}

/// A clean 2-joint log of `n` rows at 1 kHz (header `t,q1,q2,tau1,tau2`).
fn clean(n: usize) -> String {
    let mut s = String::from("t,q1,q2,tau1,tau2\n");
    for k in 0..n {
        s.push_str(&row(k));
    }
    s
}

fn row(k: usize) -> String {
    let t = k as f64 * 1e-3;
    format!(
        "{t},{},{},{},{}\n",
        (3.0 * t).sin(),
        -0.5 * t,
        1.0 + t,
        (2.0 * t).cos()
    )
}

#[test]
fn default_settings() {
    let s = LogSettings::default();
    assert_eq!((s.min_samples, s.jump_threshold), (100, 0.2));
}

#[test]
fn clean_log_round_trips_exactly() {
    let text = clean(150);
    let (log, report) = read::<2>(&text, 100).unwrap();
    assert_eq!(log.len(), 150);
    assert!(!log.is_empty());
    assert_eq!(log.lines, (2..152).collect::<Vec<_>>());
    assert_eq!(log.t[7], 7.0 * 1e-3);
    assert_eq!(log.q[7][0], (3.0 * (7.0 * 1e-3f64)).sin());
    assert!(log.qd.is_none());
    assert_eq!(
        (report.rows_read, report.rows_kept, report.dropped()),
        (150, 150, 0)
    );
    assert!((report.median_interval - 1e-3).abs() < 1e-12);
    assert!((report.rate - 1000.0).abs() < 1e-6);
    assert!(report.jitter < 1e-12);
    assert!(report.gaps.is_empty() && report.jumps.is_empty());
    assert!(!report.velocities && report.extra_columns.is_empty());
    let mut written = Vec::new();
    log.write_csv(&mut written).unwrap();
    let written = String::from_utf8(written).unwrap();
    assert_eq!(written, text);
    let (again, _) = read::<2>(&written, 100).unwrap();
    assert_eq!(again, log);
}

#[test]
fn velocities_and_columns_in_another_order_with_extras() {
    let mut text = String::from(" tau2 , mode,qd2,q1,t,qd1,tau1,q2 ,temp\n");
    for k in 0..5 {
        let t = k as f64 * 0.01;
        text.push_str(&format!(
            "{},idle,{},{},{t},{},{},{},x\n",
            20 + k,
            10 + k,
            k,
            30 + k,
            40 + k,
            50 + k
        ));
    }
    let (log, report) = read::<2>(&text, 5).unwrap();
    assert_eq!(log.t, [0.0, 0.01, 0.02, 0.03, 0.04]);
    assert_eq!(log.q[1], JointVector::<2>::new(1.0, 51.0));
    assert_eq!(
        log.qd.as_ref().unwrap()[1],
        JointVector::<2>::new(31.0, 11.0)
    );
    assert_eq!(log.tau[1], JointVector::<2>::new(41.0, 21.0));
    assert!(report.velocities);
    assert_eq!(report.extra_columns, ["mode", "temp"]);
    // Written back in the standard order, with velocities.
    let mut out = Vec::new();
    log.write_csv(&mut out).unwrap();
    let out = String::from_utf8(out).unwrap();
    assert!(out.starts_with("t,q1,q2,qd1,qd2,tau1,tau2\n0,0,50,30,10,40,20\n"));
    assert_eq!(read::<2>(&out, 5).unwrap().0.qd, log.qd);
    // Some velocities but not all: refused.
    let e = error("t,q1,q2,tau1,tau2,qd1\n", 0);
    assert!(e.starts_with("line 1: missing column `qd2`"), "{e}");
}

#[test]
fn non_finite_rows_are_dropped_and_reported() {
    let mut text = clean(120);
    text.push_str("0.5,NaN,0,0,0\n0.6,0,0,inf,0\n0.7,0,0,0,-infinity\nnan,0,0,0,0\n");
    text.push_str("0.8,0,0,0,1e999\n0.9,0,0,0,NAN\n");
    let (log, report) = read::<2>(&text, 100).unwrap();
    assert_eq!(log.len(), 120);
    assert_eq!(report.non_finite.count, 6);
    assert_eq!(report.non_finite.lines, [122, 123, 124, 125, 126]);
    assert_eq!(report.rows_read, 126);
    assert!(report
        .to_string()
        .contains("6 with NaN or infinite values (lines 122, 123, 124, 125, 126, ...)"));
}

#[test]
fn duplicate_and_backward_stamps_are_dropped() {
    let mut text = String::from("t,q1,q2,tau1,tau2\n");
    for k in 0..110 {
        text.push_str(&row(k));
        let t = k as f64 * 1e-3;
        if k == 10 {
            text.push_str(&format!("{t},9,9,9,9\n")); // line 13: the same stamp again
        }
        if k == 20 {
            text.push_str(&format!("0.005,9,9,9,9\n{t},8,8,8,8\n")); // lines 24, 25
        }
    }
    let (log, report) = read::<2>(&text, 100).unwrap();
    assert_eq!(log.len(), 110);
    assert_eq!(log.t, (0..110).map(|k| k as f64 * 1e-3).collect::<Vec<_>>());
    let t10 = 10.0f64 * 1e-3;
    assert_eq!(
        log.q[10],
        JointVector::<2>::new((3.0 * t10).sin(), -0.5 * t10)
    );
    assert_eq!(report.duplicate_time.count, 2);
    assert_eq!(report.duplicate_time.lines, [13, 25]);
    assert_eq!(report.backward_time.count, 1);
    assert_eq!(report.backward_time.lines, [24]);
    assert_eq!(report.dropped(), 3);
    assert!(report.jumps.is_empty(), "dropped rows make no jumps");
}

#[test]
fn gaps_are_reported_with_the_missing_samples() {
    let mut text = String::from("t,q1,q2,tau1,tau2\n");
    for k in (0..200).filter(|k| !(50..53).contains(k) && *k != 100) {
        text.push_str(&row(k));
    }
    let (log, report) = read::<2>(&text, 100).unwrap();
    assert_eq!(log.len(), 196);
    assert_eq!(report.gaps.len(), 2);
    let g = &report.gaps[0];
    assert_eq!(g.line, 52); // sample 53 follows sample 49 (line 51)
    assert_eq!(g.start, 49.0 * 1e-3);
    assert!((g.length - 4e-3).abs() < 1e-12);
    assert_eq!(g.missing, 3);
    assert_eq!(report.gaps[1].missing, 1);
    assert_eq!(report.gap_samples, 4);
    assert!((report.max_interval - 4e-3).abs() < 1e-12);
    assert!(
        report.jitter < 1e-12,
        "gaps are not jitter: {}",
        report.jitter
    );
    assert!(report
        .to_string()
        .contains("gaps: 2 (4 samples missing): line 52 at 0.049 s"));
}

#[test]
fn jumps_are_reported_not_dropped() {
    let mut text = String::from("t,q1,q2,tau1,tau2\n");
    for k in 0..100 {
        let q2 = if k >= 40 { 0.5 } else { 0.0 };
        text.push_str(&format!("{},0,{q2},0,0\n", k as f64 * 0.01));
    }
    let (log, report) = read::<2>(&text, 100).unwrap();
    assert_eq!(log.len(), 100);
    assert_eq!(report.jump_count, 1);
    assert_eq!(
        report.jumps,
        [Jump {
            line: 42,
            joint: 2,
            size: 0.5
        }]
    );
    let tight = LogSettings {
        min_samples: 100,
        jump_threshold: 0.6,
    };
    let (_, report) = JointLog::<2>::from_csv_reader(text.as_bytes(), &tight).unwrap();
    assert_eq!(report.jump_count, 0);
    // Many jumps: 20 kept, all counted.
    let mut text = String::from("t,q1,tau1\n");
    for k in 0..100 {
        text.push_str(&format!("{k},{},0\n", k % 2));
    }
    let (_, report) = read::<1>(&text, 100).unwrap();
    assert_eq!((report.jumps.len(), report.jump_count), (20, 99));
    assert!(report.to_string().contains("; and 94 more"));
}

#[test]
fn header_errors_name_the_line_and_column() {
    let e = error("t,q1,tau1,tau2\n0,0,0,0\n", 0);
    assert!(e.starts_with("line 1: missing column `q2`"), "{e}");
    let e = error("# from the controller\n\nt,q1,q2,tau1,tau2\n", 0);
    assert!(!e.contains("missing"), "{e}");
    let e = error("# comment\nt,q1,q2,tau1\n", 0);
    assert!(e.starts_with("line 2: missing column `tau2`"), "{e}");
    let e = error("t,q1,q2,q1,tau1,tau2\n", 0);
    assert_eq!(
        e,
        "line 1, column 4 (`q1`): duplicated column (also column 2)"
    );
    let e = error("t,q1,q2,tau1,tau2,x, x \n", 0);
    assert!(e.starts_with("line 1, column 7 (`x`): duplicated"), "{e}");
    // Names are case-sensitive.
    let e = error("T,q1,q2,tau1,tau2\n", 0);
    assert!(e.starts_with("line 1: missing column `t`"), "{e}");
    assert!(error("", 0).starts_with("line 1: the input ends before the header"));
    assert!(error("# a\n\n#b\n", 0).starts_with("line 4: the input ends before the header"));
}

#[test]
fn row_errors_name_the_line_and_column() {
    let mut text = clean(10);
    text.push_str("0.5,0,x,0,0\n");
    assert_eq!(
        error(&text, 0),
        "line 12, column 3 (`q2`): `x` is not a number"
    );
    let mut text = clean(10);
    text.push_str("\n0.5,0,,0,0\n");
    assert_eq!(
        error(&text, 0),
        "line 13, column 3 (`q2`): `` is not a number"
    );
    let mut text = clean(3);
    text.push_str("0.5,0,0,0\n");
    assert_eq!(
        error(&text, 0),
        "line 5, column 5: missing column `tau2` (expected 5 columns `t,q1,q2,tau1,tau2`, found 4)"
    );
    let mut text = clean(3);
    text.push_str("0.5,0,0,0,0,0\n");
    assert_eq!(
        error(&text, 0),
        "line 5: 6 columns, expected 5 (`t,q1,q2,tau1,tau2`)"
    );
    // Extra columns are not read.
    let (log, _) = read::<1>("t,q1,tau1,note\n0,1,2,ok\n1,1,2,-\n", 2).unwrap();
    assert_eq!(log.len(), 2);
    let bad =
        JointLog::<2>::from_csv_reader(&b"t,q1,q2,tau1,tau2\n0,0,\xFF,0,0\n"[..], &settings(0));
    assert_eq!(
        bad.unwrap_err().to_string(),
        "line 2: not UTF-8 text (byte 5 of the line is 0xFF); save the file as UTF-8"
    );
}

#[test]
fn too_few_samples_are_refused() {
    let mut text = clean(99);
    text.push_str("1,NaN,0,0,0\n0.05,0,0,0,0\n");
    let e = error(&text, 100);
    assert_eq!(
        e,
        "line 103: the log ends with 99 usable samples of 101 rows read (2 dropped: 1 not \
         finite, 0 duplicated time stamps, 1 out of order); at least 100 are needed"
    );
    assert!(read::<2>(&clean(100), 100).is_ok());
    // One sample: no interval.
    let e = error(&clean(1), 1);
    assert!(e.starts_with("line 2: the median interval"), "{e}");
    let e = error("t,q1,q2,tau1,tau2\n", 0);
    assert!(e.starts_with("line 1: the median interval"), "{e}");
    // Times too far apart to subtract.
    let e = error("t,q1,q2,tau1,tau2\n-1e308,0,0,0,0\n1e308,0,0,0,0\n", 2);
    assert!(e.contains("is inf s"), "{e}");
}

#[test]
fn comments_and_blank_lines_are_skipped() {
    let plain = read::<2>(&clean(100), 100).unwrap().0;
    let mut text = String::from("# robot: test\n\n");
    for (k, l) in clean(100).lines().enumerate() {
        text.push_str(l);
        text.push('\n');
        if k % 10 == 3 {
            text.push_str("   \n  # a comment, with commas\n");
        }
    }
    let (log, report) = read::<2>(&text, 100).unwrap();
    assert_eq!((log.t, log.q, log.tau), (plain.t, plain.q, plain.tau));
    assert_eq!(report.rows_read, 100);
    assert_eq!(log.lines[0], 4);
}

#[test]
fn byte_order_mark_and_crlf_are_accepted() {
    let plain = read::<2>(&clean(100), 100).unwrap().0;
    let crlf = clean(100).replace('\n', "\r\n");
    assert_eq!(read::<2>(&crlf, 100).unwrap().0, plain);
    assert_eq!(read::<2>(&format!("\u{feff}{crlf}"), 100).unwrap().0, plain);
    assert_eq!(
        read::<2>(&clean(100).replace('\n', "\r"), 100).unwrap().0,
        plain
    );
    let mut bad = format!("\u{feff}{crlf}");
    bad.push_str("\r\n0.5,0,0,x,0\r\n");
    assert!(error(&bad, 0).starts_with("line 103, column 4 (`tau1`)"));
}

#[test]
fn slice_time_keeps_the_lines() {
    let (log, _) = read::<2>(&clean(100), 100).unwrap();
    let part = log.slice_time(0.0105, 0.0195);
    assert_eq!(part.len(), 9);
    assert_eq!(part.t[0], log.t[11]);
    assert_eq!(part.lines, (13..22).collect::<Vec<_>>());
    assert_eq!(part.tau[0], log.tau[11]);
    assert!(log.slice_time(1.0, 0.0).is_empty());
    assert!(log.slice_time(f64::NAN, 1.0).is_empty());
    assert_eq!(log.slice_time(f64::NEG_INFINITY, f64::INFINITY), log);
    // Inconsistent public fields: no panic.
    let mut odd = log.clone();
    odd.q.truncate(3);
    odd.qd = Some(vec![]);
    assert!(odd.slice_time(0.0, 1.0).is_empty());
    let mut out = Vec::new();
    odd.write_csv(&mut out).unwrap();
    assert_eq!(out, b"t,q1,q2,qd1,qd2,tau1,tau2\n");
}

#[test]
fn report_display() {
    let mut text = String::from("t,q1,tau1,temp\n");
    for k in 0..120 {
        let t = k as f64 * 0.002;
        if k == 30 {
            text.push_str("0.06,NaN,0,40\n");
            continue;
        }
        if (60..64).contains(&k) {
            continue;
        }
        let q = if k >= 90 { 1.0 } else { 0.0 };
        text.push_str(&format!("{t},{q},0.5,40\n"));
        if k == 10 {
            text.push_str(&format!("{t},{q},0.5,40\n"));
        }
    }
    let (_, report) = read::<1>(&text, 100).unwrap();
    let shown = report.to_string();
    assert_eq!(
        shown,
        "joint log: 117 rows read, 115 kept, 2 dropped; velocities absent\n\
         sampling: median interval 0.002 s (500 Hz), min 0.002 s, max 0.01 s, jitter 0 s (gaps excluded)\n\
         dropped: 1 with NaN or infinite values (line 33)\n\
         dropped: 1 with a duplicated time stamp (line 13)\n\
         gaps: 2 (5 samples missing): line 34 at 0.058 s for 0.004 s (1 missing); line 63 at 0.118 s for 0.01 s (4 missing)\n\
         jumps over 0.2 per sample: 1 (not dropped): line 89 joint 1 by 1\n\
         extra columns (ignored): `temp`"
    );
}
