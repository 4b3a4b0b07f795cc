"""A branch of periodic orbits of a structure of several modes, continued in the forcing
frequency (:func:`structure_branch`) or, at a fixed frequency, in a damper's clearance,
restitution or mass or the force amplitude (:func:`parameter_branch`), with its bifurcations
located.

Each point is an orbit shot on the state of the N modes and K dampers
(:func:`symimpact.forced.orbits.structure_orbits.shoot_structure`, the monodromy carried through every
flight, impact, stop contact, chatter's accumulation, sticking phase and release, and differenced
where the run is not differentiated so: that function's text).  The next value's
Newton starts from the secant extrapolation of the last two orbits (natural-parameter
continuation); where it fails the step is halved, down to a floor, where the branch ends and says
why (a fold turns it back).  Between two orbits whose count of multipliers outside
the unit circle differs a multiplier has crossed it: the crossing is located by bisection in the
parameter (each trial shot from the nearer orbit) and named by where the multiplier crosses — at −1 a
period doubling, at +1 a fold or branch point, elsewhere a Neimark–Sacker point (a pair
e^{±iθ}); where the bracket closes on a change of the impacts a period, the stability changed
at a grazing (the multipliers jump there).  Where the count of impact events or contacts a period changes (a
chatter sequence counted once, :attr:`~symimpact.forced.orbits.structure_orbits.StructureOrbit.
impact_events`, so that how many of its impacts are resolved does not count), an impact was born
or died (a grazing) between the two orbits: it is reported with the counts on both sides.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ...errors import MethodNotApplicable, ParameterError
from ...model.checks import whole_number
from ...model.structure import Structure
from ...model.units import positive_float
from .structure_orbits import StructureOrbit, shoot_structure

#: Kinds of the located bifurcations (the last: the stability changes where an impact is born or
#: dies, the multipliers jumping across the circle rather than crossing it).
PERIOD_DOUBLING, FOLD, NEIMARK_SACKER = "period doubling", "fold or branch point", "Neimark-Sacker"
AT_GRAZING = "stability change at a grazing"


@dataclass(frozen=True)
class Bifurcation:
    """A multiplier crossing the unit circle at ``value`` of the branch's ``parameter`` (Ω
    [rad/s], or one of :data:`PARAMETERS` in SI), located to ``tolerance``."""

    kind: str
    value: float
    multiplier: complex
    tolerance: float
    #: the orbits at the bracket's two ends (within ``tolerance`` of each other)
    sides: tuple[StructureOrbit, StructureOrbit]
    parameter: str = "omega"

    @property
    def omega(self) -> float:
        """The forcing frequency Ω [rad/s] of the bifurcation: the located value on a branch in
        Ω, else the branch's fixed Ω."""
        return self.value if self.parameter == "omega" else self.sides[0].run.omega

    def as_dict(self) -> dict[str, Any]:
        located = {} if self.parameter == "omega" else {"parameter": self.parameter,
                                                        "value": self.value}  # fmt: skip
        return {"kind": self.kind, **located, "omega": self.omega, "tolerance": self.tolerance,
                "multiplier": [self.multiplier.real, self.multiplier.imag]}  # fmt: skip


@dataclass(frozen=True)
class StructureBranch:
    """The orbits of a branch in the order traced, its bifurcations, its grazings (Ω between
    two orbits and the impact counts on both sides) and why it ended before the band's end."""

    orbits: list[StructureOrbit]
    bifurcations: list[Bifurcation]
    grazings: list[dict[str, Any]] = field(default_factory=list)
    ended: str = ""
    #: the orbits at the ends of each located bracket (bifurcations and grazings), beside the
    #: traced ones: where a stable stretch ends
    edges: list[StructureOrbit] = field(default_factory=list)
    #: what the branch is continued in: "omega", or one of :data:`PARAMETERS`
    parameter: str = "omega"
    #: the damper whose ``gap``, ``e`` or ``m`` is continued (else "")
    damper: str = ""

    @property
    def omegas(self) -> np.ndarray:
        return np.array([o.run.omega for o in self.orbits])

    @property
    def values(self) -> np.ndarray:
        """The parameter's value at each orbit (SI; Ω [rad/s] on a branch in Ω)."""
        value = _value_of(self.parameter, self.damper)
        return np.array([value(o) for o in self.orbits])

    def amplitudes(self, point: str) -> np.ndarray:
        """The orbits' largest abs(x) at ``point`` [m]."""
        return np.array([o.amplitudes[point] for o in self.orbits])

    def as_dict(self) -> dict[str, Any]:
        value = _value_of(self.parameter, self.damper)
        located = ({} if self.parameter == "omega" else
                   {"parameter": self.parameter, "damper": self.damper or None})  # fmt: skip
        extra = (lambda o: {}) if self.parameter == "omega" else (lambda o: {"value": value(o)})
        return located | {
            "points": [_point(o) | extra(o) for o in self.orbits],
            "bifurcations": [b.as_dict() for b in self.bifurcations],
            "grazings": self.grazings,
            "ended": self.ended,
        }


