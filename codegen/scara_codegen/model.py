"""The numeric model of one robot: every exported function, derived and made compact.

Each function is derived twice and the smaller equivalent graph is kept:

* exact: derivation over trig-symbol leaves, exact normal form, Horner + CSE (``normalize``);
* direct: derivation over ``sin(q)``/``cos(q)`` nodes with the constants folded by CasADi.

Both are exact rewrites of the same function; the generator's tests check the kept graph
against an independent Lagrangian derivation.
"""

from __future__ import annotations

from dataclasses import dataclass

import casadi as ca

from . import derivation as dv
from . import export, normalize
from .description import Robot, to_float


@dataclass
class Generated:
    name: str
    doc: str
    inputs: list  # [(name, len, doc)]
    output: tuple  # (name, shape, doc)
    code: list
    result: list
    counts: dict
    method: str


def _flatten(x):
    if isinstance(x, (list, tuple)):
        return [e for item in x for e in _flatten(item)]
    return [x]


def _cost(code) -> int:
    c = export.counts(code)
    return c["flops"] + 10 * c["trig"]


class _Derivation:
    """The symbolic quantities of one robot over one kind of leaves."""

    def __init__(self, robot: Robot, L: dv.Leaves, dq):
        self.robot, self.L, self.dq = robot, L, dq
        self.fr = dv.frames(L)
        n = robot.dof
        tau = dv.rnea(L, L.qd, L.qdd, with_gravity=True)
        tau_c = dv.rnea(L, L.qd, [0] * n, with_gravity=False)
        tau_g = dv.rnea(L, [0] * n, [0] * n, with_gravity=True)
        tau_sx = ca.vertcat(*tau)
        M = ca.jacobian(tau_sx, L.qdd)
        self.M = [[M[r, k] for k in range(n)] for r in range(n)]
        self.c = tau_c
        self.g = tau_g
        # Christoffel symbols of the first kind: C_kj = sum_i G_ijk qd_i,
        # G_ijk = (dM_kj/dq_i + dM_ki/dq_j - dM_ij/dq_k) / 2, so that Mdot - 2C is skew.
        dM = [[[dq(self.M[r][k], i) for i in range(n)] for k in range(n)] for r in range(n)]
        self.C = [
            [
                sum(
                    0.5 * (dM[k][j][i] + dM[k][i][j] - dM[i][j][k]) * L.qd[i]
                    for i in range(n)
                )
                for j in range(n)
            ]
            for k in range(n)
        ]

    def function(self, name):
        n = self.robot.dof
        if name == "frame_poses":
            return [dv.homogeneous(R, p) for R, p in self.fr]
        if name == "end_effector_pose":
            return dv.homogeneous(*self.fr[-1])
        if name == "jacobian":
            return dv.geometric_jacobian(self.L, self.fr)
        if name == "mass_matrix":
            return self.M
        if name == "coriolis_matrix":
            return self.C
        if name == "coriolis":
            return self.c
        if name == "gravity":
            return self.g
        raise KeyError(name)
        del n


def _specs(robot: Robot):
    n = robot.dof
    q = ("q", n, "joint positions q (rad for revolute joints, m for prismatic joints)")
    qd = ("qd", n, "joint velocities qd (rad/s or m/s)")
    return [
        ("frame_poses", [q], ("poses", [n, 4, 4],
         "homogeneous transforms T_0i of DH frames 1..n in the base frame (m)"),
         "Poses of every DH frame, `A_1 A_2 ... A_i` with `A_i = Rz(theta_i) Tz(d_i) Tx(a_i) Rx(alpha_i)` (thesis eq. 3.2-3.7)."),
        ("end_effector_pose", [q], ("pose", [4, 4],
         "homogeneous transform of the end-effector frame (frame n) in the base frame (m)"),
         "End-effector pose, forward kinematics `T_0n` (thesis eq. 3.7)."),
        ("jacobian", [q], ("jacobian", [6, n],
         "rows vx vy vz (m/s) and wx wy wz (rad/s) per unit joint velocity, base frame"),
         "Geometric Jacobian of the end-effector frame origin in the base frame (thesis eq. 3.29)."),
        ("mass_matrix", [q], ("mass_matrix", [n, n],
         "symmetric positive definite M(q) (kg m^2, kg m, kg)"),
         "Joint-space mass matrix M(q) of `tau = M qdd + C qd + g` (thesis eq. 3.53, 3.67)."),
        ("coriolis_matrix", [q, qd], ("coriolis_matrix", [n, n],
         "C(q, qd) with C qd the velocity term; Mdot - 2C is skew-symmetric"),
         "Coriolis and centrifugal matrix C(q, qd) from the Christoffel symbols of M."),
        ("coriolis", [q, qd], ("coriolis", [n],
         "c(q, qd) = C(q, qd) qd (N m or N)"),
         "Velocity term c(q, qd) = C(q, qd) qd of the equations of motion (thesis eq. 3.53)."),
        ("gravity", [q], ("gravity", [n],
         "g(q), joint torques (N m) or forces (N) that hold the robot still"),
         "Gravity term g(q) of the equations of motion (thesis eq. 3.53, 3.68)."),
    ]


