"""symimpact._threads: the balance's linear algebra on one BLAS thread, and the count restored."""

from __future__ import annotations

from threadpoolctl import threadpool_info

from symimpact._threads import on_one_blas_thread, one_blas_thread


def _blas_threads() -> list[int]:
    import numpy as np

    np.linalg.eigvals(np.eye(3))  # BLAS loaded
    return [p["num_threads"] for p in threadpool_info() if p["user_api"] == "blas"]


def test_blas_runs_on_one_thread_inside_and_as_before_after():
    before = _blas_threads()
    assert before  # NumPy's BLAS is found
    with one_blas_thread():
        assert set(_blas_threads()) == {1}
    assert _blas_threads() == before

    @on_one_blas_thread
    def inside():
        """Its own docstring."""
        return _blas_threads()

    assert set(inside()) == {1} and inside.__doc__ == "Its own docstring."
    assert _blas_threads() == before
