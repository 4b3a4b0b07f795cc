"""The worst case beside the located peak: the steady motions a brute force reaches at the peak's
frequency and just beside it, so that a designer never reads a lower number than the motion
reaches.

A located peak often ends a stable window at a bifurcation (a period doubling, a grazing, a
fold), and past it the motion need not be periodic: on the README system with e = 0.95 the
located stable peak, 118.1 mm at the end of a stable period-2 run (a period doubling at 30.903
rad/s), has motions that do not repeat beside it, which reach 126 mm.  The
multi-start (:mod:`symimpact.forced.orbits.coverage`) samples fixed frequencies across the band
and misses such a narrow neighbourhood.  Here, at the located peak's Ω and at Ω·(1 ± r) for r in
:data:`OFFSETS`, runs from the multi-start's initial states and from the peak's own orbit settle
(as the multi-start's, :data:`~symimpact.forced.orbits.coverage.WARMUP` periods at most) and their
largest abs(x) is read over :data:`KEPT` periods, ten times the multi-start's window: a motion
that does not repeat reaches its largest excursions rarely.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ...errors import SymimpactError
from ...model.system import ImpactSystem
from ..contact_law import simulation_arguments
from ..forcing import Forcing
from ..simulation import settling_periods, simulate_forced
from .continuation import Branch
from .coverage import WARMUP, Attractor, initial_states
from .peak import Peak

#: The probe's frequencies beside the located peak's Ω, relative to it (and Ω itself).
OFFSETS = (1e-4, 1e-3)
#: The periods over which a probe's motion is read (after settling).
KEPT = 200
#: A brute force's motion larger than the located peak by at most this share is the peak's own
#: orbit (a run's amplitude reads the orbit to ~1e-10 of it; the located peak is good to 1e-9).
SAME = 1e-6
#: Frequencies of each of the two finer grids about the largest motion that does not repeat.
SCAN = 7


def _runs(system, forcing, e, ws, starts, tick: Any = None) -> list[Attractor]:
    """The steady motion reached at each of ``ws`` [rad/s] from each of ``starts`` ((x, ẋ, z, ẏ)
    and the forcing phase it is given at, None for this forcing's), read over :data:`KEPT`
    periods after the settling: "no impact", "periodic" (with its period multiple) or "not
    periodic"; a run still settling, or one the engine cannot take further, is left out.
    ``tick()`` after each run (a curve's progress)."""
    out = []
    for w in ws:
        for (x, v, z, u), phase in starts:
            f = forcing.at(w) if phase is None else forcing.at(w, phase)
            try:
                n = settling_periods(system, f, KEPT, WARMUP + KEPT)
                res = simulate_forced(system, f, **simulation_arguments(e), periods=n,
                                      discard=n - KEPT, x0=x, xdot0=v, y0=x + z,
                                      ydot0=u)  # fmt: skip
            except SymimpactError:
                continue
            finally:
                if tick is not None:
                    tick()
            st = res.steady
            if st.settling:
                continue
            fx, fv, fy, fu = res.final_state
            end = (fx, fv, fy - fx, fu)
            if st.impacts_per_period == 0 and not res.final_stuck:
                kind, k = "no impact", 0
            elif st.periodic:
                kind, k = "periodic", int(st.period_multiple)
            else:
                kind, k = "not periodic", 0
            out.append(Attractor(float(w), st.amplitude, kind, k, st.impacts_per_period, end))
    return out


def beside_peak(
    system: ImpactSystem, forcing: Forcing, e: Any, band: tuple[float, float], peak: Peak,
    branches: list[Branch], tick: Any = None,
) -> list[Attractor]:  # fmt: skip
    """The steady motions reached at the located ``peak``'s Ω and at Ω·(1 ± r), r in
    :data:`OFFSETS`, inside ``band`` [rad/s], from rest, from the primary displaced with the
    impact mass near a wall (:func:`~.coverage.initial_states`) and from the state of the peak's
    branch point nearest in Ω (at its own forcing phase) (:func:`_runs`)."""
    W = peak.omega
    ws = [W] + [W * (1.0 + s * r) for r in OFFSETS for s in (-1.0, 1.0)]
    ws = [w for w in ws if band[0] <= w <= band[1]]
    starts = [(s, None) for s in initial_states(system, forcing.at(W))[:2]]
    if peak.branch is not None and 0 <= peak.branch < len(branches):
        points = branches[peak.branch].points
        if points:
            near = min(points, key=lambda p: abs(p.omega - W))
            starts.append((near.state, near.phase))
    return _runs(system, forcing, e, ws, starts, tick)


def worst_case(
    system: ImpactSystem, forcing: Forcing, e: Any, band: tuple[float, float], peak: Peak,
    branches: list[Branch], swept: Any = (), step: float = 0.0, tick: Any = None,
) -> tuple[Peak, list[Attractor]]:  # fmt: skip
    """(the worst case, the motions run for it): the located ``peak``, or the largest motion
    reached beside it (:func:`beside_peak`) or, where motions that do not repeat are found
    (beside it, or by a sweep's run: ``swept``, the sweeps' points), the largest of those located
    on a finer grid: :data:`SCAN` frequencies across ±``step`` [rad/s] (the band's step) about
    the largest one, then as many across ±step/4 about the largest of those, each run from
    rest and from that motion's own state.  Such a motion's amplitude over Ω is smooth on the
    scale of the band's step (its largest excursion over :data:`KEPT` periods scatters by some
    0.3 % from run to run): on the README system with e = 0.95 it rises from 118.1 mm, the
    located stable peak, to 126 mm at 30.83 rad/s.  ``tick()`` after each run (a curve's
    progress)."""
    near = beside_peak(system, forcing, e, band, peak, branches, tick)
    irregular = [a for a in near if a.kind == "not periodic"] + [
        Attractor(r.omega, r.amplitude, "not periodic", 0, r.impacts_per_period, r.state)
        for r in swept
        if not r.periodic and r.impacts_per_period > 0
    ]
    if irregular:
        h = step if step > 0.0 else 1e-3 * peak.omega
        top = max(irregular, key=lambda a: a.amplitude)
        for width in (h, h / 4.0):
            ws = [w for w in np.linspace(top.omega - width, top.omega + width, SCAN)
                  if band[0] <= w <= band[1]]  # fmt: skip
            # from rest, and from that motion's state (a start like any other at another Ω)
            more = _runs(system, forcing, e, ws, [((0.0, 0.0, 0.0, 0.0), None), (top.state, None)],
                         tick)  # fmt: skip
            near += more
            top = max([top, *(a for a in more if a.kind == "not periodic")],
                      key=lambda a: a.amplitude)  # fmt: skip
    return worse_than(peak, near) or peak, near


def worse_than(peak: Peak, near: list[Attractor]) -> Peak | None:
    """The largest of ``near`` as a :class:`~.peak.Peak` (located by "brute force"), where it
    is larger than ``peak`` by more than :data:`SAME`; else None."""
    top = max(near, key=lambda a: a.amplitude, default=None)
    if top is None or not top.amplitude > peak.amplitude * (1.0 + SAME):
        return None
    return Peak(top.amplitude, top.omega, top.kind, "brute force", None,
                top.period_multiple or None, top.impacts_per_period)  # fmt: skip
