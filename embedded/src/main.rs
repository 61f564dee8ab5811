//! Firmware for the Cortex-M4 board MPS2 AN386 under QEMU: evaluates the SCARA's generated
//! `M`, `c`, `g`, forward dynamics and one full hybrid force/position controller step at the
//! fixed states of [`cases`] (the same file the host test compiles), in `f64` (software
//! floating point) and in `f32` (the FPU: the generated `f32` functions and the deployable
//! `f32` step, bare and inside its `f32` safety supervisor, through a NaN reading), prints the results as the bits of each value, checks them on the target,
//! measures each controller step's peak stack by painting, and counts the instructions of each
//! function with QEMU's instruction counting.
//!
//! Run from this folder: `cargo run --release` (the runner in `.cargo/config.toml` starts
//! `qemu-system-arm -machine mps2-an386 -icount shift=0 ...`). The exit code is 0 when every
//! on-target check passed. The output, one record a line:
//!
//! ```text
//! value <function> <case> <hex bits of each f64, space separated>
//! value32 <function> <case> <hex bits of each f32, space separated>
//! check <what> <case> ok|FAILED <detail>
//! insns <function>[_f32] <instructions per call, 2 decimals>
//! stack hybrid_step[_f32] / supervised_step_f32 <peak bytes>
//! done <number of failed checks>
//! ```

#![no_std]
#![no_main]

mod cases;

use core::fmt::Write;
use core::hint::black_box;

use armdyn::control::Controller;
use armdyn::model::{forward_dynamics_cholesky, Scara};
use armdyn_generated::scara as g;
use cortex_m::peripheral::syst::SystClkSource;
use cortex_m_rt::entry;
use cortex_m_semihosting::{debug, hio};
use nalgebra::Vector4;

/// Calls per instruction-count measurement (the SysTick resolution divided by this is the
/// resolution of the per-call figure).
const CALLS: u32 = 1000;
/// Bytes of stack painted below the caller's stack pointer before the controller step.
const PAINT_BYTES: usize = 32 * 1024;
const PAINT: u32 = 0xC0DE_5CA7;

#[entry]
fn main() -> ! {
    let failed = match hio::hstdout() {
        Ok(mut out) => run(&mut out),
        Err(()) => 1,
    };
    debug::exit(if failed == 0 {
        debug::EXIT_SUCCESS
    } else {
        debug::EXIT_FAILURE
    });
    #[allow(clippy::empty_loop)]
    loop {}
}

fn run(out: &mut hio::HostStream) -> u32 {
    let mut failed = 0u32;
    // 1. The values, through the shared evaluation.
    let built = cases::evaluate(&mut |name, case, values| {
        let _ = write!(out, "value {name} {case}");
        for v in values {
            let _ = write!(out, " {:016x}", v.to_bits());
        }
        let _ = writeln!(out);
    });
    if !built {
        let _ = writeln!(out, "check build_controller 0 FAILED gain design");
        failed += 1;
    }
    let built = cases::evaluate_f32(&mut |name, case, values| {
        let _ = write!(out, "value32 {name} {case}");
        for v in values {
            let _ = write!(out, " {:08x}", v.to_bits());
        }
        let _ = writeln!(out);
    });
    if !built {
        let _ = writeln!(out, "check build_controller_f32 0 FAILED gain design");
        failed += 1;
    }
    // 2. Checks on the target itself.
    for (k, [q, qd, tau]) in cases::STATES.iter().enumerate() {
        let qdd = g::forward_dynamics(q, qd, tau);
        let back = g::inverse_dynamics(q, qd, &qdd);
        let scale = tau.iter().fold(1.0f64, |a, t| a.max(t.abs()));
        let err = (0..4).fold(0.0f64, |a, i| a.max((back[i] - tau[i]).abs()));
        failed += check(out, "id_of_fd", k, err <= 1e-10 * scale, err);
        let reference = forward_dynamics_cholesky(
            &Scara,
            &Vector4::from(*q),
            &Vector4::from(*qd),
            &Vector4::from(*tau),
            &Vector4::zeros(),
        );
        let err = match reference {
            Ok(r) => (0..4).fold(0.0f64, |a, i| a.max((r[i] - qdd[i]).abs())),
            Err(_) => f64::INFINITY,
        };
        let scale = qdd.iter().fold(1.0f64, |a, x| a.max(x.abs()));
        failed += check(out, "fd_vs_cholesky", k, err <= 1e-10 * scale, err);
        let m = g::mass_matrix(q);
        let symmetric = (0..4).all(|i| (0..4).all(|j| m[i][j] == m[j][i]));
        failed += check(out, "mass_matrix_symmetric", k, symmetric, 0.0);
    }
    // 3. Peak stack of one controller step.
    if let Some(mut controller) = cases::hybrid() {
        let (peak, finite) = peak_stack(|| {
            cases::with_step_input(1, |input| controller.step(input, cases::CONTROL_DT))
                .iter()
                .all(|x| x.is_finite())
        });
        failed += check(out, "hybrid_step_finite", 1, finite, 0.0);
        match peak {
            Some(bytes) => {
                let _ = writeln!(out, "stack hybrid_step {bytes}");
            }
            None => {
                let _ = writeln!(out, "check stack_paint 1 FAILED painted window overrun");
                failed += 1;
            }
        }
    }
    if let Some(mut controller) = cases::hybrid_f32() {
        let input = cases::step_input_f32(1);
        let (peak, finite) = peak_stack(|| {
            controller
                .step(black_box(&input), cases::CONTROL_DT as f32)
                .iter()
                .all(|x| x.is_finite())
        });
        failed += check(out, "hybrid_step_f32_finite", 1, finite, 0.0);
        match peak {
            Some(bytes) => {
                let _ = writeln!(out, "stack hybrid_step_f32 {bytes}");
            }
            None => {
                let _ = writeln!(out, "check stack_paint_f32 1 FAILED painted window overrun");
                failed += 1;
            }
        }
    }
    if let Some(mut supervised) = cases::supervised_f32() {
        let input = cases::step_input_f32(1);
        let (peak, finite) = peak_stack(|| {
            supervised
                .step(black_box(&input), 0.0, cases::CONTROL_DT as f32)
                .iter()
                .all(|x| x.is_finite())
        });
        failed += check(out, "supervised_step_f32_finite", 1, finite, 0.0);
        if let Some(bytes) = peak {
            let _ = writeln!(out, "stack supervised_step_f32 {bytes}");
        }
        // A NaN reading: a trip, a finite torque.
        let mut bad = input;
        bad.force[2] = f32::NAN;
        bad.t += cases::CONTROL_DT as f32;
        let tau = supervised.step(&bad, 0.0, cases::CONTROL_DT as f32);
        let tripped = supervised
            .monitor()
            .trips()
            .first()
            .is_some_and(|t| t.cause.name() == "sensor-non-finite");
        failed += check(
            out,
            "supervised_nan_trips",
            1,
            tripped && tau.iter().all(|x| x.is_finite()),
            0.0,
        );
    }
    // 4. Instructions per call.
    failed += instruction_counts(out);
    let _ = writeln!(out, "done {failed}");
    failed
}

