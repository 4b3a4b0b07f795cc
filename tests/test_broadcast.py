"""Broadcasting invariant of every generated NumPy kernel, by hypothesis (issue 7; tolerances and
singular points, issue 15).

For each kernel, arguments are drawn as a mix of scalars, 1-D and 2-D arrays that broadcast
together.  Element by element, the array result must equal the kernel called on the scalars of
that element, and the ``*_scalar`` twin on the same numbers (NumPy float64 scalars, unbroadcast:
a separate code path, whose elementary functions may come from other loops than the vectorised
ones).

Tolerance: two faithful float64 evaluations of a formula differ by at most twice its rounding
bound at that point (``tests.helpers.rounding_bound``: the running error of the expression tree,
with 4 ULP for every elementary function, NumPy's documented worst case for its SIMD loops).  A
fixed relative tolerance cannot work: near a cancellation or with a large phase (cos of ωt at
ωt ≈ 20) the rounding of the inputs of a sum is what the result is made of.  At a singular point
(a zero divisor) the kernel and its twin give the same non-finite value (IEEE arithmetic on both
paths): the same infinity, or NaN in both.
"""

from __future__ import annotations

import importlib
import inspect
import math
import warnings

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.helpers import rounding_bound

MODULES = [
    "closed_forms",
    "contact_fits",
    "free_flight",
    "harmonic_balance",
    "lindstedt",
    "multiple_scales",
    "ritz",
]


def _kernels():
    for name in MODULES:
        mod = importlib.import_module(f"symimpact.generated.{name}")
        for fn_name in mod.__all__:
            if fn_name.endswith("_scalar") or not callable(getattr(mod, fn_name)):
                continue
            if fn_name in mod.BUNDLES:  # tuples of kernels: tests/test_bundles.py
                continue
            yield pytest.param(name, fn_name, id=f"{name}.{fn_name}")


KERNELS = list(_kernels())


@st.composite
def _arguments(draw, n_args: int):
    """n_args arguments in [0.05, 5] (the kernels' physical domain is positive; the runtime refuses
    what lies outside it), each a scalar, a (c,) or an
    (r, 1) array, so that together they broadcast to (), (c,), (r, 1) or (r, c)."""
    rows, cols = draw(st.integers(1, 4)), draw(st.integers(1, 5))
    values = st.floats(0.05, 5.0).map(float)  # no overflow in cosh(βξ) and the like
    out = []
    for _ in range(n_args):
        kind = draw(st.sampled_from(["scalar", "row", "column"]))
        shape = {"scalar": (), "row": (cols,), "column": (rows, 1)}[kind]
        size = int(np.prod(shape))
        data = np.array(draw(st.lists(values, min_size=size, max_size=size)), dtype=float)
        out.append(data.reshape(shape) if shape else float(data[0]))
    return out


def _same(got: float, expected: float, bound_of) -> bool:
    """Equal to within twice the rounding bound, or the same non-finite value."""
    if got == expected:
        return True
    if not (math.isfinite(got) and math.isfinite(expected)):
        return math.isnan(got) and math.isnan(expected)
    return abs(got - expected) <= 2.0 * bound_of()


@pytest.mark.parametrize(("step", "fn_name"), KERNELS)
def test_kernel_broadcasts_like_its_scalar_twin(boards, step, fn_name):
    mod = importlib.import_module(f"symimpact.generated.{step}")
    fn = getattr(mod, fn_name)
    twin = getattr(mod, f"{fn_name}_scalar")
    n_args = len(inspect.signature(fn).parameters)
    (kernel,) = [k for k in boards[step].kernels if k.name == fn_name]
    symbols = [a.symbol for a in kernel.args]

    @settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
    @given(args=_arguments(n_args))
    def case(args):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", RuntimeWarning)  # inf/NaN at a singular point
            result = np.asarray(fn(*args))
            shape = np.broadcast_shapes(*(np.shape(a) for a in args))
            assert result.shape == shape, (fn_name, result.shape, shape)
            expanded = [np.broadcast_to(a, shape) for a in args]
            for idx in np.ndindex(shape):
                point = [float(a[idx]) for a in expanded]
                one = float(np.asarray(fn(*point)))
                two = twin(*point)
                assert isinstance(two, float), (fn_name, type(two))
                got = float(result[idx])
                for expected in (one, float(two)):
                    assert _same(
                        got, expected, lambda p=point: rounding_bound(kernel.expr, symbols, p)
                    ), (
                        fn_name,
                        point,
                        got,
                        expected,
                    )

    case()


def _kernels_with(arg: str):
    for step, fn_name in (p.values for p in KERNELS):
        fn = getattr(importlib.import_module(f"symimpact.generated.{step}"), fn_name)
        if arg in inspect.signature(fn).parameters:
            yield pytest.param(step, fn_name, id=f"{step}.{fn_name}")


@pytest.mark.parametrize(("step", "fn_name"), list(_kernels_with("ba")))
def test_kernel_and_twin_agree_at_the_singular_amplitude_ratio(step, fn_name):
    """B/A = 1 makes B − A vanish (Eq. 21–33 divide by it): the kernel and its twin give the same
    non-finite value, and neither raises."""
    mod = importlib.import_module(f"symimpact.generated.{step}")
    fn, twin = getattr(mod, fn_name), getattr(mod, f"{fn_name}_scalar")
    names = list(inspect.signature(fn).parameters)
    point = [1.0 if n == "ba" else 0.5 for n in names]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        got, twin_value = float(fn(*point)), float(twin(*point))
    assert (got == twin_value) or (math.isnan(got) and math.isnan(twin_value)), (got, twin_value)
