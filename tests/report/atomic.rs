//! Tests of `armdyn::report::atomic`: atomic writes: a file replaced with no temporary left,
//! nothing left on failure, an output folder committed whole or left as it was, names that escape
//! it refused.

use armdyn::report::atomic::*;
use std::fs;
use std::io;
use std::path::Path;

fn entries(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

#[test]
fn write_atomic_replaces_and_leaves_no_temporary_file() {
    let tmp = tempfile::tempdir().unwrap();
    let path = tmp.path().join("out.csv");
    write_atomic(&path, "first").unwrap();
    write_atomic(&path, "second, longer").unwrap();
    assert_eq!(fs::read_to_string(&path).unwrap(), "second, longer");
    assert_eq!(entries(tmp.path()), ["out.csv"]);
}

#[test]
fn write_atomic_failure_leaves_nothing() {
    let tmp = tempfile::tempdir().unwrap();
    // The target is an existing non-empty folder: the rename fails.
    let target = tmp.path().join("taken");
    fs::create_dir_all(target.join("inside")).unwrap();
    assert!(write_atomic(&target, "x").is_err());
    assert_eq!(entries(tmp.path()), ["taken"]);
    // A missing folder fails before anything is created.
    assert!(write_atomic(tmp.path().join("missing/out.csv"), "x").is_err());
    assert_eq!(entries(tmp.path()), ["taken"]);
}

#[test]
fn output_dir_commit_moves_everything_and_cleans_up() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path().join("run");
    let mut out = OutputDir::create(&dir).unwrap();
    out.write("a.csv", "1").unwrap();
    out.write("plots/b.svg", "<svg/>").unwrap();
    out.write("a.csv", "2").unwrap();
    assert_eq!(out.staged().len(), 2);
    // Only the staging folder is visible before the commit.
    let before = entries(&dir);
    assert_eq!(before.len(), 1);
    assert!(before[0].starts_with(".armdyn-staging"));
    let written = out.commit().unwrap();
    assert_eq!(written, [dir.join("a.csv"), dir.join("plots/b.svg")]);
    assert_eq!(entries(&dir), ["a.csv", "plots"]);
    assert_eq!(fs::read_to_string(dir.join("a.csv")).unwrap(), "2");
    assert_eq!(entries(&dir.join("plots")), ["b.svg"]);
}

#[test]
fn output_dir_dropped_without_commit_leaves_the_folder_as_it_was() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path().join("run");
    fs::create_dir_all(&dir).unwrap();
    fs::write(dir.join("old.csv"), "old").unwrap();
    {
        let mut out = OutputDir::create(&dir).unwrap();
        out.write("old.csv", "new").unwrap();
        out.write("plots/x.svg", "<svg/>").unwrap();
        // A failing run: dropped here, never committed.
    }
    assert_eq!(entries(&dir), ["old.csv"]);
    assert_eq!(fs::read_to_string(dir.join("old.csv")).unwrap(), "old");
}

#[test]
fn output_dir_rejects_escaping_names() {
    let tmp = tempfile::tempdir().unwrap();
    let mut out = OutputDir::create(tmp.path()).unwrap();
    for bad in ["../x.csv", "/etc/x.csv", "", "a/../../x"] {
        let err = out.write(bad, "x").unwrap_err();
        assert_eq!(err.kind(), io::ErrorKind::InvalidInput, "{bad}");
    }
    assert!(out.staged().is_empty());
}
