"""Compiled forced simulation with a compliant contact (cubic, Hertz, linear, Hunt–Crossley), with
the variational equations carried through flight and contact (numba, cached on disk).

Free flight is closed form and its contact onsets are found exactly as for rigid impacts
(:mod:`symimpact.forced.engine._rigid`: Step 8's flight, Eq. F1, and its gap-free onset search).  A
contact phase, δ = s·z − d/2 > 0 on the wall s = ±1, is integrated by the Dormand–Prince 5(4)
pair of the free-decay stepper (:mod:`symimpact.free._stepper`), with the forcing in the primary's
equation,

    m ÿ = −s·F(δ, δ̇),  M ẍ = F0 cos θ − K(x − x_b) − C(ẋ − ẋ_b) + s·F(δ, δ̇),

and ends where δ returns to 0, located by re-stepping from the step's start (Illinois regula
falsi) so the located state carries the integrator's full accuracy.  The work of the forcing and
the dissipation of C and of the contact's damping are integrated with the motion, so the energy
ledger closes.  The state is recorded at ``samples`` points per forcing period.

*The monodromy.*  With ``variational`` the run also carries the derivatives of the state and of
the time at each event (contact onset or exit) with respect to the initial state, G and gt, and
returns G at the run's end (a fixed time).  Through a flight from event A to event B the
transition matrix Φ(τ) of Eq. 7 (the flight is affine in the state) acts on G − f_A·gt, the
change at B's nominal time (the closed-form flight obeys the flow's identity exactly); at a wall
B's time moves by −∇g·H/(∇g·f_B), g = s·(y − x) − d/2, and the state with it — the saltation
of the switching surface.  Through a contact the variational equations Ψ' = AΨ (A the Jacobian
of the contact's equations of motion: ∂F/∂δ, ∂F/∂δ̇ of the law) and ψ_t' = Aψ_t + ∂f/∂t (the
effect of the onset's time) are integrated by the same Runge–Kutta steps, so they are the exact
derivatives of the discrete steps, and the exit's time is differentiated through the located
last step (its rate with its length, by a central difference).  A Runge–Kutta map does not obey
the flow's identity ∂φ/∂t₀ = −Ψf at a Hertz onset, where δ^1.5 is not smooth: the saltation
matrix S = I + (f⁺ − f⁻)∇gᵀ/(∇g·f⁻) applied to Ψ was off by 5e-5 of the monodromy there, the
derivatives of the event times are not.

This module is private: :mod:`symimpact.forced.simulation` validates the input.
"""

from __future__ import annotations

import math

import numpy as np

from ... import _interrupt, budgets
from ..._compiled import compiled
from ..._interrupt import EVERY, INTERRUPTED, stop_requested
from ...free import _stepper
from ...free._stepper import P_a, P_b, P_c1, P_k1, P_khz
from . import _rigid
from ._borrowed import borrowed

HUNT_CROSSLEY = "hunt-crossley"
#: the contact laws' codes: the stepper's elastic laws, and Hertz with Hunt–Crossley damping
CUBIC, HERTZ, LINEAR, HC = _stepper.CUBIC, _stepper.HERTZ, _stepper.LINEAR, 9
CODES = {"cubic": CUBIC, "hertz": HERTZ, "linear": LINEAR, HUNT_CROSSLEY: HC}
#: Runge–Kutta tolerance in contact: rtol 1e-13, atol 1e-14 of the clearance and of the speeds'
#: scale.  A fifth-order pair's error per step accumulates over a contact's hundreds of steps:
#: against a whole-system DOP853 integration at 1e-13 (two periods, four contacts) rtol 1e-11 gave
#: 5.2e-10 of the state, 1e-12 gave 2.7e-11 and 1e-13 gives 2.0e-12, at 0.28 ms a contact.
RTOL = 1e-13
RHS_BUDGET = budgets.RHS_BUDGET  # evaluations of f (symimpact.budgets)
TOO_MUCH_WORK, TOO_MANY_STEPS, STEP_UNDERFLOW, UNRESOLVED = 2, 3, 4, 5
#: a flight ended on a wall at zero relative speed with the derivatives carried (a grazing onset)
GRAZED = 6
#: steps in one contact beyond which its time scale is out of proportion to the motion
MAX_CONTACT_STEPS = _stepper.MAX_CONTACT_STEPS
NW = 27  # x, ẋ, y, ẏ; forcing work, C's and the contact's dissipation; Ψ (4 × 4, by rows); ψ_t

