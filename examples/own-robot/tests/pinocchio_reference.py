"""Pinocchio's M, c + g and forward dynamics of the Jaco2 on the same URDF, at random states.

Usage: python3 tests/pinocchio_reference.py STATES  (prints one JSON list on stdout)

Each entry: q, qd, tau (the state, rad, rad/s, N m), m (row-major, kg m^2), bias (c + g,
N m) and qdd (forward dynamics, rad/s^2). Pinocchio's continuous joints take (cos, sin) as
their coordinates; the generated model takes the angle.
"""

import json
import random
import sys
from pathlib import Path

import numpy as np
import pinocchio as pin

HERE = Path(__file__).resolve().parent.parent
URDF = HERE / "description" / "kinova.urdf"
JOINTS = [f"j2s6s200_joint_{i}" for i in range(1, 7)]


def main() -> int:
    states = int(sys.argv[1]) if len(sys.argv) > 1 else 64
    model = pin.buildModelFromUrdf(str(URDF))
    data = model.createData()
    names = [model.names[i] for i in range(1, model.njoints)]
    assert names == JOINTS, names
    lower = model.lowerPositionLimit
    upper = model.upperPositionLimit
    rng = random.Random(0x1AC0)
    out = []
    for _ in range(states):
        q, config = [], []
        for j in model.joints[1:]:
            if j.nq == 2:  # continuous: (cos, sin)
                a = rng.uniform(-np.pi, np.pi)
                q.append(a)
                config += [np.cos(a), np.sin(a)]
            else:
                a = rng.uniform(lower[j.idx_q], upper[j.idx_q])
                q.append(a)
                config.append(a)
        qd = [rng.uniform(-2.0, 2.0) for _ in JOINTS]
        tau = [rng.uniform(-10.0, 10.0) for _ in JOINTS]
        qa, qda, taua = np.array(config), np.array(qd), np.array(tau)
        m = pin.crba(model, data, qa)
        m = np.triu(m) + np.triu(m, 1).T
        bias = pin.nonLinearEffects(model, data, qa, qda).copy()
        qdd = pin.aba(model, data, qa, qda, taua).copy()
        out.append({"q": q, "qd": qd, "tau": tau, "m": m.flatten().tolist(),
                    "bias": bias.tolist(), "qdd": qdd.tolist()})
    json.dump(out, sys.stdout)
    return 0


if __name__ == "__main__":
    sys.exit(main())
