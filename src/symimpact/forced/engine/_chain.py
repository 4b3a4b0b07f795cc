"""The rigid stroboscopic map's Jacobian along a simulated motion, compiled: the chain of
Step 8's flight transition matrices Φ(τ) and Step 9's saltation matrices (Eq. F2), through
chatter accumulations, sticking phases and releases, with a parameter's derivative ∂P/∂p carried
as a fifth column (:func:`symimpact.forced.orbits.shooting.rigid_monodromy` states the chain; this
module is its numba body, one code path with or without a parameter).

Every entry comes from a generated kernel compiled with numba (the flights' Φ and their
forcing derivatives, the saltation gains and entries, the impact law's derivative in e); the
Jacobian is a 4×5 array whose fifth column stays zero without a parameter.  An impact at zero
relative speed has no saltation matrix: the Jacobian is then NaN (the caller refuses it).  The
chain's own functions divide with NumPy's rules (error_model "numpy": ±inf or NaN, never an
exception); the generated kernels they call are guarded instead, since numba's cache of a
generated kernel is shared by every module that compiles it.
"""

from __future__ import annotations

import math

import numpy as np

from ..._compiled import compiled
from ...generated import rigid_impact as _ri
from ._rigid import (
    E_KIND,
    E_SIDE,
    E_T,
    E_VREL,
    E_X,
    E_XD,
    E_XD1,
    E_YD,
    E_YD1,
    KIND_ACCUMULATION,
    KIND_RELEASE,
    P_C,
    P_F0,
    P_K,
    P_M,
    P_PHI,
    P_VY,
    P_W,
    P_XB,
    P_e,
    P_m,
    _accel,
    flight_matrices,
    flight_parameter_terms,
    restitution,
    restitution_slope,
)

#: The parameters a fifth column can carry, by code (-1: none).
PARAMETERS = ("F0", "X_b", "omega", "gap", "e")
_F0, _XB, _OMEGA, _GAP, _E = range(5)

_gain_main = compiled(_ri.saltation_main_gain_scalar)
_gain_impact = compiled(_ri.saltation_impact_gain_scalar)
_s_main_z = compiled(_ri.saltation_main_velocity_z_scalar)
_s_impact_z = compiled(_ri.saltation_impact_velocity_z_scalar)
_v_after_d_e = compiled(_ri.main_velocity_after_d_e_scalar)
_u_after_d_e = compiled(_ri.impact_velocity_after_d_e_scalar)


@compiled(error_model="numpy")
def _times(A, B, rows):
    """A @ B for a square ``rows``×``rows`` A and B of ``rows`` rows (the chain's 4×4 and 2×2
    products, written out: BLAS costs more than the product at this size)."""
    out = np.zeros((rows, B.shape[1]))
    for i in range(rows):
        for k in range(rows):
            a = A[i, k]
            if a != 0.0:
                for j in range(B.shape[1]):
                    out[i, j] += a * B[k, j]
    return out


@compiled(error_model="numpy")
def _accel_t(p, mass, t):
    """∂ẍ/∂t at fixed x, ẋ: the forcing terms of :func:`._rigid._accel` differentiated."""
    th = p[P_W] * t + p[P_PHI]
    P = p[P_F0] + p[P_K] * p[P_XB]
    Q = -p[P_C] * p[P_W] * p[P_XB]
    return p[P_W] * (Q * math.cos(th) - P * math.sin(th)) / mass


@compiled(error_model="numpy")
def _accel_d(p, which, t, mass):
    """∂ẍ/∂p at fixed t, x, ẋ: ẍ = (F0 cos θ − K(x − X_b cos θ) − C(ẋ + X_b Ω sin θ))/mass,
    θ = Ωt + φ (Eq. F1)."""
    W, K, C = p[P_W], p[P_K], p[P_C]
    th = W * t + p[P_PHI]
    if which == _F0:
        return math.cos(th) / mass
    if which == _XB:
        return (K * math.cos(th) - C * W * math.sin(th)) / mass
    if which == _OMEGA:
        s, c = math.sin(th), math.cos(th)
        return (-(p[P_F0] + K * p[P_XB]) * s * t - C * p[P_XB] * (s + W * t * c)) / mass
    return 0.0


