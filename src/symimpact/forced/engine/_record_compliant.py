"""Compiled simulation of the primary and its impact damper with a compliant contact (cubic,
Hertz, linear, Hunt–Crossley) under a sampled load (numba, cached).

Flights are those of :mod:`symimpact.forced.engine._record_rigid`: on each interval of the record the
load is a straight line and the primary follows Step 16's flight (Eq. F8) in closed form, the
impact mass moves with the base's acceleration taken out, and the next contact onset (abs(z) =
d/2) is found by the same certified search.  A contact phase, δ = s·z − d/2 > 0 on the wall
s = ±1, is integrated by the Dormand–Prince 5(4) pair of the harmonic compliant engine
(:mod:`symimpact.forced.engine._compliant`, its tableau and its contact laws), with the record's
straight line in the primary's equation (relative to the base under a base acceleration a_b):

    m ÿ = −m·g − s·F(δ, δ̇),  M ẍ = p − K x − C ẋ + s·F(δ, δ̇),

with p the force and g = 0, or p = −Γ·M·a_b and g = a_b (Γ the primary's participation in the base's
motion, :data:`~symimpact.forced.engine._record_rigid.P_GAMMA`). Its steps end at the record's
samples (the load has a kink there) and the contact ends where δ returns to 0, located by
re-stepping from the step's start (Illinois regula falsi). The load's work, C's dissipation and the
contact's damping are integrated with the motion, so the energy ledger closes.

This module is private: :mod:`symimpact.forced.loads.record_response` validates the input.
"""

from __future__ import annotations

import math

import numpy as np

from ..._compiled import compiled
from ..._interrupt import EVERY, INTERRUPTED, stop_requested
from ...free import _stepper
from . import _compliant as _cp
from . import _record_rigid as _rr

#: the contact's Runge–Kutta tolerance (that of the harmonic compliant engine, same reasons)
RTOL = _cp.RTOL
OK, TOO_MANY_EVENTS, TOO_MANY_STEPS, STEP_UNDERFLOW = 0, 1, 3, 4
MAX_CONTACT_STEPS = _cp.MAX_CONTACT_STEPS
NW = 7  # x, ẋ, y, ẏ (relative to the base under a base acceleration); work, C's, contact's


@compiled
def _rhs(code, q, chi, p, side, q0, qd, s, w, out):
    """The contact's equations (module docstring) s into the piece whose record line is
    q0 + qd·s, and the ledger's rates."""
    M, m, K, C, h = p[_rr.P_M], p[_rr.P_m], p[_rr.P_K], p[_rr.P_C], p[_rr.P_h]
    x, v, y, u = w[0], w[1], w[2], w[3]
    load = q0 + qd * s
    delta = side * (y - x) - h
    dd = side * (u - v)
    F, _, _, damp = _cp._force(code, q, chi, delta, dd)
    if p[_rr.P_BASE] != 0.0:  # the primary's inertia load −Γ·M·a_b (Γ its participation)
        GM = p[_rr.P_GAMMA] * M
        out[1] = (-GM * load - K * x - C * v + side * F) / M
        out[3] = -load - side * F / m
        out[4] = -load * (GM * v + m * u)
    else:
        out[1] = (load - K * x - C * v + side * F) / M
        out[3] = -side * F / m
        out[4] = load * v
    out[0] = v
    out[2] = u
    out[5] = C * v * v
    out[6] = damp * dd


@compiled
def _step(code, q, chi, p, side, q0, qd, s, w, k, h, tmp, out, kout, atol):
    """One Dormand–Prince step of length h from w at s (k[0] = f there, kept): the state after it
    into ``out``, f there into ``kout``; returns the error norm of the motion."""
    for st in range(1, 6):
        for i in range(NW):
            acc = 0.0
            for j in range(st):
                acc += _cp._DP_A[st, j] * k[j, i]
            tmp[i] = w[i] + h * acc
        _rhs(code, q, chi, p, side, q0, qd, s + _cp._DP_C[st] * h, tmp, k[st])
    for i in range(NW):
        acc = 0.0
        for j in range(6):
            acc += _cp._DP_B[j] * k[j, i]
        out[i] = w[i] + h * acc
    _rhs(code, q, chi, p, side, q0, qd, s + h, out, kout)
    err = 0.0
    for i in range(4):
        acc = _cp._DP_E[6] * kout[i]
        for j in range(6):
            acc += _cp._DP_E[j] * k[j, i]
        sc = atol[i] + RTOL * max(abs(w[i]), abs(out[i]))
        err += (h * acc / sc) ** 2
    return math.sqrt(err / 4.0)


