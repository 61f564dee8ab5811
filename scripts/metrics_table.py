#!/usr/bin/env python3
"""Print a Markdown table of `metrics.json` files: one row per file, one column per `--col`.

    python3 scripts/metrics_table.py --col 'scenario=trial' \
        --col 'overshoot (%)=normal_force_overshoot_pct:.1f' out/a/metrics.json out/b/metrics.json

A column is `HEADER=KEY[|REDUCE][:FORMAT]`:
- `KEY` a dotted path into the JSON (`gains.kp`, `inverse_kinematics.failed_samples`; a
  number indexes an array: `max_abs_tau.0`), or `'TEXT'` for a fixed text;
- `REDUCE` one of `sum`, `max`, `min`, `len` for an array;
- a key a file lacks is shown as `-`;
- `FORMAT` a Python format spec (`.1f`, `.3g`, `.2e`) applied to each number; an array's
  numbers are joined by ", "; `null` is shown as `-`.

With `--label HEADER`, each file is `LABEL=FILE` and the table starts with a column of
the labels.

Used by the result blocks of `docs/` (see `scripts/results.py`).
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path


def lookup(doc, key: str):
    value = doc
    for part in key.split("."):
        if isinstance(value, list):
            value = value[int(part)]
        elif isinstance(value, dict):
            if part not in value:
                raise KeyError(key)
            value = value[part]
        else:
            raise KeyError(key)
    return value


def shown(value, spec: str) -> str:
    if value is None:
        return "-"
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, (int, float)):
        return format(value, spec) if spec else str(value)
    if isinstance(value, list):
        return ", ".join(shown(v, spec) for v in value)
    return str(value).replace("|", "\\|")


def cell(doc, column: str) -> str:
    key, _, spec = column.partition(":")
    if key.startswith("'") and key.endswith("'"):
        return key[1:-1]
    key, _, reduce = key.partition("|")
    try:
        value = lookup(doc, key)
    except (KeyError, IndexError):
        return "-"  # a key this run does not have
    if reduce:
        values = [v for v in value if v is not None]
        value = {"sum": sum, "max": max, "min": min, "len": len}[reduce](values)
    return shown(value, spec)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--col", action="append", required=True, help="HEADER=KEY[|REDUCE][:FORMAT]")
    parser.add_argument("--label", help="header of a first column of row labels, given as LABEL=FILE")
    parser.add_argument("files", nargs="+", help="metrics.json files (LABEL=FILE with --label)")
    args = parser.parse_args()
    columns = []
    for c in args.col:
        header, sep, key = c.partition("=")
        if not sep:
            print(f"error: --col {c!r} is not HEADER=KEY", file=sys.stderr)
            return 2
        columns.append((header, key))
    if args.label:
        columns.insert(0, (args.label, None))
    rows = []
    for arg in args.files:
        label, sep, name = arg.rpartition("=") if args.label else ("", "", arg)
        if args.label and not sep:
            print(f"error: {arg!r} is not LABEL=FILE (with --label)", file=sys.stderr)
            return 2
        f = Path(name)
        try:
            doc = json.loads(f.read_text())
            rows.append([label.replace("|", "\\|") if key is None else cell(doc, key) for _, key in columns])
        except (OSError, ValueError) as e:
            print(f"error: {f}: {e}", file=sys.stderr)
            return 1
    numeric = [all(r[i].replace(".", "").replace("-", "").replace("e", "").replace("+", "").isdigit() or r[i] == "-" for r in rows) for i in range(len(columns))]
    print("| " + " | ".join(h for h, _ in columns) + " |")
    print("| " + " | ".join("--:" if n else ":--" for n in numeric) + " |")
    for r in rows:
        print("| " + " | ".join(r) + " |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
