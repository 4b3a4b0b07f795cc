"""Closed forms against numerical integration of the equations they solve (scipy, tight tol)."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import quad, solve_ivp
from symimpact.generated import (
    closed_forms,
    contact_fits,
    free_flight,
    lindstedt,
    ritz,
)


def _contact_time(force, mu, v0):
    """Integrate μz'' + force(z, z') = 0 from z = 0, z' = v0 until z returns to 0."""

    def rhs(t, s):
        return [s[1], -force(s[0], s[1]) / mu]

    def back(t, s):
        return s[0]

    back.terminal, back.direction = True, -1
    t_guess = 100.0
    sol = solve_ivp(
        rhs,
        (0, t_guess),
        [0.0, v0],
        events=back,
        rtol=1e-13,
        atol=1e-16,
        method="DOP853",
        first_step=1e-9,
    )
    return sol.t_events[0][0]


@pytest.mark.parametrize(
    ("m", "M", "k_hz", "v0"),
    [
        (0.15, 1.0, 1000.0, 0.075),
        (0.25, 1.0, 1000.0, 0.075),
        (0.02, 3.0, 5e6, 0.4),
        (1.0, 1.0, 1e9, 2.0),
    ],
)
def test_hertz_duration_matches_integration(m, M, k_hz, v0):
    mu = m * M / (m + M)
    # The Hertz force vanishes for z < 0; near the ends of contact the integrator sees z ≈ 0.
    t_num = _contact_time(lambda z, zd: k_hz * max(z, 0.0) ** 1.5, mu, v0)
    t_cf = closed_forms.hertz_contact_duration(m, M, k_hz, v0)
    assert abs(t_cf / t_num - 1) < 1e-9


@pytest.mark.parametrize(
    ("m", "M", "k1", "c1", "v0"),
    [
        (0.15, 1.0, 122.7, 0.0, 0.075),
        (0.25, 1.0, 122.7, 0.5, 0.075),
        (0.05, 2.0, 1e5, 3.0, 1.0),
    ],
)
def test_linear_duration_and_restitution_match_integration(m, M, k1, c1, v0):
    mu = m * M / (m + M)
    t_num = _contact_time(lambda z, zd: k1 * z + c1 * zd, mu, v0)
    assert abs(closed_forms.linear_contact_duration(m, M, k1, c1) / t_num - 1) < 1e-9
    # restitution: −ż(T)/v0 from the same integration
    sol = solve_ivp(
        lambda t, s: [s[1], -(k1 * s[0] + c1 * s[1]) / mu],
        (0, t_num),
        [0.0, v0],
        rtol=1e-13,
        atol=1e-16,
        method="DOP853",
    )
    e_num = -sol.y[1, -1] / v0
    assert abs(closed_forms.linear_restitution(m, M, k1, c1) - e_num) < 1e-9


def test_contact_fits_against_numpy_least_squares():
    x = np.linspace(0.0, 0.02, 21)
    f = 1000.0 * x**1.5
    (a, b), *_ = np.linalg.lstsq(np.c_[x**3, x], f, rcond=None)
    assert contact_fits.cubic_fit_a(1000.0, 0.02) == pytest.approx(a, rel=1e-12)
    assert contact_fits.cubic_fit_b(1000.0, 0.02) == pytest.approx(b, rel=1e-12)
    assert contact_fits.linear_fit_k1(1000.0, 0.02) == pytest.approx((x @ f) / (x @ x), rel=1e-12)
    # The paper's printed values (N/cm³, N/cm, N/m), to their printed digits.
    assert round(contact_fits.cubic_fit_a(1000.0, 0.02) / 1e6, 4) == 0.1553
    assert round(contact_fits.cubic_fit_b(1000.0, 0.02) / 1e2, 4) == 0.8360
    assert round(contact_fits.linear_fit_k1(1000.0, 0.02), 1) == 122.7


def test_continuous_fit_minimises_the_integral():
    k, d = 1000.0, 0.02
    a, b = contact_fits.cubic_fit_a_continuous(k, d), contact_fits.cubic_fit_b_continuous(k, d)

    def cost(aa, bb):
        return quad(lambda z: (k * z**1.5 - aa * z**3 - bb * z) ** 2, 0, d, epsabs=0, epsrel=1e-13)[
            0
        ]

    best = cost(a, b)
    for da, db in [(1e-3, 0), (-1e-3, 0), (0, 1e-3), (0, -1e-3)]:
        assert cost(a * (1 + da), b * (1 + db)) > best


@pytest.mark.parametrize("mode", range(4))
@pytest.mark.parametrize("xi", [0.4, 0.7, 1.0])
def test_ritz_coefficients_against_quadrature(mode, xi):
    k = ritz.BETA_L[mode]
    assert abs(np.cos(k) * np.cosh(k) + 1) < 1e-9 * np.cosh(k)

    def phi(s):
        return ritz.mode_shape(k, s)

    phi2 = quad(lambda s: phi(s) ** 2, 0, 1, epsabs=0, epsrel=1e-13, limit=200)[0]
    sigma = (np.sin(k) + np.sinh(k)) / (np.cos(k) + np.cosh(k))

    def curvature(s):  # Eq. 3 differentiated twice by hand, in ξ
        return k**2 * (-np.sin(k * s) - np.sinh(k * s) + sigma * (np.cos(k * s) + np.cosh(k * s)))

    curv2 = quad(lambda s: curvature(s) ** 2, 0, 1, epsabs=0, epsrel=1e-13, limit=200)[0]
    assert ritz.mass_coefficient(k, xi) == pytest.approx(phi2 / phi(xi) ** 2, rel=1e-10)
    assert ritz.stiffness_coefficient(k, xi) == pytest.approx(curv2 / phi(xi) ** 2, rel=1e-9)


def test_ritz_paper_values():
    assert ritz.mass_coefficient(ritz.BETA_L[0], 1.0) == pytest.approx(0.25, rel=1e-14)
    assert round(float(ritz.stiffness_coefficient(ritz.BETA_L[0], 1.0)), 4) == 3.0906
    assert ritz.tip_stiffness(70e9, 1e-10, 0.5) == pytest.approx(
        ritz.stiffness_coefficient(ritz.BETA_L[0], 1.0) * 70e9 * 1e-10 / 0.5**3, rel=1e-14
    )


@pytest.mark.parametrize("order", [1, 2, 3])
def test_lindstedt_frequency_error_scales_with_order(order):
    """Against the numerically integrated Duffing period: error ∝ (εα²/ω₀²)^(order+1)."""
    w0, alpha = 10.0, 0.01
    freq = getattr(lindstedt, f"duffing_frequency_order{order}")
    errors = []
    for lam in (0.02, 0.01):
        eps = lam * w0**2 / alpha**2

        def rhs(t, s, eps=eps):
            return [s[1], -(w0**2) * s[0] - eps * s[0] ** 3]

        def down(t, s):
            return s[0]

        down.direction = -1
        sol = solve_ivp(
            rhs, (0, 10), [alpha, 0.0], events=down, rtol=1e-13, atol=1e-16, method="DOP853"
        )
        # x crosses 0 downwards at T/4 and 5T/4 (starting at the turning point)
        t1, t2 = sol.t_events[0][:2]
        w_num = 2 * np.pi / (t2 - t1)
        errors.append(abs(freq(w0, eps, alpha) / w_num - 1))
    ratio = errors[0] / errors[1]
    assert 2 ** (order + 1) * 0.8 < ratio < 2 ** (order + 1) * 1.25, errors


def test_lindstedt_response_and_amplitude():
    w0, eps, alpha = 10.0, 5.0, 0.05  # εα²/ω₀² = 1.25e-4
    t = np.linspace(0, 2.0, 50)
    sol = solve_ivp(
        lambda t, s: [s[1], -(w0**2) * s[0] - eps * s[0] ** 3],
        (0, 2.0),
        [alpha, 0.0],
        t_eval=t,
        rtol=1e-13,
        atol=1e-16,
        method="DOP853",
    )
    err = np.max(np.abs(lindstedt.duffing_response_order3(t, w0, eps, alpha) - sol.y[0]))
    assert err < 1e-9 * alpha
    x0, v0 = 0.0, alpha * w0
    a_exact = lindstedt.duffing_amplitude(x0, v0, w0, eps)
    assert 0.5 * v0**2 == pytest.approx(
        0.5 * w0**2 * a_exact**2 + 0.25 * eps * a_exact**4, rel=1e-14
    )


def test_free_flight_against_integration():
    M, K, C, x0, v0 = 1.0, 1e4, 4.0, 0.002, -0.3
    t = np.linspace(0, 0.5, 40)
    sol = solve_ivp(
        lambda t, s: [s[1], -(C * s[1] + K * s[0]) / M],
        (0, 0.5),
        [x0, v0],
        t_eval=t,
        rtol=1e-13,
        atol=1e-16,
        method="DOP853",
    )
    assert np.allclose(
        free_flight.main_mass_displacement(t, M, K, C, x0, v0), sol.y[0], rtol=0, atol=1e-12
    )
    assert np.allclose(
        free_flight.main_mass_velocity(t, M, K, C, x0, v0), sol.y[1], rtol=0, atol=1e-10
    )
