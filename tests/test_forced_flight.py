"""The forced free flight of Step 8 (Eq. F1) against direct numerical integration of the
equation of motion as the user writes it (force on the mass, or spring and damper attached to a
moving base), including the undamped resonance where the kernel switches branch.

Reference: scipy's DOP853 at rtol = atol-scaled 1e-12; its global error over the few hundred
periods integrated stays below 1e-9 of the response's scale (checked by the integrator's own
convergence: halving rtol changes the result by less than that), hence the 1e-8 bound below.
"""

from __future__ import annotations

import subprocess
from pathlib import Path

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from symimpact.generated import forced_flight as ff

from tests.helpers import require_tool

ROOT = Path(__file__).resolve().parent.parent
#: Integrator's global error (rtol 1e-12 over ≤ 300 periods) is ~1e-10 of the scale: 1e-8 leaves
#: a factor of 100 for the error growth with the number of periods.
RTOL = 1e-8


def _integrated(t_end, M, K, C, F0, Xb, W, phi, x0, xd0):
    def rhs(t, s):
        xb = Xb * np.cos(W * t + phi)
        xbd = -Xb * W * np.sin(W * t + phi)
        force = F0 * np.cos(W * t + phi) - C * (s[1] - xbd) - K * (s[0] - xb)
        return [s[1], force / M]

    sol = solve_ivp(rhs, (0, t_end), [x0, xd0], method="DOP853", rtol=1e-12, atol=1e-15)
    return sol.y[:, -1]


CASES = {
    "force, light damping": (1.3, 1.0, 1000.0, 0.5, 2.0, 0.0, 30.0, 0.4, 1e-3, -0.02),
    "base motion": (0.9, 2.0, 5000.0, 1.0, 0.0, 2e-3, 40.0, -1.1, 0.0, 0.1),
    "both, above resonance": (0.7, 0.5, 200.0, 0.1, -1.0, 1e-3, 55.0, 2.0, -2e-3, 0.0),
    "undamped, detuned": (2.0, 1.0, 900.0, 0.0, 1.5, 0.0, 29.0, 0.3, 0.0, 0.0),
    "undamped resonance (exact)": (2.0, 1.0, 900.0, 0.0, 1.5, 0.0, 30.0, 0.3, 1e-3, 0.01),
    "undamped resonance, base": (1.0, 4.0, 400.0, 0.0, 0.0, 1e-3, 10.0, 0.0, 0.0, 0.0),
}


@pytest.mark.parametrize("case", CASES)
def test_forced_flight_matches_integration(case):
    t, *p = CASES[case]
    x_ref, v_ref = _integrated(t, *p)
    scale = max(abs(x_ref), float(ff.linear_amplitude(*p[:6])) if p[2] > 0 else abs(x_ref))
    for f_x, f_v in (
        (ff.forced_displacement, ff.forced_velocity),
        (ff.forced_displacement_scalar, ff.forced_velocity_scalar),
    ):
        x, v = float(f_x(t, *p)), float(f_v(t, *p))
        assert np.isfinite(x) and np.isfinite(v)
        assert abs(x - x_ref) <= RTOL * scale, (case, x, x_ref)
        assert abs(v - v_ref) <= RTOL * scale * p[5], (case, v, v_ref)


def test_the_resonant_branch_grows_linearly():
    """At C = 0, Ω = ω_n the envelope grows as F0 t/(2MΩ): after n whole periods from rest with
    φ = −π/2 (force F0 sin Ωt) the displacement is −F0 t/(2MΩ) exactly (closed form of the
    textbook resonance)."""
    M, K, F0, W = 1.0, 900.0, 1.5, 30.0
    t = 10 * 2 * np.pi / W
    x = float(ff.forced_displacement(t, M, K, 0.0, F0, 0.0, W, -np.pi / 2, 0.0, 0.0))
    assert x == pytest.approx(-F0 * t / (2 * M * W), rel=1e-12)


def test_octave_selects_the_resonant_branch():
    """The Octave kernel at the exact resonance is finite and equals NumPy's (a plain
    ``c.*a + ~c.*b`` would give NaN there: the other branch divides by zero)."""
    octave = require_tool("octave-cli")
    p = CASES["undamped resonance (exact)"]
    args = ", ".join(repr(float(v)) for v in p)
    script = (
        f"addpath('{ROOT / 'generated' / 'octave'}'); "
        f"printf('%.17g\\n', forced_flight_forced_displacement({args}), "
        f"forced_flight_forced_displacement([{args.split(', ')[0]}, 0.5], {', '.join(args.split(', ')[1:])}));"
    )
    out = subprocess.run(
        [octave, "--no-gui", "--quiet", "--eval", script],
        capture_output=True,
        text=True,
        timeout=120,
        check=True,
    ).stdout.split()
    got = [float(v) for v in out]
    expected = [
        float(ff.forced_displacement(p[0], *p[1:])),
        float(ff.forced_displacement(0.5, *p[1:])),
    ]
    assert np.all(np.isfinite(got))
    np.testing.assert_allclose(got, [expected[0], expected[0], expected[1]][: len(got)], rtol=1e-13)
