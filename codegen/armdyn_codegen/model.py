"""The models of one robot: every exported function, derived and made compact.

Each function is derived twice and the smaller equivalent graph is kept:

* exact: derivation over trig-symbol leaves, exact normal form, Horner + CSE (``normalize``);
* direct: derivation over ``sin(q)``/``cos(q)`` nodes with the constants folded by CasADi.

Both are exact rewrites of the same function; the generator's tests check the kept graph
against an independent Lagrangian derivation.

Two models per robot: the numeric one (parameters folded in) and the parametric one, whose
dynamics functions take the standard inertial parameters ``params`` (10 per link, order
``description.PARAMETER_NAMES``) as an input, for identification and model-mismatch studies.
"""

from __future__ import annotations

from dataclasses import dataclass

import casadi as ca

from . import derivation as dv
from . import export, normalize
from .chain import Chain
from .description import PARAMETER_NAMES, to_float


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
    function: object = None  # the kept CasADi graph, for CasADi's own C code generator


def _flatten(x):
    if isinstance(x, (list, tuple)):
        return [e for item in x for e in _flatten(item)]
    return [x]


def _cost(code) -> int:
    c = export.counts(code)
    return c["flops"] + 10 * c["trig"]


class _Derivation:
    """The symbolic quantities of one robot over one kind of leaves; ``dq(e, i)`` is the
    partial derivative of ``e`` with respect to joint variable i."""

    def __init__(self, robot: Chain, L: dv.Leaves, dq, params=None):
        self.robot, self.L, self.dq, self.params = robot, L, dq, params
        n = robot.dof
        self.fr = dv.frames(L)
        self.tau = dv.rnea(L, L.qd, L.qdd, with_gravity=True)
        self._M = self._C = self._c = self._g = self._J = None
        self.n = n

    @property
    def M(self):
        if self._M is None:
            M = ca.jacobian(ca.vertcat(*self.tau), self.L.qdd)
            self._M = [[M[r, k] for k in range(self.n)] for r in range(self.n)]
        return self._M

    @property
    def C(self):
        # Christoffel symbols of the first kind: C_kj = sum_i G_ijk qd_i,
        # G_ijk = (dM_kj/dq_i + dM_ki/dq_j - dM_ij/dq_k) / 2, so that Mdot - 2C is skew.
        if self._C is None:
            n, M, qd = self.n, self.M, self.L.qd
            dM = [[[self.dq(M[r][k], i) for i in range(n)] for k in range(n)] for r in range(n)]
            self._C = [
                [
                    sum(0.5 * (dM[k][j][i] + dM[k][i][j] - dM[i][j][k]) * qd[i] for i in range(n))
                    for j in range(n)
                ]
                for k in range(n)
            ]
        return self._C

    @property
    def J(self):
        if self._J is None:
            self._J = dv.geometric_jacobian(self.L, self.fr)
        return self._J

    def function(self, name):
        n, L = self.n, self.L
        if name == "frame_poses":
            return [dv.homogeneous(R, p) for R, p in self.fr]
        if name == "end_effector_pose":
            return dv.homogeneous(*dv.end_effector(L, self.fr))
        if name == "jacobian":
            return self.J
        if name == "jdot_qd":
            v = [sum(self.J[r][k] * L.qd[k] for k in range(n)) for r in range(6)]
            return [sum(self.dq(v[r], k) * L.qd[k] for k in range(n)) for r in range(6)]
        if name == "jacobian_derivatives":
            # [k][r][c] = d J_rc / d q_k
            return [[[self.dq(self.J[r][c], k) for c in range(n)] for r in range(6)]
                    for k in range(n)]
        if name == "mass_matrix":
            return self.M
        if name == "coriolis_matrix":
            return self.C
        if name == "coriolis":
            return dv.rnea(L, L.qd, [0] * n, with_gravity=False)
        if name == "gravity":
            return dv.rnea(L, [0] * n, [0] * n, with_gravity=True)
        if name == "inverse_dynamics":
            return self.tau
        if name == "bias":
            # c(q, qd) + g(q) in one recursive Newton-Euler pass: the right-hand side of
            # forward dynamics (not exported by itself).
            return dv.rnea(L, L.qd, [0] * n, with_gravity=True)
        if name == "regressor":
            Y = ca.jacobian(ca.vertcat(*self.tau), ca.vertcat(*[x for link in L.pi for x in link]))
            return [[Y[r, k] for k in range(10 * n)] for r in range(n)]
        if name == "standard_parameters":
            return [x for link in L.pi for x in link]
        raise KeyError(name)


