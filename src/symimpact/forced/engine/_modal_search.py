"""The modal engine's searches (:mod:`._modal`): the next impact, contact onset or release.

All free dampers are marched together on the bounds' certified grid; a crossing is bracketed and
refined by Illinois regula falsi on the point's Taylor polynomial (:func:`_point_taylor`,
:func:`_refine`, :func:`_none_before`, :func:`_next_impact`); a stuck mass is released where its
wall would pull (:func:`_release`); a compliant stop's contact begins (:func:`_next_contact`) or a
rigid stop's impulse is taken (:func:`_stop_impulse`).  The module docstring of :mod:`._modal`
tells the whole engine.
"""

from __future__ import annotations

import math

import numpy as np

from ..._compiled import compiled
from ..._interrupt import EVERY, stop_requested
from ...free._stepper import secant_point
from ._modal_flight import (
    _base_a,
    _base_v,
    _base_x,
    _bounds,
    _dot,
    _form_fresh,
    _free_states,
    _growth,
    _held_off,
    _point_accel,
    _rows_at,
    _states,
    _sum_at_start,
)
from ._rigid import (
    P_C,
    P_F0,
    P_K,
    P_M,
    P_PHI,
    P_W,
    P_XB,
)

#: 1/n! and 1/n (n < 30; 1/0 unused) for :func:`_expint_series`.
_INV_FACT = np.array([1.0 / math.factorial(n) for n in range(30)])
_INV_N = np.array([0.0] + [1.0 / n for n in range(1, 30)])


#: The highest degree of a point's Taylor polynomial (:func:`_point_taylor`).
TAYLOR_MAX = 24


@compiled
def _point_taylor(pm, cfg, Phi, row, t0, q0, v0, c, h, rows, xb, poly, extra):
    """The degree n and poly[0 … n] of the Taylor polynomial of the point's displacement since
    the flight's start, dx(c + ς) = x_b(t0 + c + ς) − x_b(t0) + φᵀ(q(c + ς) − q0) ≈ Σₖ polyₖςᵏ
    for abs(ς) ≤ h; −1 where it is not formed (a mode without Eq. F1's form, a flight read
    through neither form nor projection, a cache not holding this flight, or r = ρh ≥ 0.5).
    The flight is a sum of terms Re(aₗe^{μₗτ}) (Eq. F1 per mode, μ = −σ + iω_d, and its steady
    part with μ = iΩ; or the projection's columns, :func:`_held_rows`), so polyₖ =
    Σₗ Re(aₗμₗᵏe^{μₗc})/k! for k ≥ 1, and poly₀ = dx(c) as the flight's own evaluation sums it.
    With ρ ≥ every abs(μₗ), the terms left out are below Σₗ abs(aₗe^{μₗc})·rⁿ⁺¹/(n + 1)! times
    1/(1 − r/(n + 2)) ≤ 1.34: n is the least degree that puts them below 1e-17 of the terms'
    sizes, under the rounding of the sum itself; ``extra`` degrees more for a polynomial whose
    derivative is read (the speed's terms left out are r·(rⁿ/n!) of its sizes).  A refinement
    (:func:`_refine`, :func:`_segment`'s zeros of ẋₚ) then reads the point at each look by
    Horner's rule, not by every mode's exponential, cosine and sine."""
    N = pm.shape[0]
    W = pm[0, P_W]
    dec = cfg[6]
    rate = W
    if dec:
        form = cfg[10]
        if not _form_fresh(form, t0, q0, v0):
            return -1
        for i in range(N):
            if form[i, 12] == 0.0:
                return -1
            rate = max(rate, math.hypot(form[i, 8], form[i, 9]))
    elif rows.shape[0] > 0:
        hf, cplx, n2 = cfg[11], cfg[1], cfg[2]
        last = cplx.shape[0] - 1
        for m in range(n2):
            if hf[2 * N + 2, m].real != 0.0:
                rate = max(rate, abs(cplx[last, m]))
    else:
        return -1
    r = rate * h
    if not r < 0.5:
        return -1
    n = 0
    bound = r
    while bound >= 7.4e-18 and n < TAYLOR_MAX:
        n += 1
        bound *= r * _INV_N[n + 1]
    n = min(n + extra, TAYLOR_MAX)
    poly[: n + 1] = 0.0
    th = W * c
    ec = complex(math.cos(th), math.sin(th))  # e^{iΩc}
    iw = complex(0.0, W)
    d0 = _base_x(pm, xb, t0 + c) - _base_x(pm, xb, t0)
    if xb != 0.0:  # x_b(t0 + c + ς) = Re(X_b e^{iθ(t0 + c)} e^{iΩς})
        tb = W * (t0 + c) + pm[0, P_PHI]
        p = xb * complex(math.cos(tb), math.sin(tb))
        for k in range(1, n + 1):
            p *= iw
            poly[k] += p.real
    if dec:
        form = cfg[10]
        forcing = 0.0j
        for i in range(N):
            f = form[i]
            ex = math.exp(-f[8] * c)
            cd, sd = math.cos(f[9] * c), math.sin(f[9] * c)
            qi = f[0] * ec.real + f[1] * ec.imag + ex * (f[2] * cd + f[3] * sd)
            d0 += Phi[row, i] * (qi - q0[i])
            forcing += Phi[row, i] * complex(f[0], -f[1])
            p = Phi[row, i] * complex(f[2], -f[3]) * complex(ex * cd, ex * sd)
            mu = complex(-f[8], f[9])
            for k in range(1, n + 1):
                p *= mu
                poly[k] += p.real
        p = forcing * ec
    else:
        hf, cplx, n2 = cfg[11], cfg[1], cfg[2]
        last = cplx.shape[0] - 1
        R = rows[row, 0]
        p = R[n2] * ec
        acc = R[n2 + 1].real + p.real
        for m in range(n2):
            if hf[2 * N + 2, m].real == 0.0:
                continue
            lam = cplx[last, m]
            er, ei = _growth(lam, c)
            a = R[m] * complex(er, ei)
            acc += a.real
            for k in range(1, n + 1):
                a *= lam
                poly[k] += a.real
        d0 += acc - _sum_at_start(R, hf[2 * N + 2], n2, R[n2 + 1].real)
    for k in range(1, n + 1):  # the steady part's (forcing's) column, e^{iΩτ}
        p *= iw
        poly[k] += p.real
    for k in range(1, n + 1):
        poly[k] *= _INV_FACT[k]
    poly[0] = d0
    return n


