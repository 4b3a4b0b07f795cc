"""Compiled contact phases of a structure's compliant impact dampers (numba, cached).

While damper k presses a wall s = ±1 of its clearance, δₖ = s·(yₖ − xₐ) − dₖ/2 > 0 with its
point xₐ = x_b + φₖᵀq, the mass and the structure push each other with the contact law's force
Fₖ(δₖ, δ̇ₖ) (Eq. 35's linear k₁δ + c₁δ̇, Eq. 9's Hertz k_hz·δ^1.5 + c₁δ̇, or Hunt–Crossley's
k_hz·δ^1.5·(1 + χδ̇), Eq. F4: the one-mode engine's laws, :func:`symimpact.forced.engine._compliant.
_force`), which enters the modes through their shapes (Step 15, item 4, Eq. F7, with the impulse
spread over the contact):

    Mᵢ(q̈ᵢ + 2ζᵢωᵢq̇ᵢ + ωᵢ²qᵢ) = (Eq. F7's modal force)ᵢ + Σₖ φᵢ(aₖ)·sₖFₖ,   mₖÿₖ = −sₖFₖ.

A contact phase — from one damper's onset until no damper presses a wall — is integrated over the
whole state (q, q̇, y, ẏ) by the Dormand–Prince 5(4) pair of the one-mode contact
(:mod:`symimpact.forced.engine._compliant`, rtol 1e-13), with the work of the modal forces, the
dissipation of the Cᵢ and of the contacts' damping carried along, so the energy ledger closes.
Any damper's onset or exit inside a step is located by re-stepping from the step's start
(Illinois regula falsi on the step's length), so that the law's kink at δ = 0 falls on a step's
end.  Between phases the flight is the closed form of :mod:`symimpact.forced.engine._modal`, which hands
over at an onset.  A rigid damper flies through a phase as a free mass (ÿₖ = 0); where it meets
a wall of its clearance (located as an onset is) Step 15's impact law (Eq. F7) acts at once:
P = (1 + e)μ(ẏₖ − ẋₐ), μ = (1/mₖ + φₖᵀBφₖ)⁻¹, q̇ += BφₖP, ẏₖ −= P/mₖ, its loss
½μ(1 − e²)(ẏₖ − ẋₐ)² in the ledger, the mass set on its wall (B = diag(1/Mᵢ) while nothing
rides or is held, :func:`mass_inverse`).  A chatter that would accumulate there (Step 9's test,
as in the modal engine: 2w/(a(1 − e)) within its limit) is taken to its accumulation point,
where the mass and its point close plastically, and the mass then rides on its point, the
structure carrying it ((diag(Mᵢ) + Σmₖφₖφₖᵀ)q̈ = the forces), until sₖ·ẍₐ turns positive (its
wall would pull; located as an onset is).  A linear stop acts in a phase by its law,
k₁(xₛ ∓ g) + c₁ẋₛ on its point while the point is past its gap (the modal engine's law, which
the closed form takes between phases), its onsets and exits located as a damper's, its
dashpot's dissipation in the ledger.  A rigid stop's point that meets its wall in a phase
takes Newton's law there at once, φᵀq̇⁺ = −e·φᵀq̇⁻ through the structure's effective mass at the
point (φᵀBφ)⁻¹ (Step 15's impact against the ground, the modal engine's law), its loss in the
ledger; its chatter accumulates as a damper's, and its wall then holds the point (Ψᵀq̈ = 0 over
the held points Ψ, B the constrained inverse) until the wall's reaction would pull.  An impulse
that would pull a riding mass or a held point lets it go first, as in the modal engine.  A phase
ends when no damper presses a wall and no chatter is on its way to its accumulation point,
whatever the stops do; a mass still riding and a point still held are handed to the modal
engine so.  Each output point's largest abs(x) in each forcing period is taken over the
steps' cubic Hermite interpolant (its position and velocity at both ends).

Private: :mod:`symimpact.forced.structure_response` runs the alternation.
"""

from __future__ import annotations

import math

import numpy as np

from ..._compiled import compiled
from ...free._stepper import secant_point
from ._compliant import _DP_A, _DP_B, _DP_C, _DP_E, RTOL, _force
from ._rigid import P_C, P_F0, P_K, P_M, P_PHI, P_W, P_XB

#: Status beside OK (0): the step fell below 1e-14 of the forcing period (a contact too stiff
#: for its time scale), or a phase took more than its budget of steps.
STEP_UNDERFLOW, TOO_MANY_STEPS = 4, 3
#: Steps one contact phase may take.
MAX_PHASE_STEPS = 2_000_000
#: The contact's event kinds (as the modal engine's log): onset (3) and exit (4), a rigid
#: damper's impact (0), its chatter's accumulation (1) and its release (2).
KIND_ONSET, KIND_EXIT, KIND_IMPACT, KIND_ACCUMULATION, KIND_RELEASE = 3, 4, 0, 1, 2
#: Columns of a phase's event log: (t, damper, wall, kind, δ̇, the point's x and ẋ, the mass's
#: ẏ, the point's ẋ and the mass's ẏ after the event, the energy it took).
N_PHASE_COLS = 11
#: A damper's law code for rigid impacts (the others: :data:`symimpact.forced.engine._compliant.CODES`)
RIGID = -1
#: The code of a rigid damper whose mass rides on its point (its chatter accumulated): the
#: structure carries it there (module text).
STUCK = -2


