"""Each bad description gives a message naming file, link and rule, exit 1, and writes nothing."""

import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
GOOD = (ROOT / "robots" / "planar2.toml").read_text()


def _edit(old: str, new: str, count: int = 1) -> str:
    assert old in GOOD, old
    return GOOD.replace(old, new, count)


CASES = {
    # name: (file text, what the message must contain)
    "syntax-error": (GOOD.replace("mass = 2.0", "mass = = 2.0"), ["TOML syntax error", "line"]),
    "unknown-key": (_edit("mass = 2.0", "mass = 2.0\ncolour = \"red\""), ["link 1 (joint q1)", "unknown key `colour`"]),
    "negative-mass": (_edit("mass = 1.5", "mass = -1.5"), ["link 2 (joint q2)", "`mass` must be >= 0"]),
    "not-psd": (
        _edit("inertia = [[0.0003, 0.0, 0.0], [0.0, 0.02015, 0.0], [0.0, 0.0, 0.02015]]",
              "inertia = [[0.0003, 0.0, 0.0], [0.0, 0.02015, 0.03], [0.0, 0.03, 0.02015]]"),
        ["link 2 (joint q2)", "positive semi-definite"],
    ),
    "asymmetric": (
        _edit("inertia = [[0.0003, 0.0, 0.0], [0.0, 0.02015, 0.0], [0.0, 0.0, 0.02015]]",
              "inertia = [[0.0003, 0.001, 0.0], [0.0, 0.02015, 0.0], [0.0, 0.0, 0.02015]]"),
        ["link 2 (joint q2)", "symmetric"],
    ),
    "triangle": (
        _edit("inertia = [[0.0003, 0.0, 0.0], [0.0, 0.02015, 0.0], [0.0, 0.0, 0.02015]]",
              "inertia = [[0.0003, 0.0, 0.0], [0.0, 0.002, 0.0], [0.0, 0.0, 0.02015]]"),
        ["link 2 (joint q2)", "triangle inequality", "accept_triangle_violation"],
    ),
    "nan": (_edit("mass = 1.5", "mass = nan"), ["link 2 (joint q2)", "`mass` must be finite"]),
    "infinite-length": (_edit("a = 0.4", "a = inf"), ["joint 2 (q2)", "`a` must be finite"]),
    "prismatic-variable-theta": (
        _edit('kind = "revolute"\na = 0.4', 'kind = "prismatic"\na = 0.4'),
        ["joint 2 (q2)", "prismatic joint cannot have a variable `theta`"],
    ),
    "revolute-variable-d": (
        _edit('d = 0.0\ntheta = "q"', 'd = "q"\ntheta = "q"'),
        ["joint 1 (q1)", "revolute joint cannot have a variable `d`"],
    ),
    "bad-angle": (_edit('alpha = "0"', 'alpha = "half a turn"'), ["joint 1 (q1)", "`alpha` must be a number (rad) or an angle"]),
    "unknown-convention": (_edit('convention = "standard-dh"', 'convention = "craig"'), ["top level", "`convention` must be \"standard-dh\" or \"modified-dh\""]),
    "variable-alpha": (_edit('alpha = "0"', 'alpha = "q"'), ["joint 1 (q1)", "`alpha` cannot be the joint variable"]),
    "limits-reversed": (_edit('limits = ["-pi", "pi"]', 'limits = ["pi", "-pi"]'), ["joint 1 (q1)", "lower"]),
    # Magnitudes whose products would overflow (or underflow) a double in the model.
    "overflowing-mass": (
        _edit("mass = 2.0", "mass = 1e308"),
        ["link 1 (joint q1)", "`mass` = 1E+308 is out of range", "0 or between 1e-30 and 1e30 in magnitude"],
    ),
    "overflowing-length": (_edit("a = 0.5", "a = 1e200"), ["joint 1 (q1)", "`a` = 1E+200 is out of range"]),
    "huge-exponent": (_edit("mass = 1.5", "mass = 1e999999999"), ["link 2 (joint q2)", "`mass` = 1E+999999999 is out of range"]),
    "underflowing-inertia": (
        _edit("inertia = [[0.0003, 0.0, 0.0]", "inertia = [[1e-40, 0.0, 0.0]"),
        ["link 2 (joint q2)", "`inertia[0]`[0] = 1E-40 is out of range"],
    ),
    "angle-out-of-range": (_edit('alpha = "0"', 'alpha = "1e40deg"'), ["joint 1 (q1)", "`alpha` = 1e40deg is out of range"]),
    "too-many-digits": (_edit("mass = 2.0", "mass = 2." + "0" * 120 + "1"), ["link 1 (joint q1)", "`mass` has 122 significant digits"]),
    "overlong-integer": (_edit("effort = 50.0", "effort = 1" + "0" * 5000), ["TOML: a value cannot be read", "4300 digits"]),
    "deep-nesting": (_edit("com = [-0.25, 0.0, 0.0]", "com = " + "[" * 2000 + "]" * 2000), ["nested too deeply"]),
    # Names that cannot be the generated Rust module.
    "keyword-name": (_edit('name = "planar2"', 'name = "fn"'), ["top level", '`name` "fn" is a Rust keyword']),
    "reserved-keyword-name": (_edit('name = "planar2"', 'name = "yield"'), ["top level", '`name` "yield" is a Rust keyword']),
    "crate-name": (_edit('name = "planar2"', 'name = "core"'), ["top level", '`name` "core" is the name of a crate']),
    "not-an-identifier": (_edit('name = "planar2"', 'name = "2link"'), ["top level", "`name` must be a snake-case identifier"]),
    # Strings where numbers belong.
    "string-mass": (
        _edit("mass = 2.0", 'mass = "2.0"'),
        ["link 1 (joint q1)", '`mass` must be a number, not the string "2.0" (write the number without quotes)'],
    ),
    "string-length": (_edit("a = 0.4", 'a = "0.4"'), ["joint 2 (q2)", '`a` must be a number, not the string "0.4"']),
    "string-gravity": (_edit("gravity = [0.0, -9.81, 0.0]", 'gravity = [0.0, "-9.81", 0.0]'), ["top level", "`gravity`[1] must be a number, not the string"]),
    "string-effort": (_edit("effort = 30.0", 'effort = "30"'), ["joint 2 (q2)", "`effort` must be a number, not the string"]),
    "boolean-format": (_edit("format = 1", "format = true"), ["top level", "`format` must be 1, got true"]),
    # The task: the end-effector directions the robot controls.
    "task-unknown-direction": (_edit('task = ["x", "y"]', 'task = ["x", "w"]'), ["top level", '`task`: unknown direction "w"']),
    "task-repeated-direction": (_edit('task = ["x", "y"]', 'task = ["x", "x"]'), ["top level", '`task`: direction "x" is given twice']),
    "task-not-an-array": (_edit('task = ["x", "y"]', 'task = "xy"'), ["top level", "`task` must be a non-empty array of direction names"]),
    "task-empty": (_edit('task = ["x", "y"]', "task = []"), ["top level", "`task` must be a non-empty array"]),
    "task-partial-rotation": (_edit('task = ["x", "y"]', 'task = ["x", "rx"]'), ["top level", "the rotations must be none, `rz` alone, or all of"]),
    "task-more-directions-than-joints": (
        _edit('task = ["x", "y"]', 'task = ["x", "y", "rz"]'),
        ["top level", "`task` has 3 directions but the robot has 2 joints"],
    ),
    "task-missing-for-two-joints": (
        _edit('task = ["x", "y"]', ""),
        ["top level", "`task` is missing: a robot of 2 joints cannot control all six"],
    ),
    # The arm moves in the x-y plane: it cannot move its tool along z.
    "task-rank-deficient": (
        _edit('task = ["x", "y"]', 'task = ["x", "z"]'),
        ["`task` = [x, z]: the Jacobian's rows for these directions have rank at most 1 < 2"],
    ),
}


