"""A robot of the user's own in the package: built with ``ARMDYN_PYTHON_MODELS`` naming the
folder of graphs ``armdyn-codegen`` wrote (here ``examples/own-robot/models``, the Kinova
Jaco2), it is ``armdyn.Robot("jaco2")`` like the registry's, with the same functions,
batches and identification; its M, c + g and forward dynamics equal Pinocchio's on the same
URDF. Without the variable at build time the package has no such robot and these tests skip
(CI builds it both ways: ``.ci/run``)."""

import os

import numpy as np
import pytest

import armdyn
from conftest import ROOT, require

URDF = ROOT / "examples/own-robot/description/kinova.urdf"

pytestmark = pytest.mark.skipif(
    "jaco2" not in armdyn.robots() and not os.environ.get("ARMDYN_PYTHON_MODELS"),
    reason="the package was built without ARMDYN_PYTHON_MODELS=examples/own-robot/models",
)


def test_the_own_robot_is_listed_after_the_registry():
    names = armdyn.robots()
    assert "jaco2" in names, names
    assert names.index("jaco2") > names.index("ur5")
    jaco = armdyn.Robot("jaco2")
    assert jaco.dof == 6
    assert jaco.joint_names[0] == "j2s6s200_joint_1"


def test_the_own_robot_equals_pinocchio_in_batches():
    pin = require("pinocchio")
    model = pin.buildModelFromUrdf(str(URDF))
    data = model.createData()
    rng = np.random.default_rng(7)
    lo = np.array([-np.pi, 0.9, 0.4, -np.pi, 0.6, -np.pi])
    hi = np.array([np.pi, 5.4, 5.9, np.pi, 5.7, np.pi])
    q = rng.uniform(lo, hi, (50, 6))
    qd = rng.uniform(-2, 2, (50, 6))
    tau = rng.uniform(-10, 10, (50, 6))
    jaco = armdyn.Robot("jaco2")
    m, bias = jaco.mass_matrix_and_bias(q, qd)
    qdd = jaco.forward_dynamics(q, qd, tau)
    for k in range(50):
        config = []
        for j, a in zip(model.joints[1:], q[k]):
            config += [np.cos(a), np.sin(a)] if j.nq == 2 else [a]
        config = np.array(config)
        want_m = pin.crba(model, data, config)
        want_m = np.triu(want_m) + np.triu(want_m, 1).T
        for got, want in ((m[k], want_m), (bias[k], pin.nonLinearEffects(model, data, config, qd[k])),
                          (qdd[k], pin.aba(model, data, config, qd[k], tau[k]))):
            scale = max(1.0, float(np.abs(want).max()))
            assert float(np.abs(got - want).max()) / scale <= 1e-9


def test_the_own_robot_is_identified_like_the_registry_s():
    r = armdyn.identify("jaco2", noise_pct=1.0, evaluations=200)
    assert r["robot"] == "jaco2"
