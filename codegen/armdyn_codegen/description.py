"""Robot description files (``robots/README.md``): parsing and validation.

Numbers are kept exact (``sympy.Rational`` from the decimal text, exact multiples of pi for
angles) so that the derivation folds parameters without rounding until the very end.
"""

from __future__ import annotations

import math
import re
import tomllib
from dataclasses import dataclass
from decimal import Decimal
from pathlib import Path

import sympy as sp

from .exact_values import (  # noqa: F401 (re-exported for the URDF reader)
    ACCEPTED_RANGE, MAX_DIGITS, MAX_MAGNITUDE, MIN_MAGNITUDE, _ANGLE, _BIDI,
    _DEG, _NUM, _PI, _Problems, _VAR, _WIDE,
    _check_keys, _decimal, _escape, _exact_angle, _exact_number, _plain,
    _show, _text_problem, _variable, _vector,
)

FORMAT_VERSION = 1
TOP_KEYS = {"format", "name", "description", "convention", "gravity", "joints", "task"}
# The task directions, in the order of the geometric Jacobian's rows (vx vy vz wx wy wz).
TASK_DIRECTIONS = ("x", "y", "z", "rx", "ry", "rz")
JOINT_KEYS = {"name", "kind", "a", "alpha", "d", "theta", "limits", "effort", "link"}
LINK_KEYS = {"mass", "com", "inertia", "accept_triangle_violation"}
# Relative slack for the rigid-body inertia checks, so that a published set rounded to a few
# digits is not rejected for its last digit.
INERTIA_SLACK = 1e-9

# Words that cannot name the robot's module `armdyn_generated::<name>`: Rust's strict and
# reserved keywords of every edition (the module would not parse), and the crates that the
# generated crate's root can name (a module of the same name would shadow or make ambiguous
# `core::`, `libm::` or `armdyn_derive::` paths there).
RUST_KEYWORDS = frozenset(
    "as break const continue crate else enum extern false fn for if impl in let loop match mod "
    "move mut pub ref return self Self static struct super trait true type unsafe use where "
    "while async await dyn abstract become box do final macro override priv typeof unsized "
    "virtual yield try gen".split()
)
CRATE_NAMES = ("alloc", "core", "libm", "armdyn_derive", "std")


class DescriptionError(Exception):
    """Every problem found in one description file; ``str()`` lists them, one a line."""

    def __init__(self, path: Path, problems: list[str]):
        self.path = Path(path)
        self.problems = problems
        super().__init__("\n".join(f"{path}: {p}" for p in problems))


PARAMETER_NAMES = ("m", "mx", "my", "mz", "Ixx", "Ixy", "Ixz", "Iyy", "Iyz", "Izz")
"""Standard inertial parameters of one link, in this order: mass (kg), first moment m*c (kg m),
inertia about the link frame's origin in its axes (kg m^2). The dynamics is linear in them."""


@dataclass(frozen=True)
class Link:
    mass: sp.Rational
    com: tuple[sp.Rational, sp.Rational, sp.Rational]
    inertia: tuple[tuple[sp.Rational, ...], ...]  # 3 x 3 at the COM, axes of the link frame

    def standard_parameters(self) -> list:
        """[m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz] with the inertia moved from the COM
        to the frame origin (parallel axis: I_o = I_c + m (|c|^2 E - c c^T)), exact."""
        m, c = self.mass, self.com
        cc = c[0] ** 2 + c[1] ** 2 + c[2] ** 2
        Io = [
            [self.inertia[r][k] + m * ((cc if r == k else 0) - c[r] * c[k]) for k in range(3)]
            for r in range(3)
        ]
        return [m, m * c[0], m * c[1], m * c[2], Io[0][0], Io[0][1], Io[0][2], Io[1][1], Io[1][2], Io[2][2]]


