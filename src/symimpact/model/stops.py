"""Stops: walls fixed to the ground that a structure's point meets across a gap (the vibro-impact
oscillator with a stop; a unilateral contact).  A stop at point ``at`` with gap ``g`` [m] has a
wall at x = +g (``side`` "+"), at x = −g ("-") or both ("both"), and a linear contact law there:
while the point presses the wall w (w·x > g) it feels −k₁(x − w·g) − c₁ẋ (Eq. 35's k₁δ with the
dashpot c₁δ̇ of the one-mode contact laws), and the contact ends where the point comes back to
the wall.  A pressed stop adds k₁φφᵀ and c₁φφᵀ to the structure's modal stiffness and damping
(Step 15's modal form, φ the modes' values at the point), so the flight stays closed form.

:func:`stops` reads a list of ``{"name", "at", "gap", "side", "contact": "linear", "k1", "c1"}``
(the structure file's ``"stops"`` entry; SI numbers or quantity texts such as ``"1 mm"``,
``"2 kN/m"``).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from ..errors import ParameterError
from .structure import Structure
from .units import nonnegative_float, positive_float

#: The fields a stop takes.
FIELDS = ("name", "at", "gap", "side", "contact", "k1", "c1")
#: The walls of each side: +1 the wall at +g, −1 at −g, 0 both.
SIDES = {"+": 1, "-": -1, "both": 0}


@dataclass(frozen=True)
class Stop:
    """A stop at point ``at``: walls at ``side`` ("+": x = +gap, "-": x = −gap, "both"), linear
    contact of stiffness ``k1`` [N/m] and damping ``c1`` [N s/m]."""

    name: str
    at: str
    gap: float
    side: str
    k1: float
    c1: float

    @property
    def walls(self) -> int:
        """+1: the wall at +gap; −1: at −gap; 0: both."""
        return SIDES[self.side]

    def as_dict(self) -> dict[str, Any]:
        return {"name": self.name, "at": self.at, "gap": self.gap, "side": self.side,
                "contact": "linear", "k1": self.k1, "c1": self.c1}  # fmt: skip


def stop(structure: Structure, name: Any, at: Any, gap: Any, side: Any = "both",
         contact: Any = "linear", k1: Any = None, c1: Any = 0.0) -> Stop:  # fmt: skip
    """One checked :class:`Stop` on ``structure`` (its point ``at`` must exist and move)."""
    label = f"stops.{name}"
    if not isinstance(name, str) or not name:
        raise ParameterError("stops.name", f"must be a non-empty text, got {name!r}")
    if contact != "linear":
        raise ParameterError(f"{label}.contact", f"only the linear law (k1, c1) acts at a stop so "
                                                 f"far, got {contact!r}")  # fmt: skip
    if side not in SIDES:
        raise ParameterError(f"{label}.side", f'must be "+", "-" or "both", got {side!r}')
    if k1 is None:
        raise ParameterError(f"{label}.k1", "missing: the contact stiffness [N/m]")
    try:
        point = structure._point(at)
    except ParameterError as exc:
        raise ParameterError(f"{label}.at", exc.reason) from None
    if all(mode.node_at(point) for mode in structure.modes):
        raise ParameterError(f"{label}.at", f"no mode moves the point {point!r} (a support): "
                                            "the stop would never act")  # fmt: skip
    return Stop(
        name,
        point,
        positive_float(f"{label}.gap", gap, "m"),
        side,
        positive_float(f"{label}.k1", k1, "N/m"),
        nonnegative_float(f"{label}.c1", c1, "N*s/m"),
    )


def stops(structure: Structure, entries: Any) -> tuple[Stop, ...]:
    """The checked stops of ``entries`` (a list of dicts with :data:`FIELDS`)."""
    if not isinstance(entries, (list, tuple)) or not entries:
        raise ParameterError("stops", "must be a non-empty list of {name, at, gap, side, "
                                      "contact, k1, c1}")  # fmt: skip
    out: list[Stop] = []
    for i, entry in enumerate(entries):
        if not isinstance(entry, dict):
            raise ParameterError(f"stops[{i}]", f"must be a table of {', '.join(FIELDS)}")
        unknown = sorted(set(entry) - set(FIELDS))
        if unknown:
            raise ParameterError(f"stops[{i}]", f"unknown field {unknown[0]!r} (fields: "
                                                f"{', '.join(FIELDS)})")  # fmt: skip
        missing = [f for f in ("name", "at", "gap", "side") if f not in entry]
        if missing:
            raise ParameterError(f"stops[{i}]", f"missing {missing[0]!r}")
        s = stop(structure, **entry)
        if any(o.name == s.name for o in out):
            raise ParameterError(f"stops.{s.name}", "two stops have this name")
        out.append(s)
    return tuple(out)