# the Dormand–Prince 5(4) tableau of the free-decay stepper, as arrays
_DP_A = np.zeros((6, 6))
_DP_A[1, 0] = _stepper._A21
_DP_A[2, :2] = (_stepper._A31, _stepper._A32)
_DP_A[3, :3] = (_stepper._A41, _stepper._A42, _stepper._A43)
_DP_A[4, :4] = (_stepper._A51, _stepper._A52, _stepper._A53, _stepper._A54)
_DP_A[5, :5] = (_stepper._A61, _stepper._A62, _stepper._A63, _stepper._A64, _stepper._A65)
_DP_B = np.array([_stepper._B1, 0.0, _stepper._B3, _stepper._B4, _stepper._B5, _stepper._B6])
_DP_C = np.array([0.0, _stepper._C2, _stepper._C3, _stepper._C4, _stepper._C5, 1.0])
_DP_E = np.array(
    [_stepper._E1, 0.0, _stepper._E3, _stepper._E4, _stepper._E5, _stepper._E6, _stepper._E7]
)


def _base(law: str) -> str:
    """The stepper's elastic law under ``law`` (Hunt–Crossley's is Hertz's)."""
    return "hertz" if law == HUNT_CROSSLEY else law


def contact_potential(law: str, q: np.ndarray, delta: float) -> float:
    """Elastic energy stored in the contact at penetration δ [J] (the stepper's, by law)."""
    return _stepper.contact_potential(_stepper.LAWS[_base(law)], q, delta)


@compiled
def _force(code, q, chi, delta, dd):
    """(F, ∂F/∂δ, ∂F/∂δ̇, the damping part) of the contact force [N] at penetration δ [m] and
    rate δ̇ [m/s]: the elastic laws of Eq. 8 (cubic aδ³ + bδ), Eq. 9 (Hertz k_hz·δ^1.5) and
    Eq. 35 (linear k₁δ) with c₁δ̇, or Hunt–Crossley k_hz·δ^1.5·(1 + χδ̇) (Eq. F4).  ``q``: the
    stepper's parameter vector (:func:`symimpact.free._stepper.pack`)."""
    if code == HERTZ or code == HC:
        dp = max(delta, 0.0)
        root = math.sqrt(dp)
        fe = q[P_khz] * dp * root
        fe_d = 1.5 * q[P_khz] * root
    elif code == LINEAR:
        fe = q[P_k1] * delta
        fe_d = q[P_k1]
    else:
        fe = (q[P_a] * delta * delta + q[P_b]) * delta
        fe_d = 3.0 * q[P_a] * delta * delta + q[P_b]
    if code == HC:
        damp = fe * chi * dd
        return fe + damp, fe_d * (1.0 + chi * dd), fe * chi, damp
    damp = q[P_c1] * dd
    return fe + damp, fe_d, q[P_c1], damp


@compiled
def _forces(code, q, chi, delta, dd):
    """:func:`_force` at each of the arrays ``delta`` and ``dd``: (F, ∂F/∂δ, ∂F/∂δ̇)."""
    n = delta.shape[0]
    F, F_d, F_dd = np.empty(n), np.empty(n), np.empty(n)
    for j in range(n):
        F[j], F_d[j], F_dd[j], _ = _force(code, q, chi, delta[j], dd[j])
    return F, F_d, F_dd


