"""The cost of stepping a scenario's controller from Python: ``armdyn.Controller.step`` over a
run's own samples (numpy arrays in, a numpy array out), per call, for the thesis trial (SCARA)
and the Panda's wipe; the step inside costs what ``cargo bench --bench control`` measures for
the same laws, the rest is the crossing (argument checks, array creation).

Run: ``python3 python/bench_controller.py`` (needs ``pip install ./python``). Prints a Markdown
table; the machine's load is printed first.
"""

import os
import sys
import time

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

_HERE = os.path.dirname(os.path.abspath(__file__))
sys.path = [p for p in sys.path if os.path.abspath(p or ".") != _HERE]
import armdyn  # noqa: E402

ROOT = os.path.dirname(_HERE)


def per_call(file, repeats=3):
    """Best time per ``step`` over the run's samples of ``file``, s, and the controller."""
    path = os.path.join(ROOT, "scenarios", file)
    run = armdyn.run_scenario(path)
    c = armdyn.Controller(path)
    rows = list(zip(run.t, run.q, run.qd, run.wrench))
    best = float("inf")
    for _ in range(repeats):
        c.reset(0.0, run.q[0], run.qd[0])
        t0 = time.perf_counter()
        for t, q, qd, w in rows:
            c.step(t, q, qd, w)
        best = min(best, (time.perf_counter() - t0) / len(rows))
    return best, c.name, len(rows)


def main():
    print(f"load average {os.getloadavg()[0]:.2f} on {os.cpu_count()} cores")
    print("\n| scenario | controller | steps | time per `step` from Python |")
    print("| --- | --- | ---: | ---: |")
    for file in ("thesis-hybrid.toml", "panda-wipe.toml"):
        t, name, n = per_call(file)
        print(f"| {file} | {name} | {n} | {t * 1e6:.2f} us |")


if __name__ == "__main__":
    main()
