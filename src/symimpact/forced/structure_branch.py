"""A branch of periodic orbits of a structure of several modes, continued in the forcing
frequency, with its bifurcations located: :func:`structure_branch`.

Each point is an orbit shot on the state of the N modes and K dampers
(:func:`symimpact.forced.structure_orbits.shoot_structure`, the monodromy carried through every
flight, impact and stop contact).  The next frequency's Newton starts from the secant
extrapolation of the last two orbits (natural-parameter continuation); where it fails the step is
halved, down to a floor, where the branch ends and says why (a fold turns it back; an orbit that
sticks or chatters is not followed yet).  Between two orbits whose count of multipliers outside
the unit circle differs a multiplier has crossed it: the crossing is located by bisection in Ω
(each trial shot from the nearer orbit) and named by where the multiplier crosses — at −1 a
period doubling, at +1 a fold or branch point, elsewhere a Neimark–Sacker point (a pair
e^{±iθ}); where the bracket closes on a change of the impacts a period, the stability changed
at a grazing (the multipliers jump there).  Where the count of impacts or contacts a period changes, an impact was born or died
(a grazing) between the two orbits: it is reported with the counts on both sides.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..errors import MethodNotApplicable, ParameterError
from ..model.checks import whole_number
from ..model.structure import Structure
from ..model.units import positive_float
from .structure_orbits import StructureOrbit, shoot_structure

#: Kinds of the located bifurcations (the last: the stability changes where an impact is born or
#: dies, the multipliers jumping across the circle rather than crossing it).
PERIOD_DOUBLING, FOLD, NEIMARK_SACKER = "period doubling", "fold or branch point", "Neimark-Sacker"
AT_GRAZING = "stability change at a grazing"


@dataclass(frozen=True)
class Bifurcation:
    """A multiplier crossing the unit circle at ``omega`` [rad/s] (located to ``tolerance``)."""

    kind: str
    omega: float
    multiplier: complex
    tolerance: float

    def as_dict(self) -> dict[str, Any]:
        return {"kind": self.kind, "omega": self.omega, "tolerance": self.tolerance,
                "multiplier": [self.multiplier.real, self.multiplier.imag]}  # fmt: skip


@dataclass(frozen=True)
class StructureBranch:
    """The orbits of a branch in the order traced, its bifurcations, its grazings (Ω between
    two orbits and the impact counts on both sides) and why it ended before the band's end."""

    orbits: list[StructureOrbit]
    bifurcations: list[Bifurcation]
    grazings: list[dict[str, Any]] = field(default_factory=list)
    ended: str = ""

    @property
    def omegas(self) -> np.ndarray:
        return np.array([o.run.omega for o in self.orbits])

    def amplitudes(self, point: str) -> np.ndarray:
        """The orbits' largest abs(x) at ``point`` [m]."""
        return np.array([o.amplitudes[point] for o in self.orbits])

    def as_dict(self) -> dict[str, Any]:
        return {
            "points": [_point(o) for o in self.orbits],
            "bifurcations": [b.as_dict() for b in self.bifurcations],
            "grazings": self.grazings,
            "ended": self.ended,
        }


def _point(o: StructureOrbit) -> dict[str, Any]:
    return {"omega": o.run.omega, "amplitudes": o.amplitudes, "stable": o.stable,
            "largest_multiplier": float(max(abs(o.multipliers))), "impacts": o.impacts}  # fmt: skip


def _unstable(o: StructureOrbit) -> int:
    """The multipliers outside the unit circle (a damper that meets no wall excepted)."""
    return int(np.sum(np.abs(o.multipliers) > 1.0)) if not o.stable else 0


def _crossing(o: StructureOrbit) -> complex:
    """The multiplier nearest the unit circle."""
    m = o.multipliers
    return complex(m[int(np.argmin(np.abs(np.abs(m) - 1.0)))])


