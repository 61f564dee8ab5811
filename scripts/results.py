#!/usr/bin/env python3
"""Regenerate the result blocks of `README.md` and `docs/*.md` from the commands they name.

A block is the text between an opening comment and `<!-- /results -->`:

    <!-- results: armdyn run hybrid --all --out target/results/hybrid -->
    | force law | ... |            <- rewritten from the command's output
    <!-- /results -->

The opening comment says what to take from the command's standard output:

    <!-- results: CMD -->              the first Markdown table printed
    <!-- results table=N: CMD -->      the N-th table (1-based)
    <!-- results text: CMD -->         all of it, in a ```text fence
    <!-- results grep=REGEX: CMD -->   the lines matching REGEX, in a ```text fence
    <!-- results rows=REGEX: CMD -->   the first table's header and its rows matching REGEX

`armdyn` at the start of CMD is the release binary (built first); CMD runs from the repository's
root with `sh -c`. Deterministic blocks are `results`. Timing blocks are `timings`: the same
forms, plus `bench` (a criterion benchmark run with `--output-format bencher`, shown as a
table of medians). A timing block ends with a line naming the command, the date and the
machine, and only `--timings` reruns it (not in CI: timings depend on the machine and its
load). A command named by several blocks runs once per invocation, so that the blocks show
the same measurement.

The deterministic commands run before the files are rewritten, as many at once as the machine
has cores; commands that name the same `target/results/NAME` folder run one after the other,
in the order of the files.

    python3 scripts/results.py            rewrite every `results` block
    python3 scripts/results.py --check    rewrite nothing; exit 1 and show the difference
                                          if any block differs from what the code prints
    python3 scripts/results.py --timings  rewrite the `timings` blocks (slow)
    python3 scripts/results.py --only PAT only the files whose name contains PAT
    python3 scripts/results.py --block PAT  only the blocks whose command contains PAT
    python3 scripts/results.py --check --discard-outputs
                                          as --check, removing each `target/results/NAME`
                                          folder once its group of commands is done (CI:
                                          about 1 GB of samples and figures not kept)

Each file is rewritten, whole, through a temporary file and a rename as soon as its blocks
are done; a command that fails stops the run with its output and the file and line of its
block, and leaves that file (and the ones after it) as they were.
"""

from __future__ import annotations

import argparse
import datetime
import difflib
import os
import platform
import re
import shutil
import subprocess
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs"
OPEN = re.compile(r"^<!-- (results|timings)( [^:]*)?: (.*) -->$")
CLOSE = "<!-- /results -->"


class BlockError(Exception):
    pass


@dataclass
class Block:
    path: Path
    line: int  # 1-based line of the opening comment
    kind: str  # "results" or "timings"
    mode: str  # "", "table=N", "text", "grep=REGEX", "bench"
    command: str
    start: int  # index of the first line inside
    end: int  # index of the closing line


def blocks_of(path: Path, lines: list[str]) -> list[Block]:
    out = []
    i = 0
    while i < len(lines):
        m = OPEN.match(lines[i])
        if m:
            j = i + 1
            while j < len(lines) and lines[j] != CLOSE:
                if OPEN.match(lines[j]):
                    raise BlockError(f"{path}:{j + 1}: a block opens inside the block of line {i + 1}")
                j += 1
            if j == len(lines):
                raise BlockError(f"{path}:{i + 1}: the block has no closing `{CLOSE}`")
            out.append(Block(path, i + 1, m.group(1), (m.group(2) or "").strip(), m.group(3), i + 1, j))
            i = j
        i += 1
    return out


def binary() -> str:
    subprocess.run(["cargo", "build", "--release", "-q", "--bin", "armdyn"], cwd=ROOT, check=True)
    return str(ROOT / "target" / "release" / "armdyn")


# Outputs of the deterministic commands run so far, by command: a command that two files
# show (the README and the doc it summarises) runs once per check.
_RUN: dict[str, str] = {}

OUTPUT = re.compile(r"target/results/[^\s'\"/]+")


