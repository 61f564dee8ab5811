//! The instruction set of `FORMAT.md` (`input`, `const`, the one- and two-operand operations)
//! and the decoding of one raw JSON instruction into an [`Op`], checking its operands, its
//! input ranges and its constant's text.

use crate::message::truncate;
use crate::parse::Input;
use serde_json::Value;

/// Longest constant text accepted (Python's `repr` never needs more than 24 characters).
const MAX_CONST_LEN: usize = 64;

/// A one-operand operation.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Unary {
    Neg,
    Sq,
    Twice,
    Inv,
    Sqrt,
    Sin,
    Cos,
    Fabs,
}

/// A two-operand operation.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Binary {
    Add,
    Sub,
    Mul,
    Div,
    Atan2,
}

/// One decoded, checked instruction. Operands are indices of earlier instructions.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) enum Op {
    /// Element `elem` of input `arg`.
    Input {
        arg: usize,
        elem: usize,
    },
    /// A finite constant; the text is exactly as in the file (it round-trips).
    Const(String),
    Unary(Unary, usize),
    Binary(Binary, usize, usize),
}

impl Op {
    /// `(flops, trig)` contributed by this instruction, as `counts` defines them.
    pub(crate) fn cost(&self) -> (u64, u64) {
        match self {
            Op::Input { .. } | Op::Const(_) => (0, 0),
            Op::Unary(Unary::Sin | Unary::Cos, _) | Op::Binary(Binary::Atan2, _, _) => (0, 1),
            Op::Unary(..) | Op::Binary(..) => (1, 0),
        }
    }
}

const UNARY: &[(&str, Unary)] = &[
    ("neg", Unary::Neg),
    ("sq", Unary::Sq),
    ("twice", Unary::Twice),
    ("inv", Unary::Inv),
    ("sqrt", Unary::Sqrt),
    ("sin", Unary::Sin),
    ("cos", Unary::Cos),
    ("fabs", Unary::Fabs),
];

const BINARY: &[(&str, Binary)] = &[
    ("add", Binary::Add),
    ("sub", Binary::Sub),
    ("mul", Binary::Mul),
    ("div", Binary::Div),
    ("atan2", Binary::Atan2),
];

const KNOWN_OPS: &str =
    "input, const, neg, sq, twice, inv, sqrt, sin, cos, fabs, add, sub, mul, div, atan2";

/// Decodes instruction `i`, checking operand indices and input ranges.
pub(crate) fn decode(raw: &Value, i: usize, inputs: &[Input]) -> Result<Op, Vec<String>> {
    let Some(items) = raw.as_array() else {
        return Err(vec![format!(
            "must be an array such as [\"add\", 3, 4], found {}",
            short(raw)
        )]);
    };
    let Some(first) = items.first() else {
        return Err(vec!["is an empty array".to_owned()]);
    };
    let Some(name) = first.as_str() else {
        return Err(vec![format!(
            "the first element must be the operation name, found {}",
            short(first)
        )]);
    };
    let args = &items[1..];
    let arity = |n: usize| -> Result<(), Vec<String>> {
        if args.len() == n {
            Ok(())
        } else {
            Err(vec![format!(
                "`{name}` takes {n} operand{}, found {}",
                if n == 1 { "" } else { "s" },
                args.len()
            )])
        }
    };

    match name {
        "input" => {
            arity(2)?;
            let (arg, elem) = (index(&args[0], "input number"), index(&args[1], "element"));
            let (arg, elem) = both(arg, elem)?;
            let Some(input) = inputs.get(arg) else {
                return Err(vec![format!(
                    "input number {arg} is out of range (the function has {} input{})",
                    inputs.len(),
                    if inputs.len() == 1 { "" } else { "s" }
                )]);
            };
            if elem >= input.len {
                return Err(vec![format!(
                    "element {elem} of input `{}` is out of range (its length is {})",
                    input.name, input.len
                )]);
            }
            Ok(Op::Input { arg, elem })
        }
        "const" => {
            arity(1)?;
            let Some(text) = args[0].as_str() else {
                return Err(vec![format!(
                    "`const` takes the number as a string such as \"1.25\", found {}",
                    short(&args[0])
                )]);
            };
            check_const(text).map_err(|problem| vec![problem])?;
            Ok(Op::Const(text.to_owned()))
        }
        _ => {
            if let Some(&(_, op)) = UNARY.iter().find(|(n, _)| *n == name) {
                arity(1)?;
                let x = operand(&args[0], 0, i).map_err(|e| vec![e])?;
                Ok(Op::Unary(op, x))
            } else if let Some(&(_, op)) = BINARY.iter().find(|(n, _)| *n == name) {
                arity(2)?;
                let (x, y) = both(operand(&args[0], 0, i), operand(&args[1], 1, i))?;
                Ok(Op::Binary(op, x, y))
            } else {
                Err(vec![format!(
                    "unknown operation `{}` (known: {KNOWN_OPS})",
                    truncate(name)
                )])
            }
        }
    }
}

/// Combines two fallible values, keeping both errors.
fn both<A, B>(a: Result<A, String>, b: Result<B, String>) -> Result<(A, B), Vec<String>> {
    match (a, b) {
        (Ok(a), Ok(b)) => Ok((a, b)),
        (a, b) => Err(a.err().into_iter().chain(b.err()).collect()),
    }
}

