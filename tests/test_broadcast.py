"""Broadcasting invariant of every generated NumPy kernel, by hypothesis (issue 7).

For each kernel, arguments are drawn as a mix of scalars, 1-D and 2-D arrays that broadcast
together.  Element by element, the array result must equal the kernel called on the scalars of
that element, and the ``*_scalar`` twin (Python floats and the ``math`` module, a separate code
path) on the same numbers, to 1e-14 relative (NaN where and only where the twin gives NaN or
raises a math domain error).  The compiled Eq. 31 kernels are checked likewise in
tests/test_fixed_points.py.
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
            yield pytest.param(mod, fn_name, id=f"{name}.{fn_name}")


KERNELS = list(_kernels())


def _scalar_twin(fn, args):
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            return float(fn(*args))
    except (ValueError, ZeroDivisionError, OverflowError):  # math's domain errors: NaN in NumPy
        return math.nan


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


@pytest.mark.parametrize(("mod", "fn_name"), KERNELS)
def test_kernel_broadcasts_like_its_scalar_twin(mod, fn_name):
    fn = getattr(mod, fn_name)
    twin = getattr(mod, f"{fn_name}_scalar")
    n_args = len(inspect.signature(fn).parameters)

    @settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
    @given(args=_arguments(n_args))
    def case(args):
        with np.errstate(all="ignore"):
            result = np.asarray(fn(*args))
            shape = np.broadcast_shapes(*(np.shape(a) for a in args))
            assert result.shape == shape, (fn_name, result.shape, shape)
            expanded = [np.broadcast_to(a, shape) for a in args]
            for idx in np.ndindex(shape):
                point = [float(a[idx]) for a in expanded]
                one = float(np.asarray(fn(*point)))
                two = _scalar_twin(twin, point)
                got = float(result[idx])
                for expected in (one, two):
                    if math.isnan(expected) or math.isnan(got):
                        assert math.isnan(expected) and math.isnan(got), (fn_name, point)
                    else:
                        assert got == pytest.approx(expected, rel=1e-14, abs=1e-300), (
                            fn_name,
                            point,
                        )

    case()
