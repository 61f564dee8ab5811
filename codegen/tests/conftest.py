import os
import json
import sys
from pathlib import Path
from types import SimpleNamespace

from hypothesis import settings

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "codegen"))

# Property tests (test_description_properties.py). "ci", the default: derandomized (the same
# examples on every run), no example database, no deadline (a slow machine is not a failure).
# HYPOTHESIS_PROFILE=explore: fresh random examples, ten times as many, to look for new bugs.
settings.register_profile("ci", derandomize=True, database=None, deadline=None, print_blob=True)
settings.register_profile("explore", deadline=None, print_blob=True)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci"))
EXAMPLES_SCALE = 10 if os.environ.get("HYPOTHESIS_PROFILE") == "explore" else 1


def pytest_configure(config):
    config.addinivalue_line(
        "markers", "slow: takes tens of seconds (installs the generator into a scratch venv); "
        "deselect with -m 'not slow'",
    )


_CACHE = {}


def generated(path, parametric=False):
    """{function name: graph} of one description: the committed graphs of
    ``generated/models/<name>.json`` (``<name>_parametric.json``), each with ``code``,
    ``result``, ``inputs`` and ``counts`` as the generator made them.

    The tests check these rather than generating every robot again (minutes for the Panda):
    CI's drift check regenerates every robot and fails unless the result is byte-identical to
    the committed graphs, so what is checked here is what the generator writes.
    """
    from armdyn_codegen import loader

    key = (str(path), parametric)
    if key not in _CACHE:
        name = loader.load(path).name
        doc = json.loads((ROOT / "generated" / "models" /
                          f"{name}{'_parametric' if parametric else ''}.json").read_text())
        _CACHE[key] = {
            f["name"]: SimpleNamespace(name=f["name"], code=f["instructions"], result=f["result"],
                                       inputs=f["inputs"], counts=f["counts"])
            for f in doc["functions"]
        }
    return _CACHE[key]
