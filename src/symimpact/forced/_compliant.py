"""Forced simulation with a compliant contact (cubic, Hertz, linear, Hunt–Crossley).

Free flight is closed form and its contact onsets are found exactly as for rigid impacts
(:mod:`symimpact.forced._rigid`: Step 8's flight, Eq. F1, and its gap-free onset search).  A
contact phase, δ = s·z − d/2 > 0 on the wall s = ±1, is integrated by SciPy's DOP853 (rtol 1e-11)
with the forcing in the primary's equation,

    m ÿ = −s·F(δ, δ̇),  M ẍ = F0 cos θ − K(x − x_b) − C(ẋ − ẋ_b) + s·F(δ, δ̇),

and ends where δ returns to 0 (a located event).  The work of the forcing and the dissipation of
C and of the contact's damping are integrated with the motion, so the energy ledger closes.  The
state is recorded at ``samples`` points per forcing period (the Poincaré sections and the CSV).

This module is private: :mod:`symimpact.forced.simulation` validates the input.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from .. import _stepper
from . import _rigid

HUNT_CROSSLEY = "hunt-crossley"
#: DOP853's tolerances in contact: rtol 1e-11 (the closed-form flight carries ~1e-15; a tighter
#: rtol than ~1e-12 only adds steps), atol 1e-14 of the clearance (state components in m, m/s
#: scaled by the contact's own time scale would be finer than needed for a 1e-8 amplitude).
RTOL = 1e-11
#: The contacts' work budget in evaluations of the equations of motion (about 15 µs each, so a
#: minute or two): a typical contact takes 500–1000, so this is thousands of contacts; a run
#: that would need more (long, stiff contacts under an enormous force) stops and says so.
RHS_BUDGET = 5_000_000
TOO_MUCH_WORK = 2


class _OutOfWork(Exception):
    """Raised inside the integration when the run has spent :data:`RHS_BUDGET`."""


def _parts(law: str, q: np.ndarray, chi: float, delta: float, ddelta: float):
    """(elastic, damping) parts of the contact force [N] at penetration δ [m] and rate δ̇ [m/s]:
    the stepper's laws (Eq. 8, 9, 35) with c1·δ̇, or Hunt–Crossley k_hz·δ^1.5·(1 + χδ̇) (Eq. F4).
    ``q``: the stepper's parameter vector (:func:`symimpact._stepper.pack`)."""
    elastic = _stepper.contact_force(_stepper.LAWS[_base(law)], q, delta, 0.0)
    if law == HUNT_CROSSLEY:
        return elastic, elastic * chi * ddelta
    return elastic, q[_stepper.P_c1] * ddelta


def _base(law: str) -> str:
    """The stepper's elastic law under ``law`` (Hunt–Crossley's is Hertz's)."""
    return "hertz" if law == HUNT_CROSSLEY else law


def contact_potential(law: str, q: np.ndarray, delta: float) -> float:
    """Elastic energy stored in the contact at penetration δ [J] (the stepper's, by law)."""
    return _stepper.contact_potential(_stepper.LAWS[_base(law)], q, delta)