#: What :func:`parameter_branch` continues at a fixed Ω, with its SI unit: a damper's total
#: clearance, restitution or mass, or the force amplitude.
PARAMETERS = {"gap": "m", "e": "", "m": "kg", "F0": "N"}


def _value_of(parameter: str, damper: str):
    """The function giving an orbit's value of ``parameter`` (of damper ``damper``)."""
    if parameter == "omega":
        return lambda o: o.run.omega
    if parameter == "F0":
        return lambda o: o.run.F0

    def value(o: StructureOrbit) -> float:
        return float(getattr(next(d for d in o.run.dampers if d.name == damper), parameter))

    return value


def _base_at(base: Any, omega: float) -> float:
    """X_b [m] at Ω: ``base`` is the supports' displacement amplitude, or a function of Ω giving
    it (a constant acceleration level: :meth:`~symimpact.model.structure_model.StructureModel.
    base_at`)."""
    return float(base(omega)) if callable(base) else float(base)


def _returns_after(o: StructureOrbit, periods: int, args: tuple, stops: Any, phase: float) -> bool:
    """Whether orbit ``o`` comes back after ``periods`` (to 1e-6 of its state's size): an orbit
    of fewer periods than it was shot for."""
    from ..structure_response import simulate_structure

    run = simulate_structure(*args, o.run.omega, periods=periods, phase=phase, state=o.state,
                             base=o.run.X_b, stops=stops, energy=False)  # fmt: skip
    n = len(o.state)
    gap = np.linalg.norm(run.final_state[1 : 1 + n] - o.state)
    return bool(gap <= 1e-6 * np.linalg.norm(o.state))


