//! `armdyn._native`: the Rust core of the `armdyn` Python package (see `python/README.md`).
//!
//! - [`robot`]: every generated robot by name, its functions on numpy states and batches;
//! - [`scenario`]: scenario files or dicts run, samples as arrays, metrics as a dict;
//! - [`sweep`]: Monte Carlo sweeps in chunks any executor can run;
//! - [`identify`]: identification on the simulated plant;
//! - [`controller`]: a scenario's controller alone, stepped from a Python loop;
//! - [`plan`]: optimised joint moves.
//!
//! No Rust panic crosses into Python: every input is checked and every library error becomes
//! an exception (`ValueError`, `ScenarioError`, `SimulationError`, `RuntimeError`).

/// The package's own robots (`ARMDYN_PYTHON_MODELS` at build time; see `build.rs`).
#[macro_use]
mod own {
    #![allow(missing_docs, clippy::all)]
    include!(concat!(env!("OUT_DIR"), "/own_robots.rs"));
}

/// For `armdyn_generated::for_each_robot!` and `for_each_own_robot!`: with `robot` bound to
/// the robot whose module is called `name` (a `&str`), returns `body` from the enclosing
/// function; falls through when none is.
macro_rules! return_for_robot {
    ([$name:ident, |$robot:ident| $body:expr; $($path:ident)::+]
     $(($module:ident, $ty:ident, $n:literal, $doc:literal))*) => {{
        #[allow(unused_imports)]
        use $($path)::+ as types;
        match $name {
            $(stringify!($module) => {
                let $robot = &types::$ty;
                return $body;
            })*
            _ => {}
        }
    }};
}

mod buffer;
mod controller;
mod identify;
mod inputs;
mod model;
mod plan;
mod pool;
mod robot;
mod scenario;
mod sweep;

use pyo3::prelude::*;

#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add_class::<robot::Robot>()?;
    m.add_class::<controller::Controller>()?;
    m.add_function(wrap_pyfunction!(robot::robots, m)?)?;
    m.add_function(wrap_pyfunction!(scenario::run_scenario, m)?)?;
    m.add_function(wrap_pyfunction!(sweep::sweep_plan, m)?)?;
    m.add_function(wrap_pyfunction!(sweep::sweep_chunk, m)?)?;
    m.add_function(wrap_pyfunction!(sweep::sweep_table, m)?)?;
    m.add_function(wrap_pyfunction!(identify::identify, m)?)?;
    m.add_function(wrap_pyfunction!(plan::plan, m)?)?;
    m.add_function(wrap_pyfunction!(plan::plan_terminal_cost, m)?)?;
    m.add("ScenarioError", py.get_type::<scenario::ScenarioError>())?;
    m.add(
        "SimulationError",
        py.get_type::<scenario::SimulationError>(),
    )?;
    m.add("PARALLEL_MIN_STATES", robot::PARALLEL_MIN_STATES)?;
    Ok(())
}
