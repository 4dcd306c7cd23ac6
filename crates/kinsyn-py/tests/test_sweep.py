"""kinsyn.sweep against the kinsyn command line (an independent run of `kinsyn sweep` by the
binary named by $KINSYN_BIN, or `cargo run`): the files of a Python run are the command's
(designs.jsonl and sweep.json byte for byte; designs.parquet, which Python encodes with pyarrow
and the command with the Parquet crate, with the same schema, key-value metadata, row groups
and values); three shards run on a Dask cluster of two worker processes and merged are one
run's files likewise; the Parquet and JSON-lines files read back give equal frames with the
command's design count; bad input raises InputError with the command's one-line message.

Dask (dask, distributed) is required in CI (`CI` set) and skipped elsewhere when missing; the
Parquet reading needs pyarrow likewise.
"""

from __future__ import annotations

import json
import os
import pickle
from pathlib import Path

import pytest

import kinsyn
import kinsyn.sweep as ks

from test_kinsyn import cli, cli_error

# Three chains, one actuated joint per leg: 3 × 6 designs of 3 legs, 8 lock subsets each.
CHAINS = ["T1-001", "T1-002", "T4-034"]
SMALL = dict(chains=CHAINS, actuated=(1,))
SMALL_ARGS = ["--chains", ",".join(CHAINS), "--actuated", "1"]
FILES = ["designs.jsonl", "designs.parquet", "sweep.json"]


def optional(module: str, why: str):
    """`module` imported; a failure in CI, a skip with the reason elsewhere."""
    try:
        return __import__(module)
    except ImportError:
        if os.environ.get("CI"):
            pytest.fail(f"CI is set but {module} does not import: pip install {module} ({why})")
        pytest.skip(f"{module} is not installed: {why} is skipped")


def assert_same_table(a: Path, b: Path) -> None:
    """The two designs.parquet files hold the same table: schema (names, types, nullability),
    key-value metadata, row groups and values, read by pyarrow."""
    import pyarrow.parquet as pq

    fa, fb = pq.ParquetFile(a), pq.ParquetFile(b)
    assert fa.metadata.num_row_groups == fb.metadata.num_row_groups
    assert [fa.metadata.row_group(i).num_rows for i in range(fa.metadata.num_row_groups)] == [
        fb.metadata.row_group(i).num_rows for i in range(fb.metadata.num_row_groups)
    ]
    ta, tb = fa.read(), fb.read()
    kinsyn_keys = lambda t: {k: v for k, v in t.schema.metadata.items() if k.startswith(b"kinsyn.")}
    assert kinsyn_keys(ta) == kinsyn_keys(tb) and len(kinsyn_keys(ta)) == 6
    assert ta.schema.remove_metadata().equals(tb.schema.remove_metadata())
    assert ta.equals(tb)


def assert_same_files(a: Path, b: Path) -> None:
    for name in FILES:
        if name.endswith(".parquet"):
            assert_same_table(a / name, b / name)
        else:
            assert (a / name).read_bytes() == (b / name).read_bytes(), name
    assert not (a / "checkpoint.jsonl").exists()


def cli_sweep(out: Path, *args: str) -> dict:
    done = cli("sweep", "--out", str(out), *args, "--json")
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


@pytest.fixture(scope="module")
def cli_run(tmp_path_factory) -> tuple[Path, dict]:
    """The command's run of the small sweep: its directory and its --json summary."""
    d = tmp_path_factory.mktemp("cli") / "whole"
    return d, cli_sweep(d, *SMALL_ARGS)


def test_a_python_run_writes_the_command_s_files(tmp_path, cli_run):
    cli_dir, cli_summary = cli_run
    got = ks.run(None, tmp_path / "py", threads=2, **SMALL)
    assert got.complete and not got.already_complete and got.resumed == 0
    assert got.evaluated == cli_summary["evaluated"] == cli_summary["manifest"]["designs"] == 18
    assert got.lock_subsets == 18 * 2**3 - 8 * got.errors
    assert got.manifest == cli_summary["manifest"]
    assert_same_files(tmp_path / "py", cli_dir)
    # Run again: already complete, nothing rewritten.
    again = ks.run(None, tmp_path / "py", **SMALL)
    assert again.already_complete and again.evaluated == 0
    assert_same_files(tmp_path / "py", cli_dir)


def test_an_interrupted_python_run_resumes_to_the_same_files(tmp_path, cli_run):
    cut = tmp_path / "cut"
    first = ks.run(None, cut, stop_after=5, threads=1, **SMALL)
    assert not first.complete and first.evaluated == 5
    assert not (cut / "designs.jsonl").exists()
    second = ks.run(None, cut, **SMALL)
    assert second.complete and second.resumed == 5 and second.evaluated == 13
    assert_same_files(cut, cli_run[0])


