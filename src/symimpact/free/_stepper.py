"""Compiled event-driven stepper (numba, cached on disk): free flight in closed form, contact
integrated by an embedded Runge–Kutta 5(4) pair (Dormand–Prince) with located events.

Free flight (Eq. 7) uses the generated ``*_scalar`` kernels compiled by numba.  The onset of
contact, |y − x| = d/2, is found without sampling gaps: on [τa, τb] the relative displacement
z = y − x obeys |z''| = |ẍ| ≤ A_max (Cauchy–Schwarz on the main mass's energy, which free flight
never increases), so max z ≤ max(z_a, z_b) + A_max·(τb − τa)²/8.  An interval that this bound
clears is skipped; one that it does not clear is halved, down to a resolution below which a
missed excursion would be shorter than 1e-20 of the gap.  Crossings are then bracketed and refined.

Contact (Eq. 10 with the chosen law) is integrated step by step.  Its end δ = 0, and the maxima of
x (for Eq. 36), are located by re-stepping from the start of the step with a shorter step until
the event function vanishes (Illinois regula falsi), so located states carry the integrator's
full accuracy.  Dissipation by C and c₁ is integrated with the motion for the energy balance.

This module is private: :mod:`symimpact.free.simulation` validates the input and builds the result.
"""

from __future__ import annotations

import math

import numpy as np

from .._compiled import compiled
from .._interrupt import EVERY, INTERRUPTED, stop_requested
from ..generated import free_flight as _ff
from ..generated import multiple_scales as _ms

CUBIC, HERTZ, LINEAR, PERTURBATION = 0, 1, 2, 3
LAWS = {"cubic": CUBIC, "hertz": HERTZ, "linear": LINEAR, "perturbation": PERTURBATION}
# parameter vector layout
(P_M, P_K, P_C, P_m, P_h, P_a, P_b, P_khz, P_k1, P_c1, P_ba, P_rtol, P_atolx, P_atolv, P_rest) = (
    range(15)
)
N_PARAMS = 15
# impact-log columns
(
    I_T,
    I_X,
    I_XD,
    I_Y,
    I_YD,
    I_SIDE,
    I_TOFF,
    I_XOFF,
    I_XDOFF,
    I_YOFF,
    I_YDOFF,
    I_EON,
    I_EOFF,
    I_DC1,
    I_DC,
    I_DONE,
) = range(16)
N_IMPACT_COLS = 16
# trace columns: t, x, xd, y, yd, xdd, ydd, kind (0: free flight from here, 1: contact point,
# 2: at rest from here)
N_TRACE_COLS = 8
# status codes
OK, FULL_IMPACTS, STEP_UNDERFLOW, NO_CONVERGENCE, AT_REST, TOO_MANY_STEPS = range(6)
# a contact of a sane system takes tens to hundreds of steps; this many means a time scale the
# integrator cannot bridge (e.g. a contact 1e-15 of the main period)
MAX_CONTACT_STEPS = 100_000
STATUS_TEXT = {
    STEP_UNDERFLOW: "step size underflow (stiff or singular contact); check the contact law "
    "parameters",
    TOO_MANY_STEPS: f"more than {MAX_CONTACT_STEPS:,} steps in one contact: its time scale is "
    "out of proportion to the motion (check the masses, the gap and the contact stiffness)",
}
# what ends a free flight
ONSET_CONTACT, ONSET_NONE, ONSET_REST = 0, 1, 2

_x_ff = compiled(_ff.main_mass_displacement_scalar)
_xd_ff = compiled(_ff.main_mass_velocity_scalar)
_T_map = compiled(_ms.contact_duration_map_scalar)
_T_start = compiled(_ms.contact_duration_start_scalar)
_z_pert = compiled(_ms.relative_displacement_scalar)
_zd_pert = compiled(_ms.relative_velocity_scalar)

# Dormand–Prince 5(4) tableau
_C2, _C3, _C4, _C5 = 1 / 5, 3 / 10, 4 / 5, 8 / 9
_A21 = 1 / 5
_A31, _A32 = 3 / 40, 9 / 40
_A41, _A42, _A43 = 44 / 45, -56 / 15, 32 / 9
_A51, _A52, _A53, _A54 = 19372 / 6561, -25360 / 2187, 64448 / 6561, -212 / 729
_A61, _A62, _A63, _A64, _A65 = 9017 / 3168, -355 / 33, 46732 / 5247, 49 / 176, -5103 / 18656
_B1, _B3, _B4, _B5, _B6 = 35 / 384, 500 / 1113, 125 / 192, -2187 / 6784, 11 / 84
_E1, _E3, _E4, _E5, _E6, _E7 = (
    71 / 57600,
    -71 / 16695,
    71 / 1920,
    -17253 / 339200,
    22 / 525,
    -1 / 40,
)
NV = 6  # x, ẋ, y, ẏ, ∫Cẋ², ∫c₁δ̇²


def pack(system, rtol, atol_x, atol_v, ba=0.0, free=False, rest_energy=0.0):
    """The stepper's parameter vector for an ImpactSystem (SI floats; ``free`` drops K and C).

    ``rest_energy`` [J]: a contact whose onset finds less mechanical energy in the system ends
    the run (status AT_REST); 0 never does."""
    p = np.zeros(N_PARAMS)
    p[P_M] = system.M
    p[P_K] = 0.0 if free else system.K
    p[P_C] = 0.0 if free else system.C
    p[P_m] = system.m
    p[P_h] = 0.5 * system.gap
    p[P_a] = system.a or 0.0
    p[P_b] = system.b or 0.0
    p[P_khz] = system.k_hz or 0.0
    p[P_k1] = system.k1 or 0.0
    p[P_c1] = system.c1
    p[P_ba] = ba
    p[P_rtol] = rtol
    p[P_atolx] = atol_x
    p[P_atolv] = atol_v
    p[P_rest] = rest_energy
    return p


