"""Symbolic derivation in CasADi SX over a ``chain.Chain``: frames, geometric Jacobian, dynamics.

The same code runs over two kinds of leaves (see ``Leaves``):

* *trig-symbol* leaves: ``sin`` and ``cos`` of every revolute joint angle are free SX symbols
  ``s_i``, ``c_i``, and every robot constant other than 0 and +-1 is an SX symbol. Every quantity
  is then a polynomial in (s_i, c_i, prismatic q_i, qd, qdd), which ``normalize`` folds exactly;
* *numeric* leaves: ``sin(q_i)``, ``cos(q_i)`` of the input and the constants as doubles, with
  CasADi's own folding of 0 and 1. Used where it is smaller than the normalised form.

Each joint's transform from link frame i-1 to link frame i, ``P_i Motion_i Post_i`` (``chain``),
is precomputed exactly as ``R_i = R0 + c R_c + s R_s`` and ``p_i = p0 + c p_c + s p_s`` (revolute)
or ``R_i = R0``, ``p_i = p0 + x p_a`` (prismatic), so exact zeros (pi/2 twists, axes along a
frame axis) never reach the graph. Link i is rigidly attached to frame i;
tau = M(q) qdd + C(q, qd) qd + g(q) (thesis eq. 3.53).
"""

from __future__ import annotations

from dataclasses import dataclass

import casadi as ca
import sympy as sp

from .chain import Chain
from .description import PARAMETER_NAMES, to_float


@dataclass
class Leaves:
    """Everything the derivation reads: joint trig and variables, and robot constants."""

    s: list  # sin(q_i + offset) of each revolute joint (None for prismatic)
    c: list  # cos(q_i + offset)
    x: list  # q_i + offset of each prismatic joint (None for revolute)
    R0: list  # per joint, 3 x 3: R_i = R0 + c Rc + s Rs (revolute) or R0 (prismatic)
    Rc: list
    Rs: list
    p0: list  # per joint, 3: p_i = p0 + c pc + s ps (revolute) or p0 + x pa (prismatic)
    pc: list
    ps: list
    pa: list
    z: list  # joint axis in link frame i
    pQ: list  # a point Q of the joint axis (nearest O_{i-1}) in link frame i-1
    rE: list  # Q -> link frame origin O_i, link frame i (at x = 0 for a prismatic joint)
    jaxis: list  # joint axis in link frame i-1
    tool: tuple  # (R, p) end-effector frame in link frame n
    pi: list  # per link: standard parameters (description.PARAMETER_NAMES)
    gravity: list  # 3-vector, base frame
    revolute: list  # bools
    qd: object
    qdd: object


def _m(t):
    return sp.Matrix(t)