@compiled
def _refine(pm, cfg, nstuck, Phi, row, h, t0, q0, v0, z0, u0, s, lo, hi, za, zb, q, v, rows, out,
            xb):  # fmt: skip
    """The first τ in (lo, hi] where s·z reaches h (z(lo) = za inside, z(hi) = zb beyond), by
    Illinois regula falsi to 4e-16 of the time (``rows``, ``out``: as :func:`_held_off`'s).  The
    point's displacement is read from its Taylor polynomial about the bracket's middle
    (:func:`_point_taylor`) where it is formed, else from the flight at each look."""
    dec = cfg[6]
    proj = not dec and rows.shape[0] > 0
    hf, cplx, n2, W = cfg[11], cfg[1], cfg[2], pm[0, P_W]
    flo = min(s * za - h, 0.0)
    fhi = s * zb - h
    kept = 0
    mid = 0.5 * (lo + hi)
    poly = np.empty(TAYLOR_MAX + 1)
    deg = _point_taylor(pm, cfg, Phi, row, t0, q0, v0, mid, 0.5 * (hi - lo), rows, xb, poly, 0)
    for _ in range(200):
        den = fhi - flo
        tm = (lo * fhi - hi * flo) / den if den != 0.0 else 0.5 * (lo + hi)
        if not (lo < tm < hi):
            tm = 0.5 * (lo + hi)
        if deg >= 0:
            sg = tm - mid
            dx = poly[deg]
            for k in range(deg - 1, -1, -1):
                dx = dx * sg + poly[k]
        elif proj:
            dx = _base_x(pm, xb, t0 + tm) - _base_x(pm, xb, t0)
            _rows_at(rows, hf, cplx, n2, W, tm, out)
            dx += out[row, 0] - out[row, 3]
        else:
            dx = _base_x(pm, xb, t0 + tm) - _base_x(pm, xb, t0)
            if dec:
                _free_states(pm, cfg[10], t0, q0, v0, tm, q, v)
            else:
                _states(pm, cfg, nstuck, t0, q0, v0, tm, q, v)
            for i in range(pm.shape[0]):
                dx += Phi[row, i] * (q[i] - q0[i])
        fm = s * (z0 + u0 * tm - dx) - h
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


