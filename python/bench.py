"""The Python package's speed: for the Panda, M + c + g, forward dynamics and the derivatives of
inverse and forward dynamics over 100,000 states in one batched call, per state, against a
Python loop over Pinocchio's ``crba`` + ``nonLinearEffects``, ``aba``,
``computeRNEADerivatives`` and ``computeABADerivatives`` on the same states, in one run; the single-state call's
overhead; and where a batch starts to pay running on every core.

Run: ``python3 python/bench.py [--states N]`` (needs ``pip install ./python`` and ``pin``).
Prints Markdown tables; the machine's load is printed first.
"""

import argparse
import os
import sys
import time

# One thread for numpy's BLAS: its idle threads would spin on the cores being measured.
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import numpy as np  # noqa: E402

# The installed package, not the source folder beside this script (it has no native module).
_HERE = os.path.dirname(os.path.abspath(__file__))
sys.path = [p for p in sys.path if os.path.abspath(p or ".") != _HERE]
import armdyn  # noqa: E402


def best(f, repeats):
    """Best wall time of ``repeats`` calls of ``f``, s."""
    times = []
    for _ in range(repeats):
        t = time.perf_counter()
        f()
        times.append(time.perf_counter() - t)
    return min(times)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--states", type=int, default=100_000)
    ap.add_argument("--repeats", type=int, default=5)
    a = ap.parse_args()
    import pinocchio as pin

    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    robot = armdyn.Robot("panda")
    model = pin.buildModelFromUrdf(os.path.join(root, "generated/urdf/panda.urdf"))
    model.gravity.linear = robot.gravity
    data = model.createData()
    n, N = robot.dof, a.states
    rng = np.random.default_rng(1)
    lim = robot.joint_limits
    q = rng.uniform(lim[:, 0], lim[:, 1], (N, n))
    qd = rng.uniform(-1, 1, (N, n))
    tau = rng.uniform(-10, 10, (N, n))
    print(f"load average {os.getloadavg()[0]:.2f} on {os.cpu_count()} cores; {N} Panda states")

    def pin_mcg():
        for k in range(N):
            pin.crba(model, data, q[k])
            pin.nonLinearEffects(model, data, q[k], qd[k])

    def pin_aba():
        for k in range(N):
            pin.aba(model, data, q[k], qd[k], tau[k])

    def pin_rnea_derivatives():
        for k in range(N):
            pin.computeRNEADerivatives(model, data, q[k], qd[k], tau[k])

    def pin_aba_derivatives():
        for k in range(N):
            pin.computeABADerivatives(model, data, q[k], qd[k], tau[k])

    rows = []
    for what, ours, theirs in (
        ("M + c + g", lambda: robot.mass_matrix_and_bias(q, qd, parallel=False), pin_mcg),
        ("forward dynamics", lambda: robot.forward_dynamics(q, qd, tau, parallel=False), pin_aba),
        ("inverse dynamics derivatives vs computeRNEADerivatives",
         lambda: robot.inverse_dynamics_derivatives(q, qd, tau, parallel=False), pin_rnea_derivatives),
        ("forward dynamics derivatives vs computeABADerivatives",
         lambda: robot.forward_dynamics_derivatives(q, qd, tau, parallel=False), pin_aba_derivatives),
    ):
        t_ours = best(ours, a.repeats) / N
        t_pin = best(theirs, max(1, a.repeats // 2)) / N
        rows.append((what, t_ours, t_pin))
    print("\n| Panda, per state | armdyn, one batched call, one thread | Python loop over Pinocchio | ratio |")
    print("| --- | ---: | ---: | ---: |")
    for what, t_ours, t_pin in rows:
        print(f"| {what} | {t_ours * 1e9:.0f} ns | {t_pin * 1e9:.0f} ns | {t_pin / t_ours:.1f}x |")

    # The single-state call: its time less the per-state time inside a batch is the overhead
    # of crossing into Rust (argument checks, array creation).
    q1, qd1, tau1 = q[0].copy(), qd[0].copy(), tau[0].copy()
    reps = 20_000

    def single_mcg():
        for _ in range(reps):
            robot.mass_matrix_and_bias(q1, qd1)

    def single_pin():
        for _ in range(reps):
            pin.crba(model, data, q1)
            pin.nonLinearEffects(model, data, q1, qd1)

    def single_fd():
        for _ in range(reps):
            robot.forward_dynamics(q1, qd1, tau1)

    s_mcg = best(single_mcg, 3) / reps
    s_fd = best(single_fd, 3) / reps
    s_pin = best(single_pin, 3) / reps
    print("\n| one state per call | time per call | of which the call's overhead |")
    print("| --- | ---: | ---: |")
    print(f"| armdyn M + c + g | {s_mcg * 1e9:.0f} ns | {(s_mcg - rows[0][1]) * 1e9:.0f} ns |")
    print(f"| armdyn forward dynamics | {s_fd * 1e9:.0f} ns | {(s_fd - rows[1][1]) * 1e9:.0f} ns |")
    print(f"| Pinocchio crba + nonLinearEffects | {s_pin * 1e9:.0f} ns | |")

    # Where a batch pays running on every core (default from armdyn.PARALLEL_MIN_STATES).
    print(f"\nparallel=None runs batches of at least {armdyn.PARALLEL_MIN_STATES} states on every core")
    print(f"\n| batch (forward dynamics) | one thread, per state | every core, per state |")
    print("| ---: | ---: | ---: |")
    for size in (64, 256, 1024, 2048, 8192, N):
        qs, qds, taus = q[:size], qd[:size], tau[:size]
        serial = best(lambda: robot.forward_dynamics(qs, qds, taus, parallel=False), a.repeats) / size
        par = best(lambda: robot.forward_dynamics(qs, qds, taus, parallel=True), a.repeats) / size
        print(f"| {size} | {serial * 1e9:.0f} ns | {par * 1e9:.0f} ns |")


if __name__ == "__main__":
    main()
