"""The modal engine's configurations kept per pattern of stuck dampers and pressed stops
(:func:`_modal_flight._kept_config`): the pattern's code is one to one, and a pattern met again gives the
configuration computed the first time, equal to :func:`_modal_flight._config`'s."""

from __future__ import annotations

import itertools

import numpy as np

from symimpact.forced.engine import _modal_flight
from symimpact.forced.engine._rigid import N_PARAMS, P_C, P_K, P_M, P_PHI, P_W


def test_each_pattern_has_its_own_code():
    seen = {}
    for digits in itertools.product((-1, 0, 1), repeat=4):
        for split in range(5):  # the same digits split between dampers and stops
            stuck = np.array(digits[:split], dtype=np.int64)
            contact = np.array(digits[split:], dtype=np.int64)
            code = int(_modal_flight._pattern(stuck, contact))
            assert 0 <= code < 3**4
            seen.setdefault(code, set()).add(digits)
    assert all(len(d) == 1 for d in seen.values())
    assert len(seen) == 3**4
    many = np.zeros(40, dtype=np.int64)
    assert _modal_flight._pattern(many, np.zeros(0, dtype=np.int64)) == -1


def _structure():
    """Three modes (1, 4 and 9 Hz-ish, 1 % damping) and two dampers' shapes."""
    N = 3
    pm = np.zeros((N, N_PARAMS))
    for i, (m, w) in enumerate(((1.0, 6.0), (0.8, 25.0), (1.2, 57.0))):
        pm[i, P_M], pm[i, P_K], pm[i, P_C] = m, m * w * w, 2 * 0.01 * w * m
        pm[i, P_W], pm[i, P_PHI] = 7.0, 0.2
    Phi = np.array([[1.0, -0.7, 0.4], [0.5, 0.9, -0.8]])
    none = np.zeros((0, N))
    return pm, Phi, np.array([0.05, 0.03]), none


def test_a_pattern_met_again_reuses_its_configuration():
    pm, Phi, md, Sphi = _structure()
    e, i0 = np.zeros(0), np.zeros(0, dtype=np.int64)
    free = np.zeros(2, dtype=np.int64)
    keys = [_modal_flight._pattern(free, i0)]
    cfgs = [_modal_flight._config(pm, Phi, md, free, Sphi, e, e, e, i0, i0, 0.0)]
    kept = _modal_flight._kept_config.py_func  # the same code, run by Python on Python lists
    stuck = np.array([0, 1], dtype=np.int64)
    first = kept(keys, cfgs, pm, Phi, md, stuck, Sphi, e, e, e, i0, i0, 0.0)
    assert len(keys) == 2
    again = kept(keys, cfgs, pm, Phi, md, stuck.copy(), Sphi, e, e, e, i0, i0, 0.0)
    assert again is first and len(keys) == 2
    fresh = _modal_flight._config(pm, Phi, md, stuck, Sphi, e, e, e, i0, i0, 0.0)
    assert not fresh[6]  # a stuck mass couples the modes: the eigen-decomposition is kept
    for a, b in zip(first, fresh, strict=True):
        assert np.array_equal(np.asarray(a), np.asarray(b))
    other = kept(keys, cfgs, pm, Phi, md, np.array([-1, 0], dtype=np.int64), Sphi, e, e, e,
                 i0, i0, 0.0)  # fmt: skip
    assert len(keys) == 3 and other is not first
    assert kept(keys, cfgs, pm, Phi, md, free, Sphi, e, e, e, i0, i0, 0.0) is cfgs[0]
