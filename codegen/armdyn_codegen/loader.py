"""One entry point for every kind of description: ``robots/<name>.toml`` -> ``chain.Chain``.

A description whose ``convention`` is ``"urdf"`` takes its kinematics and inertias from a URDF
file (``urdf``); the others are DH tables (``description``). Both end as the same chain.
"""

from __future__ import annotations

import tomllib
from pathlib import Path

from . import urdf
from .chain import Chain, from_dh
from .description import DescriptionError, load as load_dh


def load(path: str | Path) -> Chain:
    """Parse and validate one description; raises DescriptionError listing every problem."""
    path = Path(path)
    try:
        doc = tomllib.loads(path.read_bytes().decode("utf-8-sig"))
    except (OSError, UnicodeDecodeError, tomllib.TOMLDecodeError, RecursionError, ValueError):
        doc = None  # the DH reader reports it, with its own message
    if isinstance(doc, dict) and doc.get("convention") == "urdf":
        return urdf.load(path)
    return from_dh(load_dh(path))


__all__ = ["load", "DescriptionError"]
