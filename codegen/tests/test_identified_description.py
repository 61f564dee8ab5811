"""From a log to a generated model: ``armdyn identify --log ... --write-description DIR`` writes a
robot description, the generator derives it, and the derived M, c and g equal the original
robot's parametric model at the identified standard parameters (1e-9 relative).

The SCARA is identified from a log simulated here (``--write-log``), the Panda from the shipped
``logs/panda_simulated.csv``. The Panda case derives a 7-joint model (about five minutes on two
cores, measured with ``python3 -m pytest -q codegen/tests/test_identified_description.py -k
panda``), so it runs only with ``ARMDYN_SLOW_TESTS=1``; the SCARA case runs always. The command line comes from ``cargo run --release`` (built by the
test command before the generator's tests in ``.ci/run``)."""

import json
import os
import random
import subprocess
import sys

import numpy as np
import pytest

from conftest import ROOT
from armdyn_codegen import export, loader
from armdyn_codegen.description import to_float

TOL = 1e-9
STATES = 40


def _armdyn(*args):
    proc = subprocess.run(
        ["cargo", "run", "--release", "--quiet", "--bin", "armdyn", "--", *map(str, args)],
        capture_output=True, text=True, cwd=ROOT,
    )
    assert proc.returncode == 0, proc.stderr
    return proc.stdout


def _functions(path):
    doc = json.loads(path.read_text())
    return {f["name"]: f for f in doc["functions"]}


def _eval(f, *args):
    return np.array(export.evaluate(f["instructions"], f["result"], [list(a) for a in args]))


SLOW = pytest.mark.skipif(
    not os.environ.get("ARMDYN_SLOW_TESTS"),
    reason="the Panda's derivation takes minutes: set ARMDYN_SLOW_TESTS=1 to run it",
)


@pytest.mark.parametrize("robot", ["scara", pytest.param("panda", marks=SLOW)])
def test_identified_description_regenerates_the_identified_model(robot, tmp_path):
    if robot == "panda":
        log = ROOT / "logs" / "panda_simulated.csv"
    else:
        log = tmp_path / "log.csv"
        _armdyn("identify", "--robot", robot, "--friction", "on", "--noise-pct", "1",
               "--evaluations", "300", "--write-log", log)
    descriptions = tmp_path / "robots"
    _armdyn("identify", "--robot", robot, "--log", log, "--out", tmp_path / "out",
           "--write-description", descriptions)
    name = f"{robot}_identified"
    ident = json.loads((tmp_path / "out" / "identification.json").read_text())
    assert ident["physically_consistent"]
    assert min(ident["smallest_pseudo_inertia_eigenvalues"]) > 0.0
    env = dict(os.environ, PYTHONPATH=str(ROOT / "codegen"))
    proc = subprocess.run(
        [sys.executable, "-m", "armdyn_codegen", "--quiet", "--out", str(tmp_path / "models"),
         "--urdf-out", str(tmp_path / "urdf"), "--c-out", str(tmp_path / "c"),
         "--rust-index", str(tmp_path / "models.rs"), str(descriptions / f"{name}.toml")],
        capture_output=True, text=True, env=env, cwd=tmp_path,
    )
    assert proc.returncode == 0, proc.stderr
    new = _functions(tmp_path / "models" / f"{name}.json")
    original = _functions(ROOT / "generated" / "models" / f"{robot}_parametric.json")
    chain = loader.load(ROOT / "robots" / f"{robot}.toml")
    n = chain.dof
    params = [ident["standard_parameters"][nm] for nm in _standard_names(n)]
    rng = random.Random(0x1D)
    worst = 0.0
    for _ in range(STATES):
        q = [rng.uniform(to_float(j.lower), to_float(j.upper)) for j in chain.joints]
        qd = [rng.uniform(-2.0, 2.0) for _ in range(n)]
        for what, got, want in (
            ("M", _eval(new["mass_matrix"], q), _eval(original["mass_matrix"], q, params)),
            ("c", _eval(new["coriolis"], q, qd), _eval(original["coriolis"], q, qd, params)),
            ("g", _eval(new["gravity"], q), _eval(original["gravity"], q, params)),
        ):
            err = float(np.abs(got - want).max()) / max(1.0, float(np.abs(want).max()))
            worst = max(worst, err)
            assert err <= TOL, f"{name}: {what} differs from the identified parameters' by {err:.3e}"
    print(f"\n{name}: largest relative difference from the identified parameters {worst:.2e}")


def _standard_names(n):
    """The generated order of the standard parameters (``armdyn::identification::standard_names``)."""
    out = []
    for j in range(1, n + 1):
        out += [f"m{j}", f"m{j} cx{j}", f"m{j} cy{j}", f"m{j} cz{j}", f"Ixx{j}", f"Ixy{j}",
                f"Ixz{j}", f"Iyy{j}", f"Iyz{j}", f"Izz{j}"]
    return out