@dataclass(frozen=True)
class Joint:
    name: str
    kind: str  # "revolute" | "prismatic"
    a: sp.Expr
    alpha: sp.Expr
    d: sp.Expr  # offset added to q for a prismatic joint, constant otherwise
    theta: sp.Expr  # offset added to q for a revolute joint, constant otherwise
    lower: sp.Expr
    upper: sp.Expr
    effort: sp.Rational
    link: Link

    @property
    def revolute(self) -> bool:
        return self.kind == "revolute"


@dataclass(frozen=True)
class Robot:
    """A validated robot, always in standard DH form (a modified-DH file is converted exactly).

    ``base = (a0, alpha0)``: fixed transform ``Tx(a0) Rx(alpha0)`` from the base frame to the
    frame that the standard-DH chain starts from. ``frame_offsets[i] = (a, alpha)``: the user's
    frame i is the standard frame i times ``(Tx(a) Rx(alpha))^-1``. Both are zero for a
    standard-DH file. Links (mass, COM, inertia) stay in the user's frames; the derivation
    moves them into the chain's frames.
    """

    path: Path
    name: str
    description: str
    convention: str
    gravity: tuple[sp.Rational, sp.Rational, sp.Rational]
    joints: tuple[Joint, ...]
    sha256: str
    warnings: tuple[str, ...]
    base: tuple = (sp.Integer(0), sp.Integer(0))
    frame_offsets: tuple = ()
    task: tuple = ()  # Jacobian rows of the task (see ``parse_task``)

    @property
    def dof(self) -> int:
        return len(self.joints)


def _check_inertia(inertia, where, problems, accept_triangle, warnings):
    """Symmetric, positive semi-definite, principal moments obeying the triangle inequality."""
    m = sp.Matrix(inertia)
    if m != m.T:
        problems.add(where, "inertia must be symmetric (Ixy = Iyx, Ixz = Izx, Iyz = Izy)")
        return
    # Principal moments of a symmetric 3 x 3 (floats are fine for a check).
    import numpy as _np  # casadi depends on numpy, so it is always present

    eig = sorted(_np.linalg.eigvalsh(_np.array(m.tolist(), dtype=float)))
    scale = max(1.0, max(abs(e) for e in eig))
    if eig[0] < -INERTIA_SLACK * scale:
        problems.add(
            where,
            "inertia must be positive semi-definite; principal moments are "
            + ", ".join(f"{e:.6g}" for e in eig),
        )
        return
    a, b, c = eig
    if a + b < c - INERTIA_SLACK * scale:
        msg = (
            f"inertia breaks the triangle inequality of rigid bodies: principal moments "
            f"{a:.6g} + {b:.6g} < {c:.6g}"
        )
        if accept_triangle:
            warnings.append(f"{where}: warning: {msg} (accepted: accept_triangle_violation = true)")
        else:
            problems.add(where, msg + "; set `accept_triangle_violation = true` in this link to accept it")


def parse_task(value, problems):
    """``task``: the task-space directions the end effector is controlled in, as names of
    ``TASK_DIRECTIONS`` (``["x", "y", "z", "rz"]`` for a SCARA): distinct, with no rotation, ``rz``
    alone, or all of ``rx``, ``ry``, ``rz``. Returns the Jacobian rows in order, ``None`` when
    the key is absent (``resolve_task`` then picks the default), ``()`` after a problem."""
    if value is None:
        return None
    where = "top level"
    if not isinstance(value, list) or not value or not all(isinstance(v, str) for v in value):
        problems.add(where, f"`task` must be a non-empty array of direction names "
                            f"({', '.join(TASK_DIRECTIONS)}), got {_show(value)}")
        return ()
    rows = []
    for v in value:
        if v not in TASK_DIRECTIONS:
            problems.add(where, f"`task`: unknown direction {_show(v)}; known: "
                                f"{', '.join(TASK_DIRECTIONS)}")
            return ()
        if TASK_DIRECTIONS.index(v) in rows:
            problems.add(where, f"`task`: direction {_show(v)} is given twice")
            return ()
        rows.append(TASK_DIRECTIONS.index(v))
    rotations = tuple(r for r in sorted(rows) if r >= 3)
    if rotations not in ((), (5,), (3, 4, 5)):
        problems.add(where, "`task`: the rotations must be none, `rz` alone, or all of `rx`, "
                            f"`ry`, `rz`; got {', '.join(TASK_DIRECTIONS[r] for r in rotations)}")
        return ()
    return tuple(sorted(rows))


