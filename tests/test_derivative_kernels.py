"""The derivative kernels (issue 38, item 1): ``<value>_d_<argument>``, ``sympy.diff`` of a value
kernel's expression (:meth:`derive.board.Board.derivatives`), emitted to every target like any
kernel — the flight's transition matrix and its derivatives in the forcing (Step 8), the impact
map's Jacobian in the velocities and in e (Step 9), the contact durations' sensitivities
(Eqs. 34, 35) and the slow flow's response surface's slopes (Step 12).

Each is checked at its recorded points (``derive/checkpoints.py``, the points every target's
check program uses) against two things that do not use ``sympy.diff``:

- complex-step differentiation of the NumPy *value* kernel, Im f(x + ih·eᵢ)/h with h = 1e-30·|xᵢ|
  (the ``_scalar`` twin's generated code run on complex128 instead of float64): no subtraction,
  so it is as accurate as the value kernel's own rounding; agreement to 1e-12 of
  the derivative's error scale (the sum of its terms' sizes, :func:`derive.board.rounding_scale`),
  the tolerance every target is held to;
- mpmath's numerical differentiation of the value expression at 50 digits against the recorded
  50-digit value of the derivative, to 1e-12 of the same scale (mpmath's step error is far
  below it at 50 digits).

And the runtime uses them: the shooting chain's flight matrices are the derivative kernels.
"""

from __future__ import annotations

import importlib
import inspect

import mpmath as mp
import numpy as np
import pytest
import sympy as sp

from derive import checkpoints

RTOL = checkpoints.RTOL


@pytest.fixture(scope="module")
def derivatives(boards):
    """[(step, derivative kernel, value kernel, recorded points)] of every derivative kernel."""
    recorded = checkpoints.recorded(list(boards.values()))
    out = []
    for step, k, points in recorded["kernels"]:
        if k.derivative_of is None:
            continue
        value = next(v for v in boards[step].kernels if v.name == k.derivative_of[0])
        out.append((step, k, value, points))
    return out


def test_the_issue_s_kernels_have_derivatives(derivatives):
    got = {(step, k.derivative_of) for step, k, _, _ in derivatives}
    for step, value, wrt in (
        ("forced_flight", "forced_displacement", ("t", "x0", "xdot0", "F0", "X_b", "phi")),
        ("forced_flight", "forced_velocity", ("t", "x0", "xdot0", "F0", "X_b", "phi")),
        ("rigid_impact", "main_velocity_after", ("e", "xdot_minus", "ydot_minus")),
        ("rigid_impact", "impact_velocity_after", ("e", "xdot_minus", "ydot_minus")),
        ("closed_forms", "hertz_contact_duration", ("m", "M", "k_hz")),
        ("closed_forms", "linear_contact_duration", ("m", "M", "k1", "c1")),
        ("slow_flow", "clearance_for_response", ("Omega", "e", "xi")),
    ):
        for name in wrt:
            assert (step, (value, name)) in got, (step, value, name)


def _complex_twin(module, name: str):
    """The generated ``<name>_scalar`` with its float64 conversions made complex128."""
    source = inspect.getsource(getattr(module, f"{name}_scalar"))
    namespace = dict(vars(module))
    exec(source.replace("numpy.float64(", "numpy.complex128("), namespace)
    return namespace[f"{name}_scalar"]


def test_every_derivative_kernel_agrees_with_the_complex_step_of_its_value_kernel(derivatives):
    for step, k, value, points in derivatives:
        module = importlib.import_module(f"symimpact.generated.{step}")
        f, df = _complex_twin(module, value.name), getattr(module, k.name)
        i = [a.name for a in k.args].index(k.derivative_of[1])
        for p in points:
            x = [complex(float(a)) for a in p.args]
            h = 1e-30 * max(abs(x[i].real), 1e-30)
            x[i] += 1j * h
            step_value = complex(f(*(np.complex128(c) for c in x))).imag / h
            got = float(df(*(float(a) for a in p.args)))
            bound = RTOL * float(p.scale)
            assert abs(got - step_value) <= bound, (step, k.name, p.args, got, step_value)


def test_every_derivative_kernel_agrees_with_mpmath_differentiation_of_the_value(derivatives):
    for _, k, value, points in derivatives:
        symbols = [a.symbol for a in value.args]
        f = sp.lambdify(symbols, value.expr, "mpmath", cse=True)
        i = [a.name for a in k.args].index(k.derivative_of[1])
        with mp.workdps(checkpoints.DIGITS):
            for p in points:
                x = [mp.mpf(a) for a in p.args]

                def along(u, f=f, x=x, i=i):
                    return mp.re(f(*x[:i], u, *x[i + 1 :]))

                exact = mp.diff(along, x[i])
                assert abs(mp.mpf(p.value) - exact) <= RTOL * mp.mpf(p.scale), (k.name, p.args)


def test_the_shooting_chain_s_flight_matrix_is_the_derivative_of_the_flight():
    """Φ(τ) of the runtime (the derivative kernels, compiled) against central differences of the
    flight's value kernel in x0 and ẋ0 (steps 1e-6 of the state: error ~1e-10)."""
    from symimpact.generated import forced_flight as ff

    from symimpact.forced.engine import _rigid

    M, K, C = 1.3, 1000.0, 0.7
    for tau in (1e-3, 0.05, 0.4, 2.0):
        phi = _rigid.flight_matrices(np.array([tau]), np.array([M]), K, C)[0]
        h = 1e-6
        for col, (dx, dv) in enumerate(((h, 0.0), (0.0, h))):
            plus = [f(tau, M, K, C, 3.0, 1e-3, 20.0, 0.4, 0.01 + dx, 0.2 + dv)
                    for f in (ff.forced_displacement, ff.forced_velocity)]  # fmt: skip
            minus = [f(tau, M, K, C, 3.0, 1e-3, 20.0, 0.4, 0.01 - dx, 0.2 - dv)
                     for f in (ff.forced_displacement, ff.forced_velocity)]  # fmt: skip
            diff = (np.array(plus) - np.array(minus)) / (2 * h)
            assert np.allclose(phi[:2, col], diff, rtol=1e-8, atol=1e-8), (tau, col)