@compiled(error_model="numpy")
def _stuck_at(J2, side, which):
    """(x, ẋ) rows into a sticking phase: δz = 0 (z = s·d/2, which moves with d), δẏ = δẋ."""
    out = np.zeros((4, 5))
    for j in range(5):
        out[0, j] = J2[0, j]
        out[1, j] = J2[1, j]
        out[3, j] = J2[1, j]
    if which == _GAP:
        out[2, 4] = 0.5 * side
    return out


@compiled(error_model="numpy")
def _impact_time_d(row, which):
    """∂t/∂p of an impact at a fixed incoming state: the wall s·z = d/2 moves with d, so
    δt = δd/(2·s·ż) (Eq. F2's impact condition)."""
    if which != _GAP:
        return 0.0
    return 0.5 / (row[E_SIDE] * (row[E_YD] - row[E_XD]))


@compiled(error_model="numpy")
def _law_d(p, row, which):
    """∂(x, ẋ⁺, z, ẏ⁺)/∂p of the impact law at fixed velocities before it: in e, the generated
    ``main_velocity_after_d_e`` and ``impact_velocity_after_d_e`` (Eq. F2)."""
    out = np.zeros(4)
    if which == _E:
        m, M, e = p[P_m], p[P_M], p[P_e]
        out[1] = _v_after_d_e(m, M, e, row[E_XD], row[E_YD])
        out[3] = _u_after_d_e(m, M, e, row[E_XD], row[E_YD])
    return out


@compiled(error_model="numpy")
def _impact(p, row, J, which):
    """J through an impact: Step 9's saltation matrix, and the parameter column's explicit
    term (G·f⁻ − f⁺)·∂t/∂p plus the law's own derivative (G the impact law's Jacobian, f∓ the
    vector fields before and after)."""
    m, M, C = p[P_m], p[P_M], p[P_C]
    t, x, v, u = row[E_T], row[E_X], row[E_XD], row[E_YD]
    if u == v:  # an impact at zero relative speed has no saltation matrix
        return np.full(J.shape, np.nan)
    e = restitution(p[P_e], p[P_VY], row[E_VREL])
    kM, km = _gain_main(m, M, e), _gain_impact(m, M, e)
    a_pre = _accel(p, M, t, x, v)
    S = np.zeros((4, 4))
    S[0, 0], S[0, 2] = 1.0, kM
    S[2, 2] = -e
    if p[P_VY] <= 0.0:  # one e for every impact: Step 9's entries as derived
        S[1, 1], S[1, 2], S[1, 3] = 1.0 - kM, _s_main_z(m, M, e, C, u - v, a_pre), kM
        S[3, 1], S[3, 2], S[3, 3] = km, _s_impact_z(m, M, e, u - v, a_pre), 1.0 - km
    else:
        # e follows the approach speed w: the velocity jumps' slopes in the velocities hold
        # ê = d(e·w)/dw (Step 13) in place of e, the jump itself (k_M, k_m, f⁺) still e.  The
        # column z is (f⁺ − G·f⁻)/ż with G the velocities' Jacobian: Step 9's entries at ê,
        # less C·k_M/M for the primary's damping force after the jump
        eh = restitution_slope(p[P_e], p[P_VY], row[E_VREL])
        kMh, kmh = _gain_main(m, M, eh), _gain_impact(m, M, eh)
        S[1, 1], S[1, 3] = 1.0 - kMh, kMh
        S[1, 2] = _s_main_z(m, M, eh, 0.0, u - v, a_pre) - C * kM / M
        S[3, 1], S[3, 2], S[3, 3] = kmh, _s_impact_z(m, M, eh, u - v, a_pre), 1.0 - kmh
        kM, km = kMh, kmh  # the parameter column's (G·f⁻) terms below
    out = _times(S, J, 4)
    if which >= 0:
        col = _law_d(p, row, which)
        dt = _impact_time_d(row, which)
        if dt != 0.0:
            v1, u1 = row[E_XD1], row[E_YD1]
            a_post = _accel(p, M, t, x, v1)
            col[0] += (v - v1) * dt
            col[1] += ((1.0 - kM) * a_pre - a_post) * dt
            col[2] += ((u - v) - (u1 - v1)) * dt
            col[3] += km * a_pre * dt
        for r in range(4):
            out[r, 4] += col[r]
    return out