fn check(out: &mut hio::HostStream, what: &str, case: usize, ok: bool, detail: f64) -> u32 {
    let verdict = if ok { "ok" } else { "FAILED" };
    let _ = writeln!(out, "check {what} {case} {verdict} {detail:e}");
    u32::from(!ok)
}

/// Runs `f` on a stack whose next `PAINT_BYTES` below the current stack pointer were painted,
/// and returns the deepest byte it wrote (relative to that stack pointer; `None` if it
/// reached the end of the painted window) with `f`'s result.
#[inline(never)]
fn peak_stack<T>(f: impl FnOnce() -> T) -> (Option<usize>, T) {
    let sp = cortex_m::register::msp::read() as usize;
    let bottom = sp - PAINT_BYTES;
    // SAFETY: [bottom, sp) is free stack below this frame (RAM is 4 MiB, the stack starts at
    // its top and nothing else lives within 32 KiB of it); no interrupt is enabled, so nothing
    // else uses it while it is painted and read back; word-aligned (sp is 8-byte aligned).
    unsafe {
        for addr in (bottom..sp).step_by(4) {
            core::ptr::write_volatile(addr as *mut u32, PAINT);
        }
    }
    let result = black_box(f());
    let mut deepest = None;
    for addr in (bottom..sp).step_by(4) {
        // SAFETY: as above; reading back the painted window.
        let word = unsafe { core::ptr::read_volatile(addr as *const u32) };
        if word != PAINT {
            deepest = Some(sp - addr);
            break;
        }
    }
    // A write at the very bottom of the window means the window was too small.
    let peak = match deepest {
        Some(bytes) if bytes >= PAINT_BYTES => None,
        Some(bytes) => Some(bytes),
        None => Some(0),
    };
    (peak, result)
}

/// SysTick, from the processor clock, free-running down from 2^24 - 1.
struct Ticks {
    syst: cortex_m::peripheral::SYST,
}

impl Ticks {
    fn new(mut syst: cortex_m::peripheral::SYST) -> Self {
        syst.set_clock_source(SystClkSource::Core);
        syst.set_reload(0x00FF_FFFF);
        syst.clear_current();
        syst.enable_counter();
        Self { syst }
    }

    /// SysTick ticks taken by `f` (must be under 2^24).
    fn time(&mut self, f: impl FnOnce()) -> u32 {
        self.syst.clear_current();
        let start = cortex_m::peripheral::SYST::get_current();
        f();
        let end = cortex_m::peripheral::SYST::get_current();
        start.wrapping_sub(end) & 0x00FF_FFFF
    }
}

