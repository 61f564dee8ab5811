"""The README's "Use it on your own robot" block runs as written: in an empty folder outside
the repository, with ``ARMDYN`` naming the clone, in a scratch virtual environment (so that its
``pip install`` does not touch this Python's packages; the venv sees them, so nothing is
downloaded but pip's build backend). Then the crate it built has the Jaco2's functions.

Needs cargo; the crate's build folder is ``target/from-scratch`` of this repository, shared
with ``test_from_scratch.py``."""

import os
import re
import shutil
import subprocess
import sys
import venv
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]

pytestmark = pytest.mark.skipif(shutil.which("cargo") is None, reason="needs cargo")


def _block():
    text = (ROOT / "README.md").read_text()
    m = re.search(r"<!-- own robot[^>]*-->\s*```sh\n(.*?)```", text, re.S)
    assert m, "README.md has no own-robot block"
    return m.group(1)


def test_the_readme_flow_is_at_most_ten_lines():
    assert len(_block().strip().splitlines()) <= 10


def test_the_readme_own_robot_block_runs_as_written(tmp_path):
    env_dir = tmp_path / "venv"
    venv.EnvBuilder(system_site_packages=True, with_pip=True).create(env_dir)
    work = tmp_path / "home"
    work.mkdir()
    env = dict(os.environ)
    env.pop("PYTHONPATH", None)
    env["PATH"] = f"{env_dir / 'bin'}{os.pathsep}{env['PATH']}"
    env["VIRTUAL_ENV"] = str(env_dir)
    env["ARMDYN"] = str(ROOT)
    env["CARGO_TARGET_DIR"] = str(ROOT / "target" / "from-scratch")
    script = "set -euo pipefail\n" + _block()
    r = subprocess.run(["bash", "-c", script], cwd=work, env=env, capture_output=True,
                       text=True, timeout=1800)
    assert r.returncode == 0, f"{r.stdout}\n{r.stderr}"
    crate = work / "my-arm"
    assert sorted(p.name for p in (crate / "models").iterdir()) == [
        "jaco2.json", "jaco2.urdf", "jaco2_parametric.json"]
    # The graphs are the example's, byte for byte (same description, same generator).
    for name in ("jaco2.json", "jaco2_parametric.json"):
        got = (crate / "models" / name).read_text()
        want = (ROOT / "examples/own-robot/models" / name).read_text()
        # The provenance names the description by its path from where the command ran.
        source = re.compile(r'"source": "[^"]*"')
        assert source.sub("", got) == source.sub("", want), name
    assert (env_dir / "bin" / "armdyn-codegen").exists()
    assert "armdyn-runtime" in (crate / "Cargo.toml").read_text()
