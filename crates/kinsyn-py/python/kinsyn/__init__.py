"""kinsyn: structural synthesis and kinematics of parallel manipulators, from Python.

The same computations and numbers as the ``kinsyn`` command line (each function names the
command it mirrors), as pandas DataFrames and numpy arrays:

- :func:`catalogue`, :func:`catalogue_patterns` and :func:`query`: the catalogue of 3T3R legs of
  paper 000 §2 and the motion patterns their joints give when locked;
- :class:`Manipulator`: a parallel manipulator from a description file or built from a leg
  chain; its Jacobians and singularities (:meth:`Manipulator.analyze`), its motion patterns
  per set of locked inputs (:meth:`Manipulator.modes`) and all its assemblies at given inputs
  (:meth:`Manipulator.assemblies`);
- :func:`solve` and :func:`solve_file`: every isolated solution of a polynomial system in
  Bertini's input format, by homotopy continuation, certified;
- :func:`components`: the irreducible components (assemblies, self-motions, operation modes)
  of a manipulator's constraint variety or of a polynomial system (paper 004);
- :mod:`kinsyn.configurable`: paper 003's planar 4-RRR with a configurable platform (inverse
  and forward position, velocities by screw theory);
- :mod:`kinsyn.sweep`: the catalogue-wide multioperation sweep as files in a directory (one
  run, or shards for a cluster such as Dask, merged), read back as a DataFrame.

Bad input raises :class:`InputError` (a :class:`KinsynError`) whose ``str()`` is the one-line
message the command prints after ``kinsyn: error:``.
"""

from __future__ import annotations

import html as _html
import json
import warnings
from dataclasses import dataclass, field
from os import PathLike
from pathlib import Path
from typing import Any, Dict, List, Mapping, Optional, Sequence, Union

import numpy as np
import pandas as pd

from . import _native
from ._native import InputError, KinsynError

__all__ = [
    "Analysis",
    "Assemblies",
    "InputError",
    "KinsynError",
    "KinsynWarning",
    "Manipulator",
    "Solutions",
    "View",
    "catalogue",
    "catalogue_patterns",
    "components",
    "configurable",
    "query",
    "merge_shards",
    "solve",
    "solve_file",
    "solve_shard",
    "sweep",
]


class KinsynWarning(UserWarning):
    """A leg warning (docs/mechanism-format.md, "Leg checks"), as the command prints it."""


Inputs = Union[str, Mapping[str, float], None]
Pose = Union[str, Sequence[float], None]
Locks = Union[str, Sequence[str], None]


def _inputs_text(inputs: Inputs) -> Optional[str]:
    """Input values as the command line takes them: ``"R1.1=10,P1.3=0.05"``."""
    if inputs is None or isinstance(inputs, str):
        return inputs
    return ",".join(f"{label}={float(value)!r}" for label, value in inputs.items())


def _pose_text(pose: Pose) -> Optional[str]:
    """A pose as the command line takes it: ``"x,y,z,rx,ry,rz"``."""
    if pose is None or isinstance(pose, str):
        return pose
    return ",".join(repr(float(v)) for v in pose)


def _locks_text(lock: Locks) -> Optional[str]:
    """Locked inputs as the command line takes them: ``"R1.1,R2.1"``."""
    if lock is None or isinstance(lock, str):
        return lock
    return ",".join(lock)


Study = Optional[Sequence[Union[str, Sequence[float]]]]


def _study_texts(study: Study) -> List[str]:
    """Study parameters as the command line takes them: one ``"x0:x1:x2:x3:y0:y1:y2:y3"`` per
    moving body."""
    if study is None:
        return []
    return [s if isinstance(s, str) else ":".join(repr(float(v)) for v in s) for s in study]


def _warn(report: Mapping[str, Any]) -> None:
    for w in report.get("warnings", []):
        warnings.warn(w, KinsynWarning, stacklevel=3)


def _complex(pairs: Sequence[Sequence[float]]) -> np.ndarray:
    """``[[re, im], ...]`` as a complex vector."""
    a = np.asarray(pairs, dtype=float).reshape(-1, 2)
    return a[:, 0] + 1j * a[:, 1]


