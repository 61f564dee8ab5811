"""The README's Python quick start runs as written (from the repository's root)."""

import os
import re

import numpy as np

from conftest import ROOT


def test_the_readme_quick_start_runs_as_written(monkeypatch):
    text = (ROOT / "README.md").read_text()
    m = re.search(r"<!-- python quick start[^>]*-->\s*```python\n(.*?)```", text, re.S)
    assert m, "README.md has no python quick start block"
    code = m.group(1)
    assert len(code.strip().splitlines()) == 5, code
    monkeypatch.chdir(ROOT)
    env = {}
    exec(compile(code, "README.md", "exec"), env)
    assert env["M"].shape == (1000, 7, 7) and env["b"].shape == (1000, 7)
    assert np.allclose(env["M"], np.swapaxes(env["M"], 1, 2))
    assert env["run"].metrics["robot"] == "scara"
    assert os.getcwd() == str(ROOT)
