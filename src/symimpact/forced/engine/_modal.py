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

Private: :mod:`symimpact.forced.structure_response` checks the input and builds the result.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from ..._interrupt import EVERY, INTERRUPTED, stop_requested
from ...free._stepper import secant_point
from ...generated import forced_flight as _fl
from ._borrowed import borrowed, borrowed_config
from ._rigid import (
    _GL_W,
    _GL_X,
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
    _accel_bound,
    _grow,
    _steady_cos,
    _steady_sin,
    _transition,
    _xvf,
    restitution,
)

#: Eq. F1 in the flight's own time (Step 8's ``flight_form``): a, b, c, s of x, then of ẋ, σ, ω_d.
_form = njit(cache=True)(_fl.flight_form_scalar)
#: A flight's form cache (:func:`_free_states`), one per configuration: row i holds mode i's ten
#: coefficients, its start (qᵢ, q̇ᵢ) and whether the form has them (0: an undamped mode driven
#: at its own frequency, where Eq. F1 grows like t and has no such form); row N holds the
#: flight's start time and whether the cache is filled.  Columns 13 … of row i hold mode i's
#: constants in its configuration (:func:`_mode_constants`), which the bounds and the ledger of
#: every flight read.
(FC_STEADY, FC_A, FC_B, FC_AMP, FC_SIGMA, FC_WD, FC_WN2, FC_FAST2, FC_LEDGER, FC_K2MU, FC_K2S,
 FC_KPLUS, FC_KMINUS) = (13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 24, 25, 27)  # fmt: skip
FORM_COLS = 29
#: The 4-point Gauss–Legendre rule (the one-mode engine's is 8-point, _GL_X, _GL_W), for the
#: ledger's short steps (:func:`_segment`).
_GL4_X, _GL4_W = np.polynomial.legendre.leggauss(4)

#: Run status beside OK, TOO_MANY_EVENTS and INTERRUPTED: the stuck structure has no harmonic
#: response (undamped, driven at one of its own frequencies) or no eigen-decomposition.
SINGULAR_STUCK = 3
#: Run status: a compliant damper's contact begins (its onset is the log's last event); the
#: caller integrates the contact (:mod:`symimpact.forced.engine._structure_contact`) and runs on.
CONTACT = 5
#: Extra event-log column: the damper of the event (its index).
E_DAMPER = N_EVENT_COLS
N_MODAL_EVENT_COLS = N_EVENT_COLS + 1
#: Event kinds beside the one-mode engine's: a stop's contact begins, or ends.
KIND_ONSET, KIND_EXIT = 3, 4


# --- the flight: free modes (Eq. F1 each), or the stuck structure's closed form -----------------


@njit(cache=True)
def _mode_accel(pm, i, mass, t, x, v):
    """Mode i's q̈ᵢ (:func:`symimpact.forced.engine._rigid._accel` on row i of ``pm``)."""
    W, K, C = pm[i, P_W], pm[i, P_K], pm[i, P_C]
    th = W * t + pm[i, P_PHI]
    P = pm[i, P_F0] + K * pm[i, P_XB]
    Q = -C * W * pm[i, P_XB]
    return (P * math.cos(th) + Q * math.sin(th) - C * v - K * x) / mass


@njit(cache=True)
def _mode_jerk(pm, i, mass, t, x, v):
    """Mode i's d³qᵢ/dt³ (:func:`symimpact.forced.engine._rigid._jerk` on row i of ``pm``)."""
    W, K, C = pm[i, P_W], pm[i, P_K], pm[i, P_C]
    th = W * t + pm[i, P_PHI]
    P = pm[i, P_F0] + K * pm[i, P_XB]
    Q = -C * W * pm[i, P_XB]
    a = _mode_accel(pm, i, mass, t, x, v)
    return (W * (Q * math.cos(th) - P * math.sin(th)) - C * a - K * v) / mass


@njit(cache=True)
def _base_x(pm, xb, t):
    """x_b(t) = X_b·cos(Ωt + φ) [m], the supports' displacement (``xb``: X_b; 0 without base
    motion, then exactly 0)."""
    if xb == 0.0:
        return 0.0
    return xb * math.cos(pm[0, P_W] * t + pm[0, P_PHI])


@njit(cache=True)
def _base_v(pm, xb, t):
    """ẋ_b(t) [m/s]."""
    if xb == 0.0:
        return 0.0
    return -xb * pm[0, P_W] * math.sin(pm[0, P_W] * t + pm[0, P_PHI])


@njit(cache=True)
def _base_a(pm, xb, t):
    """ẍ_b(t) [m/s²]."""
    if xb == 0.0:
        return 0.0
    W = pm[0, P_W]
    return -xb * W * W * math.cos(W * t + pm[0, P_PHI])


@njit(cache=True)
def _config(pm, Phi, md, stuck, Sphi, sk, sc, sg, contact, srig, xb):
    """The structure with the dampers of ``stuck[k] != 0`` riding on it and the stops of
    ``contact[s] != 0`` pressed by it: M_s⁻¹, Λ, V, V⁻¹, X̂, K_s, C_s, f_s, q_s, M_s⁻¹
    unconstrained and (ΦₕM_s⁻¹Φₕᵀ)⁻¹ packed by :func:`_pack` in the tuple (mats, cplx, 2n, vecs,
    h, ok, decoupled, pm_s, ω_max).  ``pm_s``: ``pm`` with column P_M holding M_s's diagonal, the
    parameters every other function of the engine reads (an array of its own would cost a reference count
    wherever the innermost loops take it out of the tuple).  A stop s in contact on its wall
    w = ``contact[s]`` adds its linear law's spring and dashpot at its point, K_s = K + k₁φφᵀ,
    C_s = C + c₁φφᵀ, and the constant load f_s = k₁·w·g·φ (the force −k₁(φᵀq − w·g) − c₁φᵀq̇ on
    the point), whose static deflection q_s = K_s⁻¹f_s shifts the closed form.  A rigid stop
    (``srig[s]``) held on its wall w = ``contact[s]`` after its impacts accumulated constrains
    its point to w·g: the structure moves in the null space of the held points' shapes,
    q = q* + Zr (Z orthonormal, q* the least-norm q on the walls), r flying as the reduced
    structure ZᵀM_sZ, ZᵀC_sZ, ZᵀK_sZ; V and V⁻¹ then map r's 2(N − h) modes to the 2N state,
    M_s⁻¹ becomes Z(ZᵀM_sZ)⁻¹Zᵀ (accelerations and impulses the walls allow), and the walls'
    reactions λ = −(ΦₕM_s⁻¹Φₕᵀ)⁻¹ΦₕM_s⁻¹f follow from the unconstrained inverse (returned with
    (ΦₕM_s⁻¹Φₕᵀ)⁻¹).  Under base motion (``xb`` = X_b: the modes relative to the supports,
    the masses absolute) a stuck mass's inertia −m·ẍ_b adds m·Ω²X_b·φ to the modal loads.
    ``decoupled``:
    no stop is pressed and M_s is diagonal (no mass sticks, or one mode alone moves each stuck
    point: one mode with φ = 1 is Step 9's sticking, one mass M + m), and the modes fly by Eq. F1
    with those masses; otherwise by the eigen-decomposition (module text).  ω_max: the largest of
    Ω and the structure's damped frequencies, which sets the searches' steps."""
    N = pm.shape[0]
    W = pm[0, P_W]
    if xb != 0.0 and np.any(stuck != 0):
        # a mass riding on its point moves with it absolutely, x_b + φᵀq: its inertia
        # −m·ẍ_b = m·Ω²X_b·cos θ loads the modes through φ, in phase with the force
        pm = pm.copy()
        for k in range(Phi.shape[0]):
            if stuck[k] != 0:
                for i in range(N):
                    pm[i, P_F0] += md[k] * Phi[k, i] * W * W * xb
    Ms = np.zeros((N, N))
    Ks = np.zeros((N, N))
    Cs = np.zeros((N, N))
    fs = np.zeros(N)
    qs = np.zeros(N)
    for i in range(N):
        Ms[i, i] = pm[i, P_M]
        Ks[i, i] = pm[i, P_K]
        Cs[i, i] = pm[i, P_C]
    for k in range(Phi.shape[0]):
        if stuck[k] != 0:
            for i in range(N):
                for j in range(N):
                    Ms[i, j] += md[k] * Phi[k, i] * Phi[k, j]
    pressed = False
    held = 0
    for s in range(Sphi.shape[0]):
        if contact[s] != 0 and srig[s] != 0:
            held += 1
            pressed = True
        elif contact[s] != 0:
            pressed = True
            for i in range(N):
                fs[i] += sk[s] * contact[s] * sg[s] * Sphi[s, i]
                for j in range(N):
                    Ks[i, j] += sk[s] * Sphi[s, i] * Sphi[s, j]
                    Cs[i, j] += sc[s] * Sphi[s, i] * Sphi[s, j]
    masses = pm.copy()
    decoupled = not pressed
    for i in range(N):
        masses[i, P_M] = Ms[i, i]
        for j in range(N):
            if i != j and Ms[i, j] != 0.0:
                decoupled = False
    if decoupled:  # no LAPACK call (its threads would spin beside the engine)
        Minv = np.zeros((N, N))
        for i in range(N):
            Minv[i, i] = 1.0 / Ms[i, i]
    else:
        Minv = np.ascontiguousarray(np.linalg.inv(Ms))
    Pinv = np.zeros((held, held))
    if held > 0:
        return _held_config(pm, Sphi, sg, contact, srig, held, Ms, Ks, Cs, fs, Minv, masses)
    lam = np.zeros(2 * N, dtype=np.complex128)
    V = np.eye(2 * N, dtype=np.complex128)
    Vinv = np.eye(2 * N, dtype=np.complex128)
    Xhat = np.zeros(2 * N, dtype=np.complex128)
    ok = True
    wmax = W
    if decoupled:
        for i in range(N):
            M, K, C = masses[i, P_M], pm[i, P_K], pm[i, P_C]
            wmax = max(wmax, math.sqrt(max(K / M - C * C / (4 * M * M), 0.0)))
        return _pack(Minv, Ks, Cs, Minv, Pinv, lam, V, Vinv, Xhat, fs, qs, ok, decoupled, masses,
                     wmax, _slowest(lam, masses, pm, W, True))  # fmt: skip
    A = np.zeros((2 * N, 2 * N), dtype=np.complex128)
    for i in range(N):
        A[i, N + i] = 1.0
        for j in range(N):
            for m in range(N):
                A[N + i, j] -= Minv[i, m] * Ks[m, j]
                A[N + i, N + j] -= Minv[i, m] * Cs[m, j]
    lam, V = np.linalg.eig(A)
    V = np.ascontiguousarray(V)
    Vinv = np.ascontiguousarray(np.linalg.inv(V))
    # the load on each mode, (F + K·X_b)cos θ − CΩ·X_b sin θ = Re((F + K·X_b + iCΩ·X_b)e^{iθ})
    b = np.zeros(2 * N, dtype=np.complex128)
    for i in range(N):
        for j in range(N):
            load = pm[j, P_F0] + pm[j, P_K] * pm[j, P_XB] + 1j * W * pm[j, P_C] * pm[j, P_XB]
            b[N + i] += Minv[i, j] * load
    D = 1j * W * np.eye(2 * N) - A
    if np.linalg.cond(D) > 1e12 or np.linalg.cond(V) > 1e12:
        ok = False
    else:
        Xhat = np.linalg.solve(D, b)
    if pressed:
        if np.linalg.cond(Ks) > 1e12:
            ok = False
        else:
            qs = np.linalg.solve(Ks, fs)
    for m in range(2 * N):
        wmax = max(wmax, abs(lam[m].imag))
    return _pack(Minv, Ks, Cs, Minv, Pinv, lam, V, Vinv, Xhat, fs, qs, ok, decoupled, masses, wmax,
                 _slowest(lam, masses, pm, W, False))  # fmt: skip