@compiled
def contact_force(law: int, p: np.ndarray, delta: float, ddelta: float) -> float:
    """Force pushing the masses apart at penetration δ and rate δ̇ (Eq. 8, 9, 35 + c₁δ̇)."""
    if law == HERTZ:
        fe = p[P_khz] * max(delta, 0.0) ** 1.5
    elif law == LINEAR:
        fe = p[P_k1] * delta
    else:
        fe = (p[P_a] * delta * delta + p[P_b]) * delta
    return fe + p[P_c1] * ddelta


@compiled
def contact_potential(law: int, p: np.ndarray, delta: float) -> float:
    """Elastic energy stored in the contact at penetration δ ≥ 0."""
    if delta <= 0.0:
        return 0.0
    if law == HERTZ:
        return 0.4 * p[P_khz] * delta**2.5
    if law == LINEAR:
        return 0.5 * p[P_k1] * delta * delta
    return 0.25 * p[P_a] * delta**4 + 0.5 * p[P_b] * delta * delta


@compiled
def _hermite_min(y0: float, y1: float, m0: float, m1: float) -> tuple[float, float]:
    """(least value, where) of the cubic with values y0, y1 and slopes m0, m1 at 0 and 1 over its
    interior critical points in (0, 1); (inf, -1) when it has none (the ends are the caller's)."""
    a1 = m0
    a2 = -3.0 * y0 - 2.0 * m0 + 3.0 * y1 - m1
    a3 = 2.0 * y0 + m0 - 2.0 * y1 + m1
    lowest, where = math.inf, -1.0
    # H'(s) = 3a3·s² + 2a2·s + a1
    qa, qb, qc = 3.0 * a3, 2.0 * a2, a1
    if qa == 0.0:
        roots = (-qc / qb if qb != 0.0 else -1.0, -1.0)
    else:
        disc = qb * qb - 4.0 * qa * qc
        if disc < 0.0:
            return lowest, where
        sq = math.sqrt(disc)
        roots = ((-qb - sq) / (2.0 * qa), (-qb + sq) / (2.0 * qa))
    for r in roots:
        if 0.0 < r < 1.0:
            value = ((a3 * r + a2) * r + a1) * r + y0
            if value < lowest:
                lowest, where = value, r
    return lowest, where


@compiled
def _penetration_scale(law: int, p: np.ndarray, v: float) -> float:
    """Largest penetration [m] of an undamped contact of the free pair (reduced mass
    μ = mM/(m + M)) at approach speed v: the contact potential equals ½μv²."""
    mu = p[P_m] * p[P_M] / (p[P_m] + p[P_M])
    e = 0.5 * mu * v * v
    if law == HERTZ:
        return (2.5 * e / p[P_khz]) ** 0.4
    if law == LINEAR:
        return math.sqrt(2.0 * e / p[P_k1])
    a, b = p[P_a], p[P_b]  # a/4·δ⁴ + b/2·δ² = e, a quadratic in δ²
    if a > 0.0:
        return math.sqrt(4.0 * e / (b + math.sqrt(b * b + 4.0 * a * e)))
    return math.sqrt(2.0 * e / b)


@compiled
def _f(law, p, side, x, xd, y, yd):
    """Right-hand side of Eq. 10 in contact on ``side`` as a 6-tuple: ẋ, ẍ, ẏ, ÿ and the
    dissipation rates Cẋ², c₁δ̇² (scalars, no arrays: the step stays in registers)."""
    delta = side * (y - x) - p[P_h]
    ddelta = side * (yd - xd)
    f = contact_force(law, p, delta, ddelta)
    return (
        xd,
        (side * f - p[P_C] * xd - p[P_K] * x) / p[P_M],
        yd,
        -side * f / p[P_m],
        p[P_C] * xd * xd,
        p[P_c1] * ddelta * ddelta,
    )


@compiled
def _stage2(u, h, k1):
    return u + h * _A21 * k1


@compiled
def _stage3(u, h, k1, k2):
    return u + h * (_A31 * k1 + _A32 * k2)


@compiled
def _stage4(u, h, k1, k2, k3):
    return u + h * (_A41 * k1 + _A42 * k2 + _A43 * k3)


@compiled
def _stage5(u, h, k1, k2, k3, k4):
    return u + h * (_A51 * k1 + _A52 * k2 + _A53 * k3 + _A54 * k4)


@compiled
def _stage6(u, h, k1, k2, k3, k4, k5):
    return u + h * (_A61 * k1 + _A62 * k2 + _A63 * k3 + _A64 * k4 + _A65 * k5)


@compiled
def _stage7(u, h, k1, k3, k4, k5, k6):
    return u + h * (_B1 * k1 + _B3 * k3 + _B4 * k4 + _B5 * k5 + _B6 * k6)


