//! `armdyn identify --log` end to end: a simulated log written by `--write-log` is identified,
//! its description and excitation written; a log like a real robot's (`--break-link`,
//! `--unmodelled-friction`) is identified by either consistent solver, the solver's status,
//! evaluations and budget and every stage's time stated in the text and the JSON; a log it
//! cannot use, or a bad `--write-log` option, is refused naming it, with a non-zero exit and
//! nothing written.

use crate::common::{armdyn, s, stderr, tmp};

/// The prefix of this file's temporary folders.
const AREA: &str = "idlog";

#[test]
fn a_written_log_is_identified_and_becomes_a_description() {
    let dir = tmp(AREA, "roundtrip");
    let log = dir.join("log.csv");
    let o = armdyn(&[
        "identify",
        "--robot",
        "scara",
        "--friction",
        "on",
        "--noise-pct",
        "1",
        "--evaluations",
        "200",
        "--write-log",
        s(&log),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    // `--robot` takes `-` for `_`, as every command does.
    let hyphenated = armdyn(&[
        "identify",
        "--robot",
        "scara-mdh",
        "--evaluations",
        "200",
        "--write-log",
        s(&dir.join("mdh.csv")),
    ]);
    assert!(hyphenated.status.success(), "{}", stderr(&hyphenated));
    let (out, robots) = (dir.join("out"), dir.join("robots"));
    let o = armdyn(&[
        "identify",
        "--robot",
        "scara",
        "--log",
        s(&log),
        "--out",
        s(&out),
        "--write-description",
        s(&robots),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(text.contains("physically consistent"), "{text}");
    assert!(text.contains("dropped"), "{text}");
    let v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("identification.json")).unwrap())
            .unwrap();
    assert_eq!(v["physically_consistent"], true);
    for f in ["validation_torques.svg", "friction.svg"] {
        assert!(std::fs::read_to_string(out.join(f))
            .unwrap()
            .starts_with("<svg"));
    }
    let toml = std::fs::read_to_string(robots.join("scara_identified.toml")).unwrap();
    assert!(toml.contains("scara_identified.urdf"), "{toml}");
    assert!(
        std::fs::read_to_string(robots.join("scara_identified.urdf"))
            .unwrap()
            .contains("<robot")
    );
}

#[test]
fn the_excitation_is_written_for_the_robot_to_run() {
    let dir = tmp(AREA, "excitation");
    let out = dir.join("exc");
    let o = armdyn(&[
        "identify",
        "--robot",
        "ur5",
        "--excitation-only",
        "--evaluations",
        "100",
        "--out",
        s(&out),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let csv = std::fs::read_to_string(out.join("excitation.csv")).unwrap();
    let mut lines = csv.lines().filter(|l| !l.starts_with('#'));
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    assert_eq!(header.len(), 1 + 3 * 6, "{header:?}");
    assert_eq!(header[0], "t");
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    assert!(rows.len() > 100);
    // Uniform time stamps, and the positions inside the UR5's limits (+-2 pi).
    let dt = rows[1][0] - rows[0][0];
    assert!(rows
        .windows(2)
        .all(|w| ((w[1][0] - w[0][0]) - dt).abs() < 1e-9));
    assert!(rows.iter().all(|r| r[1..7]
        .iter()
        .all(|q| q.abs() <= 2.0 * std::f64::consts::PI)));
}

#[test]
fn a_log_like_a_real_robots_is_fitted_and_the_stages_timed() {
    let dir = tmp(AREA, "real");
    let log = dir.join("log.csv");
    let o = armdyn(&[
        "identify",
        "--robot",
        "scara",
        "--friction",
        "on",
        "--noise-pct",
        "1",
        "--evaluations",
        "200",
        "--log-seconds",
        "6",
        "--lost-pct",
        "2.5",
        "--break-link",
        "2",
        "--unmodelled-friction",
        "--write-log",
        s(&log),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(text.contains("6 s of the 10 s excitation"), "{text}");
    assert!(
        text.contains("link 2's inertia breaking the triangle inequality"),
        "{text}"
    );
    assert!(text.contains("Stribeck"), "{text}");
    for solver in ["barrier", "log-cholesky"] {
        let out = dir.join(solver);
        let o = armdyn(&[
            "identify",
            "--robot",
            "scara",
            "--log",
            s(&log),
            "--holdout",
            "0.3",
            "--consistent-solver",
            solver,
            "--out",
            s(&out),
        ]);
        assert!(o.status.success(), "{}", stderr(&o));
        let text = String::from_utf8_lossy(&o.stdout);
        assert!(
            text.contains(&format!("consistent fit ({solver}): ")),
            "{text}"
        );
        assert!(text.contains("of 4000 evaluations"), "{text}");
        assert!(text.contains("x the unconstrained fit's"), "{text}");
        for stage in [
            "time: reading",
            "filtering",
            "linear fit",
            "consistent fit",
            "validation",
            "figures",
            "; total",
        ] {
            assert!(text.contains(stage), "{stage} not in {text}");
        }
        // Not a terminal: no progress drawn on stderr.
        assert_eq!(stderr(&o), "", "{solver}");
        let v: serde_json::Value = serde_json::from_str(
            &std::fs::read_to_string(out.join("identification.json")).unwrap(),
        )
        .unwrap();
        let solver_json = &v["solver"];
        assert_eq!(solver_json["method"], solver);
        let (used, budget) = (
            solver_json["evaluations"].as_u64().unwrap(),
            solver_json["budget"].as_u64().unwrap(),
        );
        assert!(used <= budget && budget == 4000, "{solver_json}");
        let status = solver_json["status"].as_str().unwrap();
        assert!(
            [
                "converged",
                "at the consistency boundary",
                "budget exhausted"
            ]
            .contains(&status),
            "{status}"
        );
        assert_eq!(
            solver_json["converged"],
            status != "budget exhausted",
            "{solver_json}"
        );
        assert!(solver_json["cost_ratio_to_unconstrained"].as_f64().unwrap() >= 1.0 - 1e-9);
        let t = &v["timings_s"];
        let stages = [
            "reading",
            "filtering",
            "linear_fit",
            "consistent_fit",
            "validation",
            "figures",
        ];
        let sum: f64 = stages.iter().map(|k| t[*k].as_f64().unwrap()).sum();
        approx::assert_relative_eq!(t["total"].as_f64().unwrap(), sum, epsilon = 1e-9);
    }
    // The barrier solver converges here: its status is not the budget's.
    let v: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(dir.join("barrier").join("identification.json")).unwrap(),
    )
    .unwrap();
    assert_eq!(v["solver"]["converged"], true, "{}", v["solver"]);
}

#[test]
fn bad_write_log_options_are_refused_naming_them() {
    let dir = tmp(AREA, "bad-write-log");
    let log = dir.join("log.csv");
    for (args, needle) in [
        (
            vec!["--break-link", "5"],
            "--break-link 5: scara has links 1 to 4",
        ),
        (
            vec!["--unmodelled-friction"],
            "--unmodelled-friction: needs --friction on",
        ),
        (
            vec!["--log-seconds", "0"],
            "--log-seconds 0: must be in (0, 3600]",
        ),
        (
            vec!["--lost-pct", "100"],
            "--lost-pct 100: must be a percentage in [0, 100)",
        ),
    ] {
        let mut all = vec!["identify", "--robot", "scara", "--write-log", s(&log)];
        all.extend(args);
        let o = armdyn(&all);
        assert!(!o.status.success(), "{all:?} accepted");
        assert!(
            stderr(&o).contains(needle),
            "{needle} not in {}",
            stderr(&o)
        );
        assert!(!log.exists(), "{all:?} wrote the log");
    }
}

fn refused(name: &str, robot: &str, csv: &str, needles: &[&str]) {
    let dir = tmp(AREA, name);
    let (log, out) = (dir.join("log.csv"), dir.join("out"));
    std::fs::write(&log, csv).unwrap();
    let o = armdyn(&[
        "identify",
        "--robot",
        robot,
        "--log",
        s(&log),
        "--out",
        s(&out),
    ]);
    assert!(!o.status.success(), "{name}: accepted");
    let e = stderr(&o);
    for n in needles {
        assert!(e.contains(n), "{name}: `{n}` not in {e}");
    }
    assert!(!e.contains("panicked"), "{e}");
    assert!(!out.exists(), "{name}: wrote {}", out.display());
}

#[test]
fn a_log_it_cannot_use_is_refused_naming_the_line() {
    let good = |k: usize| format!("{},0.1,0.2,0.3,0.4,1,2,3,4\n", k as f64 * 1e-3);
    let header = "t,q1,q2,q3,q4,tau1,tau2,tau3,tau4\n";
    let mut not_a_number = format!("# a comment\n{header}");
    for k in 0..200 {
        not_a_number.push_str(&if k == 3 {
            "0.003,0.1,0.2,abc,0.4,1,2,3,4\n".to_string()
        } else {
            good(k)
        });
    }
    refused(
        "nan-field",
        "scara",
        &not_a_number,
        &["log.csv", "line 6", "`q3`", "`abc` is not a number"],
    );
    let mut short_row = header.to_string();
    for k in 0..200 {
        short_row.push_str(&if k == 10 {
            "0.01,0.1,0.2\n".to_string()
        } else {
            good(k)
        });
    }
    refused(
        "short-row",
        "scara",
        &short_row,
        &["line 12", "missing column", "found 3"],
    );
    refused(
        "missing-column",
        "scara",
        "t,q1,q2,q3,q4,tau1,tau2,tau3\n0,0,0,0,0,0,0,0\n",
        &["line 1", "missing column `tau4`"],
    );
    let mut other_robot = header.to_string();
    for k in 0..200 {
        other_robot.push_str(&good(k));
    }
    refused(
        "other-robot",
        "puma560",
        &other_robot
            .replace("tau4\n", "tau4,q7\n")
            .replace("4\n", "4,0\n"),
        &["line 1", "`q7`", "6 joints"],
    );
    refused(
        "too-short",
        "scara",
        &format!("{header}{}", good(0)),
        &[
            "line 3",
            "the log ends with 1 usable samples",
            "at least 100",
        ],
    );
}
