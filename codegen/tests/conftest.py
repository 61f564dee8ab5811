import os
import sys
from pathlib import Path

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


_CACHE = {}


def generated(path, parametric=False):
    """{function name: Generated} of one description, generated once per test session."""
    from scara_codegen import description, model

    key = (str(path), parametric)
    if key not in _CACHE:
        robot = description.load(path)
        _CACHE[key] = {f.name: f for f in model.generate(robot, parametric=parametric)}
    return _CACHE[key]