def _params_input(n):
    """The ``params`` input of the parametric model's functions (always their last input)."""
    return ("params", 10 * n,
            "standard inertial parameters, per link [m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, "
            "Iyz, Izz] (kg, kg m, kg m^2; inertia about the link frame origin, link frame axes)")


def _specs(robot: Chain, parametric: bool):
    n = robot.dof
    q = ("q", n, "joint positions q (rad for revolute joints, m for prismatic joints)")
    qd = ("qd", n, "joint velocities qd (rad/s or m/s)")
    qdd = ("qdd", n, "joint accelerations qdd (rad/s^2 or m/s^2)")
    P = [_params_input(n)] if parametric else []
    dyn = [
        ("mass_matrix", [q] + P, ("mass_matrix", [n, n],
         "symmetric positive definite M(q) (kg m^2, kg m, kg)"),
         "Joint-space mass matrix M(q) of `tau = M qdd + C qd + g` (thesis eq. 3.53, 3.67)."),
        ("coriolis_matrix", [q, qd] + P, ("coriolis_matrix", [n, n],
         "C(q, qd) with C qd the velocity term; Mdot - 2C is skew-symmetric"),
         "Coriolis and centrifugal matrix C(q, qd) from the Christoffel symbols of M."),
        ("coriolis", [q, qd] + P, ("coriolis", [n], "c(q, qd) = C(q, qd) qd (N m or N)"),
         "Velocity term c(q, qd) = C(q, qd) qd of the equations of motion (thesis eq. 3.53)."),
        ("gravity", [q] + P, ("gravity", [n],
         "g(q), joint torques (N m) or forces (N) that hold the robot still"),
         "Gravity term g(q) of the equations of motion (thesis eq. 3.53, 3.68)."),
        ("inverse_dynamics", [q, qd, qdd] + P, ("tau", [n],
         "joint torques (N m) or forces (N), no external wrench"),
         "Inverse dynamics `tau = M(q) qdd + C(q, qd) qd + g(q)` (recursive Newton-Euler)."),
    ]
    if parametric:
        return dyn
    kin = [
        ("frame_poses", [q], ("poses", [n, 4, 4],
         "homogeneous transforms T_0i of the description's frames 1..n in the base frame (m)"),
         "Poses of every link frame (the description's DH frames, or its URDF links), products of the "
         "joint transforms `A_1 ... A_i` (thesis eq. 3.2-3.7)."),
        ("end_effector_pose", [q], ("pose", [4, 4],
         "homogeneous transform of the end-effector frame (frame n, or the URDF's tip link) in the "
         "base frame (m)"),
         "End-effector pose, forward kinematics `T_0n` (thesis eq. 3.7)."),
        ("jacobian", [q], ("jacobian", [6, n],
         "rows vx vy vz (m/s) and wx wy wz (rad/s) per unit joint velocity, base frame"),
         "Geometric Jacobian of the end-effector frame origin in the base frame (thesis eq. 3.29)."),
        ("jdot_qd", [q, qd], ("jdot_qd", [6],
         "Jdot(q, qd) qd: m/s^2 (rows 0-2) and rad/s^2 (rows 3-5), base frame"),
         "Acceleration term of the end-effector twist: `d/dt (J qd) = J qdd + Jdot qd`."),
        ("jacobian_derivatives", [q], ("jacobian_derivatives", [n, 6, n],
         "`[k][r][c] = d J_rc / d q_k`, the partial derivatives of `jacobian` (m/rad or 1/rad "
         "per row kind; per m for prismatic joints)"),
         "Partial derivatives of the geometric Jacobian, `d J / d q_k` for each joint k: "
         "`Jdot = sum_k d J/d q_k qd_k`, and `d (J^T f)/d q_k = (d J/d q_k)^T f` for a tool "
         "wrench f."),
    ]
    ident = [
        ("regressor", [q, qd, qdd], ("regressor", [n, 10 * n],
         "Y(q, qd, qdd), columns in the order of `standard_parameters`"),
         "Dynamic regressor: `inverse_dynamics(q, qd, qdd) = Y(q, qd, qdd) * standard_parameters()`."),
        ("standard_parameters", [], ("params", [10 * n],
         "per link [m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz] (kg, kg m, kg m^2, "
         "inertia about the link frame origin)"),
         "The robot's own standard inertial parameters, the `params` of the parametric model."),
    ]
    return kin + dyn + ident


