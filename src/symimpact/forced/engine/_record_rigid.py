"""Compiled event-driven simulation of the primary and its impact damper (rigid impacts, Step 9's
law, Eq. F2) under a sampled load (numba, cached).

Between events everything is closed form: on each interval of the record the load is a straight
line and the primary follows Step 16's flight (``symimpact.generated.sampled_load.ramp_state``,
Eq. F8); the impact mass moves with the base's acceleration taken out (constant velocity under a
force; under a base acceleration a_b, relative to the base, ÿ = −a_b: a cubic in time on each
interval).  No ODE is integrated.

*Finding the next impact without sampling gaps.*  On a piece of an interval, x is the ramp's
particular response (a straight line) plus a decaying oscillation of amplitude at most R, so
|x⁽ᵏ⁾| ≤ ω_nᵏ·R for k ≥ 2 (|−σ + iω_d| = ω_n).  The relative displacement z = y − x then has
|z''| ≤ A = max|a_b| + ω_n²R, |z'''| ≤ J = |ȧ_b| + ω_n³R and |z''''| ≤ Q = ω_n⁴R.  An interval
[τa, τb] with max(z_a, z_b) + A(τb − τa)²/8 below the wall is skipped, any other halved; a
crossing is bracketed and refined by Illinois regula falsi.  A piece that starts on a wall (after
an impact, a release, or across a sample) with f = s·z − d/2 = 0 and f' ≤ 0 cannot reach it again
while the Taylor bounds f ≤ f'τ + Aτ²/2, f ≤ f'τ + f''τ²/2 + Jτ³/6 or
f ≤ f'τ + f''τ²/2 + f'''τ³/6 + Qτ⁴/24 stay negative; half the longest such stretch is skipped.
An excursion past a wall by less than 1e-20 of the clearance may be missed (the halving stops at
a width whose bound is that small).

*Chatter and sticking.*  As for the harmonic engine (:mod:`symimpact.forced.engine._rigid`): when the
impact mass keeps returning to the same wall with relative acceleration a towards it and a
separation speed w so small that the flights' sum Δ = 2w/(a(1 − e)) is at most ``chatter`` of a
natural period, the run jumps to the accumulation point, where the masses move on together
(momentum conserved; the relative kinetic energy is the impacts' loss); the pair M + m then
follows Eq. F8 while the wall's force on the impact mass stays compressive (s·ẍ_abs ≤ 0, ẍ_abs the
absolute acceleration), released where s·ẍ_abs turns positive — by more than 1e-12 of the pair's
acceleration scale, so that a tangency touched by rounding does not release and re-stick the pair
for ever (certified as above with |d²ẍ_abs/dτ²| ≤ ω_n⁴R of the pair).

*Energy ledger.*  E = ½Mẋ² + ½Kx² + ½mẏ² (velocities relative to the base) changes by the load's
work — ∫p·ẋ dt for a force p, −∫a_b·(ΓMẋ + mẏ) dt for a base acceleration (the inertial load in
the base's frame; Γ the primary's participation in the base's motion, 1 for a primary whose
spring and damper attach to the base, Γᵢφᵢ(a) for mode i of a structure seen at the point a,
Eq. F7) — less C's dissipation ∫Cẋ² dt and the impacts' losses; the integrals by 8-point
Gauss–Legendre on sub-pieces of at most 1/16 of the natural period (the integrands are smooth
there).

This module is private: :mod:`symimpact.forced.loads.record_response` validates the input and builds
the result.
"""

from __future__ import annotations

import math

import numpy as np

from ..._compiled import compiled
from ..._interrupt import EVERY, INTERRUPTED, stop_requested
from ...free._stepper import secant_point
from ...generated import sampled_load as _sl
from ._rigid import restitution

