"""Paper 003's planar 4-RRR manipulator with a configurable (4-bar) platform, by the paper's own
formulas, with the geometry of its §5 (a = 80, b = 120, c = 120 mm; the base joints A_i at
(±200, 0) and (0, ±200) mm). Lengths are in mm and angles in degrees, as at ``kinsyn
configurable``.

- :func:`inverse`: the input sets (two elbows per leg, up to 16) that put the platform at a pose
  (§3.2);
- :func:`forward`: every assembly at given inputs, by homotopy continuation on method 1 or 2's
  equations (§3.2), certified;
- :func:`velocity`: the corner velocities by screw theory (§4).
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from typing import Any, Dict, Optional, Sequence, Union

import numpy as np
import pandas as pd

from . import _native

__all__ = ["Forward", "forward", "inverse", "velocity"]

Numbers = Union[str, Sequence[float]]


def _numbers_text(values: Optional[Numbers]) -> Optional[str]:
    """Numbers as the command line takes them: ``"1.5,-2"``."""
    if values is None or isinstance(values, str):
        return values
    return ",".join(repr(float(v)) for v in values)


def inverse(
    theta: float,
    phi: float,
    centre: Optional[Numbers] = None,
    c4: Optional[Numbers] = None,
) -> pd.DataFrame:
    """The input sets ``q1..q4`` (degrees) that put the platform at a pose given by its centre
    ``C = (x, y)`` with θ, φ in eq. 11's sense, or by its corner ``C4 = (x, y)`` with θ, φ the
    directions of C4→C1 and C4→C3 (eq. 13) (``kinsyn configurable inverse (--centre X,Y | --c4
    X,Y) --theta T --phi P --json``). One row per set; ``df.attrs["report"]`` also holds the
    corners ``C1..C4``."""
    r = json.loads(
        _native.configurable_inverse_json(theta, phi, _numbers_text(centre), _numbers_text(c4))
    )
    df = pd.DataFrame(r["q_deg"], columns=["q1", "q2", "q3", "q4"])
    df.attrs["report"] = r
    return df


@dataclass(frozen=True)
class Forward:
    """Every assembly of the 4-RRR at given inputs (``kinsyn configurable forward --json``).

    ``complex_solutions``: the finite solutions of the method's equations (complex ones
    included); ``real_solutions``: the real ones; ``complex_assemblies``: the distinct
    assemblies among the complex solutions; ``complete``: no path lost. ``assemblies``: one
    row per real assembly, the corner ``C4 = (c4_x, c4_y)`` mm, θ and φ (degrees, eq. 13),
    whether it is certified and its loop-closure error (mm).
    """

    report: Dict[str, Any] = field(repr=False)
    assemblies: pd.DataFrame = field(repr=False)
    method: int
    complex_solutions: int
    real_solutions: int
    complex_assemblies: int
    complete: bool


def forward(q: Numbers, method: int = 2) -> Forward:
    """Every assembly at the inputs ``q`` (four angles in degrees) by §3.2's method 1 (unknowns
    w1..w6, eqs. 1–5, 10) or 2 (x4, y4 and the sines and cosines of θ, φ, eqs. 12–15), solved by
    homotopy continuation and certified (``kinsyn configurable forward --q Q --method M
    --json``)."""
    r = json.loads(_native.configurable_forward_json(_numbers_text(q), method))
    assemblies = pd.DataFrame(
        [
            {
                "c4_x": a["c4"][0],
                "c4_y": a["c4"][1],
                "theta_deg": a["theta_deg"],
                "phi_deg": a["phi_deg"],
                "certified": a["certified"],
                "closure_error": a["closure_error"],
            }
            for a in r["assemblies"]
        ],
        columns=["c4_x", "c4_y", "theta_deg", "phi_deg", "certified", "closure_error"],
    )
    return Forward(
        report=r,
        assemblies=assemblies,
        method=r["method"],
        complex_solutions=r["complex_solutions"],
        real_solutions=r["real_solutions"],
        complex_assemblies=r["complex_assemblies"],
        complete=r["complete"],
    )


def velocity(q: Numbers, qdot: Numbers, near: Optional[Numbers] = None) -> Dict[str, Any]:
    """The velocities by screw theory (§4, eqs. 16–29) at the inputs ``q`` (degrees) and rates
    ``qdot`` (rad/s), at the assembly nearest ``near`` (``C4x, C4y, θ, φ`` in mm and degrees;
    default Table 1's pose) (``kinsyn configurable velocity --q Q --qdot QDOT [--near N]
    --json``): the report, with ``corner_velocities`` (mm/s) as a 4×2 array, ``omega_m1``,
    ``omega_m3`` (rad/s), ``loop_rate`` and the assembly (``c4``, ``theta_deg``, ``phi_deg``).
    """
    r = json.loads(
        _native.configurable_velocity_json(
            _numbers_text(q), _numbers_text(qdot), _numbers_text(near)
        )
    )
    r["corner_velocities"] = np.asarray(r["corner_velocities"], dtype=float).reshape(4, 2)
    return r
