"""A point's Taylor polynomial along a flight (:func:`_modal_search._point_taylor`), which the impact
search's refinement reads instead of every mode's exponential, cosine and sine, against the same
flight summed in mpmath (50 digits) from its closed form: Eq. F1's coefficients per mode while
the modes are uncoupled, the projection's columns while a mass rides.

Bound: 16 ulps of the terms' sizes, Σ abs(φᵢ)·(abs(aᵢ) + abs(bᵢ) + abs(cᵢ) + abs(sᵢ)) (and the
base's X_b) or Σ abs of the projection's columns: the polynomial's own truncation is below 1e-17
of them (the degree is chosen so), and Horner's rule and the coefficients' sums round a few
times at most."""

from __future__ import annotations

import math

import mpmath
import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from symimpact.forced.engine import _modal_flight, _modal_search
from symimpact.forced.engine._rigid import N_PARAMS, P_C, P_F0, P_K, P_M, P_PHI, P_W, P_XB

W, PHASE = 2 * math.pi * 7.0, 0.4
SHAPE = np.array([[1.0, -0.7, 0.4], [0.3, 1.0, -0.2]])
MASS = np.array([0.2, 0.1])
EPS = np.finfo(float).eps
mpmath.mp.dps = 50


def _parameters(xb):
    """Three modes of 6, 25 and 57 Hz (modal masses 1, 0.8, 1.2 kg, ζ 1–3 %), forced at 7 Hz."""
    pm = np.zeros((3, N_PARAMS))
    for i, (m, f, z) in enumerate(zip((1.0, 0.8, 1.2), (6.0, 25.0, 57.0), (0.01, 0.02, 0.03),
                                      strict=True)):  # fmt: skip
        w = 2 * math.pi * f
        pm[i, P_M], pm[i, P_K], pm[i, P_C] = m, m * w * w, 2 * z * w * m
        pm[i, P_F0] = (3.0, -1.0, 0.5)[i]
        pm[i, P_XB] = xb * (1.1, -0.4, 0.2)[i]  # each mode's participation in the base's motion
        pm[i, P_W], pm[i, P_PHI] = W, PHASE
    return pm


def _config(pm, stuck, xb):
    e, nothing = np.zeros(0), np.zeros(0, dtype=np.int64)
    return _modal_flight._config(pm, SHAPE, MASS, np.array(stuck), np.zeros((0, 3)), e, e, e, nothing,
                          nothing, xb)  # fmt: skip


def _horner(poly, n, s):
    acc = poly[n]
    for k in range(n - 1, -1, -1):
        acc = acc * s + poly[k]
    return acc


def _base(xb, t):
    return xb * mpmath.cos(W * mpmath.mpf(t) + PHASE)


START = (0.37, np.array([2e-3, -1e-3, 4e-4]), np.array([0.05, 0.2, -0.3]))


@settings(deadline=None)  # the first example compiles the engine's functions
@given(
    row=st.integers(0, 1),
    xb=st.sampled_from([0.0, 1e-3]),
    c=st.floats(0.0, 0.2),
    r=st.floats(1e-9, 0.49),
)
def test_the_polynomial_is_the_uncoupled_flight(row, xb, c, r):
    pm = _config(_parameters(xb), [0, 0], xb)[7]
    cfg = _config(pm, [0, 0], xb)
    assert cfg[6]  # decoupled: Eq. F1 per mode
    t0, q0, v0 = START
    q, v = np.zeros(3), np.zeros(3)
    _modal_flight._free_states(pm, cfg[10], t0, q0, v0, c, q, v)  # the flight's form, cached
    form = cfg[10]
    rate = max(W, *(math.hypot(form[i, 8], form[i, 9]) for i in range(3)))
    h = r / rate
    poly = np.empty(_modal_search.TAYLOR_MAX + 1)
    nothing = np.zeros((0, 3, 1), complex)
    n = _modal_search._point_taylor(pm, cfg, SHAPE, row, t0, q0, v0, c, h, nothing, xb, poly, 0)
    assert 0 <= n <= _modal_search.TAYLOR_MAX
    # one degree more where the derivative is read (the speed: Eq. F1's ẋ coefficients)
    speed = np.empty(_modal_search.TAYLOR_MAX + 1)
    n1 = _modal_search._point_taylor(pm, cfg, SHAPE, row, t0, q0, v0, c, h, nothing, xb, speed, 1)
    assert n1 == min(n + 1, _modal_search.TAYLOR_MAX)
    scale = abs(xb) + sum(abs(SHAPE[row, i]) * np.abs(form[i, :4]).sum() for i in range(3))
    scale_v = abs(xb) * W + sum(abs(SHAPE[row, i]) * np.abs(form[i, 4:8]).sum() for i in range(3))
    for s in np.linspace(-h, h, 7):
        tau = mpmath.mpf(c) + mpmath.mpf(s)
        exact = _base(xb, t0 + tau) - _base(xb, t0)
        rate = -xb * W * mpmath.sin(W * (t0 + tau) + PHASE)
        for i in range(3):
            f = [mpmath.mpf(x) for x in form[i, :10]]
            ex, cd, sd = mpmath.exp(-f[8] * tau), mpmath.cos(f[9] * tau), mpmath.sin(f[9] * tau)
            cw, sw = mpmath.cos(W * tau), mpmath.sin(W * tau)
            exact += SHAPE[row, i] * (f[0] * cw + f[1] * sw + ex * (f[2] * cd + f[3] * sd) - q0[i])
            rate += SHAPE[row, i] * (f[4] * cw + f[5] * sw + ex * (f[6] * cd + f[7] * sd))
        assert abs(_horner(poly, n, s) - float(exact)) <= 16 * EPS * scale
        derivative = np.polynomial.polynomial.polyval(s, np.polynomial.polynomial.polyder(
            speed[: n1 + 1]))  # fmt: skip
        assert abs(derivative - float(rate)) <= 16 * EPS * scale_v