# parameter vector layout: masses [kg], K [N/m], C [N s/m], half clearance [m], e, chatter
# threshold [natural periods], 1.0 for a base-acceleration record (0.0: a force), the yield
# speed of a restitution that follows the impact speed [m/s] (0: the constant e), and the
# primary's participation Γ in the base's motion (1: its spring and damper attach to the base;
# a structure's mode i at the point a: Γᵢφᵢ(a), Eq. F7)
P_M, P_m, P_K, P_C, P_h, P_e, P_CHAT, P_BASE, P_VY, P_GAMMA = range(10)
N_PARAMS = 10
# event-log columns: time [s], side (±1), approach speed [m/s], energy lost [J], kind
E_T, E_SIDE, E_VREL, E_LOST, E_KIND = range(5)
N_EVENT_COLS = 5
KIND_IMPACT, KIND_ACCUMULATION, KIND_RELEASE = 0, 1, 2
OK, TOO_MANY_EVENTS = 0, 1
#: A stuck pair is released where the wall would pull by more than this fraction of the pair's
#: acceleration scale (ω_n²R + |a_b|): rounding alone releases nothing.
RELEASE = 1e-12

_ramp = compiled(_sl.ramp_state_scalar)
_GL_X, _GL_W = np.polynomial.legendre.leggauss(8)


@compiled
def _base_inertia(p, mu):
    """The mass the base's acceleration loads through the moving mass ``mu`` (M, or M + m
    riding): Γ·M + (mu − M) = mu + (Γ − 1)·M, exactly mu for Γ = 1."""
    return mu + (p[P_GAMMA] - 1.0) * p[P_M]


@compiled
def _loads(p, mu, q0, qd):
    """(p0, ṗ, g0, ġ): the load on the moving mass ``mu`` and the impact mass's acceleration
    relative to the base, at the piece's start and their slopes, for the record's line q0 + qd·τ.
    Under a base acceleration a_b the primary's inertia load is −Γ·M·a_b, the impact mass's
    −m·a_b (riding: −(Γ·M + m)·a_b = −(mu + (Γ − 1)·M)·a_b, exactly −mu·a_b for Γ = 1)."""
    if p[P_BASE] != 0.0:
        inertia = _base_inertia(p, mu)
        return -inertia * q0, -inertia * qd, -q0, -qd
    return q0, qd, 0.0, 0.0


@compiled
def _decay(mu, K, C, p0, pd, x0, v0):
    """(R, ω_n): the amplitude of the decaying part of Eq. F8's flight and the natural frequency."""
    sigma = C / (2.0 * mu)
    wn2 = K / mu
    wd = math.sqrt(wn2 - sigma * sigma)
    dx = x0 - (p0 / K - C * pd / (K * K))
    dv = v0 - pd / K
    return math.sqrt(dx * dx + ((dv + sigma * dx) / wd) ** 2), math.sqrt(wn2)


@compiled
def _z(mu, K, C, p0, pd, g0, gd, x0, v0, z0, u0, s):
    """z = y − x a time s into the piece."""
    x, _ = _ramp(s, mu, K, C, p0, pd, x0, v0)
    return z0 + u0 * s + g0 * s * s / 2.0 + gd * s * s * s / 6.0 - (x - x0)


@compiled
def _wall_safe(h, side, mu, K, C, p0, pd, g0, gd, x0, v0, z0, u0, A, J, Q):
    """A stretch from the piece's start on which the wall ``side`` is certainly not reached, when
    the piece starts on it (module docstring); 0 otherwise."""
    if side == 0:
        return 0.0
    if side * z0 - h < -1e-9 * h:
        return 0.0
    a0 = (p0 - C * v0 - K * x0) / mu
    j0 = (pd - C * a0 - K * v0) / mu
    f1 = side * (u0 - v0)
    f2 = side * (g0 - a0)
    f3 = side * (gd - j0)
    if f1 > 0.0:
        return 0.0
    r = 0.0
    if f1 < 0.0:
        r = -2.0 * f1 / A
    if f2 < 0.0:
        r = max(r, -3.0 * f2 / J)
    if f2 <= 0.0 and f3 < 0.0:
        r = max(r, -4.0 * f3 / Q)
    return 0.5 * r


@compiled
def _value(which, p, side, mu, p0, pd, g0, gd, x0, v0, z0, u0, level, s):
    """s into the piece: side·z − level (``which`` 0: the gap to the wall ``side``) or the stuck
    pair's side·ẍ_abs − level (``which`` 1: the pull the wall would need)."""
    if which == 0:
        return side * _z(mu, p[P_K], p[P_C], p0, pd, g0, gd, x0, v0, z0, u0, s) - level
    return _stuck_sign(p, side, mu, p0, pd, g0, gd, x0, v0, s) - level


