"""The modal engine's closed-form energy ledger of one flight (:func:`_modal_ledger._mode_ledger`) against
adaptive quadrature (SciPy's QUADPACK) of the power and the dissipation along Eq. F1's flight as
the generated kernels give it."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad

from symimpact.forced.engine import _modal_ledger
from symimpact.forced.engine._rigid import (
    N_PARAMS,
    P_C,
    P_F0,
    P_K,
    P_M,
    P_PHI,
    P_W,
    P_XB,
    _vf,
    _xf,
)

CASES = {
    # M, K, C, F0, X_b, Ω, φ, t0, x0, v0, τ
    "forced, a few periods": (1.0, 1000.0, 0.5, 2.0, 0.0, 30.0, 0.3, 0.7, 1e-3, -0.02, 0.9),
    "base motion": (2.0, 800.0, 1.6, 0.0, 1e-3, 18.0, 0.0, 0.1, -2e-3, 0.05, 0.4),
    "force and base, short flight": (0.8, 3e5, 30.0, 5.0, 2e-4, 700.0, 1.1, 3.0, 1e-5, 1e-3, 1e-5),
    # ω_d next to Ω with light damping: the exponents μ ∓ iΩ nearly vanish (the series)
    "next to resonance": (
        1.0,
        1000.0,
        1e-3,
        1.0,
        0.0,
        math.sqrt(1000.0) + 1e-4,
        0.0,
        0.0,
        0.0,
        0.0,
        2.0,
    ),
}


@pytest.mark.parametrize("case", CASES)
def test_closed_form_ledger_equals_quadrature_of_the_flight(case):
    M, K, C, F0, Xb, W, phi, t0, x0, v0, tau = CASES[case]
    pm = np.zeros((1, N_PARAMS))
    pm[0, [P_M, P_K, P_C, P_F0, P_XB, P_W, P_PHI]] = M, K, C, F0, Xb, W, phi
    work, lost = _modal_ledger._mode_ledger(pm, 0, t0, x0, v0, tau)
    th = (W * t0 + phi) % (2 * math.pi)

    def state(s):
        args = (M, K, C, F0, Xb, W, th, x0, v0)
        return _xf(s, *args), _vf(s, *args)

    def power(s):
        x, v = state(s)
        c, sn = math.cos(W * (t0 + s) + phi), math.sin(W * (t0 + s) + phi)
        xb, vb = Xb * c, -Xb * W * sn
        return F0 * c * v - (K * (x - xb) + C * (v - vb)) * vb

    def dissipation(s):
        _, v = state(s)
        vb = -Xb * W * math.sin(W * (t0 + s) + phi)
        return C * (v - vb) ** 2

    limit = 2000
    w_ref = quad(power, 0.0, tau, epsabs=0.0, epsrel=1e-13, limit=limit)[0]
    d_ref = quad(dissipation, 0.0, tau, epsabs=0.0, epsrel=1e-13, limit=limit)[0]
    # the flight's energy scale bounds the rounding of both: terms of size M·v², K·x² cancel
    x1, v1 = state(tau)
    scale = M * max(v0**2, v1**2) + K * max(x0**2, x1**2) + abs(w_ref) + d_ref
    assert abs(work - w_ref) <= 1e-11 * scale, (work, w_ref)
    assert abs(lost - d_ref) <= 1e-11 * scale, (lost, d_ref)


def test_an_undamped_resonant_mode_is_left_to_quadrature():
    """At C = 0 and K = MΩ², Eq. F1 grows with t: the closed form declines (NaN) and the engine
    integrates numerically."""
    pm = np.zeros((1, N_PARAMS))
    pm[0, [P_M, P_K, P_C, P_F0, P_W]] = 1.0, 100.0, 0.0, 1.0, 10.0
    assert all(math.isnan(x) for x in _modal_ledger._mode_ledger(pm, 0, 0.0, 0.0, 0.0, 1.0))
