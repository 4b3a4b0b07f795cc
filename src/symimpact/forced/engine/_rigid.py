"""The one-mode pieces of the rigid-impact engine (numba, cached): Step 8's forced flight of one
mode (``symimpact.generated.forced_flight``, Eq. F1), its acceleration and its bound, the search
for a wall crossing of one mass, the Gauss–Legendre energy ledger of a flight, the impact's
restitution (Step 9, Eq. F2; Step 13's e(v), Eq. F5), the flights' transition matrices for the
shooting chain, and the parameter layout of one mode.  No ODE is integrated.

The engine itself, which composes these mode by mode for a structure of several modes and
dampers, with chatter and sticking, is :mod:`symimpact.forced.engine._modal`; the paper's primary is its
case of one mode of shape 1 and one damper (:func:`symimpact.forced.engine._modal.one_mode_run`).  The
compliant engine (:mod:`symimpact.forced.engine._compliant`) uses the same flight and search between
its contacts.

*Finding the next impact without sampling gaps.*  On [τa, τb] the relative displacement
z = y − x has |z''| = |ẍ| ≤ A, where A bounds the primary's acceleration over the flight: the
steady part contributes (its amplitude)·Ω², the decay of the deviation from it (amplitude R)·ω_n²
(|(−σ + iω_d)²| = ω_n²), and at the undamped resonance the growing part |P|/M·(1 + Ωτ/2).  So
max z ≤ max(z_a, z_b) + A(τb − τa)²/8: an interval this bound clears is skipped, any other halved;
crossings are bracketed and refined by Illinois regula falsi.  Right after an impact the wall just
left cannot be reached before τ_safe = 2w/A (w the separation speed), which keeps the search off
the root at τ = 0, nor while the primary's acceleration is certified to point away from it
(``_held_off``); a flight that leaves while the primary still accelerates back is searched from
2w/A on, so a slow return to that wall is found.

*Energy ledger.*  The work of the forcing and the dissipation of C are integrated over every
segment by 8-point Gauss–Legendre quadrature on sub-intervals of at most 1/16 of the shorter of
the forcing and natural periods (smooth integrands: error far below 1e-12 of the energies).
"""

from __future__ import annotations

import math

import numpy as np

from ..._compiled import compiled
from ..._interrupt import EVERY, stop_requested
from ...free._stepper import secant_point
from ...generated import forced_flight as _fl
from ...generated import hertz_contact as _hz

# parameter vector layout; P_VY: the yield speed of a restitution that follows the impact
# speed (Step 13, Eq. F5; 0: the constant e of P_e)
P_M, P_K, P_C, P_m, P_h, P_e, P_F0, P_XB, P_W, P_PHI, P_CHAT, P_VY = range(12)
N_PARAMS = 12
# event-log columns: time, x, xdot before, ydot before, side, relative approach speed, energy
# lost, kind (see KIND_*), xdot after, ydot after
E_T, E_X, E_XD, E_YD, E_SIDE, E_VREL, E_LOST, E_KIND, E_XD1, E_YD1 = range(10)
N_EVENT_COLS = 10
KIND_IMPACT, KIND_ACCUMULATION, KIND_RELEASE = 0, 1, 2
OK, TOO_MANY_EVENTS = 0, 1

_xf = compiled(_fl.forced_displacement_scalar)
_vf = compiled(_fl.forced_velocity_scalar)
# both at once, their common subexpressions computed once (122 operations against 189): the
# structure engine's state (:mod:`._modal`), 1.55 times as fast as the pair in a numba loop of
# 10 modes (measured); they differ from the pair by rounding (2.7e-14 relative at most over 2000
# random flights), and the compliant engine keeps the pair: its 300-period transients in the
# tests of test_compliant_orbits.py reach other states under that rounding
_xvf = compiled(_fl.forced_state_scalar)
# the flight's transition matrix: the generated derivatives of x(t), ẋ(t) in x0, ẋ0, bundled
_transition = compiled(_fl.forced_transition_scalar)
# and its derivatives in the forcing, for the map's ∂P/∂p
_xf_F0 = compiled(_fl.forced_displacement_d_F0_scalar)
_vf_F0 = compiled(_fl.forced_velocity_d_F0_scalar)
_xf_Xb = compiled(_fl.forced_displacement_d_X_b_scalar)
_vf_Xb = compiled(_fl.forced_velocity_d_X_b_scalar)
_xf_W = compiled(_fl.forced_displacement_d_Omega_scalar)
_vf_W = compiled(_fl.forced_velocity_d_Omega_scalar)
_xf_phi = compiled(_fl.forced_displacement_d_phi_scalar)
_vf_phi = compiled(_fl.forced_velocity_d_phi_scalar)
_steady_cos = compiled(_fl.steady_cosine_scalar)
_steady_sin = compiled(_fl.steady_sine_scalar)
_thornton = compiled(_hz.thornton_restitution_scalar)
_thornton_slope = compiled(_hz.thornton_separation_slope_scalar)