def forces(code: int, q: np.ndarray, chi: float, delta: np.ndarray, dd: np.ndarray):
    """(F, ∂F/∂δ, ∂F/∂δ̇) [N, N/m, N·s/m] of the law ``code`` (:data:`CODES`) at the penetrations
    δ and rates δ̇ (1-D arrays): the engine's own law (:func:`_force`; Eq. 8, 9, 35 with c₁, or
    Eq. F4), for the harmonic balance's alternating frequency–time scheme."""
    delta = np.ascontiguousarray(delta, dtype=float)
    dd = np.ascontiguousarray(dd, dtype=float)
    return _forces(code, q, float(chi), delta, dd)


@compiled
def _rhs(code, q, chi, p, side, t, w, out, n):
    """The contact's equations of motion (module docstring) at time t for the first ``n``
    components of w: the state, the ledger's rates and, with n = NW, Ψ' = AΨ."""
    M, m, h = p[_rigid.P_M], p[_rigid.P_m], p[_rigid.P_h]
    K, C, W, F0, Xb = p[_rigid.P_K], p[_rigid.P_C], p[_rigid.P_W], p[_rigid.P_F0], p[_rigid.P_XB]
    x, v, y, u = w[0], w[1], w[2], w[3]
    th = W * t + p[_rigid.P_PHI]
    c, s = math.cos(th), math.sin(th)
    xb, vb = Xb * c, -Xb * W * s
    delta = side * (y - x) - h
    dd = side * (u - v)
    F, F_d, F_dd, damp = _force(code, q, chi, delta, dd)
    rel = v - vb
    out[0] = v
    out[1] = (F0 * c - K * (x - xb) - C * rel + side * F) / M
    out[2] = u
    out[3] = -side * F / m
    out[4] = F0 * c * v - (K * (x - xb) + C * rel) * vb
    out[5] = C * rel * rel
    out[6] = damp * dd
    if n > 7:
        # A's rows: (0, 1, 0, 0), (−K − F_δ, −C − F_δ̇, F_δ, F_δ̇)/M, (0, 0, 0, 1),
        # (F_δ, F_δ̇, −F_δ, −F_δ̇)/m; Ψ' = AΨ column by column, and ψ_t' = Aψ_t + ∂f/∂t
        for j in range(5):
            if j < 4:
                p0, p1, p2, p3 = w[7 + j], w[11 + j], w[15 + j], w[19 + j]
            else:
                p0, p1, p2, p3 = w[23], w[24], w[25], w[26]
            coupling = F_d * (p2 - p0) + F_dd * (p3 - p1)
            r0, r1, r2, r3 = p1, (-K * p0 - C * p1 + coupling) / M, p3, -coupling / m
            if j < 4:
                out[7 + j], out[11 + j], out[15 + j], out[19 + j] = r0, r1, r2, r3
            else:
                a_t = (-F0 * W * s + K * vb - C * Xb * W * W * c) / M
                out[23], out[24], out[25], out[26] = r0, r1 + a_t, r2, r3


@compiled
def _step(code, q, chi, p, side, t, w, k, h, n, tmp, out, kout, atol):
    """One Dormand–Prince step of length h from w at t, with k[0] = f(t, w) (kept): the state
    after it into ``out``, f there into ``kout``; returns the error norm of the motion (x, ẋ, y,
    ẏ, against ``atol`` and :data:`RTOL`)."""
    for st in range(1, 6):
        for i in range(n):
            acc = 0.0
            for j in range(st):
                acc += _DP_A[st, j] * k[j, i]
            tmp[i] = w[i] + h * acc
        _rhs(code, q, chi, p, side, t + _DP_C[st] * h, tmp, k[st], n)
    for i in range(n):
        acc = 0.0
        for j in range(6):
            acc += _DP_B[j] * k[j, i]
        out[i] = w[i] + h * acc
    _rhs(code, q, chi, p, side, t + h, out, kout, n)
    err = 0.0
    for i in range(4):
        acc = _DP_E[6] * kout[i]
        for j in range(6):
            acc += _DP_E[j] * k[j, i]
        sc = atol[i] + RTOL * max(abs(w[i]), abs(out[i]))
        err += (h * acc / sc) ** 2
    return math.sqrt(err / 4.0)


