"""Symbolic derivation in CasADi SX: DH frames, geometric Jacobian, dynamics.

The same code runs over two kinds of leaves (see ``Leaves``):

* *trig-symbol* leaves: ``sin`` and ``cos`` of every revolute joint angle are free SX symbols
  ``s_i``, ``c_i`` and every robot constant is an SX symbol. Every quantity is then a polynomial
  in (s_i, c_i, prismatic q_i, qd, qdd), which ``normalize`` folds exactly;
* *numeric* leaves: ``sin(q_i)``, ``cos(q_i)`` of the input and the constants as doubles, with
  CasADi's own folding of 0 and 1. Used where it is smaller than the normalised form
  (kinematics).

Conventions (``robots/README.md``): standard DH ``A_i = Rz(theta_i) Tz(d_i) Tx(a_i) Rx(alpha_i)``;
link i is rigidly attached to frame i; tau = M(q) qdd + C(q, qd) qd + g(q) (thesis eq. 3.53).
"""

from __future__ import annotations

from dataclasses import dataclass

import casadi as ca

from .description import Robot, exact_sin_cos


@dataclass
class Leaves:
    """Everything the derivation reads: joint trig and variables, and robot constants."""

    s: list  # sin(theta_i) of each joint (a constant for prismatic joints)
    c: list  # cos(theta_i)
    d: list  # d_i (joint variable + offset for prismatic joints)
    a: list
    sa: list  # sin(alpha_i)
    ca_: list  # cos(alpha_i)
    mass: list
    com: list  # 3-vectors
    inertia: list  # 3 x 3 nested lists, at the COM
    gravity: list  # 3-vector
    revolute: list  # bools
    qd: ca.SX
    qdd: ca.SX


def _exact_constants(robot: Robot):
    """Robot constants as exact Rationals, in a fixed order (the replay parameter vector)."""
    vals, names = [], []
    for i, j in enumerate(robot.joints, start=1):
        sa, ca_ = exact_sin_cos(j.alpha)
        entries = [("a", j.a), ("sin_alpha", sa), ("cos_alpha", ca_)]
        if j.revolute:
            entries.append(("d", j.d))
        else:
            st, ct = exact_sin_cos(j.theta)
            entries += [("sin_theta", st), ("cos_theta", ct)]
        entries.append(("mass", j.link.mass))
        entries += [(f"com_{ax}", v) for ax, v in zip("xyz", j.link.com)]
        entries += [
            (f"I_{'xyz'[r]}{'xyz'[k]}", j.link.inertia[r][k]) for r in range(3) for k in range(3)
        ]
        for key, v in entries:
            names.append(f"{key}_{i}")
            vals.append(v)
    for ax, v in zip("xyz", robot.gravity):
        names.append(f"gravity_{ax}")
        vals.append(v)
    return names, vals


def trig_symbol_leaves(robot: Robot):
    """Leaves for the exact path. Returns (leaves, variables, parameter symbols, exact values)."""
    n = robot.dof
    names, vals = _exact_constants(robot)
    p = {nm: ca.SX.sym(nm) for nm in names}
    s, c, d, variables = [], [], [], []
    for i, j in enumerate(robot.joints, start=1):
        if j.revolute:
            si, ci = ca.SX.sym(f"s{i}"), ca.SX.sym(f"c{i}")
            s.append(si)
            c.append(ci)
            d.append(p[f"d_{i}"])
            variables.append(("sin", i - 1, si))
            variables.append(("cos", i - 1, ci))
        else:
            xi = ca.SX.sym(f"x{i}")  # q_i + d offset
            s.append(p[f"sin_theta_{i}"])
            c.append(p[f"cos_theta_{i}"])
            d.append(xi)
            variables.append(("lin", i - 1, xi))
    qd = ca.SX.sym("qd", n)
    qdd = ca.SX.sym("qdd", n)
    for k in range(n):
        variables.append(("qd", k, qd[k]))
    leaves = _leaves(robot, p, s, c, d, qd, qdd)
    return leaves, variables, [p[nm] for nm in names], vals


def _leaves(robot, p, s, c, d, qd, qdd):
    n = robot.dof
    return Leaves(
        s=s,
        c=c,
        d=d,
        a=[p[f"a_{i}"] for i in range(1, n + 1)],
        sa=[p[f"sin_alpha_{i}"] for i in range(1, n + 1)],
        ca_=[p[f"cos_alpha_{i}"] for i in range(1, n + 1)],
        mass=[p[f"mass_{i}"] for i in range(1, n + 1)],
        com=[[p[f"com_{ax}_{i}"] for ax in "xyz"] for i in range(1, n + 1)],
        inertia=[
            [[p[f"I_{r}{k}_{i}"] for k in "xyz"] for r in "xyz"] for i in range(1, n + 1)
        ],
        gravity=[p[f"gravity_{ax}"] for ax in "xyz"],
        revolute=[j.revolute for j in robot.joints],
        qd=qd,
        qdd=qdd,
    )


def numeric_leaves(robot: Robot, q: ca.SX, qd: ca.SX, qdd: ca.SX, trig):
    """Leaves for the direct path: constants as doubles, ``trig[i] = (sin, cos)`` SX nodes."""
    from .description import to_float

    names, vals = _exact_constants(robot)
    p = {nm: to_float(v) for nm, v in zip(names, vals)}
    s, c, d = [], [], []
    for i, j in enumerate(robot.joints, start=1):
        if j.revolute:
            s.append(trig[i - 1][0])
            c.append(trig[i - 1][1])
            d.append(p[f"d_{i}"])
        else:
            s.append(p[f"sin_theta_{i}"])
            c.append(p[f"cos_theta_{i}"])
            off = to_float(j.d)
            d.append(q[i - 1] + off if off != 0.0 else q[i - 1])
    return _leaves(robot, p, s, c, d, qd, qdd)


