"""Generated robot dynamics, force/position control scenarios, sweeps and identification.

Every generated robot by name, on one state ``(n,)`` or a batch ``(N, n)``::

    import numpy as np, armdyn
    panda = armdyn.Robot("panda")
    q = np.zeros(panda.dof)
    M, b = panda.mass_matrix_and_bias(q, q)      # (7, 7), (7,): M and c + g
    qdd = panda.forward_dynamics(np.zeros((1000, 7)), np.zeros((1000, 7)), np.zeros((1000, 7)))

Units are SI throughout: rad or m, rad/s or m/s, N m or N, kg; poses are 4 x 4 homogeneous
matrices in m; quaternions scalar last ``(x, y, z, w)``. Names follow the project's Rust API
(``mass_matrix``, ``coriolis``, ``gravity``, ``inverse_dynamics``, ``forward_dynamics``), one
vocabulary across Rust, the command line and Python; batches put the state index first, as
the Robotics Toolbox for Python and numpy broadcasting do.
"""

from ._native import (
    PARALLEL_MIN_STATES,
    Controller,
    Robot,
    ScenarioError,
    SimulationError,
    identify,
    plan,
    plan_terminal_cost,
    robots,
)
from ._scenario import ScenarioRun, run_scenario
from ._sweep import SweepResult, sweep

__all__ = [
    "PARALLEL_MIN_STATES",
    "Controller",
    "Robot",
    "ScenarioError",
    "ScenarioRun",
    "SimulationError",
    "SweepResult",
    "identify",
    "plan",
    "plan_terminal_cost",
    "robots",
    "run_scenario",
    "sweep",
]