@compiled
def _locate(code, q, chi, p, side, t, w, k, h_hi, g_lo, g_hi, which, n, tmp, out, kout, atol):
    """The θ in (0, h_hi] at which event ``which`` vanishes on the step from w at t (re-stepped
    with the shorter length, Illinois regula falsi): δ (which 0, the contact's end) or ẋ (which
    1, an extreme of x); ``out`` and ``kout`` hold the state there.  Returns θ.

    At the onset δ = 0 at θ = 0 with δ̇ > 0: until a point with δ > 0 is found the search
    bisects (a secant through θ = 0 would return θ ≈ 0)."""
    lo, hi = 0.0, h_hi
    flo, fhi = g_lo, g_hi
    inside_unknown = which == 0 and flo <= 0.0
    if inside_unknown:
        flo = 1.0
    kept = 0
    for _ in range(200):
        theta = _stepper.secant_point(lo, hi, flo, fhi)
        if inside_unknown:
            theta = 0.5 * (lo + hi)
        _step(code, q, chi, p, side, t, w, k, theta, n, tmp, out, kout, atol)
        g = side * (out[2] - out[0]) - p[_rigid.P_h] if which == 0 else out[1]
        if inside_unknown:
            if g > 0.0:
                inside_unknown = False
                lo, flo = theta, g
            else:
                hi, fhi = theta, g
            continue
        if g == 0.0:
            return theta
        if (g > 0.0) == (flo > 0.0):
            lo, flo = theta, g
            if kept == -1:
                fhi *= 0.5
            kept = -1
        else:
            hi, fhi = theta, g
            if kept == 1:
                flo *= 0.5
            kept = 1
        if hi - lo <= 4e-16 * (t + hi):
            break
    _step(code, q, chi, p, side, t, w, k, hi, n, tmp, out, kout, atol)
    return hi


@compiled
def _note_extreme(period_max, n_periods, T_f, t, x):
    """Raise the largest abs(x) of the forcing period holding t to abs(x)."""
    kk = int(math.floor(t / T_f))  # noqa: RUF046 (int() spelled out for numba)
    if 0 <= kk < n_periods:
        period_max[kk] = max(period_max[kk], abs(x))


@compiled
def _contact(code, q, chi, p, side, t, w, t_end, h, n, period_max, n_periods, sampled, dt_s,
             atol, work, slope, watch):  # fmt: skip
    """One contact phase from t with w (state, zeroed ledger, Ψ), to its end δ = 0 or t_end.

    w is updated in place; sampled states and extremes of x are recorded; at an end, ``slope``
    holds the last step's rate of change with its length there.  Returns (status, t, ended,
    last step length); ``work`` [0] counts the evaluations of f."""
    return _contact_phase(code, q, chi, p, side, t, w, t_end, h, n, period_max, n_periods,
                          sampled, dt_s, atol, work, slope, watch, np.zeros((6, NW)),
                          np.zeros(NW), np.zeros(NW), np.zeros(NW), np.zeros(NW),
                          np.zeros(NW))  # fmt: skip


