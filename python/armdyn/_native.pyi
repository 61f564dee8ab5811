"""Type stubs of the native module (the Rust core). Units SI; see ``armdyn`` for conventions."""

from typing import Any, Optional, Sequence, Tuple, Union

import os

import numpy as np
import numpy.typing as npt

ArrayLike = npt.ArrayLike
F64 = npt.NDArray[np.float64]

PARALLEL_MIN_STATES: int

class ScenarioError(ValueError):
    """A scenario that cannot run."""

    file: str
    key: str
    line: Optional[int]
    rule: str

class SimulationError(RuntimeError):
    """A simulation that broke down."""

class Controller:
    """A scenario's controller alone, for a loop of your own (a simulator, a robot's driver):
    ``reset(t, q, qd)``, then ``step(t, q, qd, wrench)`` every ``period_s`` seconds, and
    ``report()`` after a step. The laws, selection, sensor model, tool compensation and
    supervisor are the scenario's, exactly as ``run_scenario`` simulates them."""

    def __init__(
        self,
        scenario: Union[str, "os.PathLike[str]", dict],
        *,
        base_dir: Union[str, "os.PathLike[str]", None] = None,
        safety: Optional[bool] = None,
        controller_model: Optional[str] = None,
    ) -> None: ...
    @property
    def dof(self) -> int: ...
    @property
    def name(self) -> str: ...
    @property
    def period_s(self) -> float: ...
    @property
    def start(self) -> F64: ...
    @property
    def effort_limits(self) -> F64: ...
    def reset(self, t: float, q: ArrayLike, qd: ArrayLike) -> None: ...
    def step(self, t: float, q: ArrayLike, qd: ArrayLike, wrench: ArrayLike) -> F64: ...
    def report(self) -> dict[str, Any]: ...

class Robot:
    """A generated robot. Every function takes one state ``(n,)`` or a batch ``(N, n)`` and
    returns the matching shape; ``parallel=None`` runs batches of at least
    ``PARALLEL_MIN_STATES`` states on every core (``True``/``False`` force it)."""

    def __init__(self, name: str) -> None: ...
    @property
    def name(self) -> str: ...
    @property
    def dof(self) -> int: ...
    @property
    def joint_names(self) -> list[str]: ...
    @property
    def joint_kinds(self) -> list[str]: ...
    @property
    def joint_limits(self) -> F64:
        """``(n, 2)``: ``[lower, upper]`` per joint, rad or m."""
    @property
    def effort_limits(self) -> F64:
        """``(n,)``, N m or N."""
    @property
    def gravity(self) -> F64:
        """``(3,)`` gravity acceleration in the base frame, m/s^2."""
    @property
    def source_sha256(self) -> str: ...
    def standard_parameters(self) -> F64:
        """``(10 n,)``: per link ``[m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz]``."""
    def frame_poses(self, q: ArrayLike, *, parallel: Optional[bool] = None) -> F64:
        """``(n, 4, 4)`` link frame poses, m."""
    def end_effector_pose(self, q: ArrayLike, *, parallel: Optional[bool] = None) -> F64:
        """``(4, 4)`` tool pose, m."""
    def jacobian(self, q: ArrayLike, *, parallel: Optional[bool] = None) -> F64:
        """``(6, n)`` tool Jacobian ``[v; w]``, base frame."""
    def jdot_qd(self, q: ArrayLike, qd: ArrayLike, *, parallel: Optional[bool] = None) -> F64:
        """``(6,)`` ``Jdot qd``, m/s^2 and rad/s^2."""
    def mass_matrix(self, q: ArrayLike, *, parameters: Optional[ArrayLike] = None, parallel: Optional[bool] = None) -> F64:
        """``(n, n)`` ``M(q)``."""
    def coriolis_matrix(self, q: ArrayLike, qd: ArrayLike, *, parameters: Optional[ArrayLike] = None, parallel: Optional[bool] = None) -> F64:
        """``(n, n)`` ``C(q, qd)``, Christoffel form."""
    def coriolis(self, q: ArrayLike, qd: ArrayLike, *, parameters: Optional[ArrayLike] = None, parallel: Optional[bool] = None) -> F64:
        """``(n,)`` ``c = C qd``, N m or N."""
    def generalized_gravity(self, q: ArrayLike, *, parameters: Optional[ArrayLike] = None, parallel: Optional[bool] = None) -> F64:
        """``(n,)`` ``g(q)``, N m or N."""
    def mass_matrix_and_bias(self, q: ArrayLike, qd: ArrayLike, *, parameters: Optional[ArrayLike] = None, parallel: Optional[bool] = None) -> Tuple[F64, F64]:
        """``M(q)`` ``(n, n)`` and ``c + g`` ``(n,)``."""
    def inverse_dynamics(self, q: ArrayLike, qd: ArrayLike, qdd: ArrayLike, *, parameters: Optional[ArrayLike] = None, parallel: Optional[bool] = None) -> F64:
        """``(n,)`` ``tau = M qdd + c + g``."""
    def forward_dynamics(self, q: ArrayLike, qd: ArrayLike, tau: ArrayLike, *, parameters: Optional[ArrayLike] = None, parallel: Optional[bool] = None) -> F64:
        """``(n,)`` ``qdd = M^-1 (tau - c - g)``."""
    def inverse_dynamics_derivatives(self, q: ArrayLike, qd: ArrayLike, qdd: ArrayLike, *, parallel: Optional[bool] = None) -> Tuple[F64, F64]:
        """``(d tau/d q, d tau/d qd)``, ``(n, n)`` each (``d tau/d qdd`` is ``M``)."""
    def forward_dynamics_derivatives(self, q: ArrayLike, qd: ArrayLike, tau: ArrayLike, *, parallel: Optional[bool] = None) -> Tuple[F64, F64, F64]:
        """``(d qdd/d q, d qdd/d qd, M^-1)``, ``(n, n)`` each."""
    def regressor(self, q: ArrayLike, qd: ArrayLike, qdd: ArrayLike, *, parallel: Optional[bool] = None) -> F64:
        """``(n, 10 n)`` ``Y`` with ``tau = Y @ standard_parameters()``."""

def robots() -> list[str]: ...
def run_scenario(scenario: Any, *, base_dir: Optional[str] = None, precision: str = "reference", safety: Optional[bool] = None, controller_model: Optional[str] = None) -> dict[str, Any]: ...
def sweep_plan(scenario: Any, *, base_dir: Optional[str] = None, safety: Optional[bool] = None, controller_model: Optional[str] = None) -> Tuple[dict[str, Any], list[str]]: ...
def sweep_chunk(job: dict[str, Any], samples: int, seed: int, start: int, stop: int) -> list[tuple]: ...
def sweep_table(job: dict[str, Any], samples: int, seed: int, rows: Sequence[tuple]) -> Tuple[dict[str, Any], dict[str, Any]]: ...
def plan(robot: str, q_from: ArrayLike, q_to: ArrayLike, duration: Optional[float] = None, *, shortest: bool = False, effort_share: float = 1.0, step: float = 0.005, substeps: int = 1, limit_margin: float = 0.0, max_speed: Optional[ArrayLike] = None) -> dict[str, Any]: ...
def plan_terminal_cost(robot: str, q_from: ArrayLike, q_to: ArrayLike, duration: float, *, weight: float, initial_torques: ArrayLike, effort_share: float = 1.0, step: float = 0.005, substeps: int = 1, max_iterations: int = 200) -> dict[str, Any]: ...
def identify(robot: str, *, noise_pct: float = 1.0, friction: bool = False, seed: int = 1, evaluations: int = 1500) -> dict[str, Any]: ...