def resolve_task(task, dof: int, path):
    """The task rows of a robot of ``dof`` joints: the file's (at most ``dof`` directions), or
    all six by default for six joints or more; a robot with fewer joints must state its task."""
    if task == ():
        return ()  # already reported
    if task is None:
        if dof >= 6:
            return (0, 1, 2, 3, 4, 5)
        raise DescriptionError(path, [
            f"top level: `task` is missing: a robot of {dof} joints cannot control all six "
            f"task directions; state the ones it controls, e.g. task = "
            f"{_show(list(TASK_DIRECTIONS[:min(dof, 3)]))}"
        ])
    if len(task) > dof:
        raise DescriptionError(path, [
            f"top level: `task` has {len(task)} directions but the robot has {dof} joints; "
            "a task has at most one direction per joint"
        ])
    return task


def load(path: str | Path) -> Robot:
    """Read, parse and validate one description; raises DescriptionError listing every problem."""
    path = Path(path)
    try:
        raw = path.read_bytes()
    except OSError as e:
        raise DescriptionError(path, [f"cannot read: {e.strerror}"]) from None
    return parse(raw, path)


def parse(raw: bytes, path: str | Path) -> Robot:
    """Parse and validate the bytes of a description read from ``path`` (named in messages);
    raises DescriptionError listing every problem, and nothing else on any input."""
    path = Path(path)
    problems = _Problems()
    try:
        # "utf-8-sig": a leading byte-order mark, as some editors save it, is not content.
        doc = tomllib.loads(raw.decode("utf-8-sig"), parse_float=Decimal)
    except UnicodeDecodeError as e:
        line = raw[: e.start].count(b"\n") + 1
        raise DescriptionError(path, [f"line {line}: not UTF-8 text ({e.reason})"]) from None
    except tomllib.TOMLDecodeError as e:
        raise DescriptionError(path, [f"TOML syntax error: {e}"]) from None
    except RecursionError:
        raise DescriptionError(path, ["TOML: arrays or tables nested too deeply to read"]) from None
    except ValueError as e:  # an integer too long for Python to read (over 4300 digits)
        raise DescriptionError(path, [f"TOML: a value cannot be read: {e}".split(";")[0]]) from None

    warnings: list[str] = []
    _check_keys(doc, TOP_KEYS, "top level", problems)
    fmt = doc.get("format")
    if type(fmt) is not int or fmt != FORMAT_VERSION:
        problems.add("top level", f"`format` must be {FORMAT_VERSION}, got {_show(fmt)}")
    name = doc.get("name")
    if not isinstance(name, str) or not re.fullmatch(r"[a-z][a-z0-9_]*", name):
        problems.add(
            "top level",
            f"`name` must be a snake-case identifier ([a-z][a-z0-9_]*), got {_show(name)}",
        )
    elif name in RUST_KEYWORDS:
        problems.add(
            "top level",
            f"`name` \"{name}\" is a Rust keyword, so the generated module "
            f"`armdyn_generated::{name}` could not compile; choose another name",
        )
    elif name in CRATE_NAMES:
        problems.add(
            "top level",
            f"`name` \"{name}\" is the name of a crate that the generated crate uses "
            f"({', '.join(CRATE_NAMES)}); a module of that name would shadow it; "
            "choose another name",
        )
    description = doc.get("description", "")
    if not isinstance(description, str):
        problems.add("top level", "`description` must be a string")
        description = ""
    elif (why := _text_problem(description)) is not None:
        problems.add("top level", f"`description` {why}")
    convention = doc.get("convention")
    if convention not in ("standard-dh", "modified-dh"):
        problems.add(
            "top level",
            f"`convention` must be \"standard-dh\" or \"modified-dh\", got {_show(convention)}",
        )
    gravity = _vector(doc.get("gravity"), 3, "top level", problems, "`gravity`")
    task = parse_task(doc.get("task"), problems)

    joints_raw = doc.get("joints")
    joints: list[Joint] = []
    if not isinstance(joints_raw, list) or not joints_raw:
        problems.add("top level", "`joints` must be a non-empty array of tables ([[joints]])")
        joints_raw = []
    for i, jt in enumerate(joints_raw):
        jname = jt.get("name") if isinstance(jt, dict) else None
        where = f"joint {i + 1}" + (f" ({_plain(jname)})" if isinstance(jname, str) else "")
        if not _check_keys(jt, JOINT_KEYS, where, problems):
            continue
        if not isinstance(jname, str) or not jname:
            problems.add(where, "`name` must be a non-empty string")
        elif (why := _text_problem(jname)) is not None:
            problems.add(where, f"`name` {why}")
        kind = jt.get("kind")
        if kind not in ("revolute", "prismatic"):
            problems.add(where, f"`kind` must be \"revolute\" or \"prismatic\", got {_show(kind)}")
        values = {}
        for key, angle in (("a", False), ("alpha", True), ("d", False), ("theta", True)):
            if key not in jt:
                problems.add(where, f"missing `{key}`")
                continue
            is_var, val = _variable(jt[key], where, problems, f"`{key}`", angle)
            values[key] = (is_var, val)
            if is_var and key in ("a", "alpha"):
                problems.add(where, f"`{key}` cannot be the joint variable in DH parameters")
        th_var = values.get("theta", (False, None))[0]
        d_var = values.get("d", (False, None))[0]
        if kind == "prismatic" and th_var:
            problems.add(where, "a prismatic joint cannot have a variable `theta` (use `d = \"q\"`)")
        if kind == "revolute" and d_var:
            problems.add(where, "a revolute joint cannot have a variable `d` (use `theta = \"q\"`)")
        if kind == "prismatic" and "d" in values and not d_var:
            problems.add(where, "a prismatic joint needs `d = \"q\"` (or \"q + offset\")")
        if kind == "revolute" and "theta" in values and not th_var:
            problems.add(where, "a revolute joint needs `theta = \"q\"` (or \"q + offset\")")
        limits = jt.get("limits")
        lower = upper = None
        if not isinstance(limits, list) or len(limits) != 2:
            problems.add(where, f"`limits` must be [lower, upper], got {_show(limits)}")
        else:
            parse = _exact_angle if kind == "revolute" else _exact_number
            lower = parse(limits[0], where, problems, "`limits[0]`")
            upper = parse(limits[1], where, problems, "`limits[1]`")
            if lower is not None and upper is not None and not bool(lower < upper):
                problems.add(where, f"`limits`: lower {lower} must be below upper {upper}")
        effort = _exact_number(jt.get("effort"), where, problems, "`effort`")
        if effort is not None and effort <= 0:
            problems.add(where, f"`effort` must be positive, got {effort}")

        link_where = f"link {i + 1}" + (f" (joint {_plain(jname)})" if isinstance(jname, str) else "")
        lt = jt.get("link")
        link = None
        if lt is None:
            problems.add(link_where, "missing [joints.link] table")
        elif _check_keys(lt, LINK_KEYS, link_where, problems):
            mass = _exact_number(lt.get("mass"), link_where, problems, "`mass`")
            if mass is not None and mass < 0:
                problems.add(link_where, f"`mass` must be >= 0 kg, got {mass}")
            com = _vector(lt.get("com"), 3, link_where, problems, "`com`")
            inertia_raw = lt.get("inertia")
            inertia = None
            if not isinstance(inertia_raw, list) or len(inertia_raw) != 3:
                problems.add(link_where, "`inertia` must be a 3 x 3 list of lists (kg m^2)")
            else:
                rows = [_vector(r, 3, link_where, problems, f"`inertia[{k}]`") for k, r in enumerate(inertia_raw)]
                if all(r is not None for r in rows):
                    inertia = tuple(rows)
            accept = lt.get("accept_triangle_violation", False)
            if not isinstance(accept, bool):
                problems.add(link_where, "`accept_triangle_violation` must be true or false")
                accept = False
            if inertia is not None:
                _check_inertia(inertia, link_where, problems, accept, warnings)
            if None not in (mass, com, inertia):
                link = Link(mass, com, inertia)
        if not problems.items and link is not None:
            joints.append(
                Joint(
                    name=jname,
                    kind=kind,
                    a=values["a"][1],
                    alpha=values["alpha"][1],
                    d=values["d"][1],
                    theta=values["theta"][1],
                    lower=lower,
                    upper=upper,
                    effort=effort,
                    link=link,
                )
            )
    names = [j.get("name") for j in joints_raw if isinstance(j, dict)]
    for n in sorted({n for n in names if isinstance(n, str) and names.count(n) > 1}):
        problems.add("top level", f"joint name `{_plain(n)}` is used more than once")
    if problems.items:
        raise DescriptionError(path, problems.items)
    import hashlib

    task = resolve_task(task, len(joints), path)
    zero = (sp.Integer(0), sp.Integer(0))
    base, offsets = zero, tuple(zero for _ in joints)
    if convention == "modified-dh":
        joints, base, offsets = _modified_to_standard(joints)
    return Robot(
        path=path,
        name=name,
        description=description,
        convention=convention,
        gravity=gravity,
        joints=tuple(joints),
        sha256=hashlib.sha256(raw).hexdigest(),
        warnings=tuple(f"{path}: {w}" for w in warnings),
        base=base,
        frame_offsets=offsets,
        task=task,
    )


