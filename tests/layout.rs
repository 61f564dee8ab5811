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
                // `a/mod.rs` and `lib.rs` keep their children beside them, `a/b.rs` in `a/b/`.
                let dir = f.parent().unwrap();
                let stem = f.file_stem().unwrap();
                let home = if stem == "mod" || stem == "lib" || stem == "main" {
                    dir.to_path_buf()
                } else {
                    dir.join(stem)
                };
                tests.insert(home.join(format!("{name}.rs")));
            }
        }
    }
    tests
}

/// The code of a file: every line but comments and test-only items (an inline
/// `#[cfg(test)] mod tests { .. }` to the end of the file, or the one item after any other
/// `#[cfg(test)]`, such as a `use`).
fn code(path: &Path) -> Vec<(usize, String)> {
    let text = std::fs::read_to_string(path).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < lines.len() {
        let t = lines[i].trim();
        if t == "#[cfg(test)]" {
            let next = lines.get(i + 1).map_or("", |l| l.trim());
            if next.starts_with("mod ") && next.ends_with('{') {
                break;
            }
            i += 2;
            continue;
        }
        if !t.starts_with("//") {
            out.push((i + 1, lines[i].split("//").next().unwrap_or("").to_string()));
        }
        i += 1;
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
    // Module -> the crate modules it must not import: every module of the library has a
    // place, lowest first (`bin` is the command line, above them all).
    const ABOVE_MODEL: &[&str] = &[
        "kinematics",
        "trajectory",
        "contact",
        "control",
        "sim",
        "metrics",
        "optimal",
        "identification",
        "report",
        "scenario",
        "robots",
        "sweep",
        "bin",
    ];
    let with = |extra: &[&'static str], rest: &[&'static str]| -> Vec<&'static str> {
        extra.iter().chain(rest).copied().collect()
    };
    let rules: Vec<(&str, Vec<&str>)> = vec![
        (
            "math",
            with(&["target", "csv_text", "surface", "model"], ABOVE_MODEL),
        ),
        (
            "target",
            with(&["csv_text", "surface", "model"], ABOVE_MODEL),
        ),
        (
            "csv_text",
            with(&["target", "surface", "model"], ABOVE_MODEL),
        ),
        ("surface", with(&["model"], ABOVE_MODEL)),
        ("model", with(&["surface"], ABOVE_MODEL)),
        ("kinematics", ABOVE_MODEL[1..].to_vec()),
        ("trajectory", with(&["kinematics"], &ABOVE_MODEL[2..])),
        (
            "contact",
            with(&["kinematics", "trajectory"], &ABOVE_MODEL[3..]),
        ),
        (
            "control",
            with(&["kinematics", "trajectory"], &ABOVE_MODEL[4..]),
        ),
        (
            "sim",
            with(&["kinematics", "trajectory"], &ABOVE_MODEL[5..]),
        ),
        (
            "metrics",
            with(&["kinematics", "trajectory", "control"], &ABOVE_MODEL[6..]),
        ),
        (
            "optimal",
            with(
                &["kinematics", "trajectory", "control", "contact", "metrics"],
                &ABOVE_MODEL[7..],
            ),
        ),
        (
            "identification",
            with(
                &["kinematics", "trajectory", "metrics", "optimal"],
                &ABOVE_MODEL[8..],
            ),
        ),
        (
            "report",
            with(
                &[
                    "kinematics",
                    "trajectory",
                    "control",
                    "optimal",
                    "identification",
                ],
                &ABOVE_MODEL[9..],
            ),
        ),
        ("scenario", with(&["optimal"], &ABOVE_MODEL[10..])),
        ("robots", ABOVE_MODEL[11..].to_vec()),
        ("sweep", with(&["robots"], &ABOVE_MODEL[12..])),
        ("bin", Vec::new()),
    ];
    // Every top-level module has its place.
    let tops: BTreeSet<String> = files
        .iter()
        .map(|f| {
            f.strip_prefix(&src)
                .unwrap()
                .iter()
                .next()
                .unwrap()
                .to_string_lossy()
                .trim_end_matches(".rs")
                .to_string()
        })
        .filter(|m| m != "lib")
        .collect();
    let placed: BTreeSet<String> = rules.iter().map(|(m, _)| m.to_string()).collect();
    assert_eq!(tops, placed, "every module of src/ needs a rule here");
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
        let forbidden: &[&str] = forbidden;
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
    assert!(imports(&src.join("contact/scene.rs")).contains("surface"));
    assert!(imports(&src.join("robots/scara/scenario.rs")).contains("scenario"));
}

/// The module path of a source file below `root` (`scenario/stages/plant.rs` ->
/// `scenario::stages::plant`; `mod.rs`, `lib.rs` and `main.rs` name their folder).
fn module_of(root: &Path, file: &Path) -> Vec<String> {
    let mut parts: Vec<String> = file
        .strip_prefix(root)
        .unwrap()
        .iter()
        .map(|p| p.to_string_lossy().trim_end_matches(".rs").to_string())
        .collect();
    if matches!(
        parts.last().map(String::as_str),
        Some("mod" | "lib" | "main")
    ) {
        parts.pop();
    }
    parts
}

