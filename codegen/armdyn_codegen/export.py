"""CasADi SX function -> instruction list of ``derive/FORMAT.md``, and an evaluator of it.

Instruction ``i`` defines value ``v{i}``; CasADi's work-vector slots are renamed to these
single-assignment indices. Constants are written with Python's ``repr`` (shortest text that
round-trips to the same double).
"""

from __future__ import annotations

import math

import casadi as ca

from .normalize import OP_NAMES

UNARY = {"neg", "sq", "twice", "inv", "sqrt", "sin", "cos", "fabs"}
BINARY = {"add", "sub", "mul", "div", "atan2"}
FLOPS = {"add", "sub", "mul", "div", "neg", "sq", "twice", "inv", "sqrt", "fabs"}
TRIG = {"sin", "cos", "atan2"}


class ExportError(Exception):
    pass


def instructions(fn: ca.Function):
    """Returns (instructions, result) for a function with one dense output."""
    if fn.n_out() != 1:
        raise ExportError("exported functions have exactly one output")
    rows = fn.sparsity_out(0).row()
    n_rows = fn.size1_out(0) * fn.size2_out(0)
    work = {}
    code = []
    result = [None] * n_rows
    for k in range(fn.n_instructions()):
        name = OP_NAMES.get(fn.instruction_id(k), str(fn.instruction_id(k)))
        ins = fn.instruction_input(k)
        o = fn.instruction_output(k)
        if name == "input":
            code.append(["input", int(ins[0]), int(ins[1])])
        elif name == "output":
            result[rows[o[1]]] = work[ins[0]]
            continue
        elif name == "const":
            v = float(fn.instruction_constant(k))
            if not math.isfinite(v):
                raise ExportError(f"non-finite constant {v}")
            code.append(["const", repr(v)])
        elif name in UNARY:
            code.append([name, work[ins[0]]])
        elif name in BINARY:
            code.append([name, work[ins[0]], work[ins[1]]])
        else:
            raise ExportError(f"CasADi operation `{name}` has no Rust emission")
        work[o[0]] = len(code) - 1
    if any(r is None for r in result):
        code.append(["const", "0.0"])
        result = [len(code) - 1 if r is None else r for r in result]
    return code, result


def counts(code) -> dict:
    return {
        "flops": sum(1 for ins in code if ins[0] in FLOPS),
        "trig": sum(1 for ins in code if ins[0] in TRIG),
    }


def evaluate(code, result, inputs):
    """Evaluate an exported instruction list in double precision (for tests)."""
    fns = {
        "neg": lambda x: -x,
        "sq": lambda x: x * x,
        "twice": lambda x: 2.0 * x,
        "inv": lambda x: 1.0 / x,
        "sqrt": math.sqrt,
        "sin": math.sin,
        "cos": math.cos,
        "fabs": abs,
        "add": lambda x, y: x + y,
        "sub": lambda x, y: x - y,
        "mul": lambda x, y: x * y,
        "div": lambda x, y: x / y,
        "atan2": math.atan2,
    }
    v = []
    for ins in code:
        if ins[0] == "input":
            v.append(float(inputs[ins[1]][ins[2]]))
        elif ins[0] == "const":
            v.append(float(ins[1]))
        else:
            v.append(fns[ins[0]](*(v[a] for a in ins[1:])))
    return [v[r] for r in result]