# --- the catalogue --------------------------------------------------------------------------

_CATALOGUE_COLUMNS = [
    "id",
    "notation",
    "letters",
    "family",
    "word",
    "axes",
    "table",
    "row",
    "variant",
    "printed_in_row",
    "printed_in_appendix",
    "verified",
    "rank",
    "gap",
    "idle_joints",
    "patterns",
]


def catalogue() -> pd.DataFrame:
    """The committed catalogue of paper 000 §2, one row per entry (``kinsyn catalogue list``).

    Columns: ``id``, ``notation``, ``letters``, ``family``, ``word``, ``axes``; where the entry
    was first found in the Appendix (``table``, ``row``, ``variant``) and whether it is printed
    there (``printed_in_row``, ``printed_in_appendix``); its numerical verification:
    ``verified`` (the leg is 3T3R), ``rank``, ``gap``, ``idle_joints``; and ``patterns``, a dict
    from each motion pattern the leg gives with some joints locked to its minimal lock sets
    (joint positions in the word, ``"-"``: none). For filters on patterns use
    :func:`catalogue_patterns` (one row per entry, pattern and lock set).
    """
    entries = json.loads(_native.catalogue_json())
    rows = []
    for e in entries:
        v = e.get("verification") or {}
        p = e["provenance"]
        rows.append(
            {
                "id": e["id"],
                "notation": e["notation"],
                "letters": e["letters"],
                "family": e["family"],
                "word": e["word"],
                "axes": e["axes"],
                "table": p["table"],
                "row": p["row"],
                "variant": p["variant"],
                "printed_in_row": e["printed_in_row"],
                "printed_in_appendix": e["printed_in_appendix"],
                "verified": v.get("is_3t3r"),
                "rank": v.get("rank"),
                "gap": v.get("gap"),
                "idle_joints": v.get("idle_joints"),
                "patterns": v.get("patterns", {}),
            }
        )
    return pd.DataFrame(rows, columns=_CATALOGUE_COLUMNS)


def catalogue_patterns() -> pd.DataFrame:
    """The catalogue's patterns in long form: one row per entry, motion pattern and minimal
    lock set, with ``locks``, the number of joints locked (0 for the leg's own motion ``D``).

    Columns: ``id``, ``notation``, ``family``, ``pattern``, ``lock_set``, ``locks``. For
    example the legs that give the translations ``T3`` with three joints locked:
    ``df[(df.pattern == "T3") & (df.locks <= 3)]``.
    """
    cat = catalogue()
    rows = [
        {
            "id": r.id,
            "notation": r.notation,
            "family": r.family,
            "pattern": pattern,
            "lock_set": s,
            "locks": 0 if s == "-" else len(s),
        }
        for r in cat.itertuples()
        for pattern, sets in r.patterns.items()
        for s in sets
    ]
    return pd.DataFrame(
        rows, columns=["id", "notation", "family", "pattern", "lock_set", "locks"]
    )


def query(pattern: str, max_locks: int = 6, family: Optional[str] = None) -> pd.DataFrame:
    """The catalogue entries whose leg gives ``pattern`` with at most ``max_locks`` joints
    locked (``kinsyn query --pattern PATTERN --max-locks K [--family F] --json``): one row per
    entry and pattern matched, with the minimal ``lock_sets`` that give it.

    ``pattern`` is a displacement group (``T3``, ``X(z)``, ``G(xy)``, …) or ``nTmR``.
    Columns: ``id``, ``notation``, ``family``, ``word``, ``axes``, ``pattern``, ``lock_sets``.
    """
    rows = json.loads(_native.query_json(pattern, max_locks, family))
    return pd.DataFrame(
        rows, columns=["id", "notation", "family", "word", "axes", "pattern", "lock_sets"]
    )


# --- manipulators ---------------------------------------------------------------------------


