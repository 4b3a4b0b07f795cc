"""A whole structure file: the structure (:mod:`symimpact.model.structure`), the impact dampers on
it (:mod:`symimpact.model.dampers`), the stops it meets (:mod:`symimpact.model.stops`) and the
harmonic force that drives it — what
:func:`symimpact.forced.structure_response.simulate_structure` takes (Step 15: the modes of the
structure, each damper's impact at its point, Eq. F7).

The file's fields beside the structure's: ``"dampers"``, a list of ``{"name", "at", "m", "gap",
"contact": "rigid", "e"}``; ``"stops"``, a list of ``{"name", "at", "gap", "side", "contact":
"linear", "k1", "c1"}``; ``"force"``, ``{"at": point, "amplitude": F0}``; and ``"base"``, the
supports' harmonic motion at the force's frequency and phase, ``{"amplitude": X_b}`` (a
displacement) or ``{"acceleration": A_b}`` (X_b = A_b/Ω² at each Ω: a shaker's constant
acceleration level, e.g. ``"0.5 g"``) (SI numbers or quantity texts such as ``"2 N"``).  A file
gives dampers, stops or both, and a force, a base motion or both.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from ..errors import ParameterError
from .dampers import Damper, dampers
from .stops import Stop, stops
from .structure import LOADS, Structure, parsed_file, structure_from_dict
from .units import nonnegative_float, positive_float


@dataclass(frozen=True)
class StructureModel:
    """A structure, its dampers, its stops and the force amplitude ``F0`` [N] at point
    ``force_at``."""

    structure: Structure
    dampers: tuple[Damper, ...]
    force_at: str
    F0: float
    stops: tuple[Stop, ...] = ()
    #: the supports' displacement amplitude X_b [m], or (``base_kind`` "acceleration") their
    #: acceleration amplitude A_b [m/s²]; 0: fixed supports
    base: float = 0.0
    base_kind: str = "amplitude"

    def base_at(self, omega: float) -> float:
        """X_b [m] at the forcing frequency Ω [rad/s]: the file's displacement amplitude, or
        its acceleration amplitude over Ω² (x_b = X_b cos(Ωt + φ) has ẍ_b = −Ω²x_b)."""
        if self.base_kind == "acceleration":
            return self.base / (omega * omega)
        return self.base


def model_from_dict(data: Any, base: Any = None) -> StructureModel:
    """The :class:`StructureModel` of a parsed structure file (see :func:`read_model`)."""
    if not isinstance(data, dict):
        raise ParameterError("structure", "a table with one of beam, modes or fe")
    if "dampers" not in data and "stops" not in data:
        raise ParameterError("dampers", "the file gives no dampers and no stops: list them as "
                                        "{name, at, m, gap, contact, e} or {name, at, gap, side, "
                                        "contact, k1, c1}")  # fmt: skip
    if "force" not in data and "base" not in data:
        raise ParameterError("force", "the file gives no force and no base motion: {\"at\": "
                                      "point, \"amplitude\": F0} or \"base\": {\"amplitude\": "
                                      "X_b}")  # fmt: skip
    structure = structure_from_dict({k: v for k, v in data.items() if k not in LOADS}, base)
    found = dampers(structure, data["dampers"]) if "dampers" in data else ()
    walls = stops(structure, data["stops"]) if "stops" in data else ()
    for w in walls:
        if any(d.name == w.name for d in found):
            raise ParameterError(f"stops.{w.name}", "a damper has this name too")
    X_b, kind = 0.0, "amplitude"
    if "base" in data:
        X_b, kind = _base(data["base"])
    if "force" not in data:  # moved by its supports alone
        return StructureModel(structure, found, structure.points[0], 0.0, walls, X_b, kind)
    force = data["force"]
    if not isinstance(force, dict) or set(force) != {"at", "amplitude"}:
        raise ParameterError("force", 'must be {"at": point, "amplitude": F0}')
    try:
        at = structure._point(force["at"])
    except ParameterError as exc:
        raise ParameterError("force.at", exc.reason) from None
    if all(mode.node_at(at) for mode in structure.modes):
        raise ParameterError("force.at", f"no mode moves the point {at!r} (a support): the "
                                         "force would do nothing")  # fmt: skip
    F0 = nonnegative_float("force.amplitude", force["amplitude"], "N")
    return StructureModel(structure, found, at, F0, walls, X_b, kind)


def _base(base: Any) -> tuple[float, str]:
    """(value, kind) of the file's ``"base"``: ``{"amplitude": X_b}`` [m] or
    ``{"acceleration": A_b}`` [m/s²] (a structure whose modes have no participation factor, as
    modal data give, is refused by the run: :func:`~symimpact.forced.structure_response.
    simulate_structure`)."""
    if not isinstance(base, dict) or len(base) != 1 or set(base) - {"amplitude", "acceleration"}:
        raise ParameterError("base", 'must be {"amplitude": X_b} or {"acceleration": A_b} (the '
                                     "supports move at the force's frequency and phase)")  # fmt: skip
    ((kind, value),) = base.items()
    unit = "m" if kind == "amplitude" else "m/s^2"
    return positive_float(f"base.{kind}", value, unit), kind


def read_model(path: Any) -> StructureModel:
    """The structure file at ``path`` (JSON or TOML) with its dampers, stops and force: the
    structure as :func:`symimpact.model.structure.read_structure` reads it, ``"dampers"``,
    ``"stops"`` and ``"force"`` as the module text says."""
    data, base = parsed_file(path)
    return model_from_dict(data, base)


def has_loads(path: Any) -> bool:
    """Whether the structure file at ``path`` gives dampers, stops or loads (so it is a model
    for the engine of several modes, not one mode for the options' damper)."""
    data, _ = parsed_file(path)
    return isinstance(data, dict) and any(k in data for k in LOADS)
