"""Exact normalisation of trig-symbol graphs, and compact reconstruction.

A CasADi graph over the trig-symbol leaves (``derivation.trig_symbol_leaves``) is replayed,
instruction by instruction, over sparse polynomials with rational coefficients whose
generators are ``s_i = sin(theta_i)``, ``c_i = cos(theta_i)``, the prismatic joint variables and
``qd``. After every product, ``s_i^2`` is replaced by ``1 - c_i^2``: the result is the unique
normal form of the function modulo ``s_i^2 + c_i^2 = 1`` (the ideal's generators have coprime
leading terms, so they are a Groebner basis), so identities such as
``a^2 (c^2 + s^2) = a^2`` and every cancellation of the derivation are folded exactly, and the
robot's constants are rounded to double only once, in the final coefficients.

The normal form is then rebuilt as a CasADi graph by greedy multivariate Horner factoring
(the variable in most terms is factored out first) and CasADi's common-subexpression
elimination.
"""

from __future__ import annotations

import math
import sys
from fractions import Fraction

import casadi as ca
import sympy as sp


class ReplayError(Exception):
    pass


class CoefficientRangeError(ArithmeticError):
    """A coefficient of the normal form does not fit in a double (it would overflow, or lose
    digits as a subnormal). The description reader's range keeps every coefficient far
    inside; this is the last line of defence, with a message instead of a traceback."""


def _op_names():
    return {getattr(ca, n): n[3:].lower() for n in dir(ca) if n.startswith("OP_")}


OP_NAMES = _op_names()


def replay(fn: ca.Function, gens: list, param_values: list):
    """Evaluate ``fn(vars, params)`` (a 1-output SX function) over exact polynomials.

    ``gens``: list of ``(kind, joint, sx)`` from ``trig_symbol_leaves``; input 0 of ``fn`` is the
    vertcat of their SX, in order. Returns one normal-form dict ``{exponents: Fraction}`` per
    output element (dense, column-major as CasADi stores a column vector).
    """
    names = [f"g{k}" for k in range(len(gens))]
    R, *G = sp.ring(names, sp.QQ)
    pairs = []  # (index of s, index of c) per revolute joint
    by_joint = {}
    for k, (kind, j, _) in enumerate(gens):
        if kind in ("sin", "cos"):
            by_joint.setdefault(j, {})[kind] = k
    for j, d in sorted(by_joint.items()):
        pairs.append((d["sin"], d["cos"]))
    nvars = len(gens)

    def reduce(p):
        if not pairs:
            return p
        out = {}
        todo = []
        for mon, coef in p.terms():
            if any(mon[s] >= 2 for s, _ in pairs):
                todo.append((mon, coef))
            else:
                out[mon] = out.get(mon, 0) + coef
        if not todo:
            return p
        res = R.from_dict(out) if out else R.zero
        for mon, coef in todo:
            e = list(mon)
            factor = R.one
            for s, c in pairs:
                if e[s] >= 2:
                    k = e[s] // 2
                    e[s] -= 2 * k
                    factor *= (R.one - G[c] ** 2) ** k
            res += R.from_dict({tuple(e): coef}) * factor
        return res

    params = [R.ground_new(sp.QQ.convert(v)) for v in param_values]
    work = {}
    rows = fn.sparsity_out(0).row()
    out = [R.zero] * fn.size1_out(0)
    for k in range(fn.n_instructions()):
        op = fn.instruction_id(k)
        ins = fn.instruction_input(k)
        o = fn.instruction_output(k)
        name = OP_NAMES.get(op, str(op))
        if name == "input":
            arg, nz = ins
            work[o[0]] = G[nz] if arg == 0 else params[nz]
        elif name == "output":
            out[rows[o[1]]] = work[ins[0]]
        elif name == "const":
            work[o[0]] = R.ground_new(sp.QQ.convert(sp.Rational(Fraction(fn.instruction_constant(k)))))
        elif name == "add":
            work[o[0]] = work[ins[0]] + work[ins[1]]
        elif name == "sub":
            work[o[0]] = work[ins[0]] - work[ins[1]]
        elif name == "mul":
            work[o[0]] = reduce(work[ins[0]] * work[ins[1]])
        elif name == "neg":
            work[o[0]] = -work[ins[0]]
        elif name == "sq":
            work[o[0]] = reduce(work[ins[0]] ** 2)
        elif name == "twice":
            work[o[0]] = 2 * work[ins[0]]
        elif name in ("div", "inv"):
            num = work[ins[0]] if name == "div" else R.one
            den = work[ins[1]] if name == "div" else work[ins[0]]
            if not den.is_ground:
                raise ReplayError("division by a non-constant in a polynomial model")
            work[o[0]] = num * (1 / den.LC)
        else:
            raise ReplayError(f"operation `{name}` cannot be replayed over polynomials")
    result = []
    for p in out:
        result.append({mon: Fraction(int(c.numerator), int(c.denominator)) for mon, c in p.terms()})
    assert all(len(m) == nvars for r in result for m in r)
    return result


def _coef(x: Fraction) -> float:
    """The correctly rounded double of ``x`` (int / int is correctly rounded in Python)."""
    try:
        v = x.numerator / x.denominator
    except OverflowError:
        v = math.inf
    if x != 0 and not sys.float_info.min <= abs(v) < math.inf:
        # log10 |x| from the sizes of numerator and denominator (no huge-int-to-text).
        digits = (abs(x.numerator).bit_length() - x.denominator.bit_length()) * math.log10(2)
        raise CoefficientRangeError(
            f"a coefficient of the model, about 1e{digits:+.0f}, is outside the range of a "
            "double (2.2e-308 to 1.8e+308 in magnitude)"
        )
    return v


def horner(terms: dict, leaves: list):
    """Greedy multivariate Horner form of ``terms`` as an SX (or a float for a constant)."""
    if not terms:
        return 0.0
    nv = len(leaves)
    zero = (0,) * nv
    const = terms.get(zero, Fraction(0))
    rest = {m: c for m, c in terms.items() if m != zero and c != 0}
    if not rest:
        return _coef(const)
    counts = [0] * nv
    for m in rest:
        for v in range(nv):
            if m[v]:
                counts[v] += 1
    v = max(range(nv), key=lambda k: (counts[k], -k))
    quot = {}
    other = {}
    for m, c in rest.items():
        if m[v]:
            mm = list(m)
            mm[v] -= 1
            quot[tuple(mm)] = c
        else:
            other[m] = c
    qx = horner(quot, leaves)
    leaf = leaves[v]
    negate = False
    if isinstance(qx, float):
        if qx == 1.0:
            prod = leaf
        elif qx == -1.0:
            prod, negate = leaf, True
        elif qx < 0:
            prod, negate = (-qx) * leaf, True
        else:
            prod = qx * leaf
    else:
        prod = qx * leaf
    if const != 0:
        other[zero] = const
    ox = horner(other, leaves) if other else None
    if ox is None:
        return -prod if negate else prod
    if isinstance(ox, float) and ox == 0.0:
        return -prod if negate else prod
    return ox - prod if negate else ox + prod


def rebuild(polys: list, leaves: list):
    """Normal forms -> one CasADi SX column (Horner per entry, then common subexpressions)."""
    entries = [horner(p, leaves) for p in polys]
    col = ca.vertcat(*[ca.SX(e) if isinstance(e, float) else e for e in entries])
    return ca.cse(col)
