"""∂P/∂p of the rigid stroboscopic map carried along the monodromy's chain (issue 38, item 1):
:func:`symimpact.forced.orbits.shooting.monodromy` with ``parameter`` returns a fifth column, built from
the generated derivative kernels of the flight (in F0, X_b, Ω and the phase), of the impact law (in
e), the wall's move with d, the chatter's Δ and the end of the k periods.

Checked against what does not use it: fourth-order central differences of the map itself in the
parameter, on orbits with plain impacts, with chatter that accumulates, with sticking phases and
with plastic impacts.  The differences' own error sets the tolerance: the map is computed to
~1e-12 of its size (event times located to rounding), so a step of 1e-4 of the parameter leaves
~1e-8 of noise, and fourth-order differences a truncation error of ~(1e-4)⁴ — 1e-6 of the
derivative's largest entry.  (A step of 1e-5 left 1.1e-7 to 1.3e-6 of noise on the orbit with
chatter, whose accumulation points carry more rounding, as rounding happened to fall.)
The continuation, which uses the column, traces the same branch as with differenced ∂P/∂p (the
issue's 1e-8).
"""

from __future__ import annotations

import numpy as np
import pytest

from symimpact.errors import MethodNotApplicable
from symimpact.forced import Forcing
from symimpact.forced.orbits import continuation as cont
from symimpact.forced.orbits.shooting import monodromy, shoot_from_rest
from symimpact.model.system import ImpactSystem

SYSTEM = ImpactSystem(M=1.0, K=1000.0, C=0.5, m=0.05, gap=0.02, contact="hertz", k_hz=1000.0)
FORCING = dict(F0=2.0, X_b=1e-3)


def _value(parameter: str, e: float, forcing: Forcing) -> float:
    return {"omega": forcing.omega, "gap": SYSTEM.gap, "F0": forcing.F0, "X_b": forcing.X_b,
            "e": e}[parameter]  # fmt: skip


def _orbit(forcing: Forcing, e: float, what):
    """An orbit shot from a state of the motion from rest, with ``what`` events (impacts,
    accumulations, releases) a period where given.  At 33 rad/s that motion is chaotic (three
    impacts a period on average) and Newton from a state of it lands on one of its unstable
    orbits, two or three impacts a period, or on none, as rounding moves the trajectory: the
    first warm-up that gives the orbit sought is taken."""
    for warmup in (300, 200, 400, 800, 1600, 3200):
        try:
            orbit = shoot_from_rest(SYSTEM, forcing, e, warmup=warmup)
        except MethodNotApplicable:
            continue
        res = monodromy(SYSTEM, forcing, e, np.array(orbit.state), orbit.period_multiple,
                        jacobian=False)[2]  # fmt: skip
        if what is None or tuple(np.bincount(res.events[:, 7].astype(int), minlength=3)) == what:
            return orbit
    raise AssertionError("no warm-up gave the orbit sought")


@pytest.mark.parametrize(
    ("e", "omega", "what"),
    [
        (0.6, 36.0, (2, 0, 0)),  # two impacts a period
        (0.6, 33.0, (3, 0, 0)),  # three
        (0.05, 28.0, None),  # chatter that accumulates, sticking, release
        (0.0, 29.0, None),  # plastic impacts that stick
        (0.6, 30.8, None),  # 60 impacts a period between two accumulations
    ],
)
def test_the_carried_parameter_derivative_equals_differences_of_the_map(e, omega, what):
    forcing = Forcing(omega=omega, **FORCING)
    orbit = _orbit(forcing, e, what)
    s, k = np.array(orbit.state), orbit.period_multiple
    for parameter in ("omega", "gap", "F0", "X_b", "e"):
        if parameter == "e" and e == 0.0:
            continue  # e = 0 is the edge of its range: no central difference
        problem = cont._Problem(SYSTEM, forcing, e, k, np.ones(4), 1.0, parameter)
        value = _value(parameter, e, forcing)
        _, J, res = monodromy(*problem.at(value), s, k, parameter=parameter)
        if what is not None:
            assert tuple(np.bincount(res.events[:, 7].astype(int), minlength=3)) == what
        else:  # chatter or sticking: the accumulation and release links are exercised
            assert np.any(res.events[:, 7] > 0)

        def P(v, problem=problem):
            return monodromy(*problem.at(v), s, k, jacobian=False)[0]

        h = 1e-4 * value
        fd = (8 * (P(value + h) - P(value - h)) - (P(value + 2 * h) - P(value - 2 * h))) / (12 * h)
        scale = np.max(np.abs(J[:, 4]))
        assert np.max(np.abs(J[:, 4] - fd)) <= 1e-6 * scale, (parameter, J[:, 4], fd)


@pytest.mark.parametrize(
    ("parameter", "bounds", "direction"),
    [("omega", (25.0, 40.0), -1), ("gap", (0.005, 0.04), 1), ("e", (0.3, 0.9), 1)],
)
def test_the_continuation_traces_the_same_branch_as_with_differences(
    parameter, bounds, direction, monkeypatch
):
    forcing = Forcing(omega=36.0, F0=2.0)
    orbit = shoot_from_rest(SYSTEM, forcing, 0.6)
    chain = cont.continue_orbit(SYSTEM, forcing, 0.6, orbit.state, bounds, parameter=parameter,
                                direction=direction)  # fmt: skip
    monkeypatch.setattr(cont._Problem, "carried", False)  # ∂P/∂p by differences
    diff = cont.continue_orbit(SYSTEM, forcing, 0.6, orbit.state, bounds, parameter=parameter,
                               direction=direction)  # fmt: skip
    assert len(chain.points) == len(diff.points) > 30
    a = np.array([(p.value, p.amplitude) for p in chain.points])
    b = np.array([(p.value, p.amplitude) for p in diff.points])
    assert np.all(np.abs(a - b) <= 1e-8 * np.abs(b)), np.max(np.abs(a - b) / np.abs(b), axis=0)
    assert [x.kind for x in chain.bifurcations] == [x.kind for x in diff.bifurcations]
    assert chain.stopped.split(" at ")[0] == diff.stopped.split(" at ")[0]