@compiled
def _rhs(pm, Phi, md, hd, code, lq, chi, stp, xb, t, w, out, N, K, Ainv):
    """(q̇, q̈, ẏ, ÿ, the ledger's rates) at time t (module text): the ledger's rates are the
    power of the modal forces (with the masses' inertia −mₖẍ_b under base motion, the ledger
    being the one seen from the supports), of the Cᵢ, of the contacts' damping and of the
    stops' dashpots.  ``stp``: the stops, a row each (φ at the point, gap g, k₁, c₁, walls +1,
    −1 or 0 for both, 1 for a rigid stop else 0, its e): a point past a linear stop's gap,
    xₛ = φᵀq beyond ±g on a wall it has, is pushed back by k₁(xₛ ∓ g) + c₁ẋₛ (the modal engine's
    law, :func:`symimpact.forced.engine._modal_flight._config`); a rigid stop adds no force."""
    W, phi = pm[0, P_W], pm[0, P_PHI]
    th = W * t + phi
    c, s = math.cos(th), math.sin(th)
    x_b, v_b, a_b = xb * c, -xb * W * s, -xb * W * W * c
    power, d_c, d_k = 0.0, 0.0, 0.0
    for i in range(N):
        v = w[N + i]
        Kf, Cf = pm[i, P_K], pm[i, P_C]
        thi = pm[i, P_W] * t + pm[i, P_PHI]
        P = pm[i, P_F0] + Kf * pm[i, P_XB]
        Q = -Cf * pm[i, P_W] * pm[i, P_XB]
        f = P * math.cos(thi) + Q * math.sin(thi)
        out[i] = v
        out[N + i] = (f - Cf * v - Kf * w[i]) / pm[i, P_M]
        power += f * v
        d_c += Cf * v * v
    for k in range(K):
        xa, va = x_b, v_b
        for i in range(N):
            xa += Phi[k, i] * w[i]
            va += Phi[k, i] * w[N + i]
        y, u = w[2 * N + k], w[2 * N + K + k]
        side = 1.0 if y > xa else -1.0
        delta = side * (y - xa) - hd[k]
        out[2 * N + k] = u
        acc = 0.0
        if delta > 0.0 and code[k] >= 0:
            dd = side * (u - va)
            F, _, _, damp = _force(code[k], lq[k], chi[k], delta, dd)
            for i in range(N):
                out[N + i] += Phi[k, i] * side * F / pm[i, P_M]
            acc = -side * F / md[k]
            d_k += damp * dd
        out[2 * N + K + k] = acc
        if xb != 0.0:
            power -= md[k] * (u - v_b) * a_b
    d_s = 0.0
    for r in range(stp.shape[0]):  # a linear stop pressed past its gap (its walls: column N + 3)
        if stp[r, N + 4] != 0.0:
            continue  # a rigid stop acts by impulses only (:func:`_stop_impact`)
        xs, vs = 0.0, 0.0
        for i in range(N):
            xs += stp[r, i] * w[i]
            vs += stp[r, i] * w[N + i]
        side = 1.0 if xs > 0.0 else -1.0
        if side * stp[r, N + 3] < 0.0 or side * xs - stp[r, N] <= 0.0:
            continue
        F = stp[r, N + 1] * (xs - side * stp[r, N]) + stp[r, N + 2] * vs
        for i in range(N):
            out[N + i] -= stp[r, i] * F / pm[i, P_M]
        d_s += stp[r, N + 2] * vs * vs
    riding = False
    for k in range(K):
        riding = riding or code[k] == STUCK
    for r in range(stp.shape[0]):
        riding = riding or stp[r, N + 6] != 0.0
    if riding:  # q̈ = B·(the forces, less the riding masses' −mₖẍ_b) (:func:`mass_inverse`)
        g = np.empty(N)
        for i in range(N):
            g[i] = out[N + i] * pm[i, P_M]
            for k in range(K):
                if code[k] == STUCK:
                    g[i] -= md[k] * Phi[k, i] * a_b
        for i in range(N):
            acc = 0.0
            for j in range(N):
                acc += Ainv[i, j] * g[j]
            out[N + i] = acc
        for r in range(stp.shape[0]):  # a held stop's wall's reaction −R·g, after the ledger
            lam = 0.0
            if stp[r, N + 6] != 0.0:
                for j in range(N):
                    lam -= Ainv[N + r, j] * g[j]
            out[2 * N + 2 * K + 4 + r] = lam
        for k in range(K):
            if code[k] == STUCK:  # the mass goes with its point
                acc = a_b
                for i in range(N):
                    acc += Phi[k, i] * out[N + i]
                out[2 * N + K + k] = acc
    if not riding:
        for r in range(stp.shape[0]):
            out[2 * N + 2 * K + 4 + r] = 0.0
    out[2 * N + 2 * K] = power
    out[2 * N + 2 * K + 1] = d_c
    out[2 * N + 2 * K + 2] = d_k
    out[2 * N + 2 * K + 3] = d_s


@compiled
def _step(pm, Phi, md, hd, code, lq, chi, stp, xb, t, w, kk, h, n, tmp, out, kout, atol, N, K,
          Ainv):  # fmt: skip
    """One Dormand–Prince step of length h from w at t, kk[0] = f(t, w): the state after it in
    ``out``, f there in ``kout``; returns the error norm of the motion (q, q̇, y, ẏ against
    ``atol`` and :data:`RTOL`)."""
    for st in range(1, 6):
        for i in range(n):
            acc = 0.0
            for j in range(st):
                acc += _DP_A[st, j] * kk[j, i]
            tmp[i] = w[i] + h * acc
        _rhs(pm, Phi, md, hd, code, lq, chi, stp, xb, t + _DP_C[st] * h, tmp, kk[st], N, K, Ainv)
    for i in range(n):
        acc = 0.0
        for j in range(6):
            acc += _DP_B[j] * kk[j, i]
        out[i] = w[i] + h * acc
    _rhs(pm, Phi, md, hd, code, lq, chi, stp, xb, t + h, out, kout, N, K, Ainv)
    m = 2 * N + 2 * K
    err = 0.0
    for i in range(m):
        acc = _DP_E[6] * kout[i]
        for j in range(6):
            acc += _DP_E[j] * kk[j, i]
        sc = atol[i] + RTOL * max(abs(w[i]), abs(out[i]))
        err += (h * acc / sc) ** 2
    return math.sqrt(err / m)


@compiled
def _delta(pm, Phi, hd, stp, xb, t, w, k, side, N, K):
    """δₖ on wall ``side`` of the state w at time t (k ≥ K: stop k − K of ``stp``, its
    side·xₛ − g)."""
    if k >= K:
        xs = 0.0
        for i in range(N):
            xs += stp[k - K, i] * w[i]
        return side * xs - stp[k - K, N]
    xa = xb * math.cos(pm[0, P_W] * t + pm[0, P_PHI])
    for i in range(N):
        xa += Phi[k, i] * w[i]
    return side * (w[2 * N + k] - xa) - hd[k]