def joint_coefficients(chain: Chain):
    """Exact coefficient matrices of every joint transform (see ``Leaves``), one dict per joint."""
    out = []
    for j in chain.joints:
        RP, pP = j.placement.matrix(), j.placement.vector()
        Rq, pq = j.post.matrix(), j.post.vector()
        a = _m(j.axis)
        A = a * a.T
        S = sp.Matrix([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
        z, jaxis = Rq.T * a, RP * a
        along = (jaxis.T * pP)[0, 0]
        # The joint frame origin J, moved along the axis to the point Q nearest to O_{i-1}:
        # Q = O_{i-1} + pQ (frame i-1) = O_i - rE (frame i). For a DH joint pQ = 0.
        k = {"z": z, "pQ": pP - jaxis * along, "rE": Rq.T * pq + z * along, "jaxis": jaxis}
        if j.revolute:
            k["R0"], k["Rc"], k["Rs"] = RP * A * Rq, RP * (sp.eye(3) - A) * Rq, RP * S * Rq
            k["p0"], k["pc"], k["ps"] = pP + RP * A * pq, RP * (sp.eye(3) - A) * pq, RP * S * pq
        else:
            k["R0"], k["p0"], k["pa"] = RP * Rq, pP + RP * pq, RP * a
        out.append({key: v.applyfunc(sp.expand) for key, v in k.items()})
    return out


def standard_parameters(chain: Chain):
    """Exact standard parameters of every link, concatenated (10 per link)."""
    return [v for j in chain.joints for v in j.link.standard_parameters()]


def parameter_names(chain: Chain):
    return [f"{nm}_{i}" for i in range(1, chain.dof + 1) for nm in PARAMETER_NAMES]


def _build(chain: Chain, const, s, c, x, qd, qdd, pi):
    """Leaves from the chain's exact constants; ``const(name, exact) -> leaf``."""
    coefs = joint_coefficients(chain)

    def vec(name, v):
        return [const(f"{name}_{r}", v[r]) for r in range(3)]

    def mat(name, m):
        return [[const(f"{name}_{r}{k}", m[r, k]) for k in range(3)] for r in range(3)]

    L = Leaves(s=s, c=c, x=x, R0=[], Rc=[], Rs=[], p0=[], pc=[], ps=[], pa=[], z=[], pQ=[],
               rE=[], jaxis=[], tool=None, pi=[list(pi[10 * k: 10 * k + 10]) for k in range(chain.dof)],
               gravity=[const(f"gravity_{ax}", v) for ax, v in zip("xyz", chain.gravity)],
               revolute=[j.revolute for j in chain.joints], qd=qd, qdd=qdd)
    for i, k in enumerate(coefs, start=1):
        for key in ("R0", "Rc", "Rs"):
            getattr(L, key).append(mat(f"j{i}_{key}", k[key]) if key in k else None)
        for key in ("p0", "pc", "ps", "pa", "z", "pQ", "rE", "jaxis"):
            getattr(L, key).append(vec(f"j{i}_{key}", k[key]) if key in k else None)
    L.tool = (mat("tool_R", chain.tool.matrix()), vec("tool_p", chain.tool.vector()))
    return L


def trig_symbol_leaves(chain: Chain, parametric: bool = False):
    """Leaves for the exact path.

    Returns (leaves, variables, constant symbols, exact constant values). ``variables`` are the
    polynomial generators ``(kind, index, sx)``: kind ``sin``/``cos``/``lin`` (joint), ``qd``,
    ``qdd``, and with ``parametric`` also ``param`` (standard parameters, otherwise constants).
    Constants equal to 0, 1 or -1 are literal (exact in double); the others are symbols whose
    exact values ``normalize`` substitutes.
    """
    n = chain.dof
    syms, vals = [], []

    def const(name, v):
        v = sp.nsimplify(v) if isinstance(v, sp.Expr) and v.has(sp.pi) else v
        if v in (0, 1, -1):
            return float(v)
        sym = ca.SX.sym(name)
        syms.append(sym)
        vals.append(v)
        return sym

    s, c, x, variables = [], [], [], []
    for i, j in enumerate(chain.joints, start=1):
        if j.revolute:
            si, ci = ca.SX.sym(f"s{i}"), ca.SX.sym(f"c{i}")
            s.append(si)
            c.append(ci)
            x.append(None)
            variables.append(("sin", i - 1, si))
            variables.append(("cos", i - 1, ci))
        else:
            xi = ca.SX.sym(f"x{i}")  # q_i + offset
            s.append(None)
            c.append(None)
            x.append(xi)
            variables.append(("lin", i - 1, xi))
    qd = ca.SX.sym("qd", n)
    qdd = ca.SX.sym("qdd", n)
    for k in range(n):
        variables.append(("qd", k, qd[k]))
    for k in range(n):
        variables.append(("qdd", k, qdd[k]))
    pnames = parameter_names(chain)
    pvals = standard_parameters(chain)
    if parametric:
        psx = [ca.SX.sym(nm) for nm in pnames]
        for k, sym in enumerate(psx):
            variables.append(("param", k, sym))
    else:
        psx = [const(nm, v) for nm, v in zip(pnames, pvals)]
    leaves = _build(chain, const, s, c, x, qd, qdd, psx)
    return leaves, variables, syms, vals


def numeric_leaves(chain: Chain, q, qd, qdd, trig, params=None):
    """Leaves for the direct path: constants as doubles, ``trig[i] = (sin, cos)`` SX nodes;
    standard parameters as doubles, or the SX vector ``params`` for a parametric model."""
    s, c, x = [], [], []
    for i, j in enumerate(chain.joints):
        if j.revolute:
            s.append(trig[i][0])
            c.append(trig[i][1])
            x.append(None)
        else:
            off = to_float(j.offset)
            s.append(None)
            c.append(None)
            x.append(q[i] + off if off != 0.0 else q[i])
    if params is None:
        pi = [to_float(v) for v in standard_parameters(chain)]
    else:
        pi = [params[k] for k in range(params.numel())]
    return _build(chain, lambda name, v: to_float(v), s, c, x, qd, qdd, pi)


# --- small 3-vector helpers over SX or floats (no CasADi matrices: keeps 0/1 folding) ---


def _is0(v) -> bool:
    return isinstance(v, (int, float)) and v == 0


def _sum(*terms):
    out = 0.0
    for t in terms:
        if _is0(t):
            continue
        out = t if _is0(out) else out + t
    return out


def _sub(a, b):
    if _is0(b):
        return a
    if _is0(a):
        return -b
    return a - b


def cross(u, v):
    return [_sub(_mul(u[1], v[2]), _mul(u[2], v[1])),
            _sub(_mul(u[2], v[0]), _mul(u[0], v[2])),
            _sub(_mul(u[0], v[1]), _mul(u[1], v[0]))]


def _mul(a, b):
    if _is0(a) or _is0(b):
        return 0.0
    if isinstance(a, (int, float)) and a == 1:
        return b
    if isinstance(b, (int, float)) and b == 1:
        return a
    return a * b


def add(u, v):
    return [_sum(x, y) for x, y in zip(u, v)]


def scale(k, u):
    return [_mul(k, x) for x in u]


def matvec(m, v):
    return [_sum(*(_mul(m[r][k], v[k]) for k in range(3))) for r in range(3)]


def matTvec(m, v):
    return [_sum(*(_mul(m[k][r], v[k]) for k in range(3))) for r in range(3)]


def matmul(a, b):
    return [[_sum(*(_mul(a[r][k], b[k][cc]) for k in range(3))) for cc in range(3)] for r in range(3)]


def dot(u, v):
    return _sum(*(_mul(u[k], v[k]) for k in range(3)))


def joint_transform(L: Leaves, i: int):
    """(R_i, p_i): link frame i in link frame i-1, from the precomputed coefficients."""
    if L.revolute[i]:
        s, c = L.s[i], L.c[i]
        R = [[_sum(L.R0[i][r][k], _mul(L.Rc[i][r][k], c), _mul(L.Rs[i][r][k], s)) for k in range(3)]
             for r in range(3)]
        p = [_sum(L.p0[i][r], _mul(L.pc[i][r], c), _mul(L.ps[i][r], s)) for r in range(3)]
    else:
        R = L.R0[i]
        p = [_sum(L.p0[i][r], _mul(L.pa[i][r], L.x[i])) for r in range(3)]
    return R, p


def identity():
    return [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]], [0.0, 0.0, 0.0]


def frames(L: Leaves):
    """Poses of link frames 1..n in the base frame, as (R, p) pairs (R 3 x 3 nested, p 3)."""
    out = []
    R, p = identity()
    for i in range(len(L.revolute)):
        Ri, pi = joint_transform(L, i)
        p = add(p, matvec(R, pi))
        R = matmul(R, Ri)
        out.append((R, p))
    return out


def end_effector(L: Leaves, fr):
    R, p = fr[-1]
    Rt, pt = L.tool
    return matmul(R, Rt), add(p, matvec(R, pt))


def homogeneous(R, p):
    return [list(R[0]) + [p[0]], list(R[1]) + [p[1]], list(R[2]) + [p[2]], [0, 0, 0, 1]]


def geometric_jacobian(L: Leaves, fr):
    """6 x n geometric Jacobian at the end-effector origin, base frame, rows vx vy vz wx wy wz."""
    n = len(fr)
    pe = end_effector(L, fr)[1]
    cols = []
    for i in range(n):
        R, o = identity() if i == 0 else fr[i - 1]
        z = matvec(R, L.jaxis[i])
        if L.revolute[i]:
            point = add(o, matvec(R, L.pQ[i]))
            cols.append(cross(z, [_sub(pe[k], point[k]) for k in range(3)]) + z)
        else:
            cols.append(z + [0.0, 0.0, 0.0])
    return [[cols[j][r] for j in range(n)] for r in range(6)]


def rnea(L: Leaves, qd, qdd, with_gravity: bool):
    """Recursive Newton-Euler in the local link frames (Luh, Walker and Paul), in the standard
    inertial parameters (mass, first moment h = m c, inertia about the link frame origin), so
    the result is linear in them.

    Joint i turns (or slides) link i about the axis ``z`` through the point Q_i, fixed in link
    i-1 at ``pQ`` and in link i at ``-rE``: the acceleration of O_i is that of Q_i as a point of
    link i-1, plus that of O_i about Q_i as a point of link i. For a DH joint Q_i = O_{i-1}
    (``pQ = 0``), which is Luh, Walker and Paul's form.

    Returns tau = M qdd + C qd + g (g only if ``with_gravity``) as a list of n expressions.
    """
    n = len(L.revolute)
    w = [0.0, 0.0, 0.0]
    wd = [0.0, 0.0, 0.0]
    # Base "acceleration" = -gravity, base frame.
    acc = scale(-1.0, L.gravity) if with_gravity else [0.0, 0.0, 0.0]
    bodies = []
    for i in range(n):
        R, _ = joint_transform(L, i)
        z = L.z[i]
        pQ = L.pQ[i]
        # Acceleration of the axis point Q_i (a point of link i-1), link frame i.
        aJ = matTvec(R, add(acc, add(cross(wd, pQ), cross(w, cross(w, pQ)))))
        wi = matTvec(R, w)
        wdi = matTvec(R, wd)
        if L.revolute[i]:
            zq = scale(qd[i], z)
            wd_new = add(add(wdi, cross(wi, zq)), scale(qdd[i], z))
            w_new = add(wi, zq)
            r = L.rE[i]
            acc = add(aJ, add(cross(wd_new, r), cross(w_new, cross(w_new, r))))
        else:
            w_new, wd_new = wi, wdi
            r = add(L.rE[i], scale(L.x[i], z))
            acc = add(
                add(aJ, add(cross(wd_new, r), cross(w_new, cross(w_new, r)))),
                add(scale(2.0, cross(w_new, scale(qd[i], z))), scale(qdd[i], z)),
            )
        w, wd = w_new, wd_new
        m, hx, hy, hz, ixx, ixy, ixz, iyy, iyz, izz = L.pi[i]
        h = [hx, hy, hz]
        Io = [[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]]
        # Newton-Euler of link i about its frame origin O_i.
        F = add(scale(m, acc), add(cross(wd, h), cross(w, cross(w, h))))
        N = add(add(matvec(Io, wd), cross(w, matvec(Io, w))), cross(h, acc))
        bodies.append((F, N, R, r))
    # Backward pass: f, nn = force and moment (about O_i) on link i from link i-1, frame i.
    tau = [None] * n
    f = [0.0, 0.0, 0.0]
    nn = [0.0, 0.0, 0.0]
    for i in reversed(range(n)):
        F, N, R, r = bodies[i]
        if i + 1 < n:
            Rc, pQc = bodies[i + 1][2], L.pQ[i + 1]
            fc = matvec(Rc, f)
            nJ = matvec(Rc, nn_J)  # child's moment about its axis point Q_{i+1}, frame i
            f = add(F, fc)
            nn = add(add(N, nJ), cross(pQc, fc))
        else:
            f, nn = F, N
        nn_J = add(nn, cross(r, f))  # moment about the axis point Q_i
        z = L.z[i]
        tau[i] = dot(nn_J, z) if L.revolute[i] else dot(f, z)
    return tau


def crba(L: Leaves):
    """Mass matrix by the composite-rigid-body algorithm (Featherstone, RBDA ch. 6.2) in the
    local link frames: the composite inertia of links i..n (mass, first moment, inertia about
    O_i, frame i), its momentum for a unit velocity of joint i, carried down the chain to each
    joint j < i and projected on its motion. A second derivation of ``M`` beside the derivative
    of Newton-Euler; the generator keeps the smaller graph."""
    n = len(L.revolute)
    T = [joint_transform(L, i) for i in range(n)]

    def motion(i):
        z = L.z[i]
        if L.revolute[i]:
            return z, cross(z, L.rE[i])  # angular, linear velocity of O_i per unit qd_i
        return [0.0, 0.0, 0.0], z

    comp = []
    for i in range(n):
        m, hx, hy, hz, ixx, ixy, ixz, iyy, iyz, izz = L.pi[i]
        comp.append((m, [hx, hy, hz], [[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]]))
    for i in reversed(range(1, n)):
        m, h, I = comp[i]
        R, p = T[i]
        hr = matvec(R, h)
        Rt = [[R[k][r] for k in range(3)] for r in range(3)]
        Ir = matmul(matmul(R, I), Rt)
        pp, hp = dot(p, p), dot(hr, p)
        diag = _sum(_mul(m, pp), _mul(2.0, hp))
        In = [[_sub(_sub(_sub(_sum(Ir[r][k], diag if r == k else 0.0), _mul(m, _mul(p[r], p[k]))),
                         _mul(hr[r], p[k])), _mul(p[r], hr[k]))
               for k in range(3)] for r in range(3)]
        m0, h0, I0 = comp[i - 1]
        comp[i - 1] = (_sum(m0, m), add(h0, add(hr, scale(m, p))),
                       [[_sum(I0[r][k], In[r][k]) for k in range(3)] for r in range(3)])
    M = [[0.0] * n for _ in range(n)]
    for i in range(n):
        m, h, I = comp[i]
        w, v = motion(i)
        f = [_sub(a, b) for a, b in zip(scale(m, v), cross(h, w))]
        nn = add(matvec(I, w), cross(h, v))
        M[i][i] = _sum(dot(w, nn), dot(v, f))
        for j in reversed(range(i)):
            R, p = T[j + 1]
            f = matvec(R, f)
            nn = add(matvec(R, nn), cross(p, f))
            wj, vj = motion(j)
            M[i][j] = M[j][i] = _sum(dot(wj, nn), dot(vj, f))
    return M