def _run(tmp_path, files):
    out = tmp_path / "out"
    env = dict(os.environ, PYTHONPATH=str(ROOT / "codegen"))
    proc = subprocess.run(
        [sys.executable, "-m", "armdyn_codegen", "--out", str(out)] + [str(f) for f in files],
        capture_output=True, text=True, env=env, cwd=tmp_path,
    )
    return proc, out


@pytest.mark.parametrize("case", sorted(CASES))
def test_bad_description_is_refused(tmp_path, case):
    text, needles = CASES[case]
    bad = tmp_path / f"{case}.toml"
    bad.write_text(text)
    # A good file beside the bad one: still nothing is written.
    good = tmp_path / "good.toml"
    good.write_text((ROOT / "robots" / "scara.toml").read_text())
    proc, out = _run(tmp_path, [good, bad])
    assert proc.returncode == 1, proc.stderr
    assert str(bad.name) in proc.stderr, proc.stderr
    for needle in needles:
        assert needle in proc.stderr, f"{needle!r} not in:\n{proc.stderr}"
    assert "nothing written" in proc.stderr
    assert not out.exists() or not any(out.iterdir())


def test_accepted_triangle_violation_warns_every_read(tmp_path):
    good = tmp_path / "scara.toml"
    good.write_text((ROOT / "robots" / "scara.toml").read_text())
    for _ in range(2):
        proc, out = _run(tmp_path, [good])
        assert proc.returncode == 0, proc.stderr
        assert "link 2 (joint q2): warning: inertia breaks the triangle inequality" in proc.stderr
    assert (out / "scara.json").exists()