#: Configurations :func:`run` keeps, one per pattern of stuck dampers and pressed stops met.
MAX_CONFIGS = 64


@njit(cache=True)
def _pattern(stuck, contact):
    """The pattern of stuck dampers and pressed stops as one number, each one's −1, 0 or 1 a
    base-3 digit; −1 where there are too many of them to encode (more than 39)."""
    if stuck.shape[0] + contact.shape[0] > 39:
        return -1
    code = 0
    for k in range(stuck.shape[0]):
        code = 3 * code + stuck[k] + 1
    for k in range(contact.shape[0]):
        code = 3 * code + contact[k] + 1
    return code


@njit(cache=True)
def _kept_config(keys, cfgs, pm, Phi, md, stuck, Sphi, sk, sc, sg, contact, srig, xb):
    """:func:`_config`, computed once per pattern of stuck dampers and pressed stops
    (:func:`_pattern`) in a run: a run's configurations differ only by that pattern, and a
    damper that chatters, sticks and is let go over and over (hundreds of times a second at a
    cantilever's mid-span) met the eigen-decomposition of the same stuck structure at each
    stick and each release (190 µs with 10 modes).  ``keys``, ``cfgs``: the run's patterns and
    their configurations, appended to (at most MAX_CONFIGS kept)."""
    code = _pattern(stuck, contact)
    if code >= 0:
        for j in range(len(keys)):
            if keys[j] == code:
                return cfgs[j]
    cfg = _config(pm, Phi, md, stuck, Sphi, sk, sc, sg, contact, srig, xb)
    if code >= 0 and len(keys) < MAX_CONFIGS:
        keys.append(code)
        cfgs.append(cfg)
    return cfg


@njit(cache=True)
def _working_config(keys, cfgs, pm, Phi, md, stuck, Sphi, sk, sc, sg, contact, srig, xb):
    """:func:`_kept_config` as :func:`run` works with it: borrowed (:mod:`._borrowed`) where
    ``cfgs`` keeps it, as computed where it does not (a pattern that cannot be encoded, or more
    than MAX_CONFIGS of them: the run's variable then owns it)."""
    cfg = _kept_config(keys, cfgs, pm, Phi, md, stuck, Sphi, sk, sc, sg, contact, srig, xb)
    code = _pattern(stuck, contact)
    if code >= 0:
        for j in range(len(keys)):
            if keys[j] == code:
                return borrowed_config(cfgs[j])
    return cfg


@njit(cache=True)
def _slowest(lam, masses, pm, W, decoupled):
    """max(Ω, the lowest damped frequency of the flight's modes) [rad/s]: the searches' and the
    periods' maxima's coarsest step is a sixteenth of its period (their bounds certify any step;
    a structure's high modes, which set the finest one, need not set the coarsest).  With one mode
    it is that mode's ω_d, as ω_max (:func:`_pack`)."""
    w = math.inf
    if decoupled:
        for i in range(pm.shape[0]):
            M, K, C = masses[i, P_M], pm[i, P_K], pm[i, P_C]
            w = min(w, math.sqrt(max(K / M - C * C / (4 * M * M), 0.0)))
    else:
        for m in range(lam.shape[0]):
            if lam[m].imag != 0.0:
                w = min(w, abs(lam[m].imag))
    return W if w == math.inf else max(W, w)


@njit(cache=True)
def _mode_constants(pm, i, row):
    """Mode i's constants in a configuration (``pm`` its pm_s), written into columns 13 … of its
    form row (FORM_COLS) once per configuration, not once per flight: whether Eq. F1 has its
    steady part (D = (K − MΩ²)² + (CΩ)² > 1e-24·K²), that part's cosine and sine amplitudes
    A, B (Eq. F1's steady cosine and sine) and √(A² + B²), σ = C/2M, ω_d = √(K/M − σ²),
    ω_n² = K/M and max(Ω, ω_n)² (the acceleration bound's, :func:`_mode_accel_bound`); whether
    the closed-form ledger applies (ω_d² > 0 and D as above) and 1/(2μ), 1/(−2σ), 1/(μ + iΩ),
    1/(μ − iΩ), μ = −σ + iω_d (:func:`_mode_ledger_at`: its integrals multiply by them)."""
    M, K, C, F0, Xb, W = pm[i, P_M], pm[i, P_K], pm[i, P_C], pm[i, P_F0], pm[i, P_XB], pm[i, P_W]
    row[FC_STEADY:] = 0.0
    sigma = C / (2.0 * M)
    wn2 = K / M
    wd2 = wn2 - sigma * sigma
    D = (K - M * W * W) ** 2 + (C * W) ** 2
    steady = D > 1e-24 * K * K
    row[FC_SIGMA] = sigma
    row[FC_WD] = math.sqrt(wd2) if wd2 >= 0.0 else math.nan
    row[FC_WN2] = wn2
    row[FC_FAST2] = max(W, math.sqrt(wn2)) ** 2
    if not steady:
        return
    A = _steady_cos(M, K, C, F0, Xb, W)
    B = _steady_sin(M, K, C, F0, Xb, W)
    row[FC_STEADY] = 1.0
    row[FC_A] = A
    row[FC_B] = B
    row[FC_AMP] = math.sqrt(A * A + B * B)
    if not wd2 > 0.0:
        return
    mu = complex(-sigma, row[FC_WD])
    row[FC_LEDGER] = 1.0
    k = 1.0 / (2.0 * mu)
    row[FC_K2MU], row[FC_K2MU + 1] = k.real, k.imag
    row[FC_K2S] = 1.0 / (-2.0 * sigma) if sigma != 0.0 else 0.0
    k = 1.0 / (mu + complex(0.0, W))
    row[FC_KPLUS], row[FC_KPLUS + 1] = k.real, k.imag
    k = 1.0 / (mu - complex(0.0, W))
    row[FC_KMINUS], row[FC_KMINUS + 1] = k.real, k.imag


@njit(cache=True)
def _pack(Minv, Ks, Cs, Mfull, Pinv, lam, V, Vinv, Xhat, fs, qs, ok, decoupled, masses, wmax,
          wlow):  # fmt: skip
    """The configuration tuple (mats, cplx, 2n, vecs, h, ok, decoupled, pm_s, ω_max, ω_low of
    :func:`_slowest`): its arrays packed in three (every array in a tuple that a function takes
    costs a reference count at each call): mats = [M_s⁻¹ (as the walls allow), K_s, C_s,
    M_s⁻¹ unconstrained, (ΦₕM_s⁻¹Φₕᵀ)⁻¹ in its top-left h × h]; cplx holds V (2N × 2n), V⁻¹
    (2n × 2N), X̂ and Λ in its rows; vecs = [f_s, q_s] (:func:`_config`); then the flights'
    caches (:func:`_free_states`, :func:`_held_free`) and λ_max, the fastest rate of the
    configuration's flights (:func:`_segment`'s quadrature step)."""
    N = Ks.shape[0]
    n2 = lam.shape[0]
    h = Pinv.shape[0]
    mats = np.zeros((5, N, N))
    mats[0] = Minv
    mats[1] = Ks
    mats[2] = Cs
    mats[3] = Mfull
    mats[4, :h, :h] = Pinv
    cplx = np.zeros((2 * N + n2 + 2, max(2 * N, n2, 1)), dtype=np.complex128)
    cplx[: 2 * N, :n2] = V
    cplx[2 * N : 2 * N + n2, : 2 * N] = Vinv
    cplx[2 * N + n2, : 2 * N] = Xhat
    cplx[2 * N + n2 + 1, :n2] = lam
    vecs = np.zeros((2, N))
    vecs[0] = fs
    vecs[1] = qs
    form = np.zeros((N + 1, FORM_COLS))  # :func:`_free_states`'s cache, empty
    for i in range(N):
        _mode_constants(masses, i, form[i])
    held = np.zeros((2 * N + 3, 2 * N + 1), dtype=np.complex128)  # :func:`_held_free`'s, empty
    held[2 * N + 2, :n2] = _pair_weights(lam)
    # λ_max ≥ every rate the flight holds: Ω, abs(λ) of the coupled modes, and ωₙ and Cᵢ/Mᵢ of
    # the free ones (an over-damped mode's abs(λ) ≤ C/M): the ledger's quadrature step
    lmax = wmax
    for m in range(n2):
        lmax = max(lmax, abs(lam[m]))
    for i in range(N):
        lmax = max(
            lmax, math.sqrt(masses[i, P_K] / masses[i, P_M]), masses[i, P_C] / masses[i, P_M]
        )
    return mats, cplx, n2, vecs, h, ok, decoupled, masses, wmax, wlow, form, held, lmax


