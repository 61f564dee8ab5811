//! The 3-D viewer (`view.html`) in a real headless browser: the thesis hybrid run (SCARA)
//! and the Panda on its cylinder, each loaded at stated times. The page must report no
//! JavaScript error, the tool it draws (the generated forward kinematics' end effector,
//! interpolated between the page's frames) must be the `trajectory.csv` position at that
//! time to 1 mm, and a screenshot is saved in `target/viewer/`. Also: the file is
//! self-contained and under 5 MB, `armdyn view DIR` writes the same page again, and
//! `--no-view` writes none (and removes an earlier run's).
//!
//! Needs Chromium (`chromium`, Debian's package). Without it the test is skipped with a
//! message, except under CI (`CI` set), where it fails.

use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

/// The page's size limit for a 10 s run, bytes.
const MAX_BYTES: u64 = 5_000_000;

fn in_ci() -> bool {
    std::env::var_os("CI").is_some_and(|v| !v.is_empty() && v != "false" && v != "0")
}

fn chromium() -> Option<&'static str> {
    ["chromium", "chromium-browser", "google-chrome"]
        .into_iter()
        .find(|p| {
            Command::new(p)
                .arg("--version")
                .stdout(Stdio::null())
                .stderr(Stdio::null())
                .status()
                .is_ok_and(|s| s.success())
        })
}

fn armdyn(args: &[&str]) -> Output {
    let o = Command::new(env!("CARGO_BIN_EXE_armdyn"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("armdyn runs");
    assert!(
        o.status.success(),
        "armdyn {args:?}: {}",
        String::from_utf8_lossy(&o.stderr)
    );
    o
}

/// Chromium, headless, on `page` at `t` (s), `extra` its own options.
fn browse(browser: &str, page: &Path, t: f64, extra: &[String]) -> Output {
    let url = format!("file://{}#t={t}", page.display());
    let o = Command::new(browser)
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--hide-scrollbars",
            "--window-size=1280,800",
            "--virtual-time-budget=3000",
        ])
        .args(extra)
        .arg(&url)
        .stdin(Stdio::null())
        .output()
        .expect("chromium runs");
    assert!(o.status.success(), "{browser} {url}: {:?}", o.status);
    o
}

/// The recorded tool position at `t` (s), linear between the samples around it.
fn csv_tool_at(csv: &str, t: f64) -> [f64; 3] {
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |name: &str| header.iter().position(|h| *h == name).unwrap();
    let (x, y, z) = (col("x_m"), col("y_m"), col("z_m"));
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|f| f.parse().unwrap()).collect())
        .collect();
    let i = rows.partition_point(|r| r[0] <= t).clamp(1, rows.len() - 1);
    let (a, b) = (&rows[i - 1], &rows[i]);
    let w = ((t - a[0]) / (b[0] - a[0])).clamp(0.0, 1.0);
    [x, y, z].map(|k| a[k] + w * (b[k] - a[k]))
}

