//! The binary's output to a stdout closed by its reader (`armdyn ... | head -1`): the
//! command ends quietly with success, without a panic message.

use std::process::{Command, Stdio};

/// Runs `armdyn args` with stdout a pipe whose read end is already closed, so that its first
/// write fails with a broken pipe; returns the exit status and stderr.
fn with_closed_stdout(args: &[&str]) -> (std::process::ExitStatus, String) {
    let (reader, writer) = std::io::pipe().expect("a pipe");
    drop(reader);
    let out = Command::new(env!("CARGO_BIN_EXE_armdyn"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .stdout(writer)
        .stderr(Stdio::piped())
        .output()
        .expect("running the armdyn binary");
    (
        out.status,
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn a_closed_stdout_ends_every_printing_command_quietly() {
    for args in [
        &[
            "design",
            "force",
            "--k",
            "1000",
            "--dt",
            "0.001",
            "--mass",
            "5",
            "--bandwidth-hz",
            "20",
            "--damping",
            "1",
        ][..],
        &["urdf", "--robot", "panda"],
        &["model", "--robot", "scara", "--q", "0,0,0.1,0"],
        &["run", "scenario", "--check", "scenarios/oblique-plane.toml"],
    ] {
        let (status, stderr) = with_closed_stdout(args);
        assert!(status.success(), "{args:?}: {status}, stderr: {stderr}");
        assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
    }
}
