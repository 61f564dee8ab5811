import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "codegen"))


_CACHE = {}


def generated(path, parametric=False):
    """{function name: Generated} of one description, generated once per test session."""
    from scara_codegen import loader, model

    key = (str(path), parametric)
    if key not in _CACHE:
        robot = loader.load(path)
        _CACHE[key] = {f.name: f for f in model.generate(robot, parametric=parametric)}
    return _CACHE[key]