def test_failed_run_leaves_existing_output_untouched(tmp_path):
    good = tmp_path / "planar2.toml"
    good.write_text(GOOD)
    proc, out = _run(tmp_path, [good])
    assert proc.returncode == 0
    before = (out / "planar2.json").read_bytes()
    good.write_text(GOOD.replace("mass = 2.0", "mass = -2.0"))
    proc, out = _run(tmp_path, [good])
    assert proc.returncode == 1
    assert (out / "planar2.json").read_bytes() == before
    assert sorted(p.name for p in out.iterdir()) == ["planar2.json", "planar2.urdf",
                                                     "planar2_parametric.json"]


def test_accepted_extremes_generate_finite_models(tmp_path):
    """Numbers near both ends of the accepted range still give a model whose constants are
    finite doubles: planar2 with every length, mass, inertia, gravity and effort scaled by
    1e28 (largest 5e29) or 1e-26 (smallest 3e-30)."""
    import json
    import math
    import re

    for exponent, check in (("e28", lambda c: abs(c) > 1e80), ("e-26", lambda c: 0 < abs(c) < 1e-75)):
        scaled = re.sub(
            r"(?m)^((?:a|d|mass|com|inertia|gravity|effort) = )(.*)$",
            lambda m: m.group(1) + re.sub(r"(\d+\.\d+)", r"\g<1>" + exponent, m.group(2)),
            GOOD,
        )
        assert scaled.count(exponent) == 35, scaled  # 3 + 2 x (a, d, effort, mass, 3 com, 9 inertia)
        folder = tmp_path / exponent
        folder.mkdir()
        path = folder / "scaled.toml"
        path.write_text(scaled)
        proc, out = _run(folder, [path])
        assert proc.returncode == 0, proc.stderr
        doc = json.loads((out / "planar2.json").read_text())
        consts = [float(i[1]) for f in doc["functions"] for i in f["instructions"] if i[0] == "const"]
        assert consts and all(math.isfinite(c) for c in consts)
        assert any(check(c) for c in consts), exponent


