"""Side-by-side benchmark of the generated dynamics against Pinocchio (C++), per robot and in
both Rust builds (plain release, and `-C target-cpu=native`).

    python3 -m pip install pin cmeel-eigen      # once: Pinocchio's wheel (headers and
                                                 # libpinocchio_default) and Eigen's headers
    python3 benches/pinocchio/compare.py [--robots scara puma560] [--rounds 7] [--states 1000]

The script
1. writes each robot's Pinocchio model (joint placements, axes and link inertias, from
   robots/<name>.toml through the generator's own reader: DH tables and URDF alike) and one
   file of random states within the joint limits;
2. builds benches/pinocchio/pinocchio_side.cpp against the wheel (g++ -O3 -DNDEBUG), and
   examples/pinocchio_side.rs twice (plain release in target/, native in target-native/);
3. checks that the three programs agree on M, c + g, forward and inverse dynamics and their
   derivatives at the first
   states (relative 1e-9), so that the timings compare the same robot;
4. runs them alternately, `--rounds` times, on the same states, and prints the median time per
   call and the ratio Pinocchio time / project time for M + c + g vs crba + nonLinearEffects,
   forward dynamics vs aba, inverse dynamics vs rnea, and the derivatives of both
   (`inverse_dynamics_derivatives` vs `computeRNEADerivatives`, `forward_dynamics_derivatives`
   vs `computeABADerivatives`; each side returns d/dq, d/dqd and M, respectively M^-1). Our
   M + c + g is one call of the
   generated `mass_matrix_and_bias` (`[M | c + g]`); the row "M, c, g (3 calls)" times the
   three separate functions against the same crba + nonLinearEffects.

Any robot of the registry (`--robots ur5 panda`).
"""

from __future__ import annotations

import argparse
import os
import random
import site
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "codegen"))
from armdyn_codegen.description import to_float  # noqa: E402
from armdyn_codegen.loader import load  # noqa: E402

# (our timing, what it is, Pinocchio's algorithm); "mcg" is one call of the generated
# mass_matrix_and_bias ([M | c + g]), "mcg3" the three calls mass_matrix, coriolis, gravity.
PAIRS = [("mcg", "M + c + g", "crba + nonLinearEffects"),
         ("mcg3", "M, c, g (3 calls)", "crba + nonLinearEffects"),
         ("fd", "forward_dynamics", "aba"), ("id", "inverse_dynamics", "rnea"),
         ("did", "inverse_dynamics_derivatives", "computeRNEADerivatives"),
         ("dfd", "forward_dynamics_derivatives", "computeABADerivatives")]
# The timing of Pinocchio's side that each of ours is compared with.
THEIRS = {"mcg3": "mcg"}


AXES = {(1.0, 0.0, 0.0): 0, (0.0, 1.0, 0.0): 1, (0.0, 0.0, 1.0): 2}


def _placement(P):
    m = np.eye(4)
    m[:3, :3] = [[to_float(x) for x in row] for row in P.R]
    m[:3, 3] = [to_float(x) for x in P.p]
    return m


def model_text(robot) -> str:
    """Every robot through the generator's internal chain (``chain.Chain``): link frame
    ``F_i = F_{i-1} P_i Motion_i(q_i + offset_i) Post_i``. Pinocchio's joint i sits at
    ``Post_{i-1} P_i Motion_i(offset_i)`` in joint i-1's frame, and link i is moved from
    ``F_i`` into the joint frame by ``Post_i`` (as ``armdyn urdf`` writes it). Joint kinds:
    0-2 revolute about x, y, z; 3-5 prismatic along x, y, z; 6 and 7 revolute and prismatic
    about the unit axis that follows."""
    lines = [str(robot.dof), " ".join(repr(to_float(g)) for g in robot.gravity)]
    post_prev = np.eye(4)
    for j in robot.joints:
        axis = tuple(to_float(a) + 0.0 for a in j.axis)
        off = to_float(j.offset)
        motion = np.eye(4)
        if j.revolute:
            a = np.array(axis)
            K = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
            motion[:3, :3] = np.eye(3) + np.sin(off) * K + (1 - np.cos(off)) * K @ K
        else:
            motion[:3, 3] = off * np.array(axis)
        placement = post_prev @ _placement(j.placement) @ motion
        post = _placement(j.post)
        r, p = post[:3, :3], post[:3, 3]
        com = r @ np.array([to_float(x) for x in j.link.com]) + p
        inertia = r @ np.array([[to_float(x) for x in row] for row in j.link.inertia]) @ r.T
        kind = AXES.get(axis)
        kind = (6 if j.revolute else 7) if kind is None else kind + (0 if j.revolute else 3)
        lines.append(" ".join(
            [str(kind)] + [repr(a) for a in axis]
            + [repr(float(x)) for x in placement[:3, :3].ravel()]
            + [repr(float(x)) for x in placement[:3, 3]]
            + [repr(to_float(j.link.mass))]
            + [repr(float(x)) for x in com]
            + [repr(float(inertia[i, k])) for i, k in ((0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2))]
        ))
        post_prev = post
    return "\n".join(lines) + "\n"


def states_text(robot, count, seed) -> str:
    rng = random.Random(seed)
    out = [str(count)]
    for _ in range(count):
        q = [rng.uniform(to_float(j.lower), to_float(j.upper)) for j in robot.joints]
        qd = [rng.uniform(-2.0, 2.0) for _ in robot.joints]
        u = [rng.uniform(-0.5, 0.5) * to_float(j.effort) for j in robot.joints]
        out.append(" ".join(repr(x) for x in q + qd + u))
    return "\n".join(out) + "\n"


