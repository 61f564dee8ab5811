//! The firmware of `embedded/` on an emulated Cortex-M4 (QEMU's `mps2-an386`) against the
//! host: both evaluate `embedded/src/cases.rs` (the SCARA's generated `M`, `c`, `g`, forward
//! dynamics and one hybrid controller step per state, in `f64` and in `f32`); every printed
//! `f64` and `f32` must equal the host's to the last bit, every on-target check must pass, and
//! the firmware must exit 0.
//!
//! Needs `qemu-system-arm` and the `thumbv7em-none-eabihf` target. Without them the test is
//! skipped with a message, except under CI (`CI` set), where it fails.
//!
//! `cargo test --release --test embedded_qemu -- --nocapture` also prints the firmware's
//! flash size, the controller step's peak stack and the instructions per call.

#[path = "../embedded/src/cases.rs"]
mod cases;

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

const TARGET: &str = "thumbv7em-none-eabihf";
const TIMEOUT: Duration = Duration::from_secs(300);

fn in_ci() -> bool {
    std::env::var_os("CI").is_some_and(|v| !v.is_empty() && v != "false" && v != "0")
}

/// Skips (outside CI) or fails (in CI) with a loud message.
fn unavailable(why: &str) {
    let msg = format!(
        "\n\n*** embedded_qemu: {why}; the emulated firmware was NOT run and NOT compared \
         with the host ***\n\n"
    );
    if in_ci() {
        panic!("{msg}(CI is set: this is a failure)");
    }
    eprintln!("{msg}");
}

fn have(program: &str, arg: &str) -> bool {
    Command::new(program)
        .arg(arg)
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .is_ok_and(|s| s.success())
}

fn embedded_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("embedded")
}

/// A cargo command in `embedded/`, cleared of what the outer build may have set for the host
/// (`RUSTFLAGS` such as `-C target-cpu=native`, a shared target directory).
fn cargo_in_embedded() -> Command {
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let mut cmd = Command::new(cargo);
    cmd.current_dir(embedded_dir())
        .env_remove("RUSTFLAGS")
        .env_remove("CARGO_ENCODED_RUSTFLAGS")
        .env_remove("CARGO_BUILD_RUSTFLAGS")
        .env_remove("CARGO_BUILD_TARGET")
        .env("CARGO_TARGET_DIR", embedded_dir().join("target"));
    cmd
}

/// Runs `cmd`, killing it after `TIMEOUT`; returns (status success, stdout, stderr).
fn run_with_timeout(mut cmd: Command) -> (Option<i32>, String, String) {
    let mut child = cmd
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("spawn");
    let mut stdout = child.stdout.take().expect("stdout");
    let mut stderr = child.stderr.take().expect("stderr");
    let out = std::thread::spawn(move || {
        let mut s = String::new();
        std::io::Read::read_to_string(&mut stdout, &mut s).ok();
        s
    });
    let err = std::thread::spawn(move || {
        let mut s = String::new();
        std::io::Read::read_to_string(&mut stderr, &mut s).ok();
        s
    });
    let start = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().expect("wait") {
            break status;
        }
        if start.elapsed() > TIMEOUT {
            child.kill().ok();
            panic!("the firmware did not finish within {TIMEOUT:?}");
        }
        std::thread::sleep(Duration::from_millis(50));
    };
    (
        status.code(),
        out.join().expect("stdout reader"),
        err.join().expect("stderr reader"),
    )
}

/// Bytes of an ELF32 (little endian) image by where they live: (flash, RAM). Flash holds every
/// allocated section with contents (vector table, code, read-only data, the initial values of
/// `.data`); RAM every allocated section placed at 0x2000_0000 or above (`.data`, `.bss`).
fn elf_sizes(elf: &[u8]) -> (u64, u64) {
    let u16_at = |o: usize| u64::from(u16::from_le_bytes([elf[o], elf[o + 1]]));
    let u32_at = |o: usize| {
        u64::from(u32::from_le_bytes([
            elf[o],
            elf[o + 1],
            elf[o + 2],
            elf[o + 3],
        ]))
    };
    assert_eq!(&elf[..5], b"\x7fELF\x01", "not an ELF32 file");
    let (shoff, shentsize, shnum) = (u32_at(0x20), u16_at(0x2e), u16_at(0x30));
    const SHF_ALLOC: u64 = 2;
    const SHT_NOBITS: u64 = 8;
    let (mut flash, mut ram) = (0, 0);
    for i in 0..shnum {
        let h = (shoff + i * shentsize) as usize;
        let (kind, flags, addr, size) =
            (u32_at(h + 4), u32_at(h + 8), u32_at(h + 12), u32_at(h + 20));
        if flags & SHF_ALLOC == 0 {
            continue;
        }
        if kind != SHT_NOBITS {
            flash += size;
        }
        if addr >= 0x2000_0000 {
            ram += size;
        }
    }
    (flash, ram)
}

