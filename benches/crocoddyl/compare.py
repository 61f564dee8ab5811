"""The same trajectory-optimisation problem solved by armdyn's control-limited iLQR
(``armdyn.plan_terminal_cost``, on the generated derivatives) and by Crocoddyl's
``SolverBoxFDDP`` (on Pinocchio's analytical derivatives), in one run, one thread each.

The problem, for each robot (the same URDF: the one the generator wrote from the robot's
description), horizon, time step, costs, limits and initial guess on both sides::

    x = [q; qd],  u = tau (N m), held over each step dt, integrated by RK4
    minimise   sum_k dt sum_i (u_k,i / e_i)^2  +  (w / 2) |x_K - [q_goal; 0]|^2
    subject to |u_k,i| <= s e_i                  (e: the effort limits, s: the share)
    initial guess: u_k = g(q_start) (gravity held), x its roll-out

Crocoddyl: ``DifferentialActionModelFreeFwdDynamics`` with ``ResidualModelControl`` under
``ActivationModelWeightedQuad(2 / e^2)`` (its 0.5 r^T W r is then sum (u/e)^2), integrated by
``IntegratedActionModelRK`` (RK4), a terminal ``ResidualModelState`` under
``ActivationModelWeightedQuad(w)``, ``u_lb``/``u_ub`` the box, ``problem.nthreads = 1``.
Both run to their own convergence; the table gives each one's final cost, iterations and
time per iteration (the solve's wall time over its iterations, best of ``--repeats``).

Run, in a virtual environment of its own (Crocoddyl's wheels need the Pinocchio they were
built against, not the one of ``codegen/requirements-check.txt``)::

    python3 -m venv /tmp/croc && /tmp/croc/bin/pip install -r benches/crocoddyl/requirements.txt
    python3 -m pip wheel --no-deps ./python -w /tmp/wheel && /tmp/croc/bin/pip install /tmp/wheel/*.whl
    /tmp/croc/bin/python benches/crocoddyl/compare.py

Prints a Markdown table; the machine's load first.
"""

import argparse
import os
import sys
import time

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("OMP_NUM_THREADS", "1")

import numpy as np  # noqa: E402

_HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(_HERE))
# The installed package, not a source folder of the same name.
sys.path = [p for p in sys.path if os.path.abspath(p or ".") not in (_HERE, ROOT)]
import armdyn  # noqa: E402

# Start and goal (rad), inside the joint limits, and the problem's settings.
CASES = {
    "ur5": ([0.0, -1.2, 1.0, -0.5, 0.3, 0.0], [1.2, -0.6, 0.4, -1.1, 0.9, 0.8]),
    "panda": ([0.0, -0.5, 0.0, -2.0, 0.0, 1.6, 0.8], [0.5, -0.2, -0.2, -1.6, 0.3, 1.9, 0.4]),
}


def problem(robot, a):
    q0, q1 = (np.array(v) for v in CASES[robot.name])
    steps = int(round(a.duration / a.step))
    guess = np.tile(robot.generalized_gravity(q0), (steps, 1))
    return q0, q1, steps, guess


