"""Continuation through grazing (issue 33, item 2): where an impact appears or vanishes the
branch goes on with the new impacts.  Checked by the simulation alone on each side: the orbits
next to a crossed grazing repeat over their period (the event-driven run, not the continuation's
corrector) with the impacts a period the grazing names, and a stable one is what a long run
settles on."""

from __future__ import annotations

import math

import numpy as np
import pytest

from symimpact.forced import Forcing, simulate_forced
from symimpact.forced.frf import frequency_response
from symimpact.system import ImpactSystem

SYSTEM = ImpactSystem(M=1.0, K=1000.0, C=0.5, m=0.05, gap=0.02, contact="linear", k1=1e6)
E = 0.6


@pytest.fixture(scope="module")
def curve():
    return frequency_response(SYSTEM, Forcing(F0=2.0, omega=25.0), E, np.linspace(25, 40, 151),
                              sweeps=False, multistart=0)  # fmt: skip


def _run(p, k, periods):
    x, v, z, u = p.state
    f = Forcing(F0=2.0, omega=p.omega, phase=p.phase)
    return simulate_forced(SYSTEM, f, e=E, periods=periods, discard=periods - k, x0=x, xdot0=v,
                           y0=x + z, ydot0=u)  # fmt: skip


def test_branches_go_on_through_grazings_with_the_impacts_they_name(curve):
    crossed = 0
    for b in curve.branches:
        k = b.period_multiple
        for f in b.bifurcations:
            if f.kind != "grazing" or math.isnan(f.impacts_after):
                continue
            # the branch's points on either side: the nearest with each count
            sides = {}
            for p in b.points:
                if p.impacts_per_period in (f.impacts_before, f.impacts_after):
                    best = sides.get(p.impacts_per_period)
                    if best is None or abs(p.omega - f.omega) < abs(best.omega - f.omega):
                        sides[p.impacts_per_period] = p
            assert set(sides) == {f.impacts_before, f.impacts_after}, (f, sides)
            for count, p in sides.items():
                res = _run(p, k, k)  # one period of the orbit, from its state
                x, v, y, u = res.final_state
                back = np.array([x, v, y - x, u])
                scale = np.array([p.amplitude, p.amplitude * p.omega, SYSTEM.gap / 2,
                                  p.amplitude * p.omega])  # fmt: skip
                # it repeats (1e-8: Newton's tolerance times the map's conditioning) with the
                # impacts the grazing names on this side
                assert np.max(np.abs((back - np.array(p.state)) / scale)) < 1e-8
                assert len(res.impacts) == round(count * k)
                if p.stable and max(abs(m) for m in p.multipliers) < 0.95:
                    st = _run(p, k, 600).steady
                    assert st.amplitude == pytest.approx(p.amplitude, rel=1e-6)
            crossed += 1
    assert crossed >= 3  # the README's system crosses a dozen
