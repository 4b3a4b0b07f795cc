"""The peak of a frequency-response curve, located rather than sampled: the largest amplitude
of the primary over the band among the steady motions the curve holds, and the same for the
primary without the damper.

- **Stable orbits** (:func:`stable_peak`): along each branch, every stable point in the band;
  where the amplitude has an interior maximum on a run of stable points, that maximum located
  by Brent's method in the parameter, each trial orbit found by Newton's method from the
  branch's interpolated state (:func:`symimpact.forced.orbits.continuation.orbit_between`); the
  located bifurcations that end a stable run (fold, branch point, period doubling,
  Neimark–Sacker, grazing: there the amplitude is the supremum of the stable ones); and the
  orbits exactly at the band's edges.
- **The motion without impacts** (:func:`no_impact_peak`): the primary's linear response X(Ω)
  (Step 8, Eq. F1) on the Ω intervals where it stays inside the clearance, X < d/2: the
  resonance peak if inside one, else the interval's end nearer to it (a grazing, X = d/2, or
  the band's edge).
- **The primary alone** (:func:`baseline_peak`): the maximum of X(Ω) over the band, located by
  Brent's method on the closed form (textbook: Ω = ω_n√(1 − 2ζ²) and F0/(2Kζ√(1 − ζ²)) for a
  force).
"""

from __future__ import annotations

import itertools
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np
from scipy.optimize import minimize_scalar

from ...model.system import ImpactSystem
from ..forcing import Forcing
from .continuation import Branch, orbit_between

#: The kinds of steady motion (:mod:`symimpact.forced.orbits.coverage`) no branch of periodic orbits can
#: hold.
UNTRACEABLE = ("chatter or sticking", "not periodic", "chaotic", "quasi-periodic")
#: Brent's method stops when the bracket on Ω is below this share of Ω: the amplitude is flat to
#: second order at a maximum, so the located amplitude is good to ~(1e-9)² relative.
XTOL = 1e-9


@dataclass(frozen=True)
class Peak:
    """A located peak (SI): ``amplitude`` [m] max abs(x), ``omega`` [rad/s], ``motion``
    ("periodic", "no impact", "linear": the primary alone, or a multi-start's "chatter or
    sticking" or "not periodic" motion, sampled at its frequency), ``branch`` (the curve's branch
    number, or None), ``period_multiple`` k, ``impacts_per_period`` of a periodic motion and its
    ``impact_events_per_period`` (a chatter sequence counting once),
    ``where``: how it was located ("maximum", a bifurcation's kind, "band edge", "point",
    "resonance", "grazing", "multi-start", or "brute force": runs beside the located peak and
    across a motion that does not repeat, :mod:`symimpact.forced.orbits.worst_case`)."""

    amplitude: float
    omega: float
    motion: str
    where: str
    branch: int | None = None
    period_multiple: int | None = None
    impacts_per_period: float | None = None
    impact_events_per_period: float | None = None

    def as_dict(self) -> dict[str, Any]:
        return dict(self.__dict__)


def linear_amplitude(system: ImpactSystem, forcing: Forcing, w: Any) -> np.ndarray:
    """The primary without the damper: amplitude of Step 8's steady solution (Eq. F1) [m]."""
    from ..responses import steady_amplitude

    return np.abs(steady_amplitude(system, forcing, w))


def _maximum(f, lo: float, hi: float) -> tuple[float, float]:
    """(x, f(x)) of the largest of f on [lo, hi]: Brent's method on −f, beside both ends."""
    best = max(((lo, f(lo)), (hi, f(hi))), key=lambda r: r[1])
    if hi > lo:
        r = minimize_scalar(lambda x: -f(x), bounds=(lo, hi), method="bounded",
                            options={"xatol": XTOL * hi})  # fmt: skip
        if -r.fun > best[1]:
            best = (float(r.x), float(-r.fun))
    return best


def baseline_peak(
    system: ImpactSystem, forcing: Forcing, band: tuple[float, float],
    linear: Callable[[Any], Any] | None = None,
) -> Peak:  # fmt: skip
    """The largest amplitude of the primary without the damper over ``band`` [rad/s]: the
    maximum of X(Ω) (Step 8, Eq. F1) located by Brent's method (resonance) or a band edge.
    ``linear``: another response of Ω to locate instead of X(Ω) (one maximum in the band, as
    :func:`symimpact.forced.responses.linear_response`'s)."""
    if linear is None:

        def linear(x):
            return linear_amplitude(system, forcing, x)

    lo, hi = band
    grid = np.linspace(lo, hi, 401)
    i = int(np.argmax(linear(grid)))
    a, b = grid[max(i - 1, 0)], grid[min(i + 1, len(grid) - 1)]
    w, amp = _maximum(lambda x: float(linear(x)), float(a), float(b))
    where = "band edge" if w in (lo, hi) else "resonance"
    return Peak(amp, w, "linear", where)


def no_impact_peak(
    system: ImpactSystem, forcing: Forcing, intervals: list[tuple[float, float]],
    linear: Callable[[Any], Any] | None = None,
) -> Peak | None:  # fmt: skip
    """The largest amplitude of the motion without impacts (the impact mass at rest midway, the
    primary's linear response inside the clearance) over its Ω ``intervals``; None if it has
    none.  X(Ω) has one maximum, so on an interval it is the resonance or an end.  ``linear``
    as for :func:`baseline_peak`."""
    best: Peak | None = None
    for lo, hi in intervals:
        inner = baseline_peak(system, forcing, (lo, hi), linear)
        where = inner.where
        X = float(linear_amplitude(system, forcing, inner.omega))
        if where == "band edge" and abs(X - system.gap / 2) <= 1e-9 * system.gap:
            where = "grazing"  # the interval ends where X reaches d/2
        peak = Peak(inner.amplitude, inner.omega, "no impact", where)
        if best is None or peak.amplitude > best.amplitude:
            best = peak
    return best