def parse(text):
    times, values = {}, {}
    for line in text.splitlines():
        f = line.split()
        if f and f[0] == "time":
            times[f[1]] = float(f[2])
        elif f and f[0] == "value":
            values[(f[1], int(f[2]))] = np.array([float(x) for x in f[3:]])
    return times, values


def run(cmd, **kw):
    return subprocess.run(cmd, check=True, capture_output=True, text=True, **kw).stdout


def build(tmp: Path):
    prefix = Path(site.getsitepackages()[0]) / "cmeel.prefix"
    if not (prefix / "include" / "pinocchio").is_dir():
        raise SystemExit(f"no Pinocchio headers under {prefix}: python3 -m pip install pin cmeel-eigen")
    exe = tmp / "pinocchio_side"
    cmd = [
        "g++", "-O3", "-DNDEBUG", "-std=c++17",
        "-DPINOCCHIO_ENABLE_TEMPLATE_INSTANTIATION", "-DBOOST_MPL_LIMIT_LIST_SIZE=30",
        "-DBOOST_MPL_LIMIT_VECTOR_SIZE=30", "-DBOOST_MPL_CFG_NO_PREPROCESSED_HEADERS",
        f"-I{prefix / 'include'}", f"-I{prefix / 'include' / 'eigen3'}",
        str(ROOT / "benches" / "pinocchio" / "pinocchio_side.cpp"), "-o", str(exe),
        f"-L{prefix / 'lib'}", "-lpinocchio_default", f"-Wl,-rpath,{prefix / 'lib'}",
    ]
    print("building Pinocchio's side:", " ".join(cmd[:3]), "...", flush=True)
    subprocess.run(cmd, check=True)
    rust = {}
    for build_name, target_dir, flags in (("plain", "target", ""), ("native", "target-native", "-C target-cpu=native")):
        env = dict(os.environ, CARGO_TARGET_DIR=str(ROOT / target_dir), RUSTFLAGS=flags)
        print(f"building the project's side ({build_name}): RUSTFLAGS='{flags}' "
              f"CARGO_TARGET_DIR={target_dir} cargo build --release --example pinocchio_side", flush=True)
        subprocess.run(["cargo", "build", "--release", "--quiet", "--example", "pinocchio_side"],
                       check=True, cwd=ROOT, env=env)
        rust[build_name] = ROOT / target_dir / "release" / "examples" / "pinocchio_side"
    return exe, rust


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--robots", nargs="+", default=["scara", "puma560"])
    ap.add_argument("--rounds", type=int, default=7)
    ap.add_argument("--states", type=int, default=1000)
    ap.add_argument("--reps", type=int, default=200, help="passes over the states per timing")
    ap.add_argument("--extra", nargs="*", default=[], metavar="NAME=PATH",
                    help="more builds of examples/pinocchio_side to run alternately with the others "
                         "(for example an earlier commit's), each a column pair NAME ns, NAME ratio")
    args = ap.parse_args(argv)
    with tempfile.TemporaryDirectory() as tmpdir:
        tmp = Path(tmpdir)
        cpp, rust = build(tmp)
        for extra in args.extra:
            label, _, path = extra.partition("=")
            rust[label] = Path(path)
        rows = []
        for name in args.robots:
            robot = load(ROOT / "robots" / f"{name}.toml")
            (tmp / f"{name}.model").write_text(model_text(robot))
            (tmp / f"{name}.states").write_text(states_text(robot, args.states, 12))
            programs = {"pinocchio": [str(cpp), str(tmp / f"{name}.model")]}
            for b, exe in rust.items():
                programs[b] = [str(exe), name]
            samples = {p: {} for p in programs}
            reference = None
            for r in range(args.rounds):
                for p, cmd in programs.items():
                    times, values = parse(run(cmd + [str(tmp / f"{name}.states"), str(args.reps)]))
                    for k in times:
                        samples[p].setdefault(k, []).append(times[k])
                    if reference is None:
                        reference = values
                    elif r == 0:
                        for key, want in reference.items():
                            got = values[key]
                            err = np.abs(got - want).max() / max(1.0, np.abs(want).max())
                            if err > 1e-9:
                                raise SystemExit(f"{name}: {p} disagrees with Pinocchio on {key}: {err:.2e}")
            print(f"{name}: the three programs agree (relative 1e-9) on M, c + g, FD, ID and their derivatives", flush=True)
            for k, ours, theirs in PAIRS:
                pin_ns = statistics.median(samples["pinocchio"][THEIRS.get(k, k)])
                row = [name, f"{ours} vs {theirs}", f"{pin_ns:.1f}"]
                for b in rust:
                    if k not in samples[b]:  # an extra build without this timing
                        row += ["-", "-"]
                        continue
                    ns = statistics.median(samples[b][k])
                    row += [f"{ns:.1f}", f"{pin_ns / ns:.1f}"]
                rows.append(row)
        head = ["robot", "project vs Pinocchio", "Pinocchio ns"]
        for b in rust:
            head += [f"{b} ns", f"{b} ratio"]
        print()
        print("| " + " | ".join(head) + " |")
        print("|" + "|".join([":--"] * 2 + ["--:"] * (len(head) - 2)) + "|")
        for row in rows:
            print("| " + " | ".join(row) + " |")
        print(f"\nmedians of {args.rounds} alternating rounds, {args.states} random states, "
              f"{args.reps} passes per timing; ratio = Pinocchio time / project time")


if __name__ == "__main__":
    main()
