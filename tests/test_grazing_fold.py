"""A branch that turns back at a grazing (issue 33, items 2 and 5): on the README's system the
symmetric four-impact orbits reach a grazing of both walls near 30.4438 rad/s beyond which no
orbit continues them; the asymmetric five-impact orbits meet them there from the same side (a
non-smooth fold).  With ``folds`` the continuation turns back onto them and reaches the stable
five-impact motion near 29.876 rad/s that the default curve misses (benchmark 6's coverage).
Checked against the simulation alone: a long run from the multi-start's initial states at
29.8756 rad/s settles on the orbit the branch holds there."""

from __future__ import annotations

import numpy as np
import pytest

from symimpact.forced import Forcing, shoot, simulate_forced
from symimpact.forced.orbits.continuation import continue_orbit, orbits_at
from symimpact.forced.orbits.coverage import attractor
from symimpact.forced.orbits.frf import frequency_response
from symimpact.model.system import ImpactSystem

SYSTEM = ImpactSystem(M=1.0, K=1000.0, C=0.5, m=0.05, gap=0.02, contact="linear", k1=1e6)
E = 0.6
BAND = (25.0, 45.0)
#: A start near the symmetric four-impact orbit at 30.4269 rad/s (a point of the README curve's
#: branch, to 8 digits; shooting corrects it): (x, ẋ, z, ẏ) at the section, its forcing phase
START_OMEGA, START_PHASE = 30.426885, 2.4389825
START = (-0.0087731680, -1.7880209, 0.0091118339, -1.6543761)
#: Where the multi-start's brute force finds the stable five-impact motion (benchmark 6's band)
OMEGA = 29.875621890547265


@pytest.fixture(scope="module")
def branches():
    forcing = Forcing(F0=2.0, omega=START_OMEGA, phase=START_PHASE)
    orbit = shoot(SYSTEM, forcing, E, START)
    assert orbit.impacts_per_period == 4
    kw = {"direction": 1, "step": 0.05}
    ends = continue_orbit(SYSTEM, forcing, E, orbit.state, BAND, **kw)
    turns = continue_orbit(SYSTEM, forcing, E, orbit.state, BAND, folds=1, **kw)
    return forcing, ends, turns


def test_without_folds_the_branch_ends_at_the_grazing(branches):
    _, ends, _ = branches
    g = ends.bifurcations[-1]
    assert g.kind == "grazing" and g.impacts_before == 4 and np.isnan(g.impacts_after)
    assert abs(g.omega - 30.4438) < 1e-3
    assert max(p.omega for p in ends.points) < g.omega + 1e-6


def test_the_branch_turns_back_onto_the_five_impact_orbits(branches):
    """The grazing names the impacts on both sides; beyond it the branch runs back down in Ω
    on asymmetric orbits with five impact events a period."""
    _, ends, turns = branches
    g = turns.bifurcations[0]
    assert g.kind == "grazing" and (g.impacts_before, g.impacts_after) == (4, 5)
    assert abs(g.omega - ends.bifurcations[-1].omega) < 1e-6 * g.omega  # the same grazing
    after = turns.points[len(ends.points) :]
    assert after and all(p.omega < g.omega for p in after[:10])
    assert all(p.asymmetric for p in after if p.impact_events_per_period == 5)
    assert min(p.omega for p in after) < OMEGA


def test_the_turned_branch_holds_the_motion_a_long_run_settles_on(branches):
    """At 29.8756 rad/s the stable orbit the branch holds is the motion a 600-period run from
    the brute force's attractor settles on (amplitude to 1e-6: the run's transient decays as
    the largest multiplier's modulus, measured ≤ 0.9, to ~1e-20 of its start)."""
    forcing, _, turns = branches
    here = forcing.at(OMEGA, forcing.phase)
    held = [o for o in orbits_at(turns, SYSTEM, here, E, OMEGA) if o.stable]
    assert held, "no stable orbit of the turned branch at 29.8756 rad/s"
    # the brute force's motion there: a run from rest lands elsewhere, a run from the
    # multi-start's state (coverage.initial_states) on this one; it is classified by the
    # simulation alone (coverage.attractor: its least period and its amplitude)
    found = attractor(SYSTEM, Forcing(F0=2.0, omega=OMEGA), E,
                      (0.0297, 0.375, 0.00868, 1.178), exponent=False)  # fmt: skip
    assert found.kind == "periodic" and found.period_multiple == 1
    assert found.impacts_per_period == 5
    run = simulate_forced(SYSTEM, Forcing(F0=2.0, omega=OMEGA), e=E, periods=600,
                          x0=found.state[0], xdot0=found.state[1],
                          y0=found.state[0] + found.state[2], ydot0=found.state[3])  # fmt: skip
    amplitude = float(run.period_max[-1])
    assert any(abs(o.amplitude - amplitude) <= 1e-6 * amplitude for o in held), (
        [o.amplitude for o in held],
        amplitude,
    )


@pytest.mark.slow
def test_the_curve_with_folds_holds_the_motion_the_default_curve_misses():
    """``frequency_response(folds=True)`` over 29.5–30.6 rad/s (no multi-start, no sweeps):
    a branch turned back at a grazing end holds, at 29.8756 rad/s, the stable five-impact
    motion a 600-period run settles on (amplitude to 1e-6, as above); the default curve
    over the same band has no branch there (measured: 30 against 47 branches)."""
    band = np.linspace(29.5, 30.6, 23)
    forcing = Forcing(F0=2.0, omega=OMEGA)
    run = simulate_forced(SYSTEM, forcing, e=E, periods=600, x0=0.0297, xdot0=0.375,
                          y0=0.0297 + 0.00868, ydot0=1.178)  # fmt: skip
    amplitude = float(run.period_max[-1])
    for folds in (False, True):
        curve = frequency_response(SYSTEM, forcing, E, band, sweeps=False, multistart=0,
                                   folds=folds)  # fmt: skip
        held = [o.amplitude for b in curve.branches
                for o in orbits_at(b, SYSTEM, forcing.at(OMEGA, b.phase), E, OMEGA)
                if o.stable and b.period_multiple == 1]  # fmt: skip
        on = any(abs(a - amplitude) <= 1e-6 * amplitude for a in held)
        assert on == folds, (folds, held, amplitude)
        if folds:
            turned = [b for b in curve.branches if b.origin.startswith("turned back")]
            assert turned