@njit(cache=True)
def _pair_weights(lam):
    """wₗ for Re Σₗ wₗVₗcₗe^{λₗτ}, the coupled flight's sum (:func:`_held_free`): the state is
    real, so the terms of two conjugate eigenvalues are conjugate, and the sum is twice the real
    part of the one with positive imaginary part (w = 2, its partner 0); a real eigenvalue keeps
    w = 1.  Where an eigenvalue finds no partner within 1e-8 of its size (not met: A is real)
    every w is 1, the full sum."""
    n2 = lam.shape[0]
    w = np.ones(n2)
    used = np.zeros(n2, dtype=np.bool_)
    for m in range(n2):
        if used[m]:
            continue
        used[m] = True
        size = abs(lam[m])
        if abs(lam[m].imag) <= 1e-12 * size:
            continue
        best, dist = -1, math.inf
        for k in range(n2):
            if not used[k] and abs(lam[k] - np.conj(lam[m])) < dist:
                best, dist = k, abs(lam[k] - np.conj(lam[m]))
        if best < 0 or dist > 1e-8 * size:
            w[:] = 1.0
            return w
        used[best] = True
        up, down = (m, best) if lam[m].imag > 0.0 else (best, m)
        w[up], w[down] = 2.0, 0.0
    return w


@njit(cache=True)
def _modes_of(cfg):
    """(Λ, V, V⁻¹, X̂) of a coupled configuration (views into its packed array)."""
    cplx, n2 = cfg[1], cfg[2]
    N2 = cplx.shape[0] - n2 - 2
    return cplx[N2 + n2 + 1, :n2], cplx[:N2, :n2], cplx[N2 : N2 + n2, :N2], cplx[N2 + n2, :N2]


@njit(cache=True)
def _held_config(pm, Sphi, sg, contact, srig, held, Ms, Ks, Cs, fs, Minv, masses):
    """:func:`_config` while rigid stops are held on their walls: the reduced structure in the
    null space of the held points' shapes (:func:`_config`'s text)."""
    N = pm.shape[0]
    W = pm[0, P_W]
    H = np.zeros((held, N))
    gh = np.zeros(held)
    j = 0
    for s in range(Sphi.shape[0]):
        if contact[s] != 0 and srig[s] != 0:
            H[j] = Sphi[s]
            gh[j] = contact[s] * sg[s]
            j += 1
    _, _, Vt = np.linalg.svd(H)  # full: Vt is N × N, its last N − h rows span the null space
    nr = N - held
    Z = np.ascontiguousarray(Vt[held:].T)
    qstar = H.T @ np.linalg.solve(H @ H.T, gh)
    HM = H @ Minv
    Pinv = np.ascontiguousarray(np.linalg.inv(HM @ H.T))
    ok = True
    wmax = W
    lam = np.zeros(2 * nr, dtype=np.complex128)
    V = np.zeros((2 * N, 2 * nr), dtype=np.complex128)
    Vinv = np.zeros((2 * nr, 2 * N), dtype=np.complex128)
    Xhat = np.zeros(2 * N, dtype=np.complex128)
    qs = qstar.copy()
    Meff = np.zeros((N, N))
    if nr > 0:
        Mr = Z.T @ Ms @ Z
        Mrinv = np.linalg.inv(Mr)
        Meff = Z @ Mrinv @ Z.T
        Kr, Cr = Z.T @ Ks @ Z, Z.T @ Cs @ Z
        A = np.zeros((2 * nr, 2 * nr), dtype=np.complex128)
        MK, MC = Mrinv @ Kr, Mrinv @ Cr
        for i in range(nr):
            A[i, nr + i] = 1.0
            for m in range(nr):
                A[nr + i, m] = -MK[i, m]
                A[nr + i, nr + m] = -MC[i, m]
        lamr, Vr = np.linalg.eig(A)
        lam = lamr
        Vrinv = np.linalg.inv(np.ascontiguousarray(Vr))
        Zc = Z.astype(np.complex128)
        V[:N] = Zc @ np.ascontiguousarray(Vr[:nr])
        V[N:] = Zc @ np.ascontiguousarray(Vr[nr:])
        Vinv[:, :N] = np.ascontiguousarray(Vrinv[:, :nr]) @ Zc.T
        Vinv[:, N:] = np.ascontiguousarray(Vrinv[:, nr:]) @ Zc.T
        load = np.zeros(N, dtype=np.complex128)
        for i in range(N):
            load[i] = pm[i, P_F0] + pm[i, P_K] * pm[i, P_XB] + 1j * W * pm[i, P_C] * pm[i, P_XB]
        b = np.zeros(2 * nr, dtype=np.complex128)
        b[nr:] = Mrinv.astype(np.complex128) @ (Zc.T @ load)
        D = 1j * W * np.eye(2 * nr) - A
        if np.linalg.cond(D) > 1e12 or np.linalg.cond(Vr) > 1e12 or np.linalg.cond(Kr) > 1e12:
            ok = False
        else:
            Xr = np.linalg.solve(D, b)
            Xhat[:N] = Zc @ Xr[:nr]
            Xhat[N:] = Zc @ Xr[nr:]
            qs = qstar + Z @ np.linalg.solve(Kr, Z.T @ (fs - Ks @ qstar))
        for m in range(2 * nr):
            wmax = max(wmax, abs(lam[m].imag))
    return _pack(Meff, Ks, Cs, Minv, Pinv, lam, V, Vinv, Xhat, fs, qs, ok, False, masses, wmax,
                 _slowest(lam, masses, pm, W, False))  # fmt: skip


@njit(cache=True)
def _coefficients(pm, cfg, t0, q0, v0):
    """c = V⁻¹(X₀ − X_p(t₀) − (q_s, 0)): the coupled flight's modal amplitudes from (q0, v0) at
    t0 (q_s: the pressed stops' static deflection, :func:`_config`)."""
    _, _, Vinv, Xhat = _modes_of(cfg)
    qs = cfg[3][1]
    N = pm.shape[0]
    rot = np.exp(1j * (pm[0, P_W] * t0 + pm[0, P_PHI]))
    X0 = np.empty(2 * N, dtype=np.complex128)
    for i in range(N):
        X0[i] = q0[i] - (Xhat[i] * rot).real - qs[i]
        X0[N + i] = v0[i] - (Xhat[N + i] * rot).real
    return _cmv(Vinv, X0)


@njit(cache=True)
def _cmv(A, x):
    """A·x for a complex matrix of any shape (a held structure's may have no column)."""
    out = np.zeros(A.shape[0], dtype=np.complex128)
    for i in range(A.shape[0]):
        acc = 0.0j
        for j in range(A.shape[1]):
            acc += A[i, j] * x[j]
        out[i] = acc
    return out


@njit(cache=True)
def _form_fresh(form, t0, q0, v0):
    """Whether the flight's form cache ``form`` (:func:`_free_states`) holds the flight from
    (q0, v0) at t0."""
    N = q0.shape[0]
    if not (form[N, 1] == 1.0 and form[N, 0] == t0):
        return False
    for i in range(N):
        if form[i, 10] != q0[i] or form[i, 11] != v0[i]:
            return False
    return True


@njit(cache=True)
def _free_states(pm, form, t0, q0, v0, tau, q, v):
    """Every mode's (qᵢ, q̇ᵢ) by Eq. F1 a time τ after (q0, v0) at t0, written into q and v, while
    the modes are uncoupled (:func:`_states`; the searches' and the ledger's innermost loops call
    this one directly, without the configuration tuple).  A search evaluates one flight at many τ: the
    flight's form (Step 8's ``flight_form``, x = a·cos Ωτ + b·sin Ωτ + e^(−στ)(c·cos ω_dτ +
    s·sin ω_dτ) and ẋ alike) is computed once per flight into ``form`` (the configuration's
    cache, keyed by t0, q0 and v0), and each τ then costs cos Ωτ and sin Ωτ, shared by the
    modes, and e^(−στ), cos ω_dτ and sin ω_dτ per mode."""
    N = pm.shape[0]
    if not _form_fresh(form, t0, q0, v0):
        for i in range(N):
            W = pm[i, P_W]
            th = (W * t0 + pm[i, P_PHI]) % (2.0 * math.pi)
            M, K, C, F0, Xb = pm[i, P_M], pm[i, P_K], pm[i, P_C], pm[i, P_F0], pm[i, P_XB]
            c = _form(M, K, C, F0, Xb, W, th, q0[i], v0[i])
            ok = True
            for j in range(10):
                form[i, j] = c[j]
                ok = ok and math.isfinite(c[j])
            form[i, 10] = q0[i]
            form[i, 11] = v0[i]
            form[i, 12] = 1.0 if ok else 0.0
        form[N, 0] = t0
        form[N, 1] = 1.0
    W = pm[0, P_W]
    cw, sw = math.cos(W * tau), math.sin(W * tau)
    for i in range(N):
        f = form[i]
        if (
            f[12] == 0.0
        ):  # :func:`symimpact.forced.engine._rigid._state` on row i: Eq. F1's own branch
            th = (pm[i, P_W] * t0 + pm[i, P_PHI]) % (2.0 * math.pi)
            q[i], v[i] = _xvf(tau, pm[i, P_M], pm[i, P_K], pm[i, P_C], pm[i, P_F0],
                              pm[i, P_XB], pm[i, P_W], th, q0[i], v0[i])  # fmt: skip
            continue
        ex = math.exp(-f[8] * tau)
        cd, sd = math.cos(f[9] * tau), math.sin(f[9] * tau)
        q[i] = f[0] * cw + f[1] * sw + ex * (f[2] * cd + f[3] * sd)
        v[i] = f[4] * cw + f[5] * sw + ex * (f[6] * cd + f[7] * sd)


@njit(cache=True)
def _states(pm, cfg, nstuck, t0, q0, v0, tau, q, v):
    """Every mode's (qᵢ, q̇ᵢ) a time τ after (q0, v0) at t0, written into q and v: Eq. F1 per mode
    while no mass sticks, else the stuck structure's closed form (module text, :func:`_held_free`)."""
    if cfg[6]:
        _free_states(pm, cfg[10], t0, q0, v0, tau, q, v)
        return
    hf = cfg[11]
    if not _held_fresh(hf, t0, q0, v0):
        _held_fill(pm, cfg, t0, q0, v0)
    _held_free(pm, hf, cfg[1], cfg[2], cfg[3], tau, q, v)


@njit(cache=True)
def _held_fresh(hf, t0, q0, v0):
    """Whether the coupled flight's cache ``hf`` (:func:`_held_free`) holds the flight from
    (q0, v0) at t0."""
    N = q0.shape[0]
    N2 = 2 * N
    if hf[N2 + 1, 1].real != 1.0 or hf[N2 + 1, 0].real != t0:
        return False
    for i in range(N):
        if hf[N2, i].real != q0[i] or hf[N2, N + i].real != v0[i]:
            return False
    return True