@compiled
def _err(h, k1, k3, k4, k5, k6, k7, u, unew, atol, rtol):
    e = h * (_E1 * k1 + _E3 * k3 + _E4 * k4 + _E5 * k5 + _E6 * k6 + _E7 * k7)
    sc = atol + rtol * max(abs(u), abs(unew))
    return (e / sc) ** 2


@compiled
def _dp_step(law, p, side, u, k1, h):
    """One Dormand–Prince step of length h from the 6-tuple state u with k1 = f(u).

    Returns (unew, k7 = f(unew), error norm), all in scalars and tuples (the state, the stages
    and the error stay in registers; no array is allocated per step)."""
    k2 = _f(
        law,
        p,
        side,
        _stage2(u[0], h, k1[0]),
        _stage2(u[1], h, k1[1]),
        _stage2(u[2], h, k1[2]),
        _stage2(u[3], h, k1[3]),
    )
    k3 = _f(
        law,
        p,
        side,
        _stage3(u[0], h, k1[0], k2[0]),
        _stage3(u[1], h, k1[1], k2[1]),
        _stage3(u[2], h, k1[2], k2[2]),
        _stage3(u[3], h, k1[3], k2[3]),
    )
    k4 = _f(
        law,
        p,
        side,
        _stage4(u[0], h, k1[0], k2[0], k3[0]),
        _stage4(u[1], h, k1[1], k2[1], k3[1]),
        _stage4(u[2], h, k1[2], k2[2], k3[2]),
        _stage4(u[3], h, k1[3], k2[3], k3[3]),
    )
    k5 = _f(
        law,
        p,
        side,
        _stage5(u[0], h, k1[0], k2[0], k3[0], k4[0]),
        _stage5(u[1], h, k1[1], k2[1], k3[1], k4[1]),
        _stage5(u[2], h, k1[2], k2[2], k3[2], k4[2]),
        _stage5(u[3], h, k1[3], k2[3], k3[3], k4[3]),
    )
    k6 = _f(
        law,
        p,
        side,
        _stage6(u[0], h, k1[0], k2[0], k3[0], k4[0], k5[0]),
        _stage6(u[1], h, k1[1], k2[1], k3[1], k4[1], k5[1]),
        _stage6(u[2], h, k1[2], k2[2], k3[2], k4[2], k5[2]),
        _stage6(u[3], h, k1[3], k2[3], k3[3], k4[3], k5[3]),
    )
    unew = (
        _stage7(u[0], h, k1[0], k3[0], k4[0], k5[0], k6[0]),
        _stage7(u[1], h, k1[1], k3[1], k4[1], k5[1], k6[1]),
        _stage7(u[2], h, k1[2], k3[2], k4[2], k5[2], k6[2]),
        _stage7(u[3], h, k1[3], k3[3], k4[3], k5[3], k6[3]),
        _stage7(u[4], h, k1[4], k3[4], k4[4], k5[4], k6[4]),
        _stage7(u[5], h, k1[5], k3[5], k4[5], k5[5], k6[5]),
    )
    k7 = _f(law, p, side, unew[0], unew[1], unew[2], unew[3])
    ax, av, rtol = p[P_atolx], p[P_atolv], p[P_rtol]
    acc = _err(h, k1[0], k3[0], k4[0], k5[0], k6[0], k7[0], u[0], unew[0], ax, rtol)
    acc += _err(h, k1[1], k3[1], k4[1], k5[1], k6[1], k7[1], u[1], unew[1], av, rtol)
    acc += _err(h, k1[2], k3[2], k4[2], k5[2], k6[2], k7[2], u[2], unew[2], ax, rtol)
    acc += _err(h, k1[3], k3[3], k4[3], k5[3], k6[3], k7[3], u[3], unew[3], av, rtol)
    return unew, k7, math.sqrt(acc / 4.0)


@compiled
def _energy(law, p, u, side):
    x, xd, y, yd = u[0], u[1], u[2], u[3]
    e = 0.5 * p[P_M] * xd * xd + 0.5 * p[P_K] * x * x + 0.5 * p[P_m] * yd * yd
    if side != 0:
        e += contact_potential(law, p, side * (y - x) - p[P_h])
    return e


@compiled
def _locate(law, p, side, u, k1, h_hi, g_lo, g_hi, which):
    """Shortest step θ ∈ (0, h_hi] from u at which event ``which`` vanishes: (θ, state there,
    f of that state).

    which = 0: penetration δ (end of contact); which = 1: main-mass velocity ẋ (maximum of x).
    """
    lo, hi = 0.0, h_hi
    flo, fhi = g_lo, g_hi
    # A step from the onset itself starts at δ = 0 exactly with δ̇ > 0: θ = 0 is on the inside,
    # not a root.  Until a point with δ > 0 is found, bisect (a secant through δ = 0 at θ = 0
    # would return θ ≈ 0: a contact of 1e-17 s whenever a whole short contact fits in one step).
    inside_unknown = which == 0 and flo <= 0.0
    if inside_unknown:
        flo = 1.0
    side_kept = 0
    theta = hi
    for _ in range(200):
        den = fhi - flo  # the secant point, or the midpoint where the chord is flat
        theta = (lo * fhi - hi * flo) / den if den != 0.0 else 0.5 * (lo + hi)
        if inside_unknown or not (lo < theta < hi):
            theta = 0.5 * (lo + hi)
        out, kout, _ = _dp_step(law, p, side, u, k1, theta)
        g = side * (out[2] - out[0]) - p[P_h] if which == 0 else out[1]
        if inside_unknown:
            if g > 0.0:
                inside_unknown = False
                lo, flo = theta, g
            else:
                hi, fhi = theta, g
            continue
        if g == 0.0:
            return theta, out, kout
        if (g > 0.0) == (flo > 0.0):
            lo, flo = theta, g
            if side_kept == -1:
                fhi *= 0.5
            side_kept = -1
        else:
            hi, fhi = theta, g
            if side_kept == 1:
                flo *= 0.5
            side_kept = 1
        if hi - lo <= 4e-16 * max(hi, 1e-300) + 1e-300:
            break
    out, kout, _ = _dp_step(law, p, side, u, k1, hi)
    return hi, out, kout