@compiled
def restitution(e, vy, vrel):
    """e of an impact at approach speed ``vrel`` [m/s]: the constant ``e`` where ``vy`` is 0,
    else 1 at or below the yield speed ``vy`` and Thornton's e(vy/vrel) above it (Eq. F5)."""
    if vy <= 0.0:
        return e
    if vrel <= vy:
        return 1.0
    return _thornton(vy / vrel)


@compiled
def restitution_slope(e, vy, vrel):
    """ê = d(e·w)/dw, the separation speed's slope in the approach speed ``vrel`` [m/s] (Step
    13): ``e`` where ``vy`` is 0 (a constant e), 1 at or below the yield speed ``vy``,
    Thornton's T(r) − r·T'(r), r = vy/vrel, above it."""
    if vy <= 0.0:
        return e
    if vrel <= vy:
        return 1.0
    return _thornton_slope(vy / vrel)


#: 8-point Gauss–Legendre nodes and weights on [−1, 1] (NumPy computes them; none typed in).
_GL_X, _GL_W = np.polynomial.legendre.leggauss(8)


@compiled
def _phase(p, t):
    """Forcing phase Ωt + φ at time t, reduced to [0, 2π)."""
    return (p[P_W] * t + p[P_PHI]) % (2.0 * math.pi)


@compiled
def _state(p, mass, t0, x0, v0, tau):
    """Primary's (x, ẋ) a time τ after (x0, v0) at t0, for a moving mass ``mass`` (Eq. F1)."""
    th = _phase(p, t0)
    args = (mass, p[P_K], p[P_C], p[P_F0], p[P_XB], p[P_W], th, x0, v0)
    return _xf(tau, *args), _vf(tau, *args)


@compiled
def flight_matrices(taus, masses, K, C):
    """Φ(τ) of flights (Step 8, Eq. F1: ∂(x, ẋ)/∂(x0, ẋ0), the generated derivative kernels
    ``forced_displacement_d_x0`` … ``forced_velocity_d_xdot0`` in their bundle
    ``forced_transition``, which the forcing does not enter; z = y − x moves by τ·ẏ − (x(τ) − x0), ẏ constant), one 4×4 per flight of ``taus``
    [s] with its moving mass ``masses`` [kg]: the Jacobians of the shooting chain."""
    out = np.zeros((taus.shape[0], 4, 4))
    for i in range(taus.shape[0]):
        tau, mass = taus[i], masses[i]
        _, _, p11, p12, p21, p22 = _transition(tau, mass, K, C, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0)
        out[i, 0, 0], out[i, 0, 1] = p11, p12
        out[i, 1, 0], out[i, 1, 1] = p21, p22
        out[i, 2, 0], out[i, 2, 1], out[i, 2, 2], out[i, 2, 3] = 1.0 - p11, -p12, 1.0, tau
        out[i, 3, 3] = 1.0
    return out


@compiled
def flight_parameter_terms(times, masses, xa, va, K, C, F0, X_b, W, phi, which):
    """∂(x, ẋ)/∂p at the end of each flight from its fixed start (time ``times[i]``, state
    ``xa[i]``, ``va[i]``, moving mass ``masses[i]``) to ``times[i + 1]``, the generated
    derivative kernels of Eq. F1 compiled: ``which`` 0 F0, 1 X_b, 2 Ω (with the start phase
    Ω·tₐ + φ moving too); returned, shape (n, 2)."""
    n = masses.shape[0]
    out = np.zeros((n, 2))
    for i in range(n):
        ta, tau = times[i], times[i + 1] - times[i]
        mu, th, x0, v0 = masses[i], W * ta + phi, xa[i], va[i]
        if which == 0:
            out[i, 0] = _xf_F0(tau, mu, K, C, F0, X_b, W, th, x0, v0)
            out[i, 1] = _vf_F0(tau, mu, K, C, F0, X_b, W, th, x0, v0)
        elif which == 1:
            out[i, 0] = _xf_Xb(tau, mu, K, C, F0, X_b, W, th, x0, v0)
            out[i, 1] = _vf_Xb(tau, mu, K, C, F0, X_b, W, th, x0, v0)
        else:
            out[i, 0] = _xf_W(tau, mu, K, C, F0, X_b, W, th, x0, v0) + ta * _xf_phi(
                tau, mu, K, C, F0, X_b, W, th, x0, v0
            )
            out[i, 1] = _vf_W(tau, mu, K, C, F0, X_b, W, th, x0, v0) + ta * _vf_phi(
                tau, mu, K, C, F0, X_b, W, th, x0, v0
            )
    return out


