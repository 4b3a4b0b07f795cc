"""The package's compiled functions: numba's ``njit(cache=True)``, compiled once per argument
type, not once per constant a caller passes.

numba types a constant written in compiled code as a literal (``Literal[int](0)``,
``Literal[bool](False)``), and a jitted function called with it from compiled code is compiled
afresh for that value, with every function it calls.  The event-driven engine's helpers are
called with constants (a wall's side, a column, whether the variational equations run), and
numba's decorator compiled up to nine specialisations of one helper, and the rigid forced
engine's first compilation took 35 % longer than with one specialisation per type (one run of
each on a fresh cache, the same machine; with the one-mode run's compiled wrapper also gone,
175 s → 120 s of one core: benchmark 15 in ``benchmarks/RESULTS.md``), the results bit for bit
the same.  The branches numba pruned on a literal flag are taken at run time instead (a
comparison per call).

``compiled`` is used as numba's decorator is: ``@compiled``, ``compiled(f)`` or
``compiled(error_model="numpy")(f)``; the result is cached on disk (``NUMBA_CACHE_DIR`` or
``__pycache__``) as ``njit(cache=True)``'s is.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from numba.core import config, types
from numba.core.registry import CPUDispatcher


class _OneTypeDispatcher(CPUDispatcher):
    """numba's CPU dispatcher, its calls from compiled code typed without their literal values."""

    def get_call_template(self, args, kws):
        args = tuple(types.unliteral(a) for a in args)
        kws = {k: types.unliteral(v) for k, v in kws.items()}
        return super().get_call_template(args, kws)


def compiled(func: Callable | None = None, **options: Any) -> Any:
    """``func`` compiled in numba's nopython mode, cached on disk, one specialisation per
    argument type (module text); ``options`` are numba's (e.g. ``error_model="numpy"``)."""

    def wrap(f: Callable) -> CPUDispatcher:
        if config.DISABLE_JIT:  # NUMBA_DISABLE_JIT=1, as njit does: the function itself
            return f
        targetoptions = {"nopython": True, "boundscheck": None, **options}
        dispatcher = _OneTypeDispatcher(py_func=f, locals={}, targetoptions=targetoptions)
        dispatcher.enable_caching()
        return dispatcher

    return wrap if func is None else wrap(func)
