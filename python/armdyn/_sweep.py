"""``sweep``: a Monte Carlo sweep of a scenario's ``[sweep]`` table, in this process or
through any ``concurrent.futures.Executor`` (a process pool, Dask's ``client.get_executor()``,
Ray's), trial for trial the same whatever runs it."""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from typing import Any, Mapping, Optional, Union

from . import _native


def _run_chunk(job, samples, seed, start, stop):
    """Trials ``start..stop`` of a sweep (module level, so an executor can pickle it)."""
    return _native.sweep_chunk(job, samples, seed, start, stop)


@dataclass(frozen=True)
class SweepResult:
    """A sweep's per-trial table (a pandas ``DataFrame`` if pandas is installed, else a dict of
    numpy arrays and lists; the columns of ``trials.csv``, undefined metrics NaN) and its
    summary (``summary.json``: percentiles per metric, failures and their reasons)."""

    trials: Any
    summary: dict = field(repr=False)
    chunks: int = 1


def sweep(
    scenario: Union[str, "os.PathLike[str]", Mapping[str, Any]],
    samples: int,
    seed: int = 1,
    executor=None,
    *,
    chunk_size: Optional[int] = None,
    base_dir: Optional[Union[str, "os.PathLike[str]"]] = None,
    safety: Optional[bool] = None,
    controller_model: Optional[str] = None,
    as_dataframe: Optional[bool] = None,
) -> SweepResult:
    """Runs ``samples`` trials of ``scenario`` (a path or a dict with a ``[sweep]`` table) with
    draws seeded by ``seed``, as ``armdyn sweep`` does.

    With ``executor=None`` the trials run here, on every core. With any
    ``concurrent.futures.Executor`` they are split into chunks of ``chunk_size`` trials
    (default: ``samples`` split in 16, at least 1 each) submitted to it; each trial's draws
    come from its index, so the table is the same, trial for trial, whatever the executor
    and the chunking. ``as_dataframe``: ``None`` gives a DataFrame when pandas is installed.
    """
    if not isinstance(samples, int) or samples < 1:
        raise ValueError(f"samples: {samples!r} is not a whole number of at least 1")
    if not isinstance(seed, int) or seed < 0:
        raise ValueError(f"seed: {seed!r} is not a whole number of at least 0")
    if isinstance(scenario, Mapping) and not isinstance(scenario, dict):
        scenario = dict(scenario)
    job, _columns = _native.sweep_plan(
        scenario,
        base_dir=None if base_dir is None else os.fspath(base_dir),
        safety=safety,
        controller_model=controller_model,
    )
    if executor is None:
        rows = _run_chunk(job, samples, seed, 0, samples)
        chunks = 1
    else:
        if chunk_size is None:
            chunk_size = max(1, -(-samples // 16))
        if not isinstance(chunk_size, int) or chunk_size < 1:
            raise ValueError(f"chunk_size: {chunk_size!r} is not a whole number of at least 1")
        bounds = [(a, min(a + chunk_size, samples)) for a in range(0, samples, chunk_size)]
        futures = [executor.submit(_run_chunk, job, samples, seed, a, b) for a, b in bounds]
        rows = []
        for f in futures:
            rows.extend(f.result())
        chunks = len(bounds)
    table, summary = _native.sweep_table(job, samples, seed, [tuple(r) for r in rows])
    return SweepResult(trials=_table(table, as_dataframe), summary=summary, chunks=chunks)


def _table(columns: dict, as_dataframe: Optional[bool]):
    import numpy as np

    out = {}
    for k, v in columns.items():
        if k in ("status", "failures", "error"):
            out[k] = list(v)
        elif k in ("trial", "sensor_seed"):
            out[k] = np.asarray(v, dtype=np.uint64 if k == "sensor_seed" else np.int64)
        else:
            out[k] = np.asarray(v, dtype=np.float64)
    if as_dataframe is False:
        return out
    try:
        import pandas as pd
    except ImportError:
        if as_dataframe:
            raise
        return out
    return pd.DataFrame(out)