@compiled
def _room(a, n):
    """``a`` if it has a row ``n``, else a copy with twice the rows (amortised growth: no
    buffer ever truncates a log or restarts a run)."""
    if n < a.shape[0]:
        return a
    b = np.zeros((2 * a.shape[0] + 16, a.shape[1]))
    b[: a.shape[0]] = a
    return b


@compiled
def _trace_contact_row(trace, ntr, t, u, k):
    """Row ``ntr`` of the trace: time, state, accelerations (from the stage k), contact flag."""
    trace[ntr, 0] = t
    for i in range(4):
        trace[ntr, 1 + i] = u[i]
    trace[ntr, 5] = k[1]
    trace[ntr, 6] = k[3]
    trace[ntr, 7] = 1.0


@compiled
def _trace_rest_row(trace, ntr, t, u):
    """Row ``ntr`` of the trace: the state held from ``t`` on (the run stopped at rest)."""
    trace[ntr, 0] = t
    for i in range(4):
        trace[ntr, 1 + i] = u[i]
    trace[ntr, 5] = 0.0
    trace[ntr, 6] = 0.0
    trace[ntr, 7] = 2.0


@compiled
def _contact(law, p, side, t0, u0, t_end, h_guess, peaks, npk, trace, ntr, record):
    """Integrate one contact from δ = 0; returns (status, t, npk, ntr, done, h_last, peaks,
    trace) with u0 updated in place to the state at the end of contact (or at t_end); ``peaks``
    and ``trace`` are the buffers, grown where they filled."""
    u = (u0[0], u0[1], u0[2], u0[3], 0.0, 0.0)
    k1 = _f(law, p, side, u[0], u[1], u[2], u[3])
    t = t0
    # the first step is at most the time to the largest penetration at the approach speed (an
    # elastic estimate, about a third of the contact): a step that holds a whole short contact
    # would leave its end to the event search alone
    v = side * (u[3] - u[1])
    h = h_guess
    if v > 0.0:
        h = min(h, _penetration_scale(law, p, v) / v)
    status = OK
    done = False
    if record:
        trace = _room(trace, ntr)
        _trace_contact_row(trace, ntr, t, u, k1)
        ntr += 1
    nsteps = 0
    while True:
        if t_end - t <= 0.0:
            break
        nsteps += 1
        if nsteps > MAX_CONTACT_STEPS:
            status = TOO_MANY_STEPS
            break
        h = min(h, t_end - t)
        if h < 1e-15 * max(abs(t), 1e-3):
            status = STEP_UNDERFLOW
            break
        unew, k7, err = _dp_step(law, p, side, u, k1, h)
        if err > 1.0 or not math.isfinite(err):
            fac = 0.2 if not math.isfinite(err) else max(0.2, 0.9 * err**-0.2)
            h *= fac
            continue
        d_old = side * (u[2] - u[0]) - p[P_h]
        d_new = side * (unew[2] - unew[0]) - p[P_h]
        hstep = h
        ended = d_new < 0.0
        if not ended:
            # both ends in contact: does δ dip below zero inside the step (the masses part and
            # touch again)?  The cubic Hermite interpolant of δ points at where; a step to that
            # point says whether the dip is real, and if so the contact ends before it.
            dip, s_dip = _hermite_min(
                d_old, d_new, h * side * (u[3] - u[1]), h * side * (unew[3] - unew[1])
            )
            if dip < 0.0:
                uev, _, _ = _dp_step(law, p, side, u, k1, s_dip * h)
                d_dip = side * (uev[2] - uev[0]) - p[P_h]
                if d_dip < 0.0:
                    ended = True
                    hstep, unew, k7 = _locate(law, p, side, u, k1, s_dip * h, d_old, d_dip, 0)
        else:
            hstep, unew, k7 = _locate(law, p, side, u, k1, h, d_old, d_new, 0)
        if u[1] > 0.0 and unew[1] <= 0.0:
            hp, uev, _ = _locate(law, p, side, u, k1, hstep, u[1], unew[1], 1)
            if uev[0] > 0.0:
                peaks = _room(peaks, npk)
                peaks[npk, 0] = t + hp
                peaks[npk, 1] = uev[0]
                npk += 1
        t = t + hstep
        u = unew
        k1 = k7
        if record:
            trace = _room(trace, ntr)
            _trace_contact_row(trace, ntr, t, u, k1)
            ntr += 1
        if ended:
            done = True
            break
        h = hstep * min(5.0, max(0.2, 0.9 * max(err, 1e-10) ** -0.2))
    for i in range(NV):
        u0[i] = u[i]
    return status, t, npk, ntr, done, h, peaks, trace


