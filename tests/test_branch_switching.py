"""Branch switching (issue 33, item 1): the branches that leave a symmetry-breaking branch point
and a period doubling are traced, checked against what does not use them — shooting from a
brute-force run, long simulations from the branch's states, and the mirror image integrated on
its own.

The system is the issue's: M 1 kg, K 1000 N/m, C 0.5 N s/m, m 0.05 kg, d 20 mm, F0 2 N, rigid
e 0.6, band 23.7–42.7 rad/s.  Before switching, the curve held at 25.39 rad/s only the symmetric
orbit (6.666 mm, unstable past its branch point at 24.94 rad/s), while every start settles on a
stable asymmetric orbit of 6.749 mm.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from symimpact.errors import ParameterError
from symimpact.forced import Forcing, shoot_from_rest, simulate_forced
from symimpact.forced.orbits.continuation import branch_starts, monodromy, orbits_at
from symimpact.forced.orbits.frf import frequency_response
from symimpact.model.system import ImpactSystem

SYSTEM = ImpactSystem(M=1.0, K=1000.0, C=0.5, m=0.05, gap=0.02, contact="linear", k1=1e6)
E = 0.6
BAND = np.linspace(23.7, 42.7, 191)


@pytest.fixture(scope="module")
def curve():
    return frequency_response(SYSTEM, Forcing(F0=2.0, omega=23.7), E, BAND, sweeps=False)


def _steady(omega, state, phase, periods=600, kept=20):
    """A long run from ``state`` (x, ẋ, z, ẏ) at forcing phase ``phase``: its steady part."""
    x, v, z, u = state
    f = Forcing(F0=2.0, omega=omega, phase=phase)
    res = simulate_forced(SYSTEM, f, e=E, periods=periods, discard=periods - kept, x0=x,
                          xdot0=v, y0=x + z, ydot0=u)  # fmt: skip
    return res.steady


def test_the_stable_asymmetric_orbit_at_25_39_is_on_a_branch(curve):
    # shooting and a 600-period simulation agree on a stable orbit of 6.7455 mm (the issue
    # quotes 6.749 mm; the traced branch passes 6.7509 mm at 25.3947 rad/s, 1.15 mm per rad/s)
    shot = shoot_from_rest(SYSTEM, Forcing(F0=2.0, omega=25.39), E, warmup=600)
    run = _steady(25.39, (0.0, 0.0, 0.0, 0.0), 0.0)
    assert shot.stable and shot.amplitude == pytest.approx(6.7455e-3, abs=1e-7)
    on = [o for b in curve.branches for o in orbits_at(b, SYSTEM, Forcing(F0=2.0, omega=25.39), E,
                                                       25.39) if o.stable]  # fmt: skip
    # the same orbit: amplitude to the shooting tolerance, and to the run's transient (600
    # periods at ζω_n = 0.25/s leave exp(−0.25·148) ≈ 1e-16 of the start; 1e-6 asserted)
    assert any(abs(o.amplitude - shot.amplitude) <= 1e-9 * shot.amplitude for o in on), on
    assert any(abs(o.amplitude - run.amplitude) <= 1e-6 * run.amplitude for o in on)
    # and it is asymmetric: a branch point's child, drawn with its mirror image
    holding = [b for b in curve.branches
               if any(abs(o.amplitude - shot.amplitude) <= 1e-9 * shot.amplitude
                      for o in orbits_at(b, SYSTEM, Forcing(F0=2.0, omega=25.39), E, 25.39))]  # fmt: skip
    assert holding and all(b.mirrored for b in holding)


def test_the_mirror_image_is_an_orbit_of_its_own(curve):
    # x̃(t) = −x(t + T/2): integrated by the simulation from −s(T/2), it repeats with the same
    # amplitude and is not the orbit itself
    b = next(b for b in curve.branches if b.mirrored)
    p = next(p for p in b.points if p.asymmetric)
    f = Forcing(F0=2.0, omega=p.omega, phase=p.phase)
    T = 2 * math.pi / p.omega
    from symimpact.forced.simulation import state_at

    res = monodromy(SYSTEM, f, E, np.array(p.state), b.period_multiple)[2]
    mirror = -state_at(res, np.array([T / 2]))[0]
    back = monodromy(SYSTEM, f, E, mirror, b.period_multiple)
    scale = np.array([p.amplitude, p.amplitude * p.omega, 0.01, p.amplitude * p.omega])
    assert np.max(np.abs((back[0] - mirror) / scale)) < 1e-9
    assert float(np.max(back[2].period_max)) == pytest.approx(p.amplitude, rel=1e-12)
    assert np.max(np.abs((mirror - np.array(p.state)) / scale)) > 1e-3


def test_period_two_branches_from_the_doublings_are_brute_force_steady_states(curve):
    # the period-2 branches switched onto at a doubling (a jump from a branch end may also
    # land on a period-2 orbit; its branch begins where it landed)
    twos = [b for b in curve.branches
            if b.period_multiple == 2 and b.origin.startswith("period-doubling")]  # fmt: skip
    assert twos
    checked = 0
    for b in twos:
        # the branch begins at the doubling it left: the amplitude there is the old orbit's
        assert b.points[0].amplitude == pytest.approx(
            next(f.amplitude for old in curve.branches for f in old.bifurcations
                 if f.kind == "period-doubling" and f.omega == b.points[0].omega), rel=1e-12)  # fmt: skip
        for p in b.points[1:]:
            # a genuine period-2 orbit: one period does not bring the state back
            one = monodromy(SYSTEM, Forcing(F0=2.0, omega=p.omega, phase=p.phase), E,
                            np.array(p.state), 1)[0]  # fmt: skip
            assert np.max(np.abs(one - np.array(p.state))) > 1e-6 * p.amplitude
            if p.stable and max(abs(m) for m in p.multipliers) < 0.9:
                # perturbed by 1e-4 of its amplitude, a long run returns to it: period 2
                x, v, z, u = p.state
                st = _steady(p.omega, (x * (1 + 1e-4), v, z, u), p.phase, periods=800)
                assert st.period_multiple == 2
                assert st.amplitude == pytest.approx(p.amplitude, rel=1e-6)
                checked += 1
    assert checked >= 3


def test_more_stable_motions_are_traced_than_before(curve):
    # before switching, the band held 7 branches and no stable asymmetric or period-2 orbit
    # between 25 and 27.4 rad/s; a brute-force run from rest at each of these frequencies now
    # lands on a stable traced orbit (at 27.3 rad/s a run from rest settles on a stable
    # three-impact orbit that no start reaches yet: the multi-start coverage of item 5)
    for omega in (25.2, 26.0, 27.2):
        shot = shoot_from_rest(SYSTEM, Forcing(F0=2.0, omega=omega), E, warmup=1500,
                               periods=2 if omega > 27.1 else 1)  # fmt: skip
        f = Forcing(F0=2.0, omega=omega)
        amps = [o.amplitude for b in curve.branches if b.period_multiple == shot.period_multiple
                for o in orbits_at(b, SYSTEM, f, E, omega) if o.stable]  # fmt: skip
        assert any(abs(a - shot.amplitude) <= 1e-9 * shot.amplitude for a in amps), (omega, amps)


def test_switching_refuses_what_it_cannot_leave(curve):
    graze = next(f for b in curve.branches for f in b.bifurcations if f.kind == "grazing")
    f = Forcing(F0=2.0, omega=graze.omega, phase=graze.phase)
    with pytest.raises(ParameterError, match="bifurcation: new branches leave a branch-point"):
        branch_starts(SYSTEM, f, E, graze, (23.7, 42.7))
    with pytest.raises(ParameterError, match="bifurcation: must be a Bifurcation"):
        branch_starts(SYSTEM, f, E, "branch-point", (23.7, 42.7))