@njit(cache=True)
def _sum_at_start(terms, weights, n2, const):
    """A coupled flight's sum at τ = 0 without its transcendentals, for one row ``terms`` of its
    columns (the cache's, :func:`_held_sum`, or a point's projection, :func:`_rows_at`; the
    forcing's at n2, ``weights`` the cache's row of wₗ): there cos Ωτ = e^{λτ} = 1 and sin = 0
    exactly, and x·1 − y·0 = x, so the same additions in the same order give the same double
    (``const``: q_s's entry or φᵀq_s for a displacement, 0 for a speed)."""
    acc = const + terms[n2].real
    for m in range(n2):
        if weights[m].real != 0.0:
            acc += terms[m].real
    return acc


@njit(cache=True)
def _held_fill(pm, cfg, t0, q0, v0):
    """Fill the coupled flight's cache cfg[11] for the flight from (q0, v0) at t0
    (:func:`_held_free`)."""
    N = pm.shape[0]
    n2 = cfg[2]
    hf = cfg[11]
    N2 = 2 * N
    _, V, _, Xhat = _modes_of(cfg)
    c = _coefficients(pm, cfg, t0, q0, v0)
    th = pm[0, P_W] * t0 + pm[0, P_PHI]
    rot = complex(math.cos(th), math.sin(th))
    for j in range(N2):
        for m in range(n2):
            hf[j, m] = hf[N2 + 2, m].real * V[j, m] * c[m]
        hf[j, n2] = Xhat[j] * rot
    qs = cfg[3][1]
    for i in range(N):  # the start, and the sum's own value there (:func:`_held_free`)
        hf[N2, i] = complex(q0[i], _sum_at_start(hf[i], hf[N2 + 2], n2, qs[i]))
        hf[N2, N + i] = complex(v0[i], _sum_at_start(hf[N + i], hf[N2 + 2], n2, 0.0))
    hf[N2 + 1, 0] = t0
    hf[N2 + 1, 1] = 1.0


@njit(cache=True)
def _growth(lam, tau):
    """(Re, Im) of e^{λτ}: one term of the coupled flight's sum (:func:`_held_free`)."""
    ex = math.exp(lam.real * tau)
    return ex * math.cos(lam.imag * tau), ex * math.sin(lam.imag * tau)


@njit(cache=True)
def _held_free(pm, hf, cplx, n2, vecs, tau, q, v):
    """The stuck (coupled) structure's (q, q̇) a time τ into the flight whose cache ``hf`` is
    filled (:func:`_held_fill`), written into q and v: X(τ) = Re Σₗ wₗ(Vₗcₗ)e^{λₗτ} +
    Re((X̂e^{iθ₀})e^{iΩτ}) + (q_s, 0) (module text; c = V⁻¹(X₀ − X_p(t₀) − (q_s, 0)),
    :func:`_coefficients`; wₗ of :func:`_pair_weights`), as X₀ + (S(τ) − S(0)), S the sum as
    :func:`_held_sum` rounds it: the flight starts exactly where the last one ended.  S(0) differs
    from X₀ by the rounding of c (up to V's condition number in ulps of the terms, 2e-16 m on a
    ten-mode cantilever's tip), and a search that read S(τ) − X₀ saw a mass that had just left
    its wall start beyond it: a chatter then met that offset δ at every flight and settled at the
    approach speed √(2aδ/(1 − e²)), a rebound every few nanoseconds that never accumulated.
    ``cplx``, ``n2``, ``vecs``: the configuration's (:func:`_pack`), taken one by one (the
    configuration tuple costs a reference count per array at each call)."""
    _held_sum(pm, hf, cplx, n2, vecs, tau, q, v)
    N = pm.shape[0]
    N2 = 2 * N
    for i in range(N):
        q[i] = hf[N2, i].real + (q[i] - hf[N2, i].imag)
        v[i] = hf[N2, N + i].real + (v[i] - hf[N2, N + i].imag)


@njit(cache=True)
def _held_sum(pm, hf, cplx, n2, vecs, tau, q, v):
    """S(τ) of :func:`_held_free`, the coupled flight's closed form as its cache's terms sum it,
    written into q and v.  A search evaluates one flight at many τ: the columns wₗVₗcₗ and
    X̂e^{iθ₀} are formed once per flight (rows 0 … 2N − 1 of the cache, the last column X̂e^{iθ₀};
    row 2N the start (q0, q̇0) with S(0) in its imaginary parts; row 2N + 1 t0 and whether
    filled; row 2N + 2 the weights), and each τ then costs e^{λₗτ} for the kept half of Λ and a
    real sum of 2N rows."""
    N = pm.shape[0]
    N2 = 2 * N
    last = cplx.shape[0] - 1  # Λ's row
    W = pm[0, P_W]
    cw, sw = math.cos(W * tau), math.sin(W * tau)
    for i in range(N):
        q[i] = vecs[1, i] + hf[i, n2].real * cw - hf[i, n2].imag * sw
        v[i] = hf[N + i, n2].real * cw - hf[N + i, n2].imag * sw
    for m in range(n2):
        if hf[N2 + 2, m].real == 0.0:
            continue
        er, ei = _growth(cplx[last, m], tau)
        for i in range(N):
            q[i] += hf[i, m].real * er - hf[i, m].imag * ei
            v[i] += hf[N + i, m].real * er - hf[N + i, m].imag * ei


@njit(cache=True)
def _held_rows(pm, cfg, shapes, t0, q0, v0, rows, out):
    """The coupled flight from (q0, v0) at t0 (:func:`_held_free`) projected on each point r of
    ``shapes`` (its row φᵣ), written into ``rows`` (R × 3 × (2N + 2), complex): for d = 0, 1, 2
    the coefficients of dᵈ(φᵣᵀq)/dτᵈ = Re Σₗ rows[r, d, l]e^{λₗτ} + Re(rows[r, d, n]e^{iΩτ})
    (+ rows[r, 0, n + 1] = φᵣᵀq_s for d = 0; n = 2n of the configuration, l < n):
    rows[r, 0, l] = φᵣᵀ(wₗVₗcₗ) over q's rows, rows[r, 1, l] the same over q̇'s, and
    rows[r, 2, l] = λₗ·rows[r, 1, l] (iΩ for the forcing's column): the derivatives of the closed
    form, which solves M_sq̈ + C_sq̇ + K_sq = loads exactly.  out[r, 3] ← the sum's own
    displacement at τ = 0, which is φᵣᵀq0 but for the rounding of c, so that a search's
    out[r, 0] − out[r, 3] is exactly 0 at the start (why: :func:`_held_free`).  A search that
    reads a few points' displacements, speeds or accelerations along one flight then costs, per
    τ, e^{λₗτ} for the kept half of Λ and three sums of as many terms per point
    (:func:`_rows_at`), not the 2N rows of the state and the point's acceleration from it
    (:func:`_point_accel`: 3N² products)."""
    hf = cfg[11]
    if not _held_fresh(hf, t0, q0, v0):
        _held_fill(pm, cfg, t0, q0, v0)
    N = pm.shape[0]
    n2 = cfg[2]
    cplx = cfg[1]
    last = cplx.shape[0] - 1
    qs = cfg[3][1]
    W = pm[0, P_W]
    for r in range(shapes.shape[0]):
        for m in range(n2 + 1):
            x, xv = 0.0j, 0.0j
            if m == n2 or hf[2 * N + 2, m].real != 0.0:
                for i in range(N):
                    x += shapes[r, i] * hf[i, m]
                    xv += shapes[r, i] * hf[N + i, m]
            rate = cplx[last, m] if m < n2 else 1j * W
            rows[r, 0, m] = x
            rows[r, 1, m] = xv
            rows[r, 2, m] = rate * xv
        c = 0.0
        for i in range(N):
            c += shapes[r, i] * qs[i]
        rows[r, 0, n2 + 1] = c
        out[r, 3] = _sum_at_start(rows[r, 0], hf[2 * N + 2], n2, c)  # :func:`_rows_at` at τ = 0


@njit(cache=True)
def _rows_at(rows, hf, cplx, n2, W, tau, out):
    """out[r, d] ← dᵈ(φᵣᵀq)/dτᵈ at τ into the flight, d = 0, 1, 2, for each point r of ``rows``
    (:func:`_held_rows`; ``hf``, ``cplx``, ``n2``: the configuration's cache, arrays and 2n,
    taken one by one as :func:`_held_free` takes them)."""
    N2 = hf.shape[0] - 3
    last = cplx.shape[0] - 1
    cw, sw = math.cos(W * tau), math.sin(W * tau)
    for r in range(rows.shape[0]):
        for d in range(3):
            c = rows[r, d, n2]
            out[r, d] = c.real * cw - c.imag * sw
        out[r, 0] += rows[r, 0, n2 + 1].real
    for m in range(n2):
        if hf[N2 + 2, m].real == 0.0:
            continue
        er, ei = _growth(cplx[last, m], tau)
        for r in range(rows.shape[0]):
            for d in range(3):
                c = rows[r, d, m]
                out[r, d] += c.real * er - c.imag * ei


@njit(cache=True)
def _stuck_loads(pm, cfg, t, q, v):
    """r = Pcos θ + Qsin θ + f_s − C_sq̇ − K_sq of the coupled structure, P = F + K·X_b,
    Q = −CΩ·X_b per mode (Eq. F1's right side with the pressed stops' springs, dashpots and
    load, :func:`_config`): q̈ = M_s⁻¹r (:func:`_stuck_acceleration`)."""
    Ks, Cs, fs = cfg[0][1], cfg[0][2], cfg[3][0]
    N = pm.shape[0]
    W = pm[0, P_W]
    th = W * t + pm[0, P_PHI]
    c, sn = math.cos(th), math.sin(th)
    r = np.empty(N)
    for j in range(N):
        P = pm[j, P_F0] + pm[j, P_K] * pm[j, P_XB]
        Q = -pm[j, P_C] * W * pm[j, P_XB]
        cv, kq = 0.0, 0.0
        for m in range(N):
            cv += Cs[j, m] * v[m]
            kq += Ks[j, m] * q[m]
        r[j] = P * c + Q * sn + fs[j] - cv - kq
    return r