@compiled
def _pull(pm, Phi, xb, t, f, k, side, N):
    """side·ẍₐ of riding damper k's point at t from the rates ``f`` there: positive where its
    wall would pull the mass (Step 15, item 5: the mass is then let go)."""
    W = pm[0, P_W]
    acc = -xb * W * W * math.cos(W * t + pm[0, P_PHI])
    for i in range(N):
        acc += Phi[k, i] * f[N + i]
    return side * acc


@compiled
def _locate(pm, Phi, md, hd, code, lq, chi, stp, xb, t, w, kk, h_hi, g_hi, k, side, n, tmp, out,
            kout, atol, N, K, from_wall, Ainv):  # fmt: skip
    """The θ in (0, h_hi] where δₖ on wall ``side`` changes sign on the step from w at t (δₖ(0)
    is of the other sign or 0), re-stepped with the shorter length (Illinois regula falsi);
    ``out``, ``kout`` hold the state there.  While no point of δₖ's starting sign is known
    (δₖ(0) = 0 at an onset just handed over, or ``from_wall``: a rigid damper that left this wall
    at the step's start, δₖ(0) its rounding) it bisects."""
    held = k < K and code[k] == STUCK  # its root: where the wall would pull (:func:`_pull`)
    holds = k >= K and stp[k - K, N + 6] != 0.0  # a held stop's: its reaction turns to a pull
    if from_wall:
        g0 = 0.0
    elif held:
        g0 = _pull(pm, Phi, xb, t, kk[0], k, side, N)
    elif holds:
        g0 = stp[k - K, N + 6] * kk[0, 2 * N + 2 * K + 4 + k - K]
    else:
        g0 = _delta(pm, Phi, hd, stp, xb, t, w, k, side, N, K)
    lo, hi = 0.0, h_hi
    flo, fhi = g0, g_hi
    unknown = flo == 0.0
    kept = 0
    for _ in range(300):
        theta = 0.5 * (lo + hi) if unknown else secant_point(lo, hi, flo, fhi)
        _step(pm, Phi, md, hd, code, lq, chi, stp, xb, t, w, kk, theta, n, tmp, out, kout, atol,
              N, K, Ainv)  # fmt: skip
        if held:
            g = _pull(pm, Phi, xb, t + theta, kout, k, side, N)
        elif holds:
            g = stp[k - K, N + 6] * kout[2 * N + 2 * K + 4 + k - K]
        else:
            g = _delta(pm, Phi, hd, stp, xb, t + theta, out, k, side, N, K)
        if unknown:
            if g != 0.0 and (g > 0.0) != (fhi > 0.0):
                unknown = False
                lo, flo = theta, g
            else:
                hi, fhi = theta, g
            if hi <= 4e-16 * (t + hi):
                break
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
    _step(pm, Phi, md, hd, code, lq, chi, stp, xb, t, w, kk, hi, n, tmp, out, kout, atol, N, K,
          Ainv)  # fmt: skip
    return hi


@compiled
def _note(period_max, n_periods, T_f, t0, h, Pout, pm, xb, w0, w1, N):
    """Raise each output point's per-period maximum of abs(x) over the step [t0, t0 + h] by the
    cubic Hermite interpolant of its x and ẋ at both ends (its extreme where ẋ's quadratic
    vanishes)."""
    W, phi = pm[0, P_W], pm[0, P_PHI]
    for p in range(Pout.shape[0]):
        x0, v0, x1, v1 = 0.0, 0.0, 0.0, 0.0
        for i in range(N):
            x0 += Pout[p, i] * w0[i]
            v0 += Pout[p, i] * w0[N + i]
            x1 += Pout[p, i] * w1[i]
            v1 += Pout[p, i] * w1[N + i]
        if xb != 0.0:
            x0 += xb * math.cos(W * t0 + phi)
            x1 += xb * math.cos(W * (t0 + h) + phi)
            v0 -= xb * W * math.sin(W * t0 + phi)
            v1 -= xb * W * math.sin(W * (t0 + h) + phi)
        cands = np.array([0.0, 1.0, -1.0, -1.0])
        # x(s) = h00 x0 + h10 h v0 + h01 x1 + h11 h v1, s in [0, 1]; x'(s) = a s² + b s + c
        a = 6.0 * (x0 - x1) + 3.0 * h * (v0 + v1)
        b = -6.0 * (x0 - x1) - 2.0 * h * (2.0 * v0 + v1)
        c = h * v0
        if a != 0.0:
            disc = b * b - 4.0 * a * c
            if disc >= 0.0:
                r = math.sqrt(disc)
                cands[2] = (-b + r) / (2.0 * a)
                cands[3] = (-b - r) / (2.0 * a)
        elif b != 0.0:
            cands[2] = -c / b
        for j in range(4):
            sv = cands[j]
            if sv < 0.0 or sv > 1.0:
                continue
            s2, s3 = sv * sv, sv * sv * sv
            x = ((2 * s3 - 3 * s2 + 1) * x0 + (s3 - 2 * s2 + sv) * h * v0
                 + (-2 * s3 + 3 * s2) * x1 + (s3 - s2) * h * v1)  # fmt: skip
            kp = int(math.floor((t0 + sv * h) / T_f))  # noqa: RUF046 (numba)
            if 0 <= kp < n_periods:
                period_max[kp, p] = max(period_max[kp, p], abs(x))


@compiled
def _room(events, n_ev):
    """The phase's event log with room for one more row (doubled when full)."""
    if n_ev < events.shape[0]:
        return events
    grown = np.zeros((2 * n_ev, N_PHASE_COLS))
    grown[:n_ev] = events
    return grown


