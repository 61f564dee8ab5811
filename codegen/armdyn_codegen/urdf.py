"""URDF input: a description (``convention = "urdf"``) naming a URDF file, a base and a tip link.

The URDF is parsed by ``urdf_parser_py`` (ROS's reference parser, pinned in
``codegen/requirements.txt``); this module only turns the parsed tree into a ``chain.Chain``:

* the chain is the path of joints from ``base_link`` down to ``tip_link``; its revolute,
  continuous and prismatic joints move, its fixed joints are merged;
* every other joint that moves with the arm (off the path, e.g. gripper fingers, or on it but
  listed in ``[locked]``) is fixed at its stated value (``[locked]``; a mimic joint follows its
  leader), so each moving body is the rigid union of its links, whose masses, COMs and
  inertias are lumped exactly into the body's frame (the child link of its joint);
* angles within 1e-9 rad of a multiple of pi/2 (the ``1.57079632679`` of a URDF) are taken as
  that multiple, so their sin and cos are exact 0 and +-1;
* limits and efforts come from the URDF's ``<limit>`` unless ``[joints.<name>]`` overrides
  them; a continuous joint without an override gets ``[-pi, pi]``.

Every problem is reported with the description file, the URDF file and the element; nothing
is written.
"""

from __future__ import annotations

import hashlib
import math
import re
import tomllib
from decimal import Decimal
from pathlib import Path

import sympy as sp

from .chain import (ONE, ZERO, Chain, ChainJoint, Placement, axis_rotation, rotation_x,
                    rotation_y, rotation_z, translation)
from .description import (FORMAT_VERSION, DescriptionError, Link, _check_inertia, _check_keys,
                          _exact_angle, _exact_number, _Problems, _vector, exact_sin_cos,
                          parse_task, resolve_task)

TOP_KEYS = {"format", "name", "description", "convention", "urdf", "base_link", "tip_link",
            "gravity", "locked", "joints", "accept_triangle_violation", "task"}
OVERRIDE_KEYS = {"limits", "effort"}
DEFAULT_GRAVITY = (ZERO, ZERO, sp.Rational("-9.81"))
# An angle this close to a multiple of pi/2 is taken as exactly that multiple.
RIGHT_ANGLE_SNAP = 1e-9
# An axis whose length differs from 1 by more than this is an error (it is then normalised).
AXIS_UNIT_TOLERANCE = 1e-6
MOVING = ("revolute", "continuous", "prismatic")
SUPPORTED = MOVING + ("fixed",)


class _Fail(Exception):
    pass


def _number(x, where, problems, what):
    """A parsed URDF float -> exact Rational of its shortest decimal form; None on error."""
    if isinstance(x, bool) or not isinstance(x, (int, float)):
        problems.add(where, f"{what} must be a number, got {x!r}")
        return None
    if not math.isfinite(x):
        problems.add(where, f"{what} must be finite, got {x}")
        return None
    return sp.Rational(repr(float(x)))


def _angle(x, where, problems, what):
    v = _number(x, where, problems, what)
    if v is None:
        return None
    k = round(float(x) / (math.pi / 2))
    if abs(float(x) - k * math.pi / 2) <= RIGHT_ANGLE_SNAP:
        return k * sp.pi / 2
    return v


def _triple(values, where, problems, what, angle=False, default=(0.0, 0.0, 0.0)):
    if values is None:
        values = default
    if len(values) != 3:
        problems.add(where, f"{what} must have 3 numbers, got {values!r}")
        return None
    conv = _angle if angle else _number
    out = [conv(v, where, problems, f"{what}[{i}]") for i, v in enumerate(values)]
    return None if any(v is None for v in out) else tuple(out)


def _pose(origin, where, problems) -> Placement | None:
    """URDF ``<origin xyz rpy>``: translation, then ``Rz(yaw) Ry(pitch) Rx(roll)``."""
    xyz = _triple(origin.xyz if origin is not None else None, where, problems, "origin xyz")
    rpy = _triple(origin.rpy if origin is not None else None, where, problems, "origin rpy", True)
    if xyz is None or rpy is None:
        return None
    (sr, cr), (sp_, cp), (sy, cy) = (exact_sin_cos(a) for a in rpy)
    R = rotation_z(sy, cy) * rotation_y(sp_, cp) * rotation_x(sr, cr)
    return translation(*xyz) * R


