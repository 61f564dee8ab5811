"""Shared paths and the optional references: Pinocchio and Dask are required under CI."""

import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


def require(module):
    """``module`` imported, or the test skipped (a failure under CI, where it must exist)."""
    try:
        return __import__(module)
    except ImportError:
        if os.environ.get("CI"):
            raise
        pytest.skip(f"{module} is not installed")


def cli(*args, cwd=ROOT):
    """Runs the command line ``armdyn ARGS`` (release build) and returns its output."""
    out = subprocess.run(
        ["cargo", "run", "--release", "--quiet", "--bin", "armdyn", "--", *map(str, args)],
        cwd=cwd,
        capture_output=True,
        text=True,
    )
    assert out.returncode == 0, out.stderr
    return out.stdout
