"""The generated graphs agree with the thesis's Lagrangian method at random states."""

import random
from pathlib import Path

import numpy as np
import pytest

from lagrange import build
from scara_codegen import description, export, model
from scara_codegen.description import to_float

ROOT = Path(__file__).resolve().parents[2]
ROBOTS = sorted((ROOT / "robots").glob("*.toml"))
STATES = 60
# Relative tolerance: |a - b| <= TOL * max(1, |b|_inf over the whole output).
TOL = 1e-10


def _states(robot, seed):
    rng = random.Random(seed)
    for _ in range(STATES):
        q = [rng.uniform(to_float(j.lower), to_float(j.upper)) for j in robot.joints]
        qd = [rng.uniform(-2.0, 2.0) for _ in robot.joints]
        yield q, qd


@pytest.mark.parametrize("path", ROBOTS, ids=lambda p: p.stem)
def test_generated_equals_lagrangian(path):
    robot = description.load(path)
    fns = {f.name: f for f in model.generate(robot)}
    slow = build(robot)
    n = robot.dof
    for q, qd in _states(robot, 7):
        ref = slow(q, qd)
        expected = {
            "end_effector_pose": np.array(ref[0]),
            "jacobian": np.array(ref[1]),
            "mass_matrix": np.array(ref[2]),
            "coriolis_matrix": np.array(ref[3]),
            "coriolis": np.array(ref[4]).ravel(),
            "gravity": np.array(ref[5]).ravel(),
        }
        for name, want in expected.items():
            f = fns[name]
            args = [q] if len(f.inputs) == 1 else [q, qd]
            got = np.array(export.evaluate(f.code, f.result, args)).reshape(want.shape)
            scale = max(1.0, float(np.abs(want).max()))
            err = float(np.abs(got - want).max())
            assert err <= TOL * scale, f"{robot.name}::{name} at q={q}, qd={qd}: error {err:.3e}"
        poses = fns["frame_poses"]
        got = np.array(export.evaluate(poses.code, poses.result, [q])).reshape(n, 4, 4)
        assert np.abs(got[-1] - expected["end_effector_pose"]).max() <= TOL


@pytest.mark.parametrize("path", ROBOTS, ids=lambda p: p.stem)
def test_trig_only_of_single_joint_angles_once(path):
    robot = description.load(path)
    for f in model.generate(robot):
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
    robot = description.load(ROOT / "robots" / "scara.toml")
    fns = {f.name: f for f in model.generate(robot)}
    total = sum(fns[k].counts["flops"] for k in ("mass_matrix", "coriolis", "gravity"))
    assert total <= 60, total


def test_scara_matches_thesis_numbers():
    robot = description.load(ROOT / "robots" / "scara.toml")
    fns = {f.name: f for f in model.generate(robot)}
    for q2 in (-1.0, 0.0, 0.4, 2.0):
        q = [0.3, q2, 0.2, -0.5]
        M = np.array(export.evaluate(fns["mass_matrix"].code, fns["mass_matrix"].result, [q])).reshape(4, 4)
        c2 = np.cos(q2)
        thesis = np.array(  # eq. 3.67, to the printed digits
            [[3.23 + 2.34 * c2, 1.12 + 1.17 * c2, 0, -0.0025],
             [1.12 + 1.17 * c2, 1.12, 0, -0.0025],
             [0, 0, 4.94, 0],
             [-0.0025, -0.0025, 0, 0.0025]]
        )
        assert np.abs(M - thesis).max() < 0.005 + 0.005 * 1.0
        assert np.allclose(np.round(M[2:, 2:], 4), thesis[2:, 2:])


def test_identical_input_gives_identical_bytes(tmp_path):
    from scara_codegen.cli import main

    a, b = tmp_path / "a", tmp_path / "b"
    args = [str(p) for p in ROBOTS]
    assert main(["--quiet", "--out", str(a)] + args) == 0
    assert main(["--quiet", "--out", str(b)] + args) == 0
    for p in ROBOTS:
        name = description.load(p).name
        assert (a / f"{name}.json").read_bytes() == (b / f"{name}.json").read_bytes()