@compiled
def _ended(events, n_ev, pm, Phi, xb, t, w, k, sides, pressing, N, K):
    """Damper k's contact begins or ends at t (``pressing[k]`` flips): logged as (t, damper,
    wall, kind, δ̇, the point's x and ẋ, the mass's ẏ).  Returns (count, log)."""
    pressing[k] = 1 - pressing[k]
    xa = xb * math.cos(pm[0, P_W] * t + pm[0, P_PHI])
    va = -xb * pm[0, P_W] * math.sin(pm[0, P_W] * t + pm[0, P_PHI])
    for i in range(N):
        xa += Phi[k, i] * w[i]
        va += Phi[k, i] * w[N + i]
    events = _room(events, n_ev)
    events[n_ev, 0] = t
    events[n_ev, 1] = k
    events[n_ev, 2] = sides[k]
    events[n_ev, 3] = KIND_ONSET if pressing[k] else KIND_EXIT
    events[n_ev, 4] = sides[k] * (w[2 * N + K + k] - va)
    events[n_ev, 5] = xa
    events[n_ev, 6] = va
    events[n_ev, 7] = w[2 * N + K + k]
    events[n_ev, 8] = va
    events[n_ev, 9] = w[2 * N + K + k]
    events[n_ev, 10] = 0.0
    return n_ev + 1, events


@compiled
def _stop_ended(events, n_ev, stp, t, w, j, sides, pressing, N, K):
    """Stop j − K's contact begins or ends at t (``pressing[j]`` flips): logged as damper j with
    its wall, kind, speed and the point's x and ẋ.  Returns (count, log)."""
    pressing[j] = 1 - pressing[j]
    xs, vs = 0.0, 0.0
    for i in range(N):
        xs += stp[j - K, i] * w[i]
        vs += stp[j - K, i] * w[N + i]
    events = _room(events, n_ev)
    events[n_ev, 0], events[n_ev, 1], events[n_ev, 2] = t, j, sides[j]
    events[n_ev, 3] = KIND_ONSET if pressing[j] else KIND_EXIT
    events[n_ev, 4], events[n_ev, 5], events[n_ev, 6] = abs(vs), xs, vs
    events[n_ev, 8] = vs
    return n_ev + 1, events


@compiled
def mass_inverse(pm, Phi, md, code, stp, N, K):
    """The structure's inverse mass while the riding dampers (code :data:`STUCK`) ride on their
    points and the held rigid stops (``stp``'s column N + 6: the wall, or 0) hold theirs (Step
    15, item 5): with A = diag(Mᵢ) + Σ mₖφₖφₖᵀ and Ψ the held points' shapes, rows 0 … N − 1 are
    B = A⁻¹ − A⁻¹Ψ(ΨᵀA⁻¹Ψ)⁻¹ΨᵀA⁻¹, so that q̈ = B·(the forces) keeps Ψᵀq̈ = 0 and an impulse
    φP moves q̇ by BφP; row N + r is stop r's row of R = (ΨᵀA⁻¹Ψ)⁻¹ΨᵀA⁻¹, its wall's reaction
    to the forces g being −R·g (0 for a stop that does not hold)."""
    S = stp.shape[0]
    A = np.zeros((N, N))
    for i in range(N):
        A[i, i] = pm[i, P_M]
    for k in range(K):
        if code[k] == STUCK:
            for i in range(N):
                for j in range(N):
                    A[i, j] += md[k] * Phi[k, i] * Phi[k, j]
    Ai = np.linalg.inv(A)
    out = np.zeros((N + S, N))
    out[:N] = Ai
    H = 0
    for r in range(S):
        if stp[r, N + 6] != 0.0:
            H += 1
    if H == 0:
        return out
    rows = np.empty(H, dtype=np.int64)
    Psi = np.empty((N, H))
    h = 0
    for r in range(S):
        if stp[r, N + 6] != 0.0:
            rows[h] = r
            Psi[:, h] = stp[r, :N]
            h += 1
    Y = Ai @ Psi
    R = np.linalg.solve(Psi.T @ Y, Y.T)
    out[:N] = Ai - Y @ R
    for h in range(H):
        out[N + rows[h]] = R[h]
    return out


@compiled
def _log_row(events, n_ev, t, k, side, kind, rate, x, xd, yd, xd1, yd1, lost):
    """One row of the phase's log (:data:`N_PHASE_COLS`).  Returns (count, log)."""
    events = _room(events, n_ev)
    events[n_ev, 0], events[n_ev, 1], events[n_ev, 2], events[n_ev, 3] = t, k, side, kind
    events[n_ev, 4], events[n_ev, 5], events[n_ev, 6], events[n_ev, 7] = rate, x, xd, yd
    events[n_ev, 8], events[n_ev, 9], events[n_ev, 10] = xd1, yd1, lost
    return n_ev + 1, events


@compiled
def _point(pm, Phi, xb, t, w, k, N):
    """Damper k's point: (xₐ, ẋₐ) = x_b + φₖᵀq, ẋ_b + φₖᵀq̇ at t."""
    W, ph = pm[0, P_W], pm[0, P_PHI]
    xa, va = xb * math.cos(W * t + ph), -xb * W * math.sin(W * t + ph)
    for i in range(N):
        xa += Phi[k, i] * w[i]
        va += Phi[k, i] * w[N + i]
    return xa, va


@compiled
def _stop_point(stp, w, r, N):
    """Stop r's point: (xₛ, ẋₛ) = φᵀq, φᵀq̇ (relative to the ground, which its wall is fixed to)."""
    xs, vs = 0.0, 0.0
    for i in range(N):
        xs += stp[r, i] * w[i]
        vs += stp[r, i] * w[N + i]
    return xs, vs


@compiled
def _on_wall(xa, side, h):
    """The position of a free mass just off its wall ``side`` (its point at xa, half clearance
    h), after an impact or where it is let go: four units in the last place of max(h, abs(xa))
    inside, so that δ = side·(y − xa) − h starts below zero despite the rounding of y − xa (as
    :func:`_inside` does for a stop's point).  Set on the wall to the bit, δ could start an ulp
    beyond it, and a mass let go where its wall draws away met it again at once, over and over
    at one instant."""
    return xa + side * (h - 4e-16 * max(h, abs(xa)))