def structure_branch(structure: Structure, dampers: Any, force_at: Any, F0: Any,
                     omega_start: Any, omega_end: Any, state: Any, periods: Any = 1,
                     stops: Any = (), step: Any = None, phase: Any = 0.0,
                     locate: float = 1e-9) -> StructureBranch:  # fmt: skip
    """Continue the period-``periods`` orbit near ``state`` at ``omega_start`` to ``omega_end``
    [rad/s] (either direction; module text), with a first step ``step`` (default 1/100 of the
    band) that grows to it again after halvings; bifurcations located to ``locate`` of Ω."""
    w0 = positive_float("omega_start", omega_start, "rad/s")
    w1 = positive_float("omega_end", omega_end, "rad/s")
    if w0 == w1:
        raise ParameterError("omega_end", "must differ from omega_start")
    k = whole_number("periods", periods, 1)
    band = abs(w1 - w0)
    h_max = band / 100.0 if step is None else positive_float("step", step, "rad/s")
    h_max = min(h_max, band)
    direction = math.copysign(1.0, w1 - w0)
    args = (structure, dampers, force_at, F0)

    def shot(w: float, s: np.ndarray) -> StructureOrbit:
        return shoot_structure(*args, w, s, k, stops, phase, max_iterations=12)

    orbits = [shot(w0, np.asarray(state, dtype=float))]
    bifurcations: list[Bifurcation] = []
    grazings: list[dict[str, Any]] = []
    h, h_min = h_max, band * 1e-7
    ended = ""
    while direction * (w1 - orbits[-1].run.omega) > 1e-12 * band:
        last = orbits[-1]
        w = last.run.omega + direction * min(h, abs(w1 - last.run.omega))
        guess = last.state
        if len(orbits) > 1:  # the secant through the last two orbits
            prev = orbits[-2]
            slope = (last.state - prev.state) / (last.run.omega - prev.run.omega)
            guess = last.state + slope * (w - last.run.omega)
        try:
            o = shot(w, guess)
        except (MethodNotApplicable, ParameterError) as exc:
            if h / 2.0 < h_min:
                ended = (f"at Ω {last.run.omega:.9g} rad/s no orbit is found a step further "
                         f"({exc})")  # fmt: skip
                break
            h /= 2.0
            continue
        if _unstable(o) != _unstable(last):
            bifurcations.append(_locate(shot, last, o, locate))
        if o.impacts != last.impacts:
            grazings.append({"between": [last.run.omega, o.run.omega], "before": last.impacts,
                             "after": o.impacts})  # fmt: skip
        orbits.append(o)
        h = min(2.0 * h, h_max)
    return StructureBranch(orbits, bifurcations, grazings, ended)


def _locate(shot, a: StructureOrbit, b: StructureOrbit, tol: float) -> Bifurcation:
    """Bisection in Ω between orbits ``a`` and ``b`` on either side of a crossing, each trial
    shot from the nearer side's orbit, to ``tol`` of Ω."""
    lo, hi = a, b
    side = _unstable(a)
    while abs(hi.run.omega - lo.run.omega) > tol * abs(hi.run.omega):
        w = 0.5 * (lo.run.omega + hi.run.omega)
        try:
            mid = shot(w, lo.state)
        except (MethodNotApplicable, ParameterError):
            break
        if _unstable(mid) == side:
            lo = mid
        else:
            hi = mid
    lam = _crossing(hi if abs(abs(_crossing(hi)) - 1) < abs(abs(_crossing(lo)) - 1) else lo)
    angle = abs(math.atan2(lam.imag, lam.real))
    if lo.impacts != hi.impacts:
        kind = AT_GRAZING
    elif angle > math.pi - 1e-3:
        kind = PERIOD_DOUBLING
    elif angle < 1e-3:
        kind = FOLD
    else:
        kind = NEIMARK_SACKER
    omega = 0.5 * (lo.run.omega + hi.run.omega)
    return Bifurcation(kind, omega, lam, abs(hi.run.omega - lo.run.omega))