def test_partitions_are_the_command_s_shards(tmp_path, cli_run):
    parts = ks.partitions(3, chains=["t4-034", "T1-002", "T1-001"], actuated=[1])
    assert [p.shard for p in parts] == ["1/3", "2/3", "3/3"]
    # Design i is in shard (i mod 3) + 1: 18 designs, 6 per shard.
    assert [p.designs for p in parts] == [6, 6, 6]
    assert all(p.sweep_designs == 18 for p in parts)
    assert parts[0].chains == tuple(CHAINS)  # the catalogue's spelling and order
    assert parts[0].seed == 2026 and parts[0].legs == 3 and parts[0].actuated == (1,)
    assert pickle.loads(pickle.dumps(parts)) == parts
    # Shard 2/3 by the Python method and by the command: the same files.
    parts[1].run(tmp_path / "py2")
    cli_sweep(tmp_path / "cli2", *SMALL_ARGS, "--shard", "2/3")
    assert_same_files(tmp_path / "py2", tmp_path / "cli2")
    assert [len(ks.partitions(n, **SMALL)) for n in (1, 7)] == [1, 7]
    assert sum(p.designs for p in ks.partitions(7, **SMALL)) == 18


def test_three_shards_on_a_dask_cluster_merge_to_one_run(tmp_path, cli_run):
    optional("dask", "the Dask recipe's test")
    distributed = optional("distributed", "the Dask recipe's test")
    parts = ks.partitions(3, **SMALL)
    dirs = [tmp_path / f"shard{p.index}" for p in parts]
    with distributed.LocalCluster(
        n_workers=2, processes=True, threads_per_worker=1, dashboard_address=None
    ) as cluster, distributed.Client(cluster) as client:
        results = client.gather(client.map(ks.run, parts, dirs, threads=1))
        workers = {r["pid"] for r in client.run(lambda: {"pid": os.getpid()}).values()}
    assert len(workers) == 2 and os.getpid() not in workers
    assert [r.manifest["shard"] for r in results] == [
        {"index": k, "count": 3} for k in (1, 2, 3)
    ]
    assert all(r.complete for r in results)
    assert sum(r.evaluated for r in results) == 18
    merged = ks.merge(list(reversed(dirs)), tmp_path / "merged")
    assert merged["designs"] == 18 and merged["shard"] is None and merged["complete"]
    assert_same_files(tmp_path / "merged", cli_run[0])


def test_parquet_and_jsonl_read_to_the_same_frame(cli_run):
    optional("pyarrow", "reading designs.parquet")
    cli_dir, cli_summary = cli_run
    from_parquet = ks.read(cli_dir)
    from_jsonl = ks.read(cli_dir, source="jsonl")
    assert len(from_parquet) == len(from_jsonl) == cli_summary["manifest"]["designs"] == 18
    assert list(from_parquet.columns) == list(from_jsonl.columns) == ks.COLUMNS
    assert (from_parquet.dtypes == from_jsonl.dtypes).all()
    assert from_parquet.to_dict("records") == from_jsonl.to_dict("records")
    assert from_parquet.equals(ks.read(cli_dir / "designs.parquet"))
    assert from_parquet.attrs["manifest"] == cli_summary["manifest"]
    # The rows are the JSON lines, in design order.
    lines = [json.loads(l) for l in (cli_dir / "designs.jsonl").read_text().splitlines()]
    assert list(from_parquet["design"]) == list(range(18))
    assert list(from_parquet["chain"]) == [l["chain"] for l in lines]
    assert from_parquet["groups"].tolist() == [l["groups"] for l in lines]
    # T4-034 is the UPS leg: with its 3 sliders actuated the 3-UPS has 6 dof (paper 000 §5.1).
    ups = from_parquet[
        (from_parquet.chain == "T4-034") & from_parquet.actuated.map(lambda a: list(a) == [3])
    ]
    assert list(ups["dof"]) == [6]


def test_bad_input_raises_the_command_s_message(tmp_path, cli_run):
    out = str(tmp_path / "never")
    cases = [
        (lambda: ks.partitions(0), ["sweep", "--out", out, "--shard", "1/0"]),
        (lambda: ks.partitions(-2), ["sweep", "--out", out, "--shard", "1/-2"]),
        (
            lambda: ks.partitions(2, chains=["T1-001", "T9-999"]),
            ["sweep", "--out", out, "--chains", "T1-001,T9-999"],
        ),
        (
            lambda: ks.run(None, out, chains=["T9-999"]),
            ["sweep", "--out", out, "--chains", "T9-999"],
        ),
        (lambda: ks.partitions(2, legs=7), ["sweep", "--out", out, "--legs", "7"]),
        (lambda: ks.partitions(2, family="QQQ"), ["sweep", "--out", out, "--family", "QQQ"]),
        (lambda: ks.run(None, out, threads=0, **SMALL), ["sweep", "--out", out, "--threads", "0"]),
    ]
    for call, args in cases:
        with pytest.raises(kinsyn.InputError) as e:
            call()
        assert str(e.value) == cli_error(*args)
    assert not Path(out).exists()
    # Merging an incomplete shard: shard 1/2 stopped after 2 rows, shard 2/2 complete.
    parts = ks.partitions(2, **SMALL)
    a, b = tmp_path / "a", tmp_path / "b"
    parts[0].run(a, stop_after=2)
    parts[1].run(b)
    with pytest.raises(kinsyn.InputError) as e:
        ks.merge([a, b], tmp_path / "m")
    assert str(e.value) == cli_error("sweep", "merge", str(a), str(b), "--out", str(tmp_path / "m"))
    assert "incomplete" in str(e.value)
    # A directory holding another sweep.
    with pytest.raises(kinsyn.InputError) as e:
        ks.run(None, b, **SMALL)
    assert str(e.value) == cli_error("sweep", "--out", str(b), *SMALL_ARGS)
    with pytest.raises(kinsyn.InputError, match="not a complete sweep directory"):
        ks.read(a)
    with pytest.raises(TypeError):
        ks.run(parts[0], tmp_path / "c", legs=4)


