"""The engine of several modes evaluates a flight in its own time (Step 8's ``flight_form``,
computed once a flight and kept in the configuration's cache by :func:`_modal_flight._free_states`):
every mode's state equals Eq. F1's kernel (``forced_state``, checked itself against mpmath) to
rounding, a mode driven exactly at its undamped frequency (no such form) takes Eq. F1's own
resonant branch, and the cache answers for the flight it was filled by, not for another."""

from __future__ import annotations

import math

import numpy as np
import pytest

from symimpact.forced.engine import _modal_flight
from symimpact.forced.engine._rigid import N_PARAMS, P_C, P_F0, P_K, P_M, P_PHI, P_W, P_XB, _xvf

OMEGA = 52.0  # rad/s, every mode driven at it


def _modes(rng: np.random.Generator) -> np.ndarray:
    """Five modes: four damped (ζ 0.001–0.2, ω 0.3–40 Ω, masses 0.1–10 kg, force and base
    amplitudes of either sign), and one undamped mode whose K is M·Ω² exactly."""
    pm = np.zeros((5, N_PARAMS))
    for i in range(4):
        M = 10 ** rng.uniform(-1, 1)
        w = OMEGA * 10 ** rng.uniform(math.log10(0.3), math.log10(40))
        pm[i, P_M], pm[i, P_K] = M, M * w * w
        pm[i, P_C] = 2 * 10 ** rng.uniform(-3, math.log10(0.2)) * M * w
        pm[i, P_F0], pm[i, P_XB] = rng.normal(), 1e-3 * rng.normal()
    pm[4, P_M], pm[4, P_K], pm[4, P_C], pm[4, P_F0] = 2.0, 2.0 * OMEGA * OMEGA, 0.0, 0.5
    pm[:, P_W], pm[:, P_PHI] = OMEGA, 0.7
    return pm


def _eq_f1(pm, t0, q0, v0, tau):
    """Each mode's (q, q̇) by Eq. F1's kernel, one mode at a time."""
    out = np.zeros((2, pm.shape[0]))
    for i in range(pm.shape[0]):
        th = (pm[i, P_W] * t0 + pm[i, P_PHI]) % (2.0 * math.pi)
        out[:, i] = _xvf(tau, pm[i, P_M], pm[i, P_K], pm[i, P_C], pm[i, P_F0], pm[i, P_XB],
                         pm[i, P_W], th, q0[i], v0[i])  # fmt: skip
    return out


@pytest.mark.parametrize("seed", range(8))
def test_the_flight_form_is_eq_f1_and_its_cache_keeps_to_its_flight(seed):
    """At 40 times of each of two flights, evaluated in turn so that the cache is refilled: the
    state equals Eq. F1's to 1e-13 of the mode's scale (its largest abs over the flight's
    times: the form regroups Eq. F1's terms, a few units of rounding of the largest; measured
    up to 1.6e-14 over 200 seeds), and
    exactly on the resonant mode (the same kernel)."""
    rng = np.random.default_rng(seed)
    pm = _modes(rng)
    N = pm.shape[0]
    form = np.zeros((N + 1, _modal_flight.FORM_COLS))
    flights = [(rng.uniform(0, 3), 1e-3 * rng.normal(size=N), 1e-2 * rng.normal(size=N))
               for _ in range(2)]  # fmt: skip
    taus = np.sort(rng.uniform(0, 4 * math.pi / OMEGA, 40))
    q, v = np.zeros(N), np.zeros(N)
    want = [np.array([_eq_f1(pm, *f, tau) for tau in taus]) for f in flights]
    for _ in range(2):
        for f, ref in zip(flights, want, strict=True):
            got = np.zeros_like(ref)
            for j, tau in enumerate(taus):
                _modal_flight._free_states(pm, form, *f, tau, q, v)
                got[j] = q, v
            scale = np.max(np.abs(ref), axis=0)
            assert np.all(np.abs(got - ref) <= 1e-13 * scale)
            assert np.array_equal(got[:, :, 4], ref[:, :, 4])  # the resonant mode's own branch
            assert form[N, 0] == f[0] and form[4, 12] == 0.0 and np.all(form[:4, 12] == 1.0)
