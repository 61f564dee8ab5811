//! Prints the operation counts of the generated functions as a Markdown table: floating-point
//! operations + sin/cos calls per function, one column per robot.
//!
//! `cargo run --release --example operation_counts -- scara puma560 ur5 panda`
//! (no robot names: every robot of the registry).

use armdyn::model::{RobotModel, ROBOTS};

/// The functions shown, in this order, with how the table names them.
const FUNCTIONS: [(&str, &str); 13] = [
    ("mass_matrix", "`mass_matrix`"),
    ("coriolis", "`coriolis` (`C qd`)"),
    ("gravity", "`gravity`"),
    ("coriolis_matrix", "`coriolis_matrix`"),
    ("inverse_dynamics", "`inverse_dynamics`"),
    ("forward_dynamics", "`forward_dynamics`"),
    (
        "mass_matrix_and_bias",
        "`mass_matrix_and_bias` (`[M \\| c + g]`)",
    ),
    ("jacobian", "`jacobian`"),
    ("end_effector_pose", "`end_effector_pose`"),
    ("regressor", "`regressor`"),
    (
        "inverse_dynamics_derivatives",
        "`inverse_dynamics_derivatives` (`d tau/d (q, qd)`, `M`)",
    ),
    (
        "forward_dynamics_derivatives",
        "`forward_dynamics_derivatives` (`d qdd/d (q, qd)`, `M^-1`)",
    ),
    (
        "jacobian_derivatives",
        "`jacobian_derivatives` (`d J/d q_k`)",
    ),
];

fn main() {
    let mut names: Vec<String> = std::env::args().skip(1).collect();
    if names.is_empty() {
        names = ROBOTS.iter().map(|s| s.to_string()).collect();
    }
    let mut columns = Vec::new();
    for name in &names {
        match armdyn::with_robot_named!(name.as_str(), |_robot: R, N, _module| R::OPERATION_COUNTS)
        {
            Some(c) => columns.push(c),
            None => {
                eprintln!("error: no robot `{name}`; known: {}", ROBOTS.join(", "));
                std::process::exit(2);
            }
        }
    }
    println!("| function | {} |", names.join(" | "));
    println!("| :-- |{}", " --: |".repeat(names.len()));
    for (function, shown) in FUNCTIONS {
        let cells: Vec<String> = columns
            .iter()
            .map(|c| match c.iter().find(|(f, _, _)| *f == function) {
                Some((_, flops, trig)) => format!("{flops} + {trig}"),
                None => "-".to_string(),
            })
            .collect();
        println!("| {shown} | {} |", cells.join(" | "));
    }
}
