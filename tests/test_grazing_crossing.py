"""Continuation through grazing (issue 33, item 2): where an impact appears or vanishes the
branch goes on with the new impacts.  Checked by the simulation alone on each side: the orbits
next to a crossed grazing repeat over their period (the event-driven run, not the continuation's
corrector) with the impacts a period the grazing names, and a stable one is what a long run
settles on.  And a located grazing is one: the orbit there touches a wall."""

from __future__ import annotations

import math

import numpy as np
import pytest

from symimpact.forced import Forcing, simulate_forced
from symimpact.forced.engine import _rigid
from symimpact.forced.orbits.frf import frequency_response
from symimpact.forced.simulation import impact_counts
from symimpact.model.system import ImpactSystem

SYSTEM = ImpactSystem(M=1.0, K=1000.0, C=0.5, m=0.05, gap=0.02, contact="linear", k1=1e6)
E = 0.6
#: Issue 33's base-motion system (M 2 kg, K 800 N/m, C 1.6 N s/m, m 0.3 kg, d 4 mm, X_b 1 mm,
#: e 0.4), whose branches cross grazings into sequences of many impacts near 17 and 19.5 rad/s
BASE = ImpactSystem(M=2.0, K=800.0, C=1.6, m=0.3, gap=0.004, contact="linear", k1=1e6)
BASE_E = 0.4


@pytest.fixture(scope="module")
def curve():
    return frequency_response(SYSTEM, Forcing(F0=2.0, omega=25.0), E, np.linspace(25, 40, 151),
                              sweeps=False, multistart=0)  # fmt: skip


@pytest.fixture(scope="module")
def base_curve():
    return frequency_response(BASE, Forcing(X_b=0.001, omega=20.0), BASE_E,
                              np.linspace(14, 26, 200), sweeps=False, multistart=0)  # fmt: skip


def _run(p, k, periods):
    x, v, z, u = p.state
    f = Forcing(X_b=0.001, omega=p.omega, phase=p.phase)
    return simulate_forced(BASE, f, e=BASE_E, periods=periods, discard=periods - k, x0=x,
                           xdot0=v, y0=x + z, ydot0=u)  # fmt: skip


def test_branches_go_on_through_grazings_with_the_impacts_they_name(base_curve):
    crossed = 0
    for b in base_curve.branches:
        k = b.period_multiple
        for f in b.bifurcations:
            if f.kind != "grazing" or math.isnan(f.impacts_after):
                continue
            # the branch's points on either side: the nearest with each count
            sides = {}
            for p in b.points:
                n = p.impact_events_per_period  # a chatter sequence counts once
                if n in (f.impacts_before, f.impacts_after):
                    best = sides.get(n)
                    if best is None or abs(p.omega - f.omega) < abs(best.omega - f.omega):
                        sides[n] = p
            assert set(sides) == {f.impacts_before, f.impacts_after}, (f, sides)
            for count, p in sides.items():
                res = _run(p, k, k)  # one period of the orbit, from its state
                x, v, y, u = res.final_state
                back = np.array([x, v, y - x, u])
                scale = np.array([p.amplitude, p.amplitude * p.omega, BASE.gap / 2,
                                  p.amplitude * p.omega])  # fmt: skip
                # it repeats (1e-8: Newton's tolerance times the map's conditioning; a state
                # known to the map's rounding, ~1e-15 of its scale, comes back within ten times
                # that times the largest multiplier, 1e7 beside the grazing at 20.343 rad/s)
                # with the impacts the grazing names on this side
                bound = max(1e-8, 1e-14 * max(abs(m) for m in p.multipliers))
                assert np.max(np.abs((back - np.array(p.state)) / scale)) < bound
                assert impact_counts(res.events, -math.inf, math.inf)[1] == round(count * k)
                if p.stable and max(abs(m) for m in p.multipliers) < 0.95:
                    st = _run(p, k, 600).steady
                    assert st.amplitude == pytest.approx(p.amplitude, rel=1e-6)
            crossed += 1
    assert crossed >= 3  # measured: 8


def _closest_approach(res, h: float, periods: int) -> float:
    """The smallest gap h − abs(z) [m] at the turning points of z = y − x in flight (ż = 0) over
    the run ``res`` of ``periods`` forcing periods: local maxima of abs(z) on 20 001 samples a
    period, each refined on 4001 samples across its neighbours, twice, and kept where ż there is
    zero to the refined grid's resolution (a sampled maximum just before an impact has ż of
    the impact's speed)."""
    from symimpact.forced.simulation import state_at

    ts = np.linspace(0.0, res.forcing.period * periods, 20_001)
    s = state_at(res, ts)
    a = np.abs(s[:, 2])
    speed = np.max(np.abs(s[:, 3] - s[:, 1]))  # the largest relative speed of the run
    # samples on a wall (a sticking phase) are excluded, not those merely near it: at a grazing
    # the flight turns within ~1e-10 of d/2 of the wall (measured 4.3e-10 at the end of the
    # base-motion system's decaying sequence at 17.29 rad/s), which a margin of 1e-9 hid
    turning = np.nonzero((a[1:-1] > a[:-2]) & (a[1:-1] >= a[2:]) & (a[1:-1] < h * (1 - 1e-14)))[0]
    gaps = []
    for i in turning + 1:
        lo, hi = ts[i - 1], ts[i + 1]
        for _ in range(2):
            tf = np.linspace(lo, hi, 4001)
            sf = state_at(res, tf)
            j = int(np.argmax(np.abs(sf[:, 2])))
            lo, hi = tf[max(j - 1, 0)], tf[min(j + 1, len(tf) - 1)]
        zdot = sf[j, 3] - sf[j, 1]
        if 0 < j < len(tf) - 1 and abs(zdot) < 1e-6 * speed:
            gaps.append(h - abs(sf[j, 2]))
    return min(gaps, default=math.inf)


def test_every_located_grazing_touches_a_wall(curve, base_curve):
    """A located grazing is where the orbit touches a wall with zero relative speed: run over
    its period from the located orbit's state, a flight turns at a wall or an impact's speed
    vanishes, to the bisection's resolution (1e-6 of a step ≤ 0.08 in the scaled unknowns,
    times the margin's slope, O(10) in d/2 or in the square of the impact's speed over the
    fastest's, which grows linearly from a grazing as the turning point's distance does).  From
    the impacting side Newton's basin narrows with the impact's speed and the bracket stops
    sooner: below GRAZING_MARGIN = 1e-4; measured ≤ 2.7e-5 over the 85 located here, most
    ≤ 1e-9."""
    cases = ((curve, SYSTEM, {"F0": 2.0}, E), (base_curve, BASE, {"X_b": 0.001}, BASE_E))
    located = 0
    for frf, system, load, e in cases:
        h = system.gap / 2
        for b in frf.branches:
            for f in b.bifurcations:
                if f.kind != "grazing":
                    continue
                x, v, z, u = f.state
                k = b.period_multiple
                res = simulate_forced(system, Forcing(**load, omega=f.omega, phase=f.phase), e=e,
                                      periods=k, x0=x, xdot0=v, y0=x + z, ydot0=u)  # fmt: skip
                speeds = np.abs(res.events[:, _rigid.E_VREL])
                touch = min(_closest_approach(res, h, k) / h, (speeds.min() / speeds.max()) ** 2)
                assert touch < 1e-4, f
                located += 1
    assert located >= 10  # measured: 85 in all