/// A non-negative integer index.
fn index(value: &Value, what: &str) -> Result<usize, String> {
    value
        .as_u64()
        .and_then(|n| usize::try_from(n).ok())
        .ok_or_else(|| {
            format!(
                "{what} must be a non-negative integer, found {}",
                short(value)
            )
        })
}

/// Operand `k` of instruction `i`: an index of an earlier instruction.
fn operand(value: &Value, k: usize, i: usize) -> Result<usize, String> {
    let x = index(value, &format!("operand {k}"))?;
    if x < i {
        Ok(x)
    } else {
        Err(format!(
            "operand {x} refers to a later or missing instruction (operands must be < {i})"
        ))
    }
}

/// Checks that `text` is a plain decimal literal (`-?D+(.D+)?([eE][+-]?D+)?`) of a finite
/// `f64` that round-trips exactly: its significant digits and decimal exponent are those of
/// the shortest text that reads back as the same `f64` (what Python's `repr` writes; trailing
/// zeros and the choice between `0.001` and `1e-3` do not matter). This rejects overflow
/// (`1e400`), underflow (`1e-400`) and digits the value does not carry
/// (`0.10000000000000001`, which reads as the same `f64` as `0.1`).
fn check_const(text: &str) -> Result<f64, String> {
    let shown = truncate(text);
    if text.len() > MAX_CONST_LEN {
        return Err(format!(
            "constant \"{shown}\" is longer than {MAX_CONST_LEN} characters"
        ));
    }
    let syntax = || {
        format!(
            "constant \"{shown}\" is not a plain decimal number such as \"-1.25\" or \"6.02e+23\""
        )
    };
    let body = text.strip_prefix('-').unwrap_or(text);
    let (mantissa, exponent) = match body.find(['e', 'E']) {
        Some(at) => (&body[..at], Some(&body[at + 1..])),
        None => (body, None),
    };
    let (int, frac) = match mantissa.split_once('.') {
        Some((int, frac)) => (int, Some(frac)),
        None => (mantissa, None),
    };
    let digits = |s: &str| !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit());
    if !digits(int) || !frac.is_none_or(digits) {
        return Err(syntax());
    }
    let exp10: i64 = match exponent {
        None => 0,
        Some(e) => {
            let unsigned = e.strip_prefix(['+', '-']).unwrap_or(e);
            if !digits(unsigned) {
                return Err(syntax());
            }
            e.parse()
                .map_err(|_| format!("constant \"{shown}\" has an exponent out of range"))?
        }
    };
    let value: f64 = text.parse().map_err(|_| syntax())?;
    if !value.is_finite() {
        return Err(format!("constant \"{shown}\" is not a finite f64"));
    }

    let all_digits = format!("{int}{}", frac.unwrap_or(""));
    let significant = all_digits.trim_start_matches('0');
    if significant.is_empty() {
        return Ok(value); // a zero, exactly representable
    }
    // Lengths are at most MAX_CONST_LEN, so they fit an i64.
    let length = |s: &str| i64::try_from(s.len()).unwrap_or(i64::MAX);
    let leading_zeros = length(&all_digits) - length(significant);
    let scientific_exp = length(int) - 1 - leading_zeros + exp10;
    let significant = significant.trim_end_matches('0');
    // `{:e}` writes the shortest digits that read back as `value`, in scientific form.
    let shortest = format!("{:e}", value.abs());
    let round_trips = shortest.split_once('e').is_some_and(|(m, e)| {
        m.chars().filter(|c| *c != '.').eq(significant.chars())
            && e.parse::<i64>() == Ok(scientific_exp)
    });
    if round_trips {
        Ok(value)
    } else {
        Err(format!(
            "constant \"{shown}\" does not round-trip: it reads as the f64 whose shortest exact \
             form is {shortest} (write constants with Python's `repr`)"
        ))
    }
}

/// A JSON value for a message, cut short.
fn short(value: &Value) -> String {
    truncate(&value.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn constants() {
        for good in [
            "0",
            "-0.0",
            "2",
            "2.0",
            "1.25",
            "-1.5",
            "1e-20",
            "6.02e+23",
            "1E5",
            "2.33736",
            "0.1",
            "0.001",
            "100",
            "1000.0",
            "2.000",
            "5e-324",
            "1e-320",
            "1.7976931348623157e+308",
            "3.141592653589793",
            "-9.81",
            "0.6220166666666667",
            "0.30000000000000004",
            "3.0000000000000004e-1",
        ] {
            assert!(check_const(good).is_ok(), "{good}: {:?}", check_const(good));
        }
        for bad in [
            "",
            "-",
            ".5",
            "5.",
            "1e",
            "1e+",
            "+1",
            "inf",
            "NaN",
            "1_0",
            "0x10",
            " 1",
            "1e400",
            "-1e400",
            "1e-400",
            "0.10000000000000000000001",
            "9.99999999999999999999",
            "1e99999999999999999999",
            "2.3373600000000001",
            "9.8100000000000005",
            "0.30000000000000005",
            "3.1415926535897932",
        ] {
            assert!(check_const(bad).is_err(), "{bad} accepted");
        }
    }
}
