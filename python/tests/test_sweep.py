"""Sweeps from Python: trial for trial the same in this process, through a process pool and
through a Dask cluster of two worker processes, and the same as ``armdyn sweep``."""

import csv
import json
import math
from concurrent.futures import ProcessPoolExecutor

import numpy as np
import pytest

import armdyn
from conftest import ROOT, cli, require

SCENARIO = ROOT / "scenarios/fault-sweep.toml"
SAMPLES = 6


def same(a, b):
    assert list(a) == list(b)
    for k in a:
        x, y = a[k], b[k]
        if isinstance(x, np.ndarray) and x.dtype.kind == "f":
            assert np.array_equal(x, y, equal_nan=True), k
        else:
            assert list(x) == list(y), k


@pytest.fixture(scope="module")
def here():
    return armdyn.sweep(SCENARIO, samples=SAMPLES, seed=4, as_dataframe=False)


def test_in_process_equals_the_command_line(here, tmp_path):
    cli("sweep", SCENARIO, "--samples", SAMPLES, "--seed", 4, "--out", tmp_path)
    summary = json.loads((tmp_path / "summary.json").read_text())
    assert here.summary == summary
    with open(tmp_path / "trials.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == SAMPLES
    for i, r in enumerate(rows):
        for k, v in r.items():
            got = here.trials[k][i]
            if got is None:  # no error message
                assert v == "", (k, i)
            elif isinstance(got, str):
                assert got == v, (k, i)
            elif v == "":
                assert math.isnan(got), (k, i)
            else:
                assert float(got) == float(v), (k, i)


def test_a_process_pool_in_chunks_gives_the_same_trials(here):
    with ProcessPoolExecutor(max_workers=2) as pool:
        there = armdyn.sweep(SCENARIO, samples=SAMPLES, seed=4, executor=pool, chunk_size=4, as_dataframe=False)
    assert there.chunks == 2
    same(here.trials, there.trials)
    assert here.summary == there.summary


def test_a_dask_cluster_of_two_workers_gives_the_same_trials(here):
    distributed = require("distributed")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        with distributed.Client(cluster) as client:
            there = armdyn.sweep(
                SCENARIO, samples=SAMPLES, seed=4, executor=client.get_executor(), chunk_size=1, as_dataframe=False
            )
    assert there.chunks == SAMPLES
    same(here.trials, there.trials)
    assert here.summary == there.summary


def test_a_dataframe_when_pandas_is_installed(here):
    pd = require("pandas")
    df = armdyn.sweep(SCENARIO, samples=2, seed=4).trials
    assert isinstance(df, pd.DataFrame) and len(df) == 2
    assert list(df["trial"]) == [0, 1]


def test_bad_sweep_arguments():
    with pytest.raises(ValueError, match="samples"):
        armdyn.sweep(SCENARIO, samples=0)
    with pytest.raises(ValueError, match="has no \\[sweep\\] table"):
        armdyn.sweep(ROOT / "scenarios/thesis-hybrid.toml", samples=2)
