"""Property tests of the description reader: whatever the input, a valid robot or a
``DescriptionError`` naming the file, never a traceback.

Inputs: random documents shaped like a description, mutated copies of the shipped robots,
random bytes, and single fields set to random values (where the rule is simple enough to
predict the outcome exactly). The reader is fuzzed heavily (it takes milliseconds); the
whole generator (CasADi derivation and export) runs on a handful of random valid robots.
Settings come from the Hypothesis profile in ``conftest.py`` (derandomized by default).
"""

from __future__ import annotations

import contextlib
import io
import json
import math
import re
import tempfile
from decimal import Decimal
from pathlib import Path

import sympy as sp
from conftest import EXAMPLES_SCALE
from hypothesis import event, given, note, settings
from hypothesis import strategies as st

from armdyn_codegen import cli, description

ROOT = Path(__file__).resolve().parents[2]
ROBOTS = {p.name: p.read_text() for p in sorted((ROOT / "robots").glob("*.toml"))}
PLANAR2 = ROBOTS["planar2.toml"]
FILE = "fuzz.toml"
KEYS = sorted(description.TOP_KEYS | description.JOINT_KEYS | description.LINK_KEYS)


def examples(n: int) -> settings:
    return settings(max_examples=n * EXAMPLES_SCALE)


# --- TOML value text --------------------------------------------------------------------


def _toml_string(s: str) -> str:
    return json.dumps(s, ensure_ascii=False)  # JSON's escapes are TOML basic-string escapes


numbers = st.one_of(
    st.integers(-(10**40), 10**40).map(str),
    st.floats().map(lambda x: "nan" if math.isnan(x) else repr(x).replace("inf", "inf")),
    st.builds(lambda m, e: f"{m}e{e}", st.integers(-999, 999), st.integers(-(10**10), 10**10)),
    st.builds(lambda m, f, e: f"{m}.{f}e{e}", st.integers(-99, 99), st.integers(0, 10**6), st.integers(-40, 40)),
    st.sampled_from(
        ["0", "-0.0", "+0.0", "1e30", "-1e-30", "1.0000001e30", "9.99e-31", "0x7f", "0o17", "0b101",
         "1_000.5", "+inf", "-nan", "1" + "0" * 120, "0." + "1" * 150, "1" * 5000]
    ),
)
angle_strings = st.one_of(
    st.sampled_from(
        ["pi", "-pi/2", "7*pi/8", "30deg", "q", "q + pi/2", "q - 0.1", "0", "pi/0", "1e40deg",
         "1e-999999999deg", "q + q", "q + 1e31", "-160deg", "2 pi", "pi/", "q+", " q ", "deg"]
    ),
    st.builds(lambda n, d: f"{n}*pi/{d}", st.integers(0, 10**35), st.integers(0, 10**35)),
    st.builds(lambda v: f"{v}deg", numbers),
    st.builds(lambda v: f"q + {v}", numbers),
    numbers,  # a number written as a string
)
strings = st.one_of(
    angle_strings.map(_toml_string),
    st.text(max_size=12).map(_toml_string),
    st.sampled_from(["revolute", "prismatic", "standard-dh", "modified-dh", "fn", "core", "planar2"]).map(_toml_string),
)
identifiers = st.one_of(
    st.from_regex(r"[a-z_][a-z0-9_]{0,8}", fullmatch=True),
    st.sampled_from(sorted(description.RUST_KEYWORDS) + list(description.CRATE_NAMES)),
    st.text(max_size=8),
)
scalars = st.one_of(numbers, strings, st.sampled_from(["true", "false", "1979-05-27", "07:32:00"]))
values = st.recursive(
    scalars,
    lambda inner: st.one_of(
        st.lists(inner, max_size=4).map(lambda xs: "[" + ", ".join(xs) + "]"),
        st.dictionaries(st.sampled_from(KEYS + ["x"]), inner, max_size=3).map(
            lambda d: "{" + ", ".join(f"{k} = {v}" for k, v in d.items()) + "}"
        ),
    ),
    max_leaves=10,
)


def _vector(n, element=numbers):
    return st.lists(element, min_size=n, max_size=n).map(lambda xs: "[" + ", ".join(xs) + "]")


