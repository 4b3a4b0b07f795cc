"""One run of a map: the system of a point (its swept inputs set on the base system) simulated,
and the row it gives: the figures of Sect. 4 and the energy ledger, with its gap class."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..errors import ParameterError
from ..system import ImpactSystem
from .points import INITIAL

#: Output columns of a map row, in table order (after ``run`` and the swept inputs).
OUTPUTS = (
    "n_impacts",
    "n_effective",
    "effectiveness",
    "damping_inclination",
    "zeta_eq",
    "energy_initial",
    "energy_dissipated",
    "energy_dissipated_contact",
    "energy_residual",
    "class",
)


def gap_class(n_impacts: int, n_effective: int) -> str:
    """``in range``, ``out of range`` or ``no impact`` by the criterion of this module."""
    if n_impacts == 0:
        return "no impact"
    return "in range" if n_effective >= n_impacts - n_effective else "out of range"


@dataclass(frozen=True)
class _Base:
    system: ImpactSystem
    initial: tuple[tuple[str, float], ...]
    contact: str | None


def _point_system(base: _Base, names: tuple[str, ...], values: Sequence[float]):
    initial = dict(base.initial)
    changes: dict[str, float] = {}
    ratio = None
    for n, v in zip(names, values, strict=True):
        if n in INITIAL:
            initial[n] = float(v)
        elif n == "mass_ratio":
            ratio = float(v)
        else:
            changes[n] = float(v)
    if ratio is not None:
        if not ratio > 0:
            raise ParameterError("mass_ratio", f"must be positive, got {ratio:g}")
        changes["m"] = ratio * changes.get("M", base.system.M)
    system = base.system.with_(**changes) if changes else base.system
    return system, initial


def run_point(base: _Base, names: tuple[str, ...], values: Sequence[float]) -> dict[str, Any]:
    """The table row (without ``run``) of one map point."""
    from ..simulation import simulate

    system, initial = _point_system(base, names, values)
    res = simulate(system, contact=base.contact, **initial)
    e = res.energy
    row: dict[str, Any] = dict(zip(names, (float(v) for v in values), strict=True))
    row.update(
        n_impacts=res.n_impacts,
        n_effective=res.n_effective,
        effectiveness=res.effectiveness,
        damping_inclination=res.damping_inclination,
        zeta_eq=res.zeta_eq,
        energy_initial=e["initial"],
        energy_dissipated=e["dissipated_C"] + e["dissipated_c1"],
        energy_dissipated_contact=e["dissipated_c1"],
        energy_residual=e["residual"],
    )
    row["class"] = gap_class(res.n_impacts, res.n_effective)
    return row


def _run_chunk(payload: tuple[_Base, tuple[str, ...], list[int], np.ndarray]):
    base, names, runs, values = payload
    rows = []
    for run, vals in zip(runs, values, strict=True):
        row = {"run": int(run)}
        row.update(run_point(base, names, vals))
        rows.append(row)
    return rows