def _modified_to_standard(joints):
    """Craig's modified DH, ``A_i = Rx(alpha_{i-1}) Tx(a_{i-1}) Rz(theta_i) Tz(d_i)``, as a fixed
    base transform followed by standard-DH rows: the chain
    ``Rx(al0)Tx(a0) Rz(th1)Tz(d1) Rx(al1)Tx(a1) Rz(th2)Tz(d2) ...`` regrouped as
    ``[Tx(a0)Rx(al0)] [Rz(th1)Tz(d1)Tx(a1)Rx(al1)] [Rz(th2)...]`` (Rx and Tx commute). Link
    parameters stay in the modified frames (see ``Robot``)."""
    from dataclasses import replace

    n = len(joints)
    out, offsets = [], []
    for i, j in enumerate(joints):
        a_next = joints[i + 1].a if i + 1 < n else sp.Integer(0)
        al_next = joints[i + 1].alpha if i + 1 < n else sp.Integer(0)
        out.append(replace(j, a=a_next, alpha=al_next))
        offsets.append((a_next, al_next))
    return out, (joints[0].a, joints[0].alpha), tuple(offsets)


def exact_sin_cos(angle: sp.Expr) -> tuple[sp.Rational, sp.Rational]:
    """sin and cos of a constant angle: exact where sympy knows them as rationals
    (multiples of pi/2 give 0 and +-1 exactly), else the correctly rounded double as a Rational."""
    out = []
    for f in (sp.sin, sp.cos):
        v = sp.nsimplify(f(angle)) if angle.has(sp.pi) else f(angle)
        if isinstance(v, sp.Rational):
            out.append(v)
        else:
            out.append(sp.Rational(float(sp.N(v, 40))))
    return out[0], out[1]


def to_float(x: sp.Expr) -> float:
    """Correctly rounded double of an exact constant."""
    v = float(sp.N(x, 40))
    if not math.isfinite(v):
        raise ValueError(f"non-finite constant {x}")
    return v