@compiled
def _contact_phase(code, q, chi, p, side, t, w, t_end, h, n, period_max, n_periods, sampled, dt_s,
                   atol, work, slope, watch, k, kout, tmp, out, ev_out, ev_k):  # fmt: skip
    """:func:`_contact` with its scratch arrays (the stages ``k``, ``kout``, ``tmp``, ``out``,
    ``ev_out``, ``ev_k``), every array borrowed (:mod:`._borrowed`): the caller keeps them
    alive, and the steps' loops count no references to them (at each Dormand–Prince step they
    were 24 % of the compliant curve's time, benchmark 6)."""
    p, w, period_max, sampled, atol = (borrowed(p), borrowed(w), borrowed(period_max),
                                       borrowed(sampled), borrowed(atol))  # fmt: skip
    work, slope, watch, k, kout = (borrowed(work), borrowed(slope), borrowed(watch), borrowed(k),
                                   borrowed(kout))  # fmt: skip
    tmp, out, ev_out, ev_k = borrowed(tmp), borrowed(out), borrowed(ev_out), borrowed(ev_k)
    T_f = 2.0 * math.pi / p[_rigid.P_W]
    _rhs(code, q, chi, p, side, t, w, k[0], n)
    n_samples = sampled.shape[0]
    nsteps = 0
    while True:
        if t_end - t <= 0.0:
            return _rigid.OK, t, False, h
        nsteps += 1
        if nsteps > MAX_CONTACT_STEPS:
            return TOO_MANY_STEPS, t, False, h
        if (nsteps & (EVERY - 1)) == 0 and stop_requested(watch):
            return INTERRUPTED, t, False, h
        if work[0] > work[1]:
            return TOO_MUCH_WORK, t, False, h
        h = min(h, t_end - t)
        if h < 1e-15 * max(abs(t), 1e-3):
            return STEP_UNDERFLOW, t, False, h
        err = _step(code, q, chi, p, side, t, w, k, h, n, tmp, out, kout, atol)
        work[0] += 6
        if err > 1.0 or not math.isfinite(err):
            h *= 0.2 if not math.isfinite(err) else max(0.2, 0.9 * err**-0.2)
            continue
        d_old = side * (w[2] - w[0]) - p[_rigid.P_h]
        d_new = side * (out[2] - out[0]) - p[_rigid.P_h]
        hstep = h
        ended = d_new < 0.0
        if not ended:
            # both ends in contact: does δ dip below zero inside the step (the masses part and
            # touch again)?  The cubic Hermite interpolant of δ says where to look
            dip, s_dip = _stepper._hermite_min(
                d_old, d_new, h * side * (w[3] - w[1]), h * side * (out[3] - out[1])
            )
            if dip < 0.0:
                _step(code, q, chi, p, side, t, w, k, s_dip * h, n, tmp, ev_out, ev_k, atol)
                d_dip = side * (ev_out[2] - ev_out[0]) - p[_rigid.P_h]
                if d_dip < 0.0:
                    ended = True
                    hstep = _locate(code, q, chi, p, side, t, w, k, s_dip * h, d_old, d_dip, 0,
                                    n, tmp, out, kout, atol)  # fmt: skip
        else:
            hstep = _locate(code, q, chi, p, side, t, w, k, h, d_old, d_new, 0, n, tmp, out,
                            kout, atol)  # fmt: skip
        if ended:
            work[0] += 60
            # the located step's own rate d(out)/dθ at the exit, by a central difference: the
            # exit's saltation uses it in place of f (module docstring)
            eps = 1e-4 * hstep
            if eps > 0.0:
                _step(code, q, chi, p, side, t, w, k, hstep + eps, 7, tmp, ev_out, ev_k, atol)
                for i in range(4):
                    slope[i] = ev_out[i]
                _step(code, q, chi, p, side, t, w, k, hstep - eps, 7, tmp, ev_out, ev_k, atol)
                for i in range(4):
                    slope[i] = (slope[i] - ev_out[i]) / (2.0 * eps)
            else:  # a located step of zero length: no rate to take (see _through_contact)
                for i in range(4):
                    slope[i] = math.nan
        # extremes of x inside the step, then the samples it passes
        if (w[1] > 0.0) != (out[1] > 0.0) and w[1] != 0.0:
            th = _locate(code, q, chi, p, side, t, w, k, hstep, w[1], out[1], 1, 7, tmp,
                         ev_out, ev_k, atol)  # fmt: skip
            _note_extreme(period_max, n_periods, T_f, t + th, ev_out[0])
            work[0] += 60
        k0 = max(0, int(math.ceil(t / dt_s - 1e-9)))  # noqa: RUF046 (int() spelled out for numba)
        k1 = min(n_samples - 1, int(math.floor((t + hstep) / dt_s + 1e-9)))  # noqa: RUF046
        for ks in range(k0, k1 + 1):
            if not math.isnan(sampled[ks, 0]):
                continue
            theta = min(max(ks * dt_s - t, 0.0), hstep)
            _step(code, q, chi, p, side, t, w, k, theta, 7, tmp, ev_out, ev_k, atol)
            sampled[ks, 0] = ev_out[0]
            sampled[ks, 1] = ev_out[1]
            sampled[ks, 2] = ev_out[2] - ev_out[0]
            sampled[ks, 3] = ev_out[3]
        t = t + hstep
        for i in range(n):
            w[i] = out[i]
            k[0, i] = kout[i]
        _note_extreme(period_max, n_periods, T_f, min(t, n_periods * T_f * (1 - 1e-16)), w[0])
        if ended:
            return _rigid.OK, t, True, hstep
        h = hstep * min(5.0, max(0.2, 0.9 * max(err, 1e-10) ** -0.2))