class _Paths:
    """Both derivations of one robot (exact and direct), with everything needed to export."""

    def __init__(self, robot: Chain, parametric: bool, q, qd, qdd, params, trig):
        Lt, variables, csyms, cvals = dv.trig_symbol_leaves(robot, parametric=parametric)
        self.variables, self.cvals = variables, cvals
        self.var_sx = ca.vertcat(*[v[2] for v in variables])
        self.c_sx = ca.vertcat(*csyms)
        index = {(kind, j): v for kind, j, v in variables}

        def dq_trig(e, i):
            if robot.joints[i].revolute:
                s, c = index[("sin", i)], index[("cos", i)]
                return c * ca.jacobian(e, s) - s * ca.jacobian(e, c)
            return ca.jacobian(e, index[("lin", i)])

        self.exact = _Derivation(robot, Lt, dq_trig)
        # Final leaves: the function inputs, with sin/cos of each joint angle computed once.
        leaves = []
        for kind, j, _ in variables:
            if kind == "sin":
                leaves.append(trig[j][0])
            elif kind == "cos":
                leaves.append(trig[j][1])
            elif kind == "lin":
                off = to_float(robot.joints[j].offset)
                leaves.append(q[j] + off if off != 0.0 else q[j])
            else:
                leaves.append({"qd": qd, "qdd": qdd, "param": params}[kind][j])
        self.final_leaves = leaves
        Ln = dv.numeric_leaves(robot, q, qd, qdd, trig, params if parametric else None)
        self.direct = _Derivation(robot, Ln, lambda e, i: ca.jacobian(e, q[i]))

    def candidates(self, name, args):
        entries = _flatten(self.exact.function(name))
        fx = ca.Function("f", [self.var_sx, self.c_sx], [ca.vertcat(*[ca.SX(e) for e in entries])])
        polys = normalize.replay(fx, self.variables, self.cvals)
        col = normalize.rebuild(polys, self.final_leaves)
        fe = ca.Function(name, args, [col])
        entries_d = _flatten(self.direct.function(name))
        col_d = ca.cse(ca.vertcat(*[ca.SX(e) for e in entries_d]))
        fd = ca.Function(name, args, [col_d])
        direct = (*export.instructions(fd), fd)
        if name == "mass_matrix":
            # A second direct derivation: the composite-rigid-body algorithm.
            col_c = ca.cse(ca.vertcat(*[ca.SX(e) for e in _flatten(dv.crba(self.direct.L))]))
            fc = ca.Function(name, args, [col_c])
            crba = (*export.instructions(fc), fc)
            if _cost(crba[0]) < _cost(direct[0]):
                direct = crba
        return (*export.instructions(fe), fe), direct


FORWARD_DYNAMICS_DOC = (
    "Forward dynamics `qdd = M(q)^-1 (tau - C(q, qd) qd - g(q))` (thesis eq. 3.70), by a "
    "sparse L^T D L factorisation of M unrolled at generation time (Featherstone, RBDA "
    "ch. 6.5): structural zeros of M are skipped, sin/cos shared by M, c and g."
)