#: ``measure(state, omega, phase, periods)``: a response of the orbit through ``state`` (x, ẋ,
#: z, ẏ) at t = 0 with the forcing at ``omega`` [rad/s] and ``phase`` [rad], over ``periods``
#: forcing periods (:func:`symimpact.forced.responses.orbit_response`); None: the amplitude.
Measure = Callable[[Any, float, float, int], float]


def stable_peak(
    branches: list[Branch], system: ImpactSystem, forcing: Forcing, e: Any,
    band: tuple[float, float], measure: Measure | None = None,
) -> Peak | None:  # fmt: skip
    """The largest amplitude among the stable orbits of ``branches`` (continued in Ω) within
    ``band`` (module text); None if no branch has a stable orbit there.  With ``measure``, the
    largest of that response instead, the branches' points and bifurcations carrying it in their
    ``amplitude`` (:func:`symimpact.forced.orbits.response_curve.response_curve`)."""
    lo, hi = band
    best: Peak | None = None

    def value(o, omega: float, phase: float, periods: int) -> float:
        """The shot orbit ``o``'s amplitude, or its ``measure``."""
        return o.amplitude if measure is None else measure(o.state, omega, phase, periods)

    def offer(amp, omega, where, i, b, p):
        nonlocal best
        if lo <= omega <= hi and (best is None or amp > best.amplitude):
            best = Peak(float(amp), float(omega), "periodic", where, i, b.period_multiple,
                        p.impacts_per_period, p.impact_events_per_period)  # fmt: skip

    for i, b in enumerate(branches):
        pts = b.points
        for p in pts:
            if p.stable:
                offer(p.amplitude, p.omega, "point", i, b, p)
        for f in b.bifurcations:  # the ends of stable runs
            near = sorted(pts, key=lambda p: abs(p.omega - f.omega) / f.omega
                          + abs(p.amplitude - f.amplitude) / f.amplitude)[:2]  # fmt: skip
            if any(p.stable for p in near):
                offer(f.amplitude, f.omega, f.kind, i, b, near[0])
        for j in range(1, len(pts) - 1):
            p0, p1, p2 = pts[j - 1], pts[j], pts[j + 1]
            if not (p0.stable and p1.stable and p2.stable):
                continue
            if not (p1.amplitude >= p0.amplitude and p1.amplitude >= p2.amplitude):
                continue
            if (p1.omega - p0.omega) * (p2.omega - p1.omega) <= 0:
                continue  # Ω turns here: a fold, located as such
            located = _interior_maximum(b, p0, p1, p2, system, forcing, e, value)
            if located is not None:
                offer(*located, "maximum", i, b, p1)
        for edge in (lo, hi):
            for p, q in itertools.pairwise(pts):
                if p.stable and q.stable and min(p.omega, q.omega) <= edge <= max(p.omega, q.omega):
                    o = orbit_between(p, q, edge, _at(system, forcing, e, edge), b.period_multiple)
                    if o is not None and o.stable:
                        amp = value(o, edge, p.phase, b.period_multiple)
                        offer(amp, edge, "band edge", i, b, p)
    return best


def _at(system, forcing, e, omega):
    return system, forcing.at(omega), e


def _interior_maximum(b: Branch, p0, p1, p2, system, forcing, e, measured):
    """(amplitude, Ω) of the amplitude's maximum between p0 and p2 (Brent's method on Ω, each
    orbit by Newton's method from the nearer segment's interpolated state; ``measured(orbit, Ω,
    phase, periods)`` its amplitude or response)."""
    a, c = sorted((p0.omega, p2.omega))

    def amp(w: float) -> float:
        p, q = (p0, p1) if min(p0.omega, p1.omega) <= w <= max(p0.omega, p1.omega) else (p1, p2)
        o = orbit_between(p, q, w, _at(system, forcing, e, w), b.period_multiple)
        if o is None or not o.stable:
            return 0.0  # (below any orbit's)
        return measured(o, w, p.phase, b.period_multiple)

    w, value = _maximum(amp, a, c)
    return (value, w) if value > 0 else None


def curve_peak(
    branches: list[Branch], system: ImpactSystem, forcing: Forcing, e: Any,
    band: tuple[float, float], no_impact: list[tuple[float, float]], others: Any = (),
    measure: Measure | None = None, linear: Callable[[Any], Any] | None = None,
) -> Peak | None:  # fmt: skip
    """The largest of :func:`stable_peak`, :func:`no_impact_peak` and the steady motions that no
    branch can hold (``others``: attractors of :mod:`symimpact.forced.orbits.coverage` of the kinds
    UNTRACEABLE — chatter or sticking, chaotic, quasi-periodic, not periodic — their largest
    abs(x) over the kept periods, at the
    multi-start's frequency): the worst steady motion found over ``band``.  With ``measure``
    and ``linear`` (:func:`stable_peak`, :func:`baseline_peak`), the worst of that response; an
    untraceable motion's over the KEPT periods that follow its recorded state."""
    from .coverage import KEPT

    found = [p for p in (stable_peak(branches, system, forcing, e, band, measure),
                         no_impact_peak(system, forcing, no_impact, linear)) if p is not None]  # fmt: skip
    for a in others:
        if a.kind in UNTRACEABLE:
            amp = a.amplitude if measure is None else measure(a.state, a.omega, forcing.phase, KEPT)
            found.append(Peak(amp, a.omega, a.kind, "multi-start", None,
                              a.period_multiple or None, a.impacts_per_period))  # fmt: skip
    return max(found, key=lambda p: p.amplitude) if found else None