def _parse(path: Path, text: str, where_file: str):
    """The parsed URDF (urdf_parser_py), or DescriptionError naming the failing element."""
    from lxml import etree
    from urdf_parser_py import urdf as U
    from urdf_parser_py.xml_reflection import core

    quiet = core.on_error

    def raise_error(message):
        # Elements and attributes the URDF format does not define (simulator extensions such
        # as <gazebo>, <dynamics D=...>) are ignored, as ROS does; every other complaint of the
        # parser is an error.
        if not str(message).startswith(("Unknown attribute", "Unknown tag")):
            raise _Fail(message)

    core.on_error = raise_error
    try:
        try:
            return U.URDF.from_xml_string(text.encode("utf-8"))
        except Exception as e:  # noqa: BLE001 - every parser failure becomes a user error
            first = f"{where_file}: cannot parse the URDF: {_one_line(e)}"
        # Find the element that fails, by parsing each top-level <link> and <joint> alone.
        try:
            root = etree.fromstring(text.encode("utf-8"))
        except Exception as e:  # noqa: BLE001
            raise DescriptionError(path, [f"{where_file}: not well-formed XML: {_one_line(e)}"]) from None
        found = []
        for el in root:
            if el.tag not in ("link", "joint"):
                continue
            cls = U.Link if el.tag == "link" else U.Joint
            try:
                cls.from_xml_string(etree.tostring(el))
            except Exception as e:  # noqa: BLE001
                found.append(f"{where_file}: {el.tag} `{el.get('name')}`: {_one_line(e)}")
        raise DescriptionError(path, found or [first])
    finally:
        core.on_error = quiet


def _one_line(e) -> str:
    return re.sub(r"\s+", " ", str(e)).strip() or type(e).__name__


def load(path: str | Path) -> Chain:
    """Parse and validate one URDF-based description; raises DescriptionError listing every
    problem (the description file first, then the URDF file and element)."""
    path = Path(path)
    problems = _Problems()
    try:
        raw = path.read_bytes()
        doc = tomllib.loads(raw.decode("utf-8"), parse_float=Decimal)
    except OSError as e:
        raise DescriptionError(path, [f"cannot read: {e.strerror}"]) from None
    except (UnicodeDecodeError, tomllib.TOMLDecodeError) as e:
        raise DescriptionError(path, [f"TOML syntax error: {e}"]) from None
    _check_keys(doc, TOP_KEYS, "top level", problems)
    task = parse_task(doc.get("task"), problems)
    if doc.get("format") != FORMAT_VERSION:
        problems.add("top level", f"`format` must be {FORMAT_VERSION}, got {doc.get('format')!r}")
    name = doc.get("name")
    if not isinstance(name, str) or not re.fullmatch(r"[a-z][a-z0-9_]*", name):
        problems.add("top level", f"`name` must be a snake-case identifier, got {name!r}")
    description = doc.get("description", "")
    if not isinstance(description, str):
        problems.add("top level", "`description` must be a string")
        description = ""
    gravity = DEFAULT_GRAVITY
    if "gravity" in doc:
        gravity = _vector(doc["gravity"], 3, "top level", problems, "`gravity`")
    links = {}
    for key in ("urdf", "base_link", "tip_link"):
        v = doc.get(key)
        if not isinstance(v, str) or not v:
            problems.add("top level", f"`{key}` must be a non-empty string, got {v!r}")
        links[key] = v
    locked_raw = doc.get("locked", {})
    locked = {}
    if not isinstance(locked_raw, dict):
        problems.add("[locked]", "must be a table of joint name = value")
    else:
        for jn, v in locked_raw.items():
            val = _exact_angle(v, f"[locked] `{jn}`", problems, "value")
            if val is not None:
                locked[jn] = val
    overrides_raw = doc.get("joints", {})
    overrides = {}
    if not isinstance(overrides_raw, dict):
        problems.add("[joints]", "must be tables [joints.<urdf joint name>] with limits or effort")
    else:
        for jn, t in overrides_raw.items():
            where = f"[joints.{jn}]"
            if not _check_keys(t, OVERRIDE_KEYS, where, problems):
                continue
            o = {}
            if "limits" in t:
                lim = t["limits"]
                if not isinstance(lim, list) or len(lim) != 2:
                    problems.add(where, f"`limits` must be [lower, upper], got {lim!r}")
                else:
                    lo = _exact_angle(lim[0], where, problems, "`limits[0]`")
                    hi = _exact_angle(lim[1], where, problems, "`limits[1]`")
                    if lo is not None and hi is not None and not bool(lo < hi):
                        problems.add(where, f"`limits`: lower {lo} must be below upper {hi}")
                    o["limits"] = (lo, hi)
            if "effort" in t:
                eff = _exact_number(t["effort"], where, problems, "`effort`")
                if eff is not None and eff <= 0:
                    problems.add(where, f"`effort` must be positive, got {eff}")
                o["effort"] = eff
            overrides[jn] = o
    accept = doc.get("accept_triangle_violation", [])
    if not isinstance(accept, list) or not all(isinstance(x, str) for x in accept):
        problems.add("top level", "`accept_triangle_violation` must be a list of URDF link names")
        accept = []
    if doc.get("convention") != "urdf":
        problems.add("top level", f"`convention` must be \"urdf\", got {doc.get('convention')!r}")
    if problems.items:
        raise DescriptionError(path, problems.items)

    urdf_path = (path.parent / links["urdf"])
    try:
        urdf_raw = urdf_path.read_bytes()
        text = urdf_raw.decode("utf-8")
    except OSError as e:
        raise DescriptionError(path, [f"`urdf`: cannot read {urdf_path}: {e.strerror}"]) from None
    except UnicodeDecodeError as e:
        raise DescriptionError(path, [f"`urdf`: {urdf_path} is not UTF-8 text: {e}"]) from None
    where_file = str(urdf_path)
    model = _parse(path, text, where_file)
    builder = _Builder(model, where_file, links["base_link"], links["tip_link"], locked, overrides,
                       set(accept))
    joints, tool, warnings = builder.build()
    if builder.problems.items:
        raise DescriptionError(path, builder.problems.items)
    task = resolve_task(task, len(joints), path)
    return Chain(
        path=path, name=name, description=description, convention="urdf",
        gravity=tuple(gravity), joints=tuple(joints), tool=tool,
        sha256=hashlib.sha256(raw + b"\0" + urdf_raw).hexdigest(),
        warnings=tuple(f"{path}: {w}" for w in warnings), sources=(path, urdf_path), task=task,
    )