@compiled
def _perturbation_state(p, side, tau, X0, Xd0, Om, v, out):
    """State (x, ẋ, y, ẏ) at τ into a perturbation contact, and the pair's centre-of-mass state.

    The relative penetration z(τ) is Eq. 32 (with the B/A of ``p``); it is split between the masses
    so that it carries no momentum (Eq. 33 with B/A = −M/m): x = X − s·m/(M+m)·z, where X moves as
    the pair M + m on the main spring and damper (Eq. 7 with mass M + m) from the onset state.
    Returns (z, ż, X, Ẋ).
    """
    M, K, C, m, a, c1, ba = p[P_M], p[P_K], p[P_C], p[P_m], p[P_a], p[P_c1], p[P_ba]
    Mt = M + m
    r = m / Mt
    z = _z_pert(tau, Om, m, a, c1, v, ba)
    zd = _zd_pert(tau, Om, m, a, c1, v, ba)
    X = _x_ff(tau, Mt, K, C, X0, Xd0)
    Xd = _xd_ff(tau, Mt, K, C, X0, Xd0)
    out[0] = X - side * r * z
    out[1] = Xd - side * r * zd
    out[2] = out[0] + side * (p[P_h] + z)
    out[3] = out[1] + side * zd
    return z, zd, X, Xd


@compiled
def _perturbation_contact(p, side, t0, u0, t_end, peaks, npk, trace, ntr, record):
    """Contact by the two-variable solution (Eq. 31–33) that conserves momentum.

    The contact lasts T, the fixed point of Eq. 31, and the penetration follows Eq. 32, both with
    the B/A of ``p`` (as the paper uses them).  The motion of the masses is Eq. 33 with the B/A
    that conserves momentum, −M/m, about the pair's centre of mass, which moves on the main spring
    and damper meanwhile (see :func:`_perturbation_state`).  Eq. 33 as printed, x = z/(B/A − 1)
    about a frame at rest, conserves momentum only for B/A = −M/m and neglects the main spring for
    the whole contact; it put energy into the masses at every impact (0.125 J became 101.7 J in
    20 s on the benchmark system).  With this split the energy at exit is at most the energy at
    onset: ½(M+m)Ẋ² + ½KX² cannot grow (Eq. 7, C ≥ 0), and the relative kinetic energy ½μż²
    leaves multiplied by exp(−c₁(B − A)T/(B·m)) ≤ 1 (Eq. 32 at ξ = π).

    Returns (status, t, npk, ntr, done, dissipated by C, dissipated in the contact, peaks, trace);
    u0 is updated to the state at exit (or at t_end); the buffers grow where they filled.  The
    dissipation by C is the loss of the centre-of-mass energy; the contact's is the loss of the
    relative kinetic energy ½μ(Ż₀² − ż²) (plus the contact potential at t_end, where the run
    ends inside the contact).
    """
    M, K, m, b, c1, ba = p[P_M], p[P_K], p[P_m], p[P_b], p[P_c1], p[P_ba]
    v = side * (u0[3] - u0[1])
    T = _T_start(m, b, ba)
    converged = False
    for _ in range(500):
        Tn = _T_map(T, m, p[P_a], b, c1, v, ba)
        if abs(Tn - T) <= 1e-14 * Tn:
            T = Tn
            converged = True
            break
        T = Tn
    if not converged or not math.isfinite(T):
        return NO_CONVERGENCE, t0, npk, ntr, False, 0.0, 0.0, peaks, trace
    Om = math.pi / T
    Mt = M + m
    mu = m * M / Mt
    X0 = u0[0]
    Xd0 = (M * u0[1] + m * u0[3]) / Mt
    e_cm0 = 0.5 * Mt * Xd0 * Xd0 + 0.5 * K * X0 * X0
    t_stop = min(T, t_end - t0)
    st = np.empty(4)
    st2 = np.empty(4)
    # maxima of x inside the contact: sign changes of ẋ on a fine grid, refined by bisection;
    # the trace (for history=True) gets the grid points with accelerations by central differences
    n = 64
    prev_t = 0.0
    prev_xd = u0[1]
    for j in range(0, n + 1):
        tj = t_stop * j / n
        _perturbation_state(p, side, tj, X0, Xd0, Om, v, st)
        if record:
            trace = _room(trace, ntr)
            dt = 1e-6 * t_stop
            _perturbation_state(p, side, tj + dt, X0, Xd0, Om, v, st2)
            trace[ntr, 0] = t0 + tj
            for i in range(4):
                trace[ntr, 1 + i] = st[i]
            trace[ntr, 5] = st2[1]
            trace[ntr, 6] = st2[3]
            _perturbation_state(p, side, tj - dt, X0, Xd0, Om, v, st2)
            trace[ntr, 5] = (trace[ntr, 5] - st2[1]) / (2.0 * dt)
            trace[ntr, 6] = (trace[ntr, 6] - st2[3]) / (2.0 * dt)
            trace[ntr, 7] = 1.0
            ntr += 1
        if j == 0:
            continue
        xdj = st[1]
        if prev_xd > 0.0 and xdj <= 0.0:
            lo, hi = prev_t, tj
            for _ in range(100):
                mid = 0.5 * (lo + hi)
                _perturbation_state(p, side, mid, X0, Xd0, Om, v, st2)
                if st2[1] > 0.0:
                    lo = mid
                else:
                    hi = mid
            tm = 0.5 * (lo + hi)
            _perturbation_state(p, side, tm, X0, Xd0, Om, v, st2)
            if st2[0] > 0.0:
                peaks = _room(peaks, npk)
                peaks[npk, 0] = t0 + tm
                peaks[npk, 1] = st2[0]
                npk += 1
        prev_t, prev_xd = tj, xdj
    done = t_stop >= T
    z, zd, X, Xd = _perturbation_state(p, side, t_stop, X0, Xd0, Om, v, st)
    if done:
        # sin(π) and sin(3π) in floating point: the contact has ended exactly, δ = 0 and x = X
        z = 0.0
        st[0] = X
        st[2] = X + side * p[P_h]
    for i in range(4):
        u0[i] = st[i]
    e_cm = 0.5 * Mt * Xd * Xd + 0.5 * K * X * X
    d_c = e_cm0 - e_cm
    d_c1 = 0.5 * mu * (v * v - zd * zd)
    if not done:  # the run ends inside the contact: what the contact holds is not lost yet
        d_c1 -= contact_potential(PERTURBATION, p, z)
    return OK, t0 + t_stop, npk, ntr, done, d_c, d_c1, peaks, trace


