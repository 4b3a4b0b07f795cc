"""Compiled event-driven simulation of a structure of N modes carrying K impact dampers with
rigid impacts (numba, cached).

Between impacts everything is closed form, as in :mod:`symimpact.forced._rigid`, whose flight
functions this module composes mode by mode: mode i follows Step 8's forced flight (Eq. F1) with
its own Mᵢ, Kᵢ = ωᵢ²Mᵢ, Cᵢ = 2ζᵢωᵢMᵢ and modal force Fᵢ = Σⱼ F₀ⱼφᵢ(j) (Step 15, item 1); each
impact mass k flies at constant speed; an impact of damper k at its point aₖ applies Step 15's law
(item 4, Eq. F7): the impulse P = (1 + e)·μ·(ẏ − ẋₐ), μ the reduced mass of m and the effective
mass (Σφᵢ(a)²/Mᵢ)⁻¹, enters each mode as q̇ᵢ += φᵢ(a)P/Mᵢ and leaves the mass as ẏ −= P/m.  One mode
with φ = 1 is Step 9's impact (Eq. F2), the test of the N = 1 case.

*The next impact.*  Damper k's relative displacement zₖ = yₖ − Σφᵢ(aₖ)qᵢ has
|zₖ''| ≤ Aₖ = Σ|φᵢ(aₖ)|·Aᵢ, Aᵢ the bound of mode i's acceleration over the flight
(:func:`symimpact.forced._rigid._accel_bound`).  All dampers are marched together on one grid:
an interval every damper's bound clears is skipped, any other halved, and each damper whose z
crosses a wall there is bracketed and refined by Illinois regula falsi; the earliest crossing is
the impact.  Right after an impact the wall just left is kept off as in the one-mode search
(2w/Aₖ, and while the point's acceleration is certified to point away, with
B = Σ|φᵢ|·2Aᵢ·max(Ω, ωᵢ)² bounding its second derivative).

*Chatter.*  An impact after which the mass would return to the same wall so slowly that the
sequence accumulates within a fraction of a forcing period (Step 9's test with the point's
acceleration) ends the run with status CHATTER: the sticking of a mass on a structure of several
modes (Step 15, item 5) is derived but not yet in this engine.

*Energy ledger.*  The work of the modal forces and the dissipation of every Cᵢ, by the one-mode
engine's Gauss–Legendre rule summed over the modes, and the impacts' losses ½μ(1 − e²)ż².

Private: :mod:`symimpact.forced.structure_response` checks the input and builds the result.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from .._interrupt import EVERY, INTERRUPTED, stop_requested
from ..free._stepper import secant_point
from ._rigid import (
    _GL_W,
    _GL_X,
    E_KIND,
    E_LOST,
    E_SIDE,
    E_T,
    E_VREL,
    KIND_IMPACT,
    N_EVENT_COLS,
    OK,
    P_C,
    P_F0,
    P_K,
    P_M,
    P_PHI,
    P_W,
    TOO_MANY_EVENTS,
    _accel,
    _accel_bound,
    _grow,
    _jerk,
    _state,
    restitution,
)

#: Run status beside :data:`~symimpact.forced._rigid.OK`, ``TOO_MANY_EVENTS`` and INTERRUPTED.
CHATTER = 3
#: Extra event-log column: the damper of the impact (its index).
E_DAMPER = N_EVENT_COLS
N_MODAL_EVENT_COLS = N_EVENT_COLS + 1


@njit(cache=True)
def _states(pm, t0, q0, v0, tau, q, v):
    """Every mode's (qᵢ, q̇ᵢ) a time τ after (q0, v0) at t0, written into q and v (Eq. F1)."""
    for i in range(pm.shape[0]):
        q[i], v[i] = _state(pm[i], pm[i, P_M], t0, q0[i], v0[i], tau)


@njit(cache=True)
def _point_accel(pm, phi, t, q, v):
    """ẍₐ = Σφᵢq̈ᵢ at a point whose shapes are ``phi``."""
    a = 0.0
    for i in range(pm.shape[0]):
        a += phi[i] * _accel(pm[i], pm[i, P_M], t, q[i], v[i])
    return a


