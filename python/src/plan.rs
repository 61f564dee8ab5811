//! `armdyn.plan` and `armdyn.plan_terminal_cost`: optimised joint moves of any robot
//! (`armdyn::optimal`), as a dict of numpy arrays and figures.

use std::time::Instant;

use armdyn::model::{DynamicsDerivatives, JointVector};
use armdyn::optimal::{
    optimise_move, optimise_with_terminal_cost, shortest_move, IlqrOptions, MoveProblem,
    OptimalMove,
};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::inputs::{output, states, vector};

/// What Python asked for, read and checked except for what the planner checks itself.
struct Request {
    from: Vec<f64>,
    to: Vec<f64>,
    duration: f64,
    step: f64,
    substeps: usize,
    effort_share: f64,
    limit_margin: f64,
    max_speed: Option<Vec<f64>>,
    /// `None`: the goal as a constraint (`plan`); else the terminal weight, the initial
    /// torques (row-major, one row per knot step) and the iteration cap.
    terminal: Option<(f64, Vec<f64>, usize)>,
    shortest: bool,
}

/// The move's start, goal, duration, knot step, RK4 steps per knot step and effort share.
type Move<'a, 'py> = (
    &'a Bound<'py, PyAny>,
    &'a Bound<'py, PyAny>,
    f64,
    f64,
    usize,
    f64,
);

/// A request for a robot of `n` joints, the start and goal read and checked.
fn request(
    n: usize,
    (q_from, q_to, duration, step, substeps, effort_share): Move<'_, '_>,
    limit_margin: f64,
    max_speed: Option<Vec<f64>>,
    terminal: Option<(f64, Vec<f64>, usize)>,
    shortest: bool,
) -> PyResult<Request> {
    Ok(Request {
        from: vector(q_from, "q_from", n)?,
        to: vector(q_to, "q_to", n)?,
        duration,
        step,
        substeps,
        effort_share,
        limit_margin,
        max_speed,
        terminal,
        shortest,
    })
}

fn joint_vector<const N: usize>(x: &[f64]) -> JointVector<N> {
    JointVector::<N>::from_column_slice(x)
}

/// The plan's knots and figures into `d`.
fn fill<'py, const N: usize>(
    py: Python<'py>,
    d: &Bound<'py, PyDict>,
    m: &OptimalMove<N>,
    solve_s: f64,
) -> PyResult<()> {
    let knots = m.q.len();
    let rows =
        |v: &[JointVector<N>]| -> Vec<f64> { v.iter().flat_map(|x| x.iter().copied()).collect() };
    let t: Vec<f64> = (0..knots).map(|k| k as f64 * m.step_s).collect();
    d.set_item("t", output(py, t, 1, false, &[knots])?)?;
    d.set_item("q", output(py, rows(&m.q), knots, true, &[N])?)?;
    d.set_item("qd", output(py, rows(&m.qd), knots, true, &[N])?)?;
    d.set_item("qdd", output(py, rows(&m.qdd), m.qdd.len(), true, &[N])?)?;
    d.set_item("tau", output(py, rows(&m.tau), m.tau.len(), true, &[N])?)?;
    d.set_item("duration_s", m.duration_s())?;
    d.set_item("step_s", m.step_s)?;
    d.set_item("effort_s", m.effort)?;
    d.set_item("peak_effort_share", m.peak_effort_share)?;
    d.set_item("iterations", m.iterations)?;
    d.set_item("violation", m.violation)?;
    d.set_item("solve_time_s", solve_s)?;
    Ok(())
}

fn solve<'py, const N: usize, R: DynamicsDerivatives<N> + Sync>(
    py: Python<'py>,
    robot: &R,
    r: Request,
) -> PyResult<Bound<'py, PyDict>> {
    let problem = MoveProblem {
        from: joint_vector::<N>(&r.from),
        to: joint_vector::<N>(&r.to),
        duration_s: r.duration,
        step_s: r.step,
        substeps: r.substeps,
        max_effort_share: r.effort_share,
        limit_margin: r.limit_margin,
        max_joint_speed: r.max_speed.as_deref().map(joint_vector::<N>),
    };
    let d = PyDict::new(py);
    let started = Instant::now();
    match r.terminal {
        None => {
            let options = IlqrOptions::default();
            let m = py
                .detach(|| {
                    if r.shortest {
                        shortest_move(robot, &problem, &options)
                    } else {
                        optimise_move(robot, &problem, &options)
                    }
                })
                .map_err(|e| PyValueError::new_err(e.to_string()))?;
            fill(py, &d, &m, started.elapsed().as_secs_f64())?;
        }
        Some((weight, torques, iterations)) => {
            let initial: Vec<JointVector<N>> = torques.chunks(N).map(joint_vector::<N>).collect();
            let m = py
                .detach(|| {
                    optimise_with_terminal_cost(robot, &problem, weight, &initial, iterations)
                })
                .map_err(|e| PyValueError::new_err(e.to_string()))?;
            fill(py, &d, &m.plan, started.elapsed().as_secs_f64())?;
            d.set_item("cost", m.cost)?;
            d.set_item("terminal_cost", m.terminal_cost)?;
            d.set_item("initial_cost", m.initial_cost)?;
        }
    }
    Ok(d)
}

