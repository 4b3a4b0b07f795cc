"""Stops: walls fixed to the ground that a structure's point meets across a gap (the vibro-impact
oscillator with a stop; a unilateral contact).  A stop at point ``at`` with gap ``g`` [m] has a
wall at x = +g (``side`` "+"), at x = −g ("-") or both ("both"), and a contact law there:

- ``"linear"``: while the point presses the wall w (w·x > g) it feels −k₁(x − w·g) − c₁ẋ (Eq.
  35's k₁δ with the dashpot c₁δ̇ of the one-mode contact laws), and the contact ends where the
  point comes back to the wall.  A pressed stop adds k₁φφᵀ and c₁φφᵀ to the structure's modal
  stiffness and damping (Step 15's modal form, φ the modes' values at the point), so the flight
  stays closed form.
- ``"rigid"``: Newton's impact law at the point, φᵀq̇⁺ = −e·φᵀq̇⁻, the impulse entering the
  modes through their shapes (Step 15's law, Eq. F7, against a wall of infinite mass: the
  reduced mass is the point's effective mass).  Rebounds that would accumulate (Step 9's test)
  are taken to their accumulation point, and the point then rests on the wall — the structure
  moving in the null space of the held points' shapes — until the wall would have to pull.

:func:`stops` reads a list of ``{"name", "at", "gap", "side", "contact", "k1", "c1" | "e"}``
(the structure file's ``"stops"`` entry; SI numbers or quantity texts such as ``"1 mm"``,
``"2 kN/m"``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..errors import ParameterError
from .checks import bounded
from .structure import Structure
from .units import nonnegative_float, positive_float

#: The fields a stop takes.
FIELDS = ("name", "at", "gap", "side", "contact", "k1", "c1", "e")
#: The contact laws a stop takes.
LAWS = ("linear", "rigid")
#: The walls of each side: +1 the wall at +g, −1 at −g, 0 both.
SIDES = {"+": 1, "-": -1, "both": 0}


@dataclass(frozen=True)
class Stop:
    """A stop at point ``at``: walls at ``side`` ("+": x = +gap, "-": x = −gap, "both"), a
    linear contact of stiffness ``k1`` [N/m] and damping ``c1`` [N s/m], or (``contact``
    "rigid") rigid impacts of restitution ``e``."""

    name: str
    at: str
    gap: float
    side: str
    k1: float
    c1: float
    contact: str = "linear"
    e: float = math.nan

    @property
    def walls(self) -> int:
        """+1: the wall at +gap; −1: at −gap; 0: both."""
        return SIDES[self.side]

    def as_dict(self) -> dict[str, Any]:
        law = {"e": self.e} if self.contact == "rigid" else {"k1": self.k1, "c1": self.c1}
        return {"name": self.name, "at": self.at, "gap": self.gap, "side": self.side,
                "contact": self.contact} | law  # fmt: skip


def stop(structure: Structure, name: Any, at: Any, gap: Any, side: Any = "both",
         contact: Any = "linear", k1: Any = None, c1: Any = None, e: Any = None) -> Stop:  # fmt: skip
    """One checked :class:`Stop` on ``structure`` (its point ``at`` must exist and move)."""
    label = f"stops.{name}"
    if not isinstance(name, str) or not name:
        raise ParameterError("stops.name", f"must be a non-empty text, got {name!r}")
    if contact not in LAWS:
        raise ParameterError(f"{label}.contact", f"one of {', '.join(LAWS)} at a stop so far, "
                                                 f"got {contact!r}")  # fmt: skip
    if side not in SIDES:
        raise ParameterError(f"{label}.side", f'must be "+", "-" or "both", got {side!r}')
    if contact == "rigid":
        for field, value in (("k1", k1), ("c1", c1)):
            if value is not None:
                raise ParameterError(f"{label}.{field}", "a rigid stop takes e, not a spring")
        if e is None:
            raise ParameterError(f"{label}.e", "missing: the restitution of the rigid impacts")
    elif e is not None:
        raise ParameterError(f"{label}.e", "a linear stop takes k1 and c1, not e")
    elif k1 is None:
        raise ParameterError(f"{label}.k1", "missing: the contact stiffness [N/m]")
    try:
        point = structure._point(at)
    except ParameterError as exc:
        raise ParameterError(f"{label}.at", exc.reason) from None
    if all(mode.node_at(point) for mode in structure.modes):
        raise ParameterError(f"{label}.at", f"no mode moves the point {point!r} (a support): "
                                            "the stop would never act")  # fmt: skip
    gap = positive_float(f"{label}.gap", gap, "m")
    if contact == "rigid":
        return Stop(name, point, gap, side, 0.0, 0.0, "rigid", bounded(f"{label}.e", e, 0.0, 1.0))
    return Stop(
        name,
        point,
        gap,
        side,
        positive_float(f"{label}.k1", k1, "N/m"),
        nonnegative_float(f"{label}.c1", 0.0 if c1 is None else c1, "N*s/m"),
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
    check_walls(structure, out)
    return tuple(out)


def check_walls(structure: Structure, stops: Any) -> None:
    """Refuse, in one line naming the second stop, a rigid stop's wall at the place of another
    stop's wall in the modes kept.  Wall w (±1) of a stop of gap g at a point of shapes φ keeps
    wφᵀq ≤ g; two walls whose wφ/g agree (to 1e-9 of their size) are at one place: one point,
    side and gap, or, with few modes, two points whose shapes are proportional and gaps in that
    ratio (one mode: any two points).  Two rigid walls there are one constraint written twice:
    a point held on one is held on the other with the same reaction, the two holds cannot be
    told apart (their constraint matrix is singular), and the engine passed the point from one
    to the other at rounding-level speeds, ten million times in three periods, or stopped on a
    singular matrix.  A linear stop there never presses (the rigid wall keeps the point from
    it) but for rounding, whose contacts at the held point left the ledger open by 3e-9.  Two
    linear walls at one place (springs side by side) are kept, and so are walls elsewhere."""
    seen: list[tuple[np.ndarray, str, str, bool]] = []
    for st in stops:
        rigid = st.contact == "rigid"
        phi = structure.shapes([st.at])[0]
        for wall in (1, -1) if st.walls == 0 else (st.walls,):
            a = wall * phi / st.gap
            where = f"{'+' if wall > 0 else '-'}{st.gap * 1e3:g} mm at point {st.at!r}"
            for b, name, there, other_rigid in seen:
                if (rigid or other_rigid) and name != st.name and (
                        np.linalg.norm(a - b) <= 1e-9 * np.linalg.norm(a)):  # fmt: skip
                    same = (" too" if there == where
                            else f" ({there}) in every motion of the modes kept")  # fmt: skip
                    why = ("one rigid wall there is enough" if rigid and other_rigid
                           else "a linear stop at a rigid wall never presses")  # fmt: skip
                    kind = "rigid" if rigid else "linear"
                    raise ParameterError(f"stops.{st.name}", f"its {kind} wall ({where}) is the "
                                                             f"wall of stop {name!r}{same}: "
                                                             f"{why}")  # fmt: skip
            seen.append((a, st.name, where, rigid))
