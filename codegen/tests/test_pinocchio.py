"""The generated models against an independent implementation reading the same URDF: Pinocchio
(PyPI wheel ``pin``, pinned in ``codegen/requirements-check.txt``).

* ``ur5`` and ``panda``: Pinocchio reads the very URDF files of ``robots/urdf/`` with its own
  parser (urdfdom); for the Panda the finger joints are locked closed by Pinocchio's
  ``buildReducedModel``, as the description locks them;
* ``scara`` and ``puma560`` (DH robots): Pinocchio reads the URDF the project writes for them
  (``scara urdf``, ``generated/urdf/``).

M, c and g (and inverse dynamics) of the committed graphs (``generated/models``) agree with
Pinocchio's ``crba``, ``nonLinearEffects``, ``computeGeneralizedGravity`` and ``rnea`` to 1e-9
relative at 64 random states each. Without Pinocchio the tests are skipped, except under CI
(``CI`` set), where that is a failure.
"""

import json
import os
import random
from pathlib import Path

import numpy as np
import pytest

from scara_codegen import export, loader
from scara_codegen.description import to_float

ROOT = Path(__file__).resolve().parents[2]
TOL = 1e-9
STATES = 64

try:
    import pinocchio as pin
except ImportError:  # pragma: no cover - depends on the machine
    pin = None
    if os.environ.get("CI"):
        raise
pytestmark = pytest.mark.skipif(pin is None, reason="Pinocchio (pip install pin) is not installed")

CASES = {
    # robot: (URDF Pinocchio reads, joints it must lock at 0)
    "ur5": (ROOT / "robots/urdf/ur5_robot.urdf", []),
    "panda": (ROOT / "robots/urdf/panda.urdf", ["panda_finger_joint1", "panda_finger_joint2"]),
    "scara": (ROOT / "generated/urdf/scara.urdf", []),
    "puma560": (ROOT / "generated/urdf/puma560.urdf", []),
}


def _functions(name):
    doc = json.loads((ROOT / "generated/models" / f"{name}.json").read_text())
    return {f["name"]: f for f in doc["functions"]}


def _eval(f, *args):
    return np.array(export.evaluate(f["instructions"], f["result"], list(args)))


def _pinocchio_model(urdf, locked, chain):
    model = pin.buildModelFromUrdf(str(urdf))
    if locked:
        ids = [model.getJointId(n) for n in locked]
        assert all(i < model.njoints for i in ids), locked
        model = pin.buildReducedModel(model, ids, pin.neutral(model))
    model.gravity.linear = np.array([to_float(g) for g in chain.gravity])
    names = [model.names[i] for i in range(1, model.njoints)]
    assert names == [j.name for j in chain.joints], names
    assert model.nq == model.nv == chain.dof
    return model


@pytest.mark.parametrize("name", sorted(CASES))
def test_mass_matrix_velocity_term_and_gravity_equal_pinocchio(name):
    urdf, locked = CASES[name]
    chain = loader.load(ROOT / "robots" / f"{name}.toml")
    model = _pinocchio_model(urdf, locked, chain)
    data = model.createData()
    fns = _functions(name)
    rng = random.Random(0x9E11)
    worst = 0.0
    for _ in range(STATES):
        q = [rng.uniform(to_float(j.lower), to_float(j.upper)) for j in chain.joints]
        qd = [rng.uniform(-2.0, 2.0) for _ in chain.joints]
        qdd = [rng.uniform(-5.0, 5.0) for _ in chain.joints]
        qa, qda, qdda = np.array(q), np.array(qd), np.array(qdd)
        M = pin.crba(model, data, qa)
        M = np.triu(M) + np.triu(M, 1).T
        nle = pin.nonLinearEffects(model, data, qa, qda).copy()
        g = pin.computeGeneralizedGravity(model, data, qa).copy()
        tau = pin.rnea(model, data, qa, qda, qdda).copy()
        n = chain.dof
        for what, got, want in (
            ("M", _eval(fns["mass_matrix"], q).reshape(n, n), M),
            ("c", _eval(fns["coriolis"], q, qd), nle - g),
            ("g", _eval(fns["gravity"], q), g),
            ("inverse dynamics", _eval(fns["inverse_dynamics"], q, qd, qdd), tau),
        ):
            err = float(np.abs(got - want).max()) / max(1.0, float(np.abs(want).max()))
            worst = max(worst, err)
            assert err <= TOL, f"{name}: {what} differs from Pinocchio by {err:.3e} (relative) at q={q}, qd={qd}"
    print(f"\n{name}: largest relative difference from Pinocchio {worst:.2e}")


def test_end_effector_pose_equals_pinocchio():
    """The tip frames agree too (UR5's ee_link, the Panda's panda_hand_tcp)."""
    for name, tip in (("ur5", "ee_link"), ("panda", "panda_hand_tcp")):
        urdf, locked = CASES[name]
        chain = loader.load(ROOT / "robots" / f"{name}.toml")
        model = _pinocchio_model(urdf, locked, chain)
        data = model.createData()
        fid = model.getFrameId(tip)
        f = _functions(name)["end_effector_pose"]
        rng = random.Random(5)
        for _ in range(16):
            q = [rng.uniform(to_float(j.lower), to_float(j.upper)) for j in chain.joints]
            pin.framesForwardKinematics(model, data, np.array(q))
            want = data.oMf[fid].homogeneous
            got = _eval(f, q).reshape(4, 4)
            assert np.abs(got - want).max() <= 1e-9, (name, q)