# --- small 3-vector helpers over SX or floats (no CasADi matrices: keeps 0/1 folding) ---


def cross(u, v):
    return [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]


def add(u, v):
    return [x + y for x, y in zip(u, v)]


def scale(k, u):
    return [k * x for x in u]


def matvec(m, v):
    return [m[r][0] * v[0] + m[r][1] * v[1] + m[r][2] * v[2] for r in range(3)]


def matTvec(m, v):
    return [m[0][r] * v[0] + m[1][r] * v[1] + m[2][r] * v[2] for r in range(3)]


def matmul(a, b):
    return [[sum(a[r][k] * b[k][cc] for k in range(3)) for cc in range(3)] for r in range(3)]


def dot(u, v):
    return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]


def dh_rotation(L: Leaves, i: int):
    """Rotation part of A_i = Rz(theta) Rx(alpha), frame i in frame i-1."""
    s, c, sa, ca_ = L.s[i], L.c[i], L.sa[i], L.ca_[i]
    return [[c, -s * ca_, s * sa], [s, c * ca_, -c * sa], [0, sa, ca_]]


def dh_translation(L: Leaves, i: int):
    """Origin of frame i in frame i-1: (a cos theta, a sin theta, d)."""
    return [L.a[i] * L.c[i], L.a[i] * L.s[i], L.d[i]]


def frames(L: Leaves):
    """Poses of frames 1..n in the base frame as (R, p) pairs (R 3 x 3 nested, p 3-vector)."""
    out = []
    R = [[1, 0, 0], [0, 1, 0], [0, 0, 1]]
    p = [0, 0, 0]
    for i in range(len(L.s)):
        Ri, pi = dh_rotation(L, i), dh_translation(L, i)
        p = add(p, matvec(R, pi))
        R = matmul(R, Ri)
        out.append((R, p))
    return out


def homogeneous(R, p):
    return [R[0] + [p[0]], R[1] + [p[1]], R[2] + [p[2]], [0, 0, 0, 1]]


def geometric_jacobian(L: Leaves, fr):
    """6 x n geometric Jacobian at the origin of frame n, base frame, rows vx vy vz wx wy wz."""
    n = len(fr)
    pe = fr[-1][1]
    cols = []
    for i in range(n):
        if i == 0:
            z, o = [0, 0, 1], [0, 0, 0]
        else:
            R, o = fr[i - 1]
            z = [R[0][2], R[1][2], R[2][2]]
        if L.revolute[i]:
            cols.append(cross(z, [pe[k] - o[k] for k in range(3)]) + z)
        else:
            cols.append(z + [0, 0, 0])
    return [[cols[j][r] for j in range(n)] for r in range(6)]


def rnea(L: Leaves, qd, qdd, with_gravity: bool):
    """Recursive Newton-Euler in the local DH frames (Luh, Walker and Paul).

    Returns tau = M qdd + C qd + g (g only if ``with_gravity``) as a list of n expressions.
    """
    n = len(L.s)
    z = [0, 0, 1]
    w = [0, 0, 0]
    wd = [0, 0, 0]
    acc = scale(-1, L.gravity) if with_gravity else [0, 0, 0]  # base "acceleration" = -gravity
    forces = []
    for i in range(n):
        R = dh_rotation(L, i)
        ps = [L.a[i], L.d[i] * L.sa[i], L.d[i] * L.ca_[i]]  # origin i-1 -> i, in frame i
        if L.revolute[i]:
            w_new = matTvec(R, add(w, scale(qd[i], z)))
            wd_new = matTvec(R, add(add(wd, scale(qdd[i], z)), cross(w, scale(qd[i], z))))
            acc = add(add(cross(wd_new, ps), cross(w_new, cross(w_new, ps))), matTvec(R, acc))
        else:
            w_new = matTvec(R, w)
            wd_new = matTvec(R, wd)
            zi = matTvec(R, z)
            acc = add(
                add(matTvec(R, add(acc, scale(qdd[i], z))), cross(wd_new, ps)),
                add(scale(2, cross(w_new, scale(qd[i], zi))), cross(w_new, cross(w_new, ps))),
            )
        w, wd = w_new, wd_new
        r = L.com[i]
        acc_c = add(add(cross(wd, r), cross(w, cross(w, r))), acc)
        F = scale(L.mass[i], acc_c)
        Ic = L.inertia[i]
        N = add(matvec(Ic, wd), cross(w, matvec(Ic, w)))
        forces.append((F, N, ps, R))
    # Backward pass: f, nn = force and moment (about O_{i-1}) on link i from link i-1, frame i.
    tau = [None] * n
    f = [0, 0, 0]
    nn = [0, 0, 0]
    for i in reversed(range(n)):
        F, N, ps, R = forces[i]
        if i + 1 < n:
            # Child's force and moment (about O_i) brought into frame i; the moment is then
            # carried from O_i to O_{i-1}: R1 (n + (R1^T p*_i) x f) = R1 n + p*_i x (R1 f).
            R1 = forces[i + 1][3]
            f_child = matvec(R1, f)
            n_child = matvec(R1, add(nn, cross(matTvec(R1, ps), f)))
        else:
            f_child, n_child = [0, 0, 0], [0, 0, 0]
        f_new = add(f_child, F)
        n_new = add(add(n_child, cross(add(ps, L.com[i]), F)), N)
        f, nn = f_new, n_new
        zi = matTvec(R, z)  # joint i axis (z of frame i-1) in frame i
        tau[i] = dot(nn, zi) if L.revolute[i] else dot(f, zi)
    return tau