# Values that are right for their key (given the joint's kind), so that random documents with
# little noise are often valid.
small = st.floats(1e-3, 10.0).map(repr)
plausible = {
    "format": st.just("1"),
    "name": st.from_regex(r"[a-z][a-z0-9_]{0,8}", fullmatch=True).map(_toml_string),
    "description": st.text(st.characters(codec="ascii", min_codepoint=32), max_size=20).map(_toml_string),
    "convention": st.sampled_from(['"standard-dh"', '"modified-dh"']),
    "gravity": _vector(3, small),
    "a": small,
    "alpha": st.sampled_from(['"0"', '"pi/2"', '"-pi/2"', "0.3", '"30deg"']),
    "effort": small,
    "mass": small,
    "com": _vector(3, small),
    "inertia": st.builds(lambda x: f"[[{x}, 0.0, 0.0], [0.0, {x}, 0.0], [0.0, 0.0, {x}]]", small),
    "accept_triangle_violation": st.sampled_from(["true", "false"]),
}
by_kind = {
    '"revolute"': {
        "d": small,
        "theta": st.sampled_from(['"q"', '"q + pi/2"', '"q - 0.1"']),
        "limits": st.sampled_from(['["-pi", "pi"]', "[-0.5, 0.5]", '["-160deg", "160deg"]']),
    },
    '"prismatic"': {
        "d": st.sampled_from(['"q"', '"q + 0.1"']),
        "theta": st.sampled_from(['"0"', '"pi/2"', "0.1"]),
        "limits": st.sampled_from(["[-0.5, 0.5]", "[0, 0.3]"]),
    },
}


@st.composite
def documents(draw) -> str:
    """A random document with the shape of a description, 0 to 3 joints: with probability
    ``noise`` each key is missing or has an arbitrary value, else a value right for it;
    sometimes an unknown key. A third of the documents have no noise."""
    noise = draw(st.sampled_from([0.0, 0.05, 0.2, 0.5]))

    def assignments(keys, right):
        out = []
        for key in keys:
            if draw(st.floats(0, 1)) < noise:
                if draw(st.booleans()):
                    out.append(f"{key} = {draw(values)}")
            else:
                out.append(f"{key} = {draw(right[key])}")
        if draw(st.floats(0, 1)) < noise / 4:
            out.append(f"{draw(st.sampled_from(KEYS + ['colour']))}_x = {draw(values)}")
        return out

    lines = assignments(["format", "name", "description", "convention", "gravity"], plausible)
    for j in range(draw(st.integers(0 if noise else 1, 3))):
        kind = draw(st.sampled_from(sorted(by_kind)))
        right = dict(plausible, kind=st.just(kind), **by_kind[kind])
        lines.append("[[joints]]")
        lines.append(f"name = {_toml_string(draw(st.text(max_size=4)) if noise else f'j{j}')}")
        lines += assignments(["kind", "a", "alpha", "d", "theta", "limits", "effort"], right)
        if draw(st.floats(0, 1)) >= noise / 2:
            lines.append("[joints.link]")
            lines += assignments(["mass", "com", "inertia", "accept_triangle_violation"], right)
    return "\n".join(lines) + "\n"


@st.composite
def mutated(draw) -> bytes:
    """A shipped description with one to three random edits: a value replaced, a line
    deleted, duplicated, inserted or swapped, a character changed; sometimes a byte-order
    mark or CRLF line ends."""
    lines = ROBOTS[draw(st.sampled_from(sorted(ROBOTS)))].splitlines()
    for _ in range(draw(st.integers(1, 3))):
        i = draw(st.integers(0, len(lines) - 1))
        op = draw(st.sampled_from(["value", "value", "value", "delete", "duplicate", "insert", "swap", "char"]))
        if op == "value" and "=" in lines[i] and not lines[i].lstrip().startswith("#"):
            key = lines[i].split("=", 1)[0]
            lines[i] = f"{key}= {draw(values)}"
        elif op == "delete":
            del lines[i]
        elif op == "duplicate":
            lines.insert(i, lines[i])
        elif op == "insert":
            lines.insert(i, f"{draw(st.sampled_from(KEYS))} = {draw(values)}")
        elif op == "swap":
            j = draw(st.integers(0, len(lines) - 1))
            lines[i], lines[j] = lines[j], lines[i]
        elif op == "char" and lines[i]:
            k = draw(st.integers(0, len(lines[i]) - 1))
            lines[i] = lines[i][:k] + draw(st.characters()) + lines[i][k + 1:]
        if not lines:
            lines = [""]
    text = ("\r\n" if draw(st.booleans()) else "\n").join(lines) + "\n"
    return (b"\xef\xbb\xbf" if draw(st.booleans()) else b"") + text.encode("utf-8", "surrogatepass")