PARAMETRIC_FORWARD_DYNAMICS_DOC = (
    " The pivots `D_k` of the factorisation depend on `params`, which must therefore give a "
    "positive definite mass matrix (any physical parameter set does: positive masses, "
    "inertias that satisfy the triangle inequalities); nothing is checked, and parameters "
    "that make a pivot zero give a non-finite result."
)


def _is_zero(e) -> bool:
    return bool(e.is_zero())


def _ltdl_solve(M, b, order):
    """Solves ``M x = b`` symbolically by ``M = L^T D L`` (L unit lower triangular in the
    elimination order ``order``; Featherstone's LTDL, RBDA Algorithms 6.3 and 6.4).

    ``M`` is a nested list of SX scalars (only the lower triangle in ``order`` is read), ``b`` a
    list. Entries that are structurally zero (a constant 0 at generation time) are skipped, and
    CasADi folds the arithmetic of constants, so the unrolled factorisation costs only what the
    sparsity of this robot's ``M`` requires; the factorisation of rows and columns whose entries
    are constant is folded away entirely. Division happens once per pivot (``1 / D_k``).
    """
    n = len(b)
    # H[i][j], j <= i, in the permuted indices: H[i][j] = M[order[i]][order[j]].
    H = [[M[order[i]][order[j]] for j in range(i + 1)] for i in range(n)]
    dinv = [None] * n
    for k in reversed(range(n)):
        dinv[k] = 1 / H[k][k]
        # Rows above k descending, so that H[k][j], j < i, is still unscaled when row i reads it.
        for i in reversed(range(k)):
            if _is_zero(H[k][i]):
                continue
            a = H[k][i] * dinv[k]
            for j in range(i + 1):
                if not _is_zero(H[k][j]):
                    H[i][j] = H[i][j] - H[k][j] * a
            H[k][i] = a
    # M = L^T D L with L = unit lower part of H: solve L^T z = b, D w = z, L x = w.
    z = [b[order[i]] for i in range(n)]
    for k in reversed(range(n)):
        for i in range(k):
            if not _is_zero(H[k][i]):
                z[i] = z[i] - H[k][i] * z[k]
    x = [z[i] * dinv[i] for i in range(n)]
    for i in range(n):
        for j in range(i):
            if not _is_zero(H[i][j]):
                x[i] = x[i] - H[i][j] * x[j]
    out = [None] * n
    for i in range(n):
        out[order[i]] = x[i]
    return out


def forward_dynamics_candidates(n, q, qd, tau, mass_fns, bias_fns, params=None):
    """Every combination of a mass-matrix graph, a bias graph (``c + g``) and an elimination
    order (LTDL base-to-tip, as Featherstone's, and the reverse), composed into one graph with
    common subexpressions (sin/cos included) shared; yields ``(name, ca.Function)``.

    With ``params`` (the parametric model) the graphs take it as their last input,
    ``fm(q, params)`` and ``fb(q, qd, params)``, and so does the composition:
    ``forward_dynamics(q, qd, tau, params)``."""
    extra = [] if params is None else [params]
    for mi, fm in enumerate(mass_fns):
        m_flat = fm(q, *extra)
        M = [[m_flat[r * n + k] for k in range(n)] for r in range(n)]
        for bi, fb in enumerate(bias_fns):
            bias = fb(q, qd, *extra)
            rhs = [tau[i] - bias[i] for i in range(n)]
            for oname, order in (("ltdl", list(range(n))), ("ldlt", list(reversed(range(n))))):
                x = _ltdl_solve(M, rhs, order)
                col = ca.cse(ca.vertcat(*[ca.SX(e) for e in x]))
                yield f"{oname}, M {mi}, bias {bi}", ca.Function(
                    "forward_dynamics", [q, qd, tau, *extra], [col]
                )


