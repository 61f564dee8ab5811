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
import sympy as sp

from .description import PARAMETER_NAMES, Robot, exact_sin_cos


@dataclass
class Leaves:
    """Everything the derivation reads: joint trig and variables, and robot constants."""

    s: list  # sin(theta_i) of each joint (a constant for prismatic joints)
    c: list  # cos(theta_i)
    d: list  # d_i (joint variable + offset for prismatic joints)
    a: list
    sa: list  # sin(alpha_i)
    ca_: list  # cos(alpha_i)
    pi: list  # per link: standard parameters (description.PARAMETER_NAMES)
    gravity: list  # 3-vector, base frame
    base: tuple  # (a0, sin alpha0, cos alpha0): chain starts at Tx(a0) Rx(alpha0)
    offsets: list  # per frame: (a, sin alpha, cos alpha), user frame = standard frame X^-1
    revolute: list  # bools
    qd: ca.SX
    qdd: ca.SX


def exact_constants(robot: Robot):
    """Kinematic constants and gravity as exact Rationals, in a fixed order."""
    vals, names = [], []

    def put(name, v):
        names.append(name)
        vals.append(v)

    for i, j in enumerate(robot.joints, start=1):
        sa, ca_ = exact_sin_cos(j.alpha)
        put(f"a_{i}", j.a)
        put(f"sin_alpha_{i}", sa)
        put(f"cos_alpha_{i}", ca_)
        if j.revolute:
            put(f"d_{i}", j.d)
        else:
            st, ct = exact_sin_cos(j.theta)
            put(f"sin_theta_{i}", st)
            put(f"cos_theta_{i}", ct)
        oa, oal = robot.frame_offsets[i - 1] if robot.frame_offsets else (0, 0)
        osa, oca = exact_sin_cos(sp.sympify(oal))
        put(f"offset_a_{i}", sp.sympify(oa))
        put(f"offset_sin_alpha_{i}", osa)
        put(f"offset_cos_alpha_{i}", oca)
    bsa, bca = exact_sin_cos(sp.sympify(robot.base[1]))
    put("base_a", sp.sympify(robot.base[0]))
    put("base_sin_alpha", bsa)
    put("base_cos_alpha", bca)
    for ax, v in zip("xyz", robot.gravity):
        put(f"gravity_{ax}", v)
    return names, vals


def standard_parameters(robot: Robot):
    """Exact standard parameters of every link, concatenated (10 per link)."""
    return [v for j in robot.joints for v in j.link.standard_parameters()]


def parameter_names(robot: Robot):
    return [f"{nm}_{i}" for i in range(1, robot.dof + 1) for nm in PARAMETER_NAMES]


def trig_symbol_leaves(robot: Robot, parametric: bool = False):
    """Leaves for the exact path.

    Returns (leaves, variables, constant symbols, exact constant values). ``variables`` are the
    polynomial generators ``(kind, index, sx)``: kind ``sin``/``cos``/``lin`` (joint), ``qd``,
    ``qdd``, and with ``parametric`` also ``param`` (standard parameters, otherwise constants).
    """
    n = robot.dof
    names, vals = exact_constants(robot)
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
    for k in range(n):
        variables.append(("qdd", k, qdd[k]))
    pnames = parameter_names(robot)
    pvals = standard_parameters(robot)
    psx = [ca.SX.sym(nm) for nm in pnames]
    if parametric:
        for k, sym in enumerate(psx):
            variables.append(("param", k, sym))
    else:
        for nm, sym, v in zip(pnames, psx, pvals):
            p[nm] = sym
            names.append(nm)
            vals.append(v)
    leaves = _leaves(robot, p, s, c, d, qd, qdd, psx)
    return leaves, variables, [p[nm] for nm in names], vals


def _leaves(robot, p, s, c, d, qd, qdd, pi):
    n = robot.dof
    r = range(1, n + 1)
    return Leaves(
        s=s,
        c=c,
        d=d,
        a=[p[f"a_{i}"] for i in r],
        sa=[p[f"sin_alpha_{i}"] for i in r],
        ca_=[p[f"cos_alpha_{i}"] for i in r],
        pi=[list(pi[10 * k : 10 * k + 10]) for k in range(n)],
        gravity=[p[f"gravity_{ax}"] for ax in "xyz"],
        base=(p["base_a"], p["base_sin_alpha"], p["base_cos_alpha"]),
        offsets=[(p[f"offset_a_{i}"], p[f"offset_sin_alpha_{i}"], p[f"offset_cos_alpha_{i}"]) for i in r],
        revolute=[j.revolute for j in robot.joints],
        qd=qd,
        qdd=qdd,
    )


def numeric_leaves(robot: Robot, q: ca.SX, qd: ca.SX, qdd: ca.SX, trig, params=None):
    """Leaves for the direct path: constants as doubles, ``trig[i] = (sin, cos)`` SX nodes;
    standard parameters as doubles, or the SX vector ``params`` for a parametric model."""
    from .description import to_float

    names, vals = exact_constants(robot)
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
    if params is None:
        pi = [to_float(v) for v in standard_parameters(robot)]
    else:
        pi = [params[k] for k in range(params.numel())]
    return _leaves(robot, p, s, c, d, qd, qdd, pi)


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
    """Poses of the standard-DH frames 1..n in the base frame, as (R, p) pairs (R 3 x 3 nested,
    p 3-vector); frame 0 of the chain is the base transform ``Tx(a0) Rx(alpha0)``."""
    out = []
    R, p = base_frame(L)
    for i in range(len(L.s)):
        Ri, pi = dh_rotation(L, i), dh_translation(L, i)
        p = add(p, matvec(R, pi))
        R = matmul(R, Ri)
        out.append((R, p))
    return out


