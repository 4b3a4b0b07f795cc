"""symimpact._compiled: one specialisation per argument type, whatever constants the callers pass
(numba's njit compiles one per literal value), with the same results."""

from __future__ import annotations

import numba
import numpy as np

from symimpact._compiled import compiled


def _helper(x, side):
    if side > 0:
        return x + side
    return x - 1.0


def _callers(jit):
    helper = jit(_helper)

    @jit
    def caller(x):
        # three constants and a flag written in compiled code: numba types each as a literal
        return helper(x, 0) + helper(x, 1) + helper(x, 2) + helper(x, True)

    return helper, caller


def test_constants_passed_from_compiled_code_compile_the_callee_once():
    helper, caller = _callers(compiled)
    assert caller(1.5) == (1.5 - 1.0) + 2.5 + 3.5 + 2.5
    assert len(helper.signatures) == 2  # (float64, int64) and (float64, bool): types, not values
    # numba's own decorator, for contrast: one specialisation per constant
    plain_helper, plain_caller = _callers(numba.njit)
    assert plain_caller(1.5) == caller(1.5)
    assert len(plain_helper.signatures) == 4


def test_options_and_calls_from_python_are_numbas():
    @compiled(error_model="numpy")
    def ratio(a, b):
        return a / b

    assert np.isinf(ratio(1.0, 0.0))  # numpy's error model: no ZeroDivisionError
    assert compiled(_helper)(2.0, 3) == 5.0