@compiled
def _flight_field(p, t, x, v, u, out):
    """The flight's vector field (ẋ, ẍ, ẏ, ÿ) at t (Eq. F1; ÿ = 0)."""
    out[0] = v
    out[1] = _rigid._accel(p, p[_rigid.P_M], t, x, v)
    out[2] = u
    out[3] = 0.0


@compiled
def _through_flight(p, tau, G, gt, fa, fb, side):
    """The derivatives (G = ∂state/∂s, gt = ∂t/∂s) carried through a flight of τ from event A
    (field ``fa``) to event B (field ``fb``) on the wall ``side`` (0: B is the run's end, a fixed
    time).  H = Φ(τ)(G − fa·gt) is the change at B's nominal time (the closed-form flight obeys
    the flow's identity exactly); at a wall B's time moves by −∇g·H/(∇g·fb) and the state with
    it.  False where B meets its wall at zero relative speed (∇g·fb = 0, a grazing onset): the
    onset's time has no derivative there."""
    M, K, C = p[_rigid.P_M], p[_rigid.P_K], p[_rigid.P_C]
    a11 = _stepper._x_ff(tau, M, K, C, 1.0, 0.0)
    a12 = _stepper._x_ff(tau, M, K, C, 0.0, 1.0)
    a21 = _stepper._xd_ff(tau, M, K, C, 1.0, 0.0)
    a22 = _stepper._xd_ff(tau, M, K, C, 0.0, 1.0)
    for j in range(4):
        d0, d1 = G[0, j] - fa[0] * gt[j], G[1, j] - fa[1] * gt[j]
        d2, d3 = G[2, j] - fa[2] * gt[j], G[3, j] - fa[3] * gt[j]
        G[0, j] = a11 * d0 + a12 * d1
        G[1, j] = a21 * d0 + a22 * d1
        G[2, j] = d2 + tau * d3
        G[3, j] = d3
    if side == 0:
        gt[:] = 0.0
        return True
    rate = side * (fb[2] - fb[0])
    if rate == 0.0 or not math.isfinite(rate):
        return False
    for j in range(4):
        gt[j] = -side * (G[2, j] - G[0, j]) / rate
        for i in range(4):
            G[i, j] += fb[i] * gt[j]
    return True


@compiled
def _through_contact(w, G, gt, side, slope, ended):
    """The derivatives carried through a contact: Ψ and ψ_t (the located steps' exact
    derivatives with respect to the onset's state and time) applied to (G, gt); at an exit the
    last step's length θ moves by −∇g·(ΨG + ψ_t·gt)/(∇g·r), r = ``slope`` its rate with its
    length, and the exit's time with it; a contact cut by the run's end has a fixed end time, so
    its last step shortens by the onset's delay (r again).  False, with nothing changed, where
    the exit's rate is zero or not finite: the contact is too short for its exit to be
    differentiated at the state's precision."""
    M1 = np.zeros((4, 4))
    for i in range(4):
        for j in range(4):
            acc = w[23 + i] * gt[j]
            for k in range(4):
                acc += w[7 + 4 * i + k] * G[k, j]
            M1[i, j] = acc
    if ended:
        rate = side * (slope[2] - slope[0])
        if rate == 0.0 or not math.isfinite(rate):
            return False  # the exit's rate is below the state's precision: no derivative
        for j in range(4):
            dtheta = -side * (M1[2, j] - M1[0, j]) / rate
            for i in range(4):
                G[i, j] = M1[i, j] + slope[i] * dtheta
            gt[j] += dtheta
    else:
        for j in range(4):
            for i in range(4):
                G[i, j] = M1[i, j] - slope[i] * gt[j]
            gt[j] = 0.0
    return True


