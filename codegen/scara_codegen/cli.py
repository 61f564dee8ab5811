"""Command line: ``python3 -m scara_codegen [--out DIR] [--check] robots/*.toml``.

Every description is read and validated before anything is written; on any error nothing is
written and the exit status is 1. Each JSON file is written to a temporary file beside it and
renamed into place.
"""

from __future__ import annotations

import argparse
import functools
import hashlib
import json
import os
import sys
import tempfile
from pathlib import Path

import casadi as ca

from . import GENERATOR, export, model, normalize, urdf_out
from .description import ACCEPTED_RANGE, DescriptionError, to_float
from .loader import load

FORMAT = "scara-model-graph/1"


def render_c(robot, models) -> str:
    """CasADi's own C code for the same graphs (benchmark baseline only), one file per robot.
    Functions are named ``<robot>_<function>`` and ``<robot>_parametric_<function>``."""
    with tempfile.TemporaryDirectory() as tmp:
        gen = ca.CodeGenerator(f"{robot.name}.c", {"with_header": False, "casadi_real": "double"})
        for suffix, functions in models:
            for f in functions:
                gen.add(_renamed(f.function, f"{robot.name}{suffix}_{f.name}"))
        gen.generate(tmp + os.sep)
        return (Path(tmp) / f"{robot.name}.c").read_text()


def _renamed(fn, name):
    sx_in = [fn.sx_in(i) for i in range(fn.n_in())]
    return ca.Function(name, sx_in, fn.call(sx_in))


def type_name(name: str) -> str:
    """The Rust type of a robot: ``scara_mdh`` -> ``ScaraMdh``, ``puma560`` -> ``Puma560``."""
    return "".join(part[:1].upper() + part[1:] for part in name.split("_"))


def task_problem(robot, functions, samples: int = 64):
    """Why ``robot``'s task cannot be controlled, or ``None``: the task's rows of the generated
    Jacobian must have full row rank at some sampled configuration (a robot is singular on a
    set of measure zero, so almost all samples should have it; none having it means the tool
    cannot move in those directions independently). Configurations are drawn uniformly within
    the joint limits (infinite ones as +-pi rad or +-1 m) from a fixed seed. The rank counts
    singular values above rounding of the largest (numpy's ``matrix_rank`` tolerance): links
    whose lengths differ by more than ~1e15 are rank deficient in double precision."""
    import random

    import numpy as np

    jac = next(f.function for f in functions if f.name == "jacobian")
    rows = list(robot.task)
    rng = random.Random(1)
    best = 0
    for _ in range(samples):
        q = []
        for j in robot.joints:
            lo, hi = to_float(j.lower), to_float(j.upper)
            span = 3.141592653589793 if j.revolute else 1.0
            lo = lo if abs(lo) < 1e6 else -span
            hi = hi if abs(hi) < 1e6 else span
            q.append(rng.uniform(lo, hi))
        # The output is the 6 x N Jacobian flattened row by row.
        j_full = ca.DM(jac(q)).full().reshape(6, robot.dof)
        s = np.linalg.svd(j_full[rows, :], compute_uv=False)
        # numpy's rank tolerance: singular values below what rounding leaves of the largest.
        rank = int((s > s[0] * max(j_full.shape) * np.finfo(float).eps).sum()) if s[0] > 0 else 0
        best = max(best, rank)
        if best == len(rows):
            return None
    names = ", ".join(("x", "y", "z", "rx", "ry", "rz")[r] for r in rows)
    return (f"`task` = [{names}]: the Jacobian's rows for these directions have rank at most "
            f"{best} < {len(rows)} at {samples} configurations within the limits: the tool cannot "
            "move in them independently; state the directions it can control")