/// `robot`'s number of joints, or a `ValueError` naming the robots there are.
fn dof(robot: &str) -> PyResult<usize> {
    crate::model::arm(robot).map(|a| a.dof()).ok_or_else(|| {
        PyValueError::new_err(format!(
            "robot: no robot called {robot:?} (one of {})",
            crate::model::names().join(", ")
        ))
    })
}

/// Runs `r` on the robot called `robot`.
fn dispatch<'py>(py: Python<'py>, robot: &str, r: Request) -> PyResult<Bound<'py, PyDict>> {
    let name = robot.replace('-', "_");
    let name = name.as_str();
    armdyn_generated::for_each_robot!(return_for_robot, name, |arm| solve(py, arm, r); armdyn::model);
    for_each_own_robot!(return_for_robot, name, |arm| solve(py, arm, r); crate::own);
    Err(PyValueError::new_err(format!(
        "robot: no robot called {robot:?}"
    )))
}

/// The minimum-effort move of `robot` from `q_from` to `q_to` (both at rest) in `duration` s,
/// or with `shortest=True` the shortest move within `effort_share` of each effort limit
/// (control-limited iLQR, the goal and the joint limits by an augmented Lagrangian; as
/// `armdyn plan`). Returns a dict: `t` `(K + 1,)`, `q`, `qd` `(K + 1, n)`, `qdd`, `tau`
/// `(K, n)` (held over each step), `duration_s`, `step_s`, `effort_s`, `peak_effort_share`,
/// `iterations`, `violation`, `solve_time_s`.
#[pyfunction]
#[pyo3(signature = (robot, q_from, q_to, duration = None, *, shortest = false, effort_share = 1.0,
                    step = 0.005, substeps = 1, limit_margin = 0.0, max_speed = None))]
#[allow(clippy::too_many_arguments)]
pub fn plan<'py>(
    py: Python<'py>,
    robot: &str,
    q_from: &Bound<'py, PyAny>,
    q_to: &Bound<'py, PyAny>,
    duration: Option<f64>,
    shortest: bool,
    effort_share: f64,
    step: f64,
    substeps: usize,
    limit_margin: f64,
    max_speed: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let n = dof(robot)?;
    let duration = match (duration, shortest) {
        (Some(d), false) => d,
        (None, true) => 1.0,
        (Some(_), true) => {
            return Err(PyValueError::new_err(
                "duration: give a duration or shortest=True, not both",
            ))
        }
        (None, false) => {
            return Err(PyValueError::new_err(
                "duration: give the move's duration in s, or shortest=True",
            ))
        }
    };
    let max_speed = max_speed.map(|v| vector(v, "max_speed", n)).transpose()?;
    let move_ = (q_from, q_to, duration, step, substeps, effort_share);
    dispatch(
        py,
        robot,
        request(n, move_, limit_margin, max_speed, None, shortest)?,
    )
}

/// The move as Crocoddyl poses it: minimise the effort plus `weight / 2` times the squared
/// distance of the last state to `q_to` at rest, torques within `effort_share`, no joint
/// limits, from the roll-out of `initial_torques` `(K, n)` (one row per knot step, N m or N),
/// in at most `max_iterations` iLQR iterations. Returns `plan`'s dict plus `cost`,
/// `terminal_cost` and `initial_cost`.
#[pyfunction]
#[pyo3(signature = (robot, q_from, q_to, duration, *, weight, initial_torques, effort_share = 1.0,
                    step = 0.005, substeps = 1, max_iterations = 200))]
#[allow(clippy::too_many_arguments)]
pub fn plan_terminal_cost<'py>(
    py: Python<'py>,
    robot: &str,
    q_from: &Bound<'py, PyAny>,
    q_to: &Bound<'py, PyAny>,
    duration: f64,
    weight: f64,
    initial_torques: &Bound<'py, PyAny>,
    effort_share: f64,
    step: f64,
    substeps: usize,
    max_iterations: usize,
) -> PyResult<Bound<'py, PyDict>> {
    let n = dof(robot)?;
    let torques = states(initial_torques, "initial_torques", n)?;
    let terminal = Some((weight, torques.data, max_iterations));
    let move_ = (q_from, q_to, duration, step, substeps, effort_share);
    dispatch(py, robot, request(n, move_, 0.0, None, terminal, false)?)
}