@njit(cache=True)
def _stuck_acceleration(cfg, r, i):
    """q̈ᵢ of the coupled structure: row i of M_s⁻¹r, r its loads (:func:`_stuck_loads`,
    computed once for all i)."""
    Minv = cfg[0][0]
    g = 0.0
    for j in range(r.shape[0]):
        g += Minv[i, j] * r[j]
    return g


@njit(cache=True)
def _free_point_accel(pm, Phi, row, t, q, v, xb):
    """ẍₐ = φᵀq̈ + ẍ_b at the point of row ``row`` of ``Phi`` while the modes are uncoupled: each
    mode's Eq. F1 (:func:`_point_accel`, without the configuration: see :func:`_free_states`)."""
    a = _base_a(pm, xb, t)
    for i in range(pm.shape[0]):
        a += Phi[row, i] * _mode_accel(pm, i, pm[i, P_M], t, q[i], v[i])
    return a


@njit(cache=True)
def _point_accel(pm, cfg, nstuck, Phi, row, t, q, v, xb):
    """ẍₐ = φᵀq̈ + ẍ_b at the point of row ``row`` of ``Phi`` (its shapes; ``xb``: X_b for the
    dampers' points, which move absolutely, 0 for a stop's, relative to the ground): each mode's
    Eq. F1 while the modes are uncoupled, else the stuck structure's
    (:func:`_stuck_acceleration`)."""
    if cfg[6]:
        return _free_point_accel(pm, Phi, row, t, q, v, xb)
    # φᵀM_s⁻¹r with each load rⱼ (:func:`_stuck_loads`) formed where it is used: no array
    Minv, Ks, Cs, fs = cfg[0][0], cfg[0][1], cfg[0][2], cfg[3][0]
    N = pm.shape[0]
    W = pm[0, P_W]
    th = W * t + pm[0, P_PHI]
    c, sn = math.cos(th), math.sin(th)
    a = _base_a(pm, xb, t)
    for j in range(N):
        rj = (pm[j, P_F0] + pm[j, P_K] * pm[j, P_XB]) * c - pm[j, P_C] * W * pm[j, P_XB] * sn
        rj += fs[j]
        wj = 0.0
        for m in range(N):
            rj -= Cs[j, m] * v[m] + Ks[j, m] * q[m]
            wj += Phi[row, m] * Minv[m, j]
        a += wj * rj
    return a


@njit(cache=True)
def _point_jerk(pm, cfg, nstuck, Phi, row, t, q, v, xb):
    """d³xₐ/dt³ = φᵀ d³q/dt³ + d³x_b/dt³."""
    N = pm.shape[0]
    a = 0.0
    if xb != 0.0:
        W = pm[0, P_W]
        a = xb * W * W * W * math.sin(W * t + pm[0, P_PHI])
    if cfg[6]:
        for i in range(N):
            a += Phi[row, i] * _mode_jerk(pm, i, pm[i, P_M], t, q[i], v[i])
        return a
    Minv, Ks, Cs = cfg[0][0], cfg[0][1], cfg[0][2]
    W = pm[0, P_W]
    th = W * t + pm[0, P_PHI]
    c, sn = math.cos(th), math.sin(th)
    acc = np.empty(N)
    r = _stuck_loads(pm, cfg, t, q, v)
    for i in range(N):
        acc[i] = _stuck_acceleration(cfg, r, i)
    for i in range(N):
        g = 0.0
        for j in range(N):
            P = pm[j, P_F0] + pm[j, P_K] * pm[j, P_XB]
            Q = -pm[j, P_C] * W * pm[j, P_XB]
            ca, kv = 0.0, 0.0
            for m in range(N):
                ca += Cs[j, m] * acc[m]
                kv += Ks[j, m] * v[m]
            g += Minv[i, j] * (W * (Q * c - P * sn) - ca - kv)
        a += Phi[row, i] * g
    return a


@njit(cache=True)
def _mode_accel_bound(p, f, c, sn, t0, x0, v0, T):
    """:func:`symimpact.forced.engine._rigid._accel_bound` of mode row ``p`` from its configuration's
    constants ``f`` (its form row, :func:`_mode_constants`) and cos θ, sin θ of the flight's
    start: the same operations on the same doubles, so the same bound, without its division,
    square roots but one, and transcendentals per mode and flight."""
    if f[FC_STEADY] == 0.0:
        return _accel_bound(p, p[P_M], t0, x0, v0, T)
    A, B, W = f[FC_A], f[FC_B], p[P_W]
    xp = A * c + B * sn
    vp = W * (B * c - A * sn)
    dx, dv = x0 - xp, v0 - vp
    R = math.sqrt(dx * dx + ((dv + f[FC_SIGMA] * dx) / f[FC_WD]) ** 2)
    bound = f[FC_AMP] * W * W + R * f[FC_WN2]
    return bound * (1.0 + 1e-9) + 1e-300


@njit(cache=True)
def _bounds(pm, cfg, nstuck, Phi, t0, q0, v0, T, A, B, rows, xb):
    """(A, B): for every damper's point, A ≥ |ẍₐ| and B ≥ |d⁴xₐ/dt⁴| over [t0, t0 + T] of the
    flight (module text), written into A and B (with the base's Ω²X_b and Ω⁴X_b).  ``rows``:
    the coupled flight projected on the points (:func:`_held_rows`), or none (shape 0): each
    term's |φᵀwₗVₗcₗ| is then read there (wₗ = 2 counts a conjugate pair)."""
    N, K = pm.shape[0], Phi.shape[0]
    W = pm[0, P_W]
    A[:] = abs(xb) * W * W
    B[:] = abs(xb) * W**4
    if cfg[6]:
        form = cfg[10]
        th = (W * t0 + pm[0, P_PHI]) % (2.0 * math.pi)  # _rigid._phase, shared by the modes
        c, sn = math.cos(th), math.sin(th)
        for i in range(N):
            if pm[i, P_W] == W and pm[i, P_PHI] == pm[0, P_PHI]:
                Ai = _mode_accel_bound(pm[i], form[i], c, sn, t0, q0[i], v0[i], T)
            else:
                Ai = _accel_bound(pm[i], pm[i, P_M], t0, q0[i], v0[i], T)
            for k in range(K):
                A[k] += abs(Phi[k, i]) * Ai
                B[k] += abs(Phi[k, i]) * 2.0 * Ai * form[i, FC_FAST2]
        return A, B
    lam, V, _, Xhat = _modes_of(cfg)
    if rows.shape[0] == K:
        for k in range(K):
            for m in range(lam.shape[0]):
                amp = abs(rows[k, 0, m]) * abs(lam[m]) ** 2
                A[k] += amp
                B[k] += amp * abs(lam[m]) ** 2
            r = abs(rows[k, 0, lam.shape[0]])
            A[k] += r * W * W
            B[k] += r * W**4
            A[k] = A[k] * (1.0 + 1e-9) + 1e-300
            B[k] = B[k] * (1.0 + 1e-9) + 1e-300
        return A, B
    c = _coefficients(pm, cfg, t0, q0, v0)
    for k in range(K):
        for m in range(lam.shape[0]):
            r = 0.0j
            for i in range(N):
                r += Phi[k, i] * V[i, m]
            amp = abs(r) * abs(c[m]) * abs(lam[m]) ** 2
            A[k] += amp
            B[k] += amp * abs(lam[m]) ** 2
        r = 0.0j
        for i in range(N):
            r += Phi[k, i] * Xhat[i]
        A[k] += abs(r) * W * W
        B[k] += abs(r) * W**4
        A[k] = A[k] * (1.0 + 1e-9) + 1e-300
        B[k] = B[k] * (1.0 + 1e-9) + 1e-300
    return A, B


@njit(cache=True)
def _held_off(pm, cfg, nstuck, Phi, row, t0, q0, v0, side, T, A, B, q, v, rows, out, xb):
    """A τ up to which the wall ``side`` the damper of row ``row`` of ``Phi`` just left cannot be
    reached: :func:`symimpact.forced.engine._rigid._held_off` with the point's acceleration
    g = side·ẍₐ, A ≥ |ẍₐ| and B ≥ |g''| (q, v: scratch; ``rows``, ``out``: the coupled flight
    projected on ``Phi``'s points and their scratch, :func:`_held_rows`, or none, shape 0)."""
    period = 2.0 * math.pi / cfg[8]
    dec = cfg[6]
    proj = not dec and rows.shape[0] > 0
    hf, cplx, n2, W = cfg[11], cfg[1], cfg[2], pm[0, P_W]
    span = min(T, period)
    ga = side * _point_accel(pm, cfg, nstuck, Phi, row, t0, q0, v0, xb)
    if ga < -1e-12 * A:
        return 0.0
    ga = max(ga, 0.0)
    g1 = side * _point_jerk(pm, cfg, nstuck, Phi, row, t0, q0, v0, xb)
    tau = min((g1 + math.sqrt(g1 * g1 + 2.0 * B * ga)) / B, span)
    if tau > 0.0 and proj:
        _rows_at(rows, hf, cplx, n2, W, tau, out)
        ga = side * (out[row, 2] + _base_a(pm, xb, t0 + tau))
    elif tau > 0.0:
        _states(pm, cfg, nstuck, t0, q0, v0, tau, q, v)
        ga = side * _point_accel(pm, cfg, nstuck, Phi, row, t0 + tau, q, v, xb)
    H = period / 64.0
    while tau < span:
        H = min(H, span - tau)
        tb = tau + H
        if dec:
            _free_states(pm, cfg[10], t0, q0, v0, tb, q, v)
            gb = side * _free_point_accel(pm, Phi, row, t0 + tb, q, v, xb)
        elif proj:
            _rows_at(rows, hf, cplx, n2, W, tb, out)
            gb = side * (out[row, 2] + _base_a(pm, xb, t0 + tb))
        else:
            _states(pm, cfg, nstuck, t0, q0, v0, tb, q, v)
            gb = side * _point_accel(pm, cfg, nstuck, Phi, row, t0 + tb, q, v, xb)
        if gb >= 0.0 and min(ga, gb) - B * H * H / 8.0 >= 0.0:
            tau, ga = tb, gb
            H = min(2.0 * H, period / 64.0)
        elif H > period / 4096.0:
            H *= 0.5
        else:
            return tau
    return tau


#: The highest degree of a point's Taylor polynomial (:func:`_point_taylor`).
TAYLOR_MAX = 24


@njit(cache=True)
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


@njit(cache=True)
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


@njit(cache=True)
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


@njit(cache=True)
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


@njit(cache=True)
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


@njit(cache=True)
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


@njit(cache=True)
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