@njit(cache=True)
def _point_jerk(pm, phi, t, q, v):
    """d³xₐ/dt³ = Σφᵢ d³qᵢ/dt³."""
    a = 0.0
    for i in range(pm.shape[0]):
        a += phi[i] * _jerk(pm[i], pm[i, P_M], t, q[i], v[i])
    return a


@njit(cache=True)
def _omega_max(pm):
    """The largest of Ω and the modes' damped frequencies [rad/s]: it sets the search's steps."""
    w = pm[0, P_W]
    for i in range(pm.shape[0]):
        M, K, C = pm[i, P_M], pm[i, P_K], pm[i, P_C]
        w = max(w, math.sqrt(K / M - C * C / (4 * M * M)))
    return w


@njit(cache=True)
def _held_off(pm, phi, t0, q0, v0, side, T, A_modes):
    """A τ up to which the wall ``side`` the damper at ``phi`` just left cannot be reached:
    :func:`symimpact.forced._rigid._held_off` with the point's acceleration g = side·ẍₐ and
    B = Σ|φᵢ|·2Aᵢ·max(Ω, ωᵢ)² ≥ |g''|."""
    N = pm.shape[0]
    W = pm[0, P_W]
    A, B = 0.0, 0.0
    wmax = W
    for i in range(N):
        wn = math.sqrt(pm[i, P_K] / pm[i, P_M])
        A += abs(phi[i]) * A_modes[i]
        B += abs(phi[i]) * 2.0 * A_modes[i] * max(W, wn) ** 2
        wmax = max(wmax, wn)
    period = 2.0 * math.pi / _omega_max(pm)
    span = min(T, period)
    q = np.empty(N)
    v = np.empty(N)
    ga = side * _point_accel(pm, phi, t0, q0, v0)
    if ga < -1e-12 * A:
        return 0.0
    ga = max(ga, 0.0)
    g1 = side * _point_jerk(pm, phi, t0, q0, v0)
    tau = min((g1 + math.sqrt(g1 * g1 + 2.0 * B * ga)) / B, span)
    if tau > 0.0:
        _states(pm, t0, q0, v0, tau, q, v)
        ga = side * _point_accel(pm, phi, t0 + tau, q, v)
    H = period / 64.0
    while tau < span:
        H = min(H, span - tau)
        tb = tau + H
        _states(pm, t0, q0, v0, tb, q, v)
        gb = side * _point_accel(pm, phi, t0 + tb, q, v)
        if gb >= 0.0 and min(ga, gb) - B * H * H / 8.0 >= 0.0:
            tau, ga = tb, gb
            H = min(2.0 * H, period / 64.0)
        elif H > period / 4096.0:
            H *= 0.5
        else:
            return tau
    return tau


@njit(cache=True)
def _z(pm, phi, t0, q0, v0, z0, u0, tau, q, v):
    """z = y − xₐ a time τ into the flight: z0 + u0·τ − Σφᵢ(qᵢ(τ) − qᵢ0)."""
    _states(pm, t0, q0, v0, tau, q, v)
    dx = 0.0
    for i in range(pm.shape[0]):
        dx += phi[i] * (q[i] - q0[i])
    return z0 + u0 * tau - dx


@njit(cache=True)
def _refine(pm, phi, h, t0, q0, v0, z0, u0, s, lo, hi, za, zb, q, v):
    """The first τ in (lo, hi] where s·z reaches h (z(lo) = za inside, z(hi) = zb beyond), by
    Illinois regula falsi to 4e-16 of the time."""
    flo = min(s * za - h, 0.0)
    fhi = s * zb - h
    kept = 0
    for _ in range(200):
        den = fhi - flo
        tm = (lo * fhi - hi * flo) / den if den != 0.0 else 0.5 * (lo + hi)
        if not (lo < tm < hi):
            tm = 0.5 * (lo + hi)
        fm = s * _z(pm, phi, t0, q0, v0, z0, u0, tm, q, v) - h
        if fm >= 0.0:
            hi, fhi = tm, fm
            if kept == 1:
                flo *= 0.5
            kept = 1
        else:
            lo, flo = tm, fm
            if kept == -1:
                fhi *= 0.5
            kept = -1
        if hi - lo <= 4e-16 * (t0 + hi):
            break
    return hi


