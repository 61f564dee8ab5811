//! The project's side of `benches/pinocchio/compare.py`: times the generated `M + c + g`,
//! forward dynamics and inverse dynamics of one robot over a states file, with the same loop
//! as the C++ side, and prints a few results for the script to check against Pinocchio's.
//!
//! `M + c + g` (`mcg`) is one call of `mass_matrix_and_bias`, the generated `[M | c + g]`
//! (the pair Pinocchio's `crba` and `nonLinearEffects` compute); `mcg3` times the three
//! separate functions `mass_matrix`, `coriolis` and `gravity` for comparison. `did` and
//! `dfd` time the generated `inverse_dynamics_derivatives` and `forward_dynamics_derivatives`
//! (the outputs of Pinocchio's `computeRNEADerivatives` and `computeABADerivatives`:
//! `d/dq`, `d/dqd` and `M`, respectively `M^-1`).
//!
//! Usage: `cargo run --release --example pinocchio_side -- ROBOT STATES REPS`.
//! Output lines: `time <function> <ns per call>`, `value <function> <state> <numbers...>`.

use std::hint::black_box;
use std::time::Instant;

fn time_ns(reps: usize, states: usize, mut f: impl FnMut(usize)) -> f64 {
    let start = Instant::now();
    for _ in 0..reps {
        for s in 0..states {
            f(s);
        }
    }
    start.elapsed().as_nanos() as f64 / (reps * states) as f64
}

fn print(name: &str, s: usize, values: &[f64]) {
    let text: Vec<String> = values.iter().map(|v| format!("{v:e}")).collect();
    println!("value {name} {s} {}", text.join(" "));
}

macro_rules! run {
    ($module:ident, $n:literal, $states:expr, $reps:expr) => {{
        use armdyn_generated::$module as g;
        let states: Vec<[[f64; $n]; 3]> = $states
            .iter()
            .map(|s: &Vec<f64>| core::array::from_fn(|k| core::array::from_fn(|i| s[k * $n + i])))
            .collect();
        let count = states.len();
        let mcg = time_ns($reps, count, |s| {
            let [q, qd, _] = &states[s];
            black_box(g::mass_matrix_and_bias(black_box(q), black_box(qd)));
        });
        let mcg3 = time_ns($reps, count, |s| {
            let [q, qd, _] = &states[s];
            black_box(g::mass_matrix(black_box(q)));
            black_box(g::coriolis(black_box(q), black_box(qd)));
            black_box(g::gravity(black_box(q)));
        });
        let fd = time_ns($reps, count, |s| {
            let [q, qd, tau] = &states[s];
            black_box(g::forward_dynamics(
                black_box(q),
                black_box(qd),
                black_box(tau),
            ));
        });
        let id = time_ns($reps, count, |s| {
            let [q, qd, qdd] = &states[s];
            black_box(g::inverse_dynamics(
                black_box(q),
                black_box(qd),
                black_box(qdd),
            ));
        });
        let did = time_ns($reps, count, |s| {
            let [q, qd, qdd] = &states[s];
            black_box(g::inverse_dynamics_derivatives(
                black_box(q),
                black_box(qd),
                black_box(qdd),
            ));
        });
        let dfd = time_ns($reps, count, |s| {
            let [q, qd, tau] = &states[s];
            black_box(g::forward_dynamics_derivatives(
                black_box(q),
                black_box(qd),
                black_box(tau),
            ));
        });
        println!("time mcg {mcg:.3}\ntime mcg3 {mcg3:.3}\ntime fd {fd:.3}\ntime id {id:.3}");
        println!("time did {did:.3}\ntime dfd {dfd:.3}");
        for (s, [q, qd, u]) in states.iter().enumerate().take(3) {
            // Column-major like Eigen's: M is symmetric, so row-major is the same.
            let rows = g::mass_matrix_and_bias(q, qd);
            let m: Vec<f64> = rows.iter().flat_map(|row| &row[..$n]).copied().collect();
            print("mass_matrix", s, &m);
            let bias: Vec<f64> = rows.iter().map(|row| row[$n]).collect();
            print("bias", s, &bias);
            print("forward_dynamics", s, &g::forward_dynamics(q, qd, u));
            print("inverse_dynamics", s, &g::inverse_dynamics(q, qd, u));
            // Row-major [d/dq | d/dqd] (n x 2n), the first 2n columns of the generated rows.
            let first = |rows: &[[f64; 3 * $n]; $n]| -> Vec<f64> {
                rows.iter()
                    .flat_map(|row| &row[..2 * $n])
                    .copied()
                    .collect()
            };
            let did = g::inverse_dynamics_derivatives(q, qd, u);
            print("inverse_dynamics_derivatives", s, &first(&did));
            let dfd = g::forward_dynamics_derivatives(q, qd, u);
            print("forward_dynamics_derivatives", s, &first(&dfd));
        }
    }};
}

fn main() -> Result<(), String> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [robot, path, reps] = args.as_slice() else {
        return Err("usage: pinocchio_side ROBOT STATES REPS".into());
    };
    let reps: usize = reps.parse().map_err(|e| format!("REPS: {e}"))?;
    let text = std::fs::read_to_string(path).map_err(|e| format!("{path}: {e}"))?;
    let mut numbers = text.split_whitespace().map(str::parse::<f64>);
    let count = numbers
        .next()
        .ok_or("empty states file")?
        .map_err(|e| e.to_string())? as usize;
    let rest: Vec<f64> = numbers
        .collect::<Result<_, _>>()
        .map_err(|e| format!("{path}: {e}"))?;
    if count == 0 || !rest.len().is_multiple_of(3 * count) {
        return Err(format!("{path}: {} numbers for {count} states", rest.len()));
    }
    let states: Vec<Vec<f64>> = rest
        .chunks(rest.len() / count)
        .map(<[f64]>::to_vec)
        .collect();
    // Every robot of the generated registry.
    macro_rules! dispatch {
        ([] $(($module:ident, $ty:ident, $n:literal, $doc:literal))*) => {
            match robot.as_str() {
                $(stringify!($module) => run!($module, $n, states, reps),)*
                other => return Err(format!("unknown robot {other}")),
            }
        };
    }
    armdyn_generated::for_each_robot!(dispatch);
    Ok(())
}