def base_frame(L: Leaves):
    a0, sa0, ca0 = L.base
    return [[1, 0, 0], [0, ca0, -sa0], [0, sa0, ca0]], [a0, 0, 0]


def user_frames(L: Leaves, fr):
    """The description's own frames: standard frame i times ``(Tx(a) Rx(alpha))^-1``."""
    out = []
    for (R, p), (a, sa, ca_) in zip(fr, L.offsets):
        Rx_T = [[1, 0, 0], [0, ca_, sa], [0, -sa, ca_]]
        Ru = matmul(R, Rx_T)
        out.append((Ru, [p[k] - a * R[k][0] for k in range(3)]))
    return out


def homogeneous(R, p):
    return [R[0] + [p[0]], R[1] + [p[1]], R[2] + [p[2]], [0, 0, 0, 1]]


def geometric_jacobian(L: Leaves, fr):
    """6 x n geometric Jacobian at the origin of frame n, base frame, rows vx vy vz wx wy wz."""
    n = len(fr)
    pe = fr[-1][1]
    cols = []
    for i in range(n):
        R, o = base_frame(L) if i == 0 else fr[i - 1]
        z = [R[0][2], R[1][2], R[2][2]]
        if L.revolute[i]:
            cols.append(cross(z, [pe[k] - o[k] for k in range(3)]) + z)
        else:
            cols.append(z + [0, 0, 0])
    return [[cols[j][r] for j in range(n)] for r in range(6)]


def chain_frame_parameters(L: Leaves, i: int):
    """Link i's standard parameters moved from the description's frame i (origin O, where
    they are given) into the chain's frame i = frame i * Tx(a) Rx(alpha) (origin P = O + t,
    t = (a, 0, 0)); linear in the parameters, the identity for a standard-DH description:

    h' = R^T (h - m t),  I_P = I_O + (m |t|^2 - 2 h.t) E - m t t^T + h t^T + t h^T,
    I' = R^T I_P R,  with R = Rx(alpha).
    """
    m, hx, hy, hz, ixx, ixy, ixz, iyy, iyz, izz = L.pi[i]
    a, sa, ca_ = L.offsets[i]
    h = [hx, hy, hz]
    Io = [[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]]
    t = [a, 0, 0]
    diag = m * a * a - 2 * hx * a
    IP = [
        [Io[r][k] + (diag if r == k else 0) - m * t[r] * t[k] + h[r] * t[k] + t[r] * h[k]
         for k in range(3)]
        for r in range(3)
    ]
    R = [[1, 0, 0], [0, ca_, -sa], [0, sa, ca_]]
    h2 = matTvec(R, [h[k] - m * t[k] for k in range(3)])
    I2 = matmul(matmul([[R[k][r] for k in range(3)] for r in range(3)], IP), R)
    return m, h2, I2


def rnea(L: Leaves, qd, qdd, with_gravity: bool):
    """Recursive Newton-Euler in the local DH frames (Luh, Walker and Paul), in the standard
    inertial parameters (mass, first moment h = m c, inertia about the frame origin), so the
    result is linear in them.

    Returns tau = M qdd + C qd + g (g only if ``with_gravity``) as a list of n expressions.
    """
    n = len(L.s)
    z = [0, 0, 1]
    w = [0, 0, 0]
    wd = [0, 0, 0]
    Rb, _ = base_frame(L)
    # Base "acceleration" = -gravity, in the frame the chain starts from.
    acc = matTvec(Rb, scale(-1, L.gravity)) if with_gravity else [0, 0, 0]
    forces = []
    for i in range(n):
        R = dh_rotation(L, i)
        ps = [L.a[i], L.d[i] * L.sa[i], L.d[i] * L.ca_[i]]  # O_{i-1} -> O_i, in frame i
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
        m, h, Io = chain_frame_parameters(L, i)
        # Newton-Euler of link i about its frame origin O_i.
        F = add(scale(m, acc), add(cross(wd, h), cross(w, cross(w, h))))
        N = add(add(matvec(Io, wd), cross(w, matvec(Io, w))), cross(h, acc))
        forces.append((F, N, ps, R))
    # Backward pass: f, nn = force and moment (about O_{i-1}) on link i from link i-1, frame i.
    tau = [None] * n
    f = [0, 0, 0]
    nn = [0, 0, 0]
    for i in reversed(range(n)):
        F, N, ps, R = forces[i]
        if i + 1 < n:
            R1 = forces[i + 1][3]
            f_child = matvec(R1, f)  # child's force, frame i
            n_child = matvec(R1, nn)  # child's moment about O_i, frame i
        else:
            f_child, n_child = [0, 0, 0], [0, 0, 0]
        f = add(f_child, F)
        nn = add(add(n_child, N), cross(ps, f))  # moved from O_i to O_{i-1}
        zi = matTvec(R, z)  # joint i axis (z of frame i-1) in frame i
        tau[i] = dot(nn, zi) if L.revolute[i] else dot(f, zi)
    return tau
