import json
import sys
from pathlib import Path
from types import SimpleNamespace

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "codegen"))


_CACHE = {}


def generated(path, parametric=False):
    """{function name: graph} of one description: the committed graphs of
    ``generated/models/<name>.json`` (``<name>_parametric.json``), each with ``code``,
    ``result``, ``inputs`` and ``counts`` as the generator made them.

    The tests check these rather than generating every robot again (minutes for the Panda):
    CI's drift check regenerates every robot and fails unless the result is byte-identical to
    the committed graphs, so what is checked here is what the generator writes.
    """
    from scara_codegen import loader

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