def render_rust_index(robots, urdf_dir=None) -> str:
    """``generated/src/models.rs``: one module per robot, each with its functions in ``f64`` and
    in ``f32`` (submodule ``f32``), its parametric model (``f64`` only; and, with ``urdf_dir``,
    its URDF as ``URDF``), and the registry of every robot: ``ROBOTS`` and the
    ``for_each_robot!`` macro that the root crate, its tests and benchmarks expand."""
    robots = sorted(robots, key=lambda r: r.name)
    lines = [
        "// @generated — do not edit; regenerate with: bash codegen/regenerate.sh",
        "//",
        "// One module per description in robots/, in name order, and the registry of them all.",
        "",
    ]
    for r in robots:
        src = Path(os.path.relpath(r.path.resolve(), Path.cwd())).as_posix()
        task = ", ".join(str(row) for row in r.task)
        names = ", ".join(("x", "y", "z", "rx", "ry", "rz")[row] for row in r.task)
        lines += [
            f"/// {r.description} (`{src}`, {r.dof} DOF, {r.convention}).",
            f"pub mod {r.name} {{",
            f'    scara_derive::robot_model!("models/{r.name}.json", f32, lanes);',
            "",
            "    /// The task: the rows of the geometric Jacobian (`vx vy vz wx wy wz`) its end",
            f"    /// effector is controlled in, `{names}` (the description's `task`).",
            f"    pub const TASK_ROWS: [usize; {len(r.task)}] = [{task}];",
            "",
        ]
        if urdf_dir is not None:
            lines += [
                "    /// The robot as a URDF (links in their joint frames, inertias about the COM),",
                "    /// for Pinocchio, MuJoCo, RViz and ROS; `scara urdf` prints it.",
                f'    pub const URDF: &str = include_str!("../urdf/{r.name}.urdf");',
                "",
            ]
        lines += [
            "    /// The same robot with its standard inertial parameters as an input `params`",
            "    /// (10 per link: m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz; inertia about the",
            "    /// link frame origin), for identification and model-mismatch studies.",
            "    pub mod parametric {",
            f'        scara_derive::robot_model!("models/{r.name}_parametric.json");',
            "    }",
            "}",
            "",
        ]
    names = ", ".join(f'"{r.name}"' for r in robots)
    lines += [
        "/// The name of every generated robot (`robots/<name>.toml`), in name order.",
        f"pub const ROBOTS: [&str; {len(robots)}] = [{names}];",
        "",
        "/// The registry of generated robots: `for_each_robot!(callback)` expands to",
        "/// `callback! { [] (module, Type, dof, \"doc\"), ... }` with one entry per robot in name order",
        "/// (`module` in this crate, `Type` the name of its zero-sized model type); with more",
        "/// tokens, `for_each_robot!(callback, tokens)`, they are passed inside the brackets.",
        "/// Adding a robot is adding `robots/<name>.toml` and regenerating: everything that",
        "/// expands this macro picks it up.",
        "#[macro_export]",
        "macro_rules! for_each_robot {",
        "    ($callback:ident $(, $($args:tt)*)?) => {",
        "        $callback! {",
        "            [$($($args)*)?]",
    ]
    for r in robots:
        src = Path(os.path.relpath(r.path.resolve(), Path.cwd())).as_posix()
        doc = f"{r.description} (`{src}`, {r.dof} DOF, {r.convention})".replace("\\", "\\\\").replace('"', '\\"')
        lines.append(f'            ({r.name}, {type_name(r.name)}, {r.dof}, "{doc}")')
    lines += ["        }", "    };", "}", ""]
    return "\n".join(lines)


def render(robot, functions, source: str) -> str:
    """The JSON text, deterministic: fixed key order, one instruction per line."""
    placeholders = {}

    def ph(value):
        key = f"@@{len(placeholders)}@@"
        placeholders[key] = value
        return key

    doc = {
        "format": FORMAT,
        "robot": {
            "name": robot.name,
            "description": robot.description,
            "dof": robot.dof,
            "joints": [
                {
                    "name": j.name,
                    "kind": j.kind,
                    "lower": to_float(j.lower),
                    "upper": to_float(j.upper),
                    "effort": to_float(j.effort),
                }
                for j in robot.joints
            ],
            "gravity": [to_float(g) for g in robot.gravity],
        },
        "provenance": {
            "generator": GENERATOR,
            "generator_sha256": generator_sha256(),
            "casadi": ca.__version__,
            "source": source,
            "source_sha256": robot.sha256,
        },
        "functions": [
            {
                "name": f.name,
                "doc": f.doc,
                "inputs": [{"name": n, "len": k, "doc": d} for n, k, d in f.inputs],
                "output": {"name": f.output[0], "shape": f.output[1], "doc": f.output[2]},
                "counts": f.counts,
                "instructions": ph(f.code),
                "result": ph(f.result),
            }
            for f in functions
        ],
    }
    text = json.dumps(doc, indent=2, ensure_ascii=False)
    for key, value in placeholders.items():
        if value and isinstance(value[0], list):
            body = ",\n        ".join(json.dumps(v, separators=(", ", ": ")) for v in value)
            rep = "[\n        " + body + "\n      ]"
        else:
            rep = json.dumps(value, separators=(", ", ": "))
        text = text.replace(json.dumps(key), rep)
    return text + "\n"


