"""A configuration's per-mode constants (:func:`_modal_flight._mode_constants`), which the modal engine's
acceleration bounds and closed-form ledger read instead of recomputing them every flight.

The bound must stay the one-mode engine's bound to the bit: the searches' steps and chord tests
read it, and any change to its last bit moves impact times at the rounding level.  The ledger's
integrals ∫₀^τ e^{κt} dt are checked against mpmath on both sides of the series' threshold."""

from __future__ import annotations

import math

import mpmath
import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from symimpact.forced.engine import _modal_flight, _modal_ledger
from symimpact.forced.engine._rigid import (
    N_PARAMS,
    P_C,
    P_F0,
    P_K,
    P_M,
    P_PHI,
    P_W,
    P_XB,
    _accel_bound,
)

positive = st.floats(1e-3, 1e3)


@settings(deadline=None)  # the first example compiles the engine's functions
@given(
    M=positive,
    K=st.floats(1.0, 1e8),
    zeta=st.floats(0.0, 0.5),
    F0=st.floats(-10.0, 10.0),
    Xb=st.sampled_from([0.0, 1e-3, -2e-4]),
    ratio=st.floats(0.05, 5.0),
    phi=st.floats(0.0, 6.3),
    t0=st.floats(0.0, 50.0),
    x0=st.floats(-1e-2, 1e-2),
    v0=st.floats(-1.0, 1.0),
)
def test_the_bound_from_the_constants_is_the_one_mode_engines_to_the_bit(
    M, K, zeta, F0, Xb, ratio, phi, t0, x0, v0
):
    pm = np.zeros((1, N_PARAMS))
    C = 2.0 * zeta * math.sqrt(K * M)
    W = ratio * math.sqrt(K / M)
    pm[0, [P_M, P_K, P_C, P_F0, P_XB, P_W, P_PHI]] = M, K, C, F0, Xb, W, phi
    row = np.zeros(_modal_flight.FORM_COLS)
    _modal_flight._mode_constants(pm, 0, row)
    th = (W * t0 + phi) % (2.0 * math.pi)
    ours = _modal_flight._mode_accel_bound(pm[0], row, math.cos(th), math.sin(th), t0, x0, v0, 0.1)
    engine = _accel_bound(pm[0], M, t0, x0, v0, 0.1)
    # bit for bit (NaN where the engine's is: both read the same operations)
    assert np.array([ours]).view(np.int64)[0] == np.array([engine]).view(np.int64)[0]


def _exact(k: complex, tau: float) -> complex:
    mpmath.mp.dps = 40
    kk = mpmath.mpc(k.real, k.imag)
    return complex((mpmath.exp(kk * tau) - 1) / kk)


@settings(deadline=None)  # the first example compiles the engine's functions
@given(
    r=st.floats(1e-6, 3.0),
    angle=st.floats(0.0, 2.0 * math.pi),
    tau=st.floats(1e-9, 1.0),
)
def test_the_exponential_integral_is_mpmaths(r, angle, tau):
    """(e^{κτ} − 1)/κ to 2e-15 of its size, by the series below abs(κτ) = 0.5 and by the
    quotient above (a growing or decaying exponent, where the quotient's subtraction loses
    at most a few bits for abs(κτ) ≥ 0.5: e^{κτ} − 1 is then no smaller than 0.39 of 1)."""
    k = complex(r * math.cos(angle), r * math.sin(angle)) / tau
    ek = complex(mpmath.exp(mpmath.mpc(k.real, k.imag) * tau))
    exact = _exact(k, tau)
    got = _modal_ledger._expint(k, tau, ek)
    assert abs(got - exact) <= 2e-15 * abs(exact)
    z = k * tau
    if abs(z.real) + abs(z.imag) < 0.5:  # the series alone: the reciprocal is never formed
        got = _modal_ledger._expint_by(complex(math.nan, math.nan), z, tau, ek)
        assert abs(got - exact) <= 2e-15 * abs(exact)


def test_a_mode_without_the_closed_form_says_so():
    """An undamped mode driven at its own frequency (Eq. F1 grows like t): no steady part, no
    closed-form ledger, and the bound is the engine's own resonant one."""
    pm = np.zeros((1, N_PARAMS))
    pm[0, [P_M, P_K, P_C, P_F0, P_W]] = 1.0, 100.0, 0.0, 1.0, 10.0
    row = np.zeros(_modal_flight.FORM_COLS)
    _modal_flight._mode_constants(pm, 0, row)
    assert row[_modal_flight.FC_STEADY] == 0.0 and row[_modal_flight.FC_LEDGER] == 0.0
    assert _modal_flight._mode_accel_bound(
        pm[0], row, 1.0, 0.0, 0.0, 1e-3, 0.0, 2.0
    ) == _accel_bound(pm[0], 1.0, 0.0, 1e-3, 0.0, 2.0)
    assert all(math.isnan(x) for x in _modal_ledger._mode_ledger(pm, 0, 0.0, 0.0, 0.0, 1.0))