@njit(cache=True)
def _next_impact(pm, Phi, hd, t0, q0, v0, z0, u0, side0, T, watch):
    """(τ, damper, side): the first τ in (0, T] at which a damper's abs(z) reaches its half
    clearance, that damper and its wall (±1); (T, −1, 0) when there is none, or (τ so far, −1, 0)
    when a signal is seen on ``watch``.  ``side0[k]``: the wall damper k starts on (0: none)."""
    N, K = pm.shape[0], Phi.shape[0]
    hmax = 2.0 * math.pi / _omega_max(pm) / 16.0
    A_modes = np.empty(N)
    for i in range(N):
        A_modes[i] = _accel_bound(pm[i], pm[i, P_M], t0, q0[i], v0[i], T)
    A = np.zeros(K)
    for k in range(K):
        for i in range(N):
            A[k] += abs(Phi[k, i]) * A_modes[i]
    hmin = 1e-6 * hmax
    tau_safe = np.zeros(K)
    for k in range(K):
        hmin = min(hmin, max(1e-12 * hmax, math.sqrt(8e-20 * hd[k] / A[k])))
        if side0[k] != 0:
            xd = 0.0
            for i in range(N):
                xd += Phi[k, i] * v0[i]
            fd0 = side0[k] * (u0[k] - xd)
            if fd0 <= 0.0:
                tau_safe[k] = max(-2.0 * fd0 / A[k],
                                  _held_off(pm, Phi[k], t0, q0, v0, side0[k], T, A_modes))  # fmt: skip
    q = np.empty(N)
    v = np.empty(N)
    za = z0.copy()
    zb = np.empty(K)
    tau = 0.0
    H = hmax
    looks = 0
    while tau < T:
        looks += 1
        if (looks & (EVERY - 1)) == 0 and stop_requested(watch):
            return tau, -1, 0
        H = min(H, T - tau)
        tb = tau + H
        _states(pm, t0, q0, v0, tb, q, v)
        clear = True
        for k in range(K):
            dx = 0.0
            for i in range(N):
                dx += Phi[k, i] * (q[i] - q0[i])
            zb[k] = z0[k] + u0[k] * tb - dx
            slack = A[k] * H * H / 8.0
            up = max(za[k], zb[k]) + slack < hd[k] or (side0[k] == 1 and tb <= tau_safe[k])
            down = min(za[k], zb[k]) - slack > -hd[k] or (side0[k] == -1 and tb <= tau_safe[k])
            if not (up and down):
                clear = False
        if clear:
            tau = tb
            za[:] = zb
            H = min(2.0 * H, hmax)
            continue
        if H > hmin and H > 4e-16 * tb:
            H *= 0.5
            continue
        first, which, wall = tb, -1, 0
        for k in range(K):
            if abs(zb[k]) >= hd[k]:
                s = 1.0 if zb[k] > 0 else -1.0
                tk = _refine(pm, Phi[k], hd[k], t0, q0, v0, z0[k], u0[k], s, tau, tb, za[k],
                             zb[k], q, v)  # fmt: skip
                if which < 0 or tk < first:
                    first, which, wall = tk, k, int(s)
        if which >= 0:
            return first, which, wall
        tau = tb  # excursions shorter than hmin: below 1e-20 of the clearances
        za[:] = zb
        H = hmax
    return T, -1, 0