def generate(robot: Robot, log=None) -> list[Generated]:
    n = robot.dof
    # Exact path: trig-symbol leaves.
    Lt, variables, psyms, pvals = dv.trig_symbol_leaves(robot)
    var_sx = ca.vertcat(*[v[2] for v in variables])
    p_sx = ca.vertcat(*psyms)
    index = {(kind, j): v for kind, j, v in variables}

    def dq_trig(e, i):
        if robot.joints[i].revolute:
            s, c = index[("sin", i)], index[("cos", i)]
            return c * ca.jacobian(e, s) - s * ca.jacobian(e, c)
        return ca.jacobian(e, index[("lin", i)])

    exact = _Derivation(robot, Lt, dq_trig)

    # Final leaves: the function inputs, with sin/cos of each joint angle computed once.
    q = ca.SX.sym("q", n)
    qd = ca.SX.sym("qd", n)
    qdd = ca.SX.sym("qdd", n)
    trig = []
    final_leaves = []
    for i, j in enumerate(robot.joints):
        if j.revolute:
            off = to_float(j.theta)
            ang = q[i] + off if off != 0.0 else q[i]
            trig.append((ca.sin(ang), ca.cos(ang)))
        else:
            trig.append(None)
    for kind, j, _ in variables:
        if kind == "sin":
            final_leaves.append(trig[j][0])
        elif kind == "cos":
            final_leaves.append(trig[j][1])
        elif kind == "lin":
            off = to_float(robot.joints[j].d)
            final_leaves.append(q[j] + off if off != 0.0 else q[j])
        else:
            final_leaves.append(qd[j])

    # Direct path: numeric leaves.
    Ln = dv.numeric_leaves(robot, q, qd, qdd, trig)
    direct = _Derivation(robot, Ln, lambda e, i: ca.jacobian(e, q[i]))

    out = []
    for name, inputs, output, doc in _specs(robot):
        args = [q] if len(inputs) == 1 else [q, qd]
        # exact
        entries = _flatten(exact.function(name))
        fx = ca.Function("f", [var_sx, p_sx], [ca.vertcat(*[ca.SX(e) for e in entries])])
        polys = normalize.replay(fx, variables, pvals)
        col = normalize.rebuild(polys, final_leaves)
        code_e, res_e = export.instructions(ca.Function(name, args, [col]))
        # direct
        entries_d = _flatten(direct.function(name))
        col_d = ca.cse(ca.vertcat(*[ca.SX(e) for e in entries_d]))
        code_d, res_d = export.instructions(ca.Function(name, args, [col_d]))
        if _cost(code_d) < _cost(code_e):
            code, res, method = code_d, res_d, "direct"
        else:
            code, res, method = code_e, res_e, "exact"
        cnt = export.counts(code)
        if log:
            log(
                f"  {robot.name}::{name}: {cnt['flops']} flops, {cnt['trig']} trig ({method}; "
                f"exact {export.counts(code_e)['flops']}+{export.counts(code_e)['trig']}t, "
                f"direct {export.counts(code_d)['flops']}+{export.counts(code_d)['trig']}t)"
            )
        out.append(Generated(name, doc, inputs, output, code, res, cnt, method))
    return out