@compiled
def _first_root(which, p, side, mu, p0, pd, g0, gd, x0, v0, z0, u0, level, lo, hi, flo, fhi):
    """Where :func:`_value` reaches 0 in (lo, hi], bracketed by flo < 0 ≤ fhi: Illinois regula
    falsi to 4e-16 of the time (the bracket's end on the reached side is returned)."""
    kept = 0
    for _ in range(200):
        tm = secant_point(lo, hi, flo, fhi)
        fm = _value(which, p, side, mu, p0, pd, g0, gd, x0, v0, z0, u0, level, tm)
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
        if hi - lo <= 4e-16 * hi:
            break
    return hi


@compiled
def _next_impact(p, mu, p0, pd, g0, gd, x0, v0, z0, u0, side0, L):
    """(s, side): the first s in (0, L] with abs(z) = d/2 in the piece, and its wall; (L, 0) when
    there is none.  ``side0`` is the wall the piece starts on (0: none)."""
    h, K, C = p[P_h], p[P_K], p[P_C]
    R, wn = _decay(mu, K, C, p0, pd, x0, v0)
    A = (max(abs(g0), abs(g0 + gd * L)) + wn * wn * R) * (1.0 + 1e-9) + 1e-300
    J = (abs(gd) + wn * wn * wn * R) * (1.0 + 1e-9) + 1e-300
    Q = wn**4 * R * (1.0 + 1e-9) + 1e-300
    safe = _wall_safe(h, side0, mu, K, C, p0, pd, g0, gd, x0, v0, z0, u0, A, J, Q)
    hmax = min(L, 2.0 * math.pi / wn / 16.0)
    hmin = min(1e-6 * hmax, max(1e-12 * hmax, math.sqrt(8e-20 * h / A)))
    tau = 0.0
    za = z0
    H = hmax
    while tau < L:
        H = min(H, L - tau)
        tb = tau + H
        zb = _z(mu, K, C, p0, pd, g0, gd, x0, v0, z0, u0, tb)
        slack = A * H * H / 8.0
        up = max(za, zb) + slack < h or (side0 == 1 and tb <= safe)
        down = min(za, zb) - slack > -h or (side0 == -1 and tb <= safe)
        if up and down:
            tau, za = tb, zb
            H = min(2.0 * H, hmax)
            continue
        if H > hmin and H > 4e-16 * tb:
            H *= 0.5
            continue
        if abs(zb) >= h:
            s = 1.0 if zb > 0 else -1.0
            hit = _first_root(0, p, s, mu, p0, pd, g0, gd, x0, v0, z0, u0, h, tau, tb,
                              min(s * za - h, 0.0), s * zb - h)  # fmt: skip
            return hit, int(s)
        tau, za = tb, zb  # an excursion below 1e-20 of the clearance
        H = hmax
    return L, 0


@compiled
def _stuck_sign(p, side, mu, p0, pd, g0, gd, x0, v0, s):
    """side·ẍ_abs of the stuck pair s into the piece: ẍ − g, g the impact mass's acceleration
    relative to the base (−a_b); positive where the wall would have to pull."""
    x, v = _ramp(s, mu, p[P_K], p[P_C], p0, pd, x0, v0)
    return side * ((p0 + pd * s - p[P_C] * v - p[P_K] * x) / mu - (g0 + gd * s))


@compiled
def _release(p, side, mu, p0, pd, g0, gd, x0, v0, L):
    """s in [0, L] where the stuck pair's side·ẍ_abs first turns positive, or L (module
    docstring: certified with |d²ẍ_abs/dτ²| ≤ ω_n⁴R)."""
    K, C = p[P_K], p[P_C]
    R, wn = _decay(mu, K, C, p0, pd, x0, v0)
    B = wn**4 * R * (1.0 + 1e-9) + 1e-300
    scale = wn * wn * R + abs(g0) + abs(gd) * L + 1e-300
    # the wall must pull by more than rounding: at a tangency (s·ẍ_abs touching zero) a release
    # by rounding alone would be undone by an impact at zero speed at once, for ever
    tol = RELEASE * scale
    fa = _stuck_sign(p, side, mu, p0, pd, g0, gd, x0, v0, 0.0) - tol
    if fa > 0.0:
        return 0.0
    hmax = min(L, 2.0 * math.pi / wn / 16.0)
    hmin = min(1e-6 * hmax, max(1e-12 * hmax, math.sqrt(8e-20 * scale / B)))
    tau, H = 0.0, hmax
    while tau < L:
        H = min(H, L - tau)
        tb = tau + H
        fb = _stuck_sign(p, side, mu, p0, pd, g0, gd, x0, v0, tb) - tol
        if max(fa, fb) + B * H * H / 8.0 < 0.0:
            tau, fa = tb, fb
            H = min(2.0 * H, hmax)
            continue
        if H > hmin and H > 4e-16 * tb:
            H *= 0.5
            continue
        if fb > 0.0:
            return _first_root(1, p, side, mu, p0, pd, g0, gd, x0, v0, 0.0, 0.0, tol, tau, tb,
                               min(fa, -1e-300), fb)  # fmt: skip
        tau, fa = tb, fb  # a pull below 1e-20 of the pair's acceleration scale
        H = hmax
    return L


