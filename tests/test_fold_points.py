"""A located fold is a point of its branch (issue 33, items 6 and 7): the turn in Ω is drawn where
it is and the peak search sees it, rather than the segment between the points on either side
cutting across it (on the README's curve the stable five-impact orbit at 29.8756 rad/s lay
beyond the last point before the fold at 29.874, and no segment held it).

Checked by the simulation alone: the fold's point repeats over its period, both its neighbours
on the branch lie on the same side of it in Ω, and the stroboscopic map differenced by central
differences of one-period runs (not the continuation's chain) has a multiplier of +1 there."""

from __future__ import annotations

import numpy as np
import pytest

from symimpact.forced import Forcing, simulate_forced
from symimpact.forced.orbits.frf import frequency_response
from symimpact.model.system import ImpactSystem

SYSTEM = ImpactSystem(M=1.0, K=1000.0, C=0.5, m=0.05, gap=0.02, contact="linear", k1=1e6)
E = 0.6


@pytest.fixture(scope="module")
def folds():
    """(branch, fold, its point) of the README system's curve over 33–34.5 rad/s (one fold,
    at 33.7738 rad/s, where the symmetric two-impact orbits turn)."""
    frf = frequency_response(SYSTEM, Forcing(F0=2.0, omega=33.0), E, np.arange(33.0, 34.51, 0.1),
                             sweeps=False, multistart=0)  # fmt: skip
    out = []
    for b in frf.branches:
        for f in b.bifurcations:
            if f.kind == "fold":
                out.append((b, f, [i for i, p in enumerate(b.points) if p.value == f.value]))
    assert out
    return out


def _map(p, state):
    """One forcing period of the simulation from ``state`` (x, ẋ, z, ẏ) at p's phase."""
    x, v, z, u = state
    f = Forcing(F0=2.0, omega=p.omega, phase=p.phase)
    r = simulate_forced(SYSTEM, f, e=E, periods=1, x0=x, xdot0=v, y0=x + z, ydot0=u)
    X, V, Y, U = r.final_state
    return np.array([X, V, Y - X, U])


def test_each_located_fold_is_a_point_where_the_branch_turns(folds):
    for b, f, at in folds:
        assert len(at) == 1, (f, at)
        i = at[0]
        assert 0 < i < len(b.points) - 1
        before, here, after = (b.points[j].value for j in (i - 1, i, i + 1))
        assert (before - here) * (after - here) > 0  # both neighbours on one side of the turn


def test_the_fold_s_point_is_an_orbit_with_a_multiplier_of_one(folds):
    for b, _, (i,) in folds:
        p = b.points[i]
        s = np.array(p.state)
        scale = np.array(
            [p.amplitude, p.amplitude * p.omega, SYSTEM.gap / 2, p.amplitude * p.omega]
        )
        # it repeats to Newton's tolerance (1e-10 of the scale) times the map's conditioning
        assert np.max(np.abs((_map(p, s) - s) / scale)) < 1e-8
        # central differences of one-period runs, steps 1e-7 of the scale: truncation ~1e-14
        # and rounding ~1e-16/1e-7 = 1e-9 relative, times the map's entries (~10): 1e-6
        G = np.zeros((4, 4))
        for j in range(4):
            e = np.zeros(4)
            e[j] = 1e-7 * scale[j]
            G[:, j] = (_map(p, s + e) - _map(p, s - e)) / (2 * e[j])
        lam = np.linalg.eigvals(G)
        assert np.min(np.abs(lam - 1.0)) < 1e-6, lam
