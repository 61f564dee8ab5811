"""The generated graphs agree with the thesis's Lagrangian method at random states."""

import random
from pathlib import Path

import numpy as np
import pytest

from lagrange import build
from conftest import generated
from armdyn_codegen import export, loader, model
from armdyn_codegen.description import to_float

ROOT = Path(__file__).resolve().parents[2]
ROBOTS = sorted((ROOT / "robots").glob("*.toml"))
STATES = 60
# Relative tolerance: |a - b| <= TOL * max(1, |b|_inf over the whole output).
TOL = 1e-10
# Forward dynamics amplifies the rounding of M and tau by the condition number of M (about
# 1e3 for the PUMA 560's wrist), hence a looser bound.
FD_TOL = 1e-9


def _states(robot, seed):
    rng = random.Random(seed)
    for _ in range(STATES):
        q = [rng.uniform(to_float(j.lower), to_float(j.upper)) for j in robot.joints]
        qd = [rng.uniform(-2.0, 2.0) for _ in robot.joints]
        qdd = [rng.uniform(-5.0, 5.0) for _ in robot.joints]
        yield q, qd, qdd


@pytest.mark.parametrize("path", ROBOTS, ids=lambda p: p.stem)
def test_generated_equals_lagrangian(path):
    robot = loader.load(path)
    fns = generated(path)
    slow = build(robot)
    n = robot.dof
    for q, qd, qdd in _states(robot, 7):
        ref = slow(q, qd, qdd)
        expected = {
            "end_effector_pose": np.array(ref[0]),
            "jacobian": np.array(ref[1]),
            "mass_matrix": np.array(ref[2]),
            "coriolis_matrix": np.array(ref[3]),
            "coriolis": np.array(ref[4]).ravel(),
            "gravity": np.array(ref[5]).ravel(),
            "jdot_qd": np.array(ref[6]).ravel(),
            "inverse_dynamics": np.array(ref[7]).ravel(),
        }
        for name, want in expected.items():
            f = fns[name]
            args = [q, qd, qdd][: len(f.inputs)]
            got = np.array(export.evaluate(f.code, f.result, args)).reshape(want.shape)
            scale = max(1.0, float(np.abs(want).max()))
            err = float(np.abs(got - want).max())
            assert err <= TOL * scale, f"{robot.name}::{name} at q={q}, qd={qd}: error {err:.3e}"
        # [M | c + g] in one graph: the Lagrangian M beside the Lagrangian c + g.
        mb = fns["mass_matrix_and_bias"]
        got = np.array(export.evaluate(mb.code, mb.result, [q, qd])).reshape(n, n + 1)
        bias = (expected["coriolis"] + expected["gravity"]).reshape(n, 1)
        want = np.hstack([expected["mass_matrix"], bias])
        err = float(np.abs(got - want).max())
        assert err <= TOL * max(1.0, float(np.abs(want).max())), (
            f"{robot.name}::mass_matrix_and_bias at q={q}, qd={qd}: error {err:.3e}"
        )
        # [J | p; 0] in one graph: the Lagrangian J beside the Lagrangian tool position.
        jp = fns["jacobian_and_position"]
        got = np.array(export.evaluate(jp.code, jp.result, [q])).reshape(6, n + 1)
        last = np.concatenate([expected["end_effector_pose"][:3, 3], np.zeros(3)]).reshape(6, 1)
        want = np.hstack([expected["jacobian"], last])
        err = float(np.abs(got - want).max())
        assert err <= TOL * max(1.0, float(np.abs(want).max())), (
            f"{robot.name}::jacobian_and_position at q={q}: error {err:.3e}"
        )
        # ... and bit for bit the exported jacobian and end_effector_pose (the same graphs).
        j_alone = np.array(export.evaluate(fns["jacobian"].code, fns["jacobian"].result, [q]))
        pose = fns["end_effector_pose"]
        t_alone = np.array(export.evaluate(pose.code, pose.result, [q])).reshape(4, 4)
        assert (got[:, :n] == j_alone.reshape(6, n)).all(), f"{robot.name}: J at q={q}"
        assert (got[:3, n] == t_alone[:3, 3]).all(), f"{robot.name}: p at q={q}"
        # Forward dynamics inverts the Lagrangian inverse dynamics: FD(q, qd, ID(qdd)) = qdd.
        fd = fns["forward_dynamics"]
        got = np.array(export.evaluate(fd.code, fd.result, [q, qd, expected["inverse_dynamics"]]))
        err = float(np.abs(got - np.array(qdd)).max())
        assert err <= FD_TOL * max(1.0, max(abs(x) for x in qdd)), (
            f"{robot.name}::forward_dynamics at q={q}, qd={qd}: error {err:.3e}"
        )
        poses = fns["frame_poses"]
        got = np.array(export.evaluate(poses.code, poses.result, [q])).reshape(n, 4, 4)
        # The end effector is frame n times the fixed tool transform (the identity for DH).
        tool = np.eye(4)
        tool[:3, :3] = [[to_float(x) for x in row] for row in robot.tool.R]
        tool[:3, 3] = [to_float(x) for x in robot.tool.p]
        assert np.abs(got[-1] @ tool - expected["end_effector_pose"]).max() <= TOL


