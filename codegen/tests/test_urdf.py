"""URDF input and output: bad files give an error naming the description, the URDF file and the
element, and nothing is written; randomly mutated URDFs never crash the reader; every robot
written as a URDF and read back through the project's own URDF input is the same model."""

import os
import random
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from lxml import etree

from lagrange import build
from armdyn_codegen import loader, urdf_out
from armdyn_codegen.description import DescriptionError, to_float

ROOT = Path(__file__).resolve().parents[2]
PANDA = (ROOT / "robots/urdf/panda.urdf").read_text()
PANDA_TOML = (ROOT / "robots/panda.toml").read_text()


def _write(tmp_path, urdf_text, toml_text=PANDA_TOML):
    (tmp_path / "urdf").mkdir(exist_ok=True)
    (tmp_path / "urdf" / "panda.urdf").write_text(urdf_text)
    desc = tmp_path / "panda.toml"
    desc.write_text(toml_text)
    return desc


def _sub(old, new, text=PANDA, count=1):
    assert old in text, old
    return text.replace(old, new, count)


J2_AXIS = '''<child link="panda_link2"/>
        <axis xyz="0 0 1"/>'''

CASES = {
    # name: (URDF text, description text, what the message must contain)
    "missing-tip-link": (PANDA, _sub('tip_link = "panda_hand_tcp"', 'tip_link = "gripper"', PANDA_TOML),
                         ["`tip_link` `gripper` is not a link"]),
    "broken-chain": (_sub('<parent link="panda_link3"/>', '<parent link="panda_link0"/>'),
                     _sub('base_link = "panda_link0"', 'base_link = "panda_link1"', PANDA_TOML),
                     ["broken chain", "`panda_link0` has no parent joint"]),
    "undefined-parent-link": (_sub('<parent link="panda_link3"/>', '<parent link="panda_link33"/>'),
                              PANDA_TOML, ["joint `panda_joint4`", "parent link `panda_link33` is not defined"]),
    "zero-axis": (_sub(J2_AXIS, J2_AXIS.replace("0 0 1", "0 0 0")), PANDA_TOML,
                  ["joint `panda_joint2`", "axis is zero"]),
    "non-unit-axis": (_sub(J2_AXIS, J2_AXIS.replace("0 0 1", "0 0 2")), PANDA_TOML,
                      ["joint `panda_joint2`", "not a unit vector"]),
    "bad-inertia": (_sub('ixx="0.70337"', 'ixx="-0.70337"'), PANDA_TOML,
                    ["link `panda_link1`", "positive semi-definite"]),
    "negative-mass": (_sub('<mass value="3.228604"/>', '<mass value="-3.228604"/>'), PANDA_TOML,
                      ["link `panda_link3`", "mass must be >= 0"]),
    "unsupported-joint-type": (_sub('<joint name="panda_joint5" type="revolute">',
                                    '<joint name="panda_joint5" type="floating">'), PANDA_TOML,
                               ["joint `panda_joint5`", "unsupported joint type `floating`"]),
    "unknown-joint-type": (_sub('<joint name="panda_joint5" type="revolute">',
                                '<joint name="panda_joint5" type="ball">'), PANDA_TOML,
                           ["joint `panda_joint5`", "Invalid joint type"]),
    "finger-not-locked": (PANDA, _sub("panda_finger_joint1 = 0.0", "", PANDA_TOML),
                          ["joint `panda_finger_joint1`", "give its value in [locked]"]),
    "locked-joint-missing": (PANDA, _sub("panda_finger_joint1 = 0.0", "panda_finger_joint1 = 0.0\nthumb = 0.0", PANDA_TOML),
                             ["joint `thumb` (named in the description) is not a joint"]),
    "not-a-number": (_sub('xyz="0 0 0.333"', 'xyz="0 0 zero"'), PANDA_TOML,
                     ["joint `panda_joint1`", "could not convert"]),
    "not-finite": (_sub('xyz="0 0 0.333"', 'xyz="0 0 nan"'), PANDA_TOML,
                   ["joint `panda_joint1`", "must be finite"]),
    "unknown-description-key": (PANDA, _sub("format = 1", "format = 1\ncolour = \"white\"", PANDA_TOML),
                                ["top level", "unknown key `colour`"]),
    "missing-urdf-file": (PANDA, _sub('urdf = "urdf/panda.urdf"', 'urdf = "urdf/none.urdf"', PANDA_TOML),
                          ["`urdf`: cannot read", "none.urdf"]),
    "not-xml": (PANDA[:-40], PANDA_TOML, ["not well-formed XML"]),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_bad_urdf_is_an_error_naming_file_and_element_and_writes_nothing(tmp_path, case):
    urdf_text, toml_text, needles = CASES[case]
    desc = _write(tmp_path, urdf_text, toml_text)
    out = tmp_path / "out"
    env = dict(os.environ, PYTHONPATH=str(ROOT / "codegen"))
    proc = subprocess.run([sys.executable, "-m", "armdyn_codegen", "--out", str(out), str(desc)],
                          capture_output=True, text=True, env=env, timeout=120)
    assert proc.returncode == 1, proc.stderr
    assert str(desc) in proc.stderr
    if case not in ("unknown-description-key", "missing-urdf-file"):
        assert str(tmp_path / "urdf" / "panda.urdf") in proc.stderr, proc.stderr
    for needle in needles:
        assert needle in proc.stderr, f"{case}: {needle!r} not in:\n{proc.stderr}"
    assert "Traceback" not in proc.stderr
    assert "nothing written" in proc.stderr
    assert not out.exists() or not any(out.iterdir())


BAD_VALUES = ["nan", "inf", "-inf", "abc", "", "1e999", "0x1p3", "1,5"]


def _mutations(seed, count):
    """(element tag, element name, mutated URDF text): one numeric attribute of one <joint> or
    <link> (or of an element inside it) replaced by a value that is never valid there."""
    rng = random.Random(seed)
    root = etree.fromstring(PANDA.encode())
    targets = []
    for el in root:
        if el.tag not in ("joint", "link"):
            continue
        for sub in el.iter():
            if sub.tag in ("origin", "axis", "mass", "inertia", "limit") and sub.getparent().tag in (
                    "joint", "inertial"):
                for attr in sub.attrib:
                    if attr in ("xyz", "rpy", "value", "ixx", "ixy", "ixz", "iyy", "iyz", "izz",
                                "lower", "upper", "effort"):
                        targets.append((el, sub, attr))
    for _ in range(count):
        el, sub, attr = rng.choice(targets)
        old = sub.get(attr)
        bad = rng.choice(BAD_VALUES)
        if attr in ("xyz", "rpy"):
            parts = old.split()
            parts[rng.randrange(3)] = bad or "x"
            new = " ".join(parts)
        else:
            new = bad
        sub.set(attr, new)
        text = etree.tostring(root, encoding="unicode")
        sub.set(attr, old)
        yield el.tag, el.get("name"), f"{sub.tag} {attr}={new!r}", text


def test_mutated_urdfs_never_crash_and_name_the_element(tmp_path):
    """Property test: 80 seeded random mutations of the Panda's URDF; each is rejected with a
    DescriptionError (never another exception) naming the mutated joint or link."""
    seen = 0
    for tag, name, what, text in _mutations(0xBAD, 80):
        desc = _write(tmp_path, text)
        with pytest.raises(DescriptionError) as err:
            loader.load(desc)
        message = str(err.value)
        assert f"{tag} `{name}`" in message, f"{what} in {tag} {name}: {message}"
        assert str(desc) in message and "panda.urdf" in message
        seen += 1
    assert seen == 80


def _round_trip(name, tmp_path):
    chain = loader.load(ROOT / "robots" / f"{name}.toml")
    (tmp_path / f"{name}.urdf").write_text(urdf_out.render(chain, f"robots/{name}.toml"))
    g = ", ".join(repr(to_float(x)) for x in chain.gravity)
    desc = tmp_path / f"{name}.toml"
    desc.write_text(
        f'format = 1\nname = "{name}"\ndescription = "round trip"\nconvention = "urdf"\n'
        f'urdf = "{name}.urdf"\nbase_link = "{name}_base"\ntip_link = "{name}_tool"\n'
        f"gravity = [{g}]\n"
        # The task is the description's, not the URDF's.
        f"task = [{', '.join(repr(('x', 'y', 'z', 'rx', 'ry', 'rz')[r]).replace(chr(39), chr(34)) for r in chain.task)}]\n"
        # The DH files accept the PUMA's published inertias, which break the triangle inequality.
        f"accept_triangle_violation = [{', '.join(f'{chr(34)}{name}_link{i}{chr(34)}' for i in range(1, chain.dof + 1))}]\n"
    )
    return chain, loader.load(desc)


@pytest.mark.parametrize("name", sorted(p.stem for p in (ROOT / "robots").glob("*.toml")))
def test_urdf_output_reads_back_as_the_same_model(name, tmp_path):
    """`armdyn urdf` (the generator's URDF output) read back through the project's URDF input:
    the same joints, limits and efforts, and the same pose, Jacobian, M, C, c, g and inverse
    dynamics (the Lagrangian path on both chains) to 1e-12 at 24 random states."""
    a, b = _round_trip(name, tmp_path)
    assert [j.name for j in a.joints] == [j.name for j in b.joints]
    assert [j.kind for j in a.joints] == [j.kind for j in b.joints]
    for ja, jb in zip(a.joints, b.joints):
        for x, y in ((ja.lower, jb.lower), (ja.upper, jb.upper), (ja.effort, jb.effort)):
            assert to_float(x) == to_float(y)
    fa, fb = build(a), build(b)
    rng = random.Random(11)
    for _ in range(24):
        q = [rng.uniform(to_float(j.lower), to_float(j.upper)) for j in a.joints]
        qd = [rng.uniform(-2, 2) for _ in a.joints]
        qdd = [rng.uniform(-5, 5) for _ in a.joints]
        for k, (x, y) in enumerate(zip(fa(q, qd, qdd), fb(q, qd, qdd))):
            x, y = np.array(x), np.array(y)
            assert np.abs(x - y).max() <= 1e-12 * max(1.0, float(np.abs(x).max())), (name, k, q)
