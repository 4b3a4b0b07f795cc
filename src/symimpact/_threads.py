"""One BLAS thread for the small dense linear algebra of the harmonic balance, and in processes
that already run one per core.

NumPy's OpenBLAS splits even a 124 × 124 eigenproblem (Hill's, H = 15) over every core: on the
2-core machine the thread hand-offs cost more than the arithmetic, and beside other work (a
pool's workers, a test run) the threads wait for each other.  Benchmark 17's balance curve took
16 s with one BLAS thread (this module) and 65 s with two on a loaded machine.  :func:`one_blas_thread`
limits BLAS to one thread for the length of a ``with`` block (threadpoolctl, which finds the
BLAS that NumPy and SciPy loaded and sets its thread count through its own API);
:func:`blas_on_one_thread_from_now` does so for the rest of a process: the pool's workers
(:mod:`symimpact._pool`), one a core, and the test suite's.
"""

from __future__ import annotations

import contextlib
import functools
from collections.abc import Callable, Iterator
from typing import Any, TypeVar

T = TypeVar("T")


@functools.cache
def _controller():
    """threadpoolctl's view of the BLAS libraries NumPy and SciPy load, both loaded first (a
    controller sees only the libraries loaded when it is made)."""
    import numpy  # noqa: F401
    import scipy.linalg  # noqa: F401
    from threadpoolctl import ThreadpoolController

    return ThreadpoolController()


@contextlib.contextmanager
def one_blas_thread() -> Iterator[None]:
    """BLAS on one thread inside the block, as it was after it."""
    with _controller().limit(limits=1, user_api="blas"):
        yield


def on_one_blas_thread(fn: Callable[..., T]) -> Callable[..., T]:
    """``fn`` run inside :func:`one_blas_thread` (a decorator)."""

    @functools.wraps(fn)
    def wrapper(*args: Any, **kwargs: Any) -> T:
        with one_blas_thread():
            return fn(*args, **kwargs)

    return wrapper


def blas_on_one_thread_from_now() -> None:
    """BLAS on one thread for the rest of this process (a worker among one a core)."""
    _controller().limit(limits=1, user_api="blas")