@compiled
def _fill_flight(p, t0, x0, v0, z0, u0, t1, sampled, dt_s):
    """The sampled states of the flight from (x0, v0, z0, u0) at t0 up to t1 (Eq. F1)."""
    n_samples = sampled.shape[0]
    k0 = max(0, int(math.ceil(t0 / dt_s - 1e-9)))  # noqa: RUF046 (int() spelled out for numba)
    k1 = min(n_samples - 1, int(math.floor(t1 / dt_s + 1e-9)))  # noqa: RUF046
    for ks in range(k0, k1 + 1):
        if not math.isnan(sampled[ks, 0]):
            continue
        tau = ks * dt_s - t0
        xs, vs = _rigid._state(p, p[_rigid.P_M], t0, x0, v0, tau)
        sampled[ks, 0] = xs
        sampled[ks, 1] = vs
        sampled[ks, 2] = z0 + u0 * tau - (xs - x0)
        sampled[ks, 3] = u0


@compiled
def _run(code, q, chi, p, state0, t_end, max_events, samples, variational, budget, watch):
    """The compiled run (see :func:`run`)."""
    M, h = p[_rigid.P_M], p[_rigid.P_h]
    T_f = 2.0 * math.pi / p[_rigid.P_W]
    n_periods = int(math.floor(t_end / T_f + 0.5))  # noqa: RUF046 (int() spelled out for numba)
    period_max = np.zeros(n_periods + 1)
    ledger = np.zeros(3)
    dt_s = T_f / samples
    sampled = np.full((n_periods * samples + 1, 4), np.nan)
    events = np.zeros((64, _rigid.N_EVENT_COLS))
    n_ev = 0
    n = NW if variational else 7
    w = np.zeros(NW)
    for i in range(4):
        w[i] = state0[i]
    G = np.eye(4)  # ∂(state at the current event)/∂(initial state), and its time's gt
    gt = np.zeros(4)
    fa = np.zeros(4)
    fb = np.zeros(4)
    field = np.zeros(NW)
    atol = np.array([1e-14 * h, 0.0, 1e-14 * h, 0.0])
    work = np.array([0.0, budget])
    slope = np.zeros(4)
    t = 0.0
    side0 = 0
    in_contact = 0.0
    status = _rigid.OK
    # a contact phase at t = 0 when the start is inside a wall
    z = w[2] - w[0]
    side = 0
    if abs(z) > h:
        side = 1 if z > 0 else -1
    begun = side != 0  # the first contact began before t = 0: not an onset of this run
    looks = 0
    while t < t_end:
        looks += 1
        if (looks & (EVERY - 1)) == 0 and stop_requested(watch):
            status = INTERRUPTED
            break
        if side == 0:
            if n_ev + 2 > max_events:
                status = _rigid.TOO_MANY_EVENTS
                break
            x, v, u = w[0], w[1], w[3]
            z = w[2] - w[0]
            if variational:
                _flight_field(p, t, x, v, u, fa)
            tau, side = _rigid._next_impact(p, t, x, v, z, u, side0, t_end - t, watch)
            _rigid._segment(p, M, t, x, v, tau, ledger, period_max, n_periods)
            _fill_flight(p, t, x, v, z, u, t + tau, sampled, dt_s)
            xn, vn = _rigid._state(p, M, t, x, v, tau)
            z = z + u * tau - (xn - x)
            t = t + tau
            w[0], w[1], w[2] = xn, vn, xn + z
            if variational:
                _flight_field(p, t, xn, vn, u, fb)
                if not _through_flight(p, tau, G, gt, fa, fb, side):
                    status = GRAZED
                    break
            if side == 0:
                break
            w[2] = w[0] + side * h  # exactly on the wall (the onset is located to 4e-16)
        s = float(side)
        vrel = s * (w[3] - w[1])
        t_on, x_on, v_on, u_on = t, w[0], w[1], w[3]
        for i in range(4, NW):
            w[i] = 0.0
        for i in range(4):
            w[7 + 5 * i] = 1.0
        scale = max(abs(vrel), abs(w[1]), abs(w[3]), 1e-300)
        atol[1] = atol[3] = 1e-14 * scale
        h_contact = T_f / 64.0
        if vrel != 0.0:
            # the first step: about a tenth of the time to the largest penetration at this speed
            # (or, in a contact begun before t = 0 and parting, to cover the present one)
            depth = _stepper._penetration_scale(_stepper.HERTZ if code == HC else code, q,
                                                abs(vrel))  # fmt: skip
            depth = max(depth, s * (w[2] - w[0]) - h)
            h_contact = min(h_contact, 0.1 * depth / abs(vrel))
        status, t, ended, h_contact = _contact(code, q, chi, p, s, t, w, t_end, h_contact, n,
                                               period_max, n_periods, sampled, dt_s, atol,
                                               work, slope, watch)  # fmt: skip
        ledger[0] += w[4]
        ledger[1] += w[5]
        ledger[2] += w[6]
        if not begun:
            events = _rigid._grow(events, n_ev)
            ev = events[n_ev]
            ev[_rigid.E_T], ev[_rigid.E_X], ev[_rigid.E_XD] = t_on, x_on, v_on
            ev[_rigid.E_YD], ev[_rigid.E_SIDE], ev[_rigid.E_VREL] = u_on, s, vrel
            ev[_rigid.E_LOST], ev[_rigid.E_KIND] = w[6], _rigid.KIND_IMPACT
            ev[_rigid.E_XD1], ev[_rigid.E_YD1] = w[1], w[3]
            n_ev += 1
        begun = False
        if status != _rigid.OK:
            break
        if variational:
            if not ended:  # cut by the run's end: the contact's own field there
                _rhs(code, q, chi, p, s, t, w, field, 7)
                for i in range(4):
                    slope[i] = field[i]
            if not _through_contact(w, G, gt, s, slope, ended):
                status = UNRESOLVED
                break
        if not ended:
            in_contact = 1.0
            break
        w[2] = w[0] + s * h  # exactly on the wall again
        side0 = side
        side = 0
    final = np.array([t, w[0], w[1], w[2], w[3], in_contact])
    return status, events[:n_ev], period_max, ledger, final, sampled, G, work[0]


