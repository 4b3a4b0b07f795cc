"""The baseline a competent user writes in an afternoon: numba, scipy's DOP853 tableau, one
right-hand side switched by the contact state, events found at the ends of steps and refined by
re-stepping (Illinois regula falsi), the step capped so that a grazing impact is not stepped over.

Not part of the package: :mod:`benchmarks.stepper_peers` times it against the package's stepper,
each tuned to the same impact-time accuracy.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit
from scipy.integrate._ivp import dop853_coefficients as _dc

A = np.ascontiguousarray(_dc.A[: _dc.N_STAGES, : _dc.N_STAGES])
B = np.ascontiguousarray(_dc.B)
E3 = np.ascontiguousarray(_dc.E3)
E5 = np.ascontiguousarray(_dc.E5)
STAGES = _dc.N_STAGES


@njit(cache=True)
def _rhs(q, mode, u):
    """q = (M, K, C, m, h, a, b, c1); mode 0 free flight, ±1 in contact on that side."""
    M, K, C, m, h, a, b, c1 = q[0], q[1], q[2], q[3], q[4], q[5], q[6], q[7]
    x, xd, y, yd = u[0], u[1], u[2], u[3]
    f = 0.0
    if mode != 0:
        d = mode * (y - x) - h
        dd = mode * (yd - xd)
        f = a * d * d * d + b * d + c1 * dd
    return xd, (mode * f - C * xd - K * x) / M, yd, -mode * f / m


@njit(cache=True)
def _step(q, mode, u, f0, hh, K, rtol, atol):
    """One DOP853 step (scipy's coefficients and error norm): (u_new, error norm)."""
    for i in range(4):
        K[0, i] = f0[i]
    tmp = np.empty(4)
    for s in range(1, STAGES):
        for i in range(4):
            acc = 0.0
            for j in range(s):
                acc += A[s, j] * K[j, i]
            tmp[i] = u[i] + hh * acc
        r = _rhs(q, mode, tmp)
        for i in range(4):
            K[s, i] = r[i]
    un = np.empty(4)
    for i in range(4):
        acc = 0.0
        for j in range(STAGES):
            acc += B[j] * K[j, i]
        un[i] = u[i] + hh * acc
    r = _rhs(q, mode, un)
    for i in range(4):
        K[STAGES, i] = r[i]
    e5 = 0.0
    e3 = 0.0
    for i in range(4):
        sc = atol[i] + rtol * max(abs(u[i]), abs(un[i]))
        a5 = 0.0
        a3 = 0.0
        for j in range(STAGES + 1):
            a5 += E5[j] * K[j, i]
            a3 += E3[j] * K[j, i]
        e5 += (a5 / sc) ** 2
        e3 += (a3 / sc) ** 2
    if e5 == 0.0 and e3 == 0.0:
        return un, 0.0
    return un, abs(hh) * e5 / math.sqrt((e5 + 0.01 * e3) * 4)


@njit(cache=True)
def _g(q, mode, u, side):
    """Event function: in free flight side·(y − x) − h (crosses upward at an onset); in contact
    the penetration (crosses downward at the release)."""
    return side * (u[2] - u[0]) - q[4]


@njit(cache=True)
def simulate(q, state0, t_end, rtol, atol, max_step, rest, out_times):
    """Impact onset times into ``out_times``; returns their count (−1 if the buffer filled).

    Stops, as the package does, at an onset that finds less than ``rest`` × the initial energy.
    """
    M, K_, m = q[0], q[1], q[3]
    u = state0.copy()
    Kst = np.empty((STAGES + 1, 4))
    f0 = np.empty(4)
    t = 0.0
    mode = 0
    n = 0
    e0 = 0.5 * M * u[1] ** 2 + 0.5 * K_ * u[0] ** 2 + 0.5 * m * u[3] ** 2
    hh = max_step * 0.01
    while t < t_end:
        r = _rhs(q, mode, u)
        for i in range(4):
            f0[i] = r[i]
        hh = min(hh, t_end - t, max_step)
        un, err = _step(q, mode, u, f0, hh, Kst, rtol, atol)
        if err > 1.0:
            hh *= max(0.2, 0.9 * err ** (-1.0 / 8.0))
            continue
        # events at the end of the step
        hit = 0.0
        if mode == 0:
            for side in (1.0, -1.0):
                if _g(q, mode, un, side) > 0.0 and _g(q, mode, u, side) <= 0.0:
                    hit = side
        elif _g(q, mode, un, mode) < 0.0:
            hit = mode
        if hit != 0.0:
            lo, hi = 0.0, hh
            glo, ghi = _g(q, mode, u, hit), _g(q, mode, un, hit)
            kept = 0
            for _ in range(100):
                th = (lo * ghi - hi * glo) / (ghi - glo)
                if not (lo < th < hi):
                    th = 0.5 * (lo + hi)
                um, _e = _step(q, mode, u, f0, th, Kst, rtol, atol)
                gm = _g(q, mode, um, hit)
                if (gm > 0.0) == (glo > 0.0):
                    lo, glo = th, gm
                    if kept == -1:
                        ghi *= 0.5
                    kept = -1
                else:
                    hi, ghi = th, gm
                    if kept == 1:
                        glo *= 0.5
                    kept = 1
                if hi - lo <= 1e-15 * max(t, 1e-3):
                    break
            un, _e = _step(q, mode, u, f0, hi, Kst, rtol, atol)
            t += hi
            for i in range(4):
                u[i] = un[i]
            if mode == 0:
                e = 0.5 * M * u[1] ** 2 + 0.5 * K_ * u[0] ** 2 + 0.5 * m * u[3] ** 2
                if e < rest * e0:
                    return n
                if n == out_times.shape[0]:
                    return -1
                out_times[n] = t
                n += 1
                mode = int(hit)
                u[2] = u[0] + hit * q[4]
            else:
                mode = 0
                u[2] = u[0] + hit * q[4]
            hh = max_step * 1e-3
            continue
        t += hh
        for i in range(4):
            u[i] = un[i]
        hh *= min(10.0, 0.9 * max(err, 1e-12) ** (-1.0 / 8.0))
    return n


def impact_times(system, state, t_end, rtol, rest=1e-12, cap_per_period=200):
    """Onset times [s] of ``system`` (an ImpactSystem with the cubic law) from ``state``."""
    q = np.array(
        [system.M, system.K, system.C, system.m, 0.5 * system.gap, system.a, system.b, system.c1]
    )
    period = 2 * math.pi / math.sqrt(system.K / system.M)
    scale_x = max(0.5 * system.gap, abs(state[0]), abs(state[2]))
    scale_v = max(abs(state[1]), abs(state[3]))
    atol = np.array([scale_x, scale_v, scale_x, scale_v]) * rtol * 1e-3
    out = np.empty(100_000)
    n = simulate(q, np.asarray(state, float), t_end, rtol, atol, period / cap_per_period, rest, out)
    return out[:n].copy()