@compiled(error_model="numpy")
def _accumulation(p, impact, point, phi, J, flight, which):
    """J through an impact and the accumulation of its chatter (``J`` to just before the
    impact, ``phi`` the primary's Φ from the impact to the accumulation point, ``flight`` that
    flight's explicit parameter term): returned, the Jacobian of (x, ẋ) at the accumulation
    point t∞ (:func:`symimpact.forced.orbits.shooting.rigid_monodromy`: Δ = 2w/(a(1 − e)), the primary
    alone over Δ, the merge v_c = (M ẋ + m ẏ)/(M + m), t₀'s own dependence δt₀ = −δz/ż)."""
    M, m, K, C, e = p[P_M], p[P_m], p[P_K], p[P_C], p[P_e]
    t0, x0, v, u = impact[E_T], impact[E_X], impact[E_XD], impact[E_YD]
    s = impact[E_SIDE]
    v0, u0 = impact[E_XD1], impact[E_YD1]
    a_pre = _accel(p, M, t0, x0, v)
    dt0 = np.empty(5)
    for j in range(5):
        dt0[j] = -J[2, j] / (u - v)
    dt0[4] += _impact_time_d(impact, which)
    f_pre = (v, a_pre, u - v, 0.0)
    at = np.empty((4, 5))
    for r in range(4):
        for j in range(5):
            at[r, j] = J[r, j] + f_pre[r] * dt0[j]
    kM, km = _gain_main(m, M, e), _gain_impact(m, M, e)
    d_after = np.empty((4, 5))  # rows: δx₀, δẋ₀ (after), δz, δẏ₀ (after)
    for j in range(5):
        d_after[0, j] = at[0, j]
        d_after[1, j] = (1.0 - kM) * at[1, j] + kM * at[3, j]
        d_after[2, j] = at[2, j]
        d_after[3, j] = km * at[1, j] + (1.0 - km) * at[3, j]
    law = _law_d(p, impact, which)
    for r in range(4):
        d_after[r, 4] += law[r]
    w = -s * (u0 - v0)
    a = -s * _accel(p, M, t0, x0, v0)
    delta = 2.0 * w / (a * (1.0 - e))
    a_t = _accel_t(p, M, t0)
    d_delta = np.empty(5)
    for j in range(5):
        dw = -s * (d_after[3, j] - d_after[1, j])
        da = -s * (a_t * dt0[j] - K / M * d_after[0, j] - C / M * d_after[1, j])
        if j == 4:
            da += -s * _accel_d(p, which, t0, M)
        d_delta[j] = 2.0 / (a * (1.0 - e)) * dw - delta / a * da
    if which == _E:
        d_delta[4] += delta / (1.0 - e)  # Δ's own 1/(1 − e)
    xj, vj = point[E_X], point[E_XD]
    t_inf = t0 + delta
    f_end = (vj, _accel(p, M, t_inf, xj, vj))
    f_start0, f_start1 = v0, _accel(p, M, t0, x0, v0)
    d_j = np.empty((2, 5))
    for r in range(2):
        drift = f_end[r] - (phi[r, 0] * f_start0 + phi[r, 1] * f_start1)
        for j in range(5):
            d_j[r, j] = (phi[r, 0] * d_after[0, j] + phi[r, 1] * d_after[1, j]
                         + f_end[r] * d_delta[j] + drift * dt0[j])  # fmt: skip
    d_j[0, 4] += flight[0]
    d_j[1, 4] += flight[1]
    vc = point[E_XD1]
    f_stick = (vc, _accel(p, M + m, t_inf, xj, vc))
    out = np.empty((2, 5))
    for j in range(5):
        d_tinf = dt0[j] + d_delta[j]
        out[0, j] = d_j[0, j] - f_stick[0] * d_tinf
        out[1, j] = (M * d_j[1, j] + m * d_after[3, j]) / (M + m) - f_stick[1] * d_tinf
    return out