@dataclass(frozen=True)
class Analysis:
    """A manipulator at one configuration (``kinsyn analyze --json``): mobility, the
    Jacobians of paper 000 §4–5, their ranks and the singularities.

    ``J_D`` has one row per wrench (free inputs, locked inputs, constraints: ``rows`` names
    them), columns ``(v_P; ω)``; ``J_I`` one row per wrench and one column per free input
    (``inputs``), so that ``J_D [v_P; ω] = J_I q̇``. ``singular_values`` are those of ``J_D``
    (its rank decision). ``report`` is the whole report, as the command's JSON.
    """

    report: Dict[str, Any] = field(repr=False)
    J_D: np.ndarray = field(repr=False)
    J_I: np.ndarray = field(repr=False)
    singular_values: np.ndarray
    mobility: int
    dof: int
    jd_rank: int
    rows: List[str]
    inputs: List[str]
    singularities: List[Dict[str, Any]]
    joint_values: np.ndarray = field(repr=False)
    platform_position: np.ndarray

    @property
    def singular(self) -> bool:
        """Whether the configuration is singular (any singularity reported)."""
        return bool(self.singularities)

    @classmethod
    def _from_report(cls, r: Dict[str, Any]) -> "Analysis":
        free = len(r["inputs"])
        return cls(
            report=r,
            J_D=np.asarray(r["jd_matrix"], dtype=float).reshape(-1, 6),
            J_I=np.asarray(r["ji_matrix"], dtype=float).reshape(-1, free),
            singular_values=np.asarray(r["jd_rank"]["singular_values"], dtype=float),
            mobility=r["mobility"],
            dof=r["platform_dof"],
            jd_rank=r["jd_rank"]["rank"],
            rows=[row["row"] for row in r["rows"]],
            inputs=list(r["inputs"]),
            singularities=list(r["singularities"]),
            joint_values=np.asarray(r["joint_values"], dtype=float),
            platform_position=np.asarray(r["platform_position"], dtype=float),
        )


@dataclass(frozen=True)
class Assemblies:
    """Every assembly of a manipulator at given inputs, from its constraint polynomials in
    the Study parameters of the platform (``kinsyn analyze --all-assemblies --json``).

    ``real``: one row per real assembly (``pose`` as ``analyze --pose`` takes it, position
    ``x, y, z``, rotation vector ``rx, ry, rz`` in radians, the largest leg residual, whether it
    is certified, whether it is the one continued from the reference); ``complex``: the
    non-real regular solutions, one row of complex Study coordinates each. ``nonsingular`` is
    the number of regular solutions (real and complex).
    """

    report: Dict[str, Any] = field(repr=False)
    real: pd.DataFrame = field(repr=False)
    complex: np.ndarray = field(repr=False)
    paths: int
    nonsingular: int
    singular: int
    at_infinity: int
    certified: int
    summary: str

    @classmethod
    def _from_report(cls, r: Dict[str, Any]) -> "Assemblies":
        real = pd.DataFrame(
            [
                {
                    "pose": a["pose"],
                    "x": a["position"][0],
                    "y": a["position"][1],
                    "z": a["position"][2],
                    "rx": a["rotation_vector_rad"][0],
                    "ry": a["rotation_vector_rad"][1],
                    "rz": a["rotation_vector_rad"][2],
                    "largest_leg_residual": a["largest_leg_residual"],
                    "certified": a["certified"],
                    "continued_from_reference": a["continued_from_reference"],
                }
                for a in r["real_assemblies"]
            ],
            columns=[
                "pose", "x", "y", "z", "rx", "ry", "rz",
                "largest_leg_residual", "certified", "continued_from_reference",
            ],
        )
        nvars = len(r["formulation"]["variables"])
        complex_ = np.array(
            [_complex(x) for x in r["complex_assemblies"]], dtype=complex
        ).reshape(-1, nvars)
        return cls(
            report=r,
            real=real,
            complex=complex_,
            paths=r["paths"],
            nonsingular=r["nonsingular"],
            singular=r["singular"],
            at_infinity=r["at_infinity"],
            certified=r["certified"],
            summary=r["summary"],
        )