@compiled
def _z_free(p, tau, x0, xd0, y0, yd0):
    return y0 + yd0 * tau - _x_ff(tau, p[P_M], p[P_K], p[P_C], x0, xd0)


@compiled
def _onset(p, x0, xd0, y0, yd0, tau0, T):
    """(τ, code) for free flight from the state at τ = 0, searched on [tau0, T].

    code ONSET_CONTACT: τ is the first time with abs(z(τ)) = d/2.  ONSET_NONE: no contact before T
    (also returned early once the wall is out of reach: the main mass's amplitude
    √(2E/K) never grows in free flight).  ONSET_REST: at τ the energy of both masses has fallen
    below p[P_rest] (the run stops at rest).
    """
    M, K, C, h = p[P_M], p[P_K], p[P_C], p[P_h]
    e_damper = 0.5 * p[P_m] * yd0 * yd0
    energy = 0.5 * M * xd0 * xd0 + 0.5 * K * x0 * x0
    amax = math.sqrt(C * C / M + K) * math.sqrt(2.0 * energy) / M
    wd = math.sqrt(K / M - C * C / (4 * M * M))
    hmax = 2.0 * math.pi / wd / 16.0
    hmin = 1e-10 * hmax
    if amax > 0.0:
        hmin = max(hmin, math.sqrt(8e-20 * h / amax))
        hmin = min(hmin, 1e-6 * hmax)
    tau = tau0
    za = _z_free(p, tau, x0, xd0, y0, yd0)
    H = hmax
    accepted = 0
    while tau < T:
        H = min(H, T - tau)
        tb = tau + H
        zb = _z_free(p, tb, x0, xd0, y0, yd0)
        slack = amax * H * H / 8.0
        if max(za, zb) + slack < h and min(za, zb) - slack > -h:
            tau, za = tb, zb
            H = min(2.0 * H, hmax)
            accepted += 1
            if accepted % 64 == 0:  # every few periods: at rest, or the wall out of reach?
                x = y0 + yd0 * tau - za
                xd = _xd_ff(tau, M, K, C, x0, xd0)
                e_main = 0.5 * M * xd * xd + 0.5 * K * x * x
                if e_main + e_damper < p[P_rest]:
                    return tau, ONSET_REST
                reach = abs(y0 + yd0 * tau) + abs(yd0) * (T - tau) + math.sqrt(2.0 * e_main / K)
                if reach < h * (1.0 - 1e-12):
                    return T, ONSET_NONE
            continue
        if H > hmin and H > 4e-16 * tb:
            H *= 0.5
            continue
        if abs(zb) >= h:
            s = 1.0 if zb > 0 else -1.0
            lo, hi = tau, tb
            flo = s * za - h
            fhi = s * zb - h
            kept = 0
            for _ in range(200):
                den = fhi - flo
                tm = (lo * fhi - hi * flo) / den if den != 0.0 else 0.5 * (lo + hi)
                if not (lo < tm < hi):
                    tm = 0.5 * (lo + hi)
                fm = s * _z_free(p, tm, x0, xd0, y0, yd0) - h
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
            return hi, ONSET_CONTACT
        tau, za = tb, zb  # an excursion shorter than hmin: below 1e-20 of the gap
        H = hmax
    return T, ONSET_NONE


@compiled
def secant_point(lo, hi, flo, fhi):
    """The secant's zero between (lo, flo) and (hi, fhi), or the midpoint where it falls outside
    (lo, hi) or the two values are equal (the Illinois halving can underflow a subnormal value
    to zero, and 0/0 must not stop a run)."""
    den = fhi - flo
    if den == 0.0:
        return 0.5 * (lo + hi)
    tm = (lo * fhi - hi * flo) / den
    if not (lo < tm < hi):
        tm = 0.5 * (lo + hi)
    return tm


@compiled
def _velocity_zero(M, K, C, x0, xd0, lo, hi, flo, fhi):
    """The τ in [lo, hi] where the free-flight velocity ẋ (Eq. 7) falls through zero, given
    ẋ(lo) = flo > 0 ≥ fhi = ẋ(hi): Illinois regula falsi (a secant that halves the value kept
    twice on one side), to the resolution of τ, at most 200 steps.  ẋ is smooth and nearly
    linear at its zero, so a few evaluations do what bisection did in about fifty."""
    if fhi == 0.0:
        return hi
    kept = 0
    for _ in range(200):
        tm = secant_point(lo, hi, flo, fhi)
        fm = _xd_ff(tm, M, K, C, x0, xd0)
        if fm == 0.0:
            return tm
        if fm > 0.0:
            lo, flo = tm, fm
            if kept == -1:
                fhi *= 0.5
            kept = -1
        else:
            hi, fhi = tm, fm
            if kept == 1:
                flo *= 0.5
            kept = 1
        if hi - lo <= 4e-16 * hi:
            break
    return 0.5 * (lo + hi)