/// The crate paths `file` imports, resolved to module paths: `crate::a::b` and
/// `super::c` (relative to the file's module), each as far as its segments go.
fn import_paths(own: &[String], file: &Path) -> Vec<Vec<String>> {
    // `super` is the parent of the file's module (a `mod.rs`'s module is its folder).
    let parent = own[..own.len().saturating_sub(1)].to_vec();
    let mut out = Vec::new();
    for (_, line) in code(file) {
        for (prefix, base) in [("crate::", Vec::new()), ("super::", parent.clone())] {
            let mut rest = line.as_str();
            while let Some(i) = rest.find(prefix) {
                let preceded = i > 0 && {
                    let c = rest.as_bytes()[i - 1];
                    c.is_ascii_alphanumeric() || c == b'_' || c == b':'
                };
                let mut tail = &rest[i + prefix.len()..];
                let mut path = base.clone();
                // `super::super::x`: one level further up per `super`.
                while let Some(t) = tail.strip_prefix("super::") {
                    path.pop();
                    tail = t;
                }
                for seg in tail.split("::") {
                    let name: String = seg
                        .chars()
                        .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
                        .collect();
                    if name.is_empty() || name.len() != seg.len() && !seg.starts_with(&name) {
                        break;
                    }
                    path.push(name.clone());
                    if name.len() != seg.len() {
                        break;
                    }
                }
                if !preceded {
                    out.push(path);
                }
                rest = tail;
            }
        }
    }
    out
}

/// Cycles between sibling modules of the tree below `root`: for every module, an edge from
/// child `a` to child `b` when code under `a` (not a test) imports anything under `b`.
fn sibling_cycles(root: &Path) -> Vec<String> {
    use std::collections::BTreeMap;
    let mut files = Vec::new();
    sources(root, &mut files);
    files.sort();
    let tests = test_modules(&files);
    let modules: BTreeSet<Vec<String>> = files.iter().map(|f| module_of(root, f)).collect();
    // parent -> child -> children it imports
    let mut edges: BTreeMap<Vec<String>, BTreeMap<String, BTreeSet<String>>> = BTreeMap::new();
    for f in files.iter().filter(|f| !tests.contains(*f)) {
        let own = module_of(root, f);
        for target in import_paths(&own, f) {
            // The longest module prefix of the imported path.
            let Some(t) = (0..=target.len())
                .rev()
                .map(|k| target[..k].to_vec())
                .find(|p| modules.contains(p))
            else {
                continue;
            };
            // The common parent and the two children below it.
            let common = own.iter().zip(&t).take_while(|(a, b)| a == b).count();
            if common < own.len() && common < t.len() {
                edges
                    .entry(own[..common].to_vec())
                    .or_default()
                    .entry(own[common].clone())
                    .or_default()
                    .insert(t[common].clone());
            }
        }
    }
    let mut cycles = Vec::new();
    for (parent, graph) in &edges {
        // Depth-first search for a back edge.
        fn visit(
            n: &str,
            g: &BTreeMap<String, BTreeSet<String>>,
            state: &mut BTreeMap<String, u8>,
            stack: &mut Vec<String>,
            out: &mut Vec<Vec<String>>,
        ) {
            state.insert(n.to_string(), 1);
            stack.push(n.to_string());
            for m in g.get(n).into_iter().flatten() {
                match state.get(m.as_str()) {
                    Some(1) => {
                        let start = stack.iter().position(|s| s == m).unwrap();
                        let mut c = stack[start..].to_vec();
                        c.push(m.clone());
                        out.push(c);
                    }
                    Some(_) => {}
                    None => visit(m, g, state, stack, out),
                }
            }
            stack.pop();
            state.insert(n.to_string(), 2);
        }
        let mut state = BTreeMap::new();
        let mut found = Vec::new();
        for n in graph.keys() {
            if !state.contains_key(n.as_str()) {
                visit(n, graph, &mut state, &mut Vec::new(), &mut found);
            }
        }
        for c in found {
            let at = if parent.is_empty() {
                "crate".to_string()
            } else {
                parent.join("::")
            };
            cycles.push(format!("in {at}: {}", c.join(" -> ")));
        }
    }
    cycles
}

#[test]
fn no_module_imports_a_sibling_that_imports_it_back() {
    let manifest = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let mut found = Vec::new();
    for root in ["src", "derive/src", "generated/src"] {
        for c in sibling_cycles(&manifest.join(root)) {
            found.push(format!("{root}: {c}"));
        }
    }
    println!("{} cycles", found.len());
    assert!(found.is_empty(), "{}", found.join("\n"));
}