@compiled
def _none_before(pm, cfg, nstuck, stuck, Phi, hd, t0, q0, v0, z0, u0, side0, tau_safe, A, tau, za,
                 which, wall, tk, q, v, rows, out, xb):  # fmt: skip
    """Whether no free damper meets a wall in [τ, τₖ) when damper ``which`` meets wall ``wall``
    at τₖ (refined) and every z was inside at τ (``za``): near τₖ that damper's s·z ≤ h − r(τₖ − t)
    + Aₖ(τₖ − t)²/2 < h while τₖ − t ≤ r/Aₖ (r its rate at τₖ), and over [τ, t₁] and [t₁, τₖ],
    t₁ = τₖ − r/Aₖ, each damper's chord bound (:func:`_next_impact`'s) must clear both walls
    (a wall just left also while the interval ends before its held-off time).  False (not
    certified) sends the search back to halving its step.  ``rows``, ``out``: as
    :func:`_held_off`'s."""
    N, K = pm.shape[0], Phi.shape[0]
    dec = cfg[6]
    proj = not dec and rows.shape[0] > 0
    hf, cplx, n2, W = cfg[11], cfg[1], cfg[2], pm[0, P_W]
    if dec:
        _free_states(pm, cfg[10], t0, q0, v0, tk, q, v)
    elif proj:
        _rows_at(rows, hf, cplx, n2, W, tk, out)
    else:
        _states(pm, cfg, nstuck, t0, q0, v0, tk, q, v)
    xd = out[which, 1] if proj else _dot(Phi, which, v)
    r = wall * (u0[which] - xd - _base_v(pm, xb, t0 + tk))
    if not r > 0.0:
        return False
    t1 = max(tau, tk - r / A[which])
    zk = np.empty(K)
    shift = _base_x(pm, xb, t0 + tk) - _base_x(pm, xb, t0)
    for k in range(K):
        dx = shift
        if proj:
            dx += out[k, 0] - out[k, 3]
        else:
            for i in range(N):
                dx += Phi[k, i] * (q[i] - q0[i])
        zk[k] = z0[k] + u0[k] * tk - dx
    if dec:
        _free_states(pm, cfg[10], t0, q0, v0, t1, q, v)
    elif proj:
        _rows_at(rows, hf, cplx, n2, W, t1, out)
    else:
        _states(pm, cfg, nstuck, t0, q0, v0, t1, q, v)
    shift = _base_x(pm, xb, t0 + t1) - _base_x(pm, xb, t0)
    for k in range(K):
        if stuck[k] != 0:
            continue
        dx = shift
        if proj:
            dx += out[k, 0] - out[k, 3]
        else:
            for i in range(N):
                dx += Phi[k, i] * (q[i] - q0[i])
        z1 = z0[k] + u0[k] * t1 - dx
        for w in (1.0, -1.0):
            first = max(w * za[k], w * z1) + A[k] * (t1 - tau) ** 2 / 8.0 < hd[k]
            if not first and not (side0[k] == w and t1 <= tau_safe[k]):
                return False
            if k == which and w == wall:
                continue  # [t₁, τₖ): the rate's bound above
            last = max(w * z1, w * zk[k]) + A[k] * (tk - t1) ** 2 / 8.0 < hd[k]
            if not last and not (side0[k] == w and tk <= tau_safe[k]):
                return False
    return True


