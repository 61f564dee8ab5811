"""``armdyn.Controller``: a scenario's controller stepped from Python gives the simulator's
torques bit for bit when fed the run's own samples (joints and the true wrench), reports the
mode, the force error and the supervisor's trips, and refuses bad input naming it."""

import numpy as np
import pytest

import armdyn
from conftest import ROOT

FILES = ["thesis-hybrid.toml", "panda-wipe.toml", "faults/scara-nan.toml",
         "panda-tool-bias.toml"]


@pytest.mark.parametrize("file", FILES)
def test_stepped_from_python_equals_the_simulation(file):
    path = ROOT / "scenarios" / file
    run = armdyn.run_scenario(path)
    c = armdyn.Controller(path)
    assert c.dof == run.q.shape[1]
    assert c.period_s == pytest.approx(run.t[1] - run.t[0])
    c.reset(0.0, run.q[0], run.qd[0])
    modes = set()
    for k in range(len(run.t)):
        tau = c.step(run.t[k], run.q[k], run.qd[k], run.wrench[k])
        r = c.report()
        assert np.array_equal(tau, run.tau[k]), (file, k)
        assert np.array_equal(r["command"], run.tau_command[k]), (file, k)
        modes.add(r["mode"])
        assert (r["mode"] == "force") == bool(run.force_controlled[k]) or r["mode"] == "tripped"
    if "hybrid" in file or "wipe" in file:
        assert "force" in modes, modes
    if "nan" in file:
        assert r["mode"] == "tripped" and r["trips"] >= 1
        assert r["first_trip"] == "sensor-non-finite"


def test_the_report_says_what_the_step_did():
    c = armdyn.Controller(ROOT / "scenarios/thesis-hybrid.toml")
    q = c.start
    c.reset(10.0, q, np.zeros(4))
    c.step(10.0, q, np.zeros(4), np.zeros(6))
    r = c.report()
    assert r["t"] == 10.0 and r["mode"] == "position" and r["trips"] == 0
    assert r["first_trip"] is None
    assert r["command"].shape == (4,) and len(r["saturated"]) == 4
    assert np.all(np.abs(c.step(10.001, q, np.zeros(4), np.zeros(6))) <= c.effort_limits)


def test_bad_input_is_refused_naming_it():
    c = armdyn.Controller(ROOT / "scenarios/panda-wipe.toml")
    q = c.start
    with pytest.raises(ValueError, match=r"q: expected 7 numbers, got 6"):
        c.reset(0.0, q[:6], np.zeros(7))
    with pytest.raises(ValueError, match=r"qd\[2\] = NaN is not a finite number"):
        c.step(0.0, q, np.array([0, 0, np.nan, 0, 0, 0, 0.0]), np.zeros(6))
    with pytest.raises(ValueError, match="not a finite time"):
        c.step(float("inf"), q, np.zeros(7), np.zeros(6))
    with pytest.raises(ValueError, match="wrench: expected 6 numbers"):
        c.step(0.0, q, np.zeros(7), [1.0, 2.0])
    # A non-finite wrench is the sensor's fault, for the supervisor to judge: accepted.
    c.reset(0.0, q, np.zeros(7))
    c.step(0.0, q, np.zeros(7), np.full(6, np.nan))
    with pytest.raises(armdyn.ScenarioError):
        armdyn.Controller({"format": 1, "name": "x", "robot": "kuka"})


def test_a_recorded_run_has_the_simulations_metrics_and_files(tmp_path):
    path = ROOT / "scenarios/panda-wipe.toml"
    run = armdyn.run_scenario(path)
    c = armdyn.Controller(path)
    c.record()
    c.reset(0.0, run.q[0], run.qd[0])
    for k in range(len(run.t)):
        c.step(run.t[k], run.q[k], run.qd[k], run.wrench[k])
    metrics = c.finish(tmp_path / "out")
    assert metrics == run.metrics
    for f in ("trajectory.csv", "metrics.json", "normal_force.svg", "view.html"):
        assert (tmp_path / "out" / f).is_file(), f
    with pytest.raises(ValueError, match="finished"):
        c.step(0.0, run.q[0], run.qd[0], run.wrench[0])
    fresh = armdyn.Controller(path)
    with pytest.raises(ValueError, match="record"):
        fresh.finish()