@njit(cache=True)
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


@njit(cache=True)
def _row_response(cfg, Phi, row, P):
    """M_s⁻¹φP: the unconstrained response to an impulse P at the point of row ``row``."""
    Mfull = cfg[0][3]
    N = Mfull.shape[0]
    out = np.zeros(N)
    for i in range(N):
        for j in range(N):
            out[i] += Mfull[i, j] * Phi[row, j] * P
    return out


@njit(cache=True)
def _held_index(contact, srig, i):
    """The stop of the i-th held rigid stop."""
    j = 0
    for s in range(contact.shape[0]):
        if contact[s] != 0 and srig[s] != 0:
            if j == i:
                return s
            j += 1
    return -1


@njit(cache=True)
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


@njit(cache=True)
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


@njit(cache=True)
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


#: 1/n! and 1/n (n < 30; 1/0 unused) for :func:`_expint_series`.
_INV_FACT = np.array([1.0 / math.factorial(n) for n in range(30)])
_INV_N = np.array([0.0] + [1.0 / n for n in range(1, 30)])


@njit(cache=True)
def _expint_series(z, tau):
    """τ·Σₙ zⁿ/(n + 1)! = (e^z − 1)/z·τ for abs(z) < 0.5, z = κτ, by Horner's rule up to the
    last power whose next term a^(n+1)/(n + 2)! (a = abs(Re z) + abs(Im z) ≥ abs(z)) falls
    below 5e-18: the terms left out sum to below 1.2 times that, under 1e-17 of the sum
    (abs((e^z − 1)/z) ≥ (1 − e^(−1/2))/(1/2) = 0.79 there)."""
    a = abs(z.real) + abs(z.imag)
    n = 0
    t = 0.5 * a
    while t >= 5e-18 and n < 24:
        n += 1
        t *= a * _INV_N[n + 2]
    acc = complex(_INV_FACT[n + 1], 0.0)
    for j in range(n - 1, -1, -1):
        acc = acc * z + _INV_FACT[j + 1]
    return tau * acc


@njit(cache=True)
def _expint(k, tau, ek):
    """∫₀^τ e^{κt} dt = (e^{κτ} − 1)/κ for a complex κ from ek = e^{κτ}, by its series where κτ is
    small (there the quotient would cancel, :func:`_expint_series`; a chatter's flights are
    short)."""
    z = k * tau
    if abs(z.real) + abs(z.imag) < 0.5:
        return _expint_series(z, tau)
    return (ek - 1.0) / k


@njit(cache=True)
def _expint_by(kinv, z, tau, ek):
    """:func:`_expint` with z = κτ and 1/κ given (a mode's constants, :func:`_mode_constants`):
    a product where the quotient was."""
    if abs(z.real) + abs(z.imag) < 0.5:
        return _expint_series(z, tau)
    return (ek - 1.0) * kinv


@njit(cache=True)
def _pair(x0, x1, y0, y1, E0, E1, E2, E3, E4, E5):
    """∫₀^τ Re(x₀e^{μt} + x₁e^{iΩt})·Re(y₀e^{μt} + y₁e^{iΩt}) dt from E₀ … E₅ = ∫ e^{κt} over the
    exponents κ = 2μ, μ + μ̄, μ + iΩ, μ − iΩ, 2iΩ, 0 (Re a·Re b = (Re ab + Re ab̄)/2); scalars,
    not arrays, as the ledger of every mode's every flight takes it eight times."""
    return 0.5 * (
        (x0 * y0 * E0).real
        + (x0 * np.conj(y0) * E1).real
        + (x0 * y1 * E2).real
        + (x0 * np.conj(y1) * E3).real
        + (x1 * y0 * E2).real
        + (x1 * np.conj(y0) * np.conj(E3)).real
        + (x1 * y1 * E4).real
        + (x1 * np.conj(y1) * E5).real
    )


@njit(cache=True)
def _mode_ledger(pm, i, t0, x0, v0, tau):
    """(work of mode i's force, dissipation of its Cᵢ) over the flight [t0, t0 + τ] of Eq. F1 in
    closed form, or (NaN, NaN) where Eq. F1 takes another form (at or next to the undamped
    resonance, over-damped): the flight is Re(αe^{μt}) + Re(βe^{iΩt}) with μ = −σ + iω_d (the
    particular part β from Eq. F1's steady cosine and sine, α from the start), the force's
    terms are Re(γe^{iΩt}), and each product integrates to (e^{κτ} − 1)/κ.  The power is the
    one-mode engine's, F₀cos θ·ẋ − (K(x − x_b) + C(ẋ − ẋ_b))ẋ_b, the dissipation C(ẋ − ẋ_b)².
    Each two-term signal is a pair of complex scalars (its e^{μt} and e^{iΩt} parts)."""
    W = pm[i, P_W]
    th = (W * t0 + pm[i, P_PHI]) % (2.0 * math.pi)
    f = np.zeros(FORM_COLS)
    _mode_constants(pm, i, f)
    eW = complex(math.cos(W * tau), math.sin(W * tau))
    E4 = _expint(complex(0.0, 2.0 * W), tau, eW * eW)
    return _mode_ledger_at(pm, i, f, x0, v0, tau, math.cos(th), math.sin(th), eW, E4)


@njit(cache=True)
def _mode_ledger_at(pm, i, f, x0, v0, tau, c, sn, eW, E4):
    """:func:`_mode_ledger` from mode i's constants ``f`` (its form row, :func:`_mode_constants`)
    with cos θ₀, sin θ₀ of the flight's start, e^{iΩτ} and E4 = ∫₀^τ e^{2iΩt} dt given (the
    modes share them): each e^{κτ} is a product of e^{μτ} and e^{iΩτ}, one exponential a mode,
    and each integral a product with the constant 1/κ."""
    if f[FC_LEDGER] == 0.0:
        return math.nan, math.nan
    K, C, F0, Xb, W = pm[i, P_K], pm[i, P_C], pm[i, P_F0], pm[i, P_XB], pm[i, P_W]
    sigma, wd, A, B = f[FC_SIGMA], f[FC_WD], f[FC_A], f[FC_B]
    dx = x0 - (A * c + B * sn)
    dv = v0 - W * (B * c - A * sn)
    mu = complex(-sigma, wd)
    rot = complex(c, sn)
    iw = complex(0.0, W)
    zero = 0.0j
    x_0 = complex(dx, -(dv + sigma * dx) / wd)  # the displacement's two terms
    x_1 = complex(A, -B) * rot
    v_0 = mu * x_0
    v_1 = iw * x_1
    xb_1 = Xb * rot  # cos θ(t) is (0, rot); the base's displacement and rate
    vb_1 = iw * Xb * rot
    rel_0, rel_1 = v_0 - zero, v_1 - vb_1
    ex = math.exp(-sigma * tau)
    eu = complex(ex * math.cos(wd * tau), ex * math.sin(wd * tau))  # e^{μτ}
    E0 = _expint_by(complex(f[FC_K2MU], f[FC_K2MU + 1]), 2.0 * mu * tau, tau, eu * eu)
    E1 = _expint_by(complex(f[FC_K2S], 0.0), complex(-2.0 * sigma * tau, 0.0), tau,
                    complex(ex * ex, 0.0))  # fmt: skip
    E2 = _expint_by(complex(f[FC_KPLUS], f[FC_KPLUS + 1]), (mu + iw) * tau, tau, eu * eW)
    E3 = _expint_by(complex(f[FC_KMINUS], f[FC_KMINUS + 1]), (mu - iw) * tau, tau,
                    eu * np.conj(eW))  # fmt: skip
    E5 = complex(tau, 0.0)
    work = F0 * _pair(zero, rot, v_0, v_1, E0, E1, E2, E3, E4, E5)
    if Xb != 0.0:
        work -= K * (
            _pair(x_0, x_1, zero, vb_1, E0, E1, E2, E3, E4, E5)
            - _pair(zero, xb_1, zero, vb_1, E0, E1, E2, E3, E4, E5)
        ) + C * _pair(rel_0, rel_1, zero, vb_1, E0, E1, E2, E3, E4, E5)
    return work, C * _pair(rel_0, rel_1, rel_0, rel_1, E0, E1, E2, E3, E4, E5)


@njit(cache=True)
def _product_integral(x, y, E, Eh, same):
    """∫₀^τ Re(Σ_c x_c e^{μ_c t})·Re(Σ_d y_d e^{μ_d t}) dt = ½ Σ_cd Re(x_c y_d E_cd + x_c ȳ_d Ē'_cd)
    (Re a·Re b = (Re ab + Re ab̄)/2) from E_cd = ∫ e^{(μ_c + μ_d)t} and Eh_cd = ∫ e^{(μ_c + μ̄_d)t}
    (:func:`_held_ledger`), both filled for c ≤ d: E is symmetric and Eh_dc = conj(Eh_cd), so a
    pair c ≠ d is read once from the upper triangle.  ``same``: y is x (a square), whose pairs
    c ≠ d then count twice."""
    n = x.shape[0]
    acc = 0.0
    for c in range(n):
        for d in range(c, n):
            if same:
                term = (x[c] * y[d] * E[c, d]).real + (x[c] * np.conj(y[d]) * Eh[c, d]).real
                acc += term if c == d else 2.0 * term
            else:
                acc += (x[c] * y[d] * E[c, d]).real + (x[c] * np.conj(y[d]) * Eh[c, d]).real
                if c != d:
                    acc += (x[d] * y[c] * E[c, d]).real
                    acc += (x[d] * np.conj(y[c]) * np.conj(Eh[c, d])).real
    return 0.5 * acc


