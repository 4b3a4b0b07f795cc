"""Continuation of rigid-impact orbits in Ω (issue 21, item 2), against the closed form (Eq. F3),
which is independent of it: its two symmetric orbits exist where r(Ω) ≥ abs(c(Ω)) (a fold where
they meet), its multipliers come from Step 9's saltation matrix at the closed-form state, and its
admissibility test sees the impact mass graze a wall."""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import brentq
from symimpact.generated import periodic_orbit as po

from symimpact.errors import ParameterError
from symimpact.forced import Forcing, periodic_orbits
from symimpact.forced.orbits.continuation import continue_orbit

sys.path.insert(0, str(Path(__file__).parent))
from test_shooting import SYSTEM, E, _orbits, _quarter


def _closed(omega):
    return periodic_orbits(SYSTEM, Forcing(F0=2, omega=omega), E)


def _branch(which, direction, band=(25.0, 50.0)):
    (o,) = [o for o in _orbits(36.0) if o.stable == (which == "stable")]
    state, f = _quarter(o, 36.0)
    return continue_orbit(SYSTEM, f, E, state, band, direction=direction)


def _located(branch, kind):
    found = [b for b in branch.bifurcations if b.kind == kind]
    assert len(found) == 1, branch.bifurcations
    return found[0]


def test_the_branch_is_the_closed_form_orbit_with_its_stability():
    """Every point of the stable symmetric branch below 36 rad/s, down to its grazing: the
    closed-form admissible orbit at the same Ω (amplitude to 1e-8: both are exact to rounding,
    the amplitude's refinement to ~1e-12) and the same stability verdict."""
    branch = _branch("stable", -1)
    assert len(branch.points) > 50
    for p in branch.points:  # (above 35.4 rad/s the unstable orbit is admissible too)
        o = min(_closed(p.omega), key=lambda o: abs(o.amplitude - p.amplitude))
        assert o.admissible
        assert p.amplitude == pytest.approx(o.amplitude, rel=1e-8)
        assert p.stable == o.stable and p.impacts_per_period == 2


def test_branch_point_and_grazing_sit_where_the_closed_form_says():
    """Going down from 36 rad/s the symmetric orbit loses stability at a symmetry-breaking branch
    point (a real multiplier through +1; the closed form's multiplier there: 1 to 1e-5, as the
    located point is interpolated across the singular corrector, error ~ds⁴) and ends where it
    grazes a wall (the closed form's admissibility flips within 1e-4 rad/s of the located Ω)."""
    branch = _branch("stable", -1)
    bp = _located(branch, "branch-point")
    o = min(_closed(bp.omega), key=lambda o: abs(o.amplitude - bp.amplitude))
    assert abs(max(o.multipliers) - 1.0) < 1e-5
    graze = _located(branch, "grazing")
    assert branch.stopped.startswith("grazing")
    assert next(o.admissible for o in _closed(graze.omega + 1e-4))
    assert not any(o.admissible for o in _closed(graze.omega - 1e-4))


def test_neimark_sacker_and_fold_sit_where_the_closed_form_says():
    """Up from 36 rad/s: the stable orbit loses stability at a Neimark–Sacker point (the closed
    form's complex pair of modulus 1 to 1e-9 there; measured 1.2e-12), and the unstable orbit
    turns at the fold where the two symmetric orbits meet, r(Ω) = abs(c(Ω)) by Brent's method
    on the generated phase coefficients (measured 3e-15 apart; 1e-8 asserted)."""
    # the first along the branch: beyond the fold the branch comes back on the unstable
    # symmetric orbit, which has a Neimark–Sacker point of its own (41.75 rad/s)
    ns = next(f for f in _branch("stable", 1).bifurcations if f.kind == "neimark-sacker")
    (o,) = [o for o in _closed(ns.omega) if o.stable or o.multipliers[0] < 1.001]
    assert abs(o.multipliers[0] - 1.0) < 1e-9

    def existence(w):
        args = (SYSTEM.M, SYSTEM.K, SYSTEM.C, SYSTEM.m, E, SYSTEM.gap, 2.0, 0.0, w)
        a, b = float(po.phase_cos_coefficient(*args)), float(po.phase_sin_coefficient(*args))
        return math.hypot(a, b) - abs(float(po.phase_right_side(*args)))

    fold = _located(_branch("unstable", 1), "fold")
    exact = brentq(existence, 45.0, 50.0, xtol=1e-14)
    assert fold.omega == pytest.approx(exact, rel=1e-8)
    assert np.isclose(fold.amplitude, _closed(exact)[0].amplitude, rtol=1e-4)


@pytest.mark.parametrize(
    ("parameter", "bounds", "direction"),
    [("gap", (0.012, 0.02), -1), ("F0", (1.0, 2.5), 1), ("e", (0.3, 0.6), -1)],
)
def test_continuation_in_gap_force_and_restitution_is_the_closed_form(parameter, bounds,
                                                                        direction):  # fmt: skip
    """The stable symmetric orbit at Ω = 36 rad/s continued in the clearance, the force amplitude
    and the restitution: at every point, the closed-form orbit of the system with that value has
    the same amplitude (1e-8, as in Ω) and the same stability; each point knows its value.  In
    the clearance the branch crosses a branch point, located where the closed form's largest
    multiplier is 1 (1e-5, as in Ω)."""
    (o,) = [o for o in _orbits(36.0) if o.stable]
    state, f = _quarter(o, 36.0)
    branch = continue_orbit(SYSTEM, f, E, state, bounds, parameter=parameter, direction=direction)
    assert branch.parameter == parameter and len(branch.points) >= 5, branch.stopped
    for p in branch.points:
        assert p.omega == 36.0 and bounds[0] - 0.1 * (bounds[1] - bounds[0]) <= p.value
        system, forcing, e = SYSTEM, Forcing(F0=2, omega=36.0), E
        if parameter == "gap":
            system = SYSTEM.with_(gap=p.value)
        elif parameter == "F0":
            forcing = Forcing(F0=p.value, omega=36.0)
        else:
            e = p.value
        closed = [c for c in periodic_orbits(system, forcing, e) if c.admissible]
        c = min(closed, key=lambda c: abs(c.amplitude - p.amplitude))
        assert p.amplitude == pytest.approx(c.amplitude, rel=1e-8), (p.value, branch.stopped)
        assert p.stable == c.stable
    if parameter == "gap":  # the symmetry-breaking branch point at d = 14.64 mm, as in Ω
        bp = _located(branch, "branch-point")
        closed = periodic_orbits(SYSTEM.with_(gap=bp.value), Forcing(F0=2, omega=36.0), E)
        c = min(closed, key=lambda c: abs(c.amplitude - bp.amplitude))
        assert abs(max(c.multipliers) - 1.0) < 1e-5


def test_continuation_refuses_bad_parameters():
    (o,) = [o for o in _orbits(36.0) if o.stable]
    state, f = _quarter(o, 36.0)
    for kwargs, name in (({"parameter": "K"}, "parameter"), ({"bounds": (0.3, 0.2)}, "bounds"),
                         ({"parameter": "e", "bounds": (0.5, 1.5)}, "bounds"),
                         ({"parameter": "gap", "bounds": (0.03, 0.05)}, "bounds")):  # fmt: skip
        args = {"bounds": (30.0, 40.0), **kwargs}
        with pytest.raises(ParameterError) as exc:
            continue_orbit(SYSTEM, f, E, state, args.pop("bounds"), **args)
        assert exc.value.parameter == name
