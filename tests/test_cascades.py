"""Period-doubling cascades past period 4 (issue 81, item 2), against brute-force simulation.

On the base-excited system of the issue (M 2 kg, K 800 N/m, C 1.6 N s/m, m 0.3 kg, d 4 mm,
X_b 1 mm, e 0.4) an independent multi-start reached, from every start, a period-4 orbit just past
a grazing near 16.50 rad/s and a period-6 orbit (the doubling of a period-3 branch) near
16.55 rad/s.  The curve (measured on this machine before the change) drew the period-4 orbit
but no branch of period above 4: branch switching stopped at period 4.  It now follows doublings to period 16
(:data:`symimpact.forced.orbits.frf.MAX_SWITCH_PERIODS`; the orbits started from the
multi-start's landings stay at most 4 periods long, :data:`~symimpact.forced.orbits.frf.MAX_START_PERIODS`).

Every stable orbit of period above 4 that the curve draws over 16.2–16.8 rad/s is checked by
simulation alone: started a hair off the orbit and run for thousands of periods, the motion
settles onto a motion whose per-period maxima repeat with exactly the orbit's period (not a
divisor of it) and reach the orbit's amplitude."""

from __future__ import annotations

import numpy as np
import pytest

from symimpact.forced import Forcing, simulate_forced
from symimpact.forced.orbits.continuation import branch_starts
from symimpact.forced.orbits.frf import frequency_response
from symimpact.model.system import ImpactSystem

SYSTEM = ImpactSystem(M=2.0, K=800.0, C=1.6, m=0.3, gap=0.004, contact="linear", k1=1e6)
FORCING = Forcing(X_b=1e-3, omega=16.5)
E = 0.4
BAND = np.arange(16.2, 16.8 + 1e-9, 0.05)  # rad/s
#: periods run from the perturbed start, and the last ones compared (a multiple of 16)
RUN, KEPT = 6000, 320
#: per-period maxima agree to this (m) where the motion repeats: the perturbation (1e-9 m) has
#: decayed by a factor |μ|^n of the largest Floquet multiplier; near a doubling |μ| is close to
#: 1, so the settled maxima are compared at 1e-8 of the 4 mm clearance; the maxima of an
#: orbit's periods must differ by more than this for its least period to be read as asserted
REPEATS = 4e-11


def _least_period(maxima: np.ndarray) -> int:
    """The smallest k with maxima[n + k] = maxima[n] (to REPEATS) over the kept periods."""
    for k in range(1, 33):
        if np.max(np.abs(maxima[k:] - maxima[:-k])) < REPEATS:
            return k
    return 0


@pytest.fixture(scope="module")
def curve():
    return frequency_response(SYSTEM, FORCING, E, BAND)


def _stable(curve, k: int) -> list:
    return [p for b in curve.branches if b.period_multiple == k for p in b.points if p.stable]


def test_the_issue_s_period_4_and_period_6_orbits_are_drawn(curve):
    four = [p for p in _stable(curve, 4) if 16.45 < p.omega < 16.55]
    six = [p for p in _stable(curve, 6) if 16.53 < p.omega < 16.58]
    assert four and six, [(b.period_multiple, len(b.points)) for b in curve.branches]


def test_cascades_reach_period_16(curve):
    """A stable period-8 orbit, and a branch of period 16 (its stable stretch, where the
    continuation's steps land in it, is checked by simulation below)."""
    assert _stable(curve, 8), "no stable period-8 orbit on the curve"
    assert any(b.period_multiple == 16 for b in curve.branches), "no period-16 branch"


def test_every_doubling_of_a_period_8_branch_is_switched_onto(curve):
    """Each period doubling located on a period-8 branch starts a period-16 branch, both ways
    from it.  The one at 16.6079 rad/s lies 6.8e-3 rad/s before its branch rejoins the period-4
    orbits: every usual predictor step (step/8 to step) left the window of the doubled orbits,
    and no period-16 branch left it (branch_starts now tries shorter steps)."""
    doublings = [f for b in curve.branches if b.period_multiple == 8
                 for f in b.bifurcations if f.kind == "period-doubling"]  # fmt: skip
    assert len(doublings) >= 2
    for f in doublings:
        starts = branch_starts(SYSTEM, FORCING.at(f.omega, f.phase), E, f, (BAND[0], BAND[-1]),
                               periods=8)  # fmt: skip
        assert [s.periods for s in starts] == [16, 16], f.omega
        left = [n for n in curve.branches if n.period_multiple == 16
                and n.origin_omega == f.omega]  # fmt: skip
        assert left, f"no period-16 branch leaves the doubling at {f.omega} rad/s"


@pytest.mark.parametrize("k", [6, 8, 16])
def test_each_stable_orbit_above_period_4_is_a_motion_simulation_keeps(curve, k):
    points = _stable(curve, k)
    if not points and k == 16:  # a window the continuation's steps may step over
        pytest.skip(f"no stable period-{k} orbit on this curve")
    for p in points[:: max(1, len(points) // 3)]:
        x, v, z, u = p.state
        res = simulate_forced(SYSTEM, FORCING.at(p.omega, p.phase), e=E, periods=RUN,
                              x0=x + 1e-9, xdot0=v, y0=x + z, ydot0=u)  # fmt: skip
        maxima = res.period_max[-KEPT:]
        assert _least_period(maxima) == k, (p.omega, k, maxima[:40])
        assert np.max(maxima) == pytest.approx(p.amplitude, rel=1e-6, abs=REPEATS)