class Manipulator:
    """A parallel manipulator: a description (a file, JSON text, or legs built from a chain
    as ``kinsyn build``) and the mechanism it makes."""

    __slots__ = ("_m",)

    def __init__(self, native: "_native.Manipulator") -> None:
        self._m = native

    @classmethod
    def from_file(cls, path: Union[str, "PathLike[str]"]) -> "Manipulator":
        """The manipulator described by the file at ``path`` (as ``kinsyn analyze FILE``)."""
        return cls(_native.Manipulator.from_file(path))

    @classmethod
    def from_json(cls, text: str, source: str = "<string>") -> "Manipulator":
        """The manipulator described by the JSON text ``text``; messages name it ``source``."""
        return cls(_native.Manipulator.from_json(text, source))

    @classmethod
    def build(
        cls,
        chain: str,
        legs: int = 3,
        actuated: Optional[Sequence[int]] = None,
        axes: Optional[str] = None,
        base_radius: float = 1.0,
        platform_radius: float = 0.5,
        height: float = 1.0,
        twist: float = 0.0,
        alternate: bool = False,
        name: Optional[str] = None,
    ) -> "Manipulator":
        """``legs`` identical legs ``chain`` (a catalogue id such as ``"T4-034"`` or a chain in
        notation, ``!`` marking inputs; or ``actuated``: the 1-based primitive joints driven)
        between a base circle and a platform circle, as ``kinsyn build``. Refusals name the
        command's options (``--chain``, ``--actuated``, …)."""
        return cls(
            _native.Manipulator.build(
                chain,
                legs,
                None if actuated is None else list(actuated),
                axes,
                base_radius,
                platform_radius,
                height,
                twist,
                alternate,
                name,
            )
        )

    @property
    def name(self) -> str:
        """The manipulator's name."""
        return self._m.name

    @property
    def inputs(self) -> List[str]:
        """The inputs' labels (``P1.3``: leg 1, primitive joint 3), in order."""
        return list(self._m.inputs)

    def to_json(self) -> str:
        """The description as JSON text (what ``kinsyn build`` writes)."""
        return self._m.to_json()

    def analyze(
        self,
        pose: Pose = None,
        inputs: Inputs = None,
        lock: Locks = None,
        seed: int = 2026,
        body: Optional[str] = None,
        relative_to: Optional[str] = None,
        study: Study = None,
    ) -> Analysis:
        """The configuration with the platform at ``pose`` (``x,y,z,rx,ry,rz``, or six numbers)
        and/or the ``inputs`` at the values given (``"R1.1=10,P1.3=0.05"`` or a dict; values from
        the reference, angles in the file's unit), reached by continuation from the reference,
        with the inputs of ``lock`` held: its mobility, Jacobians and singularities
        (``kinsyn analyze FILE [--pose] [--inputs] [--lock] --json``).

        With several moving bodies: ``body`` (``--body``) is the one analysed instead of the
        end-effector, ``relative_to`` (``--relative-to``) a body whose point of view is also
        reported (``report["relative_motion"]``), and ``study`` (``--study``, one set per moving
        body in series order from the ground: ``"1:0:0:0:0:0:0:0.75"`` or eight numbers) places
        every body by its Study parameters (paper 002's Table 1)."""
        r = json.loads(
            self._m.analyze_json(
                _pose_text(pose),
                _inputs_text(inputs),
                _locks_text(lock),
                seed,
                body,
                relative_to,
                _study_texts(study),
            )
        )
        _warn(r)
        return Analysis._from_report(r)

    def modes(
        self,
        max_locks: Optional[int] = None,
        lock: Locks = None,
        pose: Pose = None,
        max_subsets: int = 4096,
        seed: int = 2026,
        samples: int = 3,
        body: Optional[str] = None,
        relative_to: Optional[str] = None,
        legs: Union[str, Sequence[int], None] = None,
    ) -> pd.DataFrame:
        """The platform's motion pattern for each subset of locked inputs (all of them, those
        of at most ``max_locks`` inputs, or the one ``lock``), the locked inputs held at their
        values at the reference or at ``pose`` (``kinsyn modes FILE … --json``). ``body``
        (``--body``): the moving body whose motion is classified instead of the end-effector;
        ``relative_to`` (``--relative-to``): the moving body it is seen from; ``legs``
        (``--legs``, ``"1-4,29"`` or a list of 1-based leg numbers): only those legs and the
        bodies they still join to the ground.

        One row per lock subset: ``locked`` (the labels, ``"-"`` for none), ``n_locked``,
        ``dof``, ``pattern`` (``"?"`` when the motion could not be sampled), ``group`` (one of
        the 12 displacement groups), ``parameters``, ``singular_start`` (the start is a
        singular configuration of the locked manipulator: the pattern is that of the branch the
        walks took and is not counted) and ``error``. ``df.attrs["report"]`` holds the whole
        report (the patterns with their minimal lock sets: ``groups``, ``non_groups``,
        ``singular_starts``)."""
        r = json.loads(
            self._m.modes_json(
                max_locks,
                _locks_text(lock),
                _pose_text(pose),
                max_subsets,
                seed,
                samples,
                body,
                relative_to,
                legs if legs is None or isinstance(legs, str) else ",".join(str(int(k)) for k in legs),
            )
        )
        _warn(r)
        df = pd.DataFrame(
            [
                {
                    "locked": m["lock_text"],
                    "n_locked": len(m["locked"]),
                    "dof": m["dof"],
                    "pattern": m["pattern"],
                    "group": m["group"],
                    "parameters": m.get("parameters"),
                    "singular_start": "singular_start" in (m.get("classification") or {}),
                    "error": m.get("error"),
                }
                for m in r["modes"]
            ],
            columns=["locked", "n_locked", "dof", "pattern", "group", "parameters", "singular_start", "error"],
        )
        df.attrs["report"] = r
        return df

    def assemblies(self, inputs: Inputs = None, seed: int = 2026) -> Assemblies:
        """Every assembly (real and complex) at the ``inputs`` (the reference values for
        inputs not named), by homotopy continuation (``kinsyn analyze FILE --inputs …
        --all-assemblies --seed S --json``)."""
        r = json.loads(self._m.assemblies_json(_inputs_text(inputs), seed))
        _warn(r)
        return Assemblies._from_report(r)

    def view(
        self,
        inputs: Inputs = None,
        steps: int = 16,
        assemblies: bool = True,
        components: bool = False,
        free_inputs: bool = False,
        max_paths: int = 65536,
        seed: int = 1,
    ) -> "View":
        """The 3D view of the manipulator (``kinsyn view FILE --out PAGE.html``, docs/view.md):
        a self-contained page with a slider per input (swept ``steps`` steps to either side,
        the other inputs held), an animation of each operation mode reached by locking inputs,
        every real assembly at ``inputs`` (unless ``assemblies`` is false) and, with
        ``components``, each component of the global decomposition (``kinsyn components``; over
        input and pose space with ``free_inputs``, within ``max_paths`` paths). Shown inline in
        Jupyter; ``View.save(path)`` writes the page."""
        return View(
            self._m.view_html(
                _inputs_text(inputs), steps, assemblies, components, free_inputs, max_paths, seed
            )
        )

    def show(self, *args: Any, **kwargs: Any) -> "View":
        """The same as :meth:`view`: in Jupyter, the last expression of a cell is displayed."""
        return self.view(*args, **kwargs)

    def __repr__(self) -> str:
        return repr(self._m)