@compiled
def _let_go(events, n_ev, pm, Phi, md, stp, hd, xb, t, w, j, sides, code, N, K):
    """Let go, at t, riding damper j (its mass set just inside its wall, :func:`_on_wall`) or,
    for j ≥ K, the point held by stop j − K (moved just inside its wall, :func:`_inside`), where
    its wall would pull: logged (kind :data:`KIND_RELEASE`).  Returns (count, log, B)."""
    if j >= K:
        r = j - K
        wall = stp[r, N + 6]
        xs, vs = _stop_point(stp, w, r, N)
        n_ev, events = _log_row(events, n_ev, t, j, wall, KIND_RELEASE, 0.0, xs, vs, 0.0, vs,
                                0.0, 0.0)  # fmt: skip
        stp[r, N + 6] = 0.0
        _inside(stp, w, r, wall, N)
    else:
        code[j] = RIGID
        xa, va = _point(pm, Phi, xb, t, w, j, N)
        w[2 * N + j] = _on_wall(xa, sides[j], hd[j])
        u = w[2 * N + K + j]
        n_ev, events = _log_row(events, n_ev, t, j, sides[j], KIND_RELEASE, 0.0, xa, va, u, va, u,
                                0.0)  # fmt: skip
    return n_ev, events, mass_inverse(pm, Phi, md, code, stp, N, K)


@compiled
def _kick(events, n_ev, pm, Phi, md, stp, hd, xb, t, w, code, sides, Ainv, phi, minv, d, e, N,
          K):  # fmt: skip
    """An impulse at a point of the structure of shape ``phi`` against a body of inverse mass
    ``minv`` (a damper's 1/mₖ, or 0: the ground) whose speed exceeds the point's by ``d``:
    Newton's law with restitution e, P = (1 + e)·d/(minv + φᵀA⁻¹φ), q̇ += A⁻¹φP, with the
    riding masses' and the held stops' B (:func:`mass_inverse`).  A riding mass or a held stop
    whose wall would have to pull during the impulse (sⱼ·ΔẋⱼP > 0, or its reaction −R·φP
    toward its wall) is let go first (:func:`_let_go`) and the impulse taken again without it,
    as the modal engine does; the masses still riding go with their points.  Returns (P,
    1/(minv + φᵀBφ), B, count, log); ``w``'s q̇ changed."""
    wv = np.empty(N)
    while True:
        inv = minv
        for i in range(N):
            acc = 0.0
            for j in range(N):
                acc += Ainv[i, j] * phi[j]
            wv[i] = acc
            inv += phi[i] * acc
        P = (1.0 + e) * d / inv
        pulled = -1
        for j in range(K):
            if code[j] == STUCK:
                dv = 0.0
                for i in range(N):
                    dv += Phi[j, i] * wv[i]
                if sides[j] * dv * P > 0.0:
                    pulled = j
                    break
        for r in range(stp.shape[0]):  # a held stop's reaction −R·φP, a push only
            if pulled < 0 and stp[r, N + 6] != 0.0:
                lam = 0.0
                for i in range(N):
                    lam -= Ainv[N + r, i] * phi[i] * P
                if stp[r, N + 6] * lam > 0.0:
                    pulled = K + r
        if pulled < 0:
            break
        n_ev, events, Ainv = _let_go(events, n_ev, pm, Phi, md, stp, hd, xb, t, w, pulled, sides,
                                     code, N, K)  # fmt: skip
    for i in range(N):
        w[N + i] += wv[i] * P
    for j in range(K):
        if code[j] == STUCK:
            w[2 * N + K + j] = _point(pm, Phi, xb, t, w, j, N)[1]
    return P, 1.0 / inv, Ainv, n_ev, events


@compiled
def _rigid_impact(events, n_ev, pm, Phi, md, stp, hd, ed, xb, t, w, k, side, N, K, code, sides,
                  Ainv):  # fmt: skip
    """Rigid damper k meets its wall ``side`` at t (module text): the impulse applied to w
    (:func:`_kick`, μ = (1/mₖ + φₖᵀA⁻¹φₖ)⁻¹), the mass set on its wall, the loss
    ½μ(1 − e²)(approach speed)² added to the contacts' dissipation and the impact logged.
    Returns (count, log, the separation speed e·(approach speed), A⁻¹)."""
    xa, va = _point(pm, Phi, xb, t, w, k, N)
    u = w[2 * N + K + k]
    vrel = side * (u - va)  # the approach speed
    e = ed[k] if vrel > 0.0 else 0.0
    P, mu, Ainv, n_ev, events = _kick(events, n_ev, pm, Phi, md, stp, hd, xb, t, w, code, sides, Ainv,
                                      Phi[k], 1.0 / md[k], u - va, e, N, K)  # fmt: skip
    va1 = _point(pm, Phi, xb, t, w, k, N)[1]
    w[2 * N + K + k] = u - P / md[k]
    w[2 * N + k] = _on_wall(xa, side, hd[k])
    lost = 0.5 * mu * (1.0 - e * e) * vrel * vrel
    w[2 * N + 2 * K + 2] += lost
    n_ev, events = _log_row(events, n_ev, t, k, side, KIND_IMPACT, vrel, xa, va, u, va1,
                            w[2 * N + K + k], lost)  # fmt: skip
    return n_ev, events, e * vrel, Ainv


@compiled
def _closure(events, n_ev, pm, Phi, md, stp, hd, xb, t, w, k, side, N, K, code, sides, Ainv):
    """Damper k's chatter on its wall ``side`` reaches its accumulation point at t: the mass and
    its point close plastically (:func:`_kick` with e = 0, the loss ½μ(ẏₖ − ẋₐ)²), and the
    mass then rides on its point (code :data:`STUCK`, Step 15, item 5, as the modal engine
    takes it).  Returns (count, log, A⁻¹)."""
    xa, va = _point(pm, Phi, xb, t, w, k, N)
    u = w[2 * N + K + k]
    _, mu, Ainv, n_ev, events = _kick(events, n_ev, pm, Phi, md, stp, hd, xb, t, w, code, sides, Ainv,
                                      Phi[k], 1.0 / md[k], u - va, 0.0, N, K)  # fmt: skip
    va1 = _point(pm, Phi, xb, t, w, k, N)[1]
    lost = 0.5 * mu * (u - va) * (u - va)
    w[2 * N + 2 * K + 2] += lost
    w[2 * N + K + k] = va1
    w[2 * N + k] = xa + side * hd[k]
    code[k] = STUCK
    Ainv = mass_inverse(pm, Phi, md, code, stp, N, K)
    n_ev, events = _log_row(events, n_ev, t, k, side, KIND_ACCUMULATION, side * (u - va), xa, va,
                            u, va1, va1, lost)  # fmt: skip
    return n_ev, events, Ainv