/// Checks the viewer of the run of `scenario` at `times` (s); a screenshot at the first.
fn check(browser: &str, scenario: &str, times: &[f64]) {
    let root = Path::new(env!("CARGO_TARGET_TMPDIR")).join("viewer");
    let name = Path::new(scenario).file_stem().unwrap().to_str().unwrap();
    let dir = root.join(name);
    let _ = std::fs::remove_dir_all(&dir);
    armdyn(&["run", "scenario", scenario, "--out", dir.to_str().unwrap()]);
    let page = dir.join("view.html");
    let html = std::fs::read_to_string(&page).unwrap();
    let bytes = std::fs::metadata(&page).unwrap().len();
    assert!(bytes < MAX_BYTES, "{name}: view.html is {bytes} bytes");
    // Self-contained: nothing fetched at view time.
    for fetch in ["src=\"http", "href=\"http", "<link", "import(", "fetch("] {
        assert!(!html.contains(fetch), "{name}: the page holds `{fetch}`");
    }
    let csv = std::fs::read_to_string(dir.join("trajectory.csv")).unwrap();
    for &t in times {
        let dom = browse(browser, &page, t, &["--dump-dom".to_string()]);
        let dom = String::from_utf8_lossy(&dom.stdout);
        let start = dom
            .find("<pre id=\"probe\"")
            .and_then(|i| dom[i..].find('>').map(|j| i + j + 1))
            .unwrap_or_else(|| panic!("{name}: no probe in the page"));
        let end = start + dom[start..].find("</pre>").unwrap();
        let probe: serde_json::Value = serde_json::from_str(&dom[start..end])
            .unwrap_or_else(|e| panic!("{name} at {t} s: the page did not run ({e})"));
        assert_eq!(probe["errors"], serde_json::json!([]), "{name} at {t} s");
        assert!((probe["t"].as_f64().unwrap() - t).abs() < 1e-9, "{probe}");
        let drawn: Vec<f64> = probe["tool"]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_f64().unwrap())
            .collect();
        let recorded = csv_tool_at(&csv, t);
        let off = (0..3)
            .map(|k| (drawn[k] - recorded[k]).powi(2))
            .sum::<f64>()
            .sqrt();
        eprintln!(
            "{name} at {t} s: drawn tool {drawn:?}, trajectory.csv {recorded:?}: {:.4} mm apart",
            1e3 * off
        );
        assert!(off < 1e-3, "{name} at {t} s: {off} m apart");
    }
    let shot = root.join(format!("{name}.png"));
    let _ = std::fs::remove_file(&shot);
    browse(
        browser,
        &page,
        times[0],
        &[format!("--screenshot={}", shot.display())],
    );
    let png = std::fs::read(&shot).expect("a screenshot");
    assert!(
        png.starts_with(b"\x89PNG") && png.len() > 10_000,
        "{}",
        png.len()
    );
    eprintln!(
        "{name}: view.html {bytes} bytes; screenshot {}",
        shot.display()
    );
    // The same page again from the folder.
    std::fs::remove_file(&page).unwrap();
    armdyn(&["view", dir.to_str().unwrap()]);
    assert_eq!(std::fs::read_to_string(&page).unwrap(), html, "{name}");
}

#[test]
fn the_viewer_draws_the_recorded_tool_in_a_real_browser() {
    let Some(browser) = chromium() else {
        let msg = "\n\n*** viewer: Chromium is not installed (apt-get install -y chromium); the \
                   viewer was NOT tested in a browser ***\n\n";
        assert!(!in_ci(), "{msg}(CI is set: this is a failure)");
        eprintln!("{msg}");
        return;
    };
    // On a sample, between samples and between the page's frames, after the switch.
    check(
        browser,
        "scenarios/thesis-hybrid.toml",
        &[5.0, 2.0021, 7.3337],
    );
    check(browser, "scenarios/panda-cylinder.toml", &[4.0, 6.1234]);
}

#[test]
fn no_view_writes_no_page() {
    let dir: PathBuf = Path::new(env!("CARGO_TARGET_TMPDIR")).join("viewer-none");
    let _ = std::fs::remove_dir_all(&dir);
    let run = |extra: &[&str]| {
        let mut args = vec!["run", "scenario", "scenarios/ur5-square.toml"];
        args.extend(extra);
        args.extend(["--out", dir.to_str().unwrap()]);
        String::from_utf8(armdyn(&args).stdout).unwrap()
    };
    assert!(run(&[]).contains("view.html"));
    assert!(dir.join("view.html").exists());
    // Without the viewer, the earlier run's is removed: it would not show this run.
    let printed = run(&["--no-view"]);
    assert!(!printed.contains("view.html"), "{printed}");
    assert!(dir.join("trajectory.csv").exists());
    assert!(!dir.join("view.html").exists());
    // A folder that is not a run's is refused, naming the file.
    let e = Command::new(env!("CARGO_BIN_EXE_armdyn"))
        .args(["view", dir.join("nothing").to_str().unwrap()])
        .output()
        .unwrap();
    assert!(!e.status.success());
    assert!(String::from_utf8_lossy(&e.stderr).contains("metrics.json"));
}
