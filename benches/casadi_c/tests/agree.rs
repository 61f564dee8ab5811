//! CasADi's generated C and the generated Rust evaluate the same expression graphs, so for
//! every function of `scara` and `puma560` (numeric and parametric) they must agree to
//! rounding at random states: `|c - r| <= 1e-12 * max(|r|, max_j |r_j|)` per element, i.e.
//! relative to the element, with the output's largest magnitude as the floor for elements
//! that cancel to (near) zero.
//!
//! Differences beyond bit-equality come from the trig: the Rust calls `libm` (a port of
//! musl's), the C the platform's `sin`/`cos` (glibc here); both are faithfully rounded but
//! may differ in the last bit, which the arithmetic then propagates.

use std::collections::BTreeMap;

use armdyn_casadi_c_bench::{CFunction, Symbols};

const STATES: usize = 50;
const TOL: f64 = 1e-12;

/// splitmix64: a small, seeded, reproducible generator.
struct Rng(u64);

impl Rng {
    fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in `[lo, hi)`.
    fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        let unit = (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
        lo + (hi - lo) * unit
    }
}

/// Row-major flattening of the Rust outputs (scalars, vectors, matrices, stacks of matrices).
trait Flatten {
    fn flatten_into(&self, out: &mut Vec<f64>);
}

impl Flatten for f64 {
    fn flatten_into(&self, out: &mut Vec<f64>) {
        out.push(*self);
    }
}

impl<T: Flatten, const N: usize> Flatten for [T; N] {
    fn flatten_into(&self, out: &mut Vec<f64>) {
        for x in self {
            x.flatten_into(out);
        }
    }
}

/// Worst agreement seen for one function.
#[derive(Default)]
struct Stats {
    calls: usize,
    elements: usize,
    bit_equal: usize,
    /// max over elements of `|c - r| / max(|r|, max_j |r_j|)`.
    worst: f64,
}

struct Checker {
    functions: BTreeMap<&'static str, (CFunction, Stats)>,
    failures: Vec<String>,
}

impl Checker {
    fn new() -> Self {
        Self {
            functions: BTreeMap::new(),
            failures: Vec::new(),
        }
    }

    fn check(&mut self, name: &str, inputs: &[&[f64]], rust: &impl Flatten) {
        let mut expected = Vec::new();
        rust.flatten_into(&mut expected);
        let sym = Symbols::find(name).unwrap_or_else(|| panic!("no C function `{name}`"));
        let (f, stats) = self.functions.entry(sym.name()).or_insert_with(|| {
            (
                CFunction::from_symbols(sym).expect("supported interface"),
                Stats::default(),
            )
        });
        assert_eq!(f.output_len(), expected.len(), "{name}: output length");
        let mut got = vec![f64::NAN; expected.len()];
        f.call(inputs, &mut got).unwrap_or_else(|e| panic!("{e}"));

        let scale = expected.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
        stats.calls += 1;
        for (j, (&c, &r)) in got.iter().zip(&expected).enumerate() {
            stats.elements += 1;
            if c.to_bits() == r.to_bits() {
                stats.bit_equal += 1;
                continue;
            }
            let denom = r.abs().max(scale);
            let err = if denom > 0.0 {
                (c - r).abs() / denom
            } else {
                (c - r).abs()
            };
            stats.worst = stats.worst.max(err);
            if err.is_nan() || err > TOL {
                self.failures.push(format!(
                    "{name}: element {j}: C {c:e} vs Rust {r:e} (relative error {err:e}), \
                     inputs {inputs:?}"
                ));
            }
        }
    }

    /// Prints the statistics, checks every C function of `robot` (and `robot_parametric`)
    /// was compared, and fails on any disagreement.
    fn finish(self, robot: &str) {
        for (name, (_, s)) in &self.functions {
            println!(
                "{name:40} {:3} calls, {:5} elements, {:5.1}% bit-equal, worst relative error {:.2e}",
                s.calls,
                s.elements,
                100.0 * s.bit_equal as f64 / s.elements as f64,
                s.worst
            );
        }
        let all: Vec<&str> = Symbols::all()
            .iter()
            .filter(|s| s.file() == robot)
            .map(Symbols::name)
            .collect();
        let missed: Vec<&&str> = all
            .iter()
            .filter(|n| !self.functions.contains_key(*n))
            .collect();
        assert!(
            missed.is_empty(),
            "C functions of {robot} not compared: {missed:?}"
        );
        assert!(
            self.failures.is_empty(),
            "{} disagreements, first ones:\n{}",
            self.failures.len(),
            self.failures[..self.failures.len().min(20)].join("\n")
        );
    }
}