def crocoddyl_solver(robot, q0, q1, steps, guess, a):
    import crocoddyl
    import pinocchio as pin

    model = pin.buildModelFromUrdf(os.path.join(ROOT, "generated/urdf", f"{robot.name}.urdf"))
    model.gravity.linear = robot.gravity
    state = crocoddyl.StateMultibody(model)
    actuation = crocoddyl.ActuationModelFull(state)
    nu, n = actuation.nu, robot.dof
    e = robot.effort_limits
    running = crocoddyl.CostModelSum(state, nu)
    running.addCost(
        "effort",
        crocoddyl.CostModelResidual(
            state,
            crocoddyl.ActivationModelWeightedQuad(2.0 / e**2),
            crocoddyl.ResidualModelControl(state, nu),
        ),
        1.0,
    )
    goal = np.concatenate([q1, np.zeros(n)])
    terminal = crocoddyl.CostModelSum(state, nu)
    terminal.addCost(
        "goal",
        crocoddyl.CostModelResidual(
            state,
            crocoddyl.ActivationModelWeightedQuad(a.weight * np.ones(2 * n)),
            crocoddyl.ResidualModelState(state, goal, nu),
        ),
        1.0,
    )
    rk4 = crocoddyl.RKType.four
    step_model = crocoddyl.IntegratedActionModelRK(
        crocoddyl.DifferentialActionModelFreeFwdDynamics(state, actuation, running), rk4, a.step
    )
    step_model.u_lb = -a.share * e
    step_model.u_ub = a.share * e
    last = crocoddyl.IntegratedActionModelRK(
        crocoddyl.DifferentialActionModelFreeFwdDynamics(state, actuation, terminal), rk4, 0.0
    )
    x0 = np.concatenate([q0, np.zeros(n)])
    shooting = crocoddyl.ShootingProblem(x0, [step_model] * steps, last)
    shooting.nthreads = 1
    us = [np.clip(u, -a.share * e, a.share * e) for u in guess]

    def solve():
        solver = crocoddyl.SolverBoxFDDP(shooting)
        xs = shooting.rollout(us)
        t = time.perf_counter()
        solver.solve(xs, us, a.max_iterations, False)
        return solver, time.perf_counter() - t

    return solve


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--robots", nargs="+", default=list(CASES))
    ap.add_argument("--duration", type=float, default=1.0, help="s")
    ap.add_argument("--step", type=float, default=0.01, help="s")
    ap.add_argument("--weight", type=float, default=1e4, help="terminal weight w")
    ap.add_argument("--share", type=float, default=0.5, help="effort share s")
    ap.add_argument("--max-iterations", type=int, default=500)
    ap.add_argument("--repeats", type=int, default=3)
    a = ap.parse_args()
    import crocoddyl

    print(
        f"load average {os.getloadavg()[0]:.2f} on {os.cpu_count()} cores; "
        f"crocoddyl {crocoddyl.__version__}; {a.duration} s in steps of {a.step} s, RK4, "
        f"w = {a.weight:g}, effort share {a.share}"
    )
    print()
    print("| robot | knots | armdyn iterations | armdyn cost | armdyn ms/iteration | armdyn ms "
          "| Crocoddyl iterations | Crocoddyl cost | Crocoddyl ms/iteration | Crocoddyl ms "
          "| cost difference | per iteration, Crocoddyl / armdyn |")
    print("|:--|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|")
    for name in a.robots:
        robot = armdyn.Robot(name)
        q0, q1, steps, guess = problem(robot, a)
        ours = None
        for _ in range(a.repeats):
            r = armdyn.plan_terminal_cost(
                name, q0, q1, a.duration, weight=a.weight, initial_torques=guess,
                effort_share=a.share, step=a.step, max_iterations=a.max_iterations,
            )
            per = r["solve_time_s"] / r["iterations"]
            if ours is None or per < ours[2]:
                ours = (r["iterations"], r["cost"], per)
        solve = crocoddyl_solver(robot, q0, q1, steps, guess, a)
        theirs = None
        for _ in range(a.repeats):
            solver, seconds = solve()
            per = seconds / max(1, solver.iter)
            if theirs is None or per < theirs[2]:
                theirs = (solver.iter, solver.cost, per)
        diff = (ours[1] - theirs[1]) / theirs[1]
        print(f"| {name} | {steps} | {ours[0]} | {ours[1]:.6g} | {ours[2] * 1e3:.2f} "
              f"| {ours[0] * ours[2] * 1e3:.1f} | {theirs[0]} | {theirs[1]:.6g} "
              f"| {theirs[2] * 1e3:.2f} | {theirs[0] * theirs[2] * 1e3:.1f} | {100 * diff:+.3f} % "
              f"| {theirs[2] / ours[2]:.1f}x |")


if __name__ == "__main__":
    main()
