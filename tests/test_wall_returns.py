"""A flight that leaves a wall slowly comes back to it: the onset search of the forced runs
(``_rigid._next_impact``, shared by rigid and compliant runs) against brute-force sampling of the
closed-form flight (Eq. F1), and whole runs against an independent check of the same thing.

Until the wall just left was certified out of reach only where sampled accelerations said so,
a flight leaving while the primary still accelerated back towards the impact mass, and turning
within a sample, could return unseen.  The impact mass then passed into the wall without a
contact: up to 43 µm in rigid runs (Ω 30.75 rad/s, e 0.6), and with a linear contact a period at
30.8 rad/s differed by 1.7e-3 of its scale from an integration of the whole system."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from symimpact.generated import forced_flight as ff

from symimpact._interrupt import NO_WATCH
from symimpact.forced import Forcing, simulate_forced
from symimpact.forced.engine import _rigid as R
from symimpact.model.system import ImpactSystem
from tests.helpers import integrate_whole_system

# the system
M, K, C, m, H, F0 = 1.0, 1000.0, 0.5, 0.05, 0.01, 2.0
SYSTEM = ImpactSystem(M=M, K=K, C=C, m=m, gap=2 * H, contact="linear", k1=1e6)


def _parameters(omega: float, phase: float) -> np.ndarray:
    p = np.zeros(R.N_PARAMS)
    p[R.P_M], p[R.P_K], p[R.P_C], p[R.P_m], p[R.P_h], p[R.P_e] = M, K, C, m, H, 0.6
    p[R.P_F0], p[R.P_W], p[R.P_PHI], p[R.P_CHAT] = F0, omega, phase, 1e-7
    return p


# no deadline: the first example compiles the onset search (numba, about 1 s on a fresh clone)
@settings(deadline=None)
@given(
    omega=st.floats(25.0, 40.0),
    phase=st.floats(0.0, 2 * math.pi),
    side=st.sampled_from([-1, 1]),
    a0=st.floats(0.1, 20.0),
    turn=st.floats(1e-4, 5e-3),
    speed=st.floats(0.02, 2.0),
)
def test_a_flight_leaving_a_wall_slowly_returns_where_sampling_finds_it(
    omega, phase, side, a0, turn, speed
):
    """The flight leaves the wall ``side`` at w = speed·a0·turn while the primary accelerates
    back towards the impact mass (side·ẍ = −a0), that acceleration vanishing after ``turn``
    (d(side·ẍ)/dt = a0/turn): the first wall reached, by sampling z of the closed-form flight
    every microsecond over 30 ms, is the onset found, on that wall.  The onset lies
    between the samples that bracket the first crossing, or is an earlier touch the samples step
    over (f = 0 there to 1e-14 of the clearance: the root's rounding)."""
    p = _parameters(omega, phase)
    acc0 = -side * a0
    v0 = (omega * (-F0 * math.sin(phase)) - C * acc0 - M * side * a0 / turn) / K
    x0 = (F0 * math.cos(phase) - C * v0 - M * acc0) / K
    # the solved start's rounding: K·x0 and C·v0 are of order 1
    assert R._accel(p, M, 0.0, x0, v0) == pytest.approx(acc0, rel=1e-9, abs=1e-9)
    w = speed * a0 * turn
    z0, u0 = side * H, v0 - side * w
    span = 0.03
    tau = np.linspace(0.0, span, 30001)
    x = ff.forced_displacement(tau, M, K, C, F0, 0.0, omega, phase, x0, v0)
    z = z0 + u0 * tau - (x - x0)
    ahead = np.nonzero(np.abs(z[1:]) >= H)[0]  # either wall
    found, wall = R._next_impact(p, 0.0, x0, v0, z0, u0, side, span, NO_WATCH)
    at_found = wall * R._z(p, 0.0, x0, v0, z0, u0, found) - H
    touch = wall != 0 and abs(at_found) <= 1e-14 * H
    if len(ahead):
        i = ahead[0] + 1
        assert wall == np.sign(z[i])
        assert found <= tau[i] + 1e-15
        assert found >= tau[i - 1] - 1e-15 or touch
    else:
        assert wall == 0 or touch


def _deepest_flight(run, omega):
    """(the largest |z| − d/2 inside any flight of a rigid run, sampled 4000 times a flight;
    the number of flights that enter a wall).  A flight begins at an impact or a release and
    ends at the next event; a sticking phase (after an accumulation) is not a flight."""
    deepest, entering = 0.0, 0
    for a, b in zip(run.events[:-1], run.events[1:], strict=True):
        if a[R.E_KIND] == R.KIND_ACCUMULATION:
            continue
        t0 = a[R.E_T]
        tau = np.linspace(0.0, b[R.E_T] - t0, 4001)[1:-1]
        x = ff.forced_displacement(tau, M, K, C, F0, 0.0, omega, (omega * t0) % (2 * math.pi),
                                   a[R.E_X], a[R.E_XD1])  # fmt: skip
        z = a[R.E_X] + a[R.E_SIDE] * H + a[R.E_YD1] * tau - x
        over = float(np.max(np.abs(z))) - H
        deepest = max(deepest, over)
        entering += over > 1e-12 * H
    return deepest, entering


def test_no_rigid_flight_enters_a_wall():
    """Rigid runs of 200 periods from rest where returns were missed (e 0.6 at 30.75 rad/s:
    250 flights into the wall, the deepest 43 µm; e 0.3 at 29.75 rad/s: 6, 14 µm): every
    flight stays within the clearance, to 1e-12 of it (the closed form's rounding)."""
    for e, omega in ((0.6, 30.75), (0.3, 29.75)):
        run = simulate_forced(SYSTEM, Forcing(F0=F0, omega=omega), e=e, periods=200)
        deepest, entering = _deepest_flight(run, omega)
        assert entering == 0, (e, omega, deepest)


def test_a_chattering_compliant_period_is_that_of_the_whole_system():
    """Linear contact (k1 1e6 N/m, c1 70.045 N s/m, e = 0.6 by Step 9) at 30.8 rad/s, where each
    period has two chatter sequences of ten or eleven contacts whose last separations are
    micrometres: one period from a state in flight after 100 periods from rest, against
    SciPy's DOP853 on the whole system (``integrate_whole_system``).  Same number of contacts;
    states to 1e-10 of their scale (the located events' rounding over twenty contacts: measured
    1.3e-13; with the missed returns it was 1.7e-3, two contacts fewer)."""
    system = SYSTEM.with_(c1=70.045)
    omega = 30.8
    run = simulate_forced(system, Forcing(F0=F0, omega=omega), contact="linear", periods=100)
    k = next(i for i in range(16) if abs(run.samples[-17 + i][2]) < 0.99 * H)
    x, v, z, u = run.samples[-17 + k]
    f = Forcing(F0=F0, omega=omega, phase=2 * math.pi * k / 16)
    one = simulate_forced(system, f, contact="linear", periods=1, x0=x, xdot0=v, y0=x + z,
                          ydot0=u)  # fmt: skip
    ref, contacts = integrate_whole_system(
        lambda d, dd: 1e6 * d + 70.045 * dd, system, f, (x, v, x + z, u), one.t_end
    )
    assert contacts == len(one.impacts) >= 18
    scale = np.array([0.1, 3.0, 0.1, 3.0])  # the amplitude and speeds of the resonant motion
    assert np.max(np.abs(np.array(one.final_state) - ref) / scale) < 1e-10
