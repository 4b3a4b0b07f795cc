"""Borrowed views (:mod:`symimpact.forced.engine._borrowed`): the same memory, shape and strides as the
array they borrow, in compiled code, for every layout the engines pass (1-D, 2-D, a row, an
integer and a complex array); writes through one are seen through the other; the modal
engine's configuration tuple keeps its scalars and borrows its arrays."""

from __future__ import annotations

import numpy as np
from numba import njit

from symimpact.forced.engine._borrowed import borrowed, borrowed_config


@njit
def _write_through(a, i, j, x):
    b = borrowed(a)
    b[i, j] = x
    return b.shape[0], b.shape[1], b.strides[0], b.strides[1], b[i].sum()


@njit
def _sum_of_slice(a):
    return borrowed(a)[1:].sum()


def test_a_borrowed_view_is_the_array_itself():
    a = np.arange(12.0).reshape(3, 4)
    n0, n1, s0, s1, row = _write_through(a, 1, 2, 100.0)
    assert a[1, 2] == 100.0  # the write went to the array's own memory
    assert (n0, n1, s0, s1) == (*a.shape, *a.strides)
    assert row == a[1].sum()
    for arr in (np.arange(5, dtype=np.int64), np.arange(4.0) + 1j, np.arange(10.0)[::2]):
        assert _sum_of_slice(arr) == arr[1:].sum()


def test_a_borrowed_configuration_keeps_its_scalars():
    mats, cplx, vecs = np.ones((5, 2, 2)), np.ones((3, 2), complex), np.ones((2, 2))
    pm, form, held = np.ones((2, 12)), np.zeros((3, 13)), np.zeros((7, 5), complex)
    cfg = (mats, cplx, 4, vecs, 1, True, False, pm, 3.0, 2.0, form, held, 9.0)

    @njit
    def scalars_and_write(cfg):
        b = borrowed_config(cfg)
        b[10][0, 0] = 7.0
        return b[2], b[4], b[5], b[6], b[8], b[9], b[12], b[0].sum(), b[1].sum()

    n2, h, ok, dec, wmax, wlow, lmax, m_sum, c_sum = scalars_and_write(cfg)
    assert (n2, h, ok, dec, wmax, wlow, lmax) == (4, 1, True, False, 3.0, 2.0, 9.0)
    assert m_sum == mats.sum() and c_sum == cplx.sum()
    assert form[0, 0] == 7.0