# --- the property ------------------------------------------------------------------------


def _magnitude_ok(x) -> bool:
    v = abs(float(sp.N(x, 30)))
    return v == 0 or 1e-30 * (1 - 1e-12) <= v <= 1e30 * (1 + 1e-12)


def _check_valid(robot: description.Robot) -> None:
    """What every accepted robot satisfies."""
    assert re.fullmatch(r"[a-z][a-z0-9_]*", robot.name)
    assert robot.name not in description.RUST_KEYWORDS | set(description.CRATE_NAMES)
    assert robot.dof >= 1 and robot.convention in ("standard-dh", "modified-dh")
    numbers_ = list(robot.gravity)
    for j in robot.joints:
        assert j.kind in ("revolute", "prismatic")
        assert bool(j.lower < j.upper) and j.effort > 0 and j.link.mass >= 0
        numbers_ += [j.a, j.alpha, j.d, j.theta, j.lower, j.upper, j.effort, j.link.mass]
        numbers_ += list(j.link.com) + [x for row in j.link.inertia for x in row]
    for x in numbers_:
        assert _magnitude_ok(x), x


def read(raw: bytes):
    """The reader's verdict on ``raw``: a checked Robot, or None after a well-formed error.
    Any other exception fails the test."""
    try:
        robot = description.parse(raw, FILE)
    except description.DescriptionError as e:
        assert e.problems and all(isinstance(p, str) and p for p in e.problems)
        assert all(line.startswith(f"{FILE}: ") for line in str(e).splitlines())
        event("refused")
        return None
    _check_valid(robot)
    event("accepted")
    return robot


@examples(100)
@given(documents())
def test_random_documents_give_a_robot_or_a_description_error(text):
    note(text)
    read(text.encode("utf-8", "surrogatepass"))


@examples(150)
@given(mutated())
def test_mutated_robots_give_a_robot_or_a_description_error(raw):
    note(repr(raw))
    read(raw)


@examples(200)
@given(st.one_of(st.binary(max_size=300), st.builds(lambda a, b: a + PLANAR2.encode() + b, st.binary(max_size=8), st.binary(max_size=8))))
def test_random_bytes_give_a_robot_or_a_description_error(raw):
    read(raw)


# --- single fields, where the rule predicts the outcome ----------------------------------


def _set(key_line: str, value: str) -> bytes:
    assert key_line in PLANAR2
    return PLANAR2.replace(key_line, f"{key_line.split(' = ')[0]} = {value}", 1).encode()


def _accepted_number(text: str) -> bool:
    dec = Decimal(text)
    digits = "".join(map(str, dec.as_tuple().digits)).strip("0")
    return dec.is_finite() and len(digits) <= 100 and (dec == 0 or Decimal("1e-30") <= abs(dec) <= Decimal("1e30"))


float_texts = st.one_of(
    st.floats(allow_nan=False, allow_infinity=False).map(repr),
    st.builds(lambda m, e: f"{m}e{e}", st.integers(-(10**6), 10**6), st.integers(-400, 400)),
    st.builds(lambda m, e: f"{m}e{e}", st.integers(1, 9), st.sampled_from([-31, -30, 29, 30, 31])),
)


@examples(150)
@given(float_texts)
def test_a_constant_length_is_accepted_exactly_in_the_stated_range(text):
    robot = read(_set("d = 0.0", text))  # joint 1's d: any finite length is a valid DH d
    assert (robot is not None) == _accepted_number(text)
    if robot is None:
        try:
            description.parse(_set("d = 0.0", text), FILE)
        except description.DescriptionError as e:
            assert "joint 1 (q1): `d`" in str(e) and "out of range" in str(e)


@examples(100)
@given(float_texts)
def test_a_mass_is_accepted_exactly_when_in_range_and_not_negative(text):
    robot = read(_set("mass = 2.0", text))
    assert (robot is not None) == (_accepted_number(text) and Decimal(text) >= 0)