@compiled
def _next_impact(pm, cfg, nstuck, stuck, Phi, hd, t0, q0, v0, z0, u0, side0, T, watch, work, rows,
                 out, xb):  # fmt: skip
    """(τ, damper, side): the first τ in (0, T] at which a free damper's abs(z) reaches its half
    clearance, that damper and its wall (±1); (T, −1, 0) when there is none, or (τ so far, −1, 0)
    when a signal is seen on ``watch``.  ``side0[k]``: the wall damper k starts on (0: none).
    While a mass rides, the flight is read through its projection on the dampers' points,
    ``rows`` (:func:`_held_rows`, filled by the caller for this flight; ``out``: its scratch)."""
    N, K = pm.shape[0], Phi.shape[0]
    if nstuck == K:  # every mass rides on its point: nothing to meet
        return T, -1, 0
    hmax = 2.0 * math.pi / cfg[9] / 16.0
    dec = cfg[6]
    proj = not dec and rows.shape[0] > 0
    hf, cplx, n2, W = cfg[11], cfg[1], cfg[2], pm[0, P_W]
    A, B, tau_safe, q, v, za, zb = work[0], work[1], work[2], work[3], work[4], work[5], work[6]
    _bounds(pm, cfg, nstuck, Phi, t0, q0, v0, T, A, B, rows, xb)
    hmin = 1e-6 * hmax
    tau_safe[:] = 0.0
    for k in range(K):
        if stuck[k] != 0:
            continue
        hmin = min(hmin, max(1e-12 * hmax, math.sqrt(8e-20 * hd[k] / A[k])))
        if side0[k] != 0:
            xd = _base_v(pm, xb, t0)
            for i in range(N):
                xd += Phi[k, i] * v0[i]
            fd0 = side0[k] * (u0[k] - xd)
            # a plastic impact leaves the two at one speed to rounding: a positive rate of a few
            # units in the last place of the speeds is that rounding, not an approach (taken as
            # one, the search met the wall again within picoseconds, below the clearance's ulp)
            if fd0 <= 8e-16 * (abs(u0[k]) + abs(xd)):
                fd0 = min(fd0, 0.0)
                tau_safe[k] = max(-2.0 * fd0 / A[k], _held_off(pm, cfg, nstuck, Phi, k, t0, q0,
                                  v0, side0[k], T, A[k], B[k], work[7], work[8], rows, out,
                                  xb))  # fmt: skip
    for k in range(K):
        za[k] = z0[k]
        zb[k] = z0[k]
    tau = 0.0
    H = min(hmax, T)
    for k in range(K):
        # a damper on the wall it left (abs(z) = h) passes the first step's chord test only
        # while the step is within its held-off time: the steps the search would halve down to
        # there fail without looking, and are not taken (the same dyadic step comes out, and
        # the same looks follow; in a chatter most of an event's looks were these)
        if stuck[k] == 0 and side0[k] != 0 and abs(z0[k]) >= hd[k]:
            while H > tau_safe[k] and H > hmin:
                H *= 0.5
    looks = 0
    while tau < T:
        looks += 1
        if (looks & (EVERY - 1)) == 0 and stop_requested(watch):
            return tau, -1, 0
        H = min(H, T - tau)
        tb = tau + H
        if dec:
            _free_states(pm, cfg[10], t0, q0, v0, tb, q, v)
        elif proj:
            _rows_at(rows, hf, cplx, n2, W, tb, out)
        else:
            _states(pm, cfg, nstuck, t0, q0, v0, tb, q, v)
        clear = True
        shift = _base_x(pm, xb, t0 + tb) - _base_x(pm, xb, t0)
        for k in range(K):
            if stuck[k] != 0:
                continue
            dx = shift
            if proj:
                dx += out[k, 0] - out[k, 3]
            else:
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
            for k in range(K):
                za[k] = zb[k]
            H = min(2.0 * H, hmax)
            continue
        if H > hmin and H > 4e-16 * tb:
            # a crossing already bracketed, away from where its damper started: refined at
            # once and taken where nothing can come before it (else the step is halved)
            first, which, wall = tb, -1, 0
            for k in range(K):
                if stuck[k] == 0 and abs(zb[k]) >= hd[k] and abs(za[k]) < hd[k] and tau > 0.0:
                    s = 1.0 if zb[k] > 0 else -1.0
                    tk = _refine(pm, cfg, nstuck, Phi, k, hd[k], t0, q0, v0, z0[k], u0[k], s,
                                 tau, tb, za[k], zb[k], q, v, rows, out, xb)  # fmt: skip
                    if which < 0 or tk < first:
                        first, which, wall = tk, k, int(s)
            if which >= 0 and _none_before(pm, cfg, nstuck, stuck, Phi, hd, t0, q0, v0, z0, u0,
                                           side0, tau_safe, A, tau, za, which, wall, first, q,
                                           v, rows, out, xb):  # fmt: skip
                return first, which, wall
            H *= 0.5
            continue
        first, which, wall = tb, -1, 0
        for k in range(K):
            if stuck[k] == 0 and abs(zb[k]) >= hd[k]:
                s = 1.0 if zb[k] > 0 else -1.0
                tk = _refine(pm, cfg, nstuck, Phi, k, hd[k], t0, q0, v0, z0[k], u0[k], s, tau,
                             tb, za[k], zb[k], q, v, rows, out, xb)  # fmt: skip
                if which < 0 or tk < first:
                    first, which, wall = tk, k, int(s)
        if which >= 0:
            return first, which, wall
        tau = tb  # excursions shorter than hmin: below 1e-20 of the clearances
        for k in range(K):
            za[k] = zb[k]
        H = hmax
    return T, -1, 0