macro_rules! agree {
    ($test:ident, $robot:ident, $seed:literal) => {
        #[test]
        fn $test() {
            use armdyn_generated::$robot as g;
            use armdyn_generated::$robot::parametric as p;
            const N: usize = g::DOF;
            let name = |f: &str| format!("{}_{f}", stringify!($robot));
            let mut rng = Rng($seed);
            let mut checker = Checker::new();
            let standard = g::standard_parameters();
            checker.check(&name("standard_parameters"), &[], &standard);
            for _ in 0..STATES {
                let q: [f64; N] = core::array::from_fn(|i| {
                    let [lo, hi] = g::JOINT_LIMITS[i];
                    rng.uniform(lo, hi)
                });
                let qd: [f64; N] = core::array::from_fn(|_| rng.uniform(-2.0, 2.0));
                let qdd: [f64; N] = core::array::from_fn(|_| rng.uniform(-5.0, 5.0));
                // Standard parameters perturbed by up to +-30 %, plus up to +-0.05 so that
                // zero parameters (e.g. centred masses) exercise their terms too.
                let params: [f64; 10 * N] = core::array::from_fn(|i| {
                    standard[i] * rng.uniform(0.7, 1.3) + rng.uniform(-0.05, 0.05)
                });

                checker.check(&name("frame_poses"), &[&q], &g::frame_poses(&q));
                checker.check(&name("end_effector_pose"), &[&q], &g::end_effector_pose(&q));
                checker.check(&name("jacobian"), &[&q], &g::jacobian(&q));
                checker.check(
                    &name("jacobian_and_position"),
                    &[&q],
                    &g::jacobian_and_position(&q),
                );
                checker.check(&name("jdot_qd"), &[&q, &qd], &g::jdot_qd(&q, &qd));
                checker.check(&name("mass_matrix"), &[&q], &g::mass_matrix(&q));
                checker.check(
                    &name("coriolis_matrix"),
                    &[&q, &qd],
                    &g::coriolis_matrix(&q, &qd),
                );
                checker.check(&name("coriolis"), &[&q, &qd], &g::coriolis(&q, &qd));
                checker.check(&name("gravity"), &[&q], &g::gravity(&q));
                checker.check(
                    &name("inverse_dynamics"),
                    &[&q, &qd, &qdd],
                    &g::inverse_dynamics(&q, &qd, &qdd),
                );
                // qdd doubles as the torque input of forward dynamics.
                checker.check(
                    &name("forward_dynamics"),
                    &[&q, &qd, &qdd],
                    &g::forward_dynamics(&q, &qd, &qdd),
                );
                checker.check(
                    &name("mass_matrix_and_bias"),
                    &[&q, &qd],
                    &g::mass_matrix_and_bias(&q, &qd),
                );
                checker.check(
                    &name("jacobian_derivatives"),
                    &[&q],
                    &g::jacobian_derivatives(&q),
                );
                checker.check(
                    &name("inverse_dynamics_derivatives"),
                    &[&q, &qd, &qdd],
                    &g::inverse_dynamics_derivatives(&q, &qd, &qdd),
                );
                checker.check(
                    &name("forward_dynamics_derivatives"),
                    &[&q, &qd, &qdd],
                    &g::forward_dynamics_derivatives(&q, &qd, &qdd),
                );
                checker.check(
                    &name("regressor"),
                    &[&q, &qd, &qdd],
                    &g::regressor(&q, &qd, &qdd),
                );

                checker.check(
                    &name("parametric_mass_matrix"),
                    &[&q, &params],
                    &p::mass_matrix(&q, &params),
                );
                checker.check(
                    &name("parametric_coriolis_matrix"),
                    &[&q, &qd, &params],
                    &p::coriolis_matrix(&q, &qd, &params),
                );
                checker.check(
                    &name("parametric_coriolis"),
                    &[&q, &qd, &params],
                    &p::coriolis(&q, &qd, &params),
                );
                checker.check(
                    &name("parametric_gravity"),
                    &[&q, &params],
                    &p::gravity(&q, &params),
                );
                checker.check(
                    &name("parametric_inverse_dynamics"),
                    &[&q, &qd, &qdd, &params],
                    &p::inverse_dynamics(&q, &qd, &qdd, &params),
                );
                // Forward dynamics divides by pivots of M: a physical parameter set, each
                // link's parameters scaled by one factor (M stays positive definite).
                let factors: [f64; N] = core::array::from_fn(|_| rng.uniform(0.7, 1.3));
                let physical: [f64; 10 * N] =
                    core::array::from_fn(|i| standard[i] * factors[i / 10]);
                checker.check(
                    &name("parametric_forward_dynamics"),
                    &[&q, &qd, &qdd, &physical],
                    &p::forward_dynamics(&q, &qd, &qdd, &physical),
                );
            }
            checker.finish(stringify!($robot));
        }
    };
}