def chains(commands: list[Block]) -> list[list[Block]]:
    """The blocks' distinct commands in groups that may run side by side: two commands that
    name the same `target/results/NAME` folder (one writes what the other reads or writes)
    are in one group, in the order given."""
    parent: dict[int, int] = {}

    def root(i: int) -> int:
        while parent.setdefault(i, i) != i:
            i = parent[i]
        return i

    distinct = list({b.command: b for b in commands}.values())
    owner: dict[str, int] = {}
    for i, block in enumerate(distinct):
        root(i)
        for folder in OUTPUT.findall(block.command):
            if folder in owner:
                parent[root(i)] = root(owner[folder])
            owner.setdefault(folder, i)
    groups: dict[int, list[Block]] = {}
    for i, block in enumerate(distinct):
        groups.setdefault(root(i), []).append(block)
    return list(groups.values())


def run_ahead(todo: list[Block], binary_path: str, discard_outputs: bool = False) -> None:
    """Runs the deterministic commands of `todo` before they are rendered, as many at once
    as the machine has cores (their outputs do not depend on the load): each group of
    [`chains`] in order, the groups side by side. Errors are raised when a block is rendered
    (its command then runs again, alone, for the message). With `discard_outputs`, the
    `target/results/NAME` folders a group names are removed once the group is done (a block
    shows what its command printed, never what it wrote)."""
    import concurrent.futures

    def run_chain(chain: list[Block]) -> None:
        try:
            for block in chain:
                try:
                    run(block, binary_path)
                except BlockError:
                    return
        finally:
            if discard_outputs:
                results = (ROOT / "target" / "results").resolve()
                for folder in {f for block in chain for f in OUTPUT.findall(block.command)}:
                    path = (ROOT / folder).resolve()
                    if path.parent == results:
                        shutil.rmtree(path, ignore_errors=True)

    with concurrent.futures.ThreadPoolExecutor(max_workers=os.cpu_count() or 1) as pool:
        list(pool.map(run_chain, chains(todo)))


def run(block: Block, binary_path: str) -> str:
    if block.command in _RUN:
        return _RUN[block.command]
    command = re.sub(r"(^|&& |; )armdyn ", lambda m: m.group(1) + binary_path + " ", block.command)
    if block.mode == "bench":
        # Criterion's own arguments follow the first ` -- `.
        command += " --output-format bencher" if " -- " in command else " -- --output-format bencher"
    proc = subprocess.run(["sh", "-c", command], cwd=ROOT, capture_output=True, text=True)
    if proc.returncode != 0:
        raise BlockError(
            f"{block.path.relative_to(ROOT)}:{block.line}: `{block.command}` failed "
            f"(exit {proc.returncode}):\n{proc.stdout[-2000:]}{proc.stderr[-4000:]}"
        )
    _RUN[block.command] = proc.stdout
    return proc.stdout


def tables(text: str) -> list[list[str]]:
    found, current = [], []
    for line in text.splitlines():
        if line.startswith("|"):
            current.append(line.rstrip())
        elif current:
            found.append(current)
            current = []
    if current:
        found.append(current)
    return found


def bench_table(text: str) -> list[str]:
    rows = ["| benchmark | median |", "| :-- | --: |"]
    for line in text.splitlines():
        m = re.match(r"test (\S+) \.\.\. bench:\s+([\d,]+) ns/iter", line)
        if m:
            ns = int(m.group(2).replace(",", ""))
            shown = f"{ns / 1e6:.2f} ms" if ns >= 1e6 else f"{ns / 1e3:.2f} µs" if ns >= 1e4 else f"{ns} ns"
            rows.append(f"| `{m.group(1)}` | {shown} |")
    if len(rows) == 2:
        raise BlockError("no benchmark result in the output")
    return rows


def machine() -> str:
    cpu = platform.processor() or platform.machine()
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    return f"{cpu}, {os.cpu_count()} cores, load average {load:.1f} before the run"


