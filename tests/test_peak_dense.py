"""The located peak against a dense multi-start brute force (issue 33, items 5 and 6): no
stable periodic motion that simulation alone finds anywhere in the band exceeds the curve's
located peak.  On benchmark 6's band the resonance of the README system breaks into short
branches of 6 to 70 impacts a period, 0.01–0.13 rad/s long; the highest of them (102 mm, a
chattering orbit) lies between the curve's own multi-start frequencies and is reached only by
the jumps from the ends of its neighbours (:func:`symimpact.forced.orbits.frf._jump_from`)."""

from __future__ import annotations

import numpy as np
import pytest

from symimpact.forced import Forcing, simulate_forced
from symimpact.forced.orbits.coverage import attractors
from symimpact.forced.orbits.frf import frequency_response
from symimpact.model.system import ImpactSystem

SYSTEM = ImpactSystem(M=1.0, K=1000.0, C=0.5, m=0.05, gap=0.02, contact="linear", k1=1e6)
FORCING = Forcing(F0=2.0, omega=30.0)
E = 0.6
BAND = np.linspace(25.0, 45.0, 200)  # rad/s: benchmark 6's band


@pytest.fixture(scope="module")
def curve():
    return frequency_response(SYSTEM, FORCING, E, BAND, sweeps=False)


@pytest.fixture(scope="module")
def found():
    # 200 frequencies × 4 initial states, each run until its transient has decayed and shot
    return attractors(SYSTEM, FORCING, E, (BAND[0], BAND[-1]), len(BAND))


@pytest.mark.slow
def test_no_stable_motion_of_a_dense_multistart_exceeds_the_located_peak(curve, found):
    top = max((a for a in found if a.kind == "periodic" and a.stable), key=lambda a: a.amplitude)
    # measured: the brute force's highest is 101.33 mm at 30.771 rad/s; the located peak 102.27
    # mm at 30.808 rad/s (before the jumps: 97.84 mm, a grazing end 0.05 rad/s below).  1e-9:
    # both are shot orbits, to Newton's tolerance
    assert curve.peak.amplitude >= top.amplitude * (1 - 1e-9), (curve.peak, top)
    assert curve.peak.motion == "periodic"
    # the peak is a motion a long run keeps: its branch's point nearest it, run 600 periods
    b = curve.branches[curve.peak.branch]
    p = min(b.points, key=lambda q: abs(q.omega - curve.peak.omega))
    assert p.stable
    x, v, z, u = p.state
    res = simulate_forced(SYSTEM, FORCING.at(p.omega, p.phase), e=E, periods=600, discard=580,
                          x0=x, xdot0=v, y0=x + z, ydot0=u)  # fmt: skip
    assert res.steady.amplitude == pytest.approx(p.amplitude, rel=1e-6)


def test_a_negative_number_of_jumps_is_refused_in_one_line():
    from symimpact.errors import ParameterError

    with pytest.raises(ParameterError, match="jumps"):
        frequency_response(SYSTEM, FORCING, E, BAND, jumps=-1)


@pytest.mark.slow
def test_the_short_branches_no_stable_end_leads_to_are_traced(curve, found):
    """The brute force's stable 4-impact period-1 orbits at 29.38–29.68 rad/s (22.6–28.0 mm)
    lie on a branch bounded by a fold and by corrector failures that no stable end and no loss
    of stability of another branch leads to; the refined multi-start
    (:func:`symimpact.forced.orbits.coverage.attractors`, ``refine``) and the runs at branch ends
    (:func:`symimpact.forced.orbits.frf._start_at_ends`) start it.  Without them none of the four is on
    the curve (measured on 8d142e9: 108 of the band's 127 periodic attractors traced)."""
    from symimpact.forced.orbits.frf import _traced

    here = [a for a in found if a.kind == "periodic" and 29.3 < a.omega < 29.7]
    assert len(here) >= 4, here
    for a in here:
        assert _traced(curve.branches, SYSTEM, FORCING.at(a.omega), E, a.omega, a.amplitude,
                       a.period_multiple), a  # fmt: skip


@pytest.mark.slow
def test_the_curve_holds_the_dense_brute_force_s_periodic_attractors(curve, found):
    """Coverage measured against brute force at 200 frequencies that are not the curve's own:
    the share of the dense multi-start's periodic attractors (of the periods a curve traces,
    ≤ MAX_START_PERIODS) that lie on a traced branch (:func:`symimpact.forced.orbits.frf._traced`:
    Newton from the branch lands on the orbit's amplitude to 1e-7).  Measured 125 of 128 (the
    three missed lie on stable windows 0.003–0.07 rad/s wide); 117 of 128 before the refined
    multi-start and the halved steps beside near-grazing orbits.  Issue 33's target is 99 %; the
    bound is the measured share less one attractor."""
    from symimpact.forced.orbits.frf import MAX_START_PERIODS, _traced

    shot = [a for a in found if a.kind == "periodic" and a.period_multiple <= MAX_START_PERIODS]
    on = [_traced(curve.branches, SYSTEM, FORCING.at(a.omega), E, a.omega, a.amplitude,
                  a.period_multiple) for a in shot]  # fmt: skip
    assert len(shot) >= 120
    missed = [round(a.omega, 3) for a, t in zip(shot, on, strict=True) if not t]
    assert sum(on) >= len(shot) - 4, missed