@pytest.mark.parametrize("path", ROBOTS, ids=lambda p: p.stem)
def test_trig_only_of_single_joint_angles_once(path):
    robot = loader.load(path)
    for f in list(generated(path).values()) + list(generated(path, parametric=True).values()):
        seen = set()
        for ins in f.code:
            if ins[0] in ("sin", "cos"):
                arg = f.code[ins[1]]
                # sin/cos of an input element, or of an input element plus a constant offset
                if arg[0] == "add":
                    kinds = sorted(f.code[k][0] for k in arg[1:])
                    assert kinds == ["const", "input"], f"{f.name}: trig of {arg}"
                else:
                    assert arg[0] == "input", f"{f.name}: trig of {arg}"
                key = (ins[0], ins[1])
                assert key not in seen, f"{f.name}: {ins[0]} computed twice"
                seen.add(key)
        assert f.counts == export.counts(f.code)


def test_scara_dynamics_is_compact():
    fns = generated(ROOT / "robots" / "scara.toml")
    total = sum(fns[k].counts["flops"] for k in ("mass_matrix", "coriolis", "gravity"))
    assert total <= 60, total


def test_scara_matches_thesis_numbers():
    """M of eq. 3.67 to the printed digits; the velocity term of docs/thesis.md section 2, not
    the printed C."""
    fns = generated(ROOT / "robots" / "scara.toml")

    def M(q2):
        return _eval(fns["mass_matrix"], [0.3, q2, 0.2, -0.5]).reshape(4, 4)

    const = M(np.pi / 2)  # cos(q2) = 0 (to 6e-17)
    coef = M(0.0) - const  # the cos(q2) coefficient
    printed_const = [[3.23, 1.12, 0, -0.0025], [1.12, 1.12, 0, -0.0025], [0, 0, 4.94, 0],
                     [-0.0025, -0.0025, 0, 0.0025]]
    printed_coef = [[2.34, 1.17, 0, 0], [1.17, 0, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0]]
    for r in range(4):
        for k in range(4):
            digits = 4 if abs(printed_const[r][k]) < 0.01 else 2
            assert round(const[r][k], digits) == printed_const[r][k], (r, k, const[r][k])
            assert round(coef[r][k], 2) == printed_coef[r][k], (r, k, coef[r][k])
    h = 0.4 * (5.37 * (0.4 - 0.224) + (4.03 + 0.91) * 0.4)  # docs/thesis.md section 2
    rng = random.Random(5)
    for _ in range(50):
        q = [rng.uniform(-1.5, 1.5), rng.uniform(-2.7, 2.7), rng.uniform(0.1, 0.35), rng.uniform(-3, 3)]
        qd = [rng.uniform(-2, 2) for _ in range(4)]
        s2 = np.sin(q[1])
        want = [-h * s2 * (2 * qd[0] * qd[1] + qd[1] ** 2), h * s2 * qd[0] ** 2, 0.0, 0.0]
        got = _eval(fns["coriolis"], q, qd)
        assert np.abs(got - want).max() <= 1e-12 * max(1.0, np.abs(want).max())
        printed = [0.0, 1.17 * qd[0] * (qd[0] + qd[1]) * s2, 0.0, 0.0]  # erratum 1
        if abs(qd[0] * qd[1]) > 0.1 and abs(s2) > 0.1:
            assert np.abs(got - printed).max() > 0.01
        g = _eval(fns["gravity"], q)
        assert np.allclose(g, [0.0, 0.0, -9.8 * (4.03 + 0.91), 0.0], rtol=0, atol=1e-12)