@njit(cache=True)
def _segment(pm, Pout, t0, q0, v0, tau, ledger, period_max, n_periods):
    """Account for the flight [t0, t0 + τ]: the work of the modal forces and the dissipation of
    the Cᵢ (ledger[0], ledger[1], Gauss–Legendre as in the one-mode engine) and, for every output
    point p (rows of ``Pout``, its shapes), the largest abs(xₚ) of every forcing period crossed
    (``period_max[k, p]``), at the sub-intervals' ends and at the zeros of ẋₚ inside them."""
    N, P = pm.shape[0], Pout.shape[0]
    W = pm[0, P_W]
    T_f = 2.0 * math.pi / W
    hq = 2.0 * math.pi / _omega_max(pm) / 16.0
    n = max(1, int(math.ceil(tau / hq)))  # noqa: RUF046 (int() spelled out for numba)
    hs = tau / n
    q = np.empty(N)
    v = np.empty(N)
    v_prev = np.empty(P)
    for p in range(P):
        v_prev[p] = 0.0
        for i in range(N):
            v_prev[p] += Pout[p, i] * v0[i]
    for j in range(n):
        a = j * hs
        for g in range(8):
            s = a + 0.5 * hs * (1.0 + _GL_X[g])
            _states(pm, t0, q0, v0, s, q, v)
            c = math.cos(W * (t0 + s) + pm[0, P_PHI])
            for i in range(N):
                ledger[0] += 0.5 * hs * _GL_W[g] * pm[i, P_F0] * c * v[i]
                ledger[1] += 0.5 * hs * _GL_W[g] * pm[i, P_C] * v[i] * v[i]
        b = (j + 1) * hs
        _states(pm, t0, q0, v0, b, q, v)
        k = int(math.floor((t0 + b) / T_f))  # noqa: RUF046 (int() spelled out for numba)
        for p in range(P):
            xb, vb = 0.0, 0.0
            for i in range(N):
                xb += Pout[p, i] * q[i]
                vb += Pout[p, i] * v[i]
            if k < n_periods:
                period_max[k, p] = max(period_max[k, p], abs(xb))
            if (v_prev[p] > 0.0) != (vb > 0.0) and v_prev[p] != 0.0:
                lo, hi, flo, fhi = a, b, v_prev[p], vb
                kept = 0
                for _ in range(100):
                    tm = secant_point(lo, hi, flo, fhi)
                    _states(pm, t0, q0, v0, tm, q, v)
                    vm = 0.0
                    for i in range(N):
                        vm += Pout[p, i] * v[i]
                    if vm == 0.0:
                        lo = hi = tm  # the zero itself: x is read there
                        break
                    if (vm > 0.0) == (flo > 0.0):
                        lo, flo = tm, vm
                        if kept == -1:
                            fhi *= 0.5
                        kept = -1
                    else:
                        hi, fhi = tm, vm
                        if kept == 1:
                            flo *= 0.5
                        kept = 1
                    if hi - lo <= 4e-16 * (t0 + hi):
                        break
                _states(pm, t0, q0, v0, 0.5 * (lo + hi), q, v)
                xm = 0.0
                for i in range(N):
                    xm += Pout[p, i] * q[i]
                km = int(math.floor((t0 + 0.5 * (lo + hi)) / T_f))  # noqa: RUF046
                if km < n_periods:
                    period_max[km, p] = max(period_max[km, p], abs(xm))
            v_prev[p] = vb


