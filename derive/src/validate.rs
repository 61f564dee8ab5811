//! Phase 2: check every rule of `derive/FORMAT.md` and decode the instructions.
//!
//! All problems are collected, each as one message that says what is wrong and where
//! ("function `mass_matrix`, instruction 12: ..."), so one compile shows them all. Nothing
//! here panics: every index is checked before it is used, and the expansion only runs on a
//! model that passed.

use crate::parse::{Function, Input, Model};
use serde_json::Value;

/// Names of the items the expansion emits next to the functions; a function or an input of
/// that name would clash with them.
pub(crate) const RESERVED_ITEMS: &[&str] = &[
    "ROBOT_NAME",
    "DESCRIPTION",
    "DOF",
    "GENERATOR",
    "CASADI_VERSION",
    "SOURCE",
    "SOURCE_SHA256",
    "JOINT_NAMES",
    "JOINT_IS_PRISMATIC",
    "JOINT_LIMITS",
    "EFFORT_LIMITS",
    "GRAVITY",
    "OPERATION_COUNTS",
];

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
    fn cost(&self) -> (u64, u64) {
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

/// Checks the whole model. On success returns the decoded instructions of every function, in
/// file order; on failure every problem found.
pub(crate) fn validate(model: &Model) -> Result<Vec<Vec<Op>>, Vec<String>> {
    let mut errors = Vec::new();
    check_robot(model, &mut errors);
    check_provenance(model, &mut errors);

    let mut programs = Vec::with_capacity(model.functions.len());
    for (index, function) in model.functions.iter().enumerate() {
        let unique = model
            .functions
            .iter()
            .filter(|other| other.name == function.name)
            .count()
            == 1;
        let label = if unique && is_identifier(&function.name) {
            format!("function `{}`", function.name)
        } else {
            format!("function {index} ({:?})", truncate(&function.name))
        };
        if let Some(problem) = identifier_problem(&function.name) {
            errors.push(format!("{label}: name {problem}"));
        } else if RESERVED_ITEMS.contains(&function.name.as_str()) {
            errors.push(format!(
                "{label}: name clashes with the constant `{}` the macro emits",
                function.name
            ));
        }
        if let Some(first) = model.functions[..index]
            .iter()
            .position(|other| other.name == function.name)
        {
            errors.push(format!(
                "{label}: duplicate function name (also function {first})"
            ));
        }
        programs.push(check_function(function, &label, &mut errors));
    }

    if errors.is_empty() {
        Ok(programs)
    } else {
        Err(errors)
    }
}

fn check_robot(model: &Model, errors: &mut Vec<String>) {
    let robot = &model.robot;
    if !is_snake_case(&robot.name) {
        errors.push(format!(
            "`robot.name` {:?} must be a snake-case Rust identifier (`[a-z_][a-z0-9_]*`, not a keyword)",
            robot.name
        ));
    }
    if robot.joints.is_empty() {
        errors.push("`robot.joints` is empty: a robot needs at least one joint".to_owned());
    }
    if robot.dof != robot.joints.len() {
        errors.push(format!(
            "`robot.dof` is {} but `robot.joints` lists {} joints",
            robot.dof,
            robot.joints.len()
        ));
    }
    for (j, joint) in robot.joints.iter().enumerate() {
        let at = format!("robot.joints[{j}] ({:?})", joint.name);
        if joint.name.is_empty() {
            errors.push(format!("{at}: `name` is empty"));
        }
        if let Some(first) = robot.joints[..j].iter().position(|o| o.name == joint.name) {
            errors.push(format!(
                "{at}: duplicate joint name (also robot.joints[{first}])"
            ));
        }
        for (key, value) in [
            ("lower", joint.lower),
            ("upper", joint.upper),
            ("effort", joint.effort),
        ] {
            if !value.is_finite() {
                errors.push(format!("{at}: `{key}` is not finite"));
            }
        }
        if joint.lower.is_finite() && joint.upper.is_finite() && joint.lower > joint.upper {
            errors.push(format!(
                "{at}: `lower` ({}) must not exceed `upper` ({})",
                joint.lower, joint.upper
            ));
        }
        if joint.effort.is_finite() && joint.effort <= 0.0 {
            errors.push(format!(
                "{at}: `effort` ({}) must be positive",
                joint.effort
            ));
        }
    }
    for (k, g) in robot.gravity.iter().enumerate() {
        if !g.is_finite() {
            errors.push(format!("`robot.gravity[{k}]` is not finite"));
        }
    }
}

fn check_provenance(model: &Model, errors: &mut Vec<String>) {
    let p = &model.provenance;
    for (key, value) in [
        ("generator", &p.generator),
        ("casadi", &p.casadi),
        ("source", &p.source),
    ] {
        if value.trim().is_empty() {
            errors.push(format!("`provenance.{key}` is empty"));
        }
    }
    let hash = &p.source_sha256;
    if hash.len() != 64
        || !hash
            .bytes()
            .all(|b| b.is_ascii_digit() || (b'a'..=b'f').contains(&b))
    {
        errors.push(format!(
            "`provenance.source_sha256` must be 64 lowercase hex digits, found {:?}",
            truncate(hash)
        ));
    }
}

/// Checks one function and decodes its instructions (`None` entries are dropped: the function
/// has errors then and its program is never expanded).
fn check_function(function: &Function, label: &str, errors: &mut Vec<String>) -> Vec<Op> {
    for (a, input) in function.inputs.iter().enumerate() {
        let at = format!("{label}, input {a}");
        if let Some(problem) = identifier_problem(&input.name) {
            errors.push(format!("{at}: name {problem}"));
        } else if is_local_name(&input.name) {
            errors.push(format!(
                "{at}: name `{}` is reserved for the generated locals (`v0`, `v1`, ...)",
                input.name
            ));
        } else if RESERVED_ITEMS.contains(&input.name.as_str()) {
            errors.push(format!(
                "{at}: name clashes with the constant `{}` the macro emits",
                input.name
            ));
        }
        if let Some(first) = function.inputs[..a]
            .iter()
            .position(|o| o.name == input.name)
        {
            errors.push(format!(
                "{at}: duplicate input name `{}` (also input {first})",
                input.name
            ));
        }
        if input.len == 0 {
            errors.push(format!("{at} (`{}`): `len` must be at least 1", input.name));
        }
    }

    let shape = &function.output.shape;
    let mut expected_len = Some(1usize);
    if shape.is_empty() || shape.len() > 3 {
        errors.push(format!(
            "{label}: output shape must have 1 to 3 dimensions, found {}",
            shape.len()
        ));
        expected_len = None;
    }
    for (d, &n) in shape.iter().enumerate() {
        if n == 0 {
            errors.push(format!(
                "{label}: output shape {shape:?} has dimension {d} equal to 0; dimensions must be positive"
            ));
            expected_len = None;
        }
        expected_len = expected_len.and_then(|len| len.checked_mul(n));
    }
    if expected_len.is_none() && !shape.is_empty() && shape.len() <= 3 && !shape.contains(&0) {
        errors.push(format!(
            "{label}: output shape {shape:?} is too large (more elements than a usize counts)"
        ));
    }
    if let Some(len) = expected_len {
        if function.result.len() != len {
            errors.push(format!(
                "{label}: `result` has {} elements but output shape {shape:?} needs {len}",
                function.result.len()
            ));
        }
    }

    let mut program = Vec::with_capacity(function.instructions.len());
    let mut all_decoded = true;
    for (i, raw) in function.instructions.iter().enumerate() {
        match decode(raw, i, &function.inputs) {
            Ok(op) => program.push(op),
            Err(problems) => {
                all_decoded = false;
                for problem in problems {
                    errors.push(format!("{label}, instruction {i}: {problem}"));
                }
            }
        }
    }

    let count = function.instructions.len();
    for (k, &index) in function.result.iter().enumerate() {
        if index >= count {
            errors.push(format!(
                "{label}, result element {k}: instruction {index} does not exist (the function has {count} instructions)"
            ));
        }
    }

    if all_decoded {
        let (flops, trig) = program.iter().fold((0u64, 0u64), |(f, t), op| {
            let (df, dt) = op.cost();
            (f + df, t + dt)
        });
        let counts = &function.counts;
        if u64::from(counts.flops) != flops || u64::from(counts.trig) != trig {
            errors.push(format!(
                "{label}: `counts` say {} flops and {} trig calls, but the instructions have {flops} flops and {trig} trig calls",
                counts.flops, counts.trig
            ));
        }
    }
    program
}

/// Decodes instruction `i`, checking operand indices and input ranges.
fn decode(raw: &Value, i: usize, inputs: &[Input]) -> Result<Op, Vec<String>> {
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

/// `v` followed by digits: the names of the generated locals.
pub(crate) fn is_local_name(name: &str) -> bool {
    name.strip_prefix('v')
        .is_some_and(|rest| !rest.is_empty() && rest.bytes().all(|b| b.is_ascii_digit()))
}

fn is_identifier(name: &str) -> bool {
    identifier_problem(name).is_none()
}

/// Why `name` cannot be used as a plain (non-raw) Rust identifier, if it cannot.
pub(crate) fn identifier_problem(name: &str) -> Option<String> {
    let mut chars = name.chars();
    let Some(first) = chars.next() else {
        return Some("is empty; it must be a Rust identifier".to_owned());
    };
    let shown = truncate(name);
    if !(first.is_ascii_alphabetic() || first == '_')
        || !chars.all(|c| c.is_ascii_alphanumeric() || c == '_')
    {
        return Some(format!(
            "{shown:?} is not a Rust identifier (ASCII letters, digits and `_`, not starting with a digit)"
        ));
    }
    if name == "_" || syn::parse_str::<syn::Ident>(name).is_err() {
        return Some(format!(
            "{shown:?} is a Rust keyword or reserved word; it cannot be an identifier"
        ));
    }
    None
}

fn is_snake_case(name: &str) -> bool {
    is_identifier(name)
        && name
            .bytes()
            .all(|b| b.is_ascii_lowercase() || b.is_ascii_digit() || b == b'_')
}

/// At most 40 characters of `s`, for messages.
fn truncate(s: &str) -> String {
    const MAX: usize = 40;
    if s.chars().count() <= MAX {
        s.to_owned()
    } else {
        let head: String = s.chars().take(MAX).collect();
        format!("{head}...")
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

    #[test]
    fn identifiers() {
        for good in ["q", "qd", "mass_matrix", "_x", "q2", "Q"] {
            assert!(identifier_problem(good).is_none(), "{good}");
        }
        for bad in [
            "", "_", "2q", "fn", "self", "Self", "crate", "q-d", "é", "r#q",
        ] {
            assert!(identifier_problem(bad).is_some(), "{bad}");
        }
        assert!(is_local_name("v0") && is_local_name("v12"));
        assert!(!is_local_name("v") && !is_local_name("vel") && !is_local_name("v1a"));
    }
}
