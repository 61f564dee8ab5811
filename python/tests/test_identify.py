"""Identification from Python: the command line's identification.json, and the arrays."""

import json

import numpy as np
import pytest

import armdyn
from conftest import cli


def test_identify_equals_the_command_line(tmp_path):
    got = armdyn.identify("planar2", noise_pct=1.0, seed=3, evaluations=60)
    arrays = got.pop("arrays")
    cli("identify", "--robot", "planar2", "--seed", 3, "--evaluations", 60, "--out", tmp_path)
    want = json.loads((tmp_path / "identification.json").read_text())
    assert got == want
    assert np.array_equal(arrays["base_parameters_estimated"], want["base_parameters_estimated"])
    v = arrays["validation"]
    k = len(v["t"])
    assert v["tau"].shape == (k, 2) and v["tau_predicted"].shape == (k, 2)
    err = np.sqrt(np.mean((v["tau_predicted"] - v["tau"]) ** 2, axis=0))
    rms = np.sqrt(np.mean(v["tau"] ** 2, axis=0))
    assert np.allclose(100 * err / rms, v["rms_error_pct"], rtol=1e-9)


def test_identify_refuses_bad_options():
    with pytest.raises(ValueError, match="robot: no robot called"):
        armdyn.identify("kuka")
    with pytest.raises(ValueError, match="noise_pct"):
        armdyn.identify("planar2", noise_pct=-1.0)
