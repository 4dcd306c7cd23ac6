"""A solve's paths in shards (``kinsyn.solve_shard``) merged (``kinsyn.merge_shards``): the
one-process answer, from Python, from the command line, and with the shards as tasks of a Dask
cluster of two processes (docs/scale.md, "A solve in shards")."""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import pytest

import kinsyn
from test_kinsyn import ROOT, cli, cli_error
from test_sweep import optional

CYCLIC5 = ROOT / "examples" / "systems" / "cyclic5.bertini"


def assert_same_solve(a: kinsyn.Solutions, b: kinsyn.Solutions) -> None:
    """Every count, the start tracked and every solution's coordinates, bit for bit."""
    for key in ("start", "complete", "paths", "nonsingular", "singular", "at_infinity", "failed",
                "certified"):
        assert getattr(a, key) == getattr(b, key), key
    assert np.array_equal(a.solutions, b.solutions)
    assert a.table.equals(b.table)


def test_shards_merge_to_the_one_process_solve(tmp_path):
    parts = [tmp_path / f"part{k}.json" for k in (1, 2, 3)]
    summaries = [kinsyn.solve_shard(CYCLIC5, k, 3, parts[k - 1], seed=3) for k in (1, 2, 3)]
    assert [s["shard"] for s in summaries] == [1, 2, 3]
    assert sum(s["tracked"] for s in summaries) == summaries[0]["paths"]
    merged = kinsyn.merge_shards(CYCLIC5, list(reversed(parts)), seed=3)
    one = kinsyn.solve_file(CYCLIC5, seed=3)
    assert_same_solve(merged, one)
    # Cyclic-5 has 70 isolated roots (Björck & Fröberg 1991).
    assert merged.nonsingular == 70
    # The command line merges the Python's shard files to the same report.
    done = cli("solve", str(CYCLIC5), "--seed", "3", "--json", "--merge", *map(str, parts))
    assert done.returncode == 0, done.stderr


def test_shards_of_another_solve_are_refused_as_the_command_refuses_them(tmp_path):
    parts = [tmp_path / f"part{k}.json" for k in (1, 2)]
    for k in (1, 2):
        kinsyn.solve_shard(CYCLIC5, k, 2, parts[k - 1], seed=3)
    with pytest.raises(kinsyn.InputError) as e:
        kinsyn.merge_shards(CYCLIC5, parts, seed=4)
    assert str(e.value) == cli_error(
        "solve", str(CYCLIC5), "--seed", "4", "--merge", *map(str, parts)
    )
    with pytest.raises(kinsyn.InputError, match="missing shard 2/2"):
        kinsyn.merge_shards(CYCLIC5, parts[:1], seed=3)
    with pytest.raises(kinsyn.InputError, match="1-based"):
        kinsyn.solve_shard(CYCLIC5, 0, 2, tmp_path / "x.json")
    with pytest.raises(kinsyn.InputError, match="exists"):
        kinsyn.solve_shard(CYCLIC5, 1, 2, parts[0], seed=3)


def test_three_shards_on_a_dask_cluster_merge_to_the_one_process_solve(tmp_path):
    optional("dask", "the Dask recipe's test")
    distributed = optional("distributed", "the Dask recipe's test")
    parts = [tmp_path / f"part{k}.json" for k in (1, 2, 3)]
    with distributed.LocalCluster(
        n_workers=2, processes=True, threads_per_worker=1, dashboard_address=None
    ) as cluster, distributed.Client(cluster) as client:
        futures = client.map(
            kinsyn.solve_shard, [CYCLIC5] * 3, [1, 2, 3], [3] * 3, parts, seed=5, threads=1
        )
        summaries = client.gather(futures)
        workers = {r["pid"] for r in client.run(lambda: {"pid": os.getpid()}).values()}
    assert len(workers) == 2 and os.getpid() not in workers
    assert [s["shard"] for s in summaries] == [1, 2, 3]
    assert all(Path(p).exists() for p in parts)
    merged = kinsyn.merge_shards(CYCLIC5, parts, seed=5)
    assert_same_solve(merged, kinsyn.solve_file(CYCLIC5, seed=5))