@compiled
def _stop_impact(events, n_ev, pm, Phi, md, stp, hd, xb, t, w, r, side, N, K, code, sides, Ainv):
    """The point of rigid stop r meets its wall ``side`` at t (module text): Newton's law at the
    point, φᵀq̇⁺ = −e·φᵀq̇⁻, through P = −(1 + e)·m_eff·φᵀq̇, m_eff = (φᵀA⁻¹φ)⁻¹, q̇ += A⁻¹φP
    (Step 15's impact at a point against the ground, :func:`_kick`), its loss
    ½m_eff(1 − e²)(φᵀq̇)² added to the impacts' dissipation and the impact logged as the modal
    engine logs a stop's (damper K + r).  Returns (count, log, the separation speed
    e·(approach speed), A⁻¹)."""
    xs, vs = _stop_point(stp, w, r, N)
    vapp = side * vs  # the approach speed
    e = stp[r, N + 5] if vapp > 0.0 else 0.0  # ≤ 0: a rounding-level meeting (the engine's rule)
    _, meff, Ainv, n_ev, events = _kick(events, n_ev, pm, Phi, md, stp, hd, xb, t, w, code, sides, Ainv,
                                        stp[r, :N], 0.0, -vs, e, N, K)  # fmt: skip
    vs1 = 0.0
    for i in range(N):
        vs1 += stp[r, i] * w[N + i]
    lost = 0.5 * meff * (1.0 - e * e) * vapp * vapp
    w[2 * N + 2 * K + 2] += lost
    n_ev, events = _log_row(events, n_ev, t, K + r, side, KIND_IMPACT, vapp, xs, vs, 0.0, vs1,
                            0.0, lost)  # fmt: skip
    return n_ev, events, e * vapp, Ainv


@compiled
def _accumulation(a, e, wsep, chat_limit, t, t_end):
    """Step 9's test after an impact with restitution e that leaves the point (or the mass) at
    the separation speed ``wsep``, the wall accelerating toward it at a: the time 2·wsep/(a(1 −
    e)) in which its rebounds accumulate, when that is within ``chat_limit`` and ends before
    t_end (0 for a plastic impact), else −1 (no accumulation is taken)."""
    if a > 0.0 and e < 1.0:
        delta = 2.0 * wsep / (a * (1.0 - e))
        if delta <= chat_limit and t + delta < t_end:
            return delta
    return -1.0


@compiled
def _inside(stp, w, r, side, N):
    """Move stop r's point, just off its wall ``side`` (an impact or a release located on the
    wall's far side by rounding), to four units in the last place inside it, q −= cψ (ψ the
    point's shape), so that its next meeting of the wall is a crossing, not the root just
    located met again (a damper's mass is set just inside its wall for the same reason,
    :func:`_on_wall`)."""
    xs, pp = 0.0, 0.0
    for i in range(N):
        xs += stp[r, i] * w[i]
        pp += stp[r, i] * stp[r, i]
    c = (side * stp[r, N] * (1.0 - 4e-16) - xs) / pp
    if side * c < 0.0:
        for i in range(N):
            w[i] += c * stp[r, i]


@compiled
def _stop_closure(events, n_ev, pm, Phi, md, stp, hd, xb, t, w, r, side, N, K, code, sides,
                  Ainv):  # fmt: skip
    """The chatter of rigid stop r's point on its wall ``side`` reaches its accumulation point at
    t: the point stops there plastically (:func:`_kick` with e = 0 against the ground, the loss
    ½m_eff(φᵀq̇)²), and the wall then holds it (``stp``'s column N + 6) until it would pull, as
    the modal engine holds it.  Returns (count, log, B)."""
    xs, vs = _stop_point(stp, w, r, N)
    _, meff, Ainv, n_ev, events = _kick(events, n_ev, pm, Phi, md, stp, hd, xb, t, w, code, sides,
                                        Ainv, stp[r, :N], 0.0, -vs, 0.0, N, K)  # fmt: skip
    lost = 0.5 * meff * vs * vs
    w[2 * N + 2 * K + 2] += lost
    stp[r, N + 6] = side
    Ainv = mass_inverse(pm, Phi, md, code, stp, N, K)
    n_ev, events = _log_row(events, n_ev, t, K + r, side, KIND_ACCUMULATION, side * vs, xs, vs,
                            0.0, 0.0, 0.0, lost)  # fmt: skip
    return n_ev, events, Ainv


