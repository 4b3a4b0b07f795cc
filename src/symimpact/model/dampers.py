"""Impact dampers attached to a structure's points: each a mass ``m`` [kg] rattling in a cavity of
total clearance ``gap`` [m] at the point ``at``, with rigid impacts of Newton's restitution ``e``
(Step 9's law, Eq. F2, at a point of a structure: Step 15, item 4, Eq. F7).

:func:`dampers` reads a list of ``{"name", "at", "m", "gap", "e"}`` (the structure file's
``"dampers"`` entry; SI numbers or quantity texts such as ``"10 mm"``) and checks each against the
structure: a point it has, a point some mode moves, a unique name.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from ..errors import ParameterError
from .checks import bounded
from .structure import Structure
from .units import positive_float

#: The fields a damper takes.
FIELDS = ("name", "at", "m", "gap", "contact", "e")


@dataclass(frozen=True)
class Damper:
    """An impact damper: ``m`` [kg] in a clearance ``gap`` [m] at point ``at``, restitution
    ``e``."""

    name: str
    at: str
    m: float
    gap: float
    e: float

    def as_dict(self) -> dict[str, Any]:
        return {"name": self.name, "at": self.at, "m": self.m, "gap": self.gap,
                "contact": "rigid", "e": self.e}  # fmt: skip


def damper(structure: Structure, name: Any, at: Any, m: Any, gap: Any, e: Any,
           contact: Any = "rigid") -> Damper:  # fmt: skip
    """One checked :class:`Damper` on ``structure`` (its point ``at`` must exist and move)."""
    label = f"dampers.{name}"
    if not isinstance(name, str) or not name:
        raise ParameterError("dampers.name", f"must be a non-empty text, got {name!r}")
    if contact != "rigid":
        raise ParameterError(f"{label}.contact", f"only rigid impacts (with e) act on a structure "
                                                 f"of several modes so far, got {contact!r}")  # fmt: skip
    try:
        point = structure._point(at)
    except ParameterError as exc:
        raise ParameterError(f"{label}.at", exc.reason) from None
    if all(mode.node_at(point) for mode in structure.modes):
        raise ParameterError(f"{label}.at", f"no mode moves the point {point!r} (a support): "
                                            "the damper would never act")  # fmt: skip
    return Damper(
        name,
        point,
        positive_float(f"{label}.m", m, "kg"),
        positive_float(f"{label}.gap", gap, "m"),
        bounded(f"{label}.e", e, 0.0, 1.0),
    )


def dampers(structure: Structure, entries: Any) -> tuple[Damper, ...]:
    """The checked dampers of ``entries`` (a list of dicts with :data:`FIELDS`)."""
    if not isinstance(entries, (list, tuple)) or not entries:
        raise ParameterError("dampers", "must be a non-empty list of {name, at, m, gap, e}")
    out: list[Damper] = []
    for i, entry in enumerate(entries):
        if not isinstance(entry, dict):
            raise ParameterError(f"dampers[{i}]", f"must be a table of {', '.join(FIELDS)}")
        unknown = sorted(set(entry) - set(FIELDS))
        if unknown:
            raise ParameterError(f"dampers[{i}]", f"unknown field {unknown[0]!r} (fields: "
                                                  f"{', '.join(FIELDS)})")  # fmt: skip
        missing = [f for f in ("name", "at", "m", "gap", "e") if f not in entry]
        if missing:
            raise ParameterError(f"dampers[{i}]", f"missing {missing[0]!r}")
        d = damper(structure, **entry)
        if any(o.name == d.name for o in out):
            raise ParameterError(f"dampers.{d.name}", "two dampers have this name")
        out.append(d)
    return tuple(out)
