"""Compiled event-driven simulation of a structure of N modes carrying K impact dampers with
rigid impacts, chatter and sticking (numba, cached).

Between events everything is closed form.  While no mass sticks, mode i follows Step 8's forced
flight (Eq. F1) with its own Mᵢ, Kᵢ = ωᵢ²Mᵢ, Cᵢ = 2ζᵢωᵢMᵢ and modal force Fᵢ = Σⱼ F₀ⱼφᵢ(j)
(Step 15, item 1), written in the flight's own time (Step 8's ``flight_form``: its coefficients
once a flight, then at each time two functions of Ωτ shared by the modes, all driven at one Ω,
and three per mode; :func:`_free_states`); each impact mass k flies at constant speed.  An
impact of damper k at its point aₖ applies Step 15's law (item 4, Eq. F7): the impulse
P = (1 + e)·μ·(ẏ − ẋₐ), μ the reduced mass of m and the effective mass (Σφᵢ(a)²/Mᵢ)⁻¹, enters
each mode as q̇ᵢ += φᵢ(a)P/Mᵢ and leaves the mass as ẏ −= P/m.  One mode with φ = 1 is Step 9's impact (Eq. F2).

*Chatter and sticking* (Step 15, item 5).  When damper k's impacts on one wall would accumulate
within a fraction of a forcing period (Step 9's test, Δ = 2w/(a(1 − e)), with the point's
acceleration a), the run jumps to the accumulation point, where the mass and the point close
plastically (the impulse with e = 0), and the mass then rides on the point: the structure's modal
mass matrix becomes diag(Mᵢ) + Σ mₖφₖφₖᵀ over the stuck dampers.  The stuck structure is still
linear, but its modes are no longer the free ones (nor is the modal damping proportional in
them), so its flight is the closed form of the first-order system X' = AX + b·cos(Ωt + φ):
X(τ) = Re(V e^{Λτ} V⁻¹(X₀ − X_p(t₀))) + X_p(t₀ + τ), with A's eigen-decomposition V, Λ and the
harmonic particular solution X_p = Re(X̂ e^{i(Ωt + φ)}), X̂ = (iΩ − A)⁻¹b, computed once each time
the set of stuck dampers changes; a flight's columns Vₗcₗ are formed once per flight, and the
state is real, so each conjugate pair of Λ costs one exponential (:func:`_held_free`).  The
searches read such a flight at the few points they watch, not in its 2N states: its columns
projected once per flight on each point's shape give the point's displacement, speed and
acceleration (the closed form's derivatives) at each τ for one exponential per pair and a sum
per point (:func:`_held_rows`, :func:`_rows_at`; benchmark 10's 400-period 10-mode runs, whose
masses ride much of the time, went from 20.1 to 12.8 µs an event at the median of eight, without
the ledger).  A flight starts exactly where the last one ended: the sum's value at τ = 0, which
misses the start by the rounding of c, is subtracted (:func:`_held_free`; else a chatter beside
a riding mass met that offset at every flight and never accumulated).  A stuck
mass is released where sₖ·ẍₐ turns positive (the wall would pull), searched on the impact
search's certified grid (its chord bound on sₖ·ẍₐ) down to 1/64 of the shortest period and
located by Illinois regula falsi (:func:`_release`).  An
impact of another damper while masses stick uses the stuck structure's mass matrix; a stuck mass
whose wall would have to pull it during that impulse is released first and the impulse taken
again without it, unless its own return would accumulate within the same fraction of a period
(Step 9's test on the speed the impulse gives it away from its wall and its point's acceleration
back, the structure without it): that excursion is jumped over as any other chatter is, and the
mass stays on its wall (:func:`_returns_at_once`).  Without this rule two masses that settle on
their walls together release each other at every closure, and their chatter, interleaved, never
meets the test of either alone (a ten-mode cantilever: 5·10⁴ events in a quarter millisecond).

*The next event.*  Damper k's relative displacement zₖ = yₖ − φₖᵀq has |zₖ''| ≤ Aₖ: while no mass
sticks Aₖ = Σ|φᵢ(aₖ)|·Aᵢ, Aᵢ the one-mode bound of mode i's acceleration over the flight
(:func:`symimpact.forced.engine._rigid._accel_bound`); while masses stick, the sum over the stuck
system's modes of |φₖᵀVₗcₗ|·|λₗ|² (each decays, Re λₗ ≤ 0; the projections above) and the
harmonic part Ω²|φₖᵀX̂|.
All free dampers are marched together: an interval every bound clears is skipped, any other
halved, and each damper whose z crosses a wall there is bracketed and refined by Illinois regula
falsi, which reads the point's displacement from its Taylor polynomial about the bracket's middle
(:func:`_point_taylor`: the flight is a sum of Re(a·e^{μτ}) terms, so its coefficients cost one
evaluation and each look a Horner sum, its degree set to leave out less than 1e-17 of the terms);
the earliest crossing is the impact.  A crossing bracketed by a longer step is refined at
once and taken where nothing can come before it (:func:`_none_before`: its rate bounds the
approach, the chord bounds the rest); else the step is halved down to where any excursion beyond
a wall would be shallower than 1e-20 of the clearance.  The wall just left is kept off as in the
one-mode search (2w/Aₖ, and while the point's acceleration is certified to point away, with a
bound B on its second derivative of the same make, |λ|⁴ in place of |λ|²).

*Energy ledger.*  The work of the modal forces and the dissipation of the Cᵢ, in closed form
while the modes are uncoupled (each flight is a sum of two complex exponentials, and so is its
force: each product integrates exactly, :func:`_mode_ledger`); while masses stick, the same in
the coupled flight's terms (its q and q̇ are sums over Λ, iΩ and a constant: O(n²N) products a
flight, :func:`_held_ledger`), or by Gauss–Legendre rules on a flight shorter than one step of
the fastest rate (4 or 8 points, :func:`_flight_ledger`); summed over the modes (both hold while
masses stick: those only add inertia), and the impacts' and closures' losses.  The searches and
the periods' maxima step up to a sixteenth of the slowest period (:func:`_slowest`) and down to
what their bounds allow: a structure's highest modes set their finest step, not their coarsest.

The engine is four modules, each importing only those before it: the flight's closed forms and
bounds (:mod:`._modal_flight`), the searches for the next event (:mod:`._modal_search`), the
energy ledger and the periods' maxima (:mod:`._modal_ledger`), and this one, the run: the events'
impulses, closures and releases, the monodromy's saltations, the loop (:func:`run`).

Private: :mod:`symimpact.forced.structure_response` checks the input and builds the result.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from ..._compiled import compiled
from ..._interrupt import EVERY, INTERRUPTED, stop_requested
from ._borrowed import borrowed, borrowed_config
from ._modal_flight import (
    CONTACT,
    E_DAMPER,
    KIND_EXIT,
    KIND_ONSET,
    N_MODAL_EVENT_COLS,
    SINGULAR_STUCK,
    _base_a,
    _base_v,
    _base_x,
    _config,
    _dot,
    _held_rows,
    _mode_accel,
    _modes_of,
    _pattern,
    _point_accel,
    _states,
    _stuck_acceleration,
    _stuck_loads,
    _working_config,
)
from ._modal_ledger import (
    _segment,
)
from ._modal_search import (
    _held_index,
    _held_reactions,
    _next_contact,
    _next_impact,
    _release,
    _row_response,
    _stop_impulse,
    _stop_jump,
    _stop_release,
)
from ._rigid import (
    E_KIND,
    E_LOST,
    E_SIDE,
    E_T,
    E_VREL,
    KIND_ACCUMULATION,
    KIND_IMPACT,
    KIND_RELEASE,
    N_EVENT_COLS,
    OK,
    P_C,
    P_CHAT,
    P_F0,
    P_K,
    P_M,
    P_PHI,
    P_VY,
    P_W,
    P_XB,
    TOO_MANY_EVENTS,
    P_e,
    P_h,
    P_m,
    _grow,
    _transition,
    restitution,
)


@compiled
def _returns_at_once(cfg, Phi, md, stuck, xb, j, k, e, u, t, q, v_before, ed, vyd, limit, vt):
    """Whether stuck damper j, released by damper k's impulse (restitution e, mass speed u, the
    structure's velocities ``v_before``), would be back on its wall within ``limit`` [s]: its
    excursion's chatter would accumulate by Step 9's test, 2σ/(a(1 − eⱼ)) ≤ limit, σ > 0 the speed
    the impulse (taken without j) gives its point away from it and a > 0 its point's acceleration
    back at t (``vt``: scratch).  Such a release is jumped over, as any chatter that short is
    (module text).  ``cfg``: the structure without j (:func:`_config`; :func:`run` passes the
    one it keeps for that pattern: formed anew at each such impact, it was 4 % of benchmark 10's
    10-mode run)."""
    if vyd[j] > 0.0 or ed[j] >= 1.0:
        return False
    side = stuck[j]
    if not cfg[5]:
        return False
    pm = cfg[7]
    others = 0
    for i in range(stuck.shape[0]):
        if stuck[i] != 0 and i != j:
            others += 1
    vt[:] = v_before
    _impulse(pm, cfg, others, Phi, k, md[k], e, u, vt, _base_v(pm, xb, t))
    sigma = side * (_dot(Phi, j, vt) - _dot(Phi, j, v_before))
    a = -side * _point_accel(pm, cfg, others, Phi, j, t, q, vt, xb)
    return sigma > 0.0 and a > 0.0 and 2.0 * sigma / (a * (1.0 - ed[j])) <= limit


@compiled
def _impulse(pm, cfg, nstuck, Phi, row, m, e, u, v, vb):
    """Step 15's impact (Eq. F7) of a mass m with speed u on the point of shapes ``Phi[row]``, the
    structure's velocities ``v`` (changed in place) and the supports' ``vb`` (the point moves at
    vb + φᵀq̇): returns (P, μ), P the impulse on the structure (P/m leaves the mass).  While
    masses stick, the structure's mass matrix is the stuck one: 1/m_eff = φᵀM_s⁻¹φ and
    q̇ += M_s⁻¹φP."""
    N = pm.shape[0]
    xd, inv = vb, 0.0
    for i in range(N):
        xd += Phi[row, i] * v[i]
    if cfg[6]:
        for i in range(N):
            inv += Phi[row, i] * Phi[row, i] / pm[i, P_M]
    else:
        Minv = cfg[0][0]
        for i in range(N):
            for j in range(N):
                inv += Phi[row, i] * Minv[i, j] * Phi[row, j]
    mu = m / (1.0 + m * inv)
    P = (1.0 + e) * mu * (u - xd)
    if cfg[6]:
        for i in range(N):
            v[i] += Phi[row, i] * P / pm[i, P_M]
    else:
        Minv = cfg[0][0]
        dv = np.zeros(N)
        for i in range(N):
            for j in range(N):
                dv[i] += Minv[i, j] * Phi[row, j] * P
        v += dv
    return P, mu


@compiled
def _wall_kept(stuck, z, hd, j):
    """The wall (±1) free damper j starts the next flight on where it sits on it, to 1e-9 of its
    half clearance (a mass let go, or met, at the instant of another's event), else 0.  Forgotten,
    the search met that wall again at once at rounding-level speeds, and two masses at one point
    passed the meeting back and forth millions of times; kept for a mass that approaches it, it
    holds nothing off (:func:`_next_impact` holds a wall off only while the mass leaves it)."""
    if stuck[j] != 0 or abs(z[j]) < hd[j] * (1.0 - 1e-9):
        return 0
    return 1 if z[j] > 0.0 else -1


@compiled
def _log(events, n_ev, t, x, xd, yd, s, vrel, lost, kind, xd1, yd1, k):
    events = _grow(events, n_ev)
    ev = events[n_ev]
    ev[E_T], ev[1], ev[2], ev[3], ev[E_SIDE] = t, x, xd, yd, s
    ev[E_VREL], ev[E_LOST], ev[E_KIND], ev[8], ev[9] = vrel, lost, kind, xd1, yd1
    ev[E_DAMPER] = k
    return events, n_ev + 1


# --- the monodromy: the flights' transition matrices and the events' saltation matrices -------


@compiled
def _flight_jacobian(pm, cfg, K, tau, G):
    """G ← Φ(τ)·G over a flight of τ: per mode Step 8's Φᵢ(τ) (the generated
    ``forced_transition``, which the forcing does not enter) while the modes are uncoupled, else
    Re(V e^{Λτ} V⁻¹) of the coupled structure (:func:`_config`); each free mass y += τ·ẏ.  The
    state is (q, q̇, y, ẏ): 2N + 2K."""
    N = pm.shape[0]
    D = 2 * N + 2 * K
    F = np.zeros((D, D))
    if cfg[6]:
        for i in range(N):
            M, Ki, C = pm[i, P_M], pm[i, P_K], pm[i, P_C]
            _, _, p11, p12, p21, p22 = _transition(tau, M, Ki, C, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0)
            F[i, i], F[i, N + i], F[N + i, i], F[N + i, N + i] = p11, p12, p21, p22
    else:
        lam, V, Vinv, _ = _modes_of(cfg)
        g = np.exp(lam * tau)
        for i in range(2 * N):
            for j in range(2 * N):
                acc = 0.0j
                for m in range(lam.shape[0]):
                    acc += V[i, m] * g[m] * Vinv[m, j]
                F[i, j] = acc.real
    for k in range(K):
        F[2 * N + k, 2 * N + k] = 1.0
        F[2 * N + k, 2 * N + K + k] = tau
        F[2 * N + K + k, 2 * N + K + k] = 1.0
    G[:, :] = F @ G


@compiled
def _field(pm, cfg, K, t, q, v, u, out):
    """The state's rate f = (q̇, q̈, ẏ, 0) of the free masses' flight (q̈: each mode's Eq. F1, or
    the coupled structure's, :func:`_stuck_acceleration`)."""
    N = pm.shape[0]
    for i in range(N):
        out[i] = v[i]
    if cfg[6]:
        for i in range(N):
            out[N + i] = _mode_accel(pm, i, pm[i, P_M], t, q[i], v[i])
    else:
        r = _stuck_loads(pm, cfg, t, q, v)
        for i in range(N):
            out[N + i] = _stuck_acceleration(cfg, r, i)
    for k in range(K):
        out[2 * N + k] = u[k]
        out[2 * N + K + k] = 0.0


@compiled
def _saltation(DJ, fm, fp, gh, G):
    """G ← S·G with S = D + (f⁺ − D·f⁻)∇hᵀ/(∇h·f⁻): the jump's Jacobian D and the effect of the
    event's time, which moves with the state (h = 0 on the switching surface, f∓ the rates just
    before and after)."""
    den = gh @ fm
    r = fp - DJ @ fm
    S = DJ + np.outer(r, gh) / den
    G[:, :] = S @ G


@compiled
def _timed_saltation(DJ, fm, fp, gh, gt, jt, G):
    """G ← S·G with S = D + (f⁺ − D·f⁻ − ∂J/∂t)∇hᵀ/(∇h·f⁻ + ∂h/∂t): :func:`_saltation` for a
    surface h and a jump J that move with time (a damper's wall on supports that move:
    ``gt`` = ∂h/∂t, ``jt`` = ∂J/∂t)."""
    den = gh @ fm + gt
    r = fp - DJ @ fm - jt
    S = DJ + np.outer(r, gh) / den
    G[:, :] = S @ G


@compiled
def _impact_jump(pm, cfg, Phi, k, K, m, e, mu):
    """D: the Jacobian of Step 15's impact law (Eq. F7) of damper k in the state (q, q̇, y, ẏ):
    q̇ += M_s⁻¹φ·P, ẏₖ −= P/m with P = (1 + e)μ(ẏₖ − φᵀq̇), linear in the speeds."""
    N = pm.shape[0]
    D = 2 * N + 2 * K
    DJ = np.eye(D)
    w = np.zeros(N)
    for i in range(N):
        if cfg[6]:
            w[i] = Phi[k, i] / pm[i, P_M]
        else:
            for j in range(N):
                w[i] += cfg[0][0][i, j] * Phi[k, j]
    c = (1.0 + e) * mu
    ku = 2 * N + K + k
    for i in range(N):
        for j in range(N):
            DJ[N + i, N + j] -= c * w[i] * Phi[k, j]
        DJ[N + i, ku] += c * w[i]
    for j in range(N):
        DJ[ku, N + j] += c * Phi[k, j] / m
    DJ[ku, ku] -= c / m
    return DJ


@compiled
def _slaved(G, Phi, stuck, N, K):
    """G's rows of each stuck mass k set from its point: while it rides on it, yₖ = φₖᵀq + x_b ± dₖ/2
    and ẏₖ = φₖᵀq̇ + ẋ_b for every motion near this one, so at a fixed time δyₖ = φₖᵀδq and
    δẏₖ = φₖᵀδq̇ (the state (q, q̇, y, ẏ): 2N + 2K)."""
    for k in range(K):
        if stuck[k] == 0:
            continue
        for c in range(G.shape[1]):
            dy, du = 0.0, 0.0
            for i in range(N):
                dy += Phi[k, i] * G[i, c]
                du += Phi[k, i] * G[N + i, c]
            G[2 * N + k, c] = dy
            G[2 * N + K + k, c] = du


@compiled
def _accel_gradient(pm, cfg, Phi, row, t, xb, out):
    """∂A/∂t, with ∇A written into ``out`` (its q and q̇ entries; the rest 0): A = φᵀq̈ + ẍ_b, the
    acceleration of the point of row ``row`` of ``Phi``, q̈ = M_s⁻¹(Pcos θ + Qsin θ + f_s − C_sq̇
    − K_sq) (:func:`_stuck_loads`), so ∂A/∂q = −φᵀM_s⁻¹K_s, ∂A/∂q̇ = −φᵀM_s⁻¹C_s and
    ∂A/∂t = φᵀM_s⁻¹Ω(Qcos θ − Psin θ) + Ω³X_b sin θ."""
    N = pm.shape[0]
    Minv, Ks, Cs = cfg[0][0], cfg[0][1], cfg[0][2]
    W = pm[0, P_W]
    th = W * t + pm[0, P_PHI]
    c, sn = math.cos(th), math.sin(th)
    out[:] = 0.0
    dt = xb * W * W * W * sn if xb != 0.0 else 0.0
    for i in range(N):
        for j in range(N):
            wij = Phi[row, i] * Minv[i, j]
            if wij == 0.0:
                continue
            P = pm[j, P_F0] + pm[j, P_K] * pm[j, P_XB]
            Q = -pm[j, P_C] * W * pm[j, P_XB]
            dt += wij * W * (Q * c - P * sn)
            for m in range(N):
                out[m] -= wij * Ks[j, m]
                out[N + m] -= wij * Cs[j, m]
    return dt


@compiled
def _accumulation_row(pm, cfg, Phi, k, K, t, s, w, a, delta, xb, r_i, fp, G, grad, r_inf):
    """r_inf ← δt∞, the row of the accumulation time's change in the run's starting state, for a
    chatter of damper k on its wall s that begins with the impact at t (Step 9's accumulation
    point, :func:`run`): t∞ = t + Δ, Δ = 2w/(a(1 − e)) with the separation speed
    w = −s(ẏₖ − φᵀq̇ − ẋ_b) and a = −s·A (:func:`_accel_gradient`) just after the impact, so
    ∇Δ = Δ(∇w/w − ∇a/a) and ∂Δ/∂t = Δ(sẍ_b/w + s(∂A/∂t)/a).  The impact itself comes δt = r_i·δ
    later, where the state just after it is X⁺ + f⁺δt (f⁺ = ``fp``, X⁺'s perturbation G·δ at the
    unperturbed time), so δt∞ = r_i(1 + ∂Δ/∂t + ∇Δ·f⁺) + ∇Δ·G.  A plastic impact (w = 0) has
    Δ = 0 for every nearby motion: δt∞ = δt."""
    N = pm.shape[0]
    if w == 0.0:
        r_inf[:] = r_i
        return
    At = _accel_gradient(pm, cfg, Phi, k, t, xb, grad)
    for j in range(grad.shape[0]):
        grad[j] = delta * s * grad[j] / a
    for i in range(N):
        grad[N + i] += delta * s * Phi[k, i] / w
    grad[2 * N + K + k] -= delta * s / w
    Dt = delta * (s * _base_a(pm, xb, t) / w + s * At / a)
    scale = 1.0 + Dt + grad @ fp
    r_inf[:] = scale * r_i + grad @ G


@compiled
def _kept_alive(owned, cfgs):
    """Nothing: its call at the end of :func:`run` keeps the run's own arrays and configurations
    alive until then, under the borrowed views the run works with (:mod:`._borrowed`)."""
    return len(owned) + len(cfgs)


@compiled
def run(pm0, Phi, md, hd, ed, vyd, law, chat, Sphi, sg, sside, sk, sc, srig, se, q0, v0, y0, u0,
        Pout, xb, t0, t_end, max_events, variational, stuck0, held0, energy, watch):  # fmt: skip
    """Simulate the structure (modes: rows of ``pm0``, the one-mode parameter layout of
    :mod:`symimpact.forced.engine._rigid`; dampers: shapes ``Phi, k`` at their points, masses ``md``,
    half clearances ``hd``, restitution ``ed`` with yield speeds ``vyd`` (0: constant e; else
    Step 13's e(v), Eq. F5, which tends to 1 at low speed, so chatter never accumulates); chatter taken to its accumulation point when it
    would end within ``chat`` forcing periods) and stops (shapes ``Sphi, s`` at their points, gaps
    ``sg``, walls ``sside``: +1 at +g, −1 at −g, 0 both; linear contact laws k₁ = ``sk``,
    c₁ = ``sc``: each pressed stop changes the structure's closed form, :func:`_config`; or,
    where ``srig[s]``, rigid impacts of restitution ``se``, whose chatter is taken to its
    accumulation point as a damper's and then holds the point on the wall until the wall would
    pull) from
    modal state (q0, v0) and the masses' (y0, u0) at t = ``t0`` to t_end (a point past a wall at
    t0 starts pressing it).  A damper with ``law[k]`` ≥ 0 (a compliant law's code) ends the run
    where its contact begins, with status :data:`CONTACT` and that onset logged last.  ``xb``: the supports' displacement amplitude X_b [m], x_b =
    X_b·cos(Ωt + φ) with the force's Ω and φ (0: fixed supports).  The modes are then relative
    to the supports (their load −MᵢΓᵢẍ_b is in ``pm0``'s forces), the masses absolute, and a
    damper's point moves at x_b + φᵀq (its walls, and the output points' displacements, go with
    it; a stop's wall is fixed to the ground, which moves with the supports: it stays relative).
    The ledger then closes on the masses' kinetic energies relative to the supports,
    ½m(ẏ − ẋ_b)²: each free mass's change in flight is the work of its inertia −m·ẍ_b.
    Without ``energy`` the flights' work and dissipation are not integrated
    (:func:`_flight_ledger`: with a mass riding on a mode shape's point, Gauss–Legendre rules at
    the highest mode's rate, 38 % of the fastest 10-mode run of benchmark 10, 26 % at the median
    of its eight) and the ledger is not whole; the motion is the same to the bit.

    Returns (status, events, n_events, period_max, ledger, final): the event log (columns of
    :mod:`symimpact.forced.engine._rigid` and E_DAMPER; columns 1, 2, 3, 8, 9 hold the point's
    displacement, its velocity and the mass's before and after; a stop's contact onset or exit,
    kinds KIND_ONSET and KIND_EXIT, has E_DAMPER = K + s, its wall in E_SIDE and the point's
    speed in E_VREL), ``period_max[k, p]`` the largest abs(x) at output point p in forcing period
    k, ledger = (work of the forces, dissipation of the Cᵢ, loss in impacts, dissipation of the
    stops' dashpots), final = (t, q…, q̇…, y…, ẏ…, stuck…, contact…), and with
    ``variational`` G = ∂(q, q̇, y, ẏ)(t_end)/∂(q, q̇, y, ẏ)(0), the chain of the flights'
    transition matrices and the events' saltation matrices (:func:`_flight_jacobian`,
    :func:`_saltation`), through a chatter's accumulation point, the plastic closure and the
    stuck structure's flight (:func:`_accumulation_row`, :func:`_slaved`) and a release (where
    the wall would pull, the mass's acceleration and the point's are 0: the identity); NaN where
    the run is not differentiable so (a mass starts on a wall, within 1e-9 of its half
    clearance: the map's sides differ there; an impulse lets a stuck mass go; a mass sticks
    while stops are in the run, or a stop holds its point; e varies with the speed; or an event
    meets its surface at zero rate).
    """
    N, K = pm0.shape[0], Phi.shape[0]
    T_f = 2.0 * math.pi / pm0[0, P_W]
    n_periods = int(math.floor(t_end / T_f + 0.5))  # noqa: RUF046 (int() spelled out for numba)
    period_max = np.zeros((n_periods + 1, Pout.shape[0]))
    ledger = np.zeros(4)
    events = np.zeros((64, N_MODAL_EVENT_COLS))
    S = Sphi.shape[0]
    contact = np.zeros(S, dtype=np.int64)
    for r in range(S):
        xs = _dot(Sphi, r, q0)
        if sside[r] >= 0 and xs > sg[r]:
            contact[r] = 1
        elif sside[r] <= 0 and xs < -sg[r]:
            contact[r] = -1
        if srig[r] != 0 and held0[r] != 0:  # a rigid stop holding its point (a contact phase
            contact[r] = 1 if held0[r] > 0 else -1  # left it so), its point on its wall
    fresh, fresh_wall = -1, 0
    pulls = np.empty(S)
    n_ev = 0
    t = t0
    q, v = q0.copy(), v0.copy()
    qn, vn = np.empty(N), np.empty(N)
    u = u0.copy()
    z = np.empty(K)
    side0 = np.zeros(K, dtype=np.int64)
    stuck = np.zeros(K, dtype=np.int64)
    nstuck = 0
    cfg = _config(pm0, Phi, md, stuck, Sphi, sk, sc, sg, contact, srig, xb)
    pm = cfg[7]
    keys = [_pattern(stuck, contact)]
    cfgs = [cfg]
    P = Pout.shape[0]
    # scratch for the searches and the ledger, allocated once: bounds A, B and the held-off
    # times of the dampers; two state buffers; z at the grid's ends; two more state buffers;
    # the release search's last values; the output points' bounds, last velocities and
    # displacements; the stops' bounds A, B, displacements at the grid's ends and held-off times
    # (one array, its rows: a tuple of arrays costs a reference count per array at every call)
    work = np.empty((22, max(N, K, P, S)))
    # a coupled flight projected on the dampers' points and on the output points, with their
    # scratch (:func:`_held_rows`)
    rows_k, out_k = np.zeros((K, 3, 2 * N + 2), dtype=np.complex128), np.zeros((K, 4))
    rows_p, out_p = np.zeros((P, 3, 2 * N + 2), dtype=np.complex128), np.zeros((P, 4))
    D = 2 * N + 2 * K
    G = np.eye(D)
    fm, fp, gh = np.empty(D), np.empty(D), np.zeros(D)
    # through a chatter: G through the closure's jump, the impact's and the accumulation's
    # time rows, the gradient of the accumulation time, the closure's time column
    Dv = D if variational else 0  # none of them without the chain
    Gjump = np.empty((Dv, Dv))
    r_i, r_inf, grad, closing = np.zeros(Dv), np.zeros(Dv), np.empty(Dv), np.zeros(Dv)
    smooth = variational
    v_before = np.empty(N)
    let_go = np.zeros(K, dtype=np.int64)
    kept = np.zeros(K, dtype=np.int64)
    v_trial = np.empty(N)
    # the run's arrays borrowed (:mod:`._borrowed`): the searches' loops then count no
    # references to them; ``owned`` keeps the locals alive to the end of the run, the caller
    # the arguments, and ``cfgs`` the configurations
    owned = (q, v, qn, vn, u, z, side0, stuck, work, contact, pulls, fm, fp, gh, v_before,
             let_go, kept, v_trial, rows_k, out_k, rows_p, out_p)  # fmt: skip
    rows_k, out_k, rows_p, out_p = (borrowed(rows_k), borrowed(out_k), borrowed(rows_p),
                                    borrowed(out_p))  # fmt: skip
    q, v, qn, vn, u, z = (borrowed(q), borrowed(v), borrowed(qn), borrowed(vn), borrowed(u),
                          borrowed(z))  # fmt: skip
    side0, stuck, work, contact = (borrowed(side0), borrowed(stuck), borrowed(work),
                                   borrowed(contact))  # fmt: skip
    pulls, fm, fp, gh = borrowed(pulls), borrowed(fm), borrowed(fp), borrowed(gh)
    v_before, let_go, kept, v_trial = (borrowed(v_before), borrowed(let_go), borrowed(kept),
                                       borrowed(v_trial))  # fmt: skip
    pm0, Phi, md, hd, ed, vyd, law = (borrowed(pm0), borrowed(Phi), borrowed(md), borrowed(hd),
                                      borrowed(ed), borrowed(vyd), borrowed(law))  # fmt: skip
    Sphi, sg, sside, sk, sc, srig, se = (borrowed(Sphi), borrowed(sg), borrowed(sside),
                                         borrowed(sk), borrowed(sc), borrowed(srig),
                                         borrowed(se))  # fmt: skip
    Pout, watch = borrowed(Pout), borrowed(watch)
    cfg = borrowed_config(cfg)
    pm = cfg[7]
    for k in range(K):
        z[k] = y0[k] - _dot(Phi, k, q) - _base_x(pm0, xb, t0)
        if abs(z[k]) >= hd[k]:
            side0[k] = 1 if z[k] > 0 else -1
            z[k] = side0[k] * hd[k]
        if abs(z[k]) >= hd[k] * (1.0 - 1e-9):
            smooth = False  # on its wall at the start: the map's two sides differ
    status = OK
    for k in range(K):  # a mass riding on its point at the start (a contact phase left it so)
        if stuck0[k] != 0:
            stuck[k] = 1 if stuck0[k] > 0 else -1
            side0[k] = stuck[k]
            z[k] = stuck[k] * hd[k]
            u[k] = _dot(Phi, k, v) + _base_v(pm0, xb, t0)
            nstuck += 1
    if nstuck > 0:
        cfg = _working_config(keys, cfgs, pm0, Phi, md, stuck, Sphi, sk, sc, sg, contact, srig,
                              xb)  # fmt: skip
        pm = cfg[7]
        if not cfg[5]:
            status = SINGULAR_STUCK
            t_end = t0
    looks = 0
    while t < t_end:
        if n_ev + 2 > max_events:
            status = TOO_MANY_EVENTS
            break
        looks += 1
        if (looks & (EVERY - 1)) == 0 and stop_requested(watch):
            status = INTERRUPTED
            break
        T = t_end - t
        kr = -1
        if not cfg[6]:
            _held_rows(pm, cfg, Phi, t, q, v, rows_k, out_k)
        if nstuck > 0:
            T, kr = _release(pm, cfg, nstuck, stuck, Phi, t, q, v, T, watch, work, rows_k,
                             out_k, xb)  # fmt: skip
        ks, ws = -1, 0
        held = 0
        for r in range(S):
            if contact[r] != 0 and srig[r] != 0:
                held += 1
        if held > 0:
            T_h, kh = _stop_release(pm, cfg, Sphi, contact, srig, t, q, v, T, watch, work)
            if kh >= 0:
                T, kr, ks, ws = T_h, -1, kh, 0
        if S > 0:
            taus, kc, wc = _next_contact(pm, cfg, nstuck, Sphi, sg, sside, contact, srig, fresh,
                                         fresh_wall, t, q, v, T, watch, work)  # fmt: skip
            if kc != -1:
                T, ks, ws = taus, kc, wc
                kr = -1
        tau, k, side = _next_impact(pm, cfg, nstuck, stuck, Phi, hd, t, q, v, z, u, side0, T,
                                    watch, work, rows_k, out_k, xb)  # fmt: skip
        _segment(pm, cfg, nstuck, Pout, t, q, v, tau, ledger, period_max, n_periods, work, Sphi,
                 sc, contact, rows_p, out_p, xb, energy)  # fmt: skip
        _states(pm, cfg, nstuck, t, q, v, tau, qn, vn)
        if smooth:
            _flight_jacobian(pm, cfg, K, tau, G)
            if nstuck > 0:
                _slaved(G, Phi, stuck, N, K)
        shift = _base_x(pm, xb, t + tau) - _base_x(pm, xb, t)
        vb0, vb1 = _base_v(pm, xb, t), _base_v(pm, xb, t + tau)
        for j in range(K):
            if stuck[j] == 0:
                z[j] = z[j] + u[j] * tau - _dot(Phi, j, qn) + _dot(Phi, j, q) - shift
                if xb != 0.0:
                    ledger[0] += 0.5 * md[j] * ((u[j] - vb1) ** 2 - (u[j] - vb0) ** 2)
            else:
                u[j] = _dot(Phi, j, vn) + vb1
        t = t + tau
        q[:] = qn
        v[:] = vn
        fresh, fresh_wall = -1, 0
        if k < 0 and ks >= 0 and tau >= T and srig[ks] != 0:
            smooth = smooth and ws != 0
            if ws == 0:
                # --- held stop ks is let go: its wall would pull ---
                wall = contact[ks]
                contact[ks] = 0
                cfg = _working_config(keys, cfgs, pm0, Phi, md, stuck, Sphi, sk, sc, sg, contact,
                                      srig, xb)  # fmt: skip
                pm = cfg[7]
                fresh, fresh_wall = ks, wall
                xd = _dot(Sphi, ks, v)
                events, n_ev = _log(events, n_ev, t, _dot(Sphi, ks, q), xd, 0.0, float(wall), 0.0,
                                    0.0, KIND_RELEASE, xd, 0.0, K + ks)  # fmt: skip
                continue
            # --- a rigid impact of stop ks's point on its wall ws ---
            sw = float(ws)
            vapp = sw * _dot(Sphi, ks, v)  # approach speed
            es = se[ks] if vapp > 0.0 else 0.0  # ≤ 0: a rounding-level meeting (dampers' rule)
            if smooth:
                _field(pm, cfg, K, t, q, v, u, fm)
            v_before[:] = v
            while True:  # a held stop whose wall would have to pull during the impulse is let go
                v[:] = v_before
                J, meff = _stop_impulse(pm, cfg, Sphi, ks, es, v)
                h = 0
                if held > 0:  # the walls' reaction impulses to J at the point
                    h = _held_reactions(
                        cfg, Sphi, contact, srig, _row_response(cfg, Sphi, ks, J), pulls
                    )
                pulled = -1
                for i in range(h):
                    if pulls[i] > 0.0:
                        pulled = _held_index(contact, srig, i)
                        break
                if pulled < 0:
                    break
                wall = contact[pulled]
                contact[pulled] = 0
                held -= 1
                cfg = _working_config(keys, cfgs, pm0, Phi, md, stuck, Sphi, sk, sc, sg, contact,
                                      srig, xb)  # fmt: skip
                pm = cfg[7]
                events, n_ev = _log(events, n_ev, t, _dot(Sphi, pulled, q), 0.0, 0.0, float(wall),
                                    0.0, 0.0, KIND_RELEASE, 0.0, 0.0, K + pulled)  # fmt: skip
            lost = 0.5 * meff * (1.0 - es * es) * vapp * vapp
            ledger[2] += lost
            events, n_ev = _log(events, n_ev, t, _dot(Sphi, ks, q), sw * vapp, 0.0, sw, vapp, lost,
                                KIND_IMPACT, _dot(Sphi, ks, v), 0.0, K + ks)  # fmt: skip
            if smooth:
                _field(pm, cfg, K, t, q, v, u, fp)
                gh[:] = 0.0
                gh[:N] = Sphi[ks]
                _saltation(_stop_jump(pm, cfg, Sphi, ks, K, es), fm, fp, gh, G)
            for j in range(K):
                if stuck[j] != 0:
                    u[j] = _dot(Phi, j, v) + _base_v(pm, xb, t)
            fresh, fresh_wall = ks, ws
            # --- chatter on the stop: would the rebounds accumulate (Step 9's test)? ---
            a = sw * _point_accel(pm, cfg, nstuck, Sphi, ks, t, q, v, 0.0)  # toward the wall
            wr = es * vapp
            if a > 0.0 and es < 1.0:
                delta = 2.0 * wr / (a * (1.0 - es))
                if delta <= chat * T_f and t + delta < t_end:
                    smooth = False
                    _segment(pm, cfg, nstuck, Pout, t, q, v, delta, ledger, period_max,
                             n_periods, work, Sphi, sc, contact, rows_p, out_p, xb,
                             energy)  # fmt: skip
                    _states(pm, cfg, nstuck, t, q, v, delta, qn, vn)
                    shift = _base_x(pm, xb, t + delta) - _base_x(pm, xb, t)
                    vb0, vb1 = _base_v(pm, xb, t), _base_v(pm, xb, t + delta)
                    for j in range(K):
                        if stuck[j] == 0:
                            z[j] = z[j] + u[j] * delta - _dot(Phi, j, qn) + _dot(Phi, j, q) - shift
                            if xb != 0.0:
                                ledger[0] += 0.5 * md[j] * ((u[j] - vb1) ** 2 - (u[j] - vb0) ** 2)
                        else:
                            u[j] = _dot(Phi, j, vn) + vb1
                    t = t + delta
                    q[:] = qn
                    v[:] = vn
                    xd = _dot(Sphi, ks, v)
                    J, meff = _stop_impulse(pm, cfg, Sphi, ks, 0.0, v)
                    lost = 0.5 * meff * xd * xd
                    ledger[2] += lost
                    for j in range(K):
                        if stuck[j] != 0:
                            u[j] = _dot(Phi, j, v) + _base_v(pm, xb, t)
                    events, n_ev = _log(events, n_ev, t, _dot(Sphi, ks, q), xd, 0.0, sw,
                                        sw * xd, lost, KIND_ACCUMULATION, _dot(Sphi, ks, v), 0.0,
                                        K + ks)  # fmt: skip
                elif wr != 0.0 and delta != 0.0:
                    continue
                # --- the point rests on the wall from here ---
                smooth = False
                contact[ks] = ws
                cfg = _working_config(keys, cfgs, pm0, Phi, md, stuck, Sphi, sk, sc, sg, contact,
                                      srig, xb)  # fmt: skip
                pm = cfg[7]
                if not cfg[5]:
                    status = SINGULAR_STUCK
                    break
                fresh, fresh_wall = -1, 0
            continue
        if k < 0 and ks >= 0 and tau >= T:
            # --- stop ks's contact begins (on wall ws) or ends ---
            wall = ws if ws != 0 else contact[ks]
            if smooth:
                _field(pm, cfg, K, t, q, v, u, fm)
            contact[ks] = ws
            cfg = _working_config(keys, cfgs, pm0, Phi, md, stuck, Sphi, sk, sc, sg, contact,
                                  srig, xb)  # fmt: skip
            pm = cfg[7]
            if smooth:  # the state is continuous, the rate jumps by the dashpot's force
                _field(pm, cfg, K, t, q, v, u, fp)
                gh[:] = 0.0
                gh[:N] = Sphi[ks]
                _saltation(np.eye(D), fm, fp, gh, G)
            fresh = ks
            xd = _dot(Sphi, ks, v)
            events, n_ev = _log(events, n_ev, t, _dot(Sphi, ks, q), xd, 0.0, float(wall),
                                abs(xd), 0.0, KIND_ONSET if ws != 0 else KIND_EXIT, xd, 0.0,
                                K + ks)  # fmt: skip
            if not cfg[5]:
                status = SINGULAR_STUCK
                break
            continue
        if k < 0 and kr >= 0 and tau >= T and t < t_end:
            # --- release of damper kr: it leaves its wall with the point's velocity (where its
            # wall would begin to pull: the mass's and the point's accelerations are both 0
            # there, so the two vector fields agree and the saltation is the identity) ---
            s = float(stuck[kr])
            stuck[kr] = 0
            nstuck -= 1
            cfg = _working_config(keys, cfgs, pm0, Phi, md, stuck, Sphi, sk, sc, sg, contact,
                                  srig, xb)  # fmt: skip
            pm = cfg[7]
            for j in range(K):  # a mass let go or met at this same instant keeps its wall
                side0[j] = _wall_kept(stuck, z, hd, j)
            side0[kr] = int(s)
            xd = _dot(Phi, kr, v) + _base_v(pm, xb, t)
            xa = _dot(Phi, kr, q) + _base_x(pm, xb, t)
            events, n_ev = _log(events, n_ev, t, xa, xd, u[kr], s, 0.0, 0.0, KIND_RELEASE, xd,
                                u[kr], kr)  # fmt: skip
            continue
        if k < 0:
            if watch[2] != 0:
                status = INTERRUPTED
            break
        # --- Step 15's impact (F7) of damper k on its wall s ---
        s = float(side)
        xd = _dot(Phi, k, v) + _base_v(pm, xb, t)
        if law[k] >= 0:  # a compliant contact begins: the caller integrates it (z unclamped,
            smooth = False  # so that dampers alike stay alike to the bit)
            events, n_ev = _log(events, n_ev, t, _dot(Phi, k, q) + _base_x(pm, xb, t), xd, u[k],
                                s, s * (u[k] - xd), 0.0, KIND_ONSET, xd, u[k], k)  # fmt: skip
            status = CONTACT
            break
        z[k] = s * hd[k]
        vrel = s * (u[k] - xd)  # approach speed
        # ≤ 0: the search met the wall of a mass leaving it below the positions' rounding (its
        # chatter's last flights, shorter than the clearance's ulp): the sequence has ended, and
        # the two close plastically (with e, the impulse would throw the mass into its wall)
        e = restitution(ed[k], vyd[k], vrel) if vrel > 0.0 else 0.0
        if smooth:
            if vyd[k] > 0.0 or not vrel > 0.0:
                smooth = False
            else:
                _field(pm, cfg, K, t, q, v, u, fm)
        v_before[:] = v
        let_go[:] = 0
        kept[:] = 0
        while True:  # a stuck mass its wall would have to pull during the impulse is let go
            v[:] = v_before
            P, mu = _impulse(pm, cfg, nstuck, Phi, k, md[k], e, u[k], v, _base_v(pm, xb, t))
            if held > 0:  # a held stop whose wall would have to pull is let go first
                h = _held_reactions(cfg, Sphi, contact, srig, _row_response(cfg, Phi, k, P), pulls)
                gone = -1
                for i in range(h):
                    if pulls[i] > 0.0:
                        gone = _held_index(contact, srig, i)
                        break
                if gone >= 0:
                    wall = contact[gone]
                    contact[gone] = 0
                    held -= 1
                    cfg = _working_config(keys, cfgs, pm0, Phi, md, stuck, Sphi, sk, sc, sg,
                                          contact, srig, xb)  # fmt: skip
                    pm = cfg[7]
                    smooth = False
                    events, n_ev = _log(events, n_ev, t, _dot(Sphi, gone, q), 0.0, 0.0,
                                        float(wall), 0.0, 0.0, KIND_RELEASE, 0.0, 0.0,
                                        K + gone)  # fmt: skip
                    continue
            pulled = -1
            for j in range(K):
                if (stuck[j] != 0 and kept[j] == 0
                        and stuck[j] * (_dot(Phi, j, v) - _dot(Phi, j, v_before)) > 0.0):  # fmt: skip
                    pulled = j
                    break
            if pulled < 0:
                break
            smooth = False  # a stuck mass let go by the impulse: not differentiated
            side_p = stuck[pulled]
            stuck[pulled] = 0  # the structure without the mass pulled
            without = _working_config(keys, cfgs, pm0, Phi, md, stuck, Sphi, sk, sc, sg, contact,
                                      srig, xb)  # fmt: skip
            stuck[pulled] = side_p
            if _returns_at_once(without, Phi, md, stuck, xb, pulled, k, e, u[k], t, q, v_before,
                                ed, vyd, chat * T_f, v_trial):  # fmt: skip
                kept[pulled] = 1
                continue
            let_go[pulled] = stuck[pulled]
            stuck[pulled] = 0
            nstuck -= 1
            cfg = _working_config(keys, cfgs, pm0, Phi, md, stuck, Sphi, sk, sc, sg, contact,
                                  srig, xb)  # fmt: skip
            pm = cfg[7]
            xa = _dot(Phi, pulled, q) + _base_x(pm, xb, t)
            events, n_ev = _log(events, n_ev, t, xa, u[pulled], u[pulled],
                                float(let_go[pulled]), 0.0, 0.0, KIND_RELEASE, u[pulled],
                                u[pulled], pulled)  # fmt: skip
        u_before = u[k]
        u[k] -= P / md[k]
        if e == 0.0:
            # a plastic impact leaves the mass at its point's speed: set so, not left to the
            # impulse's rounding (a few ulps of the speeds before, beyond the search's allowance
            # for rounding, 8e-16 of those after: a mass leaving its point after such an impact
            # was met again within picoseconds, a second impact at 1e-10 m/s)
            u[k] = _dot(Phi, k, v) + _base_v(pm, xb, t)
        for j in range(K):
            if stuck[j] != 0:
                u[j] = _dot(Phi, j, v) + _base_v(pm, xb, t)
        if smooth:
            _field(pm, cfg, K, t, q, v, u, fp)
            gh[:] = 0.0
            for i in range(N):
                gh[i] = -s * Phi[k, i]
            gh[2 * N + k] = s
            DJ = _impact_jump(pm, cfg, Phi, k, K, md[k], e, mu)
            ku = 2 * N + K + k
            jt = -_base_a(pm, xb, t) * DJ[:, ku]
            jt[ku] += _base_a(pm, xb, t)
            gt = -s * _base_v(pm, xb, t)
            # the impact time's row δt = −∇h·δX⁻/(∇h·f⁻ + ∂h/∂t), for the chatter that may follow
            r_i[:] = -(gh @ G) / (gh @ fm + gt)
            _timed_saltation(DJ, fm, fp, gh, gt, jt, G)
            if nstuck > 0:
                _slaved(G, Phi, stuck, N, K)
        lost = 0.5 * mu * (1.0 - e * e) * vrel * vrel
        ledger[2] += lost
        events, n_ev = _log(events, n_ev, t, _dot(Phi, k, q) + _base_x(pm, xb, t), xd, u_before,
                            s, vrel, lost, KIND_IMPACT, _dot(Phi, k, v) + _base_v(pm, xb, t),
                            u[k], k)  # fmt: skip
        for j in range(K):  # the masses just let go leave their walls; the others on theirs
            side0[j] = let_go[j] if let_go[j] != 0 else _wall_kept(stuck, z, hd, j)
        side0[k] = side
        # --- chatter: would the sequence accumulate (Step 9's test at the point)? ---
        a = -s * _point_accel(pm, cfg, nstuck, Phi, k, t, q, v, xb)
        w = e * vrel
        if a > 0.0 and e < 1.0 and vyd[k] <= 0.0:
            delta = 2.0 * w / (a * (1.0 - e))
            if delta <= chat * T_f and t + delta < t_end:
                if smooth and S > 0:
                    smooth = False  # sticking beside stops: not differentiated
                if smooth:
                    _accumulation_row(pm, cfg, Phi, k, K, t, s, w, a, delta, xb, r_i, fp, G,
                                      grad, r_inf)  # fmt: skip
                    _flight_jacobian(pm, cfg, K, delta, G)
                    if nstuck > 0:
                        _slaved(G, Phi, stuck, N, K)
                # jump to the accumulation point (the other masses fly on), close plastically
                _segment(pm, cfg, nstuck, Pout, t, q, v, delta, ledger, period_max, n_periods,
                         work, Sphi, sc, contact, rows_p, out_p, xb, energy)  # fmt: skip
                _states(pm, cfg, nstuck, t, q, v, delta, qn, vn)
                shift = _base_x(pm, xb, t + delta) - _base_x(pm, xb, t)
                vb0, vb1 = _base_v(pm, xb, t), _base_v(pm, xb, t + delta)
                for j in range(K):
                    if stuck[j] == 0 and xb != 0.0:
                        ledger[0] += 0.5 * md[j] * ((u[j] - vb1) ** 2 - (u[j] - vb0) ** 2)
                    if stuck[j] == 0 and j != k:
                        z[j] = z[j] + u[j] * delta - _dot(Phi, j, qn) + _dot(Phi, j, q) - shift
                    elif stuck[j] != 0:
                        u[j] = _dot(Phi, j, vn) + vb1
                t = t + delta
                q[:] = qn
                v[:] = vn
                xd = _dot(Phi, k, v) + _base_v(pm, xb, t)
                if smooth:  # the rate just before the plastic closure
                    _field(pm, cfg, K, t, q, v, u, fm)
                P, mu = _impulse(pm, cfg, nstuck, Phi, k, md[k], 0.0, u[k], v, _base_v(pm, xb, t))
                if smooth:
                    DJ = _impact_jump(pm, cfg, Phi, k, K, md[k], 0.0, mu)
                    ku = 2 * N + K + k
                    jt = -_base_a(pm, xb, t) * DJ[:, ku]
                    jt[ku] += _base_a(pm, xb, t)
                    Gjump[:, :] = DJ @ G
                    closing = DJ @ fm + jt
                lost = 0.5 * mu * (u[k] - xd) ** 2
                ledger[2] += lost
                u_before = u[k]
                u[k] = _dot(Phi, k, v) + _base_v(pm, xb, t)
                for j in range(K):
                    if stuck[j] != 0:
                        u[j] = _dot(Phi, j, v) + _base_v(pm, xb, t)
                xa = _dot(Phi, k, q) + _base_x(pm, xb, t)
                events, n_ev = _log(events, n_ev, t, xa, xd, u_before, s, s * (u_before - xd),
                                    lost, KIND_ACCUMULATION, u[k], u[k], k)  # fmt: skip
            elif w != 0.0 and delta != 0.0:
                continue
            else:
                smooth = False  # sticking at once where no accumulation is taken: rounding
            # --- the mass rides on its point from here ---
            stuck[k] = side
            nstuck += 1
            cfg = _working_config(keys, cfgs, pm0, Phi, md, stuck, Sphi, sk, sc, sg, contact,
                                  srig, xb)  # fmt: skip
            pm = cfg[7]
            if not cfg[5]:
                status = SINGULAR_STUCK
                break
            u[k] = _dot(Phi, k, v) + _base_v(pm, xb, t)
            z[k] = s * hd[k]
            if smooth:  # the closure at t∞ (:func:`_accumulation_row`), into the stuck flow
                _field(pm, cfg, K, t, q, v, u, fp)
                for i in range(D):
                    closing[i] -= fp[i]
                G[:, :] = Gjump + np.outer(closing, r_inf)
                _slaved(G, Phi, stuck, N, K)
    final = np.empty(1 + 2 * N + 3 * K + S)
    final[0] = t
    final[1 : 1 + N] = q
    final[1 + N : 1 + 2 * N] = v
    for k in range(K):
        final[1 + 2 * N + k] = _dot(Phi, k, q) + _base_x(pm0, xb, t) + z[k]
        final[1 + 2 * N + 2 * K + k] = stuck[k]
    final[1 + 2 * N + K : 1 + 2 * N + 2 * K] = u
    for r in range(S):
        final[1 + 2 * N + 3 * K + r] = contact[r]
    if not smooth:
        G[:, :] = np.nan
    _kept_alive(owned, cfgs)
    return status, events, n_ev, period_max, ledger, final, G


@compiled
def one_mode_arguments(p, state0, t_end, max_events, variational, energy, watch):
    """:func:`run`'s arguments for the paper's primary: one mode of mass M and shape 1
    (parameters ``p`` in :mod:`symimpact.forced.engine._rigid`'s layout), one damper, from
    state0 = (x, ẋ, y, ẏ), no stop; the rest as :func:`run` takes them."""
    pm = p.reshape((1, p.shape[0])).copy()
    one = np.ones((1, 1))
    return (
        pm, one, np.array([p[P_m]]), np.array([p[P_h]]), np.array([p[P_e]]),
        np.array([p[P_VY]]), np.array([-1]), p[P_CHAT], np.zeros((0, 1)), np.zeros(0),
        np.zeros(0, dtype=np.int64), np.zeros(0), np.zeros(0), np.zeros(0, dtype=np.int64),
        np.zeros(0), state0[0:1].copy(), state0[1:2].copy(),
        state0[2:3].copy(), state0[3:4].copy(), one, 0.0, 0.0, t_end, max_events, variational,
        np.zeros(1), np.zeros(0), energy, watch,
    )  # fmt: skip


@compiled
def one_mode_result(status, events, n_ev, period_max, ledger, final):
    """:func:`run`'s result in the one-mode layout: (status, events with
    :mod:`symimpact.forced.engine._rigid`'s ten columns, n_events, the largest abs(x) of every
    period, the ledger's first three terms (no stops), final = (t, x, ẋ, y, ẏ, 1.0 if it ended
    stuck))."""
    out = np.array([final[0], final[1], final[2], final[3], final[4], 0.0])
    if final[5] != 0.0:
        out[5] = 1.0
    return (status, events[:, :N_EVENT_COLS].copy(), n_ev, period_max[:, 0].copy(),
            ledger[:3].copy(), out)  # fmt: skip


def one_mode_run(p, state0, t_end, max_events, variational, energy, watch):
    """The paper's primary through :func:`run` (Step 8's flights, Step 9's impacts and
    sticking): :func:`one_mode_arguments` in, :func:`one_mode_result` out.  Plain Python, so
    that a one-mode run and a structure's share the one compiled :func:`run` (a compiled wrapper
    is a second copy of the whole engine to optimise and emit: 19 s of one core on a fresh
    clone).  Compiled code calls the three itself (:mod:`symimpact.forced.orbits._corrector`).
    ``variational`` and ``energy`` are passed on to :func:`run` (callers give False for the
    first: the one-mode chain is built from the event log, :mod:`symimpact.forced.engine._chain`)."""
    args = one_mode_arguments(p, state0, t_end, max_events, variational, energy, watch)
    status, events, n_ev, period_max, ledger, final, _ = run(*args)
    return one_mode_result(status, events, n_ev, period_max, ledger, final)


#: The engine's modules, in the order they import each other: the flight, the searches, the
#: ledger, and this one, the run.
PARTS = tuple(
    Path(__file__).with_name(f"{name}.py")
    for name in ("_modal_flight", "_modal_search", "_modal_ledger", "_modal")
)


def _forget_stale_compilations() -> None:
    """The engine's cached code (its :data:`PARTS`) and :mod:`._borrowed`'s, dropped when they, the one-mode flight
    functions it calls, the borrowed views, the forced-flight kernels or the stepper's secant
    changed (numba's cache does not follow a callee into another module)."""
    from ...free import _stepper
    from ...generated import forced_flight
    from . import _borrowed, _rigid

    sources = [*PARTS, Path(_rigid.__file__), Path(forced_flight.__file__),
               Path(_stepper.__file__), Path(_borrowed.__file__)]  # fmt: skip
    prefixes = (*(f"{p.stem}." for p in PARTS), "_borrowed.")
    _stepper.forget_stale_compilations(run, sources, prefixes)


_forget_stale_compilations()