@compiled
def phase(pm, Phi, md, hd, code0, lq, chi, stp0, xb, Pout, t, q, v, y, u, k0, s0, t_end, period_max,
          atol, ed, chat_limit, contact0, stuck0):  # fmt: skip
    """Integrate from (q, q̇, y, ẏ) at t, where damper k0's contact on wall s0 has just begun,
    until no damper presses a wall or t_end (module text); the rigid dampers' impacts on the way
    with restitution ``ed``, their chatter taken to its accumulation point where it would end
    within ``chat_limit`` [s] (Step 9's test) and the mass then riding on its point until its
    wall would pull (each riding at the start on wall ``stuck0[k]``, 0: free), and the stops of
    ``stp0`` (:func:`_rhs`), each pressed (linear) or held (rigid) on wall ``contact0[s]`` at
    the start (0: not), their contacts' onsets and exits and the rigid ones' impacts
    (:func:`_stop_impact`), their chatter's accumulation and their holding until the wall
    would pull on the way, as the dampers'.  Returns (status, t, state, ledger rises (work, C's
    dissipation, the contacts' dissipation and the rigid impacts' losses, the stops' dashpots'
    dissipation), events (:data:`N_PHASE_COLS` columns; a stop's as damper K + s) of every
    onset, exit, impact, accumulation and release after k0's onset, their count, steps taken,
    each stop's wall pressed or held at the end, each damper's wall it rides on at the end)."""
    N, K = q.shape[0], y.shape[0]
    S = stp0.shape[0]
    n = 2 * N + 2 * K + 4 + S  # the state, the ledger, the held stops' reactions (:func:`_rhs`)
    stp = stp0.copy()
    T_f = 2.0 * math.pi / pm[0, P_W]
    n_periods = period_max.shape[0]
    code = code0.copy()
    w = np.zeros(n)
    w[:N], w[N : 2 * N], w[2 * N : 2 * N + K], w[2 * N + K : 2 * N + 2 * K] = q, v, y, u
    kk = np.empty((7, n))
    tmp, out, kout = np.empty(n), np.empty(n), np.empty(n)
    sides = np.zeros(K + S)
    pressing = np.zeros(K + S, dtype=np.int64)
    g1 = np.zeros(K + S)
    t_acc = np.full(K + S, np.inf)  # a rigid chatter's accumulation point, once decided
    for r in range(S):
        sides[K + r] = 1.0 if contact0[r] >= 0 else -1.0
        if stp[r, N + 4] != 0.0:
            stp[r, N + 6] = contact0[r]  # a rigid stop holding its point
        else:
            pressing[K + r] = 1 if contact0[r] != 0 else 0
    for k in range(K):
        xa = xb * math.cos(pm[0, P_W] * t + pm[0, P_PHI])
        for i in range(N):
            xa += Phi[k, i] * q[i]
        sides[k] = 1.0 if y[k] > xa else -1.0
        g1[k] = sides[k] * (y[k] - xa) - hd[k]
        if stuck0[k] != 0:
            code[k] = STUCK
            sides[k] = stuck0[k]
    sides[k0] = s0
    for k in range(K):  # pressing: past its wall, or as far as k0 on the same side
        if code[k] >= 0 and (g1[k] > 0.0 or (g1[k] >= g1[k0] and sides[k] == s0)):
            pressing[k] = 1
    pressing[k0] = 1
    Ainv = mass_inverse(pm, Phi, md, code, stp, N, K)
    events = np.zeros((16 + K, N_PHASE_COLS))
    left = np.zeros(K + S, dtype=np.int64)  # a rigid damper or stop that left its wall at the
    # step's start
    n_ev = 0
    for k in range(K):  # another damper that reaches its wall at the same instant begins too
        if k != k0 and pressing[k]:
            xa, va = _point(pm, Phi, xb, t, w, k, N)
            n_ev, events = _log_row(events, n_ev, t, k, sides[k], KIND_ONSET, sides[k] *
                                    (u[k] - va), xa, va, u[k], va, u[k], 0.0)  # fmt: skip
    for k in range(K):  # a rigid damper on a wall at the start has just left it
        if code[k] == RIGID and g1[k] >= -1e-9 * hd[k]:
            left[k] = 1
    _rhs(pm, Phi, md, hd, code, lq, chi, stp, xb, t, w, kk[0], N, K, Ainv)
    h = T_f * 1e-4
    status = 0
    steps = 0
    while t < t_end:
        steps += 1
        if steps > MAX_PHASE_STEPS:
            status = TOO_MANY_STEPS
            break
        # a damper already at its wall and leaving it (one that left with the last located
        # exit, at the same instant) ends here, not a step later
        which = -1
        for k in range(K):
            if pressing[k] and _delta(pm, Phi, hd, stp, xb, t, w, k, sides[k], N, K) <= 0.0:
                va = _point(pm, Phi, xb, t, w, k, N)[1]
                if sides[k] * (w[2 * N + K + k] - va) < 0.0:
                    which = k
                    break
        if which >= 0:
            n_ev, events = _ended(events, n_ev, pm, Phi, xb, t, w, which, sides, pressing, N, K)
            if pressing[:K].sum() == 0 and np.all(np.isinf(t_acc)):
                break
            continue
        # the step, cut short at the run's end or an accumulation point (the controller's h
        # stands: cut to zero at an accumulation point, it would have stayed zero)
        hs = min(h, t_end - t, np.min(t_acc) - t)
        err = _step(pm, Phi, md, hd, code, lq, chi, stp, xb, t, w, kk, hs, n, tmp, out, kout, atol,
                    N, K, Ainv)  # fmt: skip
        if err > 1.0:
            h = hs * max(0.2, 0.9 * err**-0.2)
            if h < 1e-14 * T_f:
                status = STEP_UNDERFLOW
                break
            continue
        # each compliant damper's δ at the step's end, on its wall (pressing) or the nearer one;
        # a riding mass's pull on its wall (:func:`_pull`)
        xa0 = xb * math.cos(pm[0, P_W] * (t + hs) + pm[0, P_PHI])
        crossed = False
        for k in range(K):
            g1[k] = 0.0
            if code[k] == STUCK:
                g = _pull(pm, Phi, xb, t + hs, kout, k, sides[k], N)
                if g > 0.0:
                    g1[k] = g
                    crossed = True
                continue
            if not np.isinf(t_acc[k]):
                continue  # its chatter is being taken to its accumulation point
            xa = xa0
            for i in range(N):
                xa += Phi[k, i] * out[i]
            side = sides[k] if pressing[k] else (1.0 if out[2 * N + k] > xa else -1.0)
            g = side * (out[2 * N + k] - xa) - hd[k]
            if (pressing[k] and g < 0.0) or (not pressing[k] and g > 0.0):
                if code[k] == RIGID and left[k] and side != sides[k]:
                    left[k] = 0  # it crossed to the other wall: a start inside the clearance
                g1[k] = g
                sides[k] = side
                crossed = True
        for r in range(S):  # each stop's point: past its gap (pressed) or back inside it
            j = K + r
            g1[j] = 0.0
            if stp[r, N + 6] != 0.0:  # held: does its wall's reaction turn to a pull?
                g = stp[r, N + 6] * kout[2 * N + 2 * K + 4 + r]
                if g > 0.0:
                    g1[j] = g
                    crossed = True
                continue
            if not np.isinf(t_acc[j]):
                continue  # its chatter is being taken to its accumulation point
            xs = 0.0
            for i in range(N):
                xs += stp[r, i] * out[i]
            side = sides[j] if pressing[j] else (1.0 if xs > 0.0 else -1.0)
            if not pressing[j] and side * stp[r, N + 3] < 0.0:
                continue  # no wall on that side
            g = side * xs - stp[r, N]
            if (pressing[j] and g < 0.0) or (not pressing[j] and g > 0.0):
                if left[j] and side != sides[j]:
                    left[j] = 0  # a rigid stop's point crossed to its other wall
                g1[j] = g
                sides[j] = side
                crossed = True
        first, which = hs, -1
        if crossed:  # the earliest onset, exit, impact or release in the step
            for k in range(K + S):
                if g1[k] == 0.0:
                    continue
                theta = _locate(pm, Phi, md, hd, code, lq, chi, stp, xb, t, w, kk, hs, g1[k], k,
                                sides[k], n, tmp, out, kout, atol, N, K,
                                left[k] == 1, Ainv)  # fmt: skip
                if which < 0 or theta < first:
                    first, which = theta, k
            _step(pm, Phi, md, hd, code, lq, chi, stp, xb, t, w, kk, first, n, tmp, out, kout, atol,
                  N, K, Ainv)  # fmt: skip
        _note(period_max, n_periods, T_f, t, first, Pout, pm, xb, w, out, N)
        t = t + first
        w[:] = out
        kk[0, :] = kout
        left[:] = 0
        riding = code.copy()
        holding = stp[:, N + 6].copy()
        closing = -1
        if which < 0:
            for k in range(K + S):
                if t >= t_acc[k] - 4e-16 * t_acc[k]:
                    closing = k
            if closing >= K:  # a stop's chatter's accumulation point: the wall holds from here
                t_acc[closing] = np.inf
                n_ev, events, Ainv = _stop_closure(events, n_ev, pm, Phi, md, stp, hd, xb, t, w,
                                                   closing - K, sides[closing], N, K, code, sides,
                                                   Ainv)  # fmt: skip
            elif closing >= 0:  # a chatter's accumulation point: the mass rides from here
                t_acc[closing] = np.inf
                n_ev, events, Ainv = _closure(events, n_ev, pm, Phi, md, stp, hd, xb, t, w, closing,
                                              sides[closing], N, K, code, sides, Ainv)  # fmt: skip
        elif (which >= K and stp[which - K, N + 6] != 0.0) or (which < K and code[which] == STUCK):
            # a held stop's or a riding mass's wall would pull: it is let go
            n_ev, events, Ainv = _let_go(events, n_ev, pm, Phi, md, stp, hd, xb, t, w, which,
                                         sides, code, N, K)  # fmt: skip
        elif which >= K and stp[which - K, N + 4] != 0.0:  # a rigid stop's impact
            r = which - K
            n_ev, events, wsep, Ainv = _stop_impact(events, n_ev, pm, Phi, md, stp, hd, xb, t, w, r,
                                                    sides[which], N, K, code, sides, Ainv)  # fmt: skip
            _rhs(pm, Phi, md, hd, code, lq, chi, stp, xb, t, w, kk[0], N, K, Ainv)
            acc = 0.0
            for i in range(N):
                acc += stp[r, i] * kk[0, N + i]
            a = sides[which] * acc  # the point's acceleration toward the wall
            e = stp[r, N + 5]
            left[which] = 1
            _inside(stp, w, r, sides[which], N)
            delta = _accumulation(a, e, wsep, chat_limit, t, t_end)
            if delta > 4e-16 * (t + delta):
                t_acc[which] = t + delta
            elif delta >= 0.0:  # plastic, or accumulating within the time's resolution: now
                left[which] = 0
                n_ev, events, Ainv = _stop_closure(events, n_ev, pm, Phi, md, stp, hd, xb, t, w, r,
                                                   sides[which], N, K, code, sides, Ainv)  # fmt: skip
        elif which >= K:  # a linear stop's contact begins or ends
            n_ev, events = _stop_ended(events, n_ev, stp, t, w, which, sides, pressing, N, K)
        elif code[which] == RIGID:
            n_ev, events, wsep, Ainv = _rigid_impact(events, n_ev, pm, Phi, md, stp, hd, ed, xb, t,
                                                     w, which, sides[which], N, K, code, sides,
                                                     Ainv)  # fmt: skip
            _rhs(pm, Phi, md, hd, code, lq, chi, stp, xb, t, w, kk[0], N, K, Ainv)
            acc = -xb * pm[0, P_W] ** 2 * math.cos(pm[0, P_W] * t + pm[0, P_PHI])
            for i in range(N):
                acc += Phi[which, i] * kk[0, N + i]
            a = -sides[which] * acc  # the point's acceleration toward the mass on its wall
            e = ed[which]
            left[which] = 1
            delta = _accumulation(a, e, wsep, chat_limit, t, t_end)
            if delta > 4e-16 * (t + delta):
                t_acc[which] = t + delta
            elif delta >= 0.0:  # plastic, or accumulating within the time's resolution: now
                left[which] = 0
                n_ev, events, Ainv = _closure(events, n_ev, pm, Phi, md, stp, hd, xb, t, w, which,
                                              sides[which], N, K, code, sides, Ainv)  # fmt: skip
        else:
            n_ev, events = _ended(events, n_ev, pm, Phi, xb, t, w, which, sides, pressing, N, K)
        for k in range(K):  # a mass let go (:func:`_let_go`) leaves its wall
            if riding[k] == STUCK and code[k] == RIGID:
                left[k] = 1
        for r in range(S):  # and so does a point let go by its stop
            if holding[r] != 0.0 and stp[r, N + 6] == 0.0:
                left[K + r] = 1
        if which >= 0 or closing >= 0:
            _rhs(pm, Phi, md, hd, code, lq, chi, stp, xb, t, w, kk[0], N, K, Ainv)
            if pressing[:K].sum() == 0 and np.all(np.isinf(t_acc)):
                break
            continue
        if hs < h:
            continue  # a step cut short: the controller's h stands
        if err < 1e-300:
            h = hs * 5.0
        else:
            h = hs * min(5.0, max(0.2, 0.9 * err**-0.2))
    state = w[: 2 * N + 2 * K].copy()
    ledger = w[2 * N + 2 * K : 2 * N + 2 * K + 4].copy()
    walls = np.zeros(S)
    for r in range(S):
        if pressing[K + r]:
            walls[r] = sides[K + r]
        walls[r] += stp[r, N + 6]
    stuck = np.zeros(K)
    for k in range(K):
        if code[k] == STUCK:
            stuck[k] = sides[k]
    return status, t, state, ledger, events[:n_ev].copy(), n_ev, steps, walls, stuck
