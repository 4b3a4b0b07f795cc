"""Compiled figures of a run, and the compiled loop that runs a chunk of map points.

:func:`symimpact.free.simulation.simulate` and the maps use the same functions here, so a map row
and the result of ``simulate`` for the same point hold the same bits:

- :func:`prepare`: the tolerances and the rest threshold of a run (from its initial state) and
  its initial energy;
- :func:`ledger`: the final energy and the residual of the energy balance;
- :func:`damping_inclination_of`: DI of Eq. 36, the least-squares slope through the first
  positive maxima of x against t' = t·ω_n;
- :func:`zeta_eq_of`: the equivalent viscous damping ratio from the log-slope of the envelope;
- :func:`run_many`: one compiled loop over the points of a chunk, each run by
  :func:`symimpact.free._stepper.run` and summarised by the functions above.

This module is private: the public API is :func:`symimpact.free.simulation.simulate` and
:func:`symimpact.maps.parameter_map`.
"""

from __future__ import annotations

import math

import numpy as np

from .._compiled import compiled
from . import _stepper as st

# columns of a summary row (run_many)
(
    R_STATUS,
    R_N_IMPACTS,
    R_N_EFFECTIVE,
    R_DI,
    R_ZETA,
    R_E_INITIAL,
    R_DISS_C,
    R_DISS_C1,
    R_RESIDUAL,
) = range(9)
N_ROW = 9


@compiled
def prepare(p, x0, xd0, y0, yd0, rtol, rest):
    """Set the tolerances of the contact integration and the rest threshold in ``p`` from the
    initial state; return the initial mechanical energy [J].

    Absolute tolerances are ``rtol``·1e-3 of the run's length scale (the half gap, the initial
    displacements, the main mass's amplitude √(2E/K)) and of its speed scale (the initial speeds,
    ω_n times those lengths); the rest threshold is ``rest`` × the initial energy.
    """
    M, K, m, h = p[st.P_M], p[st.P_K], p[st.P_m], p[st.P_h]
    wn = math.sqrt(K / M)
    e0_main = 0.5 * M * xd0 * xd0 + 0.5 * K * x0 * x0
    amp = math.sqrt(2.0 * e0_main / K)
    length = max(h, abs(x0), abs(y0), amp)
    speed = max(abs(xd0), abs(yd0), wn * amp, wn * h)
    e_initial = e0_main + 0.5 * m * yd0 * yd0
    p[st.P_rtol] = rtol
    p[st.P_atolx] = rtol * 1e-3 * length
    p[st.P_atolv] = rtol * 1e-3 * speed
    p[st.P_rest] = rest * e_initial
    return e_initial


@compiled
def ledger(law, p, u, side, e_initial, diss_C, diss_c1):
    """(final energy, residual) [J] of the balance initial = final + dissipated by C + by c₁
    + residual; the final energy includes the contact potential when the run ends in contact."""
    e_final = st._energy(law, p, u, side)
    return e_final, e_initial - e_final - diss_C - diss_c1


@compiled
def _slope(t, y, n):
    """Least-squares slope of y against t over the first n points (centred sums)."""
    tm = 0.0
    ym = 0.0
    for k in range(n):
        tm += t[k]
        ym += y[k]
    tm /= n
    ym /= n
    sxy = 0.0
    sxx = 0.0
    for k in range(n):
        dt = t[k] - tm
        sxy += dt * (y[k] - ym)
        sxx += dt * dt
    return sxy / sxx


@compiled
def damping_inclination_of(peaks, npk, omega_n, count):
    """DI [m] of Eq. 36: abs(slope) of the least-squares line through the first ``count``
    positive maxima (t_k, X_k) of x against t' = t·ω_n; NaN with fewer than ``count``."""
    if npk < count:
        return math.nan
    t = np.empty(count)
    y = np.empty(count)
    for k in range(count):
        t[k] = peaks[k, 0] * omega_n
        y[k] = peaks[k, 1]
    return abs(_slope(t, y, count))


@compiled
def zeta_eq_of(peaks, npk, omega_n):
    """ζ_eq [1]: −s/ω_n with s the least-squares slope of ln X_k against t_k over the upper
    envelope (the positive maxima that exceed every later one); NaN with fewer than two."""
    t = np.empty(npk)
    y = np.empty(npk)
    n = 0
    later = -math.inf  # the largest positive maximum after the current one
    for k in range(npk - 1, -1, -1):
        x = peaks[k, 1]
        if x > 0.0 and x > later:
            t[n] = peaks[k, 0]  # (latest first: the slope does not depend on the order)
            y[n] = math.log(x)
            n += 1
            later = x
    if n < 2:
        return math.nan
    return -_slope(t, y, n) / omega_n


@compiled
def run_many(law, P, S, T, rtol, rest, max_impacts, out, watch):
    """Run the points of a chunk one after the other and write one summary row each to ``out``.

    P (n, N_PARAMS): each point's parameter vector (system part, as :func:`_stepper.pack`);
    S (n, 4): its initial state (x, ẋ, y, ẏ); T (n,): its end time.  Row i of ``out`` (N_ROW
    columns): status, N_tot, N_eff (Eq. 37), DI (Eq. 36, NaN if undefined), ζ_eq (NaN if
    undefined), initial energy, dissipated by C, dissipated by c₁, residual.  The log buffers
    are allocated once and reused (grown where a run needs more).
    """
    impacts = np.zeros((64, st.N_IMPACT_COLS))
    peaks = np.zeros((256, 2))
    trace = np.zeros((1, st.N_TRACE_COLS))
    state = np.empty(4)
    p = np.empty(st.N_PARAMS)
    for i in range(P.shape[0]):
        if watch[2] != 0:  # a signal stopped the run before: the chunk is not finished
            break
        for j in range(st.N_PARAMS):
            p[j] = P[i, j]
        for j in range(4):
            state[j] = S[i, j]
        e_initial = prepare(p, state[0], state[1], state[2], state[3], rtol, rest)
        status, n_imp, npk, _, u, diss_C, diss_c1, side, _, impacts, peaks, trace = st.run(
            law, p, state, T[i], impacts, peaks, trace, False, max_impacts, watch
        )
        n_eff = 0
        for k in range(n_imp):
            if impacts[k, st.I_XD] * impacts[k, st.I_YD] < 0:
                n_eff += 1
        omega_n = math.sqrt(p[st.P_K] / p[st.P_M])
        out[i, R_STATUS] = status
        out[i, R_N_IMPACTS] = n_imp
        out[i, R_N_EFFECTIVE] = n_eff
        out[i, R_DI] = damping_inclination_of(peaks, npk, omega_n, 4)
        out[i, R_ZETA] = zeta_eq_of(peaks, npk, omega_n)
        out[i, R_E_INITIAL] = e_initial
        out[i, R_DISS_C] = diss_C
        out[i, R_DISS_C1] = diss_c1
        out[i, R_RESIDUAL] = ledger(law, p, u, side, e_initial, diss_C, diss_c1)[1]
    return out
