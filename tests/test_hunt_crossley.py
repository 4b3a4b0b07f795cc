"""Step 11 (Eq. F4), the Hunt–Crossley contact, against independent computations: the exact
restitution against mpmath's Lambert W, the whole impact (restitution, duration, peak force,
largest penetration) against a direct integration of μδ̈ = −K_Hz·δ^{3/2}(1 + χδ̇), and the
Kelvin–Voigt tensile share against an integration of the linear law."""

from __future__ import annotations

import math

import mpmath as mp
import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import minimize_scalar
from symimpact.generated import hunt_crossley as hc

from symimpact.errors import ParameterError
from symimpact.model.hunt_crossley import (
    hunt_crossley_chi,
    hunt_crossley_impact,
    hunt_crossley_restitution,
)


def _lambert_restitution(z: float) -> mp.mpf:
    """e = (1 + W₀(−(1 + z)e^{−(1 + z)}))/z at 40 digits (mpmath's own Lambert W)."""
    with mp.workdps(40):
        zz = mp.mpf(z)
        return (1 + mp.re(mp.lambertw(-(1 + zz) * mp.exp(-(1 + zz))))) / zz


def test_restitution_equals_the_lambert_w_closed_form():
    z = np.concatenate([np.geomspace(1e-9, 1e4, 300), [0.05, 0.0499999, 30.0, 30.0000001]])
    e = hunt_crossley_restitution(z, 1.0)
    worst = max(abs(float((ei - _lambert_restitution(zi)) / _lambert_restitution(zi)))
                for zi, ei in zip(z, e, strict=True))  # fmt: skip
    # Newton's last step carries the rounding of g(−ez) − g(z), about eps/(e·z): at most 5e-15
    # relative at the series' edge z = 0.05; the 12-term series is exact to 1e-18 below it
    assert worst < 2e-14, worst
    assert hunt_crossley_restitution(0.0, 1.0) == 1.0  # χ = 0: Hertz, elastic


def _integrated(m, M, k_hz, chi, v0):
    """The contact integrated directly (DOP853, rtol 1e-13), its exit found as an event and the
    peaks of δ and F refined by Brent's method on the dense output."""
    mu = m * M / (m + M)

    def rhs(t, u):
        d = max(u[0], 0.0)
        return [u[1], -k_hz * d**1.5 * (1.0 + chi * u[1]) / mu]

    def leaves(t, u):
        return u[0]

    leaves.terminal, leaves.direction = True, -1
    hertz = 2.9432751843 * (1.25 * mu * v0**2 / k_hz) ** 0.4 / v0  # only to size the window
    sol = solve_ivp(rhs, (0.0, 20.0 * hertz), [0.0, v0], method="DOP853", rtol=1e-13,
                    atol=[1e-22, 1e-16], events=leaves, dense_output=True)  # fmt: skip
    t_end, v_end = float(sol.t_events[0][0]), float(sol.y_events[0][0][1])

    def force(t):
        d, v = sol.sol(t)
        return k_hz * max(d, 0.0) ** 1.5 * (1.0 + chi * v)

    ts = np.linspace(0.0, t_end, 4001)
    forces = np.array([force(t) for t in ts])
    i, j = int(np.argmax(forces)), int(np.argmax(sol.sol(ts)[0]))
    peak = -minimize_scalar(lambda t: -force(t), bracket=(ts[i - 1], ts[i], ts[i + 1]),
                            method="brent", options={"xtol": 1e-15}).fun  # fmt: skip
    depth = -minimize_scalar(lambda t: -sol.sol(t)[0], bracket=(ts[j - 1], ts[j], ts[j + 1]),
                             method="brent", options={"xtol": 1e-15}).fun  # fmt: skip
    return -v_end / v0, t_end, peak, depth, forces.min()


@pytest.mark.parametrize(
    ("chi", "v0", "rtol"),
    [(0.0, 0.5, 1e-10), (1e-4, 0.5, 1e-10), (0.05, 0.5, 1e-10), (0.4, 0.5, 1e-10),
     (1.0, 1.0, 1e-10), (3.0, 1.0, 1e-10),
     # e = 0.05: 1 − e·z ≈ 8e-9 keeps 8 digits of e's 16 in the duration's integrand
     (10.0, 2.0, 1e-7)],
)  # fmt: skip
def test_the_impact_equals_a_direct_integration(chi, v0, rtol):
    m, M, k_hz = 0.05, 1.0, 1e7
    got = hunt_crossley_impact(m, M, k_hz, chi, v0)
    e, duration, peak, depth, least = _integrated(m, M, k_hz, chi, v0)
    # DOP853 at rtol 1e-13 over ~1300 steps: its global error is some 1e-13 (measured 3e-14 to
    # 1.4e-13); 1e-10 is the issue's bound and leaves three digits for other machines' libm
    for name, ref in (("restitution", e), ("duration", duration), ("peak_force", peak),
                      ("max_penetration", depth)):  # fmt: skip
        assert getattr(got, name) == pytest.approx(ref, rel=rtol if name == "duration" else 1e-10)
    assert least >= 0.0  # the Hunt–Crossley force never pulls


def test_the_published_chi_are_first_order_truncations():
    for e in (0.99, 0.9, 0.6):
        chi = hunt_crossley_chi(e, 2.0)
        assert float(hunt_crossley_restitution(chi, 2.0)) == pytest.approx(e, rel=1e-13)
    # e(z) − (1 − 2z/3) = 4z²/9 − 44z³/135 + …  and  e(z) − √(1 − 4z/3) = 2z²/3 + …: at
    # z = 1e-3 the next terms are 1e-3 of the first, so 2e-3 relative bounds the difference
    z = 1e-3
    e = float(hunt_crossley_restitution(z, 1.0))
    assert (e - (1 - 2 * z / 3)) / z**2 == pytest.approx(4 / 9, rel=2e-3)
    assert (e - math.sqrt(1 - 4 * z / 3)) / z**2 == pytest.approx(2 / 3, rel=2e-3)


@pytest.mark.parametrize("e", [0.9, 0.6, 0.3])
def test_kelvin_voigt_pulls_during_the_derived_share(e):
    mu, k1 = 0.05 / 1.05, 1e6
    L = -math.log(e)
    c1 = 2 * L * math.sqrt(k1 * mu) / math.sqrt(math.pi**2 + L**2)  # Step 9's c1 for e
    wd = math.sqrt(k1 / mu - c1**2 / (4 * mu**2))
    sol = solve_ivp(lambda t, u: [u[1], -(k1 * u[0] + c1 * u[1]) / mu], (0.0, math.pi / wd),
                    [0.0, 1.0], method="DOP853", rtol=1e-12, atol=1e-16, dense_output=True)  # fmt: skip
    t = np.linspace(0.0, math.pi / wd, 200_001)
    d, v = sol.sol(t)
    pulling = np.mean(k1 * d + c1 * v < 0.0)
    # the share of 200,001 samples: within 1e-5 of the exact share
    assert pulling == pytest.approx(float(hc.kelvin_voigt_tensile_fraction(e)), abs=2e-5)


def test_bad_input_names_the_parameter():
    with pytest.raises(ParameterError, match="chi"):
        hunt_crossley_impact(0.05, 1.0, 1e7, -1.0, 0.5)
    with pytest.raises(ParameterError, match="e"):
        hunt_crossley_chi(1.5, 1.0)
    with pytest.raises(ParameterError, match="v0"):
        hunt_crossley_restitution(0.1, 0.0)