@compiled
def _free_peaks(p, x0, xd0, t0, tau_a, tau_b, peaks, npk):
    """Record maxima of x (ẋ from + to −, x > 0) in free flight on [tau_a, tau_b]; returns
    (npk, peaks), the buffer grown where it filled."""
    M, K, C = p[P_M], p[P_K], p[P_C]
    wd = math.sqrt(K / M - C * C / (4 * M * M))
    step = math.pi / wd / 4.0  # ẋ has at most one zero in a quarter of its half period
    a = tau_a
    fa = _xd_ff(a, M, K, C, x0, xd0)
    while a < tau_b:
        b = min(a + step, tau_b)
        fb = _xd_ff(b, M, K, C, x0, xd0)
        if fa > 0.0 and fb <= 0.0:
            tm = _velocity_zero(M, K, C, x0, xd0, a, b, fa, fb)
            xm = _x_ff(tm, M, K, C, x0, xd0)
            if xm > 0.0:
                peaks = _room(peaks, npk)
                peaks[npk, 0] = t0 + tm
                peaks[npk, 1] = xm
                npk += 1
        a, fa = b, fb
    return npk, peaks


@compiled
def run(law, p, state0, t_end, impacts, peaks, trace, record, max_impacts, watch):
    """Simulate from state0 = (x, ẋ, y, ẏ) at t = 0 to t_end (or until a signal is seen on
    ``watch``: status INTERRUPTED, :mod:`symimpact._interrupt`).

    Fills ``impacts`` (one row per contact), ``peaks`` (t, x of positive maxima of x) and, when
    ``record``, ``trace``, each grown as it fills (status FULL_IMPACTS only past ``max_impacts``
    contacts).  Returns (status, n_impacts, n_peaks, n_trace, final state [6],
    dissipated by C, dissipated by c₁, final contact side (0: free), final time, impacts, peaks,
    trace), the last three the (possibly grown) buffers.
    """
    M, K, C, h = p[P_M], p[P_K], p[P_C], p[P_h]
    u = np.zeros(NV)
    for i in range(4):
        u[i] = state0[i]
    t = 0.0
    n_imp = 0
    npk = 0
    ntr = 0
    diss_C = 0.0
    diss_c1 = 0.0
    status = OK
    side = 0.0
    tau_skip = 0.0
    h_contact = 1e-3 * 2.0 * math.pi / math.sqrt(K / M)
    looks = 0
    while t < t_end:
        looks += 1
        if (looks & (EVERY - 1)) == 0 and stop_requested(watch):
            status = INTERRUPTED
            break
        x0, xd0, y0, yd0 = u[0], u[1], u[2], u[3]
        if record:
            trace = _room(trace, ntr)
            trace[ntr, 0] = t
            trace[ntr, 1] = x0
            trace[ntr, 2] = xd0
            trace[ntr, 3] = y0
            trace[ntr, 4] = yd0
            trace[ntr, 5] = -(C * xd0 + K * x0) / M
            trace[ntr, 6] = 0.0
            trace[ntr, 7] = 0.0
            ntr += 1
        e_main0 = 0.5 * M * xd0 * xd0 + 0.5 * K * x0 * x0
        tau_stop, onset = _onset(p, x0, xd0, y0, yd0, tau_skip, t_end - t)
        if onset == ONSET_NONE:
            tau_stop = t_end - t
        npk, peaks = _free_peaks(p, x0, xd0, t, 0.0, tau_stop, peaks, npk)
        x1 = _x_ff(tau_stop, M, K, C, x0, xd0)
        xd1 = _xd_ff(tau_stop, M, K, C, x0, xd0)
        u[0] = x1
        u[1] = xd1
        u[2] = y0 + yd0 * tau_stop
        u[3] = yd0
        diss_C += e_main0 - (0.5 * M * xd1 * xd1 + 0.5 * K * x1 * x1)
        t = t + tau_stop
        if onset == ONSET_NONE:
            side = 0.0
            break
        # contact onset
        side = 1.0 if u[2] - u[0] > 0.0 else -1.0
        if onset == ONSET_REST or _energy(law, p, u, 0.0) < p[P_rest]:
            status = AT_REST  # too little energy left for the contact to be resolved
            if record:
                trace = _room(trace, ntr)
                _trace_rest_row(trace, ntr, t, u)
                ntr += 1
            side = 0.0
            break
        if n_imp >= max_impacts:
            status = FULL_IMPACTS
            break
        impacts = _room(impacts, n_imp)
        u[2] = u[0] + side * h  # exactly on the boundary (the root is located to 4e-16)
        row = impacts[n_imp]
        row[I_T] = t
        row[I_X] = u[0]
        row[I_XD] = u[1]
        row[I_Y] = u[2]
        row[I_YD] = u[3]
        row[I_SIDE] = side
        e_on = _energy(law, p, u, side)
        row[I_EON] = e_on
        if law == PERTURBATION:
            status, t1, npk, ntr, done, d_c, d_c1, peaks, trace = _perturbation_contact(
                p, side, t, u, t_end, peaks, npk, trace, ntr, record
            )
        else:
            status, t1, npk, ntr, done, h_contact, peaks, trace = _contact(
                law, p, side, t, u, t_end, h_contact, peaks, npk, trace, ntr, record
            )
            d_c, d_c1 = u[4], u[5]
        n_imp += 1
        diss_C += d_c
        diss_c1 += d_c1
        t = t1
        row[I_TOFF] = t
        row[I_XOFF] = u[0]
        row[I_XDOFF] = u[1]
        row[I_YOFF] = u[2]
        row[I_YDOFF] = u[3]
        row[I_EOFF] = _energy(law, p, u, side)
        row[I_DC1] = d_c1
        row[I_DC] = d_c
        row[I_DONE] = 1.0 if done else 0.0
        if status != OK or not done:
            break
        side_exit = side
        side = 0.0
        u[2] = u[0] + side_exit * h  # exactly on the boundary again
        # leave the boundary: f = s·z − h has f(0) = 0, f'(0) = v < 0, |f''| ≤ A, so f < 0 on
        # (0, |v|/A]; the opposite wall, 2h away, is not reached while |v|τ + Aτ²/2 < h.  The
        # search for the next onset starts at the smaller of the two.
        v = side_exit * (u[3] - u[1])
        e_main = 0.5 * M * u[1] * u[1] + 0.5 * K * u[0] * u[0]
        amax = math.sqrt(C * C / M + K) * math.sqrt(2.0 * e_main) / M
        wd = math.sqrt(K / M - C * C / (4 * M * M))
        cap = 2.0 * math.pi / wd / 16.0
        if amax > 0.0:
            far = (math.sqrt(v * v + 2.0 * amax * h) - abs(v)) / amax
        else:
            far = h / abs(v) if v != 0.0 else cap
        if v < 0.0:
            tau_skip = min(-v / amax if amax > 0.0 else cap, cap, far)
        else:
            tau_skip = min(1e-9 * cap, far)  # grazing exit
    return status, n_imp, npk, ntr, u, diss_C, diss_c1, side, t, impacts, peaks, trace