def _point(o: StructureOrbit) -> dict[str, Any]:
    return {"omega": o.run.omega, "amplitudes": o.amplitudes, "stable": o.stable,
            "largest_multiplier": float(max(abs(o.multipliers))), "impacts": o.impacts,
            "impact_events": o.impact_events, "jacobian": o.jacobian}  # fmt: skip


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
                     locate: float = 1e-9, base: Any = 0.0) -> StructureBranch:  # fmt: skip
    """Continue the period-``periods`` orbit near ``state`` at ``omega_start`` to ``omega_end``
    [rad/s] (either direction; module text), with a first step ``step`` (default 1/100 of the
    band) that grows to it again after halvings; bifurcations located to ``locate`` of Ω.
    ``base``: the supports' displacement amplitude X_b [m], or a function of Ω giving it."""
    w0 = positive_float("omega_start", omega_start, "rad/s")
    w1 = positive_float("omega_end", omega_end, "rad/s")
    if w0 == w1:
        raise ParameterError("omega_end", "must differ from omega_start")
    k = whole_number("periods", periods, 1)
    h = None if step is None else positive_float("step", step, "rad/s")
    args = (structure, dampers, force_at, F0)

    def shot(w: float, s: np.ndarray) -> StructureOrbit:
        o = shoot_structure(*args, w, s, k, stops, phase, max_iterations=12,
                            base=_base_at(base, w))  # fmt: skip
        if k % 2 == 0 and _returns_after(o, k // 2, args, stops, phase):
            # near a doubling the parent, of half the period, is a fixed point of this map too
            raise MethodNotApplicable("structure_branch", f"the orbit at Ω {w:.9g} rad/s is the "
                                      f"one of {k // 2} period(s): Newton left the branch")  # fmt: skip
        return o

    return _trace(shot, "omega", "", w0, w1, state, h, locate)


def _trace(shot, parameter: str, damper: str, p0: float, p1: float, state: Any,
           step: float | None, locate: float) -> StructureBranch:  # fmt: skip
    """Natural-parameter continuation from p0 to p1 (module text): ``shot(p, guess)`` is the
    orbit at parameter value p shot from ``guess``."""
    value = _value_of(parameter, damper)
    name, unit = ("Ω", "rad/s") if parameter == "omega" else (parameter, PARAMETERS[parameter])
    band = abs(p1 - p0)
    h_max = band / 100.0 if step is None else step
    h_max = min(h_max, band)
    direction = math.copysign(1.0, p1 - p0)
    orbits = [shot(p0, np.asarray(state, dtype=float))]
    bifurcations: list[Bifurcation] = []
    grazings: list[dict[str, Any]] = []
    edges: list[StructureOrbit] = []
    h, h_min = h_max, band * 1e-7
    ended = ""
    while direction * (p1 - value(orbits[-1])) > 1e-12 * band:
        last = orbits[-1]
        at = value(last)
        w = at + direction * min(h, abs(p1 - at))
        guess = last.state
        if len(orbits) > 1:  # the secant through the last two orbits
            prev = orbits[-2]
            slope = (last.state - prev.state) / (at - value(prev))
            guess = last.state + slope * (w - at)
        try:
            o = shot(w, guess)
        except (MethodNotApplicable, ParameterError) as exc:
            if h / 2.0 < h_min:
                ended = (f"at {name} {at:.9g}{' ' + unit if unit else ''} no orbit is found a "
                         f"step further ({exc})")  # fmt: skip
                break
            h /= 2.0
            continue
        if _unstable(o) != _unstable(last):
            found = _locate(shot, last, o, locate, value, parameter)
            bifurcations.append(found)
            edges.extend(found.sides)
        if o.impact_events != last.impact_events:
            before = last.impact_events
            a, b = _bisect(shot, last, o, locate,
                           lambda x, before=before: x.impact_events == before, value)  # fmt: skip
            grazings.append({"between": [value(a), value(b)], "before": last.impact_events,
                             "after": o.impact_events})  # fmt: skip
            edges.extend((a, b))
        orbits.append(o)
        h = min(2.0 * h, h_max)
    return StructureBranch(orbits, bifurcations, grazings, ended, edges, parameter, damper)


def parameter_branch(structure: Structure, dampers: Any, force_at: Any, F0: Any, omega: Any,
                     parameter: str, start: Any, end: Any, state: Any, damper: Any = None,
                     periods: Any = 1, stops: Any = (), step: Any = None, phase: Any = 0.0,
                     locate: float = 1e-9, base: Any = 0.0) -> StructureBranch:  # fmt: skip
    """Continue the period-``periods`` orbit near ``state`` at a fixed Ω ``omega`` [rad/s] in
    ``parameter`` (:data:`PARAMETERS`: damper ``damper``'s total clearance ``gap`` [m],
    restitution ``e`` or mass ``m`` [kg], or the force amplitude ``F0`` [N]) from ``start`` (the
    value ``state`` belongs to) to ``end``, as :func:`structure_branch` continues in Ω: the
    same shooting (the monodromy through every flight, impact and contact, Step 15), steps and
    location of bifurcations and grazings, to ``locate`` of the value."""
    from dataclasses import replace

    from ...model.dampers import Damper

    if parameter not in PARAMETERS:
        raise ParameterError("parameter", f"one of {', '.join(PARAMETERS)}, got {parameter!r}")
    w = positive_float("omega", omega, "rad/s")
    dampers = tuple(dampers)
    unit = PARAMETERS[parameter]
    bounds = []
    for label, v in (("start", start), ("end", end)):
        x = positive_float(label, v, unit) if unit else positive_float(label, v)
        if parameter == "e" and x > 1.0:
            raise ParameterError(label, f"a restitution lies in (0, 1], got {x:g}")
        bounds.append(x)
    p0, p1 = bounds
    if p0 == p1:
        raise ParameterError("end", "must differ from start")
    name = ""
    if parameter != "F0":
        names = [d.name for d in dampers]
        if damper is None and len(names) == 1:
            damper = names[0]
        if damper not in names:
            raise ParameterError("damper", f"name the damper whose {parameter} is continued "
                                           f"(the dampers: {', '.join(names) or 'none'})")  # fmt: skip
        name = str(damper)
        chosen = next(d for d in dampers if d.name == name)
        if parameter == "e" and not getattr(chosen, "rigid", True):
            raise ParameterError("parameter", f"damper {name!r} has a {chosen.contact} contact: "
                                              "it has no restitution e to continue in")  # fmt: skip
    k = whole_number("periods", periods, 1)
    h = None if step is None else (positive_float("step", step, unit) if unit
                                   else positive_float("step", step))  # fmt: skip

    def shot(p: float, s: np.ndarray) -> StructureOrbit:
        force, ds = F0, dampers
        if parameter == "F0":
            force = p
        else:
            ds = tuple(replace(d, **{parameter: p}) if isinstance(d, Damper) and d.name == name
                       else d for d in dampers)  # fmt: skip
        o = shoot_structure(structure, ds, force_at, force, w, s, k, stops, phase,
                            max_iterations=12, base=_base_at(base, w))  # fmt: skip
        if k % 2 == 0 and _returns_after(o, k // 2, (structure, ds, force_at, force), stops,
                                         phase):  # fmt: skip
            raise MethodNotApplicable("parameter_branch", f"the orbit at {parameter} {p:.9g} is "
                                      f"the one of {k // 2} period(s): Newton left the branch")  # fmt: skip
        return o

    return _trace(shot, parameter, name, p0, p1, state, h, locate)


def _omega(o: StructureOrbit) -> float:
    return o.run.omega


def _bisect(shot, a: StructureOrbit, b: StructureOrbit, tol: float, like_a,
            value=_omega) -> tuple:  # fmt: skip
    """(lo, hi): the orbits within ``tol`` of the parameter (``value`` of an orbit; Ω) of each
    other between which ``like_a`` turns false, by bisection from ``a`` (true) and ``b``
    (false), each trial shot from ``lo`` (or from ``hi`` where that fails); a bracket no trial
    narrows is returned as it stands."""
    lo, hi = a, b
    while abs(value(hi) - value(lo)) > tol * abs(value(hi)):
        w = 0.5 * (value(lo) + value(hi))
        try:
            mid = shot(w, lo.state)
        except (MethodNotApplicable, ParameterError):
            try:  # near a grazing Newton may only converge from the other side
                mid = shot(w, hi.state)
            except (MethodNotApplicable, ParameterError):
                break
        if like_a(mid):
            lo = mid
        else:
            hi = mid
    return lo, hi


def _locate(shot, a: StructureOrbit, b: StructureOrbit, tol: float, value=_omega,
            parameter: str = "omega") -> Bifurcation:  # fmt: skip
    """Bisection in the parameter (``value`` of an orbit; Ω) between orbits ``a`` and ``b`` on
    either side of a crossing, each trial shot from the nearer side's orbit, to ``tol`` of
    it."""
    side = _unstable(a)
    lo, hi = _bisect(shot, a, b, tol, lambda x: _unstable(x) == side, value)
    lam = _crossing(hi if abs(abs(_crossing(hi)) - 1) < abs(abs(_crossing(lo)) - 1) else lo)
    angle = abs(math.atan2(lam.imag, lam.real))
    if lo.impact_events != hi.impact_events:
        kind = AT_GRAZING
    elif angle > math.pi - 1e-3:
        kind = PERIOD_DOUBLING
    elif angle < 1e-3:
        kind = FOLD
    else:
        kind = NEIMARK_SACKER
    at = 0.5 * (value(lo) + value(hi))
    return Bifurcation(kind, at, lam, abs(value(hi) - value(lo)), (lo, hi), parameter)


@dataclass(frozen=True)
class StructurePeak:
    """The largest stable amplitude at a point over some branches [m], at ``omega`` [rad/s]:
    ``kind`` "maximum" (located along a branch, between orbits of one impact sequence) or
    "end" (the last stable orbit before a stability change, a grazing or the band's edge)."""

    point: str
    amplitude: float
    omega: float
    kind: str

    def as_dict(self) -> dict[str, Any]:
        return {"point": self.point, "amplitude": self.amplitude, "omega": self.omega,
                "kind": self.kind}  # fmt: skip


def located_peak(structure: Structure, dampers: Any, force_at: Any, F0: Any,
                 branches: list[StructureBranch], point: str, stops: Any = (),
                 phase: float = 0.0, base: Any = 0.0) -> StructurePeak | None:  # fmt: skip
    """The largest stable amplitude at ``point`` over ``branches``: the best traced orbit or
    stable orbit at a located bracket's end (a bifurcation's or a grazing's, to 1e-9 of Ω), and
    where the best traced orbit's neighbours on the branch are stable orbits of the same impacts (so the amplitude
    is smooth there), the maximum between them located by Brent's bounded search on Ω
    (scipy.optimize.minimize_scalar, to 1e-10 of Ω), each trial shot from the best orbit.  None
    when no traced orbit is stable."""
    from scipy.optimize import minimize_scalar

    best: tuple[float, int, int] | None = None
    for b, branch in enumerate(branches):
        for i, o in enumerate(branch.orbits):
            if o.stable and (best is None or o.amplitudes[point] > best[0]):
                best = (o.amplitudes[point], b, i)
    ends = [o for branch in branches for o in branch.edges if o.stable]
    if best is None and not ends:
        return None
    end = max(ends, key=lambda o: o.amplitudes[point], default=None)
    if best is None or (end is not None and end.amplitudes[point] > best[0]):
        return StructurePeak(point, end.amplitudes[point], end.run.omega, "end")
    _, b, i = best
    orbits = branches[b].orbits
    o = orbits[i]
    peak = StructurePeak(point, o.amplitudes[point], o.run.omega, "end")
    if not 0 < i < len(orbits) - 1:
        return peak
    lo, hi = orbits[i - 1], orbits[i + 1]
    if not (lo.stable and hi.stable and lo.impact_events == o.impact_events == hi.impact_events):
        return peak
    a, c = sorted((lo.run.omega, hi.run.omega))

    def minus_amplitude(w: float) -> float:
        try:
            trial = shoot_structure(structure, dampers, force_at, F0, w, o.state, o.periods,
                                    stops, phase, max_iterations=12,
                                    base=_base_at(base, w))  # fmt: skip
        except (MethodNotApplicable, ParameterError):
            return -0.0
        return -trial.amplitudes[point] if trial.impact_events == o.impact_events else -0.0

    found = minimize_scalar(minus_amplitude, bounds=(a, c), method="bounded",
                            options={"xatol": 1e-10 * c})  # fmt: skip
    if -found.fun >= peak.amplitude:
        return StructurePeak(point, float(-found.fun), float(found.x), "maximum")
    return peak


def doubled_branch(structure: Structure, dampers: Any, force_at: Any, F0: Any,
                   bifurcation: Bifurcation, omega_end: Any, stops: Any = (),
                   phase: float = 0.0, base: Any = 0.0) -> StructureBranch | None:  # fmt: skip
    """The branch of twice the period born at a period doubling, continued to ``omega_end``
    [rad/s]: its first orbit is shot on the side where the parent is unstable (the daughter of a
    supercritical doubling lives there), a small step past the located point, from the parent's
    state pushed along the eigenvector of its multiplier −1 — by 10⁻³ of the state's size,
    then 10⁻², then 10⁻¹ — and kept when it is genuinely of twice the period (its state after
    half its periods differs from it by more than 10⁻⁶ of its size; so is every orbit the
    continuation keeps, which near the doubling could otherwise fall back on the parent, a fixed
    point of the doubled map too).  None when no push finds one (a
    subcritical doubling: its daughter is unstable and lives on the other side)."""
    if bifurcation.kind != PERIOD_DOUBLING:
        raise ParameterError("bifurcation", f"a period doubling, got a {bifurcation.kind}")
    lo, hi = bifurcation.sides
    unstable = hi if _unstable(hi) > _unstable(lo) else lo
    k = unstable.periods
    w_end = positive_float("omega_end", omega_end, "rad/s")
    direction = math.copysign(1.0, unstable.run.omega - bifurcation.omega)
    if direction * (w_end - bifurcation.omega) <= 0.0:
        raise ParameterError("omega_end", "must lie on the side of the doubling where the parent "
                                          "orbit is unstable")  # fmt: skip
    G = unstable.run.monodromy
    values, vectors = np.linalg.eig(G)
    v = np.real(vectors[:, int(np.argmin(np.abs(values + 1.0)))])
    scale = float(np.linalg.norm(unstable.state))
    w = bifurcation.omega + direction * 1e-4 * abs(w_end - bifurcation.omega)
    for push in (1e-3, 1e-2, 1e-1):
        try:
            o = shoot_structure(structure, dampers, force_at, F0, w,
                                unstable.state + push * scale * v / np.linalg.norm(v), 2 * k,
                                stops, phase, max_iterations=20,
                                base=_base_at(base, w))  # fmt: skip
        except (MethodNotApplicable, ParameterError):
            continue
        if not _returns_after(o, k, (structure, dampers, force_at, F0), stops, phase):
            return structure_branch(structure, dampers, force_at, F0, w, w_end, o.state, 2 * k,
                                    stops, phase=phase, base=base)  # fmt: skip
    return None


#: The periods over which a run from rest's largest displacements are read, after its transient.
KEPT = 40
#: A run from rest waits until the structure's slowest free transient has fallen to this share
#: of its start (the rule of the one-mode runs: :func:`symimpact.forced.simulation.
#: settling_periods`).
SETTLED = 1e-6
#: At most this many periods of transient (an undamped mode never settles).
MOST = 300


def settling_periods(structure: Structure, omega: float, settled: float = SETTLED,
                     most: int = MOST) -> int:  # fmt: skip
    """Forcing periods at Ω = ``omega`` [rad/s] for the slowest free transient of the
    structure's modes, exp(−min ζᵢωᵢ·t) (each mode's free decay, Step 8 per mode), to fall to
    ``settled`` of its start; at most ``most`` (an undamped mode: ``most``)."""
    decay = min(m.zeta * m.omega for m in structure.modes)  # [1/s]
    if not decay > 0:
        return most
    return min(most, math.ceil(-math.log(settled) / decay / (2.0 * math.pi / omega)))


@dataclass(frozen=True)
class StructureCurve:
    """A structure's response curve over a band: the traced branches, the runs from rest at
    each frequency of the band's grid (``settled``: {"omega", "periods", "amplitudes": {point:
    m}}, each point's largest abs(x) over the run's last KEPT periods) and notes."""

    branches: list[StructureBranch]
    settled: list[dict[str, Any]]
    notes: list[str]

    def as_dict(self) -> dict[str, Any]:
        return {"branches": [dict(b.as_dict(), periods=b.orbits[0].periods)
                             for b in self.branches],
                "settled": self.settled, "notes": self.notes}  # fmt: skip


def curve_grid(omega_low: float, omega_high: float, step: float) -> np.ndarray:
    """The frequencies [rad/s] of a structure's curve over [omega_low, omega_high]: every
    ``step`` from omega_low, and omega_high last."""
    lo, hi = positive_float("omega_low", omega_low), positive_float("omega_high", omega_high)
    step = positive_float("step", step)
    if not hi > lo:
        raise ParameterError("omega_high", "must be above omega_low")
    grid = np.arange(lo, hi + 0.5 * step, step)
    grid[-1] = min(grid[-1], hi)
    if grid[-1] < hi:
        grid = np.append(grid, hi)
    return grid


def settled_run(structure: Structure, dampers: Any, force_at: Any, F0: Any, omega: float,
                stops: Any = (), warmup: Any = None,
                base: Any = 0.0) -> tuple[dict[str, Any], np.ndarray]:  # fmt: skip
    """One run from rest of a structure's curve (:func:`structure_curve`) at ``omega`` [rad/s]:
    ``warmup`` periods of transient (None: :func:`settling_periods`) and KEPT more; its entry
    {"omega", "periods", "amplitudes": {point: m}} (each point's largest abs(x) over the KEPT
    periods) and its final state (t, the N modes' and K dampers' states, ...)."""
    from ..structure_response import simulate_structure

    waited = settling_periods(structure, float(omega)) if warmup is None else warmup
    run = simulate_structure(structure, dampers, force_at, F0, float(omega), periods=waited + KEPT,
                             stops=stops, base=_base_at(base, float(omega)),
                             energy=False)  # fmt: skip
    kept = run.period_max[waited:]  # the KEPT periods after the transient
    entry = {"omega": float(omega), "periods": waited + KEPT,
             "amplitudes": {p: float(kept[:, j].max()) for j, p in enumerate(run.points)}}  # fmt: skip
    return entry, run.final_state


def structure_curve(structure: Structure, dampers: Any, force_at: Any, F0: Any, omega_low: float,
                    omega_high: float, step: float, stops: Any = (), warmup: Any = None,
                    base: Any = 0.0, runs: Any = None) -> StructureCurve:  # fmt: skip
    """The structure's response curve over [omega_low, omega_high] [rad/s]: a run from rest at
    every frequency of the grid of ``step`` (:func:`curve_grid`, :func:`settled_run`: ``warmup``
    periods of transient, None: until the slowest mode's free transient has fallen to SETTLED,
    and KEPT periods read for the largest displacements; ``runs``: those runs' results, in the
    grid's order, computed elsewhere, e.g. on several processes by
    :func:`symimpact.maps.structure_curve.structure_curve_map`); a branch continued from each
    end of the band (steps up to ``step``), each started from the orbit the run there settles
    on, of the fewest periods it comes back after (1 to 8, to 1e-6 of the state); and the
    period-doubled branch of each period doubling they locate (:func:`doubled_branch`).  The
    runs from rest hold the motions no branch follows (orbits that stick or chatter, motions
    that are not periodic).  A note says where no branch could start or where a doubling has
    no stable daughter."""
    from ..structure_response import simulate_structure

    args = (structure, dampers, force_at, F0)
    n = 2 * len(structure.modes) + 2 * len(tuple(dampers))
    branches: list[StructureBranch] = []
    notes: list[str] = []
    grid = curve_grid(omega_low, omega_high, step)
    if warmup is not None:
        warmup = whole_number("warmup", warmup, 0)
    if runs is None:
        runs = [settled_run(*args, float(w), stops, warmup, base) for w in grid]
    if [r[0]["omega"] for r in runs] != [float(w) for w in grid]:
        raise ParameterError("runs", "must be the runs at the curve's grid, in its order")
    settled = [entry for entry, _ in runs]
    ends = {float(grid[0]): runs[0], float(grid[-1]): runs[-1]}
    for w0, w1 in ((omega_low, omega_high), (omega_high, omega_low)):
        start, final = ends[float(grid[0] if w0 == omega_low else grid[-1])]
        s = final[1 : 1 + n]
        for k in range(1, 9):
            back = simulate_structure(*args, w0, periods=k, state=s, stops=stops,
                                      base=_base_at(base, w0), energy=False)  # fmt: skip
            if np.linalg.norm(back.final_state[1 : 1 + n] - s) <= 1e-6 * np.linalg.norm(s):
                break
        else:
            notes.append(f"at Ω {w0:.6g} rad/s the motion {start['periods']} periods "
                         "from rest is not an orbit of up to 8 periods (quasi-periodic or "
                         "chaotic): no branch from there")  # fmt: skip
            continue
        try:
            branches.append(structure_branch(*args, w0, w1, s, k, stops, step=step, base=base))
        except (MethodNotApplicable, ParameterError) as exc:
            notes.append(f"no branch from Ω {w0:.6g} rad/s: {exc}")
    for b in list(branches):
        for f in b.bifurcations:
            if f.kind != PERIOD_DOUBLING:
                continue
            lo_side, hi_side = f.sides
            unstable = hi_side if _unstable(hi_side) > _unstable(lo_side) else lo_side
            end = omega_high if unstable.run.omega > f.omega else omega_low
            try:
                d = doubled_branch(*args, f, end, stops, base=base)
            except (MethodNotApplicable, ParameterError) as exc:
                notes.append(f"no branch from the period doubling at Ω {f.omega:.6g} rad/s: "
                             f"{exc}")  # fmt: skip
                continue
            if d is None:
                notes.append(f"the period doubling at Ω {f.omega:.6g} rad/s has no stable "
                             "daughter on its unstable side (subcritical)")  # fmt: skip
            else:
                branches.append(d)
    return StructureCurve(branches, settled, notes)


def curve_peak(structure: Structure, dampers: Any, force_at: Any, F0: Any,
               curve: StructureCurve, point: str, stops: Any = (),
               base: Any = 0.0) -> StructurePeak | None:  # fmt: skip
    """The largest steady amplitude at ``point`` over the curve: the located peak of its
    branches (:func:`located_peak`), or, where a run from rest settled on a larger motion that
    no traced branch holds, that run's (kind "run from rest": a grid sample)."""
    peak = located_peak(structure, dampers, force_at, F0, curve.branches, point, stops,
                        base=base)  # fmt: skip
    run = max(curve.settled, key=lambda r: r["amplitudes"][point], default=None)
    if run is not None and (peak is None or run["amplitudes"][point] > peak.amplitude):
        return StructurePeak(point, run["amplitudes"][point], run["omega"], "run from rest")
    return peak


def bare_amplitude(
    structure: Structure, force_at: Any, F0: Any, point: Any, omega: float, base: Any = 0.0
) -> float:
    """The bare structure's (no damper, no stop) steady amplitude at ``point`` [m] at ``omega``
    [rad/s]: abs(F₀·H(p, f; Ω) + X_b·T(p; Ω)), the modal receptance and, on supports moving by
    X_b cos(Ωt + φ) in phase with the force (``base``: X_b [m] or a function of Ω giving it),
    the base transmissibility (Eq. F7 in the frequency domain; the absolute displacement)."""
    x = structure.receptance(point, force_at, omega) * float(F0)
    X_b = _base_at(base, omega)
    if X_b != 0.0:
        x = x + structure.base_transmissibility(point, omega) * X_b
    return float(abs(x))


def bare_curve(
    structure: Structure,
    force_at: Any,
    F0: Any,
    point: Any,
    omega_low: float,
    omega_high: float,
    base: Any = 0.0,
    n: int = 400,
) -> tuple[np.ndarray, np.ndarray]:
    """(Ω [rad/s], amplitude [m]) of the bare structure at ``point`` at ``n`` frequencies evenly
    over [omega_low, omega_high] (:func:`bare_amplitude`): the curve a figure draws, and the grid
    :func:`bare_peak` refines its maximum from."""
    w = np.linspace(omega_low, omega_high, n)
    return w, np.array([bare_amplitude(structure, force_at, F0, point, x, base) for x in w])


def bare_peak(structure: Structure, force_at: Any, F0: Any, point: Any, omega_low: float,
              omega_high: float, base: Any = 0.0) -> StructurePeak:  # fmt: skip
    """The bare structure's (no damper, no stop) largest steady amplitude at ``point`` over the
    band: max abs(F₀·H(p, f; Ω) + X_b·T(p; Ω)) of the modal receptance and, on supports moving
    by X_b cos(Ωt + φ) in phase with the force (``base``: X_b [m] or a function of Ω giving
    it), the base transmissibility (Eq. F7 in the frequency domain; the absolute displacement),
    the grid's best of 200 frequencies refined by Brent's bounded search (to 1e-12 of Ω)."""
    from scipy.optimize import minimize_scalar

    def minus(w: float) -> float:
        return -bare_amplitude(structure, force_at, F0, point, w, base)

    grid, amplitudes = bare_curve(structure, force_at, F0, point, omega_low, omega_high, base, 200)
    values = -amplitudes
    i = int(np.argmin(values))
    a, c = grid[max(i - 1, 0)], grid[min(i + 1, len(grid) - 1)]
    found = minimize_scalar(minus, bounds=(a, c), method="bounded", options={"xatol": 1e-12 * c})
    w = float(found.x) if found.fun <= values[i] else float(grid[i])
    kind = "maximum" if omega_low < w < omega_high else "end"
    return StructurePeak(str(point), -minus(w), w, kind)