@compiled
def _account(p, mu, stuck, p0, pd, g0, gd, x0, v0, u0, L, ledger):
    """Add the load's work and C's dissipation over the piece [0, L] to ledger[0], ledger[1]."""
    K, C = p[P_K], p[P_C]
    _, wn = _decay(mu, K, C, p0, pd, x0, v0)
    n = max(1, int(math.ceil(L / (2.0 * math.pi / wn / 16.0))))  # noqa: RUF046
    hs = L / n
    base = p[P_BASE] != 0.0
    for i in range(n):
        for j in range(8):
            s = (i + 0.5 * (1.0 + _GL_X[j])) * hs
            _, v = _ramp(s, mu, K, C, p0, pd, x0, v0)
            wq = 0.5 * hs * _GL_W[j]
            if base:  # a_b = −(g0 + ġ·s); the base-driven momentum relative to the base
                momentum = _base_inertia(p, mu) * v
                if not stuck:
                    momentum += p[P_m] * (u0 + g0 * s + 0.5 * gd * s * s)
                ledger[0] += wq * (g0 + gd * s) * momentum
            else:
                ledger[0] += wq * (p0 + pd * s) * v
            ledger[1] += wq * C * v * v


@compiled
def _grow(a, n):
    """``a`` if it has a row ``n``, else a copy with twice the rows."""
    if n < a.shape[0]:
        return a
    b = np.zeros((2 * a.shape[0] + 16, a.shape[1]))
    b[: a.shape[0]] = a
    return b