def run(law, q, chi, p, state0, t_end, max_events, samples, variational=False, budget=RHS_BUDGET):
    """Simulate from state0 = (x, ẋ, y, ẏ) at t = 0 to t_end (a start inside a wall begins with
    its contact phase, which is not logged as an onset).  Returns (status, events, period_max, ledger = (forcing work, C's
    dissipation, contact's dissipation), final = (t, x, ẋ, y, ẏ, 1.0 if it ended in contact),
    sampled states (n·samples + 1, 4): x, ẋ, z = y − x, ẏ at t = k·T/samples, and Ψ, the
    Jacobian of the final (x, ẋ, y, ẏ) with respect to the initial one (identity unless
    ``variational``)), and the evaluations of the equations of motion it took (status
    TOO_MUCH_WORK past ``budget`` of them).  ``law``: "cubic", "hertz", "linear" or
    "hunt-crossley"."""
    status, events, period_max, ledger, final, sampled, psi, work = _interrupt.call(
        _run, CODES[law], q, 0.0 if chi is None else float(chi), p,
        np.asarray(state0, dtype=float), float(t_end), int(max_events), int(samples),
        bool(variational), float(budget),
    )  # fmt: skip
    return status, events, period_max, ledger, final, sampled, psi, work


def _forget_stale_compilations() -> None:
    """This module's cached code, dropped when it, the rigid run's, the stepper's or the borrowed
    views' changed."""
    from pathlib import Path

    from . import _borrowed

    sources = [Path(__file__), Path(_rigid.__file__), Path(_stepper.__file__),
               Path(_borrowed.__file__)]  # fmt: skip
    _stepper.forget_stale_compilations(_run, sources, ("_compliant.",))


_forget_stale_compilations()
