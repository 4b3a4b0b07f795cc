"""The JAX target (issue 38, item 3): ``symimpact.generated.jax``, generated from the same
expressions as every other target, checked against mpmath and JAX's own transformations.

- Every kernel, called once on the arrays of its recorded points (``derive/checkpoints.py``, as
  the C, Rust and Fortran tests), against the 50-digit mpmath values to 1e-12 of the error scale;
  every iteration mapped with ``jax.vmap`` over its points, value and steps (within one).
- ``jax.vmap`` of each kernel equals its single calls to 1e-13 of the scale (the same formula;
  XLA may fuse a batch differently, which moves the last bits).
- ``jax.jacfwd`` of each kernel, with respect to every argument, at its first recorded point
  against the derivative of the derivation's expression (``sympy.diff``) evaluated by mpmath at
  50 digits, to 1e-9 of the derivative's scale |∂f/∂xᵢ| + scale/|xᵢ|: differentiation through
  the generated code multiplies rounding by the formula's conditioning, which 1e-9 leaves a
  factor 10⁶ above double rounding for.
On a CI machine (``CI`` set) a missing JAX fails the test; elsewhere it skips.
"""

from __future__ import annotations

import importlib
import os

import mpmath as mp
import numpy as np
import pytest
import sympy as sp

from derive import checkpoints

try:
    import jax
    import jax.numpy as jnp
except ImportError:  # pragma: no cover - the test extra installs it
    if os.environ.get("CI"):
        raise
    pytest.skip("jax is not installed", allow_module_level=True)

RTOL = checkpoints.RTOL
VMAP_RTOL = 1e-13
GRAD_RTOL = 1e-9


@pytest.fixture(scope="module")
def recorded(boards):
    return checkpoints.recorded(list(boards.values()))


def _module(name: str):
    return importlib.import_module(f"symimpact.generated.jax.{name}")


def _columns(points) -> list[np.ndarray]:
    return [np.array([float(p.args[i]) for p in points]) for i in range(len(points[0].args))]


def test_every_kernel_and_iteration_agrees_with_mpmath_at_the_recorded_points(recorded):
    for module, k, points in recorded["kernels"]:
        got = np.asarray(getattr(_module(module), k.name)(*_columns(points)), dtype=float)
        expected = np.array([float(p.value) for p in points])
        scale = np.array([float(p.scale) for p in points])
        assert np.all(np.abs(got - expected) <= RTOL * scale), (module, k.name, got, expected)
    assert jax.config.jax_enable_x64  # importing the package turned on float64
    for module, fp, points in recorded["iterations"]:
        f = getattr(_module(module), fp.name)
        axes = (0,) * len(fp.args) + (None, None)
        value, steps = jax.vmap(f, in_axes=axes)(*_columns(points), fp.tol, fp.max_iter)
        expected = np.array([float(p.value) for p in points])
        assert np.all(np.abs(np.asarray(value) - expected) <= RTOL * np.abs(expected)), fp.name
        assert np.all(np.abs(np.asarray(steps) - [p.steps for p in points]) <= 1), fp.name


def test_vmap_equals_single_calls(recorded):
    for module, k, points in recorded["kernels"]:
        f = getattr(_module(module), k.name)
        mapped = np.asarray(jax.vmap(f)(*(jnp.asarray(c) for c in _columns(points))))
        single = np.array([float(f(*(float(a) for a in p.args))) for p in points])
        scale = np.array([float(p.scale) for p in points])
        assert np.all(np.abs(mapped - single) <= VMAP_RTOL * scale), (module, k.name)


@pytest.mark.slow  # about a minute and a half: sympy.diff and mpmath of every kernel
def test_jacfwd_agrees_with_the_derivative_of_the_expression(recorded):
    for module, k, points in recorded["kernels"]:
        if not k.args:
            continue
        f = getattr(_module(module), k.name)
        p = points[0]
        x = [float(a) for a in p.args]
        jac = jax.jacfwd(f, argnums=tuple(range(len(x))))(*x)
        symbols = [a.symbol for a in k.args]
        with mp.workdps(checkpoints.DIGITS):
            args = [mp.mpf(v) for v in x]
            for i, s in enumerate(symbols):
                exact = mp.re(sp.lambdify(symbols, sp.diff(k.expr, s), "mpmath")(*args))
                bound = GRAD_RTOL * (abs(exact) + mp.mpf(p.scale) / abs(args[i]))
                assert abs(mp.mpf(float(jac[i])) - exact) <= bound, (
                    module, k.name, s, float(jac[i]), float(exact))  # fmt: skip