@compiled(error_model="numpy")
def rigid_jacobian(p, events, t_end, final_stuck, which, start, end_state):
    """The Jacobian (4×5: the state's columns, then ∂P/∂p for the parameter of code ``which``
    in :data:`PARAMETERS`, zero for -1) of the rigid map along the simulated motion ``events``
    (columns E_*, to ``t_end`` [s], ``final_stuck``: it ended inside a sticking phase), the
    parameter vector ``p`` (P_*) of the run; ``start`` = (x, ẋ) at t = 0 and ``end_state`` =
    (x, ẋ, ż) at t_end (for the parameter's terms)."""
    M, m = p[P_M], p[P_m]
    n = events.shape[0]
    times = np.empty(n + 2)
    times[0] = 0.0
    for i in range(n):
        times[i + 1] = events[i, E_T]
    times[n + 1] = t_end
    ends_stuck = final_stuck or (n > 0 and events[n - 1, E_KIND] == KIND_ACCUMULATION)
    masses = np.empty(n + 1)
    for i in range(n):
        masses[i] = M + m if events[i, E_KIND] == KIND_RELEASE else M
    masses[n] = M + m if ends_stuck else M
    phis = flight_matrices(np.diff(times), masses, p[P_K], p[P_C])
    # each flight's explicit term from its fixed start (after the previous event: E_XD1 is the
    # speed after an impact, the common speed after an accumulation, the speed at a release)
    flights = np.zeros((n + 1, 4))
    if which == _F0 or which == _XB or which == _OMEGA:
        xa, va = np.empty(n + 1), np.empty(n + 1)
        xa[0], va[0] = start[0], start[1]
        for i in range(n):
            xa[i + 1], va[i + 1] = events[i, E_X], events[i, E_XD1]
        d = flight_parameter_terms(times, masses, xa, va, p[P_K], p[P_C], p[P_F0], p[P_XB],
                                   p[P_W], p[P_PHI], which)  # fmt: skip
        for i in range(n + 1):
            flights[i, 0], flights[i, 1], flights[i, 2] = d[i, 0], d[i, 1], -d[i, 0]
    J = np.zeros((4, 5))
    for r in range(4):
        J[r, r] = 1.0
    i = 0
    while i < n:
        row = events[i]
        if events[i, E_KIND] == KIND_RELEASE:
            J2 = _times(phis[i, :2, :2], J[:2], 2)
            J2[0, 4] += flights[i, 0]
            J2[1, 4] += flights[i, 1]
            J = _stuck_at(J2, row[E_SIDE], which)
            i += 1
            continue
        J = _times(phis[i], J, 4)  # to just before the impact
        for r in range(4):
            J[r, 4] += flights[i, r]
        if i + 1 < n and events[i + 1, E_KIND] == KIND_ACCUMULATION:
            J2 = _accumulation(p, row, events[i + 1], phis[i + 1], J, flights[i + 1], which)
            J = _stuck_at(J2, row[E_SIDE], which)
            i += 2
            continue
        J = _impact(p, row, J, which)
        i += 1
    if ends_stuck:
        J2 = _times(phis[n, :2, :2], J[:2], 2)
        J2[0, 4] += flights[n, 0]
        J2[1, 4] += flights[n, 1]
        J = _stuck_at(J2, events[n - 1, E_SIDE] if n else 0.0, which)
    else:
        J = _times(phis[n], J, 4)
        for r in range(4):
            J[r, 4] += flights[n, r]
    if which == _OMEGA:  # the end of the k periods moves, T = 2πk/Ω: ∂T/∂Ω = −T/Ω
        x, v, zdot = end_state[0], end_state[1], end_state[2]
        k = -t_end / p[P_W]
        if ends_stuck:
            a = _accel(p, M + m, t_end, x, v)
            J[0, 4] += v * k
            J[1, 4] += a * k
            J[3, 4] += a * k
        else:
            J[0, 4] += v * k
            J[1, 4] += _accel(p, M, t_end, x, v) * k
            J[2, 4] += zdot * k
    return J