@functools.lru_cache(maxsize=None)
def generator_sha256() -> str:
    """SHA-256 of what derives a graph: every module of this package (name and text, in name
    order) and the CasADi version. A graph whose description and generator hashes are both
    current is what a regeneration would write again."""
    h = hashlib.sha256()
    for path in sorted(Path(__file__).parent.glob("*.py")):
        h.update(path.name.encode() + b"\0" + path.read_bytes() + b"\0")
    h.update(ca.__version__.encode())
    return h.hexdigest()


def unchanged_outputs(robot, args) -> list | None:
    """The files this run would write for ``robot`` (graphs, URDF, C), read from disk, if every
    one exists and its graphs record the robot's description hash and the current generator
    hash; else None (the robot is derived again)."""
    paths = [args.out / f"{stem}.json" for stem in output_stems(robot)]
    current = generator_sha256()
    for path in paths:
        try:
            provenance = json.loads(path.read_text(encoding="utf-8"))["provenance"]
        except (OSError, ValueError, KeyError, TypeError):
            return None
        if not isinstance(provenance, dict) or (
            provenance.get("source_sha256"), provenance.get("generator_sha256")
        ) != (robot.sha256, current):
            return None
    if args.urdf_out is not None:
        paths.append(args.urdf_out / f"{robot.name}.urdf")
    if args.c_out is not None:
        paths.append(args.c_out / f"{robot.name}.c")
    out = []
    for path in paths:
        try:
            out.append((path, path.read_text(encoding="utf-8")))
        except OSError:
            return None
    return out


def write_atomic(path: Path, text: str) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    try:
        with os.fdopen(fd, "w", encoding="utf-8", newline="\n") as fh:
            fh.write(text)
        os.chmod(tmp, 0o644)
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise


def output_stems(robot) -> tuple[str, str]:
    """The model files a robot gets in ``--out``, without ``.json``."""
    return robot.name, f"{robot.name}_parametric"


def _source_of(path: Path):
    """``provenance.source`` of an existing model file, or None if it is not one."""
    try:
        return json.loads(path.read_text(encoding="utf-8"))["provenance"]["source"]
    except (OSError, ValueError, KeyError, TypeError):
        return None