class _Builder:
    """URDF tree -> chain joints with lumped bodies (see the module doc)."""

    def __init__(self, model, where_file, base, tip, locked, overrides, accept_triangle):
        self.model, self.file = model, where_file
        self.base, self.tip = base, tip
        self.locked, self.overrides = locked, overrides
        self.accept_triangle = accept_triangle
        self.problems = _Problems()
        self.warnings: list[str] = []
        self.links = {}
        for link in model.links:
            if link.name in self.links:
                self.problems.add(f"{where_file}: link `{link.name}`", "defined more than once")
            self.links[link.name] = link
        self.by_child, self.children, self.by_name = {}, {}, {}
        for j in model.joints:
            w = self._where(j)
            if j.name in self.by_name:
                self.problems.add(w, "defined more than once")
            self.by_name[j.name] = j
            for role, ln in (("parent", j.parent), ("child", j.child)):
                if ln not in self.links:
                    self.problems.add(w, f"{role} link `{ln}` is not defined")
            if j.child in self.by_child:
                self.problems.add(w, f"link `{j.child}` already has parent joint "
                                     f"`{self.by_child[j.child].name}`")
            self.by_child[j.child] = j
            self.children.setdefault(j.parent, []).append(j)

    def _where(self, j):
        return f"{self.file}: joint `{j.name}`"

    def _fail(self, where, rule):
        self.problems.add(where, rule)
        raise _Fail()

    def build(self):
        try:
            return self._build()
        except _Fail:
            return [], Placement.identity(), self.warnings

    def _build(self):
        if self.problems.items:
            raise _Fail()
        for key, ln in (("base_link", self.base), ("tip_link", self.tip)):
            if ln not in self.links:
                self._fail(f"{self.file}", f"`{key}` `{ln}` is not a link of this URDF")
        path = []
        ln = self.tip
        while ln != self.base:
            j = self.by_child.get(ln)
            if j is None:
                self._fail(self.file, f"broken chain: tip link `{self.tip}` is not below base "
                                      f"link `{self.base}` (link `{ln}` has no parent joint)")
            path.append(j)
            ln = j.parent
            if len(path) > len(self.by_name):
                self._fail(self.file, "the joints form a loop")
        path.reverse()
        for name in self.accept_triangle:
            if name not in self.links:
                self._fail(f"{self.file}", f"link `{name}` (in `accept_triangle_violation`) is not a "
                                           "link of this URDF")
        for name in list(self.locked) + list(self.overrides):
            if name not in self.by_name:
                self._fail(f"{self.file}", f"joint `{name}` (named in the description) is not a "
                                           "joint of this URDF")
        moving = [j for j in path if j.type in MOVING and j.name not in self.locked]
        for j in path:
            if j.type not in SUPPORTED:
                self._fail(self._where(j), f"unsupported joint type `{j.type}` (supported: "
                                           f"{', '.join(SUPPORTED)})")
            if j in moving and j.mimic is not None:
                self._fail(self._where(j), "a mimic joint on the chain must be listed in [locked]")
        if not moving:
            self._fail(self.file, f"no moving joint between `{self.base}` and `{self.tip}`")
        self.values = {}  # joint name -> locked value (exact)
        stops = set(j.name for j in moving)
        bodies = [self._body(self.base, stops)]
        for j in moving:
            bodies.append(self._body(j.child, stops))
        joints = []
        for k, j in enumerate(moving):
            w = self._where(j)
            parent_pose = bodies[k]["poses"].get(j.parent)
            origin = self._origin(j)
            axis = self._axis(j)
            lower, upper, effort = self._limits(j)
            body = bodies[k + 1]
            joints.append(ChainJoint(
                name=j.name, kind="prismatic" if j.type == "prismatic" else "revolute",
                placement=parent_pose * origin, axis=axis, offset=ZERO,
                post=Placement.identity(), lower=lower, upper=upper, effort=effort,
                link=body["link"],
            ))
            del w
        tool = bodies[-1]["poses"][self.tip]
        return joints, tool, self.warnings

    def _origin(self, j) -> Placement:
        p = _pose(j.origin, self._where(j), self.problems)
        if p is None:
            raise _Fail()
        return p

    def _axis(self, j):
        w = self._where(j)
        a = _triple(j.axis, w, self.problems, "axis", default=(1.0, 0.0, 0.0))
        if a is None:
            raise _Fail()
        norm2 = sum(x * x for x in a)
        if norm2 == 0:
            self._fail(w, "axis is zero")
        norm = math.sqrt(float(norm2))
        if abs(norm - 1.0) > AXIS_UNIT_TOLERANCE:
            self._fail(w, f"axis {[float(x) for x in a]} is not a unit vector (length {norm:.9g})")
        if norm2 != 1:
            a = tuple(sp.Rational(repr(float(x) / norm)) for x in a)
        return a

    def _limits(self, j):
        w = self._where(j)
        o = self.overrides.get(j.name, {})
        lim = j.limit
        if "limits" in o:
            lower, upper = o["limits"]
        elif j.type == "continuous":
            lower, upper = -sp.pi, sp.pi
        elif lim is None or lim.lower is None or lim.upper is None:
            self._fail(w, "no <limit lower upper>; give `limits` in [joints." + j.name + "]")
        else:
            conv = _number
            lower = conv(lim.lower, w, self.problems, "limit lower")
            upper = conv(lim.upper, w, self.problems, "limit upper")
            if lower is None or upper is None:
                raise _Fail()
            if not bool(lower < upper):
                self._fail(w, f"limit lower {lower} must be below upper {upper}")
        if "effort" in o:
            effort = o["effort"]
        else:
            effort = _number(lim.effort, w, self.problems, "limit effort") if (
                lim is not None and lim.effort is not None) else None
            if effort is None or effort <= 0:
                self._fail(w, "needs a positive <limit effort>, or `effort` in [joints."
                              + j.name + "]")
        return lower, upper, effort

    def _check_limit(self, j):
        """The <limit> of a joint that is fixed here (locked, mimic) must still be numbers."""
        if j.limit is None:
            return
        for attr in ("lower", "upper", "effort", "velocity"):
            v = getattr(j.limit, attr, None)
            if v is not None and _number(v, self._where(j), self.problems, f"limit {attr}") is None:
                raise _Fail()

    def _motion(self, j, value) -> Placement:
        axis = self._axis(j)
        if j.type == "prismatic":
            return translation(*(value * a for a in axis))
        s, c = exact_sin_cos(sp.sympify(value))
        return axis_rotation(axis, s, c)

    def _value(self, j, seen=()):
        """The fixed value of a joint off the chain (or locked on it)."""
        if j.name in self.locked:
            return self.locked[j.name]
        w = self._where(j)
        if j.mimic is not None:
            leader = self.by_name.get(j.mimic.joint)
            if leader is None:
                self._fail(w, f"mimics joint `{j.mimic.joint}`, which is not defined")
            if leader.name in seen:
                self._fail(w, "mimic joints form a loop")
            base = self._value(leader, seen + (j.name,))
            mult = _number(1.0 if j.mimic.multiplier is None else j.mimic.multiplier, w,
                           self.problems, "mimic multiplier")
            off = _number(0.0 if j.mimic.offset is None else j.mimic.offset, w, self.problems,
                          "mimic offset")
            if mult is None or off is None:
                raise _Fail()
            return mult * base + off
        if j.name in self.stops:
            self._fail(w, "is a moving joint of the chain; it cannot be followed by a mimic joint")
        self._fail(w, f"{j.type} joint off the chain from `{self.base}` to `{self.tip}`, which "
                      f"moves with the arm: give its value in [locked] (`{j.name} = 0.0`)")

    def _body(self, root, stops):
        """The links rigidly attached to ``root`` (stopping at moving chain joints), their poses
        in root's frame, and their lumped inertia."""
        self.stops = stops
        poses = {root: Placement.identity()}
        todo = [root]
        parts = []
        while todo:
            ln = todo.pop()
            parts.append(ln)
            for j in self.children.get(ln, []):
                if j.name in stops:
                    continue
                w = self._where(j)
                if j.type not in SUPPORTED:
                    self._fail(w, f"unsupported joint type `{j.type}` (supported: "
                                  f"{', '.join(SUPPORTED)})")
                T = poses[ln] * self._origin(j)
                self._check_limit(j)
                if j.type != "fixed":
                    T = T * self._motion(j, self._value(j))
                poses[j.child] = T
                todo.append(j.child)
        return {"poses": poses, "link": self._lump([(poses[ln], self.links[ln]) for ln in
                                                    sorted(parts)])}

    def _lump(self, parts) -> Link:
        """Mass, COM and inertia (about the COM, body axes) of rigidly joined links, exact."""
        total = ZERO
        first = sp.zeros(3, 1)
        pieces = []
        for T, link in parts:
            inertial = link.inertial
            if inertial is None:
                continue
            w = f"{self.file}: link `{link.name}`"
            m = _number(inertial.mass, w, self.problems, "mass")
            if m is None:
                raise _Fail()
            if m < 0:
                self._fail(w, f"mass must be >= 0 kg, got {m}")
            it = inertial.inertia
            names = ("ixx", "ixy", "ixz", "iyy", "iyz", "izz")
            vals = [_number(getattr(it, k, 0.0) if it is not None else 0.0, w, self.problems, k)
                    for k in names]
            if any(v is None for v in vals):
                raise _Fail()
            ixx, ixy, ixz, iyy, iyz, izz = vals
            I = ((ixx, ixy, ixz), (ixy, iyy, iyz), (ixz, iyz, izz))
            n_before = len(self.problems.items)
            _check_inertia(I, w, self.problems, link.name in self.accept_triangle, self.warnings)
            if len(self.problems.items) > n_before:
                raise _Fail()
            O = _pose(inertial.origin, w, self.problems)
            if O is None:
                raise _Fail()
            X = T * O  # the inertial frame in the body frame
            R = X.matrix()
            pieces.append((m, X.vector(), R * sp.Matrix(I) * R.T))
            total += m
            first += m * X.vector()
        com = first / total if total != 0 else sp.zeros(3, 1)
        inertia = sp.zeros(3, 3)
        for m, c, Ic in pieces:
            d = c - com
            inertia += Ic + m * ((d.T * d)[0, 0] * sp.eye(3) - d * d.T)
        inertia = inertia.applyfunc(sp.expand)
        inertia = (inertia + inertia.T) / 2
        return Link(
            mass=total,
            com=tuple(sp.expand(com[k]) for k in range(3)),
            inertia=tuple(tuple(inertia[r, k] for k in range(3)) for r in range(3)),
        )


__all__ = ["load", "ONE"]