def render(block: Block, stdout: str) -> list[str]:
    where = f"{block.path.relative_to(ROOT)}:{block.line}"
    mode = block.mode
    if mode == "bench":
        body = bench_table(stdout)
    elif mode == "text":
        body = ["```text", *stdout.rstrip("\n").splitlines(), "```"]
    elif mode.startswith("grep="):
        pattern = re.compile(mode[5:])
        body = ["```text", *[l for l in stdout.splitlines() if pattern.search(l)], "```"]
        if len(body) == 2:
            raise BlockError(f"{where}: no line of `{block.command}` matches {mode[5:]!r}")
    elif mode.startswith("rows="):
        found = tables(stdout)
        if not found:
            raise BlockError(f"{where}: `{block.command}` printed no table")
        pattern = re.compile(mode[5:])
        rows = [r for r in found[0][2:] if pattern.search(r)]
        if not rows:
            raise BlockError(f"{where}: no row of `{block.command}`'s table matches {mode[5:]!r}")
        body = [*found[0][:2], *rows]
    else:
        n = 1
        if mode.startswith("table="):
            n = int(mode[6:])
        elif mode:
            raise BlockError(f"{where}: unknown form `{mode}` (table=N, text, grep=REGEX, rows=REGEX, bench)")
        found = tables(stdout)
        if len(found) < n:
            raise BlockError(f"{where}: `{block.command}` printed {len(found)} table(s), not {n}")
        body = found[n - 1]
    if block.kind == "timings":
        today = datetime.date.today().isoformat()
        body = [*body, "", f"_Measured {today} on {machine()}: `{block.command}`._"]
    return body


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--check", action="store_true")
    parser.add_argument("--timings", action="store_true")
    parser.add_argument("--only", default="")
    parser.add_argument("--block", default="")
    parser.add_argument("--discard-outputs", action="store_true")
    args = parser.parse_args()
    if args.discard_outputs and not args.check:
        parser.error("--discard-outputs goes with --check")
    kind = "timings" if args.timings else "results"
    binary_path = binary()
    changed = []
    paths = [p for p in [ROOT / "README.md", *sorted(DOCS.glob("*.md"))] if args.only in p.name]
    if kind == "results":
        try:
            every = [b for p in paths for b in blocks_of(p, p.read_text().split("\n"))]
        except BlockError as e:
            print(f"error: {e}", file=sys.stderr)
            return 1
        run_ahead(
            [b for b in every if b.kind == kind and args.block in b.command],
            binary_path,
            args.discard_outputs,
        )
    for path in paths:
        lines = path.read_text().split("\n")
        new = list(lines)
        try:
            todo = [
                b for b in blocks_of(path, lines) if b.kind == kind and args.block in b.command
            ]
        except BlockError as e:
            print(f"error: {e}", file=sys.stderr)
            return 1
        # From the last block up, so earlier indices stay valid.
        for block in reversed(todo):
            print(f"{path.relative_to(ROOT)}:{block.line}: {block.command}", file=sys.stderr)
            try:
                body = render(block, run(block, binary_path))
            except BlockError as e:
                print(f"error: {e}", file=sys.stderr)
                return 1
            new[block.start:block.end] = body
        if new != lines:
            changed.append(path)
            if not args.check:
                # Each file as soon as its blocks are done (timings take long): whole files only.
                write(path, "\n".join(new))
            if args.check:
                sys.stdout.writelines(
                    difflib.unified_diff(
                        [l + "\n" for l in lines], [l + "\n" for l in new],
                        f"{path.relative_to(ROOT)} (committed)", f"{path.relative_to(ROOT)} (the code prints)",
                    )
                )
    if args.check:
        if changed:
            print(
                f"\n*** {len(changed)} file(s) of README.md and docs/ differ from what the code prints: "
                "run `python3 scripts/results.py` and commit ***",
                file=sys.stderr,
            )
            return 1
        print("every result block of README.md and docs/ matches what the code prints", file=sys.stderr)
        return 0
    return 0


def write(path: Path, text: str) -> None:
    """Replaces `path` by `text` through a temporary file and a rename."""
    with tempfile.NamedTemporaryFile("w", dir=path.parent, delete=False, suffix=".tmp") as f:
        f.write(text)
    os.replace(f.name, path)
    print(f"rewrote {path.relative_to(ROOT)}", file=sys.stderr)


if __name__ == "__main__":
    sys.exit(main())