def test_identical_input_gives_identical_bytes(tmp_path, monkeypatch):
    """Twice the same output, and the committed one, for the DH descriptions (the URDF robots,
    minutes each, are left to the drift check of CI, which regenerates everything and compares
    with the committed files)."""
    from armdyn_codegen.cli import main

    a, b = tmp_path / "a", tmp_path / "b"
    small = [p for p in ROBOTS if loader.load(p).convention != "urdf"]
    monkeypatch.chdir(ROOT)  # the graphs name their source relative to the working folder
    args = [str(p.relative_to(ROOT)) for p in small]
    assert main(["--quiet", "--out", str(a)] + args) == 0
    assert main(["--quiet", "--out", str(b)] + args) == 0
    for p in small:
        name = loader.load(p).name
        assert (a / f"{name}.json").read_bytes() == (b / f"{name}.json").read_bytes()
        assert (a / f"{name}.json").read_bytes() == (ROOT / "generated/models" / f"{name}.json").read_bytes()


def _eval(f, *args):
    return np.array(export.evaluate(f.code, f.result, list(args)))


@pytest.mark.parametrize("path", ROBOTS, ids=lambda p: p.stem)
def test_regressor_and_parametric_model(path):
    """Y pi = inverse dynamics; the parametric model at the robot's own parameters equals the
    numeric model; and at other parameters, its inverse dynamics is Y(q, qd, qdd) params and
    its forward dynamics inverts its inverse dynamics."""
    robot = loader.load(path)
    num = generated(path)
    par = generated(path, parametric=True)
    own = _eval(num["standard_parameters"])
    assert own.size == 10 * robot.dof
    rng = random.Random(3)
    for q, qd, qdd in _states(robot, 11):
        tau = _eval(num["inverse_dynamics"], q, qd, qdd)
        Y = _eval(num["regressor"], q, qd, qdd).reshape(robot.dof, 10 * robot.dof)
        scale = max(1.0, float(np.abs(tau).max()))
        assert np.abs(Y @ own - tau).max() <= TOL * scale
        for name in ("mass_matrix", "coriolis_matrix", "coriolis", "gravity", "inverse_dynamics"):
            args = [q, qd, qdd][: len(num[name].inputs)]
            a = _eval(num[name], *args)
            b = _eval(par[name], *args, own)
            assert np.abs(a - b).max() <= 1e-12 * max(1.0, float(np.abs(a).max())), name
        other = own * np.array([rng.uniform(0.5, 1.5) for _ in own])
        b = _eval(par["inverse_dynamics"], q, qd, qdd, other)
        assert np.abs(Y @ other - b).max() <= TOL * max(1.0, float(np.abs(b).max()))
        # Forward dynamics: the numeric one at the robot's own parameters, and the inverse of
        # the parametric inverse dynamics at a physical parameter set (each link's ten
        # parameters scaled by one factor: M stays positive definite).
        a = _eval(num["forward_dynamics"], q, qd, tau)
        b = _eval(par["forward_dynamics"], q, qd, tau, own)
        assert np.abs(a - b).max() <= FD_TOL * max(1.0, float(np.abs(a).max())), "forward_dynamics"
        physical = own * np.repeat([rng.uniform(0.7, 1.3) for _ in range(robot.dof)], 10)
        tau_p = _eval(par["inverse_dynamics"], q, qd, qdd, physical)
        back = _eval(par["forward_dynamics"], q, qd, tau_p, physical)
        assert np.abs(back - np.array(qdd)).max() <= FD_TOL * max(1.0, max(abs(x) for x in qdd)), (
            f"{robot.name}::parametric::forward_dynamics at q={q}, qd={qd}"
        )


def test_modified_dh_equals_standard_dh():
    std = generated(ROOT / "robots" / "scara.toml")
    mdh_robot = loader.load(ROOT / "robots" / "scara_mdh.toml")
    assert mdh_robot.convention == "modified-dh"
    mdh = generated(ROOT / "robots" / "scara_mdh.toml")
    for q, qd, qdd in _states(mdh_robot, 5):
        for name in ("end_effector_pose", "jacobian", "mass_matrix", "coriolis_matrix", "coriolis",
                     "gravity", "inverse_dynamics", "jdot_qd"):
            args = [q, qd, qdd][: len(std[name].inputs)]
            a, b = _eval(std[name], *args), _eval(mdh[name], *args)
            assert np.abs(a - b).max() <= 1e-12 * max(1.0, float(np.abs(a).max())), name
        # Frames 1..3 differ (modified frame i sits at joint i): frame i of the modified
        # description is the standard frame i times (Tx(a_i) Rx(alpha_i))^-1.
        fa = _eval(std["frame_poses"], q).reshape(4, 4, 4)
        fb = _eval(mdh["frame_poses"], q).reshape(4, 4, 4)
        assert np.allclose(fb[0][:3, 3], [0.0, 0.0, 0.5])  # modified frame 1 sits on joint 1's axis
        assert np.allclose(fa[3], fb[3], atol=1e-12)