@compiled
def run(p, q, dt, state0, max_events, watch):
    """Simulate from state0 = (x, ẋ, z, ẏ) at t = 0 (relative to the base under a base
    acceleration; z = y − x) over the record ``q`` sampled every ``dt`` (or until a signal is
    seen on ``watch``: status INTERRUPTED, see :mod:`symimpact._interrupt`).

    Returns (status, samples, stuck, events, n_events, ledger, n_done): (x, ẋ, z, ẏ) at every
    sample, 1 where the pair is stuck there, the event log (columns E_*), ledger = (work of the
    load, dissipation by C, loss in impacts), and the number of samples reached.
    """
    M, m, K, C, h, e = p[P_M], p[P_m], p[P_K], p[P_C], p[P_h], p[P_e]
    n = q.shape[0]
    out = np.zeros((n, 4))
    stuck_at = np.zeros(n)
    events = np.zeros((64, N_EVENT_COLS))
    ledger = np.zeros(3)
    n_ev = 0
    x, v, z, u = state0[0], state0[1], state0[2], state0[3]
    side0 = 0
    if abs(z) >= h:
        side0 = 1 if z > 0 else -1
        z = side0 * h
    out[0, 0], out[0, 1], out[0, 2], out[0, 3] = x, v, z, u
    stuck = 0
    status = OK
    looks = 0
    Tn = 2.0 * math.pi * math.sqrt(M / K)
    mu_red = M * m / (M + m)
    done = 1
    for i in range(n - 1):
        qd = (q[i + 1] - q[i]) / dt
        tau = 0.0
        while tau < dt:
            looks += 1
            if (looks & (EVERY - 1)) == 0 and stop_requested(watch):
                status = INTERRUPTED
                break
            if n_ev + 2 > max_events:
                status = TOO_MANY_EVENTS
                break
            L = dt - tau
            q0 = q[i] + qd * tau
            t = i * dt + tau
            if stuck:
                mu = M + m
                p0, pd, g0, gd = _loads(p, mu, q0, qd)
                s = _release(p, side0, mu, p0, pd, g0, gd, x, v, L)
                _account(p, mu, True, p0, pd, g0, gd, x, v, v, s, ledger)
                x, v = _ramp(s, mu, K, C, p0, pd, x, v)
                u = v
                z = side0 * h
                if s >= L:
                    break
                tau += s
                stuck = 0
                events = _grow(events, n_ev)
                events[n_ev, E_T], events[n_ev, E_SIDE] = i * dt + tau, side0
                events[n_ev, E_KIND] = KIND_RELEASE
                n_ev += 1
                continue
            mu = M
            p0, pd, g0, gd = _loads(p, mu, q0, qd)
            s, side = _next_impact(p, mu, p0, pd, g0, gd, x, v, z, u, side0, L)
            _account(p, mu, False, p0, pd, g0, gd, x, v, u, s, ledger)
            xn, vn = _ramp(s, mu, K, C, p0, pd, x, v)
            zn = _z(mu, K, C, p0, pd, g0, gd, x, v, z, u, s)
            un = u + g0 * s + 0.5 * gd * s * s
            x, v, z, u = xn, vn, zn, un
            if side == 0:
                # no impact in the interval: the wall the piece began on is no longer "its" wall
                side0 = 0
                if abs(z) >= h:  # within the halving's 1e-20 of the clearance
                    side0 = 1 if z > 0 else -1
                    z = side0 * h
                elif z * z > (h * (1.0 - 1e-9)) ** 2:
                    side0 = 1 if z > 0 else -1
                break
            tau += s
            t = i * dt + tau
            sd = float(side)
            z = sd * h
            vrel = sd * (u - v)  # approach speed, ≥ 0
            e = restitution(p[P_e], p[P_VY], vrel)
            v_after = v + (1.0 + e) * mu_red / M * (u - v)
            u_after = u - (1.0 + e) * mu_red / m * (u - v)
            lost = 0.5 * mu_red * (1.0 - e * e) * vrel * vrel
            ledger[2] += lost
            events = _grow(events, n_ev)
            events[n_ev, E_T], events[n_ev, E_SIDE], events[n_ev, E_VREL] = t, sd, vrel
            events[n_ev, E_LOST], events[n_ev, E_KIND] = lost, KIND_IMPACT
            n_ev += 1
            v, u = v_after, u_after
            side0 = side
            # chatter: does the sequence accumulate within the interval?
            q1 = q[i] + qd * tau
            p1, _, g1, _ = _loads(p, M, q1, qd)
            a = sd * (g1 - (p1 - C * v - K * x) / M)  # relative acceleration towards the wall
            w = e * vrel
            if a > 0.0 and e < 1.0 and p[P_VY] <= 0.0:  # e(v) → 1 as v → 0: no accumulation
                delta = 2.0 * w / (a * (1.0 - e))
                if delta <= p[P_CHAT] * Tn and tau + delta < dt:
                    p1, pd1, g1, gd1 = _loads(p, M, q1, qd)
                    _account(p, M, False, p1, pd1, g1, gd1, x, v, u, delta, ledger)
                    xj, vj = _ramp(delta, M, K, C, p1, pd1, x, v)
                    uj = u + g1 * delta + 0.5 * gd1 * delta * delta
                    vc = (M * vj + m * uj) / (M + m)
                    lost = 0.5 * M * vj * vj + 0.5 * m * uj * uj - 0.5 * (M + m) * vc * vc
                    ledger[2] += lost
                    tau += delta
                    events = _grow(events, n_ev)
                    events[n_ev, E_T], events[n_ev, E_SIDE] = i * dt + tau, sd
                    events[n_ev, E_VREL], events[n_ev, E_LOST] = sd * (uj - vj), lost
                    events[n_ev, E_KIND] = KIND_ACCUMULATION
                    n_ev += 1
                    x, v, u = xj, vc, vc
                    stuck = 1  # (w = 0, a plastic impact, jumps by Δ = 0)
        if status != OK:
            break
        out[i + 1, 0], out[i + 1, 1], out[i + 1, 2], out[i + 1, 3] = x, v, z, u
        stuck_at[i + 1] = stuck
        done = i + 2
    return status, out, stuck_at, events, n_ev, ledger, done
