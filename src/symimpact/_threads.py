"""One BLAS thread for the small dense linear algebra of the harmonic balance.

NumPy's OpenBLAS splits even a 124 × 124 eigenproblem (Hill's, H = 15) over every core: on the
2-core machine the thread hand-offs cost more than the arithmetic, and beside other work (a
pool's workers, a test run) the threads wait for each other.  Benchmark 17's balance curve took
22 s with one BLAS thread and 65 s with two on a loaded machine.  :func:`one_blas_thread`
limits BLAS to one thread for the length of a ``with`` block (threadpoolctl, which finds the
BLAS that NumPy and SciPy loaded and sets its thread count through its own API).
"""

from __future__ import annotations

import contextlib
import functools
from collections.abc import Iterator


@functools.cache
def _controller():
    from threadpoolctl import ThreadpoolController

    return ThreadpoolController()


@contextlib.contextmanager
def one_blas_thread() -> Iterator[None]:
    """BLAS on one thread inside the block, as it was after it."""
    with _controller().limit(limits=1, user_api="blas"):
        yield


def on_one_blas_thread(fn):
    """``fn`` run inside :func:`one_blas_thread` (a decorator)."""

    @functools.wraps(fn)
    def wrapper(*args, **kwargs):
        with one_blas_thread():
            return fn(*args, **kwargs)

    return wrapper