@compiled
def _accel(p, mass, t, x, v):
    """ẍ from the equation of motion: (P cos θ + Q sin θ − Cẋ − Kx)/mass (Eq. F1's left side)."""
    th = p[P_W] * t + p[P_PHI]
    P = p[P_F0] + p[P_K] * p[P_XB]
    Q = -p[P_C] * p[P_W] * p[P_XB]
    return (P * math.cos(th) + Q * math.sin(th) - p[P_C] * v - p[P_K] * x) / mass


@compiled
def _jerk(p, mass, t, x, v):
    """d³x/dt³, the derivative of :func:`_accel` along the flight."""
    th = p[P_W] * t + p[P_PHI]
    P = p[P_F0] + p[P_K] * p[P_XB]
    Q = -p[P_C] * p[P_W] * p[P_XB]
    a = _accel(p, mass, t, x, v)
    return (p[P_W] * (Q * math.cos(th) - P * math.sin(th)) - p[P_C] * a - p[P_K] * v) / mass


@compiled
def _accel_bound(p, mass, t0, x0, v0, span):
    """A ≥ |ẍ| over [t0, t0 + span] of the flight from (x0, v0) (module docstring)."""
    M, K, C, W = mass, p[P_K], p[P_C], p[P_W]
    P = p[P_F0] + K * p[P_XB]
    Q = -C * W * p[P_XB]
    wn2 = K / M
    sigma = C / (2.0 * M)
    wd = math.sqrt(wn2 - sigma * sigma)
    D = (K - M * W * W) ** 2 + (C * W) ** 2
    th = _phase(p, t0)
    if D > 1e-24 * K * K:
        A = _steady_cos(M, K, C, p[P_F0], p[P_XB], W)
        B = _steady_sin(M, K, C, p[P_F0], p[P_XB], W)
        xp = A * math.cos(th) + B * math.sin(th)
        vp = W * (B * math.cos(th) - A * math.sin(th))
        dx, dv = x0 - xp, v0 - vp
        R = math.sqrt(dx * dx + ((dv + sigma * dx) / wd) ** 2)
        bound = math.sqrt(A * A + B * B) * W * W + R * wn2
    else:  # at or next to the undamped resonance: the t-growing response
        g = (abs(P) + abs(Q)) / (2.0 * M * W)
        R = math.sqrt(x0 * x0 + ((abs(v0) + g) / math.sqrt(wn2)) ** 2)
        bound = R * wn2 + (abs(P) + abs(Q)) / M * (1.0 + W * span / 2.0)
    return bound * (1.0 + 1e-9) + 1e-300


@compiled
def _z(p, t0, x0, v0, z0, u0, tau):
    """z = y − x a time τ into the flight: z0 + u0·τ − (x(τ) − x0)."""
    x, _ = _state(p, p[P_M], t0, x0, v0, tau)
    return z0 + u0 * tau - (x - x0)