@njit(cache=True)
def _held_ledger(pm, cfg, t0, q0, v0, tau, ledger, Sphi, sc, contact):
    """The coupled flight's ledger (:func:`_flight_ledger`'s integrals) in closed form: q and q̇ are
    sums Re Σ_c x_c e^{μ_c τ} over the flight's kept eigenvalues λₗ, the forcing's iΩ and a
    constant (μ = 0: q_s and the start's correction, :func:`_held_free`), the force and the base's
    motion are Re(·e^{iθ₀}e^{iΩτ}), and every product in the power and the dissipation integrates
    term by term to (e^{κτ} − 1)/κ (:func:`_expint`, κ = μ_c + μ_d or μ_c + μ̄_d).  Work:
    ∫ cos θ·Fᵀq̇ + ∫ (−X_bΩ sin θ)·Σᵢ Γᵢ(−Kᵢ(qᵢ − Γᵢx_b) − Cᵢ(q̇ᵢ − Γᵢẋ_b)) (ledger[0]); the modes'
    dissipation Σᵢ Cᵢ(q̇ᵢ − Γᵢẋ_b)² (ledger[1]) and the pressed stops' c(φₛᵀq̇)² (ledger[3]):
    O(n²N) products a flight where the quadrature's rule takes 8 states a step of 0.75/λ_max."""
    hf = cfg[11]
    if not _held_fresh(hf, t0, q0, v0):
        _held_fill(pm, cfg, t0, q0, v0)
    N = pm.shape[0]
    N2 = 2 * N
    n2 = cfg[2]
    cplx = cfg[1]
    last = cplx.shape[0] - 1
    W = pm[0, P_W]
    th = W * t0 + pm[0, P_PHI]
    rot = complex(math.cos(th), math.sin(th))
    nk = 0
    for m in range(n2):
        if hf[N2 + 2, m].real != 0.0:
            nk += 1
    nc = nk + 2  # the kept terms, the forcing's, the constant
    mu = np.empty(nc, dtype=np.complex128)
    ex = np.empty(nc, dtype=np.complex128)
    qc = np.zeros((nc, N), dtype=np.complex128)  # qᵢ's coefficients, column by column
    vc = np.zeros((nc, N), dtype=np.complex128)
    c = 0
    for m in range(n2):
        if hf[N2 + 2, m].real == 0.0:
            continue
        mu[c] = cplx[last, m]
        er, ei = _growth(mu[c], tau)
        ex[c] = complex(er, ei)
        for i in range(N):
            qc[c, i] = hf[i, m]
            vc[c, i] = hf[N + i, m]
        c += 1
    fo, co = nk, nk + 1
    mu[fo], ex[fo] = complex(0.0, W), complex(math.cos(W * tau), math.sin(W * tau))
    mu[co], ex[co] = 0.0j, 1.0 + 0.0j
    qs = cfg[3][1]
    for i in range(N):
        qc[fo, i] = hf[i, n2]
        vc[fo, i] = hf[N + i, n2]
        qc[co, i] = q0[i] - hf[N2, i].imag + qs[i]
        vc[co, i] = v0[i] - hf[N2, N + i].imag
    E = np.zeros((nc, nc), dtype=np.complex128)
    Eh = np.zeros((nc, nc), dtype=np.complex128)
    for a in range(nc):
        for b in range(a, nc):
            E[a, b] = _expint(mu[a] + mu[b], tau, ex[a] * ex[b])
            Eh[a, b] = _expint(mu[a] + np.conj(mu[b]), tau, ex[a] * np.conj(ex[b]))
    # the modes' dissipation, Σᵢ Cᵢ·relᵢ², relᵢ = q̇ᵢ − Γᵢẋ_b (ẋ_b's column: the forcing's)
    base = False
    for i in range(N):
        if pm[i, P_XB] != 0.0:
            base = True
    rel = np.empty(nc, dtype=np.complex128)
    lost = 0.0
    for i in range(N):
        if pm[i, P_C] == 0.0:
            continue
        for a in range(nc):
            rel[a] = vc[a, i]
        rel[fo] -= 1j * W * pm[i, P_XB] * rot
        lost += pm[i, P_C] * _product_integral(rel, rel, E, Eh, True)
    # the work: the force against Fᵀq̇, the base's motion against Σᵢ Γᵢ(−Kᵢ(qᵢ − xgᵢ) − Cᵢrelᵢ)
    y = np.zeros(nc, dtype=np.complex128)
    for a in range(nc):
        for i in range(N):
            y[a] += pm[i, P_F0] * vc[a, i]
    force = np.zeros(nc, dtype=np.complex128)
    force[fo] = rot
    work = _product_integral(force, y, E, Eh, False)
    if base:
        y[:] = 0.0
        for i in range(N):
            xbi = pm[i, P_XB]
            for a in range(nc):
                y[a] += xbi * (-pm[i, P_K] * qc[a, i] - pm[i, P_C] * vc[a, i])
            y[fo] += xbi * (pm[i, P_K] * xbi * rot + pm[i, P_C] * 1j * W * xbi * rot)
        force[fo] = 1j * W * rot
        work += _product_integral(force, y, E, Eh, False)
    ledger[0] += work
    ledger[1] += lost
    for r in range(Sphi.shape[0]):
        if contact[r] == 0 or sc[r] == 0.0:
            continue
        for a in range(nc):
            rel[a] = 0.0
            for i in range(N):
                rel[a] += Sphi[r, i] * vc[a, i]
        ledger[3] += sc[r] * _product_integral(rel, rel, E, Eh, True)


@njit(cache=True)
def _flight_ledger(pm, cfg, nstuck, t0, q0, v0, tau, ledger, work, Sphi, sc, contact, dec):
    """The energy ledger over the flight [t0, t0 + τ] (:func:`_segment`, which calls it with
    ``energy``): the work of the modal forces and the dissipation of the Cᵢ (ledger[0],
    ledger[1]) in closed form while the modes are uncoupled (``dec``, :func:`_mode_ledger`) and
    while masses stick on a flight longer than 0.75/λ_max (:func:`_held_ledger`), else by
    Gauss–Legendre rules on steps of at most 0.75/λ_max (8 points; 4 where the step is below
    0.05/λ_max; λ_max of :func:`_pack`, their errors in the code), with the pressed stops'
    dashpots, c₁(φₛᵀq̇)² (ledger[3]).  ``work``'s rows 3 and 4 are scratch for the states at the
    nodes."""
    N = pm.shape[0]
    W = pm[0, P_W]
    q, v = work[3], work[4]
    closed = dec
    if dec:
        w_sum, d_sum = 0.0, 0.0
        th0 = (W * t0 + pm[0, P_PHI]) % (2.0 * math.pi)
        c0, s0 = math.cos(th0), math.sin(th0)
        eW = complex(math.cos(W * tau), math.sin(W * tau))
        E4 = _expint(complex(0.0, 2.0 * W), tau, eW * eW)
        form = cfg[10]
        for i in range(N):
            if pm[i, P_W] == W and pm[i, P_PHI] == pm[0, P_PHI]:
                wi, di = _mode_ledger_at(pm, i, form[i], q0[i], v0[i], tau, c0, s0, eW, E4)
            else:
                wi, di = _mode_ledger(pm, i, t0, q0[i], v0[i], tau)
            if math.isnan(wi):
                closed = False
                break
            w_sum += wi
            d_sum += di
        if closed:
            ledger[0] += w_sum
            ledger[1] += d_sum
    if not dec and tau * cfg[12] > 0.75:  # more than one of the rule's steps
        _held_ledger(pm, cfg, t0, q0, v0, tau, ledger, Sphi, sc, contact)
        return
    if not closed:
        # each product in the power is a sum of e^{κt} with abs(κ) ≤ 2λ_max (cfg[12]): the
        # n-point rule's error over a step h is h·(κh)^{2n}(n!)⁴/((2n + 1)((2n)!)³) of the
        # integrand's size, ≤ 1e-20 for 8 points at κh ≤ 1.5 and ≤ 6e-18 for 4 at κh ≤ 0.1
        n = max(1, int(math.ceil(tau * cfg[12] / 0.75)))  # noqa: RUF046 (int() for numba)
        hs = tau / n
        four = hs * cfg[12] <= 0.05
        for j in range(n):
            a = j * hs
            for g in range(4 if four else 8):
                node, weight = (_GL4_X[g], _GL4_W[g]) if four else (_GL_X[g], _GL_W[g])
                s = a + 0.5 * hs * (1.0 + node)
                if dec:
                    _free_states(pm, cfg[10], t0, q0, v0, s, q, v)
                else:
                    _states(pm, cfg, nstuck, t0, q0, v0, s, q, v)
                th = W * (t0 + s) + pm[0, P_PHI]
                c, sn = math.cos(th), math.sin(th)
                for i in range(N):
                    # the one-mode engine's power with each mode's base amplitude Γᵢ·X_b
                    xg, vg = pm[i, P_XB] * c, -pm[i, P_XB] * W * sn
                    rel = v[i] - vg
                    power_in = (
                        pm[i, P_F0] * c * v[i] - (pm[i, P_K] * (q[i] - xg) + pm[i, P_C] * rel) * vg
                    )
                    ledger[0] += 0.5 * hs * weight * power_in
                    ledger[1] += 0.5 * hs * weight * pm[i, P_C] * rel * rel
                if not dec:
                    for r in range(Sphi.shape[0]):
                        if contact[r] != 0:
                            rate = _dot(Sphi, r, v)
                            ledger[3] += 0.5 * hs * weight * sc[r] * rate * rate