@examples(100)
@given(st.sampled_from(["mass = 2.0", "a = 0.5", "d = 0.0", "effort = 50.0"]), float_texts)
def test_a_number_in_quotes_is_refused_where_a_number_belongs(line, text):
    key = line.split(" = ")[0]
    try:
        description.parse(_set(line, _toml_string(text)), FILE)
    except description.DescriptionError as e:
        assert f"`{key}` must be a number, not the string" in str(e)
    else:
        raise AssertionError(f"{key} = \"{text}\" was accepted")


@examples(100)
@given(identifiers)
def test_a_robot_name_is_accepted_exactly_when_it_can_name_a_rust_module(name):
    robot = read(_set('name = "planar2"', _toml_string(name)))
    ok = bool(re.fullmatch(r"[a-z][a-z0-9_]*", name)) and name not in description.RUST_KEYWORDS
    ok = ok and name not in description.CRATE_NAMES
    assert (robot is not None) == ok, name


# --- through the whole generator -----------------------------------------------------------


def _generate(raw: bytes) -> tuple[int, str, dict]:
    """``python3 -m armdyn_codegen --quiet`` on ``raw`` in a fresh folder: (exit status,
    stderr, {name: parsed JSON} of the graphs written; the only other file is the URDF)."""
    with tempfile.TemporaryDirectory(prefix="fuzz-") as tmp:
        tmp = Path(tmp)
        (tmp / FILE).write_bytes(raw)
        err = io.StringIO()
        with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
            status = cli.main(["--quiet", "--out", str(tmp / "out"), str(tmp / FILE)])
        written = {f.name: json.loads(f.read_text()) for f in sorted((tmp / "out").glob("*.json"))}
        # Beside the two graphs, the robot as a URDF, and nothing else.
        others = sorted(f.name for f in (tmp / "out").glob("*") if f.suffix != ".json")
        assert others == sorted({f"{doc['robot']['name']}.urdf" for doc in written.values()}), others
    return status, err.getvalue(), written


@examples(25)
@given(mutated())
def test_the_generator_refuses_what_the_reader_refuses_and_writes_nothing(raw):
    if read(raw) is not None:
        return  # valid: generated below, on a few robots only (it takes a second each)
    status, err, written = _generate(raw)
    assert status == 1 and "nothing written" in err and not written


log_magnitudes = st.floats(-29.5, 29.5)


@examples(3)
@given(
    st.lists(log_magnitudes, min_size=4, max_size=4),  # a1, a2, m1, m2
    st.lists(log_magnitudes, min_size=2, max_size=2),  # inertia moments
    log_magnitudes,  # gravity
)
def test_random_valid_robots_generate_finite_models(lengths, moments, gravity):
    text = PLANAR2
    for old, e in zip(("a = 0.5", "a = 0.4", "mass = 2.0", "mass = 1.5"), lengths):
        text = text.replace(old, f"{old.split(' = ')[0]} = {10.0 ** e!r}", 1)
    text = text.replace("com = [-0.25, 0.0, 0.0]", f"com = [{-(10.0 ** lengths[0]) / 2!r}, 0.0, 0.0]")
    for row, e in zip(("[[0.0004, 0.0, 0.0], [0.0, 0.04186666666666667, 0.0], [0.0, 0.0, 0.04186666666666667]]",
                       "[[0.0003, 0.0, 0.0], [0.0, 0.02015, 0.0], [0.0, 0.0, 0.02015]]"), moments):
        x = repr(10.0 ** e)
        text = text.replace(row, f"[[{x}, 0.0, 0.0], [0.0, {x}, 0.0], [0.0, 0.0, {x}]]")
    text = text.replace("-9.81", repr(-(10.0 ** gravity)))
    note(text)
    assert read(text.encode()) is not None
    status, err, written = _generate(text.encode())
    # Links whose lengths differ by more than double precision resolves cannot move the tool
    # in two independent directions: refused by the task's rank check, with that reason.
    spread = abs(lengths[0] - lengths[1])
    if status == 1 and spread > 12:
        assert "rank at most 1 < 2" in err and "nothing written" in err, err
        return
    assert status == 0, err
    assert sorted(written) == ["planar2.json", "planar2_parametric.json"]
    for doc in written.values():
        for f in doc["functions"]:
            for ins in f["instructions"]:
                if ins[0] == "const":
                    assert math.isfinite(float(ins[1])), (f["name"], ins)