@settings(deadline=None)  # the first example compiles the engine's functions
@given(row=st.integers(0, 1), c=st.floats(0.0, 0.2), r=st.floats(1e-9, 0.49))
def test_the_polynomial_is_the_projected_coupled_flight(row, c, r):
    pm = _config(_parameters(0.0), [1, 0], 0.0)[7]
    cfg = _config(pm, [1, 0], 0.0)
    assert not cfg[6]  # a mass rides: the coupled structure's closed form
    t0, q0, v0 = START
    n2 = cfg[2]
    rows, out = np.zeros((2, 3, n2 + 2), dtype=np.complex128), np.zeros((2, 4))
    _modal_flight._held_rows(pm, cfg, SHAPE, t0, q0, v0, rows, out)
    lam = cfg[1][-1, :n2]
    weights = cfg[11][2 * 3 + 2, :n2].real
    rate = max(W, *(abs(lam[m]) for m in range(n2) if weights[m] != 0.0))
    h = r / rate
    poly = np.empty(_modal_search.TAYLOR_MAX + 1)
    n = _modal_search._point_taylor(pm, cfg, SHAPE, row, t0, q0, v0, c, h, rows, 0.0, poly, 0)
    assert 0 <= n <= _modal_search.TAYLOR_MAX
    R = rows[row, 0]
    scale = float(np.abs(R).sum())
    for s in np.linspace(-h, h, 7):
        tau = mpmath.mpf(c) + mpmath.mpf(s)
        S = mpmath.mpf(R[n2 + 1].real) + mpmath.re(
            mpmath.mpc(R[n2].real, R[n2].imag) * mpmath.exp(mpmath.mpc(0, W) * tau)
        )
        for m in range(n2):
            if weights[m] != 0.0:
                S += mpmath.re(mpmath.mpc(R[m].real, R[m].imag)
                               * mpmath.exp(mpmath.mpc(lam[m].real, lam[m].imag) * tau))  # fmt: skip
        exact = S - mpmath.mpf(out[row, 3])  # since the start, as the sum itself reads it there
        assert abs(_horner(poly, n, s) - float(exact)) <= 16 * EPS * scale


def test_no_polynomial_where_it_would_not_converge_or_the_cache_holds_another_flight():
    pm = _config(_parameters(0.0), [0, 0], 0.0)[7]
    cfg = _config(pm, [0, 0], 0.0)
    t0, q0, v0 = START
    q, v = np.zeros(3), np.zeros(3)
    _modal_flight._free_states(pm, cfg[10], t0, q0, v0, 0.0, q, v)
    poly = np.empty(_modal_search.TAYLOR_MAX + 1)
    nothing = np.zeros((0, 3, 1), complex)
    rate = max(W, *(math.hypot(cfg[10][i, 8], cfg[10][i, 9]) for i in range(3)))
    args = (pm, cfg, SHAPE, 0)
    assert (
        _modal_search._point_taylor(*args, t0, q0, v0, 0.1, 0.49 / rate, nothing, 0.0, poly, 0) >= 0
    )
    assert (
        _modal_search._point_taylor(*args, t0, q0, v0, 0.1, 0.5 / rate, nothing, 0.0, poly, 0) == -1
    )
    assert (
        _modal_search._point_taylor(*args, t0, q0 * 2, v0, 0.1, 0.1 / rate, nothing, 0.0, poly, 0)
        == -1
    )
    assert (
        _modal_search._point_taylor(*args, t0 + 1, q0, v0, 0.1, 0.1 / rate, nothing, 0.0, poly, 0)
        == -1
    )