def _symbols(robot: Chain):
    """The function inputs ``q, qd, qdd, params`` and ``trig``: per joint ``(sin, cos)`` of its
    angle (``None`` for a prismatic joint), each computed once."""
    n = robot.dof
    q = ca.SX.sym("q", n)
    qd = ca.SX.sym("qd", n)
    qdd = ca.SX.sym("qdd", n)
    params = ca.SX.sym("params", 10 * n)
    trig = []
    for j in robot.joints:
        if j.revolute:
            off = to_float(j.offset)
            ang = q[len(trig)] + off if off != 0.0 else q[len(trig)]
            trig.append((ca.sin(ang), ca.cos(ang)))
        else:
            trig.append(None)
    return q, qd, qdd, params, trig


def _choose(exact, direct):
    """The exported one of the two candidates ``(code, result, function)``: the cheaper,
    the exact one on a tie. Returns ``(code, result, method, function)``."""
    (code_e, res_e, fe), (code_d, res_d, fd) = exact, direct
    if _cost(code_d) < _cost(code_e):
        return code_d, res_d, "direct", fd
    return code_e, res_e, "exact", fe


def jacobian_function(robot: Chain):
    """The ``jacobian`` graph that ``generate(robot)`` exports (the same derivations and the
    same choice), without deriving anything else: for checking a description's task before
    generating it."""
    q, qd, qdd, params, trig = _symbols(robot)
    paths = _Paths(robot, False, q, qd, qdd, params, trig)
    return _choose(*paths.candidates("jacobian", [q]))[3]


def generate(robot: Chain, parametric: bool = False, log=None) -> list[Generated]:
    q, qd, qdd, params, trig = _symbols(robot)
    paths = {parametric: _Paths(robot, parametric, q, qd, qdd, params, trig)}
    symbols = {"q": q, "qd": qd, "qdd": qdd, "params": params}
    out = []
    kept = {}  # name -> (exact, direct) CasADi functions
    chosen = {}  # name -> the exported one of the two
    for name, inputs, output, doc in _specs(robot, parametric):
        args = [symbols[i[0]] for i in inputs]
        # The regressor is the derivative with respect to the parameters: derive it where
        # they are symbols (it does not depend on their values).
        need_params = parametric or name == "regressor"
        if need_params not in paths:
            paths[need_params] = _Paths(robot, need_params, q, qd, qdd, params, trig)
        exact, direct = paths[need_params].candidates(name, args)
        (code_e, _, fe), (code_d, _, fd) = exact, direct
        code, res, method, fn = _choose(exact, direct)
        cnt = export.counts(code)
        if log:
            ce, cd = export.counts(code_e), export.counts(code_d)
            log(
                f"  {robot.name}{'::parametric' if parametric else ''}::{name}: "
                f"{cnt['flops']} flops, {cnt['trig']} trig ({method}; exact "
                f"{ce['flops']}+{ce['trig']}t, direct {cd['flops']}+{cd['trig']}t)"
            )
        out.append(Generated(name, doc, inputs, output, code, res, cnt, method, fn))
        kept[name] = (fe, fd)
        chosen[name] = fn
        if name == "jacobian" and not parametric:
            out.append(_jacobian_and_position(robot, chosen, q, log))
        if name == "inverse_dynamics" and not parametric:
            be, bd = paths[False].candidates("bias", [q, qd])
            bias_fns = (be[2], bd[2])
            try:
                fd_generated = _forward_dynamics(robot, kept, bias_fns, q, qd, log)
                out.append(fd_generated)
            except export.ExportError as e:
                raise SingularMassMatrix(_singular_joints(robot, kept["mass_matrix"][1], e)) from None
            out.append(_mass_matrix_and_bias(robot, kept, bias_fns, q, qd, log))
            from .derivatives import derivative_functions

            chosen["forward_dynamics"] = fd_generated.function
            out.extend(derivative_functions(robot, q, qd, qdd, kept, chosen, Generated,
                                            _ltdl_solve, _cost, log))
        if name == "inverse_dynamics" and parametric:
            # The same compositions over the parametric M and c + g; the pivots depend on
            # params (see PARAMETRIC_FORWARD_DYNAMICS_DOC).
            be, bd = paths[True].candidates("bias", [q, qd, params])
            out.append(_forward_dynamics(robot, kept, (be[2], bd[2]), q, qd, log, params))
    return out


