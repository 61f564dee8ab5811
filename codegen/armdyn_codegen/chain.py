"""The generator's one internal robot representation: a chain of fixed placements and joint axes.

Every description (a DH table of ``description``, a URDF of ``urdf``) becomes a ``Chain``;
everything downstream (``derivation``, ``model``, ``export``) reads only this. Numbers stay
exact (sympy Rationals; sin/cos of multiples of pi/2 are exact 0 and +-1) so that the
derivation folds them before rounding once.

Frames: frame 0 is the base; the frame of link i (where its inertia is given, and what
``frame_poses`` reports) is

    F_i = F_{i-1} * P_i * Motion_i(q_i + offset_i) * Post_i

with ``P_i`` the joint's fixed placement in the previous link frame, ``Motion_i`` a rotation
about (revolute) or a translation along (prismatic) the unit ``axis`` given in the joint
frame, and ``Post_i`` a fixed placement from the moved joint frame to link frame i (the
identity for URDF; ``Tx(a) Rx(alpha)`` for standard DH). The end effector is
``F_n * tool``.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import sympy as sp

from .description import Link, Robot, exact_sin_cos

ZERO = sp.Integer(0)
ONE = sp.Integer(1)


@dataclass(frozen=True)
class Placement:
    """A rigid transform: rotation ``R`` (3 x 3, nested tuples) and translation ``p``, exact."""

    R: tuple
    p: tuple

    @staticmethod
    def identity() -> "Placement":
        return Placement(
            ((ONE, ZERO, ZERO), (ZERO, ONE, ZERO), (ZERO, ZERO, ONE)), (ZERO, ZERO, ZERO)
        )

    def matrix(self) -> sp.Matrix:
        return sp.Matrix(self.R)

    def vector(self) -> sp.Matrix:
        return sp.Matrix(self.p)

    def __mul__(self, other: "Placement") -> "Placement":
        R = self.matrix() * other.matrix()
        p = self.vector() + self.matrix() * other.vector()
        return Placement.of(R, p)

    def inverse(self) -> "Placement":
        Rt = self.matrix().T
        return Placement.of(Rt, -(Rt * self.vector()))

    @staticmethod
    def of(R: sp.Matrix, p: sp.Matrix) -> "Placement":
        return Placement(
            tuple(tuple(sp.expand(R[r, k]) for k in range(3)) for r in range(3)),
            tuple(sp.expand(p[k]) for k in range(3)),
        )

    def is_identity(self) -> bool:
        return self == Placement.identity()


def translation(x, y, z) -> Placement:
    return Placement(Placement.identity().R, (sp.sympify(x), sp.sympify(y), sp.sympify(z)))


def rotation_x(sin, cos) -> Placement:
    return Placement(((ONE, ZERO, ZERO), (ZERO, cos, -sin), (ZERO, sin, cos)), (ZERO,) * 3)


def rotation_y(sin, cos) -> Placement:
    return Placement(((cos, ZERO, sin), (ZERO, ONE, ZERO), (-sin, ZERO, cos)), (ZERO,) * 3)


def rotation_z(sin, cos) -> Placement:
    return Placement(((cos, -sin, ZERO), (sin, cos, ZERO), (ZERO, ZERO, ONE)), (ZERO,) * 3)


def axis_rotation(axis, sin, cos) -> Placement:
    """Rotation by an angle (given by its sin and cos) about the unit ``axis`` (Rodrigues)."""
    a = sp.Matrix(axis)
    A = a * a.T
    S = sp.Matrix([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    return Placement.of(A + cos * (sp.eye(3) - A) + sin * S, sp.zeros(3, 1))


@dataclass(frozen=True)
class ChainJoint:
    name: str
    kind: str  # "revolute" | "prismatic"
    placement: Placement  # joint frame in the previous link frame
    axis: tuple  # unit vector, joint frame
    offset: sp.Expr  # the motion is by q + offset (rad or m)
    post: Placement  # link frame in the moved joint frame
    lower: sp.Expr
    upper: sp.Expr
    effort: sp.Expr
    link: Link  # mass, COM and inertia in the link frame

    @property
    def revolute(self) -> bool:
        return self.kind == "revolute"


@dataclass(frozen=True)
class Chain:
    """A validated robot in the generator's internal form (see the module doc)."""

    path: Path
    name: str
    description: str
    convention: str  # "standard-dh" | "modified-dh" | "urdf" (where it came from)
    gravity: tuple
    joints: tuple[ChainJoint, ...]
    tool: Placement  # end-effector frame in link frame n
    sha256: str
    warnings: tuple[str, ...]
    sources: tuple = ()  # every file the model depends on (the description first)
    task: tuple = (0, 1, 2, 3, 4, 5)  # Jacobian rows of the task (description.parse_task)

    @property
    def dof(self) -> int:
        return len(self.joints)


def from_dh(robot: Robot) -> Chain:
    """A DH description (standard, or modified already converted to standard rows with a base
    transform and frame offsets, see ``description.Robot``) as a chain.

    Standard row i is ``Rz(theta) Tz(d) Tx(a) Rx(alpha)``: placement ``Tz(d)`` (revolute) or
    ``Rz(theta)`` (prismatic), motion about/along z, post ``Tx(a) Rx(alpha)``. The user's frame i
    is the standard frame i times ``Off_i^-1`` (``Off_i = Tx(oa) Rx(oalpha)``, the identity for
    a standard-DH file), so the placement of joint i gains ``Off_{i-1}`` (joint 1: the base
    transform) and the post becomes ``Tx(a) Rx(alpha) Off_i^-1``.
    """
    def tx_rx(a, alpha):
        s, c = exact_sin_cos(sp.sympify(alpha))
        return translation(a, 0, 0) * rotation_x(s, c)

    base = tx_rx(*robot.base)
    offsets = robot.frame_offsets or tuple((ZERO, ZERO) for _ in robot.joints)
    joints = []
    for i, j in enumerate(robot.joints):
        before = base if i == 0 else tx_rx(*offsets[i - 1])
        if j.revolute:
            pre, offset = translation(0, 0, j.d), j.theta
        else:
            s, c = exact_sin_cos(j.theta)
            pre, offset = rotation_z(s, c), j.d
        post = tx_rx(j.a, j.alpha) * tx_rx(*offsets[i]).inverse()
        joints.append(
            ChainJoint(
                name=j.name, kind=j.kind, placement=before * pre, axis=(ZERO, ZERO, ONE),
                offset=offset, post=post, lower=j.lower, upper=j.upper, effort=j.effort,
                link=j.link,
            )
        )
    return Chain(
        path=robot.path, name=robot.name, description=robot.description,
        convention=robot.convention, gravity=robot.gravity, joints=tuple(joints),
        tool=Placement.identity(), sha256=robot.sha256, warnings=robot.warnings,
        sources=(robot.path,), task=robot.task,
    )