class View:
    """A manipulator's 3D page (docs/view.md): ``html`` is the whole page; Jupyter shows it
    inline in a frame of ``height`` pixels."""

    __slots__ = ("html", "height")

    def __init__(self, html: str, height: int = 560) -> None:
        self.html = html
        self.height = height

    def save(self, path: Union[str, "PathLike[str]"]) -> None:
        """Writes the page to ``path`` (UTF-8), replacing a file there."""
        Path(path).write_text(self.html, encoding="utf-8")

    def _repr_html_(self) -> str:
        # The page in a frame of its own: its scripts and styles do not touch the notebook's.
        return (
            f'<iframe srcdoc="{_html.escape(self.html, quote=True)}" '
            f'style="width: 100%; height: {self.height}px; border: 1px solid #dee2e6" '
            'sandbox="allow-scripts"></iframe>'
        )

    def __repr__(self) -> str:
        return f"View({len(self.html)} characters of HTML)"


# --- polynomial systems ---------------------------------------------------------------------


@dataclass(frozen=True)
class Solutions:
    """The isolated solutions of a polynomial system (``kinsyn solve --json``).

    ``solutions``: every finite endpoint, one row of complex coordinates in the order of
    ``variables``; ``table``: the same with ``regular``, ``real``, ``reality``,
    ``multiplicity``, ``residual``, ``certified`` per solution. ``real`` (the real regular
    solutions, a real array) and the counts as the command reports them; ``start`` the start
    system tracked (``"auto"`` resolved) and ``complete`` whether every path ended.
    """

    report: Dict[str, Any] = field(repr=False)
    variables: List[str]
    solutions: np.ndarray = field(repr=False)
    table: pd.DataFrame = field(repr=False)
    start: str
    complete: bool
    paths: int
    nonsingular: int
    singular: int
    at_infinity: int
    failed: int
    certified: Optional[int]
    summary: str

    @property
    def real(self) -> np.ndarray:
        """The real regular solutions (real parts), one row each."""
        keep = (self.table["regular"] & self.table["real"]).to_numpy(dtype=bool)
        return self.solutions[keep].real

    @classmethod
    def _from_report(cls, r: Dict[str, Any]) -> "Solutions":
        n = len(r["variables"])
        sols = np.array([_complex(s["x"]) for s in r["solutions"]], dtype=complex).reshape(-1, n)
        table = pd.DataFrame(
            [
                {
                    "regular": s["regular"],
                    "real": s["real"],
                    "reality": s["reality"],
                    "multiplicity": s["multiplicity"],
                    "residual": s["residual"],
                    "certified": s["certified"],
                }
                for s in r["solutions"]
            ],
            columns=["regular", "real", "reality", "multiplicity", "residual", "certified"],
        )
        for k, v in enumerate(r["variables"]):
            table[v] = sols[:, k] if len(sols) else np.array([], dtype=complex)
        return cls(
            report=r,
            variables=list(r["variables"]),
            solutions=sols,
            table=table,
            start=r["start"],
            complete=r["complete"],
            paths=r["paths"],
            nonsingular=r["nonsingular"],
            singular=r["singular"],
            at_infinity=r["at_infinity"],
            failed=r["failed"],
            certified=r["certified"],
            summary=r["summary"],
        )