@compiled
def _exit(code, q, chi, p, side, q0, qd, s, w, k, h_hi, g_lo, g_hi, tmp, out, kout, atol):
    """The θ in (0, h_hi] at which δ returns to 0 on the step from w at s (re-stepped with the
    shorter length; Illinois regula falsi, bisecting until a point inside is found when the step
    starts at δ = 0); ``out`` holds the state there.  Returns θ."""
    lo, hi = 0.0, h_hi
    flo, fhi = g_lo, g_hi
    unknown = flo <= 0.0
    if unknown:
        flo = 1.0
    kept = 0
    for _ in range(200):
        theta = 0.5 * (lo + hi) if unknown else _stepper.secant_point(lo, hi, flo, fhi)
        _step(code, q, chi, p, side, q0, qd, s, w, k, theta, tmp, out, kout, atol)
        g = side * (out[2] - out[0]) - p[_rr.P_h]
        if unknown:
            if g > 0.0:
                unknown = False
                lo, flo = theta, g
            else:
                hi, fhi = theta, g
            continue
        if g == 0.0:
            return theta
        if g > 0.0:
            lo, flo = theta, g
            if kept == -1:
                fhi *= 0.5
            kept = -1
        else:
            hi, fhi = theta, g
            if kept == 1:
                flo *= 0.5
            kept = 1
        if hi - lo <= 4e-16 * (s + hi):
            break
    _step(code, q, chi, p, side, q0, qd, s, w, k, hi, tmp, out, kout, atol)
    return hi


@compiled
def _contact(code, q, chi, p, side, q0, qd, w, L, h, atol, counts):
    """The contact on ``side`` from w (state and ledger) at the start of a piece of length L
    whose record line is q0 + qd·s, to its end δ = 0 or to L.  w is updated in place.  Returns
    (status, s reached, ended, the next step length); counts[0] counts the run's steps,
    counts[1] this contact's (reset at its onset)."""
    k = np.zeros((6, NW))
    kout = np.zeros(NW)
    tmp = np.zeros(NW)
    out = np.zeros(NW)
    ev_out = np.zeros(NW)
    ev_k = np.zeros(NW)
    s = 0.0
    _rhs(code, q, chi, p, side, q0, qd, s, w, k[0])
    while True:
        if L - s <= 0.0:
            return OK, L, False, h
        counts[0] += 1
        counts[1] += 1
        if counts[1] > MAX_CONTACT_STEPS:
            return TOO_MANY_STEPS, s, False, h
        last = h >= L - s
        hs = L - s if last else h
        if hs < 1e-15 * max(L, 1e-3) and not last:
            return STEP_UNDERFLOW, s, False, h
        err = _step(code, q, chi, p, side, q0, qd, s, w, k, hs, tmp, out, kout, atol)
        if err > 1.0 or not math.isfinite(err):
            h = hs * (0.2 if not math.isfinite(err) else max(0.2, 0.9 * err**-0.2))
            continue
        d_old = side * (w[2] - w[0]) - p[_rr.P_h]
        d_new = side * (out[2] - out[0]) - p[_rr.P_h]
        ended = d_new < 0.0
        taken = hs
        if not ended:
            # both ends in contact: does δ dip below zero inside the step?
            dip, s_dip = _stepper._hermite_min(
                d_old, d_new, hs * side * (w[3] - w[1]), hs * side * (out[3] - out[1])
            )
            if dip < 0.0:
                _step(code, q, chi, p, side, q0, qd, s, w, k, s_dip * hs, tmp, ev_out, ev_k,
                      atol)  # fmt: skip
                d_dip = side * (ev_out[2] - ev_out[0]) - p[_rr.P_h]
                if d_dip < 0.0:
                    ended = True
                    taken = _exit(code, q, chi, p, side, q0, qd, s, w, k, s_dip * hs, d_old,
                                  d_dip, tmp, out, kout, atol)  # fmt: skip
        else:
            taken = _exit(code, q, chi, p, side, q0, qd, s, w, k, hs, d_old, d_new, tmp, out,
                          kout, atol)  # fmt: skip
        for i in range(NW):
            w[i] = out[i]
            k[0, i] = kout[i]
        s = L if last and not ended else s + taken
        nxt = hs * min(5.0, max(0.2, 0.9 * max(err, 1e-10) ** -0.2))
        if ended:
            return OK, s, True, nxt
        if not last:
            h = nxt


