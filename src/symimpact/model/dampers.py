"""Impact dampers attached to a structure's points: each a mass ``m`` [kg] rattling in a cavity of
total clearance ``gap`` [m] at the point ``at``, with rigid impacts of Newton's restitution ``e``
(Step 9's law, Eq. F2, at a point of a structure: Step 15, item 4, Eq. F7) or a compliant contact
on its walls: ``"linear"`` k₁δ + c₁δ̇ (Eq. 35 with a dashpot), ``"hertz"`` k_hz·δ^1.5 + c₁δ̇ (Eq. 9)
or ``"hunt-crossley"`` k_hz·δ^1.5·(1 + χδ̇) (Eq. F4), δ the mass's penetration of the wall (the
one-mode engine's laws, :mod:`symimpact.forced.engine._compliant`).

:func:`dampers` reads a list of ``{"name", "at", "m", "gap", "contact", "e" | law parameters}``
(the structure file's ``"dampers"`` entry; SI numbers or quantity texts such as ``"10 mm"``,
``"1000 N/m^1.5"``) and checks each against the structure: a point it has, a point some mode
moves, a unique name.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from ..errors import ParameterError
from .checks import bounded
from .structure import Structure
from .units import nonnegative_float, positive_float

#: The fields a damper takes.
FIELDS = ("name", "at", "m", "gap", "contact", "e", "k1", "c1", "k_hz", "chi")
#: The contact laws a damper takes, and the parameters each needs (beside the optional c1 of
#: the linear and Hertz laws).
LAWS = {"rigid": ("e",), "linear": ("k1",), "hertz": ("k_hz",), "hunt-crossley": ("k_hz", "chi")}
_UNITS = {"k1": "N/m", "c1": "N*s/m", "k_hz": "N/m**1.5", "chi": "s/m"}


@dataclass(frozen=True)
class Damper:
    """An impact damper: ``m`` [kg] in a clearance ``gap`` [m] at point ``at``; rigid impacts of
    restitution ``e``, or (``contact`` "linear", "hertz", "hunt-crossley") the contact law's
    ``k1`` [N/m], ``c1`` [N s/m], ``k_hz`` [N/m^1.5], ``chi`` [s/m] (module text)."""

    name: str
    at: str
    m: float
    gap: float
    e: float
    contact: str = "rigid"
    k1: float = 0.0
    c1: float = 0.0
    k_hz: float = 0.0
    chi: float = 0.0

    @property
    def rigid(self) -> bool:
        return self.contact == "rigid"

    def as_dict(self) -> dict[str, Any]:
        out = {"name": self.name, "at": self.at, "m": self.m, "gap": self.gap,
               "contact": self.contact}  # fmt: skip
        if self.rigid:
            return out | {"e": self.e}
        keys = {"linear": ("k1", "c1"), "hertz": ("k_hz", "c1"), "hunt-crossley": ("k_hz", "chi")}
        return out | {k: getattr(self, k) for k in keys[self.contact]}


def damper(structure: Structure, name: Any, at: Any, m: Any, gap: Any, e: Any = None,
           contact: Any = "rigid", k1: Any = None, c1: Any = None, k_hz: Any = None,
           chi: Any = None) -> Damper:  # fmt: skip
    """One checked :class:`Damper` on ``structure`` (its point ``at`` must exist and move)."""
    label = f"dampers.{name}"
    if not isinstance(name, str) or not name:
        raise ParameterError("dampers.name", f"must be a non-empty text, got {name!r}")
    if contact not in LAWS:
        raise ParameterError(f"{label}.contact", f"one of {', '.join(LAWS)}, got {contact!r}")
    given = {"e": e, "k1": k1, "c1": c1, "k_hz": k_hz, "chi": chi}
    takes = set(LAWS[contact]) | ({"c1"} if contact in ("linear", "hertz") else set())
    for key, value in given.items():
        if value is None and key in LAWS[contact]:
            what = "the restitution of the rigid impacts" if key == "e" else f"[{_UNITS[key]}]"
            raise ParameterError(
                f"{label}.{key}", f"missing: a {contact} contact needs it ({what})"
            )
        if value is not None and key not in takes:
            raise ParameterError(f"{label}.{key}", f"a {contact} contact does not take {key} "
                                                   f"(it takes {', '.join(sorted(takes))})")  # fmt: skip
    try:
        point = structure._point(at)
    except ParameterError as exc:
        raise ParameterError(f"{label}.at", exc.reason) from None
    if all(mode.node_at(point) for mode in structure.modes):
        raise ParameterError(f"{label}.at", f"no mode moves the point {point!r} (a support): "
                                            "the damper would never act")  # fmt: skip
    mass = positive_float(f"{label}.m", m, "kg")
    clearance = positive_float(f"{label}.gap", gap, "m")
    if contact == "rigid":
        return Damper(name, point, mass, clearance, bounded(f"{label}.e", e, 0.0, 1.0))
    law = {key: (positive_float if key in ("k1", "k_hz") else nonnegative_float)(
        f"{label}.{key}", given[key], _UNITS[key]) for key in takes if given[key] is not None}  # fmt: skip
    return Damper(name, point, mass, clearance, math.nan, contact, **law)


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
        missing = [f for f in ("name", "at", "m", "gap") if f not in entry]
        if entry.get("contact", "rigid") == "rigid" and "e" not in entry:
            missing.append("e")
        if missing:
            raise ParameterError(f"dampers[{i}]", f"missing {missing[0]!r}")
        d = damper(structure, **entry)
        if any(o.name == d.name for o in out):
            raise ParameterError(f"dampers.{d.name}", "two dampers have this name")
        out.append(d)
    return tuple(out)
