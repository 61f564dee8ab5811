"""armdyn-codegen (the same command as `python3 -m armdyn_codegen`): robot descriptions ->
model graphs.

    armdyn-codegen DESCRIPTION.toml [DESCRIPTION.toml ...] --out DIR [--urdf-out DIR2]
                   [--c-out DIR3] [--all] [--quiet]

A description is a DH table, or a URDF named by the TOML with its base and tip links (format:
robots/README.md). For each robot it writes DIR/<robot>.json and DIR/<robot>_parametric.json,
the expression graphs that `armdyn_runtime::robot_model!` expands, and the robot as a URDF,
<robot>.urdf (into DIR, or DIR2); with --c-out, CasADi's own C code of the same graphs
(<robot>.c, a benchmark baseline). Every description is read and validated before anything is
written: on any error each message names the file, the joint, link or URDF element, and the
rule, nothing is written and the exit status is 1. Each file is written to a temporary file
beside it and renamed into place. Identical input gives byte-identical output.

Registry upkeep (codegen/regenerate.sh): --check validates and writes nothing; --index-only
with --rust-index and/or --prune writes the Rust registry of the descriptions and removes the
files of robots that are none of them, deriving nothing.
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

FORMAT = "armdyn-model-graph/1"


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


def task_problem(robot, jac, samples: int = 64):
    """Why ``robot``'s task cannot be controlled, or ``None``: the task's rows of the generated
    Jacobian ``jac`` (a CasADi function of ``q``, 6 x N row by row) must have full row rank at some sampled configuration (a robot is singular on a
    set of measure zero, so almost all samples should have it; none having it means the tool
    cannot move in those directions independently). Configurations are drawn uniformly within
    the joint limits (infinite ones as +-pi rad or +-1 m) from a fixed seed. The rank counts
    singular values above rounding of the largest (numpy's ``matrix_rank`` tolerance): links
    whose lengths differ by more than ~1e15 are rank deficient in double precision."""
    import random

    import numpy as np

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


def render_rust_index(robots) -> str:
    """``generated/src/models.rs``: one module per robot, each with its functions in ``f64`` and
    in ``f32`` (submodule ``f32``), its parametric model (``f64`` only) and its URDF as
    ``URDF``, and the registry of every robot: ``ROBOTS`` and the ``for_each_robot!`` macro
    that the root crate, its tests and benchmarks expand. The layout is the registry crate's:
    the graphs in ``../models/``, the URDFs in ``../urdf/``, relative to the index."""
    robots = sorted(robots, key=lambda r: r.name)
    lines = [
        "// @generated — do not edit; regenerate with: bash codegen/regenerate.sh",
        "//",
        "// One module per description in robots/, in name order, and the registry of them all.",
        "",
    ]
    for r in robots:
        src = Path(os.path.relpath(r.path.resolve(), Path.cwd())).as_posix()
        lines += [
            f"/// {r.description} (`{src}`, {r.dof} DOF, {r.convention}).",
            f"pub mod {r.name} {{",
            f'    armdyn_runtime::robot_model!("models/{r.name}.json", f32, lanes);',
            "",
        ]
        lines += [
            "    /// The robot as a URDF (links in their joint frames, inertias about the COM),",
            "    /// for Pinocchio, MuJoCo, RViz and ROS; `armdyn urdf` prints it.",
            f'    pub const URDF: &str = include_str!("../urdf/{r.name}.urdf");',
            "",
        ]
        lines += [
            "    /// The same robot with its standard inertial parameters as an input `params`",
            "    /// (10 per link: m, m cx, m cy, m cz, Ixx, Ixy, Ixz, Iyy, Iyz, Izz; inertia about the",
            "    /// link frame origin), for identification and model-mismatch studies.",
            "    pub mod parametric {",
            f'        armdyn_runtime::robot_model!("models/{r.name}_parametric.json");',
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
            "task": list(robot.task),
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


def output_paths(robot, args) -> list[Path]:
    """Every file a run writes for ``robot``: its two graphs in ``--out``, its URDF, and with
    ``--c-out`` its C code."""
    paths = [args.out / f"{stem}.json" for stem in output_stems(robot)]
    paths.append(args.urdf_out / f"{robot.name}.urdf")
    if args.c_out is not None:
        paths.append(args.c_out / f"{robot.name}.c")
    return paths


def unchanged_outputs(robot, args) -> list | None:
    """The files this run would write for ``robot`` (graphs, URDF, C), read from disk, if every
    one exists and its graphs record the robot's description hash and the current generator
    hash; else None (the robot is derived again)."""
    paths = output_paths(robot, args)
    current = generator_sha256()
    for path in paths:
        if path.suffix != ".json":
            continue
        try:
            provenance = json.loads(path.read_text(encoding="utf-8"))["provenance"]
        except (OSError, ValueError, KeyError, TypeError):
            return None
        if not isinstance(provenance, dict) or (
            provenance.get("source_sha256"), provenance.get("generator_sha256")
        ) != (robot.sha256, current):
            return None
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


def _stems_of(description: Path) -> tuple[str, ...] | None:
    """The model stems another description (not part of this run) writes, from its ``name``;
    None if that cannot be read (then it is taken to write any)."""
    import tomllib

    try:
        name = tomllib.loads(description.read_bytes().decode("utf-8-sig")).get("name")
    except (OSError, UnicodeDecodeError, tomllib.TOMLDecodeError, RecursionError, ValueError):
        return None
    if not isinstance(name, str):
        return None
    return name, f"{name}_parametric"


def name_collisions(robots, out: Path | None) -> list[str]:
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
    if out is None:
        return problems
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
            stems = _stems_of(other)
            if stems is not None and stem not in stems:
                continue  # its description now names another robot: a stale file
            problems.append(
                f"{r.path}: robot name `{r.name}` would overwrite {existing}, the model of "
                f"{source}; give this robot another name"
            )
            break  # one message per robot
    return problems


# What can go wrong deriving a valid description (an error naming the description, not a traceback).
DERIVATION_ERRORS = (normalize.CoefficientRangeError, export.ExportError, model.SingularMassMatrix)


class GenerationError(Exception):
    """A valid description whose model cannot be generated; the message names the file."""


def cannot_generate(e) -> str:
    hint = (
        f"; the numbers of a description must be {ACCEPTED_RANGE}"
        if isinstance(e, normalize.CoefficientRangeError)
        else ""
    )
    return f"cannot generate the model: {e}{hint}"


def parse_args(argv, prog):
    ap = argparse.ArgumentParser(
        prog=prog, description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    ap.add_argument(
        "descriptions", nargs="+", type=Path, metavar="DESCRIPTION.toml",
        help="robot description files (robots/README.md)",
    )
    ap.add_argument(
        "--out", type=Path, default=None, metavar="DIR",
        help="write <robot>.json and <robot>_parametric.json (and, without --urdf-out, "
        "<robot>.urdf) here; required except with --check and --index-only",
    )
    ap.add_argument(
        "--urdf-out", type=Path, default=None, metavar="DIR2",
        help="write each robot as a URDF (<robot>.urdf) here instead of into --out",
    )
    ap.add_argument(
        "--c-out", type=Path, default=None, metavar="DIR3",
        help="also write CasADi's own C code for the same graphs here (<robot>.c, benchmark "
        "baseline)",
    )
    ap.add_argument(
        "--all", action="store_true",
        help="derive every robot; without it a robot whose graphs in --out record its "
        "description's and the generator's current hashes (and whose URDF and C files exist) "
        "is kept as it is",
    )
    ap.add_argument("--quiet", action="store_true", help="do not print operation counts")
    ap.add_argument(
        "--version", action="version",
        version=f"{GENERATOR} (generator sha256 {generator_sha256()}, casadi {ca.__version__})",
        help="print the version and the generator's hash that the graphs record, and exit",
    )
    reg = ap.add_argument_group("registry upkeep (codegen/regenerate.sh)")
    reg.add_argument(
        "--check", action="store_true",
        help="validate the descriptions (and their tasks) and write nothing; with --out, also "
        "that no robot would overwrite the model of another description there",
    )
    reg.add_argument(
        "--rust-index", type=Path, default=None, metavar="FILE",
        help="also write the Rust registry of these robots (generated/src/models.rs; graphs "
        "in ../models/ and URDFs in ../urdf/ relative to it)",
    )
    reg.add_argument(
        "--index-only", action="store_true",
        help="derive nothing: only write --rust-index and/or --prune (the graphs must exist "
        "in --out, if given)",
    )
    reg.add_argument(
        "--prune", action="store_true",
        help="remove *.json in --out, *.urdf in the URDF folder and *.c in --c-out that are "
        "not files of these robots",
    )
    args = ap.parse_args(argv)
    if args.check and (args.index_only or args.rust_index or args.prune):
        ap.error("--check writes nothing: it takes no --rust-index, --index-only or --prune")
    if args.index_only and not (args.rust_index or args.prune):
        ap.error("--index-only needs --rust-index FILE or --prune (or both)")
    if args.out is None and not (args.check or (args.index_only and not args.prune)):
        ap.error("the following argument is required: --out DIR")
    if args.urdf_out is None:
        args.urdf_out = args.out
    return args


def read_descriptions(paths, out, warn: bool = True) -> list | None:
    """Every description, validated (with ``warn``, its warnings printed); None after printing
    each error."""
    robots, failed = [], False
    for path in paths:
        try:
            robot = load(path)
        except DescriptionError as e:
            print(f"error: {e}", file=sys.stderr)
            failed = True
            continue
        for w in robot.warnings if warn else ():
            print(w, file=sys.stderr)
        robots.append(robot)
    for problem in name_collisions(robots, out):
        print(f"error: {problem}", file=sys.stderr)
        failed = True
    return None if failed else robots


def nothing_written(message: str | None = None) -> int:
    if message is not None:
        print(f"error: {message}", file=sys.stderr)
    print("error: nothing written", file=sys.stderr)
    return 1


def check(robots, args) -> int:
    """``--check``: the task of every robot (on the Jacobian the generator would export), after
    the validation every run does; nothing is written."""
    failed = False
    for robot in robots:
        try:
            problem = task_problem(robot, model.jacobian_function(robot))
        except DERIVATION_ERRORS as e:
            problem = cannot_generate(e)
        if problem is not None:
            print(f"error: {robot.path}: {problem}", file=sys.stderr)
            failed = True
    if failed:
        return nothing_written()
    if not args.quiet:
        print(f"checked {len(robots)} description(s): no errors (nothing written)")
    return 0


def derive(robot, args) -> list:
    """``[(path, text)]``: the graphs, the URDF and (with ``--c-out``) the C code of one robot.
    Raises ``GenerationError`` (naming the description) if it cannot be generated."""
    log = None if args.quiet else print
    if log:
        log(f"{robot.name} ({robot.path}):")
    try:
        functions = model.generate(robot, log=log)
        parametric = model.generate(robot, parametric=True, log=log)
    except DERIVATION_ERRORS as e:
        raise GenerationError(f"{robot.path}: {cannot_generate(e)}") from None
    jac = next(f.function for f in functions if f.name == "jacobian")
    problem = task_problem(robot, jac)
    if problem is not None:
        raise GenerationError(f"{robot.path}: {problem}")
    source = Path(os.path.relpath(robot.path.resolve(), Path.cwd())).as_posix()
    # The hash is of the description file, so identical input gives identical output.
    rendered = [
        (args.out / f"{robot.name}.json", render(robot, functions, source)),
        (args.out / f"{robot.name}_parametric.json", render(robot, parametric, source)),
        (args.urdf_out / f"{robot.name}.urdf", urdf_out.render(robot, source)),
    ]
    if args.c_out is not None:
        c_text = render_c(robot, [("", functions), ("_parametric", parametric)])
        rendered.append((args.c_out / f"{robot.name}.c", c_text))
    return rendered


def main(argv=None, prog: str = "python3 -m armdyn_codegen") -> int:
    args = parse_args(argv, prog)
    # --index-only derives nothing: the warnings are those of the runs that derived.
    robots = read_descriptions(args.descriptions, args.out, warn=not args.index_only)
    if robots is None:
        return nothing_written()
    if args.check:
        return check(robots, args)

    rendered = []
    if args.index_only:
        for robot in robots:
            if args.out is None:
                break
            for path in output_paths(robot, args)[:2]:
                if not path.is_file():
                    return nothing_written(
                        f"{robot.path}: {path} does not exist: generate the robot first "
                        f"(armdyn-codegen {robot.path} --out {args.out})"
                    )
    else:
        for robot in robots:
            same = None if args.all else unchanged_outputs(robot, args)
            if same is not None:
                print(f"{robot.name} ({robot.path}): unchanged (description and generator), kept")
                continue
            try:
                rendered.extend(derive(robot, args))
            except GenerationError as e:
                return nothing_written(str(e))
    if args.rust_index is not None:
        rendered.append((args.rust_index, render_rust_index(robots)))
    for path, text in rendered:
        write_atomic(path, text)
        digest = hashlib.sha256(text.encode()).hexdigest()[:12]
        if not args.quiet:
            print(f"wrote {path} (sha256 {digest})")
    if args.prune:
        keep = {p.resolve() for r in robots for p in output_paths(r, args)}
        for folder, pattern in ((args.out, "*.json"), (args.c_out, "*.c"), (args.urdf_out, "*.urdf")):
            if folder is None or not folder.is_dir():
                continue
            for stale in sorted(folder.glob(pattern)):
                if stale.resolve() not in keep:
                    stale.unlink()
                    print(f"removed stale {stale}")
    return 0


def main_command(argv=None) -> int:
    """The console command ``armdyn-codegen`` (``pip install ./codegen``): ``main`` under its
    installed name."""
    return main(argv, prog="armdyn-codegen")