@compiled
def run(code, q, chi, p, rec, dt, state0, max_events, watch):
    """Simulate from state0 = (x, ẋ, z, ẏ) at t = 0 (relative to the base under a base
    acceleration; z = y − x; a start inside a wall starts a contact) over the record ``rec``
    sampled every ``dt`` (or until a signal is seen on ``watch``: status INTERRUPTED).

    Returns (status, samples, events, n_events, ledger, n_done, steps): (x, ẋ, z, ẏ) at every
    sample, the contact onsets (columns of :mod:`._record_rigid`'s log: time, side, approach
    speed), ledger = (work of the load, dissipation by C, dissipation in the contacts), the
    number of samples reached and the contacts' Runge–Kutta steps."""
    M, h = p[_rr.P_M], p[_rr.P_h]
    n = rec.shape[0]
    out = np.zeros((n, 4))
    events = np.zeros((64, _rr.N_EVENT_COLS))
    ledger = np.zeros(3)
    n_ev = 0
    x, v, z, u = state0[0], state0[1], state0[2], state0[3]
    out[0, 0], out[0, 1], out[0, 2], out[0, 3] = x, v, z, u
    side = 0
    if abs(z) > h:
        side = 1 if z > 0 else -1  # a start inside a wall: in contact
    in_contact = side != 0
    side0 = 0  # the wall a flight starts on (after a contact's end)
    w = np.zeros(NW)
    counts = np.zeros(2, dtype=np.int64)
    scale_x = max(h, 1e-300)
    status = OK
    hstep = 0.0
    looks = 0
    done = 1
    for i in range(n - 1):
        qd = (rec[i + 1] - rec[i]) / dt
        tau = 0.0
        while tau < dt:
            looks += 1
            if (looks & (EVERY - 1)) == 0 and stop_requested(watch):
                status = INTERRUPTED
                break
            L = dt - tau
            q0 = rec[i] + qd * tau
            if in_contact:
                w[0], w[1], w[2], w[3] = x, v, x + z, u
                w[4], w[5], w[6] = 0.0, 0.0, 0.0
                if hstep <= 0.0:  # the contact's onset
                    counts[1] = 0
                    speed = max(abs(u - v), math.sqrt(max(z * z - h * h, 0.0)) / dt, 1e-300)
                    hstep = min(L, 0.01 * _stepper._penetration_scale(
                        _stepper.HERTZ if code == _cp.HC else code, q, speed) / speed)  # fmt: skip
                vs = max(abs(v), abs(u), abs(u - v), 1e-300)
                atol = np.array([1e-14 * scale_x, 1e-14 * vs, 1e-14 * scale_x, 1e-14 * vs])
                st, s, ended, hstep = _contact(code, q, chi, p, side, q0, qd, w, L, hstep,
                                               atol, counts)  # fmt: skip
                if st != OK:
                    status = st
                    break
                ledger[0] += w[4]
                ledger[1] += w[5]
                ledger[2] += w[6]
                x, v, z, u = w[0], w[1], w[2] - w[0], w[3]
                if not ended:
                    break  # the piece's end: the next sample
                tau += s
                z = side * h
                in_contact = False
                side0 = side
                hstep = 0.0
                continue
            p0, pd, g0, gd = _rr._loads(p, M, q0, qd)
            s, hit = _rr._next_impact(p, M, p0, pd, g0, gd, x, v, z, u, side0, L)
            _rr._account(p, M, False, p0, pd, g0, gd, x, v, u, s, ledger)
            xn, vn = _rr._ramp(s, M, p[_rr.P_K], p[_rr.P_C], p0, pd, x, v)
            zn = _rr._z(M, p[_rr.P_K], p[_rr.P_C], p0, pd, g0, gd, x, v, z, u, s)
            u = u + g0 * s + 0.5 * gd * s * s
            x, v, z = xn, vn, zn
            if hit == 0:
                side0 = 0
                if abs(z) >= h:  # within the search's 1e-20 of the clearance: on the wall
                    side0 = 1 if z > 0 else -1
                    z = side0 * h
                break
            if n_ev + 1 > max_events:
                status = TOO_MANY_EVENTS
                break
            tau += s
            side = hit
            z = side * h
            events = _rr._grow(events, n_ev)
            events[n_ev, _rr.E_T], events[n_ev, _rr.E_SIDE] = i * dt + tau, side
            events[n_ev, _rr.E_VREL] = side * (u - v)
            events[n_ev, _rr.E_KIND] = _rr.KIND_IMPACT
            n_ev += 1
            in_contact = True
        if status != OK:
            break
        out[i + 1, 0], out[i + 1, 1], out[i + 1, 2], out[i + 1, 3] = x, v, z, u
        done = i + 2
    return status, out, events, n_ev, ledger, done, counts[0]