def test_force_replaces_what_the_command_s_force_replaces(tmp_path, cli_run):
    """merge into an OUT that holds a sweep's files and run into a directory holding another
    sweep are refused with the command's message; force=True (--force) replaces them with the
    files a fresh run writes, and never discards the same sweep's progress."""
    parts = ks.partitions(2, **SMALL)
    dirs = [tmp_path / f"shard{p.index}" for p in parts]
    for p, d in zip(parts, dirs):
        p.run(d)
    out = tmp_path / "merged"
    ks.merge(dirs, out)
    with pytest.raises(kinsyn.InputError) as e:
        ks.merge(dirs, out)
    assert str(e.value) == cli_error("sweep", "merge", *map(str, dirs), "--out", str(out))
    assert "--force" in str(e.value)
    (out / "designs.jsonl").write_text("old\n")
    ks.merge(dirs, out, force=True)
    assert_same_files(out, cli_run[0])
    # Only the folder named is created.
    with pytest.raises(kinsyn.InputError, match="does not exist"):
        ks.merge(dirs, tmp_path / "missing" / "out")
    assert not (tmp_path / "missing").exists()
    # The whole sweep into a shard's directory: another sweep, replaced only with force.
    with pytest.raises(kinsyn.InputError, match="holds another sweep"):
        ks.run(None, dirs[0], **SMALL)
    assert ks.run(None, dirs[0], force=True, **SMALL).complete
    assert_same_files(dirs[0], cli_run[0])
    # Its own interrupted run: resumed with force as without it.
    cut = tmp_path / "cut"
    ks.run(None, cut, stop_after=4, threads=1, **SMALL)
    resumed = ks.run(None, cut, force=True, **SMALL)
    assert resumed.complete and resumed.resumed == 4
    assert_same_files(cut, cli_run[0])


def test_read_checks_rows_and_files_as_the_report_does(tmp_path, cli_run):
    """An edited but well-formed row, in the JSON lines or in the Parquet table, and a named
    pipe are refused by read with the message `kinsyn sweep report` gives (never read, never
    blocking); a row that checks out reads as before."""
    import shutil

    cli_dir, _ = cli_run
    edited = tmp_path / "edited"
    shutil.copytree(cli_dir, edited)
    lines = (edited / "designs.jsonl").read_text().splitlines()
    row = json.loads(lines[1])
    row["dof"] = 99
    lines[1] = json.dumps(row)
    (edited / "designs.jsonl").write_text("\n".join(lines) + "\n")
    with pytest.raises(kinsyn.InputError) as e:
        ks.read(edited, source="jsonl")
    assert str(e.value) == cli_error("sweep", "report", str(edited), "--out", str(tmp_path / "r"))
    assert "designs.jsonl line 2: design 1: dof: 99 is more than 6" in str(e.value)
    if ks._has_pyarrow():
        import pyarrow as pa
        import pyarrow.parquet as pq

        table = pq.read_table(edited / "designs.parquet")
        dof = table.column("dof").to_pylist()
        dof[1] = 99
        index = table.schema.get_field_index("dof")
        table = table.set_column(index, table.schema.field(index), pa.array(dof, pa.uint32()))
        pq.write_table(table, edited / "designs.parquet")
        with pytest.raises(kinsyn.InputError, match="designs.parquet line 2: design 1: dof: 99"):
            ks.read(edited)
    fifo = tmp_path / "pipe" / "designs.jsonl"
    fifo.parent.mkdir()
    os.mkfifo(fifo)
    with pytest.raises(kinsyn.InputError, match="not a regular file"):
        ks.read(fifo)


def test_without_pyarrow_run_and_merge_refuse_before_any_work(tmp_path, monkeypatch):
    """designs.parquet is written with pyarrow: without it, run and merge raise InputError
    naming it and leave no file behind (no design evaluated, no directory created)."""
    monkeypatch.setattr(ks, "_has_pyarrow", lambda: False)
    with pytest.raises(kinsyn.InputError, match="pip install pyarrow"):
        ks.run(None, tmp_path / "run", **SMALL)
    assert not (tmp_path / "run").exists()
    with pytest.raises(kinsyn.InputError, match="pip install pyarrow"):
        ks.merge([tmp_path / "a", tmp_path / "b"], tmp_path / "merged")
    assert not (tmp_path / "merged").exists()