def solve(
    system: str,
    seed: int = 1,
    start: str = "auto",
    runs: int = 1,
    threads: Optional[int] = None,
    certify: bool = True,
    source: str = "<string>",
) -> Solutions:
    """Every isolated solution of the polynomial system ``system``, Bertini input text as
    ``kinsyn solve`` reads it, by homotopy continuation from a ``start`` system
    (``"auto"``, the fewest paths of the others; ``"total-degree"``, ``"multi-homogeneous"``,
    ``"linear-product"`` or ``"polyhedral"``), certified by the Krawczyk test unless
    ``certify`` is false. Messages name the text ``source`` where the command names the file."""
    return Solutions._from_report(
        json.loads(_native.solve_json(system, source, seed, start, runs, threads, certify))
    )


def solve_file(
    path: Union[str, "PathLike[str]"],
    seed: int = 1,
    start: str = "auto",
    runs: int = 1,
    threads: Optional[int] = None,
    certify: bool = True,
) -> Solutions:
    """:func:`solve` for the Bertini input file at ``path`` (``kinsyn solve FILE --json``)."""
    return Solutions._from_report(
        json.loads(_native.solve_file_json(path, seed, start, runs, threads, certify))
    )


def solve_shard(
    path: Union[str, "PathLike[str]"],
    shard: int,
    shards: int,
    out: Union[str, "PathLike[str]"],
    seed: int = 1,
    start: str = "auto",
    threads: Optional[int] = None,
    force: bool = False,
) -> Dict[str, Any]:
    """Shard ``shard`` of ``shards`` (1-based) of the solve of the Bertini input file at
    ``path``: its paths tracked once each and written to the shard file ``out``
    (``kinsyn solve PATH --shard K/N --out OUT``), for :func:`merge_shards`. Returns the
    summary (``shard``, ``shards``, ``start``, ``paths``, ``tracked``, ``seconds``). Every
    shard and the merge must use the same ``seed`` and ``start``. Picklable arguments and the
    GIL released: one shard per Dask task (docs/scale.md)."""
    return json.loads(
        _native.solve_shard_json(path, shard, shards, out, seed, start, threads, force)
    )