@compiled
def one_contact(law, p, v0):
    """One contact from δ = 0: main mass at rest at x = 0, impact mass at relative speed v0.

    Returns (status, duration, end state, energy at onset, energy at exit).
    """
    u = np.zeros(NV)
    u[2] = p[P_h]
    u[3] = v0
    peaks = np.zeros((1, 2))
    trace = np.zeros((1, N_TRACE_COLS))
    e_on = _energy(law, p, u, 1.0)
    # the contact of a free or sprung pair lasts far less than this; it is only a safety stop
    t_cap = 1e3 * math.pi * math.sqrt(p[P_m] / max(p[P_b] + p[P_k1], 1e-300)) + 1e3
    h0 = 1e-4 * min(p[P_h] / v0, 1.0)
    status, t, _, _, done, _, _, _ = _contact(
        law, p, 1.0, 0.0, u, t_cap, h0, peaks, 0, trace, 0, False
    )
    if status != OK:
        return status, math.inf, u, e_on, e_on
    if not done:
        return NO_CONVERGENCE, math.inf, u, e_on, e_on
    return status, t, u, e_on, _energy(law, p, u, 1.0)


def forget_stale_compilations(dispatcher, sources, prefixes) -> None:
    """Drop numba's cached machine code of the modules named by ``prefixes`` (file-name prefixes
    such as ``"_stepper."``) when any of ``sources`` (paths) changed.

    numba keys a cached function to the time stamp of its own file only, while a compiled
    caller holds its callees' code inlined: after an edit of a module, a regeneration of the
    generated kernels it calls, or an upgrade, a cached caller would still run the old code.  A
    digest of every such source, kept beside the cache of ``dispatcher`` (one of the modules'
    compiled functions), tells.
    """
    import hashlib
    import os
    from pathlib import Path

    try:
        folder = Path(dispatcher._cache._cache_path)  # numba's cache layout is private
    except AttributeError:  # another numba version: nothing to do safely
        return
    digest = hashlib.sha256(b"".join(Path(s).read_bytes() for s in sources if Path(s).exists()))
    digest = digest.hexdigest()
    stamp = folder / f"symimpact-compiled-sources-{prefixes[0].rstrip('.')}.sha256"
    try:
        if stamp.read_text() == digest:
            return
    except OSError:
        pass
    try:
        for f in folder.iterdir():
            if f.name.startswith(tuple(prefixes)) and f.suffix in (".nbi", ".nbc"):
                f.unlink(missing_ok=True)
        tmp = stamp.with_name(f"{stamp.name}.{os.getpid()}.tmp")
        tmp.write_text(digest)
        os.replace(tmp, stamp)
    except OSError:  # a read-only cache: numba then compiles in memory, nothing is stale
        pass


def _forget_stale_compilations() -> None:
    """This module's and :mod:`symimpact.free._batch`'s cached code, dropped when this file, the batch
    loop or the free-flight and multiple-scales kernels changed."""
    from pathlib import Path

    here = Path(__file__)
    sources = [here, here.with_name("_batch.py"), Path(_ff.__file__), Path(_ms.__file__)]
    forget_stale_compilations(run, sources, ("_stepper.", "_batch."))


_forget_stale_compilations()
