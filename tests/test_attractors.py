"""Attractors that are not periodic (issue 33, item 4): the multi-start classifies them by the
largest Lyapunov exponent, carried through the impacts by the saltation matrices.  Checked by
what the exponent does not use: a chaotic motion's exponent is the growth of the distance between
two simulations started 1e-9 apart; a quasi-periodic motion's section points fill a closed curve
and never repeat.  The README's system (M 1 kg, K 1000 N/m, C 0.5 N s/m, m 0.05 kg, d 20 mm,
F0 2 N, e 0.6)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from symimpact.forced import Forcing, simulate_forced
from symimpact.forced.orbits.coverage import LYAPUNOV_ZERO, attractor, lyapunov
from symimpact.forced.orbits.frf import frequency_response
from symimpact.forced.orbits.shooting import shoot
from symimpact.model.system import ImpactSystem

SYSTEM = ImpactSystem(M=1.0, K=1000.0, C=0.5, m=0.05, gap=0.02, contact="linear", k1=1e6)
E = 0.6


def _end(f, state=(0.0, 0.0, 0.0, 0.0), periods=420):
    x, v, z, u = state
    res = simulate_forced(SYSTEM, f, e=E, periods=periods, discard=periods - 20, x0=x, xdot0=v,
                          y0=x + z, ydot0=u)  # fmt: skip
    x, v, y, u = res.final_state
    return (x, v, y - x, u), res


def test_the_chaotic_motion_at_28_75_rad_s():
    f = Forcing(F0=2.0, omega=28.75)
    a = attractor(SYSTEM, f, E, (0.0, 0.0, 0.0, 0.0))
    # λT is about 1 (0.99–1.05 as rounding moves the 400-period trajectory: its spread over the
    # four stretches is 0.1): far above the zero band, by more than three spreads
    assert a.kind == "chaotic" and a.lyapunov * f.period > 50 * LYAPUNOV_ZERO
    assert a.lyapunov > 3 * a.lyapunov_spread
    # over twice the periods the exponent agrees within the spreads of both estimates
    lam2, spread2 = lyapunov(SYSTEM, f, E, a.state, periods=800)
    assert abs(lam2 - a.lyapunov) <= 3 * (spread2 + a.lyapunov_spread)
    # independent of the tangent map: two runs 1e-9 apart separate at about exp(λt) until
    # the distance saturates; the fitted rate over the first 15 periods is within a factor
    # two of λ (a finite-time estimate of one pair against a 400-period average)
    s, _ = _end(f)
    T = f.period
    x, v, z, u = s
    one = simulate_forced(SYSTEM, f, e=E, periods=15, x0=x, xdot0=v, y0=x + z, ydot0=u)
    two = simulate_forced(SYSTEM, f, e=E, periods=15, x0=x + 1e-9 * abs(x or 1e-3), xdot0=v,
                          y0=x + z, ydot0=u)  # fmt: skip
    from symimpact.forced.simulation import state_at

    times = np.arange(1, 16) * T
    d = np.linalg.norm(state_at(one, times)[:, :2] - state_at(two, times)[:, :2], axis=1)
    growing = d < 1e-4  # before saturation at the attractor's size
    rate = np.polyfit(times[growing], np.log(d[growing]), 1)[0]
    assert 0.5 * a.lyapunov < rate < 2.0 * a.lyapunov


def test_a_quasi_periodic_motion_past_the_neimark_sacker_point():
    # the stable symmetric orbit loses stability at 41.42 rad/s through a complex pair: just
    # past it a run from the orbit's state settles on an invariant curve of the section
    c = frequency_response(SYSTEM, Forcing(F0=2.0, omega=36.0), E, np.linspace(36, 43, 36),
                           sweeps=False, multistart=0)  # fmt: skip
    ns = next(f for b in c.branches for f in b.bifurcations if f.kind == "neimark-sacker")
    assert ns.omega == pytest.approx(41.4206, abs=1e-3)
    p = next(p for b in c.branches for p in b.points
             if ns.omega < p.omega < ns.omega + 0.1 and not p.stable)  # fmt: skip
    f = Forcing(F0=2.0, omega=p.omega, phase=p.phase)
    x, v, z, u = p.state
    s, _ = _end(f, (x * (1 + 1e-3), v, z, u), periods=1500)
    a = attractor(SYSTEM, f, E, s)
    assert a.kind == "quasi-periodic", a
    assert abs(a.lyapunov) * f.period <= LYAPUNOV_ZERO
    # the section: 400 points that never repeat and lie on closed curves: their nearest
    # neighbours are as close as points spread along a curve (a few thousandths of its size),
    # not as points filling an area (1/20 of it) or repeating (zero)
    _, res = _end(f, s, periods=400)
    from symimpact.forced.simulation import state_at

    sec = state_at(res, np.arange(1, 400) * f.period)[:, :2] / np.array(
        [p.amplitude, p.amplitude * p.omega]
    )
    size = float(np.ptp(sec[:, 0]) + np.ptp(sec[:, 1]))
    assert size > 1e-4  # not a fixed point
    gaps = np.linalg.norm(sec[:, None, :] - sec[None, :, :], axis=2)
    np.fill_diagonal(gaps, np.inf)
    nearest = gaps.min(axis=1)
    assert np.min(nearest) > 1e-9 * size  # it never comes back
    assert np.median(nearest) < 2e-2 * size
    assert math.isfinite(a.amplitude)


def test_an_attractor_is_reported_with_its_least_period():
    """At 39.0625 rad/s the multi-start's starts settle slowly on the stable symmetric
    two-impact orbit; one of them once read as period 4 over its last periods (which start does
    depends on the last bits of the slow transient).  Shooting over four periods from the orbit
    finds it again, and :func:`least_period` says it repeats after one; every periodic
    attractor found is that orbit with period 1, its amplitude the closed form's (Eq. F3,
    independent of the simulation; to 1e-9, measured 1e-15)."""
    from symimpact.forced import periodic_orbits
    from symimpact.forced.orbits.coverage import initial_states, least_period

    f = Forcing(F0=2.0, omega=39.0625)
    closed = [o for o in periodic_orbits(SYSTEM, f, E) if o.admissible and o.stable]
    assert len(closed) == 1
    found = [attractor(SYSTEM, f, E, s) for s in initial_states(SYSTEM, f)]
    periodic = [a for a in found if a.kind == "periodic"]
    assert periodic
    for a in periodic:
        assert a.period_multiple == 1
        assert a.amplitude == pytest.approx(closed[0].amplitude, rel=1e-9)
    four = shoot(SYSTEM, f, E, periodic[0].state, periods=4)
    assert four.amplitude == pytest.approx(closed[0].amplitude, rel=1e-9)
    assert least_period(SYSTEM, f, E, four.state, 4, four.amplitude) == 1


def test_the_band_s_end_intervals_are_refined():
    # the report's curve at d 9 mm (its chosen reading: M 1 kg, K 100 N/m, C 1 N s/m, m 0.25 kg,
    # e 0.1594, F0 0.2 N): a stable period-3 motion at 14.60–14.95 rad/s lies between the last
    # frequency of the curve's multi-start over 5–15 rad/s (14.375) and the band's end, which
    # the multi-start's refinement now runs and halves towards.  Over 14–15 rad/s with one
    # frequency (14.5, where every start lands elsewhere), the curve holds every period-3 motion
    # of the 200-frequency brute force's runs there (independent runs from its initial states)
    from symimpact.forced.orbits.coverage import frequencies, initial_states
    from symimpact.forced.orbits.frf import _traced

    system = ImpactSystem(M=1.0, K=100.0, C=1.0, m=0.25, gap=0.009, contact="linear", k1=1e6)
    e, forcing = 0.1594, Forcing(F0=0.2, omega=14.5)
    at_middle = [attractor(system, forcing, e, s, exponent=False)
                 for s in initial_states(system, forcing)]  # fmt: skip
    assert not any(a.kind == "periodic" for a in at_middle)
    brute = [a for w in frequencies((5.0, 15.0), 200) if w > 14.5
             for s in initial_states(system, forcing.at(w))
             for a in [attractor(system, forcing.at(w), e, s, exponent=False)]
             if a.kind == "periodic" and a.period_multiple == 3]  # fmt: skip
    assert len({a.omega for a in brute}) >= 6
    curve = frequency_response(system, forcing, e, [14.0, 15.0], starts=0, sweeps=False,
                               multistart=1, jumps=0)  # fmt: skip
    for a in brute:
        assert _traced(curve.branches, system, forcing.at(a.omega), e, a.omega, a.amplitude, 3)


def test_the_initial_states_spread_over_processes_land_as_in_one(monkeypatch):
    # each initial state's runs and halvings are independent: two processes return the
    # attractors one process finds, in the same order, to the bit (28–31 rad/s holds chaotic,
    # periodic and chattering landings, so the refinement halves in every process; down to
    # 1/32 of the band here, which the forked workers inherit, to keep the test short)
    from symimpact.forced.orbits import coverage

    monkeypatch.setattr(coverage, "REFINE", 1.0 / 32)
    monkeypatch.setattr(coverage, "REFINE_IRREGULAR", 1.0 / 32)
    forcing = Forcing(F0=2.0, omega=30.0)
    one = coverage.attractors(SYSTEM, forcing, E, (28.0, 31.0), 3, refine=True, workers=1)
    two = coverage.attractors(SYSTEM, forcing, E, (28.0, 31.0), 3, refine=True, workers=2)
    assert len(one) > 10
    assert one == two


def test_windows_beside_chaos_are_refined_finer():
    # benchmark 6's band, 25–45 rad/s: the stable symmetric 14-impact motions near 30.67–30.69
    # rad/s lie between the 12- and 16-impact ones with chaos beside them; halving to 1/256 of
    # the band (0.078 rad/s) passed over them (the curve missed the brute force's 30.672 rad/s
    # motion); next to a landing that does not repeat the refinement goes on to
    # REFINE_IRREGULAR (1/1024: 0.0195 rad/s) and lands on one (at 30.684 rad/s).  Independent
    # of the multi-start: a 600-period run from the found orbit's state, the impact mass moved by
    # 1e-6 of the clearance, comes back to the same amplitude (1e-6: the orbit is stable, the
    # distance decays geometrically, to below 1e-9 of it over 580 periods)
    from symimpact.forced.orbits.coverage import REFINE, REFINE_IRREGULAR, attractors

    assert REFINE_IRREGULAR * 20.0 < 0.02 < REFINE * 20.0
    forcing = Forcing(F0=2.0, omega=30.0)
    found = [a for a in attractors(SYSTEM, forcing, E, (25.0, 45.0), refine=True)
             if a.kind == "periodic" and a.impacts_per_period == 14 and 30.6 < a.omega < 30.7]  # fmt: skip
    assert found and all(a.stable and a.period_multiple == 1 for a in found)
    a = found[0]
    x, v, z, u = a.state
    res = simulate_forced(SYSTEM, forcing.at(a.omega), e=E, periods=600, discard=580,
                          x0=x, xdot0=v, y0=x + z + 1e-6 * SYSTEM.gap, ydot0=u)  # fmt: skip
    assert res.steady.amplitude == pytest.approx(a.amplitude, rel=1e-6)
