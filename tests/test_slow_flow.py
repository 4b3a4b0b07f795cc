"""Step 12's slow flow (Eq. F5) against independent references: quadrature for the triangle's
harmonic, the textbook linear response, Step 10's exact orbits (which do not assume m ≪ M or a
harmonic primary) and a brute-force scan of the slow flow's own response for the best
clearance."""

from __future__ import annotations

import math

import mpmath as mp
import numpy as np
import pytest

from symimpact.errors import MethodNotApplicable, ParameterError
from symimpact.forced import Forcing, periodic_orbits
from symimpact.forced.orbits.slow_flow import backbone, best_clearance, slow_flow_responses
from symimpact.model.system import ImpactSystem

E = 0.6


def _system(m, gap=0.02, C=0.5):
    return ImpactSystem(M=1.0, K=1000.0, C=C, m=m, gap=gap, k_hz=1e9)


def test_triangle_first_harmonic_against_quadrature(boards):
    board = boards["slow_flow"]
    a1 = float(next(line.value for line in board.lines if line.name == "first_harmonic"))
    with mp.workdps(30):
        tri = lambda s: 1 - 2 * abs(s) / mp.pi  # noqa: E731
        quad = mp.quad(lambda s: tri(s) * mp.cos(s), [-mp.pi, 0, mp.pi]) / mp.pi
        third = mp.quad(lambda s: tri(s) * mp.cos(3 * s), [-mp.pi, 0, mp.pi]) / mp.pi
    assert abs(a1 - float(quad)) < 1e-15  # a1 = 8/π², one rounding of a number near 0.8
    assert abs(float(third) - a1 / 9) < 1e-15  # and 1/k² for the odd harmonics


def test_a_tiny_impact_mass_gives_the_linear_response():
    # m → 0: the textbook FRF F0/√((K − MΩ²)² + (CΩ)²), typed here, not taken from the kernels
    for W in (20.0, 28.0, 36.0):
        sys_ = _system(1e-9, gap=1e-4)  # a small clearance so that the damper stays active
        (top, *_) = slow_flow_responses(sys_, Forcing(F0=2.0, omega=W), E)
        linear = 2.0 / math.hypot(1000.0 - W**2, 0.5 * W)
        # the neglected impact mass changes the response by O(m/M) = 1e-9
        assert abs(top.amplitude - linear) <= 1e-8 * linear


@pytest.mark.parametrize("mass_ratio", [0.001, 0.01, 0.05])
def test_the_slow_flow_approaches_the_exact_orbit_as_the_impact_mass_shrinks(mass_ratio):
    """The exact symmetric orbit (Step 10, itself checked against simulation) and the slow flow
    differ at first order in m/M (the slow flow drops the primary's velocity jump at an impact,
    (1 + e)μ/M of the relative speed, and the triangle's higher harmonics it drives).  Measured
    error/(m/M) = 0.11, 0.14, 0.30 at m/M = 0.001, 0.01, 0.05 over these frequencies; the bound
    is m/M itself."""
    worst = 0.0
    for W in (28.0, 30.0, 33.0, 34.0, 36.0):
        f = Forcing(F0=2.0, omega=W)
        exact = [o for o in periodic_orbits(_system(mass_ratio), f, E) if o.admissible]
        slow = slow_flow_responses(_system(mass_ratio), f, E)
        for o in exact:
            nearest = min(slow, key=lambda r: abs(r.amplitude - o.amplitude))
            worst = max(worst, abs(nearest.amplitude - o.amplitude) / o.amplitude)
            assert nearest.admissible
            if o.stable:  # the stable exact orbit is the slow flow's upper branch
                assert nearest.upper
    assert 0.0 < worst <= mass_ratio


def test_the_best_clearance_against_a_brute_force_scan():
    """The backbone's largest clearance d_opt (Eq. F5) against the slow flow's responses scanned
    over the band: just below d_opt an admissible upper-branch response exists near the
    resonance, just above it none does anywhere in the band (the absorber is inactive at the
    resonance); at 0.8·d_opt the backbone's peak ξ·d/2 equals the scanned peak to within the
    backbone's own approximation (it is where the balance's real part vanishes, not where the
    amplitude peaks: a difference of second order in the damping, about 1e-3 here)."""
    sys0 = _system(0.05)
    force = Forcing(F0=2.0, omega=30.0)
    best = best_clearance(sys0, force, E)
    band = np.linspace(27.0, 34.0, 1401)  # 0.005 rad/s steps

    def scanned_peak(d):
        peak = 0.0
        for W in band:
            for r in slow_flow_responses(_system(0.05, gap=d), Forcing(F0=2.0, omega=W), E):
                if r.upper and r.admissible:
                    peak = max(peak, r.amplitude)
        return peak

    assert scanned_peak(0.99 * best.clearance) > 0.0
    assert scanned_peak(1.01 * best.clearance) == 0.0
    d = 0.8 * best.clearance
    from scipy.optimize import brentq

    lx = brentq(
        lambda v: float(backbone(sys0, force, E, [math.exp(v)]).clearance[0]) - d,
        math.log(best.xi),
        math.log(best.xi * 1e4),
    )
    predicted = math.exp(lx) * d / 2
    assert abs(scanned_peak(d) - predicted) <= 5e-3 * predicted
    # and the damper's point: the peak is far below the primary's own resonance peak F0/(C·ω_n)
    assert best.amplitude < 0.3 * 2.0 / (0.5 * math.sqrt(1000.0))


def test_bad_input_is_refused_in_one_line():
    sys0, force = _system(0.05), Forcing(F0=2.0, omega=30.0)
    with pytest.raises(ParameterError, match=r"^e: "):
        slow_flow_responses(sys0, force, 1.5)
    with pytest.raises(ParameterError, match=r"^xi: "):
        backbone(sys0, force, E, [0.01])
    with pytest.raises(MethodNotApplicable):
        best_clearance(_system(0.05, C=0.0), force, E)