class SingularMassMatrix(Exception):
    """The description is valid, but its mass matrix is singular (a joint moves no mass and no
    inertia), so forward dynamics cannot be generated; the message names the joints."""


def _singular_joints(robot: Robot, mass_matrix, error) -> str:
    """Why forward dynamics failed, from the mass matrix at q = 0: the joints whose diagonal
    entry is zero move nothing."""
    import numpy as np

    n = robot.dof
    M = np.array(mass_matrix(np.zeros(n))).reshape(n, n)
    idle = [f"joint {k + 1} ({robot.joints[k].name})" for k in range(n) if M[k, k] == 0.0]
    if idle:
        verb = "moves" if len(idle) == 1 else "move"
        return (
            f"{' and '.join(idle)} {verb} no mass and no inertia (zero diagonal of the mass matrix "
            "at q = 0), so the mass matrix is singular and forward_dynamics cannot be generated; "
            "give the links it moves a mass or an inertia"
        )
    return f"forward_dynamics: {error} (the mass matrix is singular)"


def _cheapest(candidates):
    """``(code, res, name, fn)`` of the cheapest of ``(name, ca.Function)`` candidates (the
    first of equals), by the cost of their instruction lists."""
    best = None
    for method, fn in candidates:
        code, res = export.instructions(fn)
        if best is None or _cost(code) < _cost(best[0]):
            best = (code, res, method, fn)
    return best


def _forward_dynamics(robot, kept, bias_fns, q, qd, log, params=None) -> Generated:
    """``forward_dynamics(q, qd, tau)``, or ``forward_dynamics(q, qd, tau, params)`` for the
    parametric model (``params`` given): the cheapest of the candidate compositions."""
    n = robot.dof
    tau = ca.SX.sym("tau", n)
    code, res, method, fn = _cheapest(
        forward_dynamics_candidates(n, q, qd, tau, kept["mass_matrix"], bias_fns, params)
    )
    cnt = export.counts(code)
    if log:
        log(f"  {robot.name}{'::parametric' if params is not None else ''}::forward_dynamics: "
            f"{cnt['flops']} flops, {cnt['trig']} trig ({method})")
    inputs = [
        ("q", n, "joint positions q (rad for revolute joints, m for prismatic joints)"),
        ("qd", n, "joint velocities qd (rad/s or m/s)"),
        ("tau", n, "joint torques (N m) or forces (N); subtract J^T f_ext for a contact wrench"),
    ]
    doc = FORWARD_DYNAMICS_DOC
    if params is not None:
        inputs.append(_params_input(n))
        doc += PARAMETRIC_FORWARD_DYNAMICS_DOC
    output = ("qdd", [n], "joint accelerations qdd (rad/s^2 or m/s^2)")
    return Generated("forward_dynamics", doc, inputs, output, code, res, cnt, method, fn)


MASS_MATRIX_AND_BIAS_DOC = (
    "Mass matrix and bias in one pass: row i is `[M_i0, ..., M_i(n-1), c_i + g_i]`, the "
    "`M(q)` of `mass_matrix` with the bias `c(q, qd) + g(q)` of `coriolis` and `gravity` as "
    "a last column (what Pinocchio's `crba` and `nonLinearEffects` compute together). "
    "Common subexpressions, sin/cos included, are computed once for both."
)


def mass_matrix_and_bias_candidates(n, q, qd, mass_fns, bias_fns):
    """Every combination of a mass-matrix graph and a bias graph (``c + g``), composed into
    one graph ``[M | c + g]`` (n rows of n + 1) with common subexpressions (sin/cos
    included) shared; yields ``(name, ca.Function)``."""
    for mi, fm in enumerate(mass_fns):
        m_flat = fm(q)
        for bi, fb in enumerate(bias_fns):
            bias = fb(q, qd)
            entries = [m_flat[r * n + k] if k < n else bias[r] for r in range(n) for k in range(n + 1)]
            col = ca.cse(ca.vertcat(*[ca.SX(e) for e in entries]))
            yield f"M {mi}, bias {bi}", ca.Function("mass_matrix_and_bias", [q, qd], [col])


