//! Phase 2: check every rule of `derive/FORMAT.md` and decode the instructions.
//!
//! This module holds the rules on the robot, the provenance, the functions and their names;
//! the instruction set and the decoding of one instruction are in [`crate::instruction`].
//!
//! All problems are collected, each as one message that says what is wrong and where
//! ("function `mass_matrix`, instruction 12: ..."), so one compile shows them all. Nothing
//! here panics: every index is checked before it is used, and the expansion only runs on a
//! model that passed.

use crate::instruction::{decode, Op};
use crate::message::truncate;
use crate::parse::{Function, Model};

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
    "TASK_ROWS",
    "OPERATION_COUNTS",
];

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
    if let Some(task) = &robot.task {
        if task.is_empty() {
            errors.push("`robot.task` must name at least one row".to_owned());
        }
        if let Some(row) = task.iter().find(|&&row| row > 5) {
            errors.push(format!(
                "`robot.task`: row {row} is not a row of the 6-row geometric Jacobian (0 to 5)"
            ));
        }
        if task.windows(2).any(|w| w[0] >= w[1]) {
            errors.push(format!(
                "`robot.task` ({task:?}) must be strictly increasing"
            ));
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

#[cfg(test)]
mod tests {
    use super::*;

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
