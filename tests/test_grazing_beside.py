"""The orbits beside a turned branch (issue 33, items 2 and 5): on the README's system the
symmetric 12-impact orbits (two sequences of six impacts a period, one at each wall) reach a
grazing of both walls near 30.6907 rad/s beyond which no orbit continues them.  Turned back
there (``folds``), the branch goes on with a seventh impact in one sequence (13 impact events, an
asymmetric orbit).  Beside it lie the symmetric orbits with a seventh impact in both (14), which
nothing else reaches: they run down in Ω through a fold at 30.6672 rad/s onto the stable motion
every run from the multi-start's initial states settles on at 30.6716 rad/s (benchmark 6's
coverage).  Checked against the simulation alone: a 600-period run from rest there."""

from __future__ import annotations

import numpy as np
import pytest

from symimpact.errors import MethodNotApplicable, ParameterError
from symimpact.forced import CompliantContact, Forcing, shoot, simulate_forced
from symimpact.forced.orbits.continuation import (
    continue_orbit,
    orbit_beside_grazing,
    orbits_at,
    trace_branch,
)
from symimpact.model.system import ImpactSystem

SYSTEM = ImpactSystem(M=1.0, K=1000.0, C=0.5, m=0.05, gap=0.02, contact="linear", k1=1e6)
E = 0.6
BAND = (25.0, 45.0)
#: A start near the symmetric 12-impact orbit at 30.69062 rad/s (the end of a branch of the
#: README's curve, to 10 digits; shooting corrects it): (x, ẋ, z, ẏ) at the section, phase 0
START_OMEGA = 30.6906150905
START = (0.0340637060, 2.678185862, -0.009342666536, 2.864627462)
#: Where benchmark 6's brute force finds the stable 14-impact motion the default curve misses
OMEGA = 30.671641791044777
#: frf's rule (``_beside``): the orbit beside is looked for at the turned branch's points at
#: least the continuation's shortest step from the turn (step 0.05/64 of a tenth of the band in
#: Ω), the nearest first
SHORTEST = 0.05 / 64 * (BAND[1] - BAND[0]) / 10.0


@pytest.fixture(scope="module")
def turned():
    forcing = Forcing(F0=2.0, omega=START_OMEGA)
    orbit = shoot(SYSTEM, forcing, E, START)
    assert orbit.impacts_per_period == 12 and orbit.stable is False
    branch = continue_orbit(SYSTEM, forcing, E, orbit.state, BAND, direction=1, step=0.05,
                            folds=1)  # fmt: skip
    return forcing, branch


def test_the_symmetric_orbit_turns_back_onto_asymmetric_orbits_with_one_more_impact(turned):
    _, branch = turned
    g = branch.bifurcations[0]
    assert g.kind == "grazing" and (g.impacts_before, g.impacts_after) == (12, 13)
    assert abs(g.omega - 30.6907) < 1e-4
    after = [p for p in branch.points if p.impact_events_per_period == 13]
    assert all(p.asymmetric for p in after)
    assert all(p.omega < g.omega for p in after)


@pytest.fixture(scope="module")
def beside(turned):
    """The 14-impact orbit beside the turned branch (the first found past the shortest step) and
    its whole branch."""
    _, branch = turned
    turn = branch.bifurcations[0].omega
    past = [p for p in branch.points
            if p.impact_events_per_period == 13 and turn - p.omega >= SHORTEST]  # fmt: skip
    for p in past:
        got = orbit_beside_grazing(SYSTEM, Forcing(F0=2.0, omega=p.omega, phase=p.phase), E,
                                   p.state, BAND)  # fmt: skip
        if got is not None:
            state, fs = got
            orbit = shoot(SYSTEM, fs, E, state)
            # (frf's rule: traced with an eighth of the curve's step)
            return orbit, fs, trace_branch(SYSTEM, fs, E, orbit.state, BAND, step=0.05 / 8)
    pytest.fail("no orbit beside the turned branch")


def test_beside_the_asymmetric_orbits_lie_symmetric_ones_with_two_more_impacts(beside):
    """The orbit found beside is a periodic orbit (shot: the map returns its state) with 14
    impacts a period, symmetric: its second half-period is the first mirrored."""
    orbit, fs, _ = beside
    assert orbit.impacts_per_period == 14
    run = simulate_forced(SYSTEM, fs, e=E, periods=1, x0=orbit.state[0], xdot0=orbit.state[1],
                          y0=orbit.state[0] + orbit.state[2], ydot0=orbit.state[3])  # fmt: skip
    t = np.sort(run.impacts)
    assert len(t) == 14
    # mirror symmetry: each impact's partner half a period later
    assert np.max(np.abs(t[7:] - t[:7] - fs.period / 2)) < 1e-9 * fs.period


def test_the_branch_beside_holds_the_motion_a_long_run_settles_on(beside):
    """At 30.6716 rad/s the branch holds a stable orbit whose amplitude is that of a 600-period
    run from rest (to 1e-6: the transient decays as the largest multiplier's modulus, measured
    below 0.9 over its stable stretch, to far below that)."""
    _, _, branch = beside
    fold = [f for f in branch.bifurcations if f.kind == "fold"]
    assert fold and abs(fold[0].omega - 30.6672) < 1e-3
    here = Forcing(F0=2.0, omega=OMEGA, phase=branch.phase)
    held = [o for o in orbits_at(branch, SYSTEM, here, E, OMEGA) if o.stable]
    run = simulate_forced(SYSTEM, Forcing(F0=2.0, omega=OMEGA), e=E, periods=600)
    amplitude = float(run.period_max[-1])
    assert any(abs(o.amplitude - amplitude) <= 1e-6 * amplitude for o in held), (
        [o.amplitude for o in held],
        amplitude,
    )


def test_beside_refuses_a_compliant_contact_and_a_band_without_the_frequency():
    with pytest.raises(MethodNotApplicable, match="rigid"):
        orbit_beside_grazing(SYSTEM, Forcing(F0=2.0, omega=OMEGA), CompliantContact("linear"),
                             START, BAND)  # fmt: skip
    with pytest.raises(ParameterError, match="bounds"):
        orbit_beside_grazing(SYSTEM, Forcing(F0=2.0, omega=OMEGA), E, START, (40.0, 45.0))
