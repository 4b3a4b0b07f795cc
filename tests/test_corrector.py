"""The continuation's compiled Newton corrector (:mod:`symimpact.forced.orbits._corrector`) against its
Python steps (:func:`symimpact.forced.orbits.continuation._correct` with the compiled path switched
off): the same arithmetic, so the same curve, and the same refusals.  The README's system
(M 1 kg, K 1000 N/m, C 0.5 N s/m, m 0.05 kg, d 20 mm, F0 2 N, rigid e 0.6)."""

from __future__ import annotations

import numpy as np
import pytest

from symimpact.forced import Forcing
from symimpact.forced.orbits import continuation as cont
from symimpact.forced.orbits._corrector import CONVERGED, FAILED, GRAZED, correct
from symimpact.forced.orbits.frf import frequency_response
from symimpact.model.system import ImpactSystem

SYSTEM = ImpactSystem(M=1.0, K=1000.0, C=0.5, m=0.05, gap=0.02, contact="linear", k1=1e6)
FORCING, E = Forcing(F0=2.0, omega=33.0), 0.6


def _curve():
    # 30–36 rad/s: symmetric and asymmetric two-impact orbits, chatter with 10 to 16 impacts a
    # period, grazings and folds (27 branches, 543 points); no multi-start (its runs do not
    # correct)
    return frequency_response(SYSTEM, FORCING, E, np.linspace(30.0, 36.0, 61), sweeps=False,
                              multistart=0, workers=1)  # fmt: skip


def test_the_compiled_corrector_draws_the_python_corrector_s_curve(monkeypatch):
    compiled = _curve()
    monkeypatch.setattr(cont._Problem, "compiled", property(lambda self: False))
    python = _curve()
    assert len(compiled.branches) == len(python.branches) > 10
    n = 0
    for a, b in zip(compiled.branches, python.branches, strict=True):
        assert len(a.points) == len(b.points)
        for p, q in zip(a.points, b.points, strict=True):
            # measured equal to the bit; 1e-12 allows a linear solve's summation order
            assert p.omega == pytest.approx(q.omega, rel=1e-12, abs=0)
            assert p.amplitude == pytest.approx(q.amplitude, rel=1e-12, abs=0)
            assert p.stable == q.stable and p.impacts_per_period == q.impacts_per_period
            n += 1
        assert [f.kind for f in a.bifurcations] == [f.kind for f in b.bifurcations]
    assert n > 400


def _problem_at(omega: float):
    from symimpact.forced.orbits.shooting import settled_state, shoot

    f = FORCING.at(omega)
    rest, _ = settled_state(SYSTEM, f, E, warmup=300)
    orbit = shoot(SYSTEM, f, E, rest)
    problem = cont._problem(SYSTEM, f, E, orbit.state, 1, (25.0, 45.0), "omega")
    y = np.concatenate([np.asarray(orbit.state) / problem.scale, [omega / problem.unit]])
    return problem, y


def _compiled(problem, y, start=None, count=-1.0):
    from symimpact._interrupt import NO_WATCH

    t = np.array([0.0, 0.0, 0.0, 0.0, 1.0])
    return correct(problem.run_parameters(), y, y if start is None else start, t,
                   problem.scale, float(problem.unit), 1, count, 64, cont.MAX_NEWTON, cont.TOL,
                   problem.noise, problem.stall, NO_WATCH.copy())  # fmt: skip


def test_on_an_orbit_it_converges_and_refuses_what_the_python_steps_refuse():
    problem, y = _problem_at(35.0)
    outcome, y1 = _compiled(problem, y)
    assert outcome == CONVERGED and np.max(np.abs(y1 - y)) < 1e-9
    # a start with the impact mass beyond a wall, and one that is not finite: refused, as the
    # Python steps refuse them (None)
    t = np.array([0.0, 0.0, 0.0, 0.0, 1.0])
    for bad in (y + np.array([0.0, 0.0, 2.0, 0.0, 0.0]), y + np.array([np.nan, 0, 0, 0, 0])):
        assert _compiled(problem, y, start=bad)[0] == FAILED
        with pytest.MonkeyPatch.context() as mp:
            mp.setattr(cont._Problem, "compiled", property(lambda self: False))
            assert cont._correct(problem, y, t, start=bad) is None
    # an impact count other than the orbit's: grazed at the first step, as in Python
    assert _compiled(problem, y, count=3.0)[0] == GRAZED
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(cont._Problem, "compiled", property(lambda self: False))
        assert cont._correct(problem, y, t, count=3.0) == cont.GRAZE
