"""Regenerating only what changed: a robot whose graphs record its description's hash and
the generator's is kept as it is (byte for byte); an edited description, a missing output,
a graph of another generator, or ``--all`` derives it again."""

import json
import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
GOOD = (ROOT / "robots" / "planar2.toml").read_text()


def _run(tmp_path, *extra):
    out = tmp_path / "out"
    env = dict(os.environ, PYTHONPATH=str(ROOT / "codegen"))
    proc = subprocess.run(
        [sys.executable, "-m", "armdyn_codegen", "--quiet", "--prune", "--out", str(out),
         "--urdf-out", str(tmp_path / "urdf"), "--c-out", str(tmp_path / "c"), *extra,
         str(tmp_path / "planar2.toml")],
        capture_output=True, text=True, env=env, cwd=tmp_path,
    )
    assert proc.returncode == 0, proc.stderr
    return proc.stdout


def _files(tmp_path):
    return {p.relative_to(tmp_path).as_posix(): p.read_bytes()
            for p in sorted(tmp_path.rglob("*")) if p.is_file() and p.suffix != ".toml"}


KEPT = "planar2.toml): unchanged (description and generator), kept"


def test_only_what_changed_is_derived_again(tmp_path):
    (tmp_path / "planar2.toml").write_text(GOOD)
    assert KEPT not in _run(tmp_path)
    first = _files(tmp_path)
    assert sorted(first) == ["c/planar2.c", "out/planar2.json", "out/planar2_parametric.json",
                             "urdf/planar2.urdf"]
    # Unchanged: kept, nothing pruned, every byte the same.
    assert KEPT in _run(tmp_path)
    assert _files(tmp_path) == first
    # --all derives it anyway, to the same bytes.
    assert KEPT not in _run(tmp_path, "--all")
    assert _files(tmp_path) == first
    # A missing output derives it again.
    (tmp_path / "urdf" / "planar2.urdf").unlink()
    assert KEPT not in _run(tmp_path)
    assert _files(tmp_path) == first
    # A graph of another generator derives it again.
    graph = tmp_path / "out" / "planar2.json"
    doc = json.loads(graph.read_text())
    assert len(doc["provenance"]["generator_sha256"]) == 64
    graph.write_text(graph.read_text().replace(doc["provenance"]["generator_sha256"], "0" * 64))
    assert KEPT not in _run(tmp_path)
    assert _files(tmp_path) == first
    # An edited link derives it again, with its new mass.
    (tmp_path / "planar2.toml").write_text(GOOD.replace("mass = 2.0", "mass = 2.5", 1))
    assert KEPT not in _run(tmp_path)
    assert _files(tmp_path)["out/planar2.json"] != first["out/planar2.json"]
