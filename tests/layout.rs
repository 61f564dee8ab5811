//! The layout rules of the library: nothing outside the SCARA's own module
//! (`src/robots/scara/`) assumes four joints or names the SCARA (`[f64; 4]`, `<4>`, `Scara`,
//! `SCARA_` in code that is not a test or a comment), and the modules import each other one
//! way only: the shared vocabulary (`target`) imports nothing of the crate; `control`,
//! `kinematics` and `trajectory` import none of each other; `scenario` does not know sweeps
//! exist; no library layer imports the robots' own modules, the scenarios or the command line.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

fn sources(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            sources(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// Files that are test modules themselves (`#[cfg(test)] mod name;` in their parent).
fn test_modules(files: &[PathBuf]) -> BTreeSet<PathBuf> {
    let mut tests = BTreeSet::new();
    for f in files {
        let text = std::fs::read_to_string(f).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        for (i, l) in lines.iter().enumerate() {
            let Some(name) = l
                .trim()
                .strip_prefix("mod ")
                .and_then(|r| r.strip_suffix(';'))
            else {
                continue;
            };
            if i > 0 && lines[i - 1].trim() == "#[cfg(test)]" {
                let dir = f.parent().unwrap();
                tests.insert(dir.join(format!("{name}.rs")));
            }
        }
    }
    tests
}

/// The code of a file: up to its test module, without comments.
fn code(path: &Path) -> Vec<(usize, String)> {
    let text = std::fs::read_to_string(path).unwrap();
    let mut out = Vec::new();
    for (i, line) in text.lines().enumerate() {
        let t = line.trim();
        if t == "#[cfg(test)]" {
            break;
        }
        if t.starts_with("//") {
            continue;
        }
        out.push((i + 1, line.split("//").next().unwrap_or("").to_string()));
    }
    out
}

fn library() -> (PathBuf, Vec<PathBuf>) {
    let src = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    sources(&src, &mut files);
    files.sort();
    (src, files)
}

#[test]
fn nothing_outside_the_scaras_module_assumes_its_four_joints() {
    let (src, files) = library();
    let tests = test_modules(&files);
    let own = src.join("robots").join("scara");
    let mut found = Vec::new();
    for f in files
        .iter()
        .filter(|f| !f.starts_with(&own) && !tests.contains(*f))
    {
        for (n, line) in code(f) {
            for pattern in ["[f64; 4]", "<4>", "Scara", "SCARA_"] {
                if line.contains(pattern) {
                    found.push(format!(
                        "{}:{n}: {}",
                        f.strip_prefix(&src).unwrap().display(),
                        line.trim()
                    ));
                }
            }
        }
    }
    println!("{} matches", found.len());
    assert!(found.is_empty(), "{}", found.join("\n"));
    // The scan finds what it looks for: the SCARA's own module is full of it.
    let inside = files
        .iter()
        .filter(|f| f.starts_with(&own))
        .flat_map(|f| code(f))
        .filter(|(_, l)| l.contains("Scara") || l.contains("<4>"))
        .count();
    assert!(inside > 10, "{inside}");
}

/// The crate modules `file`'s code imports (`crate::name`).
fn imports(file: &Path) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    for (_, line) in code(file) {
        let mut rest = line.as_str();
        while let Some(i) = rest.find("crate::") {
            let name: String = rest[i + 7..]
                .chars()
                .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
                .collect();
            out.insert(name);
            rest = &rest[i + 7..];
        }
    }
    out
}

#[test]
fn the_layers_import_each_other_one_way() {
    let (src, files) = library();
    let tests = test_modules(&files);
    // Module -> the crate modules it must not import.
    let rules: [(&str, &[&str]); 8] = [
        (
            "target",
            &[
                "model",
                "kinematics",
                "trajectory",
                "control",
                "sim",
                "contact",
                "scenario",
                "robots",
            ],
        ),
        (
            "model",
            &[
                "kinematics",
                "trajectory",
                "control",
                "sim",
                "scenario",
                "robots",
            ],
        ),
        (
            "kinematics",
            &["control", "trajectory", "sim", "scenario", "robots"],
        ),
        (
            "trajectory",
            &["control", "kinematics", "sim", "scenario", "robots"],
        ),
        (
            "control",
            &["kinematics", "trajectory", "sim", "scenario", "robots"],
        ),
        ("sim", &["kinematics", "trajectory", "scenario", "robots"]),
        ("scenario", &["sweep", "robots"]),
        ("sweep", &["robots"]),
    ];
    let mut found = Vec::new();
    for f in files.iter().filter(|f| !tests.contains(*f)) {
        let rel = f.strip_prefix(&src).unwrap();
        let top = rel
            .iter()
            .next()
            .unwrap()
            .to_string_lossy()
            .trim_end_matches(".rs")
            .to_string();
        let Some((_, forbidden)) = rules.iter().find(|(m, _)| *m == top) else {
            continue;
        };
        for m in imports(f) {
            if forbidden.contains(&m.as_str()) {
                found.push(format!("{} imports crate::{m}", rel.display()));
            }
        }
    }
    assert!(found.is_empty(), "{}", found.join("\n"));
    // The scan sees imports: the simulator uses the controllers, the robots' modules the
    // scenarios.
    assert!(imports(&src.join("sim/mod.rs")).contains("control"));
    assert!(imports(&src.join("robots/scara/scenario.rs")).contains("scenario"));
}