@compiled
def _next_contact(pm, cfg, nstuck, Sphi, sg, sside, contact, srig, fresh, fresh_wall, t0, q0, v0,
                  T, watch, work):  # fmt: skip
    """(τ, stop, wall): the first τ in (0, T] at which a stop's contact begins (its point xₛ,
    free of the stop, reaches the wall w·g) or ends (the point pressing the wall w comes back to
    w·g), that stop and the new value of ``contact[s]`` (w at an onset, 0 at an exit); (T, −1, 0)
    when none does, (τ so far, −2, 0) when a signal is seen on ``watch``.  The search is the
    impact search's (a grid every bound A ≥ abs(ẍₛ) certifies, halved where it cannot, Illinois
    regula falsi on the crossing); stop ``fresh``, which switched at t0 with the point's speed r,
    cannot switch again on the same wall before 2·abs(r)/A (its penetration, or its gap, grows
    as rτ − Aτ²/2), nor, when it just left its wall ``fresh_wall`` (a rigid stop's rebound or
    release), while its point's acceleration is certified to point away (:func:`_held_off`);
    a two-sided stop's other wall is watched meanwhile.  A held rigid stop does
    not switch here (:func:`_stop_release`)."""
    S = Sphi.shape[0]
    hmax = 2.0 * math.pi / cfg[9] / 16.0
    dec = cfg[6]
    A, B, fa, fb, hold = work[14], work[15], work[16], work[17], work[18]
    q, v = work[3], work[4]
    none = np.zeros((0, 3, 1), dtype=np.complex128)  # the flight read whole (no projection)
    none_out = np.zeros((0, 4))
    _bounds(pm, cfg, nstuck, Sphi, t0, q0, v0, T, A, B, none, 0.0)
    hmin = 1e-6 * hmax
    for s in range(S):
        hmin = min(hmin, max(1e-12 * hmax, math.sqrt(8e-20 * sg[s] / A[s])))
        fa[s] = _dot(Sphi, s, q0)
        hold[s] = 0.0
        if s == fresh:
            hold[s] = 2.0 * abs(_dot(Sphi, s, v0)) / A[s]
            if fresh_wall != 0:
                hold[s] = max(hold[s], _held_off(pm, cfg, nstuck, Sphi, s, t0, q0, v0,
                                                 -fresh_wall, T, A[s], B[s], work[7], work[8],
                                                 none, none_out, 0.0))  # fmt: skip
        if contact[s] != 0 and srig[s] != 0:
            hold[s] = math.inf  # held on its wall: the constraint keeps it there
    tau = 0.0
    H = hmax
    looks = 0
    while tau < T:
        looks += 1
        if (looks & (EVERY - 1)) == 0 and stop_requested(watch):
            return tau, -2, 0
        H = min(H, T - tau)
        tb = tau + H
        if dec:
            _free_states(pm, cfg[10], t0, q0, v0, tb, q, v)
        else:
            _states(pm, cfg, nstuck, t0, q0, v0, tb, q, v)
        clear = True
        for s in range(S):
            fb[s] = _dot(Sphi, s, q)
            held_off = tb <= hold[s]
            if held_off and contact[s] != 0:
                continue
            slack = A[s] * H * H / 8.0
            top = max(fa[s], fb[s]) + slack
            low = min(fa[s], fb[s]) - slack
            if contact[s] == 1:
                stays = low > sg[s]
            elif contact[s] == -1:
                stays = top < -sg[s]
            else:  # held off, only from the wall it has just left: the other is watched
                near = _dot(Sphi, s, q0) > 0.0
                stays = (sside[s] < 0 or top < sg[s] or (held_off and near)) and (
                    sside[s] > 0 or low > -sg[s] or (held_off and not near)
                )
            if not stays:
                clear = False
        if clear:
            tau = tb
            for s in range(S):
                fa[s] = fb[s]
            H = min(2.0 * H, hmax)
            continue
        if H > hmin and H > 4e-16 * tb:
            H *= 0.5
            continue
        first, which, wall = tb, -1, 0
        for s in range(S):
            held_off = tb <= hold[s]
            if held_off and contact[s] != 0:
                continue
            near = _dot(Sphi, s, q0) > 0.0  # the wall a held-off point has just left
            # the crossing as the impact search's: z = −x reaching the level h on the side d
            d, h, to = 0.0, 0.0, 0
            if contact[s] == 1 and fb[s] <= sg[s]:
                d, h, to = 1.0, -sg[s], 0
            elif contact[s] == -1 and fb[s] >= -sg[s]:
                d, h, to = -1.0, -sg[s], 0
            elif (contact[s] == 0 and sside[s] >= 0 and fb[s] >= sg[s]
                  and not (held_off and near)):  # fmt: skip
                d, h, to = -1.0, sg[s], 1
            elif (contact[s] == 0 and sside[s] <= 0 and fb[s] <= -sg[s]
                  and not (held_off and not near)):  # fmt: skip
                d, h, to = 1.0, sg[s], -1
            if d == 0.0:
                continue
            x0 = _dot(Sphi, s, q0)
            ts = _refine(pm, cfg, nstuck, Sphi, s, h, t0, q0, v0, -x0, 0.0, d, tau, tb, -fa[s],
                         -fb[s], q, v, none, none_out, 0.0)  # fmt: skip
            if which < 0 or ts < first:
                first, which, wall = ts, s, to
        if which >= 0:
            return first, which, wall
        tau = tb  # excursions shorter than hmin: below 1e-20 of the gaps
        for s in range(S):
            fa[s] = fb[s]
        H = hmax
    return T, -1, 0