def name_collisions(robots, out: Path) -> list[str]:
    """Robots whose model files would overwrite each other's, or overwrite in ``out`` the model
    of a description that is not part of this run but still exists."""
    problems = []
    owners: dict[str, list] = {}
    for r in robots:
        for stem in output_stems(r):
            owners.setdefault(stem, []).append(r)
    for stem, rs in owners.items():
        if len(rs) < 2:
            continue
        if len({r.name for r in rs}) == 1:
            msg = f"robot name `{rs[0].name}` is used by more than one description: " + ", ".join(
                str(r.path) for r in rs
            )
        else:
            msg = (
                f"robot names clash: {' and '.join(f'`{r.name}` ({r.path})' for r in rs)} would "
                f"both write {stem}.json (the parametric model of robot `x` is `x_parametric`); "
                "rename one"
            )
        if msg not in problems:
            problems.append(msg)
    inputs = {r.path.resolve() for r in robots}
    for r in robots:
        for stem in output_stems(r):
            existing = out / f"{stem}.json"
            source = _source_of(existing) if existing.is_file() else None
            if not isinstance(source, str) or not source:
                continue
            other = Path(source)
            if other.resolve() in inputs or not other.is_file():
                continue  # regenerated in this run, or its description is gone
            problems.append(
                f"{r.path}: robot name `{r.name}` would overwrite {existing}, the model of "
                f"{source}; give this robot another name"
            )
            break  # one message per robot
    return problems


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="python3 -m scara_codegen", description=__doc__)
    ap.add_argument("descriptions", nargs="+", type=Path, help="robot description files (TOML)")
    ap.add_argument("--out", type=Path, default=Path("generated/models"), help="output folder")
    ap.add_argument(
        "--c-out", type=Path, default=None,
        help="also write CasADi's own C code for the same graphs here (benchmark baseline)",
    )
    ap.add_argument(
        "--rust-index", type=Path, default=None,
        help="also write the Rust module list (generated/src/models.rs) for these robots",
    )
    ap.add_argument(
        "--prune", action="store_true",
        help="remove *.json in --out and *.c in --c-out that this run did not write",
    )
    ap.add_argument(
        "--urdf-out", type=Path, default=None,
        help="also write each robot as a URDF (<name>.urdf) here",
    )
    ap.add_argument(
        "--all", action="store_true",
        help="derive every robot; without it a robot whose graphs record its description's "
        "and the generator's current hashes (and whose URDF and C files exist) is kept as it is",
    )
    ap.add_argument("--quiet", action="store_true", help="do not print operation counts")
    args = ap.parse_args(argv)

    robots, failed = [], False
    for path in args.descriptions:
        try:
            robot = load(path)
        except DescriptionError as e:
            print(f"error: {e}", file=sys.stderr)
            failed = True
            continue
        for w in robot.warnings:
            print(w, file=sys.stderr)
        robots.append(robot)
    for problem in name_collisions(robots, args.out):
        print(f"error: {problem}", file=sys.stderr)
        failed = True
    if failed:
        print("error: nothing written", file=sys.stderr)
        return 1

    rendered, kept = [], []
    for robot in robots:
        log = None if args.quiet else print
        same = None if args.all else unchanged_outputs(robot, args)
        if same is not None:
            kept.extend(path for path, _ in same)
            print(f"{robot.name} ({robot.path}): unchanged (description and generator), kept")
            continue
        if log:
            log(f"{robot.name} ({robot.path}):")
        try:
            functions = model.generate(robot, log=log)
            parametric = model.generate(robot, parametric=True, log=log)
        except (normalize.CoefficientRangeError, export.ExportError, model.SingularMassMatrix) as e:
            hint = (
                f"; the numbers of a description must be {ACCEPTED_RANGE}"
                if isinstance(e, normalize.CoefficientRangeError)
                else ""
            )
            print(
                f"error: {robot.path}: cannot generate the model: {e}{hint}\nerror: nothing written",
                file=sys.stderr,
            )
            return 1
        problem = task_problem(robot, functions)
        if problem is not None:
            print(f"error: {robot.path}: {problem}\nerror: nothing written", file=sys.stderr)
            return 1
        source = Path(os.path.relpath(robot.path.resolve(), Path.cwd())).as_posix()
        # The hash is of the description file, so identical input gives identical output.
        rendered.append((args.out / f"{robot.name}.json", render(robot, functions, source)))
        rendered.append(
            (args.out / f"{robot.name}_parametric.json", render(robot, parametric, source))
        )
        if args.urdf_out is not None:
            rendered.append((args.urdf_out / f"{robot.name}.urdf", urdf_out.render(robot, source)))
        if args.c_out is not None:
            c_text = render_c(robot, [("", functions), ("_parametric", parametric)])
            rendered.append((args.c_out / f"{robot.name}.c", c_text))
    if args.rust_index is not None:
        rendered.append((args.rust_index, render_rust_index(robots, args.urdf_out)))
    for path, text in rendered:
        write_atomic(path, text)
        digest = hashlib.sha256(text.encode()).hexdigest()[:12]
        if not args.quiet:
            print(f"wrote {path} (sha256 {digest})")
    if args.prune:
        written = {p.resolve() for p, _ in rendered} | {p.resolve() for p in kept}
        for folder, pattern in ((args.out, "*.json"), (args.c_out, "*.c"), (args.urdf_out, "*.urdf")):
            if folder is None or not folder.is_dir():
                continue
            for stale in sorted(folder.glob(pattern)):
                if stale.resolve() not in written:
                    stale.unlink()
                    print(f"removed stale {stale}")
    return 0