def merge_shards(
    path: Union[str, "PathLike[str]"],
    parts: Sequence[Union[str, "PathLike[str]"]],
    seed: int = 1,
    start: str = "auto",
    threads: Optional[int] = None,
    certify: bool = True,
) -> Solutions:
    """The solve of the Bertini input file at ``path`` finished from the shard files
    ``parts`` of :func:`solve_shard` (any order, each of ``1 … N`` once): the same
    :class:`Solutions` as :func:`solve_file` in one process, path for path
    (``kinsyn solve PATH --merge PARTS…``)."""
    return Solutions._from_report(
        json.loads(_native.merge_shards_json(path, list(parts), seed, start, threads, certify))
    )


# --- the components of a constraint variety (paper 004) ---------------------------------------


def components(
    path: Union[str, "PathLike[str]"],
    inputs: Inputs = None,
    free_inputs: Union[bool, Sequence[str]] = False,
    method: str = "by-dimension",
    seed: int = 1,
    max_paths: Optional[int] = None,
    body: Optional[str] = None,
) -> pd.DataFrame:
    """The irreducible components of the solution set of a manipulator file's constraint
    equations in the Study parameters of its platform (at the ``inputs``, the reference values
    for inputs not named; with every input an unknown when ``free_inputs`` is ``True``, or the
    inputs it lists, e.g. ``["R1.1", "R3.1"]``, the others held) or of a Bertini input file's
    system, by numerical irreducible decomposition (``kinsyn components FILE [--inputs]
    [--free-inputs | --free LABELS] [--body] [--method] --seed S --json``; ``method``:
    ``"by-dimension"`` or ``"regeneration"``; ``max_paths``: ``--max-paths``, the command's
    default when ``None``, the most paths tracked in all, counted from the degrees before any
    tracking; past it the call raises ``InputError``; ``body``: the body whose motion is
    classified, the end-effector by default).

    One row per component: ``dimension`` (0: isolated solutions, the assemblies; above 0: a
    self-motion, or with free inputs an operation mode of that many dof), ``degree``,
    ``multiplicity`` (1 when reduced; at least 2 for a non-reduced component, found by
    deflation), ``real_points``, ``trace_test_passed``, ``motion`` (for a manipulator's real assemblies,
    the operation mode: dof and pattern with the inputs released), and ``mechanism`` (the whole
    mechanism placed at a real point the legs reach: the body's ``dof`` and ``pattern`` with
    the held inputs locked, ``moving_inputs``, ``still_inputs``, ``held_inputs``; ``None``
    for a component without one). ``df.attrs["report"]`` is the whole report (paths, junk
    points, unresolved points, seconds).
    """
    if isinstance(free_inputs, bool):
        every, some = free_inputs, None
    else:
        every, some = False, ",".join(free_inputs)
    r = json.loads(
        _native.components_json(
            path, _inputs_text(inputs), every, method, seed, max_paths, some, body
        )
    )
    df = pd.DataFrame(
        [
            {
                "dimension": c["dimension"],
                "degree": c["degree"],
                "multiplicity": c["multiplicity"],
                "real_points": c["real_points"],
                "trace_test_passed": c["trace_test_passed"],
                "motion": c.get("motion"),
                "mechanism": c.get("mechanism"),
            }
            for c in r["components"]
        ],
        columns=[
            "dimension",
            "degree",
            "multiplicity",
            "real_points",
            "trace_test_passed",
            "motion",
            "mechanism",
        ],
    )
    df.attrs["report"] = r
    return df


from . import configurable  # noqa: E402  (the submodule uses the helpers above)
from . import sweep  # noqa: E402
