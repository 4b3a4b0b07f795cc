"""Every generated kernel against a 50-digit mpmath evaluation of its SymPy expression.

200 random physical points per kernel, 50 for the heavy Step 10 in the slow set (seeded; each
argument uniform or log-uniform on the range its derivation declares, points violating the
kernel's constraints redrawn).  Each ``_scalar`` twin
(``math`` module, for numba) is checked at the same points.  Tolerance: 1e-12 relative; for
oscillating results the bound is 1e-12·(|value| + amplitude), because near a zero crossing the
float64 rounding of the phase dominates any relative measure.  Where a result is itself
ill-conditioned in its inputs (Step 10 with many natural periods in half a forcing period: the
phase ωτ of some hundreds of radians moves with the last bit of K, M or Ω), no float64
evaluation can do better than the inputs' rounding allows; there the bound also admits
CONDITIONING_ROUNDINGS unit roundings of every input, propagated through the exact expression
(the sum over the inputs of the change of the mpmath value when that input alone moves by that
relative amount).
"""

from __future__ import annotations

import importlib

import mpmath as mp
import numpy as np
import pytest
import sympy as sp

from derive import STEPS
from tests.helpers import physical_points

RTOL = 1e-12
N_POINTS = 200


#: Step 10's kernels (the four conditions' minors and weighted Cramer solutions, 12-14 k
#: operations each) run in the slow set.  Their mpmath references are lambdified with common
#: subexpressions shared (``cse=True``: the same exact arithmetic at 50 digits, each shared
#: subexpression once): 200 points in 16 s alone, where 50 points without it took 125 s alone
#: (298 s beside other tests) on the 2-core machine.
HEAVY = {"periodic_orbit"}
HEAVY_POINTS = N_POINTS

#: Roundings the kernels' first operations (K/M, its square root, π/Ω, their product) put on
#: the phase before the trigonometric functions see it: four, each of one unit (2^-53)
CONDITIONING_ROUNDINGS = 4
UNIT_ROUNDING = mp.mpf(2) ** -53


def conditioning_floor(reference, point, exact) -> mp.mpf:
    """The error a float64 evaluation cannot avoid: each input moved alone by a relative
    CONDITIONING_ROUNDINGS·2^-53, the changes of the exact value summed (first order)."""
    x = [mp.mpf(float(v)) for v in point]
    shift = 1 + CONDITIONING_ROUNDINGS * UNIT_ROUNDING
    total = mp.mpf(0)
    for i in range(len(x)):
        moved = list(x)
        moved[i] = x[i] * shift
        total += abs(mp.re(reference(*moved)) - exact)
    return total


@pytest.mark.parametrize(
    "step", [pytest.param(s, marks=pytest.mark.slow) if s in HEAVY else s for s in STEPS]
)
def test_kernels_match_mpmath(boards, step):
    module = importlib.import_module(f"symimpact.generated.{step}")
    rng = np.random.default_rng(20261122)
    assert boards[step].kernels, "every step emits kernels"
    for kernel in boards[step].kernels:
        symbols = [a.symbol for a in kernel.args]
        reference = sp.lambdify(symbols, kernel.expr, "mpmath", cse=True)
        scale = sp.lambdify(symbols, kernel.magnitude or 0, "mpmath", cse=True)
        n = HEAVY_POINTS if step in HEAVY else N_POINTS
        points = physical_points(kernel, rng, n)
        got = getattr(module, kernel.name)(*points.T)  # vectorised call: one array per argument
        assert got.shape == (n,)
        scalar = getattr(module, f"{kernel.name}_scalar")  # the math-module twin, point by point
        got_scalar = [scalar(*map(float, p)) for p in points]
        with mp.workdps(50):
            for p, value, value_scalar in zip(points, got, got_scalar, strict=True):
                exact = reference(*[mp.mpf(float(v)) for v in p])
                assert mp.im(exact) == 0, (kernel.name, p)
                exact = mp.re(exact)
                bound = RTOL * (abs(exact) + abs(scale(*[mp.mpf(float(v)) for v in p])))
                worst = max(abs(mp.mpf(float(value)) - exact), abs(mp.mpf(value_scalar) - exact))
                if worst > bound:  # judged against the conditioning only where it matters
                    bound += conditioning_floor(reference, p, exact)
                assert abs(mp.mpf(float(value)) - exact) <= bound, (
                    f"{step}.{kernel.name}{tuple(p)} = {value!r}, mpmath {mp.nstr(exact, 20)}"
                )
                assert isinstance(value_scalar, float)
                assert abs(mp.mpf(value_scalar) - exact) <= bound, (
                    f"{step}.{kernel.name}_scalar{tuple(p)} = {value_scalar!r}, "
                    f"mpmath {mp.nstr(exact, 20)}"
                )