@compiled
def _release(pm, cfg, nstuck, stuck, Phi, t0, q0, v0, T, watch, work, rows, out, xb):
    """(τ, damper): the first τ in (0, T] where a stuck damper's g = sₖ·ẍₐ turns positive (its
    wall would pull; ẍₐ the point's absolute acceleration, with ẍ_b), or (T, −1) (or the τ
    reached when a signal is seen on ``watch``).  The grid is the impact search's: a step over
    which every stuck damper's chord bound max(g(a), g(b)) + Bₖh²/8 stays negative (Bₖ ≥ |g''|,
    :func:`_bounds`) is taken and the next one doubled, up to a sixteenth of the slowest period;
    any other is halved, down to 1/64 of the shortest period, where it is taken as sampled; the
    first sample with g > 0 is refined by Illinois regula falsi.  A coupled flight is read
    through its projection on the dampers' points, ``rows`` (:func:`_held_rows`, filled by the
    caller for this flight; ``out``: its scratch; none, shape 0: the state and
    :func:`_point_accel`)."""
    K = Phi.shape[0]
    fine = 2.0 * math.pi / cfg[8] / 64.0
    hmax = max(2.0 * math.pi / cfg[9] / 16.0, fine)
    proj = not cfg[6] and rows.shape[0] > 0
    hf, cplx, n2, W = cfg[11], cfg[1], cfg[2], pm[0, P_W]
    A, B, q, v, fa, fb = work[0], work[1], work[3], work[4], work[9], work[2]
    _bounds(pm, cfg, nstuck, Phi, t0, q0, v0, T, A, B, rows, xb)
    for k in range(K):
        fa[k] = -1.0
        if stuck[k] != 0:
            fa[k] = min(stuck[k] * _point_accel(pm, cfg, nstuck, Phi, k, t0, q0, v0, xb), -1e-300)
    tau = 0.0
    H = hmax
    looks = 0
    while tau < T:
        looks += 1
        if (looks & (EVERY - 1)) == 0 and stop_requested(watch):
            return tau, -1
        H = min(H, T - tau)
        tb = tau + H
        if proj:
            _rows_at(rows, hf, cplx, n2, W, tb, out)
        else:
            _states(pm, cfg, nstuck, t0, q0, v0, tb, q, v)
        certain, pulls = True, False
        for k in range(K):
            if stuck[k] != 0 and proj:
                fb[k] = stuck[k] * (out[k, 2] + _base_a(pm, xb, t0 + tb))
            elif stuck[k] != 0:
                fb[k] = stuck[k] * _point_accel(pm, cfg, nstuck, Phi, k, t0 + tb, q, v, xb)
            if stuck[k] != 0:
                pulls = pulls or fb[k] > 0.0
                certain = certain and max(fa[k], fb[k]) + B[k] * H * H / 8.0 < 0.0
        if not certain and H > fine:
            H *= 0.5
            continue
        first, which = tb, -1
        for k in range(K):
            if stuck[k] == 0 or not fb[k] > 0.0:
                continue
            lo, hi, flo, fhi = tau, tb, fa[k], fb[k]
            kept = 0
            for _ in range(200):
                tm = secant_point(lo, hi, flo, fhi)
                if proj:
                    _rows_at(rows, hf, cplx, n2, W, tm, out)
                    fm = stuck[k] * (out[k, 2] + _base_a(pm, xb, t0 + tm))
                else:
                    _states(pm, cfg, nstuck, t0, q0, v0, tm, q, v)
                    fm = stuck[k] * _point_accel(pm, cfg, nstuck, Phi, k, t0 + tm, q, v, xb)
                if fm > 0.0:
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
            if which < 0 or hi < first:
                first, which = hi, k
        if pulls:
            return first, which
        tau = tb
        for k in range(K):
            if stuck[k] != 0:
                fa[k] = fb[k]
        H = min(2.0 * H, hmax)
    return T, -1