def run(law, q, chi, p, state0, t_end, max_events, samples):
    """Simulate from state0 = (x, ẋ, y, ẏ) at t = 0 to t_end; returns the rigid run's outputs
    (status, events, n_events, period_max, ledger = (forcing work, C's dissipation, contact's
    dissipation), final = (t, x, ẋ, y, ẏ, 1.0 if it ended in contact)) and the sampled states
    (n·samples + 1, 4): x, ẋ, z = y − x, ẏ at t = k·T/samples."""
    M, m, h = p[_rigid.P_M], p[_rigid.P_m], p[_rigid.P_h]
    K, C, W, F0, Xb, phi = (p[i] for i in (_rigid.P_K, _rigid.P_C, _rigid.P_W, _rigid.P_F0,
                                           _rigid.P_XB, _rigid.P_PHI))  # fmt: skip
    T_f = 2.0 * math.pi / W
    n_periods = round(t_end / T_f)  # a whole number of periods (floor may give one less)
    period_max = np.zeros(n_periods + 1)
    ledger = np.zeros(3)
    dt_s = T_f / samples
    n_samples = n_periods * samples + 1
    sampled = np.full((n_samples, 4), np.nan)
    events = []
    t, x, v, y, u = 0.0, *state0
    z = y - x
    side0 = 0
    in_contact = 0.0

    def fill_flight(t0, x0, v0, z0, u0, t1):
        k0 = max(0, math.ceil(t0 / dt_s - 1e-9))
        k1 = min(n_samples - 1, math.floor(t1 / dt_s + 1e-9))
        for k in range(k0, k1 + 1):
            if not np.isnan(sampled[k, 0]):
                continue
            tau = k * dt_s - t0
            xs, vs = _rigid._state(p, M, t0, x0, v0, tau)
            sampled[k] = (xs, vs, z0 + u0 * tau - (xs - x0), u0)

    spent = [0]

    def rhs(tt, s_, side):
        spent[0] += 1
        if spent[0] > RHS_BUDGET:
            raise _OutOfWork
        xx, vv, yy, uu = s_[0], s_[1], s_[2], s_[3]
        th = W * tt + phi
        xb, vb = Xb * math.cos(th), -Xb * W * math.sin(th)
        delta = side * (yy - xx) - h
        dd = side * (uu - vv)
        el, dm = _parts(law, q, chi, max(delta, 0.0), dd)
        F = el + dm
        rel = vv - vb
        a_x = (F0 * math.cos(th) - K * (xx - xb) - C * rel + side * F) / M
        a_y = -side * F / m
        power_in = F0 * math.cos(th) * vv - (K * (xx - xb) + C * rel) * vb
        return [vv, a_x, uu, a_y, power_in, C * rel * rel, dm * dd]

    while t < t_end:
        if len(events) + 2 > max_events:
            return _rigid.TOO_MANY_EVENTS, events, period_max, ledger, None, sampled
        tau, side = _rigid._next_impact(p, t, x, v, z, u, side0, t_end - t)
        _rigid._segment(p, M, t, x, v, tau, ledger, period_max, n_periods)
        fill_flight(t, x, v, z, u, t + tau)
        xn, vn = _rigid._state(p, M, t, x, v, tau)
        z = z + u * tau - (xn - x)
        t, x, v = t + tau, xn, vn
        if side == 0:
            break
        s = float(side)
        z = s * h
        y = x + z
        vrel = s * (u - v)

        def exit_(tt, s_, side=s):
            return side * (s_[2] - s_[0]) - h

        exit_.terminal, exit_.direction = True, -1
        scale = max(abs(vrel), abs(v), abs(u), 1e-300)
        energy = 0.5 * (M * v * v + m * u * u) + 0.5 * K * x * x + 1e-300
        try:
            sol = _contact_phase(rhs, t, t_end, [x, v, y, u], s, h, scale, energy, exit_)
        except _OutOfWork:
            return TOO_MUCH_WORK, events, period_max, ledger, None, sampled
        t_exit = float(sol.t_events[0][0]) if len(sol.t_events[0]) else float(sol.t[-1])
        end = sol.sol(t_exit) if len(sol.t_events[0]) else sol.y[:, -1]
        # extremes of x in contact: the steps' ends and the zeros of ẋ between them
        grid = np.append(sol.t[sol.t < t_exit], t_exit)
        vals = sol.sol(grid)
        for i, tt in enumerate(grid):
            kk = math.floor(tt / T_f)
            if kk < n_periods:
                period_max[kk] = max(period_max[kk], abs(float(vals[0, i])))
            if i and (vals[1, i - 1] > 0) != (vals[1, i] > 0):
                dense = sol.sol
                tm = brentq(
                    lambda s2, f=dense: f(s2)[1], grid[i - 1], tt, xtol=1e-15 * max(1.0, tt)
                )
                kk = math.floor(tm / T_f)
                if kk < n_periods:
                    period_max[kk] = max(period_max[kk], abs(float(sol.sol(tm)[0])))
        k0 = max(0, math.ceil(t / dt_s - 1e-9))
        k1 = min(n_samples - 1, math.floor(t_exit / dt_s + 1e-9))
        for k in range(k0, k1 + 1):
            st = sol.sol(k * dt_s)
            sampled[k] = (st[0], st[1], st[2] - st[0], st[3])
        ledger[0] += end[4]
        ledger[1] += end[5]
        ledger[2] += end[6]
        events.append((t, x, v, u, s, vrel, end[6], _rigid.KIND_IMPACT, end[1], end[3]))
        t, x, v, y, u = t_exit, end[0], end[1], end[2], end[3]
        if not len(sol.t_events[0]):
            in_contact = 1.0
            z = y - x
            break
        z = s * h
        side0 = side
    # the end of the run inside a flight: fill the last sample
    final = np.array([t, x, v, x + z, u, in_contact])
    ev = np.array(events, dtype=float).reshape(-1, _rigid.N_EVENT_COLS)
    return _rigid.OK, ev, period_max, ledger, final, sampled


def _contact_phase(rhs, t, t_end, state, side, h, scale, energy, exit_):
    """One contact phase from ``t`` (at most to ``t_end``) by DOP853, with the forcing's work and
    the dissipations integrated alongside (three more components), ended by ``exit_``."""
    return solve_ivp(
        rhs,
        (t, t_end),
        [*state, 0.0, 0.0, 0.0],
        method="DOP853",
        rtol=RTOL,
        atol=[1e-14 * h, 1e-14 * scale, 1e-14 * h, 1e-14 * scale, *(3 * [1e-14 * energy])],
        events=exit_,
        dense_output=True,
        args=(side,),
    )