def test_range_ends_are_accepted_and_just_beyond_refused(tmp_path):
    from armdyn_codegen import description

    for value, ok in (("1e30", True), ("-1e-30", True), ("0.0", True), ("1.0000001e30", False), ("9.9e-31", False)):
        path = tmp_path / "edge.toml"
        path.write_text(_edit("d = 0.0", f"d = {value}"))
        if ok:
            description.load(path)
        else:
            with pytest.raises(description.DescriptionError, match="is out of range"):
                description.load(path)


def test_byte_order_mark_is_accepted(tmp_path):
    path = tmp_path / "bom.toml"
    path.write_bytes(b"\xef\xbb\xbf" + GOOD.encode())
    proc, out = _run(tmp_path, [path])
    assert proc.returncode == 0, proc.stderr
    assert (out / "planar2.json").exists()


def test_robot_names_must_not_clash(tmp_path):
    a = tmp_path / "a.toml"
    a.write_text(GOOD)
    same = tmp_path / "same.toml"
    same.write_text(GOOD)
    proc, out = _run(tmp_path, [a, same])
    assert proc.returncode == 1
    assert f"robot name `planar2` is used by more than one description: {a}, {same}" in proc.stderr
    # `planar2_parametric.json` is planar2's parametric model.
    clash = tmp_path / "clash.toml"
    clash.write_text(_edit('name = "planar2"', 'name = "planar2_parametric"'))
    proc, out = _run(tmp_path, [a, clash])
    assert proc.returncode == 1
    assert f"robot names clash: `planar2` ({a}) and `planar2_parametric` ({clash})" in proc.stderr
    assert "nothing written" in proc.stderr and not out.exists()


def test_a_robot_does_not_overwrite_the_model_of_another_description(tmp_path):
    a = tmp_path / "a.toml"
    a.write_text(GOOD)
    proc, out = _run(tmp_path, [a])
    assert proc.returncode == 0, proc.stderr
    before = (out / "planar2.json").read_bytes()
    copy = tmp_path / "copy.toml"
    copy.write_text(GOOD.replace("mass = 2.0", "mass = 3.0"))
    proc, out = _run(tmp_path, [copy])
    assert proc.returncode == 1
    assert f"{copy}: robot name `planar2` would overwrite {out / 'planar2.json'}, the model of a.toml" in proc.stderr
    assert (out / "planar2.json").read_bytes() == before
    # Once a.toml is gone, its model is stale and may be replaced.
    a.unlink()
    proc, out = _run(tmp_path, [copy])
    assert proc.returncode == 0, proc.stderr
    assert (out / "planar2.json").read_bytes() != before


def test_coefficients_outside_double_range_are_an_error_not_a_traceback():
    from fractions import Fraction

    from armdyn_codegen import normalize

    assert normalize._coef(Fraction(1, 3)) == 1 / 3
    assert normalize._coef(Fraction(0)) == 0.0
    for x in (Fraction(10**400), Fraction(-(10**309)), Fraction(1, 10**320)):
        with pytest.raises(normalize.CoefficientRangeError, match="outside the range of a double"):
            normalize._coef(x)


def test_a_joint_that_moves_nothing_is_named(tmp_path):
    """Link 2 without mass or inertia: joint 2 moves nothing, the mass matrix is singular and
    forward dynamics cannot be generated. A clear error naming the joint, nothing written."""
    text = _edit("mass = 1.5", "mass = 0.0").replace(
        "inertia = [[0.0003, 0.0, 0.0], [0.0, 0.02015, 0.0], [0.0, 0.0, 0.02015]]",
        "inertia = [[0.0, 0.0, 0.0], [0.0, 0.0, 0.0], [0.0, 0.0, 0.0]]",
    )
    bad = tmp_path / "idle.toml"
    bad.write_text(text)
    proc, out = _run(tmp_path, [bad])
    assert proc.returncode == 1, proc.stderr
    assert f"{bad}: cannot generate the model: joint 2 (q2) moves no mass and no inertia" in proc.stderr
    assert "nothing written" in proc.stderr and not out.exists()