#[test]
fn firmware_on_qemu_equals_host_bit_for_bit() {
    if !have("qemu-system-arm", "--version") {
        unavailable("qemu-system-arm is not installed (Debian: apt-get install qemu-system-arm)");
        return;
    }
    let rustup = Command::new("rustup")
        .args(["target", "list", "--installed"])
        .output();
    if let Ok(out) = rustup {
        if !String::from_utf8_lossy(&out.stdout)
            .lines()
            .any(|l| l.trim() == TARGET)
        {
            unavailable(&format!(
                "the Rust target {TARGET} is not installed (rustup target add {TARGET})"
            ));
            return;
        }
    }

    // Build, then run through the runner of embedded/.cargo/config.toml.
    let mut build = cargo_in_embedded();
    build.args(["build", "--release", "--quiet"]);
    let (code, _, err) = run_with_timeout(build);
    assert_eq!(code, Some(0), "building the firmware failed:\n{err}");
    let mut run = cargo_in_embedded();
    run.args(["run", "--release", "--quiet"]);
    let (code, stdout, stderr) = run_with_timeout(run);

    // The host's own evaluation of the same cases.
    let mut host = Vec::new();
    assert!(cases::evaluate(&mut |name, case, values| {
        host.push((
            name.to_string(),
            case,
            values.iter().map(|v| v.to_bits()).collect::<Vec<u64>>(),
        ));
    }));

    let mut host32 = Vec::new();
    assert!(cases::evaluate_f32(&mut |name, case, values| {
        host32.push((
            name.to_string(),
            case,
            values
                .iter()
                .map(|v| u64::from(v.to_bits()))
                .collect::<Vec<u64>>(),
        ));
    }));

    let mut target = Vec::new();
    let mut target32 = Vec::new();
    let mut failed_checks = Vec::new();
    let mut report = BTreeMap::new();
    for line in stdout.lines() {
        let fields: Vec<&str> = line.split_whitespace().collect();
        match fields.first().copied() {
            Some(kind @ ("value" | "value32")) => {
                let bits = fields[3..]
                    .iter()
                    .map(|h| u64::from_str_radix(h, 16).expect("hex bits"))
                    .collect::<Vec<u64>>();
                let record = (
                    fields[1].to_string(),
                    fields[2].parse::<usize>().unwrap(),
                    bits,
                );
                if kind == "value" {
                    target.push(record);
                } else {
                    target32.push(record);
                }
            }
            Some("check") if fields.get(3) != Some(&"ok") => failed_checks.push(line.to_string()),
            Some("insns" | "stack" | "icount_calibration") => {
                report.insert(fields[..2].join(" "), fields[2..].join(" "));
            }
            _ => {}
        }
    }
    assert!(
        stdout.lines().any(|l| l == "done 0") && code == Some(0),
        "the firmware failed (exit code {code:?}):\n{stdout}\n{stderr}"
    );
    assert!(
        failed_checks.is_empty(),
        "on-target checks failed:\n{}",
        failed_checks.join("\n")
    );
    assert_eq!(target.len(), host.len(), "number of records:\n{stdout}");
    assert_eq!(
        target32.len(),
        host32.len(),
        "number of f32 records:\n{stdout}"
    );
    let mut differences = Vec::new();
    let single = |bits: u64| f64::from(f32::from_bits(u32::try_from(bits).unwrap_or(u32::MAX)));
    for (precision, host, target) in [("f64", &host, &target), ("f32", &host32, &target32)] {
        for ((hn, hk, hv), (tn, tk, tv)) in host.iter().zip(target) {
            assert_eq!((hn, hk), (tn, tk), "records out of order");
            assert_eq!(hv.len(), tv.len(), "{hn} case {hk}: lengths");
            for (i, (h, t)) in hv.iter().zip(tv).enumerate() {
                if h != t {
                    let (h, t) = if precision == "f64" {
                        (f64::from_bits(*h), f64::from_bits(*t))
                    } else {
                        (single(*h), single(*t))
                    };
                    differences.push(format!(
                        "{precision} {hn} case {hk} [{i}]: host {h} target {t}"
                    ));
                }
            }
        }
    }
    assert!(
        differences.is_empty(),
        "{} values differ from the host's:\n{}",
        differences.len(),
        differences.join("\n")
    );

    let elf = embedded_dir().join(format!("target/{TARGET}/release/armdyn-embedded"));
    let (flash, ram) = elf_sizes(&std::fs::read(&elf).expect("read the firmware ELF"));
    let values: usize = host.iter().map(|r| r.2.len()).sum();
    let values32: usize = host32.iter().map(|r| r.2.len()).sum();
    println!(
        "firmware {}: flash {flash} bytes, static RAM {ram} bytes",
        elf.display()
    );
    println!(
        "{} records, {values} f64 values and {values32} f32 values: all equal to the host's, \
         bit for bit",
        host.len() + host32.len()
    );
    for (k, v) in &report {
        println!("{k} {v}");
    }
}