@compiled
def _held_off(p, t0, x0, v0, side, fd0, T):
    """A τ up to which the wall ``side`` just left cannot be reached: while side·ẍ ≥ 0 the
    relative coordinate f = side·z − d/2 is concave, and with f(0) = 0, f'(0) = fd0 ≤ 0 it stays
    negative.

    g = side·ẍ is certified non-negative with B ≥ |g''| = |d⁴x/dt⁴|, taken as 2·A·max(Ω, ω_n)²
    (A the acceleration bound: each part of the flight, oscillating at Ω or decaying at
    |−σ + iω_d| = ω_n, gains its frequency squared in two more derivatives; the 2 covers the
    t-growing part at resonance).  First from the start, g ≥ g(0) + g'(0)τ − Bτ²/2 up to the
    root of that bound (a release from sticking starts at g = 0 with g' > 0); then interval by
    interval, g ≥ min(g(τa), g(τb)) − B(τb − τa)²/8 on [τa, τb], intervals of 1/64 of the
    shorter period halved down to 1/4096 of it.  Returns the end of the certified stretch, at
    most one period (0 when g < 0 at once, beyond the rounding of a located release).  Sampling g alone is not enough: a flight that
    leaves a wall slowly while g is still negative, and turns positive within a sample, comes
    back to the wall."""
    M, K, C, W = p[P_M], p[P_K], p[P_C], p[P_W]
    wn = math.sqrt(K / M)
    wd = math.sqrt(K / M - C * C / (4 * M * M))
    period = 2.0 * math.pi / max(wd, W)
    span = min(T, period)
    A = _accel_bound(p, M, t0, x0, v0, span)
    B = 2.0 * A * max(W, wn) ** 2
    ga = side * _accel(p, M, t0, x0, v0)
    if ga < -1e-12 * A:
        return 0.0
    ga = max(ga, 0.0)  # a release from sticking, located where g = 0 to rounding
    g1 = side * _jerk(p, M, t0, x0, v0)
    tau = min((g1 + math.sqrt(g1 * g1 + 2.0 * B * ga)) / B, span)
    if tau > 0.0:
        x, v = _state(p, M, t0, x0, v0, tau)
        ga = side * _accel(p, M, t0 + tau, x, v)
    H = period / 64.0
    while tau < span:
        H = min(H, span - tau)
        tb = tau + H
        x, v = _state(p, M, t0, x0, v0, tb)
        gb = side * _accel(p, M, t0 + tb, x, v)
        if gb >= 0.0 and min(ga, gb) - B * H * H / 8.0 >= 0.0:
            tau, ga = tb, gb
            H = min(2.0 * H, period / 64.0)
        elif H > period / 4096.0:
            H *= 0.5
        else:
            return tau
    return tau


@compiled
def _next_impact(p, t0, x0, v0, z0, u0, side0, T, watch):
    """(τ, side): the first τ in (0, T] with abs(z) = d/2 in the flight from the state at t0, and
    its wall (+1 or −1); (T, 0) when there is none.  ``side0`` is the wall the flight starts on
    (0: none).  A signal seen on ``watch`` (:mod:`symimpact._interrupt`) ends the search at once
    with (τ so far, 0)."""
    h = p[P_h]
    M, K, C, W = p[P_M], p[P_K], p[P_C], p[P_W]
    wd = math.sqrt(K / M - C * C / (4 * M * M))
    hmax = 2.0 * math.pi / max(wd, W) / 16.0
    A = _accel_bound(p, M, t0, x0, v0, T)
    hmin = min(1e-6 * hmax, max(1e-12 * hmax, math.sqrt(8e-20 * h / A)))
    fd0 = side0 * (u0 - v0)  # rate at which the wall just left is approached (< 0: leaving)
    tau_safe = 0.0
    if side0 != 0 and fd0 <= 0.0:
        tau_safe = max(-2.0 * fd0 / A, _held_off(p, t0, x0, v0, side0, fd0, T))
    tau = 0.0
    za = z0
    H = hmax
    looks = 0
    while tau < T:
        looks += 1
        if (looks & (EVERY - 1)) == 0 and stop_requested(watch):
            return tau, 0
        H = min(H, T - tau)
        tb = tau + H
        zb = _z(p, t0, x0, v0, z0, u0, tb)
        slack = A * H * H / 8.0
        up = max(za, zb) + slack < h or (side0 == 1 and tb <= tau_safe)
        down = min(za, zb) - slack > -h or (side0 == -1 and tb <= tau_safe)
        if up and down:
            tau, za = tb, zb
            H = min(2.0 * H, hmax)
            continue
        if H > hmin and H > 4e-16 * tb:
            H *= 0.5
            continue
        if abs(zb) >= h:
            s = 1.0 if zb > 0 else -1.0
            lo, hi = tau, tb
            flo = min(s * za - h, 0.0)
            fhi = s * zb - h
            kept = 0
            for _ in range(200):
                den = fhi - flo
                tm = (lo * fhi - hi * flo) / den if den != 0.0 else 0.5 * (lo + hi)
                if not (lo < tm < hi):
                    tm = 0.5 * (lo + hi)
                fm = s * _z(p, t0, x0, v0, z0, u0, tm) - h
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
            return hi, int(s)
        tau, za = tb, zb  # an excursion shorter than hmin: below 1e-20 of the gap
        H = hmax
    return T, 0