@compiled
def _held_pulls(pm, cfg, Sphi, contact, srig, t, q, v, out):
    """For each held rigid stop (in their order), w·λ: its wall's reaction force λ on the
    structure times the wall's side w; positive where the wall would have to pull
    (λ = −(ΦₕM_s⁻¹Φₕᵀ)⁻¹ΦₕM_s⁻¹f, f the modal forces of the held structure's flight, M_s⁻¹
    unconstrained: :func:`_config`).  Returns the number of held stops."""
    N = pm.shape[0]
    Ks, Cs, fs, Mfull = cfg[0][1], cfg[0][2], cfg[3][0], cfg[0][3]
    W = pm[0, P_W]
    th = W * t + pm[0, P_PHI]
    c, sn = math.cos(th), math.sin(th)
    f = np.empty(N)
    for j in range(N):
        P = pm[j, P_F0] + pm[j, P_K] * pm[j, P_XB]
        Q = -pm[j, P_C] * W * pm[j, P_XB]
        cv, kq = 0.0, 0.0
        for m in range(N):
            cv += Cs[j, m] * v[m]
            kq += Ks[j, m] * q[m]
        f[j] = P * c + Q * sn + fs[j] - cv - kq
    Mf = np.zeros(N)
    for i in range(N):
        for j in range(N):
            Mf[i] += Mfull[i, j] * f[j]
    return _held_reactions(cfg, Sphi, contact, srig, Mf, out)


@compiled
def _held_reactions(cfg, Sphi, contact, srig, Mf, out):
    """w·λ for each held rigid stop from the unconstrained response M_s⁻¹f (or M_s⁻¹φP of an
    impulse): λ = −(ΦₕM_s⁻¹Φₕᵀ)⁻¹Φₕ·M_s⁻¹f.  Returns the number of held stops."""
    h = cfg[4]
    Pinv = cfg[0][4]
    a = np.zeros(h)
    walls = np.zeros(h)
    j = 0
    for s in range(Sphi.shape[0]):
        if contact[s] != 0 and srig[s] != 0:
            a[j] = _dot(Sphi, s, Mf)
            walls[j] = contact[s]
            j += 1
    for i in range(h):
        lam = 0.0
        for j in range(h):
            lam -= Pinv[i, j] * a[j]
        out[i] = walls[i] * lam
    return h


@compiled
def _row_response(cfg, Phi, row, P):
    """M_s⁻¹φP: the unconstrained response to an impulse P at the point of row ``row``."""
    Mfull = cfg[0][3]
    N = Mfull.shape[0]
    out = np.zeros(N)
    for i in range(N):
        for j in range(N):
            out[i] += Mfull[i, j] * Phi[row, j] * P
    return out


