"""symimpact._threads: the balance's linear algebra on one BLAS thread, and the count restored."""

from __future__ import annotations

from threadpoolctl import threadpool_info, threadpool_limits

from symimpact._threads import on_one_blas_thread, one_blas_thread


def _blas_threads() -> list[int]:
    import numpy as np

    np.linalg.eigvals(np.eye(3))  # BLAS loaded
    return [p["num_threads"] for p in threadpool_info() if p["user_api"] == "blas"]


def test_blas_runs_on_one_thread_inside_and_as_before_after():
    # from two threads (the test suite's workers run on one, tests/conftest.py)
    with threadpool_limits(limits=2, user_api="blas"):
        before = _blas_threads()
        assert before and set(before) == {2}  # NumPy's BLAS is found and obeys
        with one_blas_thread():
            assert set(_blas_threads()) == {1}
        assert _blas_threads() == before

        @on_one_blas_thread
        def inside():
            """Its own docstring."""
            return _blas_threads()

        assert set(inside()) == {1} and inside.__doc__ == "Its own docstring."
        assert _blas_threads() == before


def test_a_pool_worker_runs_blas_on_one_thread():
    from symimpact._pool import spread

    with threadpool_limits(limits=2, user_api="blas"):
        assert set(_blas_threads()) == {2}
        got = list(spread(_worker_blas_threads, [0, 1], workers=2))
    assert [set(g) for g in got] == [{1}, {1}]


def _worker_blas_threads(_):
    return _blas_threads()
