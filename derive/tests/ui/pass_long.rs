//! Function bodies longer than the chunk size (200 instructions) are emitted as blocks that
//! hand on the values later blocks read; the expansion compiles without warnings and computes
//! exactly what the instructions say, bit for bit.

#![deny(warnings, missing_docs)]

/// The long model.
pub mod long {
    armdyn_derive::robot_model!("tests/ui/pass_long.json");
}

/// `long::long`, one step at a time: after the three inputs, instruction `i` is by `i % 5` a
/// constant `0.25 + (i % 7) / 8`, `v[i-1] * v[i-2]`, `sin(v[i-1])`, `v[i-1] + v[i-200]`
/// (`v[0]` while `i < 200`) or `v[i-1] - v[i-3]`.
fn long_reference(x: &[f64; 3]) -> [[f64; 3]; 2] {
    let mut v = [0.0_f64; 450];
    for i in 0..450 {
        v[i] = match (i, i % 5) {
            (0..=2, _) => x[i],
            (_, 0) => 0.25 + (i % 7) as f64 * 0.125,
            (_, 1) => v[i - 1] * v[i - 2],
            (_, 2) => libm::sin(v[i - 1]),
            (_, 3) => v[i - 1] + v[if i >= 200 { i - 200 } else { 0 }],
            _ => v[i - 1] - v[i - 3],
        };
    }
    [[v[0], v[1], v[2]], [v[149], v[300], v[449]]]
}

/// `long::forms`: `x 0.5^132` (the only value the first block hands on), a block whose values
/// nothing reads, then 132 times `sin` of twice that.
fn forms_reference(x: f64) -> f64 {
    let mut a = x;
    for _ in 0..132 {
        a *= 0.5;
    }
    let mut b = a + a;
    for _ in 0..132 {
        b = libm::sin(b);
    }
    b
}

fn main() {
    for x in [[0.3, -1.2, 2.5], [0.0, 0.0, 0.0], [-2.0, 0.7, 1e-3]] {
        let got = long::long(&x);
        let want = long_reference(&x);
        assert_eq!(got.map(|row| row.map(f64::to_bits)), want.map(|row| row.map(f64::to_bits)));
    }
    for x in [1.5, -0.25, 3.0] {
        assert_eq!(long::forms(&[x])[0].to_bits(), forms_reference(x).to_bits());
        assert_eq!(long::limit(&[x]), [x * 2f64.powi(199)]);
    }
    assert_eq!(
        long::OPERATION_COUNTS,
        [("long", 269, 89), ("forms", 133, 265), ("limit", 199, 0)]
    );
}
