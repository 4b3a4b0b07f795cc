"""Step 17's claims about the balance in H harmonics (derive/multi_harmonic_balance.py), held to
what does not use the derivation.

- The contact force's harmonics fall as k^−(ν+1), ν the power with which the force starts at an
  onset (Eq. F12): the exact periodic orbit of the impact damper (shooting, the compliant
  engine), integrated again over one period by SciPy's DOP853 (its own law, its own events),
  sampled and transformed; the envelope's rate over 128–2048 against the board's, for
  Hunt–Crossley's δ^(3/2)(1 + χδ̇) (ν = 3/2) and Hertz with a dashpot (a step, ν = 0).
- The clearance's describing function (Eq. F11, the generated kernel and its derivatives)
  against SciPy's quadrature of the projection, and against the balance's own AFT at H = 1
  (:mod:`symimpact.forced.orbits.harmonic_balance`) as its samples grow.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import quad, solve_ivp
from symimpact.generated import multi_harmonic_balance as kernels

from symimpact.forced.contact_law import CompliantContact
from symimpact.forced.forcing import Forcing
from symimpact.forced.orbits.harmonic_balance import _problem
from symimpact.forced.orbits.shooting import shoot_from_rest
from symimpact.model.system import ImpactSystem

#: The README's primary at 34 rad/s with a Hertz contact (k_hz 1e5 N/m^1.5): a stable orbit with
#: two contacts a period, with the dashpot c₁ 0.5 N s/m or with Hunt–Crossley's χ 0.5 s/m.
W, F0 = 34.0, 2.0
CASES = {
    "hunt-crossley": (ImpactSystem(M=1.0, K=1000.0, C=0.5, m=0.05, gap=0.02, k_hz=1e5), 0.5,
                      sp.Rational(3, 2)),
    "hertz": (ImpactSystem(M=1.0, K=1000.0, C=0.5, m=0.05, gap=0.02, k_hz=1e5, c1=0.5), None, 0),
}  # fmt: skip
#: Samples of the period: the transform of a sampled step differs from the series' by the factor
#: (πk/N)/sin(πk/N), at most 2.6 % at k = 2048.
SAMPLES = 2**14


def _line(board, name):
    return next(line.value for line in board.lines if line.name == name)


def _force_record(system, law, chi, state):
    """The contact force on the primary at SAMPLES instants of one period, integrated by DOP853
    from the orbit's state (x, ẋ, z, ẏ), stopping at each wall so no step spans an onset."""
    M, K, C, m, h, k = system.M, system.K, system.C, system.m, system.gap / 2, system.k_hz

    def law_force(delta, rate):
        if delta <= 0.0:
            return 0.0
        elastic = k * delta**1.5
        return (
            elastic * (1.0 + chi * rate) if law == "hunt-crossley" else elastic + system.c1 * rate
        )

    def force(w):
        z = w[2] - w[0]
        s = 1.0 if z > h else -1.0 if z < -h else 0.0
        return s * law_force(s * z - h, s * (w[3] - w[1])) if s else 0.0

    def rhs(t, w):
        f = force(w)
        return [w[1], (F0 * math.cos(W * t) - K * w[0] - C * w[1] + f) / M, w[3], -f / m]

    def upper(t, w):
        return w[2] - w[0] - h

    def lower(t, w):
        return -(w[2] - w[0]) - h

    upper.terminal = lower.terminal = True
    T = 2 * math.pi / W
    grid = np.arange(SAMPLES) * T / SAMPLES
    out = np.zeros(SAMPLES)
    x0, v0, z0, u0 = state
    t0, w0 = 0.0, np.array([x0, v0, x0 + z0, u0])
    while t0 < T:
        sol = solve_ivp(rhs, (t0, T), w0, method="DOP853", rtol=1e-12, atol=1e-15,
                        events=(upper, lower), dense_output=True)  # fmt: skip
        t1 = sol.t[-1]
        for i in np.nonzero((grid >= t0) & (grid < t1))[0]:
            out[i] = force(sol.sol(grid[i]))
        t0, w0 = t1, sol.y[:, -1]
        if t1 < T:  # past the wall, so that its event does not end the next run at once
            t0 = t1 + 1e-12
            w0 = sol.sol(t0)
    return out, np.array([w0[0], w0[1], w0[2] - w0[0], w0[3]])