def _mass_matrix_and_bias(robot, kept, bias_fns, q, qd, log) -> Generated:
    """``mass_matrix_and_bias(q, qd)``: ``[M | c + g]``, the cheapest of the compositions."""
    n = robot.dof
    code, res, method, fn = _cheapest(
        mass_matrix_and_bias_candidates(n, q, qd, kept["mass_matrix"], bias_fns)
    )
    cnt = export.counts(code)
    if log:
        log(f"  {robot.name}::mass_matrix_and_bias: {cnt['flops']} flops, {cnt['trig']} trig "
            f"({method})")
    inputs = [
        ("q", n, "joint positions q (rad for revolute joints, m for prismatic joints)"),
        ("qd", n, "joint velocities qd (rad/s or m/s)"),
    ]
    output = ("mass_matrix_and_bias", [n, n + 1],
              "rows `[M(q) | c(q, qd) + g(q)]`: the symmetric positive definite M (kg m^2, kg m, "
              "kg), then the bias (N m or N)")
    return Generated("mass_matrix_and_bias", MASS_MATRIX_AND_BIAS_DOC, inputs, output, code, res,
                     cnt, method, fn)


JACOBIAN_AND_POSITION_DOC = (
    "Jacobian and tool position in one pass: `[J | p; 0]`, row r is `[J_r0, ..., J_r(n-1), "
    "p_r]` with `J` the geometric Jacobian of `jacobian` and `p` the end-effector origin of "
    "`end_effector_pose` (rows 0-2; the last column of rows 3-5 is 0), the same operations "
    "as those two functions (bit-identical results), with common subexpressions, sin/cos "
    "included, computed once for both and the pose's rotation not computed."
)


def jacobian_and_position_function(n, q, fj, fp):
    """The exported Jacobian graph ``fj`` and end-effector-pose graph ``fp`` composed into one
    graph ``[J | p; 0]`` (6 rows of n + 1: the Jacobian, then the tool position in rows 0-2 of
    the last column and zeros below) with common subexpressions (sin/cos included) shared.
    The graphs are the exported ones, not the cheapest combination, so that the results are
    bit for bit those of ``jacobian`` and ``end_effector_pose``."""
    j_flat = fj(q)
    pose = fp(q)  # 4 x 4 row-major: the position is entries 3, 7, 11
    last = [pose[4 * r + 3] if r < 3 else 0 for r in range(6)]
    entries = [j_flat[r * n + k] if k < n else last[r] for r in range(6) for k in range(n + 1)]
    col = ca.cse(ca.vertcat(*[ca.SX(e) for e in entries]))
    return ca.Function("jacobian_and_position", [q], [col])


def _jacobian_and_position(robot, chosen, q, log) -> Generated:
    """``jacobian_and_position(q)``: ``[J | p; 0]`` of the exported ``jacobian`` and
    ``end_effector_pose`` graphs."""
    n = robot.dof
    fn = jacobian_and_position_function(n, q, chosen["jacobian"], chosen["end_effector_pose"])
    code, res = export.instructions(fn)
    cnt = export.counts(code)
    if log:
        log(f"  {robot.name}::jacobian_and_position: {cnt['flops']} flops, {cnt['trig']} trig")
    inputs = [("q", n, "joint positions q (rad for revolute joints, m for prismatic joints)")]
    output = ("jacobian_and_position", [6, n + 1],
              "rows `[J(q) | p(q); 0]`: the geometric Jacobian of `jacobian` (rows vx vy vz per "
              "unit joint velocity, then wx wy wz, base frame), then the end-effector origin "
              "(m, base frame) in rows 0-2 of the last column, 0 in rows 3-5")
    return Generated("jacobian_and_position", JACOBIAN_AND_POSITION_DOC, inputs, output, code,
                     res, cnt, "exported", fn)


__all__ = ["Generated", "generate", "jacobian_function", "PARAMETER_NAMES"]
