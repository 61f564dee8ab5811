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
}


def _run(tmp_path, files):
    out = tmp_path / "out"
    env = dict(os.environ, PYTHONPATH=str(ROOT / "codegen"))
    proc = subprocess.run(
        [sys.executable, "-m", "scara_codegen", "--out", str(out)] + [str(f) for f in files],
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
    assert sorted(p.name for p in out.iterdir()) == ["planar2.json", "planar2_parametric.json"]