@pytest.mark.parametrize("law", CASES)
def test_the_contact_forces_harmonics_fall_as_its_onset_says(boards, law):
    system, chi, nu = CASES[law]
    board = boards["multi_harmonic_balance"]
    predicted = float(_line(board, "force_harmonic_decay").subs(sp.Symbol("nu", positive=True), nu))
    orbit = shoot_from_rest(system, Forcing(F0=F0, omega=W), CompliantContact(law, chi=chi))
    record, end = _force_record(system, law, chi, orbit.state)
    # the integration closes the orbit: SciPy's law and events are the engine's (measured 1e-9
    # of each coordinate; shooting's own residual and DOP853's tolerances are ~1e-10)
    assert np.allclose(end, orbit.state, rtol=1e-7, atol=1e-12), (end, orbit.state)
    spectrum = np.abs(np.fft.rfft(record)) / SAMPLES
    # the envelope: the largest harmonic of each octave 128–255 … 1024–2047 (two contacts a
    # period make the harmonics beat, the largest of an octave follows the rate)
    octaves = range(7, 11)
    k = np.log([1.5 * 2**j for j in octaves])
    envelope = np.log([spectrum[2**j : 2 ** (j + 1)].max() for j in octaves])
    measured = np.polyfit(k, envelope, 1)[0]
    # measured −2.51 (Hunt–Crossley, −2.5 predicted) and −0.97 (a dashpot's step, −1): the next
    # term of the onset's expansion is 1/k smaller (1/128 here) and the sampling's factor moves
    # an octave's maximum by at most 2.6 %, a slope by ~0.04
    assert abs(measured - predicted) < 0.1, (measured, predicted)


def _projected(k1, gap, A):
    """(1/π)∫ f(A cos θ) cos θ dθ over a period by SciPy's quadrature, f the linear contact's
    force k₁(|z| − d/2) sign z beyond the walls, the contact arcs' ends as break points."""
    h = gap / 2

    def f(th):
        z = A * math.cos(th)
        return math.copysign(k1 * (abs(z) - h), z) if abs(z) > h else 0.0

    arc = math.acos(h / A)
    ends = [arc, math.pi - arc, math.pi + arc, 2 * math.pi - arc]
    return quad(lambda th: f(th) * math.cos(th), 0, 2 * math.pi, points=ends,
                epsabs=0, epsrel=1e-13, limit=200)[0] / math.pi  # fmt: skip


@pytest.mark.parametrize("ratio", [0.999, 0.9, 0.5, 0.1, 1e-3])
def test_the_clearance_kernel_is_the_projection_of_the_force(ratio):
    k1, gap = 2e4, 0.02
    A = gap / 2 / ratio
    value, d_k1, d_gap, d_A = kernels.clearance_first_harmonic_and_derivatives(k1, gap, A)
    exact = _projected(k1, gap, A)
    # quadrature to 1e-13 of a piecewise-linear integrand; the kernel's terms are of size k₁A
    assert abs(value - exact) < 1e-12 * k1 * A, (value, exact)
    assert d_k1 == pytest.approx(value / k1, rel=1e-13)
    # the derivatives against central differences of the quadrature (step 1e-6 of A and d:
    # truncation ~1e-12, the quadrature's 1e-13·k₁A over 1e-6·A)
    h = 1e-6
    fd_A = (_projected(k1, gap, A * (1 + h)) - _projected(k1, gap, A * (1 - h))) / (2 * h * A)
    fd_gap = (_projected(k1, gap * (1 + h), A) - _projected(k1, gap * (1 - h), A)) / (2 * h * gap)
    assert d_A == pytest.approx(fd_A, rel=1e-6, abs=1e-6 * k1)
    assert d_gap == pytest.approx(fd_gap, rel=1e-6, abs=1e-6 * k1 * A / gap)


def test_the_balances_aft_at_one_harmonic_converges_to_the_kernel():
    """The damper's equation in the balance's residual at H = 1, y = A cos θ and x = 0:
    −mω²A + F₁, so F₁ is read from the residual; AFT's error falls as N⁻² (the force has a kink
    at each wall, sampled)."""
    system = ImpactSystem(M=1.0, K=1000.0, C=0.5, m=0.05, gap=0.02, contact="linear", k1=2e4)
    A, omega = 0.015, 30.0
    exact = float(kernels.clearance_first_harmonic(system.k1, system.gap, A))
    errors = []
    for N in (64, 256, 1024, 4096):
        pr = _problem(system, Forcing(F0=F0, omega=omega), CompliantContact("linear"), 1, N, 1)
        U = np.zeros(6)
        U[4] = A  # (x: a₀ a₁ b₁, y: a₀ a₁ b₁)
        F1 = pr.residual(U, omega)[4] + system.m * omega**2 * A
        errors.append(abs(F1 - exact) / exact)
    # N⁻² on average: 64 → 4096 samples divide the error by 4096; where the walls' kinks fall
    # between samples makes each fourfold step irregular (measured ×44, ×4.7, ×40: 1.1e-3 to
    # 1.4e-7); a first-order rule (N⁻¹) would divide it by 64 only
    assert errors[-1] < errors[0] / 1000, errors
    assert errors[-1] < 1e-6, errors
