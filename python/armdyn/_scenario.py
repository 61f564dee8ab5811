"""``run_scenario``: a scenario file or dict run as ``armdyn run scenario`` runs it."""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from typing import Any, Mapping, Optional, Union

import numpy as np

from . import _native


@dataclass(frozen=True)
class ScenarioRun:
    """One run's samples (one row per control period) and its metrics.

    Arrays: ``t`` (K,) s; ``q``, ``qd`` (K, n) rad or m (per s); ``tau`` (K, n) the applied
    torque after saturation, ``tau_command`` (K, n) before it, N m or N; ``position`` (K, 3) m
    and ``orientation`` (K, 4) the tool's (quaternion, scalar last), base frame; ``wrench``
    (K, 6) the true wrench of the tool on the environment and ``measured_wrench`` (K, 6) the
    force-sensor reading the controller received (N, N m, base frame); the reference:
    ``q_ref``, ``qd_ref``, ``qdd_ref`` (K, n), ``position_ref`` (K, 3), ``orientation_ref``
    (K, 4), ``wrench_ref`` (K, 6); ``force_controlled`` (K,) bool. ``metrics`` is the
    command line's ``metrics.json``.
    """

    name: str
    robot: str
    joint_names: list
    t: np.ndarray
    q: np.ndarray
    qd: np.ndarray
    tau: np.ndarray
    tau_command: np.ndarray
    position: np.ndarray
    orientation: np.ndarray
    wrench: np.ndarray
    measured_wrench: np.ndarray
    q_ref: np.ndarray
    qd_ref: np.ndarray
    qdd_ref: np.ndarray
    position_ref: np.ndarray
    orientation_ref: np.ndarray
    wrench_ref: np.ndarray
    force_controlled: np.ndarray
    metrics: dict = field(repr=False)


def run_scenario(
    scenario: Union[str, "os.PathLike[str]", Mapping[str, Any]],
    *,
    base_dir: Optional[Union[str, "os.PathLike[str]"]] = None,
    precision: str = "reference",
    safety: Optional[bool] = None,
    controller_model: Optional[str] = None,
) -> ScenarioRun:
    """Runs a scenario and returns its samples and metrics.

    ``scenario`` is a scenario file's path, or a dict of its tables (as ``tomllib.load`` gives
    them; relative file names in it resolve in ``base_dir``, default the working folder).
    ``precision`` is ``"reference"`` (the library's controllers), ``"f64"`` or ``"f32"`` (the
    robot's deployable step); ``safety`` turns the supervisor on or off over the file's
    ``[safety]``; ``controller_model`` is ``"nominal"`` or an ``identification.json``.

    Raises ``ScenarioError`` (a ``ValueError`` with ``file``, ``key``, ``line`` and ``rule``)
    for a scenario that cannot run, ``SimulationError`` if the simulation breaks down.
    """
    if isinstance(scenario, Mapping) and not isinstance(scenario, dict):
        scenario = dict(scenario)
    d = _native.run_scenario(
        scenario,
        base_dir=None if base_dir is None else os.fspath(base_dir),
        precision=precision,
        safety=safety,
        controller_model=controller_model,
    )
    return ScenarioRun(**d)
