"""The catalogue-wide multioperation sweep (``kinsyn sweep``, docs/sweep.md) from Python: every
design (a verified catalogue chain as every leg of a symmetric manipulator, the same joints of
each leg actuated) with the displacement groups and non-group patterns its lock subsets reach,
written as files in a directory (``designs.jsonl``, ``designs.parquet``, ``sweep.json``), the
command's files (the JSON files byte for byte, the Parquet table encoded by pyarrow with the
command's columns, types and metadata).

- :func:`partitions`: the ``n`` shards of a sweep, as picklable :class:`Partition` values;
- :func:`run`: one shard (or the whole sweep) into a directory, resumable like the command
  (``kinsyn sweep --out DIR [--shard K/N]``);
- :func:`merge`: complete shard directories into the files of one run (``kinsyn sweep merge``);
- :func:`read`: a sweep's rows as a DataFrame (from ``designs.parquet`` with pyarrow, else from
  ``designs.jsonl``; the same frame either way).

On a Dask cluster (docs/scale.md), each shard is one task; the shard directories must be on a
file system the client can read for the merge::

    from pathlib import Path
    from dask.distributed import Client
    import kinsyn.sweep as ks

    client = Client("tcp://scheduler:8786")          # or Client(LocalCluster(...))
    out = Path("/shared/sweep-4legs")
    out.mkdir(parents=True, exist_ok=True)           # kinsyn creates out/shardK, not out
    parts = ks.partitions(64, legs=4, actuated=(1,))
    futures = client.map(ks.run, parts, [out / f"shard{p.index}" for p in parts], threads=1)
    client.gather(futures)                           # a lost worker: resubmit, it resumes
    ks.merge([out / f"shard{p.index}" for p in parts], out / "all")
    df = ks.read(out / "all")

or with ``dask.bag``::

    import dask.bag as db
    bag = db.from_sequence(parts, npartitions=len(parts))
    bag.map(lambda p: ks.run(p, out / f"shard{p.index}", threads=1)).compute()

Bad input raises :class:`kinsyn.InputError` with the command's one-line message.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from os import PathLike, fspath
from pathlib import Path
from typing import Any, Dict, List, Optional, Sequence, Tuple, Union

import pandas as pd

from . import _native
from ._native import InputError

__all__ = ["COLUMNS", "Partition", "SweepResult", "merge", "partitions", "read", "run"]

PathType = Union[str, "PathLike[str]"]

#: The columns of :func:`read` (docs/sweep.md, "Columns").
COLUMNS = [
    "design",
    "chain",
    "notation",
    "family",
    "legs",
    "actuated",
    "inputs",
    "dof",
    "subgroups",
    "group_kinds",
    "kinds",
    "groups",
    "non_groups",
    "unsampled",
    "singular",
    "singular_lock_sets",
    "error",
]


@dataclass(frozen=True)
class Partition:
    """Shard ``index``/``count`` (``kinsyn sweep --shard K/N``, K 1-based) of the sweep of
    ``legs`` legs with ``actuated`` actuated joints per leg over ``chains`` (catalogue ids, in
    catalogue order; ``None``: every verified chain) and ``family``, motions sampled with
    ``seed``. ``designs`` is the shard's number of designs, ``sweep_designs`` the whole sweep's.
    Plain fields: it pickles, for a task of a cluster."""

    index: int
    count: int
    legs: int
    actuated: Tuple[int, ...]
    seed: int
    chains: Optional[Tuple[str, ...]]
    family: Optional[str]
    designs: int
    sweep_designs: int

    @property
    def shard(self) -> str:
        """``"K/N"``, as ``--shard`` takes it."""
        return f"{self.index}/{self.count}"

    def run(
        self,
        out: PathType,
        *,
        threads: Optional[int] = None,
        stop_after: Optional[int] = None,
        force: bool = False,
    ) -> "SweepResult":
        """Runs (or resumes) this shard into the directory ``out``: :func:`run`."""
        return run(self, out, threads=threads, stop_after=stop_after, force=force)


@dataclass(frozen=True)
class SweepResult:
    """What one run did (``kinsyn sweep --json``): the directory ``out`` and its ``manifest``
    (``sweep.json`` as a dict); ``resumed`` rows taken from an interrupted run's checkpoint,
    ``evaluated`` designs evaluated now, ``errors`` rows whose design could not be built or
    sampled, ``lock_subsets`` sampled now; ``seconds`` of evaluation, ``write_ms`` of writing,
    ``threads``; ``complete`` (every row written), ``already_complete`` (nothing was done);
    ``designs_per_second`` and ``subsets_per_core_second`` (``--bench``'s figures)."""

    out: str
    manifest: Dict[str, Any] = field(repr=False)
    resumed: int
    evaluated: int
    errors: int
    lock_subsets: int
    seconds: float
    write_ms: float
    threads: int
    complete: bool
    already_complete: bool
    designs_per_second: float
    subsets_per_core_second: float


def _selection(
    chains: Optional[Sequence[str]],
) -> Optional[List[str]]:
    if chains is None:
        return None
    if isinstance(chains, str):
        return [chains]
    return list(chains)


def _partition(m: Dict[str, Any]) -> Partition:
    settings, selection = m["settings"], m["selection"]
    chains = selection["chains"]
    return Partition(
        index=m["shard"]["index"],
        count=m["shard"]["count"],
        legs=settings["legs"],
        actuated=tuple(settings["actuated_per_leg"]),
        seed=settings["sampling"]["seed"],
        chains=None if chains is None else tuple(chains),
        family=selection["family"],
        designs=m["designs"],
        sweep_designs=m["sweep_designs"],
    )


def partitions(
    n: int,
    *,
    legs: int = 3,
    actuated: Sequence[int] = (1, 2),
    seed: Optional[int] = None,
    chains: Optional[Sequence[str]] = None,
    family: Optional[str] = None,
) -> List[Partition]:
    """The ``n`` shards ``1/n`` … ``n/n`` of the sweep of ``legs`` legs (3 to 6) with each
    count of ``actuated`` joints per leg, over the catalogue ids ``chains`` (any case and order;
    ``None``: every verified chain) and ``family`` (``PPPRRR``, ``PPRRRR``, ``PRRRRR`` or
    ``RRRRRR``), motions sampled with ``seed`` (``None``: the command's default, 2026). Design
    ``i`` (0-based, in sweep order) is in shard ``(i mod n) + 1``. The options are checked here
    as ``kinsyn sweep`` checks them."""
    text = _native.sweep_partitions_json(
        n, legs, list(actuated), seed, _selection(chains), family
    )
    return [_partition(m) for m in json.loads(text)]


def run(
    partition: Optional[Partition],
    out: PathType,
    *,
    threads: Optional[int] = None,
    legs: Optional[int] = None,
    actuated: Optional[Sequence[int]] = None,
    seed: Optional[int] = None,
    chains: Optional[Sequence[str]] = None,
    family: Optional[str] = None,
    stop_after: Optional[int] = None,
    force: bool = False,
) -> SweepResult:
    """Runs the shard ``partition`` of a sweep into the directory ``out`` (created if missing;
    its parent must exist),
    or with ``partition=None`` the whole sweep given by ``legs`` (default 3), ``actuated``
    (default ``(1, 2)``), ``seed``, ``chains`` and ``family`` as for :func:`partitions`
    (``kinsyn sweep --out OUT [--shard K/N] … --json``). ``threads``: worker threads (``None``:
    one per core). Resumable: a directory left by an interrupted run of the same sweep is
    finished, one already complete is left as it is (``already_complete``); one holding
    another sweep's files, or files of none, is refused unless ``force`` (``--force``), which
    starts this sweep afresh there. ``stop_after`` stops once that many rows are done, as an
    interruption would. The GIL is released while the designs are evaluated."""
    _require_pyarrow()
    selection = (legs, actuated, seed, chains, family)
    if partition is not None:
        if any(v is not None for v in selection):
            raise TypeError(
                "run(partition, out): the partition names the sweep; give legs, actuated, "
                "seed, chains or family only with partition=None"
            )
        legs, actuated, seed = partition.legs, partition.actuated, partition.seed
        chains, family = partition.chains, partition.family
        shard: Optional[str] = partition.shard
    else:
        shard = None
    r = json.loads(
        _native.sweep_json(
            fspath(out),
            3 if legs is None else legs,
            [1, 2] if actuated is None else list(actuated),
            seed,
            _selection(chains),
            family,
            shard,
            threads,
            stop_after,
            force,
        )
    )
    return SweepResult(
        out=r["out"],
        manifest=r["manifest"],
        resumed=r["resumed"],
        evaluated=r["evaluated"],
        errors=r["errors"],
        lock_subsets=r["lock_subsets"],
        seconds=r["seconds"],
        write_ms=r["write_ms"],
        threads=r["threads"],
        complete=r["complete"],
        already_complete=r["already_complete"],
        designs_per_second=r["designs_per_second"],
        subsets_per_core_second=r["subsets_per_core_second"],
    )


def merge(dirs: Sequence[PathType], out: PathType, *, force: bool = False) -> Dict[str, Any]:
    """Merges the complete shard directories ``dirs`` of one sweep (shards 1/N … N/N, each
    once, any order) into ``out`` (created if missing; its parent must exist): the files one
    run of the whole sweep writes (``kinsyn sweep merge DIRS… --out OUT``): ``designs.jsonl``
    and ``sweep.json`` byte for byte, ``designs.parquet`` the same table encoded by pyarrow.
    A sweep's file already in ``out`` is refused unless ``force`` (``--force``), which
    replaces it. Returns the merged manifest (``sweep.json``)."""
    _require_pyarrow()
    return json.loads(
        _native.sweep_merge_json([fspath(d) for d in dirs], fspath(out), force)
    )


# designs.parquet's columns and Arrow types, as the command writes them (docs/sweep.md).
_TABLE_COLUMNS = [
    ("design", "uint32"),
    ("chain", "string"),
    ("notation", "string"),
    ("family", "string"),
    ("legs", "uint32"),
    ("actuated", "list<uint32>"),
    ("inputs", "uint32"),
    ("dof", "uint32"),
    ("subgroups", "uint32"),
    ("kinds", "uint32"),
    ("group_kinds", "list<string>"),
    ("groups", "string"),
    ("non_groups", "string"),
    ("unsampled", "uint32"),
    ("singular", "uint32"),
    ("singular_lock_sets", "list<string>"),
    ("error", "string"),
]

# Rows per row group, as the command writes them: a sweep of up to this many designs is one group.
_ROW_GROUP = 16_384


def _parquet_bytes(rows_jsonl: str, metadata: Sequence[Tuple[str, str]]) -> bytes:
    """The bytes of ``designs.parquet`` for the rows ``rows_jsonl`` (JSON lines sorted by
    design, ``groups`` and ``non_groups`` already compact JSON text) with the key-value
    ``metadata`` (the manifest's fields): the command's columns, types, snappy pages and row
    groups, encoded by pyarrow. The native sweep and merge call it when they write the table
    (:func:`run` and :func:`merge` check first that pyarrow imports)."""
    import pyarrow as pa
    import pyarrow.parquet as pq

    types = {
        "uint32": pa.uint32(),
        "string": pa.string(),
        "list<uint32>": pa.list_(pa.uint32()),
        "list<string>": pa.list_(pa.string()),
    }
    schema = pa.schema(
        [pa.field(name, types[t], nullable=(name == "error")) for name, t in _TABLE_COLUMNS],
        metadata=dict(metadata),
    )
    rows = [json.loads(line) for line in rows_jsonl.splitlines() if line]
    columns = {name: [r.get(name) for r in rows] for name, _ in _TABLE_COLUMNS}
    table = pa.Table.from_pydict(columns, schema=schema)
    sink = pa.BufferOutputStream()
    pq.write_table(table, sink, compression="snappy", row_group_size=_ROW_GROUP)
    return sink.getvalue().to_pybytes()


def _require_pyarrow() -> None:
    """Refuses a run or merge before any work when pyarrow, which writes ``designs.parquet``,
    does not import (rather than after every design is evaluated)."""
    if not _has_pyarrow():
        raise InputError("kinsyn.sweep writes designs.parquet with pyarrow: pip install pyarrow")


def _has_pyarrow() -> bool:
    try:
        import pyarrow.parquet  # noqa: F401
    except ImportError:
        return False
    return True


def _cells(row: Dict[str, Any]) -> Dict[str, Any]:
    """One row with the columns of :data:`COLUMNS`: ``groups`` and ``non_groups`` as lists of
    dicts (Parquet holds them as JSON text), ``actuated`` and ``group_kinds`` as lists, a
    missing ``error`` as ``None``."""
    cells = {c: row.get(c) for c in COLUMNS}
    for c in ("groups", "non_groups"):
        if isinstance(cells[c], str):
            cells[c] = json.loads(cells[c])
    for c in ("actuated", "group_kinds", "singular_lock_sets"):
        cells[c] = list(cells[c])
    return cells


_INTEGERS = ["design", "legs", "inputs", "dof", "subgroups", "kinds", "unsampled", "singular"]


def read(path: PathType, *, source: Optional[str] = None) -> pd.DataFrame:
    """A sweep's rows, one per design, columns :data:`COLUMNS` (docs/sweep.md): from a sweep
    directory (its ``designs.parquet`` when pyarrow is installed, else its ``designs.jsonl``;
    ``source="parquet"`` or ``"jsonl"`` chooses) or from one of those files. ``groups`` and
    ``non_groups`` are lists of dicts (``pattern``, ``parameters``, ``dof``, ``subsets``,
    ``lock_sets``); ``error`` is ``None`` for a design that was evaluated. Reading a directory
    puts its manifest in ``df.attrs["manifest"]``.

    The files are read as ``kinsyn sweep report`` reads them: regular files within the size
    limit of files of rows (docs/limits.md), every row a design of the folder's sweep (of the
    catalogue without ``sweep.json``) whose fields agree; anything else raises
    :class:`kinsyn.InputError` naming the file and line."""
    p = Path(fspath(path))
    if p.is_dir():
        if source not in (None, "parquet", "jsonl"):
            raise InputError(f"source={source!r}: give 'parquet' or 'jsonl'")
        if source is None:
            source = "parquet" if _has_pyarrow() and (p / "designs.parquet").is_file() else "jsonl"
        file = p / f"designs.{source}"
        if not file.is_file():
            raise InputError(
                f"{p}: no {file.name}: not a complete sweep directory (run its kinsyn sweep "
                "again to finish it)"
            )
    elif p.exists():
        if p.suffix not in (".parquet", ".jsonl"):
            raise InputError(f"{p}: not designs.parquet or designs.jsonl")
        file = p
    else:
        raise InputError(f"{p}: No such file or directory")
    if file.suffix == ".parquet":
        if not _has_pyarrow():
            raise InputError(f"{file}: reading Parquet needs pyarrow (pip install pyarrow)")
        import pyarrow.parquet as pq

        _native.sweep_check_table(fspath(file))
        table = [_cells(r) for r in pq.read_table(file).to_pylist()]
        lines = "\n".join(json.dumps(r) for r in table)
        read_back = json.loads(_native.sweep_table_rows_json(fspath(file), lines))
    else:
        read_back = json.loads(_native.sweep_rows_json(fspath(file)))
    df = pd.DataFrame([_cells(r) for r in read_back["rows"]], columns=COLUMNS)
    df[_INTEGERS] = df[_INTEGERS].astype("int64")
    df["error"] = df["error"].astype(object).where(df["error"].notna(), None)
    if p.is_dir() and read_back["manifest"] is not None:
        df.attrs["manifest"] = read_back["manifest"]
    return df