@njit(cache=True)
def _segment(pm, cfg, nstuck, Pout, t0, q0, v0, tau, ledger, period_max, n_periods, work, Sphi,
             sc, contact, rows, out, xb, energy):  # fmt: skip
    """Account for the flight [t0, t0 + τ]: with ``energy``, its energy ledger
    (:func:`_flight_ledger`); and, for every output point p (rows of ``Pout``, its shapes), the largest abs(xₚ) of every forcing period
    crossed (``period_max[k, p]``), at the ends of the steps and at the zeros of ẋₚ inside them.
    Within a step of length h, abs(xₚ) ≤ max(abs(xₚ(a)), abs(xₚ(b))) + Aₚh²/8 (Aₚ ≥ abs(ẍₚ), as
    the impact search bounds it): a step whose bound cannot raise the period's maximum is taken,
    so is one over which ẋₚ keeps its sign (ẋₚ(a) + ẋₚ(b) > Aₚh, of one sign: the extremes are
    its ends), and any other is halved down to a sixteenth of the shortest period, where a zero
    of ẋₚ is located where its sign changes (with several modes, ẋₚ ripples at the highest
    mode's frequency and most of its zeros are such).  Under base motion (``xb`` = X_b) the
    output points' displacements are absolute, x_b + φₚᵀq.  A coupled flight is read through
    its projection on the output points (:func:`_held_rows`, into ``rows``; ``out``: its
    scratch)."""
    N, P = pm.shape[0], Pout.shape[0]
    dec = cfg[6]
    hf, cplx, n2, W = cfg[11], cfg[1], cfg[2], pm[0, P_W]
    Ap, Bp, v_prev, x_prev = work[10], work[11], work[12], work[13]
    xs, vs, fine = work[19], work[20], work[21]
    W = pm[0, P_W]
    T_f = 2.0 * math.pi / W
    hq = 2.0 * math.pi / cfg[8] / 16.0
    q, v = work[3], work[4]
    if energy:
        _flight_ledger(pm, cfg, nstuck, t0, q0, v0, tau, ledger, work, Sphi, sc, contact, dec)
    if P == 0:
        return
    if not dec:
        _held_rows(pm, cfg, Pout, t0, q0, v0, rows, out)
    _bounds(pm, cfg, nstuck, Pout, t0, q0, v0, tau, Ap, Bp, rows, xb)
    for p in range(P):
        v_prev[p] = _base_v(pm, xb, t0)
        x_prev[p] = _base_x(pm, xb, t0)
        for i in range(N):
            v_prev[p] += Pout[p, i] * v0[i]
            x_prev[p] += Pout[p, i] * q0[i]
    Hc = 2.0 * math.pi / cfg[9] / 16.0
    a = 0.0
    H = Hc
    poly = np.empty(TAYLOR_MAX + 1)
    while a < tau:
        H = min(H, tau - a)
        b = a + H
        if dec:
            _free_states(pm, cfg[10], t0, q0, v0, b, q, v)
        else:
            _rows_at(rows, hf, cplx, n2, W, b, out)
        ka = min(int(math.floor((t0 + a) / T_f)), n_periods)  # noqa: RUF046
        k = int(math.floor((t0 + b) / T_f))  # noqa: RUF046 (int() spelled out for numba)
        taken = True
        xbb, vbb = _base_x(pm, xb, t0 + b), _base_v(pm, xb, t0 + b)
        for p in range(P):
            xp, vp = xbb, vbb
            if dec:
                for i in range(N):
                    xp += Pout[p, i] * q[i]
                    vp += Pout[p, i] * v[i]
            else:
                xp += out[p, 0]
                vp += out[p, 1]
            xs[p], vs[p], fine[p] = xp, vp, 0.0
            top = max(abs(x_prev[p]), abs(xp)) + Ap[p] * H * H / 8.0
            low = period_max[ka, p]
            if k < n_periods:
                low = min(low, period_max[k, p])
            slope = v_prev[p] + vp
            one_sign = (v_prev[p] > 0.0) == (vp > 0.0) and v_prev[p] != 0.0 and vp != 0.0
            if top <= low or (one_sign and abs(slope) > Ap[p] * H):
                continue
            if H > hq and H > 4e-16 * (t0 + b):
                taken = False
                break
            fine[p] = 1.0
        if not taken:
            H *= 0.5
            continue
        for p in range(P):
            if k < n_periods:
                period_max[k, p] = max(period_max[k, p], abs(xs[p]))
            if fine[p] != 0.0 and (v_prev[p] > 0.0) != (vs[p] > 0.0) and v_prev[p] != 0.0:
                lo, hi, flo, fhi = a, b, v_prev[p], vs[p]
                kept = 0
                mid = 0.5 * (a + b)  # ẋₚ from the derivative of xₚ's Taylor polynomial
                deg = _point_taylor(pm, cfg, Pout, p, t0, q0, v0, mid, 0.5 * (b - a), rows, xb,
                                    poly, 1)  # fmt: skip
                for _ in range(100):
                    tm = secant_point(lo, hi, flo, fhi)
                    if deg >= 1:
                        sg = tm - mid
                        vm = deg * poly[deg]
                        for j in range(deg - 1, 0, -1):
                            vm = vm * sg + j * poly[j]
                    elif dec:
                        vm = _base_v(pm, xb, t0 + tm)
                        _free_states(pm, cfg[10], t0, q0, v0, tm, q, v)
                        for i in range(N):
                            vm += Pout[p, i] * v[i]
                    else:
                        vm = _base_v(pm, xb, t0 + tm)
                        _rows_at(rows, hf, cplx, n2, W, tm, out)
                        vm += out[p, 1]
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
                xm = _base_x(pm, xb, t0 + 0.5 * (lo + hi))
                if dec:
                    _free_states(pm, cfg[10], t0, q0, v0, 0.5 * (lo + hi), q, v)
                    for i in range(N):
                        xm += Pout[p, i] * q[i]
                else:
                    _rows_at(rows, hf, cplx, n2, W, 0.5 * (lo + hi), out)
                    xm += out[p, 0]
                km = int(math.floor((t0 + 0.5 * (lo + hi)) / T_f))  # noqa: RUF046
                if km < n_periods:
                    period_max[km, p] = max(period_max[km, p], abs(xm))
            x_prev[p] = xs[p]
            v_prev[p] = vs[p]
        a = b
        H = min(2.0 * H, Hc)


@njit(cache=True)
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


@njit(cache=True)
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


@njit(cache=True)
def _wall_kept(stuck, z, hd, j):
    """The wall (±1) free damper j starts the next flight on where it sits on it, to 1e-9 of its
    half clearance (a mass let go, or met, at the instant of another's event), else 0.  Forgotten,
    the search met that wall again at once at rounding-level speeds, and two masses at one point
    passed the meeting back and forth millions of times; kept for a mass that approaches it, it
    holds nothing off (:func:`_next_impact` holds a wall off only while the mass leaves it)."""
    if stuck[j] != 0 or abs(z[j]) < hd[j] * (1.0 - 1e-9):
        return 0
    return 1 if z[j] > 0.0 else -1


@njit(cache=True)
def _log(events, n_ev, t, x, xd, yd, s, vrel, lost, kind, xd1, yd1, k):
    events = _grow(events, n_ev)
    ev = events[n_ev]
    ev[E_T], ev[1], ev[2], ev[3], ev[E_SIDE] = t, x, xd, yd, s
    ev[E_VREL], ev[E_LOST], ev[E_KIND], ev[8], ev[9] = vrel, lost, kind, xd1, yd1
    ev[E_DAMPER] = k
    return events, n_ev + 1


@njit(cache=True)
def _dot(Phi, row, v):
    out = 0.0
    for i in range(Phi.shape[1]):
        out += Phi[row, i] * v[i]
    return out


# --- the monodromy: the flights' transition matrices and the events' saltation matrices -------


@njit(cache=True)
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


@njit(cache=True)
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


@njit(cache=True)
def _saltation(DJ, fm, fp, gh, G):
    """G ← S·G with S = D + (f⁺ − D·f⁻)∇hᵀ/(∇h·f⁻): the jump's Jacobian D and the effect of the
    event's time, which moves with the state (h = 0 on the switching surface, f∓ the rates just
    before and after)."""
    den = gh @ fm
    r = fp - DJ @ fm
    S = DJ + np.outer(r, gh) / den
    G[:, :] = S @ G


@njit(cache=True)
def _timed_saltation(DJ, fm, fp, gh, gt, jt, G):
    """G ← S·G with S = D + (f⁺ − D·f⁻ − ∂J/∂t)∇hᵀ/(∇h·f⁻ + ∂h/∂t): :func:`_saltation` for a
    surface h and a jump J that move with time (a damper's wall on supports that move:
    ``gt`` = ∂h/∂t, ``jt`` = ∂J/∂t)."""
    den = gh @ fm + gt
    r = fp - DJ @ fm - jt
    S = DJ + np.outer(r, gh) / den
    G[:, :] = S @ G


@njit(cache=True)
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


@njit(cache=True)
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


@njit(cache=True)
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


@njit(cache=True)
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


@njit(cache=True)
def _kept_alive(owned, cfgs):
    """Nothing: its call at the end of :func:`run` keeps the run's own arrays and configurations
    alive until then, under the borrowed views the run works with (:mod:`._borrowed`)."""
    return len(owned) + len(cfgs)


@njit(cache=True)
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


@njit(cache=True)
def one_mode_run(p, state0, t_end, max_events, variational, energy, watch):
    """The paper's primary through :func:`run`: one mode of mass M and shape 1 (parameters
    ``p`` in :mod:`symimpact.forced.engine._rigid`'s layout), one damper, from state0 = (x, ẋ, y, ẏ).
    ``variational`` is passed on to :func:`run` as it came (callers give False: the one-mode
    chain is built from the event log, :mod:`symimpact.forced.engine._chain`).  It is an argument, not
    a constant written here, because numba compiles a callee once for each literal it is given:
    a ``False`` typed here would compile the whole engine a second time (minutes on a 2-core
    machine) beside the structure's own signature, which this one now shares; ``energy`` is
    passed on so too.

    Returns (status, events, n_events, period_max, ledger, final) in the one-mode layout: events
    with :mod:`symimpact.forced.engine._rigid`'s ten columns, the largest abs(x) of every period, the
    ledger's first three terms (no stops), final = (t, x, ẋ, y, ẏ, 1.0 if it ended stuck)."""
    pm = p.reshape((1, p.shape[0])).copy()
    one = np.ones((1, 1))
    status, events, n_ev, period_max, ledger, final, _ = run(
        pm, one, np.array([p[P_m]]), np.array([p[P_h]]), np.array([p[P_e]]),
        np.array([p[P_VY]]), np.array([-1]), p[P_CHAT], np.zeros((0, 1)), np.zeros(0),
        np.zeros(0, dtype=np.int64), np.zeros(0), np.zeros(0), np.zeros(0, dtype=np.int64),
        np.zeros(0), state0[0:1].copy(), state0[1:2].copy(),
        state0[2:3].copy(), state0[3:4].copy(), one, 0.0, 0.0, t_end, max_events, variational,
        np.zeros(1), np.zeros(0), energy, watch,
    )  # fmt: skip
    out = np.array([final[0], final[1], final[2], final[3], final[4], 0.0])
    if final[5] != 0.0:
        out[5] = 1.0
    return (status, events[:, :N_EVENT_COLS].copy(), n_ev, period_max[:, 0].copy(),
            ledger[:3].copy(), out)  # fmt: skip


def _forget_stale_compilations() -> None:
    """This module's and :mod:`._borrowed`'s cached code, dropped when it, the one-mode flight
    functions it calls, the borrowed views, the forced-flight kernels or the stepper's secant
    changed (numba's cache does not follow a callee into another module)."""
    from pathlib import Path

    from ...free import _stepper
    from ...generated import forced_flight
    from . import _borrowed, _rigid

    sources = [Path(__file__), Path(_rigid.__file__), Path(forced_flight.__file__),
               Path(_stepper.__file__), Path(_borrowed.__file__)]  # fmt: skip
    _stepper.forget_stale_compilations(run, sources, ("_modal.", "_borrowed."))


_forget_stale_compilations()