@compiled
def _held_index(contact, srig, i):
    """The stop of the i-th held rigid stop."""
    j = 0
    for s in range(contact.shape[0]):
        if contact[s] != 0 and srig[s] != 0:
            if j == i:
                return s
            j += 1
    return -1


@compiled
def _stop_release(pm, cfg, Sphi, contact, srig, t0, q0, v0, T, watch, work):
    """(τ, stop): the first τ in (0, T] where a held rigid stop's wall would pull
    (:func:`_held_pulls` turns positive), or (T, −1) (or the τ reached on a signal)."""
    step = 2.0 * math.pi / cfg[8] / 64.0
    q, v, fa, fb = work[3], work[4], work[16], work[17]
    h = _held_pulls(pm, cfg, Sphi, contact, srig, t0, q0, v0, fa)
    for i in range(h):
        fa[i] = min(fa[i], -1e-300)
    tau = 0.0
    looks = 0
    while tau < T:
        looks += 1
        if (looks & (EVERY - 1)) == 0 and stop_requested(watch):
            return tau, -1
        tb = min(tau + step, T)
        _states(pm, cfg, 0, t0, q0, v0, tb, q, v)
        _held_pulls(pm, cfg, Sphi, contact, srig, t0 + tb, q, v, fb)
        first, which = tb, -1
        for i in range(h):
            if fb[i] > 0.0:
                lo, hi, flo, fhi = tau, tb, fa[i], fb[i]
                kept = 0
                out = np.empty(h)
                for _ in range(200):
                    tm = secant_point(lo, hi, flo, fhi)
                    _states(pm, cfg, 0, t0, q0, v0, tm, q, v)
                    _held_pulls(pm, cfg, Sphi, contact, srig, t0 + tm, q, v, out)
                    fm = out[i]
                    if fm > 0.0:
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
                if which < 0 or hi < first:
                    first, which = hi, _held_index(contact, srig, i)
        if which >= 0:
            return first, which
        for i in range(h):
            fa[i] = fb[i]
        tau = tb
    return T, -1


@compiled
def _stop_impulse(pm, cfg, Sphi, s, e, v):
    """A rigid impact of the point of stop s on its wall, Newton's law with restitution e at the
    point: φᵀq̇⁺ = −e·φᵀq̇⁻ through J = −(1 + e)φᵀq̇/(φᵀM_s⁻¹φ), q̇ += M_s⁻¹φJ (M_s⁻¹ the
    one the held walls allow, :func:`_config`); ``v`` changed in place.  Returns (J, m_eff):
    the loss is ½m_eff(1 − e²)(φᵀq̇)²."""
    N = pm.shape[0]
    Minv = cfg[0][0]
    w = np.zeros(N)
    for i in range(N):
        if cfg[6]:
            w[i] = Sphi[s, i] / pm[i, P_M]
        else:
            for j in range(N):
                w[i] += Minv[i, j] * Sphi[s, j]
    inv = _dot(Sphi, s, w)
    if inv <= 0.0:
        return 0.0, math.inf
    J = -(1.0 + e) * _dot(Sphi, s, v) / inv
    for i in range(N):
        v[i] += w[i] * J
    return J, 1.0 / inv


@compiled
def _stop_jump(pm, cfg, Sphi, s, K, e):
    """D: the Jacobian of a rigid stop's impact law (:func:`_stop_impulse`) in the state
    (q, q̇, y, ẏ): q̇⁺ = q̇ − (1 + e)·w·φᵀq̇/(φᵀw), w = M_s⁻¹φ."""
    N = pm.shape[0]
    DJ = np.eye(2 * N + 2 * K)
    w = np.zeros(N)
    for i in range(N):
        if cfg[6]:
            w[i] = Sphi[s, i] / pm[i, P_M]
        else:
            for j in range(N):
                w[i] += cfg[0][0][i, j] * Sphi[s, j]
    inv = _dot(Sphi, s, w)
    for i in range(N):
        for j in range(N):
            DJ[N + i, N + j] -= (1.0 + e) * w[i] * Sphi[s, j] / inv
    return DJ
