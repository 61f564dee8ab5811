"""Scenarios from Python: the same metrics as the command line, arrays of the right shapes,
the scenario format's errors as exceptions with the file, key and line."""

import json
import tomllib

import numpy as np
import pytest

import armdyn
from conftest import ROOT, cli

THESIS = ROOT / "scenarios/thesis-hybrid.toml"


def test_a_scenario_gives_the_command_lines_metrics_exactly(tmp_path):
    path = str(THESIS)
    run = armdyn.run_scenario(path)
    cli("run", "scenario", path, "--out", tmp_path, "--no-view")
    metrics = json.loads((tmp_path / "metrics.json").read_text())
    assert run.metrics == metrics
    k = len(run.t)
    assert k == metrics["samples"]
    assert run.q.shape == (k, 4) and run.tau.shape == (k, 4)
    assert run.position.shape == (k, 3) and run.orientation.shape == (k, 4)
    assert run.wrench.shape == (k, 6) and run.measured_wrench.shape == (k, 6)
    assert run.wrench_ref.shape == (k, 6) and run.force_controlled.dtype == bool
    assert np.allclose(np.linalg.norm(run.orientation, axis=1), 1.0)
    # The thesis trial's force reaches its 200 N target.
    assert abs(run.wrench[-1, 2] + 200.0) < 5.0, run.wrench[-1]


def test_a_dict_runs_as_its_file(tmp_path):
    path = ROOT / "scenarios/panda-wipe.toml"
    d = tomllib.loads(path.read_text())
    a = armdyn.run_scenario(d, base_dir=path.parent)
    b = armdyn.run_scenario(path)
    assert np.array_equal(a.q, b.q) and np.array_equal(a.measured_wrench, b.measured_wrench)
    a.metrics.pop("scenario"), b.metrics.pop("scenario")
    assert a.metrics == b.metrics


def test_a_noisy_sensor_is_measured_not_true():
    d = tomllib.loads(THESIS.read_text())
    d["sensor"] = {"noise_n": 2.0, "seed": 3}
    run = armdyn.run_scenario(d, base_dir=THESIS.parent)
    spread = np.std(run.measured_wrench[-2000:, 2] - run.wrench[-2000:, 2])
    assert 1.5 < spread < 2.5, spread


def test_scenario_errors_name_file_key_and_line(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text(THESIS.read_text().replace("[force]", "[force]\ngain_typo = 3", 1))
    with pytest.raises(armdyn.ScenarioError) as e:
        armdyn.run_scenario(bad)
    err = e.value
    assert err.file == str(bad) and "gain_typo" in str(err)
    assert isinstance(err.line, int) and err.line > 1
    assert isinstance(err, ValueError)
    d = tomllib.loads(THESIS.read_text())
    d["robot"] = "kuka"
    with pytest.raises(armdyn.ScenarioError) as e:
        armdyn.run_scenario(d)
    assert e.value.key == "robot" and e.value.file == "<dict>"
    with pytest.raises(armdyn.ScenarioError, match="cannot read"):
        armdyn.run_scenario(tmp_path / "missing.toml")
    with pytest.raises(ValueError, match="precision"):
        armdyn.run_scenario(THESIS, precision="f16")
    with pytest.raises(ValueError, match="expected a file path"):
        armdyn.run_scenario(42)