@compiled
def _segment(p, mass, t0, x0, v0, tau, ledger, period_max, n_periods):
    """Account for the segment [t0, t0 + τ] of the primary (moving mass ``mass``): the work of
    the forcing and the dissipation of C (ledger[0], ledger[1]) and the largest abs(x) of every
    forcing period it crosses."""
    K, C, W, F0, Xb = p[P_K], p[P_C], p[P_W], p[P_F0], p[P_XB]
    T_f = 2.0 * math.pi / W
    wd = math.sqrt(K / mass - C * C / (4 * mass * mass))
    hq = 2.0 * math.pi / max(wd, W) / 16.0
    n = max(1, int(math.ceil(tau / hq)))  # noqa: RUF046 (int() spelled out for numba)
    hs = tau / n
    v_prev = v0
    for i in range(n):
        a = i * hs
        for j in range(8):
            s = a + 0.5 * hs * (1.0 + _GL_X[j])
            x, v = _state(p, mass, t0, x0, v0, s)
            th = p[P_W] * (t0 + s) + p[P_PHI]
            xb = Xb * math.cos(th)
            vb = -Xb * W * math.sin(th)
            rel = v - vb
            power_in = F0 * math.cos(th) * v - (K * (x - xb) + C * rel) * vb
            ledger[0] += 0.5 * hs * _GL_W[j] * power_in
            ledger[1] += 0.5 * hs * _GL_W[j] * C * rel * rel
        # extremes of x: the sub-interval's ends and any zero of ẋ inside
        b = (i + 1) * hs
        x_b, v_b = _state(p, mass, t0, x0, v0, b)
        k = int(math.floor((t0 + b) / T_f))  # noqa: RUF046 (int() spelled out for numba)
        if k < n_periods:
            period_max[k] = max(period_max[k], abs(x_b))
        if (v_prev > 0.0) != (v_b > 0.0) and v_prev != 0.0:
            lo, hi, flo, fhi = a, b, v_prev, v_b
            kept = 0
            for _ in range(100):
                tm = secant_point(lo, hi, flo, fhi)
                xm, vm = _state(p, mass, t0, x0, v0, tm)
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
            xm, _ = _state(p, mass, t0, x0, v0, 0.5 * (lo + hi))
            k = int(math.floor((t0 + 0.5 * (lo + hi)) / T_f))  # noqa: RUF046 (int() spelled out for numba)
            if k < n_periods:
                period_max[k] = max(period_max[k], abs(xm))
        v_prev = v_b


@compiled
def states_at(ev, times, initial, final_stuck, h, M, m, K, C, F0, X_b, W, phi):
    """The states (x, ẋ, z = y − x, ẏ) at ``times`` [s] of a run whose event log is ``ev``,
    started at ``initial`` (x, ẋ, y, ẏ) at t = 0: the closed-form flight (Eq. F1, the forcing
    phase Ω·t0 + φ of the last event before each time) from that event's state after it, with
    the mass M + m where the next event is a release (or the run ended stuck after the last);
    at an event's time, the state after it."""
    n = ev.shape[0]
    out = np.empty((times.shape[0], 4))
    for i in range(times.shape[0]):
        j = np.searchsorted(ev[:, E_T], times[i], side="right") - 1
        if j < 0:
            t0, x0, v0, stuck = 0.0, initial[0], initial[1], False
            z0, u0 = initial[2] - initial[0], initial[3]
        else:
            t0, x0, v0 = ev[j, E_T], ev[j, E_X], ev[j, E_XD1]
            z0, u0 = ev[j, E_SIDE] * h, ev[j, E_YD1]
            stuck = ev[j + 1, E_KIND] == KIND_RELEASE if j + 1 < n else final_stuck
        mass = M + m if stuck else M
        tau = times[i] - t0
        x = _xf(tau, mass, K, C, F0, X_b, W, W * t0 + phi, x0, v0)
        v = _vf(tau, mass, K, C, F0, X_b, W, W * t0 + phi, x0, v0)
        out[i, 0], out[i, 1] = x, v
        out[i, 2] = z0 if stuck else z0 + u0 * tau - (x - x0)
        out[i, 3] = v if stuck else u0
    return out


@compiled
def _grow(a, n):
    """``a`` if it has a row ``n``, else a copy with twice the rows."""
    if n < a.shape[0]:
        return a
    b = np.zeros((2 * a.shape[0] + 16, a.shape[1]))
    b[: a.shape[0]] = a
    return b


def _forget_stale_compilations() -> None:
    """This module's cached code, dropped when it or the forced-flight kernels changed."""
    from pathlib import Path

    from ...free._stepper import forget_stale_compilations

    forget_stale_compilations(_next_impact, [Path(__file__), Path(_fl.__file__)], ("_rigid.",))


_forget_stale_compilations()
