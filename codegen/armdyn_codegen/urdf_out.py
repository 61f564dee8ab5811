"""URDF output: any chain (a DH table included) as a URDF that Pinocchio, MuJoCo, RViz and ROS load.

A URDF joint moves its child link's frame, so each link is written in its moved joint frame
``G_i = F_i Post_i^-1`` (``chain``): its COM and inertia are moved there, ``Post_i`` and the
joint offset are folded into the next joint's origin, and the end effector becomes a massless
link ``<name>_tool`` on a fixed joint. The model (M, c, g, Jacobian, end-effector pose) is
unchanged; the link frames of a DH robot are its joint frames. Written with urdf_parser_py;
numbers as the shortest decimal text that reads back to the same double. Gravity is not part of
URDF: it is stated in a comment.
"""

from __future__ import annotations

import math

import sympy as sp

from .chain import Chain, Placement, axis_rotation, translation
from .description import exact_sin_cos, to_float


def _f(x) -> float:
    return to_float(x) + 0.0  # no "-0.0" in the text


def _rpy(R):
    """Roll, pitch, yaw of ``R = Rz(yaw) Ry(pitch) Rx(roll)`` (floats)."""
    r = [[_f(R[i][k]) for k in range(3)] for i in range(3)]
    if abs(r[2][0]) >= 1.0 - 1e-12:
        pitch = math.copysign(math.pi / 2, -r[2][0])
        return [math.atan2(-r[1][2], r[1][1]) + 0.0, pitch, 0.0]
    return [a + 0.0 for a in (math.atan2(r[2][1], r[2][2]),
                              math.atan2(-r[2][0], math.hypot(r[0][0], r[1][0])),
                              math.atan2(r[1][0], r[0][0]))]


def _pose(P: Placement):
    from urdf_parser_py import urdf as U

    return U.Pose(xyz=[_f(x) for x in P.p], rpy=_rpy(P.R))


def render(chain: Chain, source: str) -> str:
    from urdf_parser_py import urdf as U

    robot = U.URDF(name=chain.name)
    links = [f"{chain.name}_base"] + [f"{chain.name}_link{i}" for i in range(1, chain.dof + 1)]
    robot.add_link(U.Link(name=links[0]))
    before = Placement.identity()  # Post of the previous joint (and its frame change)
    for i, j in enumerate(chain.joints, start=1):
        if j.revolute:
            s, c = exact_sin_cos(sp.sympify(j.offset))
            motion = axis_rotation(j.axis, s, c)
        else:
            motion = translation(*(j.offset * a for a in j.axis))
        origin = before * j.placement * motion
        post = j.post
        R = post.matrix()
        com = R * sp.Matrix(j.link.com) + post.vector()
        inertia = R * sp.Matrix(j.link.inertia) * R.T
        f = lambda r, k: _f(inertia[r, k])  # noqa: E731
        robot.add_link(U.Link(
            name=links[i],
            inertial=U.Inertial(
                mass=_f(j.link.mass),
                inertia=U.Inertia(ixx=f(0, 0), ixy=f(0, 1), ixz=f(0, 2), iyy=f(1, 1),
                                  iyz=f(1, 2), izz=f(2, 2)),
                origin=U.Pose(xyz=[_f(com[k]) for k in range(3)], rpy=[0.0, 0.0, 0.0]),
            ),
        ))
        robot.add_joint(U.Joint(
            name=j.name, parent=links[i - 1], child=links[i],
            joint_type="revolute" if j.revolute else "prismatic",
            axis=[_f(a) for a in j.axis], origin=_pose(origin),
            limit=U.JointLimit(effort=_f(j.effort), velocity=0.0,
                               lower=_f(j.lower), upper=_f(j.upper)),
        ))
        before = post
    tool = f"{chain.name}_tool"
    robot.add_link(U.Link(name=tool))
    robot.add_joint(U.Joint(name=f"{chain.name}_tool_joint", parent=links[-1], child=tool,
                            joint_type="fixed", origin=_pose(before * chain.tool)))
    text = robot.to_xml_string()
    g = ", ".join(repr(_f(x)) for x in chain.gravity)
    head, _, body = text.partition("\n")
    comment = (
        f"<!-- @generated from {source} by armdyn-codegen; do not edit: change the "
        f"description and run it again.\n"
        f"     Gravity (base frame, m/s^2): [{g}]. Joint velocity limits are not modelled "
        f"(written as 0). -->\n"
    )
    return head + "\n" + comment + body
