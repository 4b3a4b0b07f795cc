"""The clearance of one damper on a structure of several modes, chosen by the located peak of the
structure's response curve: :func:`structure_design`.

For each clearance the structure's curve over the band is traced from both ends with its
period-doubled branches and run from rest at each frequency of the band's grid
(:func:`symimpact.forced.orbits.structure_branch.structure_curve`), and the peak at the chosen point is
located on it (:func:`symimpact.forced.orbits.structure_branch.curve_peak`: on the branches, or a run
from rest's where it settled on a larger motion no branch holds);
the best clearance is the one of the lowest peak, reported beside the bare structure's peak
(:func:`symimpact.forced.orbits.structure_branch.bare_peak`).  The clearances run one after the other;
each curve's runs from rest run on the map engine's executors
(:func:`symimpact.maps.structure_curve.structure_curve_map`).
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from ..errors import ParameterError
from ..forced.orbits.structure_branch import StructurePeak, bare_peak, curve_peak
from ..model.dampers import Damper
from ..model.structure import Structure
from .structure_curve import structure_curve_map


@dataclass(frozen=True)
class StructureDesign:
    """Each clearance's located peak at ``point`` (None where no stable orbit was traced), the
    best clearance and the bare structure's peak (SI)."""

    damper: str
    point: str
    gaps: np.ndarray
    peaks: list[StructurePeak | None]
    notes: list[list[str]]
    bare: StructurePeak

    @property
    def best(self) -> tuple[float, StructurePeak] | None:
        """(clearance, peak) of the lowest located peak, or None."""
        found = [(g, p) for g, p in zip(self.gaps, self.peaks, strict=True) if p is not None]
        return min(found, key=lambda gp: gp[1].amplitude, default=None)

    def as_dict(self) -> dict[str, Any]:
        best = self.best
        return {
            "damper": self.damper,
            "point": self.point,
            "rows": [
                _row(g, p, n) for g, p, n in zip(self.gaps, self.peaks, self.notes, strict=True)
            ],
            "best": None if best is None else {"gap": float(best[0]), "peak": best[1].as_dict()},
            "bare_peak": self.bare.as_dict(),
        }


def _row(gap: float, peak: StructurePeak | None, notes: list[str]) -> dict[str, Any]:
    return {"gap": float(gap), "peak": None if peak is None else peak.as_dict(), "notes": notes}


def structure_design(structure: Structure, dampers: Any, force_at: Any, F0: Any, damper: str,
                     gaps: Any, omega_low: float, omega_high: float, step: float,
                     point: Any = None, stops: Any = (), base: Any = 0.0, *,
                     executor: str | None = None, workers: Any = None, client: Any = None,
                     scheduler: str | None = None) -> StructureDesign:  # fmt: skip
    """The located peak at ``point`` (default: the driven point) over [omega_low, omega_high]
    [rad/s] for each clearance of ``gaps`` [m] given to the damper named ``damper`` (module
    text); ``base``: the supports' displacement amplitude X_b [m], or a function of Ω giving
    it; ``executor``, ``workers``, ``client``, ``scheduler``: where each curve's runs from rest
    run (:func:`symimpact.maps.structure_curve.structure_curve_map`)."""
    dampers = tuple(dampers)
    names = [d.name for d in dampers]
    if damper not in names:
        raise ParameterError("damper", f"no damper {damper!r} (the dampers: "
                                        f"{', '.join(names) or 'none'})")  # fmt: skip
    at = structure._point(force_at if point is None else point)
    values = np.asarray(gaps, dtype=float).ravel()
    if not len(values) or not np.all(np.isfinite(values)) or np.any(values <= 0):
        raise ParameterError("gaps", "must be positive clearances [m]")
    k = names.index(damper)
    peaks: list[StructurePeak | None] = []
    notes: list[list[str]] = []
    for gap in values:
        trial: list[Damper] = list(dampers)
        trial[k] = replace(dampers[k], gap=float(gap))
        curve = structure_curve_map(structure, trial, force_at, F0, omega_low, omega_high, step,
                                    stops, base=base, executor=executor, workers=workers,
                                    client=client, scheduler=scheduler)  # fmt: skip
        peaks.append(curve_peak(structure, trial, force_at, F0, curve, at, stops, base=base))
        notes.append(curve.notes)
    bare = bare_peak(structure, force_at, F0, at, omega_low, omega_high, base=base)
    return StructureDesign(damper, at, values, peaks, notes, bare)