agree!(scara_c_agrees_with_rust, scara, 0x5CA7A);
agree!(puma560_c_agrees_with_rust, puma560, 0x9_0560);

/// The wrapper rejects wrong sizes instead of letting the C read or write out of bounds.
#[test]
fn sizes_are_checked() {
    let mut f = CFunction::new("scara_inverse_dynamics").unwrap();
    assert_eq!(f.input_lens(), [4, 4, 4]);
    assert_eq!(f.output_len(), 4);
    let x = [0.0; 4];
    let mut out = [0.0; 4];
    assert!(f.call(&[&x, &x], &mut out).is_err());
    assert!(f.call(&[&x, &x, &x[..3]], &mut out).is_err());
    assert!(f.call(&[&x, &x, &x], &mut out[..3]).is_err());
    f.call(&[&x, &x, &x], &mut out).unwrap();
    assert!(CFunction::new("scara_no_such_function").is_err());

    // The regressor's output is structurally sparse in CasADi; the wrapper scatters it.
    let r = CFunction::new("puma560_regressor").unwrap();
    assert_eq!(r.output_len(), 6 * 60);
    assert!(r.output_nnz() < r.output_len());
}

/// Counts `(flops, trig)` in the body of each function of a CasADi C file: the statements
/// `aN=(aI op aJ);` (op in `+ - * /`), `aN=(-aI);`, `aN=(1./aI);` and `aN=f(...)` for `f` in
/// `casadi_sq`, `sqrt`, `fabs` (flops) or `sin`, `cos`, `atan2` (trig), the same classes as
/// `OPERATION_COUNTS`. Keyed by the function's C name.
fn c_operation_counts(c: &str) -> BTreeMap<String, (u32, u32)> {
    let mut counts = BTreeMap::new();
    let mut current: Option<(String, u32, u32)> = None;
    for line in c.lines() {
        if let Some(rest) = line.strip_prefix("/* ") {
            // `/* scara_mass_matrix:(i0[4])->(o0[16]) */` precedes the body.
            if let Some((name, _)) = rest.split_once(":(") {
                current = Some((name.to_owned(), 0, 0));
            }
            continue;
        }
        let Some((_, flops, trig)) = current.as_mut() else {
            continue;
        };
        if line == "}" {
            let (name, flops, trig) = current.take().unwrap();
            counts.insert(name, (flops, trig));
            continue;
        }
        let Some((lhs, rhs)) = line.trim().split_once('=') else {
            continue;
        };
        if !lhs.starts_with('a') || !lhs[1..].bytes().all(|b| b.is_ascii_digit()) {
            continue;
        }
        let rhs = rhs.trim_end_matches(';');
        if let Some(inner) = rhs.strip_prefix('(').and_then(|r| r.strip_suffix(')')) {
            let is_var = |s: &str| s.starts_with('a') && s[1..].bytes().all(|b| b.is_ascii_digit());
            let binary = ['+', '-', '*', '/'].iter().any(|&op| {
                inner
                    .split_once(op)
                    .is_some_and(|(x, y)| (is_var(x) || x == "1.") && is_var(y))
            });
            let negation = inner.strip_prefix('-').is_some_and(is_var);
            assert!(binary || negation, "unexpected expression `{line}`");
            *flops += 1;
        } else if let Some((f, _)) = rhs.split_once('(') {
            match f {
                "casadi_sq" | "sqrt" | "fabs" => *flops += 1,
                "sin" | "cos" | "atan2" => *trig += 1,
                _ => panic!("unexpected call `{line}`"),
            }
        }
    }
    counts
}

/// The table of `bench_table` quotes `OPERATION_COUNTS` for the C too: check that CasADi's C
/// performs exactly those operations (same graph, same counts).
#[test]
fn c_operation_counts_match_rust() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../../generated/casadi_c");
    type Counts = &'static [(&'static str, u32, u32)];
    let models: [(&str, &str, Counts); 4] = [
        (
            "scara",
            "scara_",
            &armdyn_generated::scara::OPERATION_COUNTS,
        ),
        (
            "scara",
            "scara_parametric_",
            &armdyn_generated::scara::parametric::OPERATION_COUNTS,
        ),
        (
            "puma560",
            "puma560_",
            &armdyn_generated::puma560::OPERATION_COUNTS,
        ),
        (
            "puma560",
            "puma560_parametric_",
            &armdyn_generated::puma560::parametric::OPERATION_COUNTS,
        ),
    ];
    for (file, prefix, rust) in models {
        let c = std::fs::read_to_string(format!("{dir}/{file}.c")).unwrap();
        let c = c_operation_counts(&c);
        for &(function, flops, trig) in rust {
            let name = format!("{prefix}{function}");
            assert_eq!(
                c.get(&name),
                Some(&(flops, trig)),
                "{name}: C (flops, trig) vs Rust"
            );
        }
    }
}