/// Exactly `2 n` instructions: `subs` and `bne`, `n` times.
#[inline(never)]
fn known_loop(n: u32) {
    // SAFETY: register-only arithmetic and a local branch; no memory, no stack.
    unsafe {
        core::arch::asm!(
            "2:",
            "subs {n}, {n}, #1",
            "bne 2b",
            n = inout(reg) n => _,
            options(nomem, nostack),
        );
    }
}

/// Instructions per call of each function. With `-icount shift=0` QEMU advances its virtual
/// clock by 1 ns per executed instruction, and SysTick counts that clock; the number of
/// instructions per tick is measured with a loop of known length rather than assumed, and the
/// cost of the measuring loop itself (an empty call) is subtracted.
fn instruction_counts(out: &mut hio::HostStream) -> u32 {
    let Some(peripherals) = cortex_m::Peripherals::take() else {
        let _ = writeln!(out, "check systick 0 FAILED peripherals taken");
        return 1;
    };
    let mut ticks = Ticks::new(peripherals.SYST);
    const KNOWN: u32 = 2_000_000;
    let known = ticks.time(|| known_loop(black_box(KNOWN)));
    if known == 0 {
        let _ = writeln!(
            out,
            "check icount 0 FAILED SysTick did not advance (run with -icount)"
        );
        return 1;
    }
    // Instructions per tick; the call, return and the set-up of `known_loop` add a handful of
    // instructions to 4 million, below the resolution.
    let per_tick = f64::from(2 * KNOWN) / f64::from(known);
    let _ = writeln!(
        out,
        "icount_calibration {per_tick:.3} instructions per SysTick tick"
    );
    let [q, qd, tau] = cases::STATES[1];
    let mut per_call = |f: &mut dyn FnMut()| {
        let t = ticks.time(|| {
            for _ in 0..CALLS {
                f();
            }
        });
        f64::from(t) * per_tick / f64::from(CALLS)
    };
    let empty = per_call(&mut || {
        black_box(black_box(&q));
    });
    let mut report = |name: &str, cost: f64| {
        let _ = writeln!(out, "insns {name} {:.2}", cost - empty);
    };
    report(
        "mass_matrix",
        per_call(&mut || {
            black_box(g::mass_matrix(black_box(&q)));
        }),
    );
    report(
        "coriolis",
        per_call(&mut || {
            black_box(g::coriolis(black_box(&q), black_box(&qd)));
        }),
    );
    report(
        "gravity",
        per_call(&mut || {
            black_box(g::gravity(black_box(&q)));
        }),
    );
    report(
        "forward_dynamics",
        per_call(&mut || {
            black_box(g::forward_dynamics(
                black_box(&q),
                black_box(&qd),
                black_box(&tau),
            ));
        }),
    );
    report(
        "forward_dynamics_cholesky",
        per_call(&mut || {
            let _ = black_box(forward_dynamics_cholesky(
                &Scara,
                black_box(&Vector4::from(q)),
                black_box(&Vector4::from(qd)),
                black_box(&Vector4::from(tau)),
                &Vector4::zeros(),
            ));
        }),
    );
    if let Some(mut controller) = cases::hybrid() {
        let mut step = || {
            cases::with_step_input(1, |input| {
                black_box(controller.step(black_box(input), cases::CONTROL_DT));
            });
        };
        let cost = per_call(&mut step);
        report("hybrid_step", cost);
    }
    // The same in single precision, on the FPU.
    let [q, qd, tau] = cases::states_f32()[1];
    report(
        "mass_matrix_f32",
        per_call(&mut || {
            black_box(g::f32::mass_matrix(black_box(&q)));
        }),
    );
    report(
        "coriolis_f32",
        per_call(&mut || {
            black_box(g::f32::coriolis(black_box(&q), black_box(&qd)));
        }),
    );
    report(
        "gravity_f32",
        per_call(&mut || {
            black_box(g::f32::gravity(black_box(&q)));
        }),
    );
    report(
        "forward_dynamics_f32",
        per_call(&mut || {
            black_box(g::f32::forward_dynamics(
                black_box(&q),
                black_box(&qd),
                black_box(&tau),
            ));
        }),
    );
    if let Some(mut controller) = cases::hybrid_f32() {
        let input = cases::step_input_f32(1);
        let cost = per_call(&mut || {
            black_box(controller.step(black_box(&input), cases::CONTROL_DT as f32));
        });
        report("hybrid_step_f32", cost);
    }
    if let Some(mut supervised) = cases::supervised_f32() {
        let input = cases::step_input_f32(1);
        let cost = per_call(&mut || {
            black_box(supervised.step(black_box(&input), 0.0, cases::CONTROL_DT as f32));
        });
        report("supervised_step_f32", cost);
    }
    0
}

#[panic_handler]
fn panic(info: &core::panic::PanicInfo) -> ! {
    if let Ok(mut out) = hio::hstdout() {
        let _ = writeln!(out, "panic {info}");
    }
    debug::exit(debug::EXIT_FAILURE);
    #[allow(clippy::empty_loop)]
    loop {}
}