@njit(cache=True)
def run(pm, Phi, md, hd, ed, chat, q0, v0, y0, u0, Pout, t_end, max_events, watch):
    """Simulate the structure (modes: rows of ``pm``, the one-mode parameter layout of
    :mod:`symimpact.forced._rigid`; dampers: shapes ``Phi[k]`` at their points, masses ``md``,
    half clearances ``hd``, restitution ``ed``) from modal state (q0, v0) and the masses' (y0, u0)
    at t = 0 to t_end.

    Returns (status, events, n_events, period_max, ledger, final): the event log (columns of
    :mod:`symimpact.forced._rigid` and E_DAMPER; E_X, E_XD, E_YD, E_XD1, E_YD1 hold the point's
    displacement, velocities before and after), ``period_max[k, p]`` the largest abs(x) at output
    point p in forcing period k, ledger = (work of the forces, dissipation, loss in impacts),
    final = (t, q…, q̇…, y…, ẏ…).
    """
    N, K = pm.shape[0], Phi.shape[0]
    T_f = 2.0 * math.pi / pm[0, P_W]
    n_periods = int(math.floor(t_end / T_f + 0.5))  # noqa: RUF046 (int() spelled out for numba)
    period_max = np.zeros((n_periods + 1, Pout.shape[0]))
    ledger = np.zeros(3)
    events = np.zeros((64, N_MODAL_EVENT_COLS))
    n_ev = 0
    t = 0.0
    q, v = q0.copy(), v0.copy()
    qn, vn = np.empty(N), np.empty(N)
    u = u0.copy()
    z = np.empty(K)
    side0 = np.zeros(K, dtype=np.int64)
    for k in range(K):
        x = 0.0
        for i in range(N):
            x += Phi[k, i] * q[i]
        z[k] = y0[k] - x
        if abs(z[k]) >= hd[k]:
            side0[k] = 1 if z[k] > 0 else -1
            z[k] = side0[k] * hd[k]
    status = OK
    looks = 0
    while t < t_end:
        if n_ev + 2 > max_events:
            status = TOO_MANY_EVENTS
            break
        looks += 1
        if (looks & (EVERY - 1)) == 0 and stop_requested(watch):
            status = INTERRUPTED
            break
        tau, k, side = _next_impact(pm, Phi, hd, t, q, v, z, u, side0, t_end - t, watch)
        _segment(pm, Pout, t, q, v, tau, ledger, period_max, n_periods)
        _states(pm, t, q, v, tau, qn, vn)
        for j in range(K):
            dx = 0.0
            for i in range(N):
                dx += Phi[j, i] * (qn[i] - q[i])
            z[j] = z[j] + u[j] * tau - dx
        t = t + tau
        q[:] = qn
        v[:] = vn
        if k < 0:
            if watch[2] != 0:
                status = INTERRUPTED
            break
        # --- Step 15's impact (F7) of damper k on its wall s ---
        s = float(side)
        z[k] = s * hd[k]
        xa, xda, inv_meff = 0.0, 0.0, 0.0
        for i in range(N):
            xa += Phi[k, i] * q[i]
            xda += Phi[k, i] * v[i]
            inv_meff += Phi[k, i] * Phi[k, i] / pm[i, P_M]
        vrel = s * (u[k] - xda)  # approach speed, ≥ 0
        e = restitution(ed[k], 0.0, vrel)
        mu = md[k] / (1.0 + md[k] * inv_meff)
        P = (1.0 + e) * mu * (u[k] - xda)
        for i in range(N):
            v[i] += Phi[k, i] * P / pm[i, P_M]
        u_before = u[k]
        u[k] -= P / md[k]
        lost = 0.5 * mu * (1.0 - e * e) * vrel * vrel
        ledger[2] += lost
        xda1 = 0.0
        for i in range(N):
            xda1 += Phi[k, i] * v[i]
        events = _grow(events, n_ev)
        ev = events[n_ev]
        ev[E_T], ev[1], ev[2], ev[3], ev[E_SIDE] = t, xa, xda, u_before, s
        ev[E_VREL], ev[E_LOST], ev[E_KIND], ev[8], ev[9] = vrel, lost, KIND_IMPACT, xda1, u[k]
        ev[E_DAMPER] = k
        n_ev += 1
        for j in range(K):
            side0[j] = 0
        side0[k] = side
        # --- chatter: would the sequence accumulate (Step 9's test at the point)? ---
        a = -s * _point_accel(pm, Phi[k], t, q, v)
        w = e * vrel
        if a > 0.0 and e < 1.0:
            delta = 2.0 * w / (a * (1.0 - e))
            if delta <= chat * T_f and t + delta < t_end:
                status = CHATTER
                break
    final = np.empty(1 + 2 * N + 2 * K)
    final[0] = t
    final[1 : 1 + N] = q
    final[1 + N : 1 + 2 * N] = v
    for k in range(K):
        x = 0.0
        for i in range(N):
            x += Phi[k, i] * q[i]
        final[1 + 2 * N + k] = x + z[k]
    final[1 + 2 * N + K :] = u
    return status, events, n_ev, period_max, ledger, final
