"""The modal engine's flight (:mod:`._modal`): the closed form between events.

While no mass sticks, mode i follows Step 8's forced flight (Eq. F1) in the flight's own time
(:func:`_free_states`); while masses stick, the stuck structure's first-order closed form
X(τ) = Re(V e^{Λτ} V⁻¹(X₀ − X_p(t₀))) + X_p(t₀ + τ) (:func:`_held_config`, :func:`_held_free`),
and the projections of either on the points the searches watch (:func:`_held_rows`,
:func:`_rows_at`).  The bounds on a point's acceleration that certify the searches' steps
(:func:`_bounds`) and the wall just left kept off (:func:`_held_off`).  The module docstring of
:mod:`._modal` tells the whole engine.
"""

from __future__ import annotations

import math

import numpy as np

from ..._compiled import compiled
from ...generated import forced_flight as _fl
from ._borrowed import borrowed_config
from ._rigid import (
    N_EVENT_COLS,
    P_C,
    P_F0,
    P_K,
    P_M,
    P_PHI,
    P_W,
    P_XB,
    _accel_bound,
    _steady_cos,
    _steady_sin,
    _xvf,
)

#: Eq. F1 in the flight's own time (Step 8's ``flight_form``): a, b, c, s of x, then of ẋ, σ, ω_d.
_form = compiled(_fl.flight_form_scalar)
#: A flight's form cache (:func:`_free_states`), one per configuration: row i holds mode i's ten
#: coefficients, its start (qᵢ, q̇ᵢ) and whether the form has them (0: an undamped mode driven
#: at its own frequency, where Eq. F1 grows like t and has no such form); row N holds the
#: flight's start time and whether the cache is filled.  Columns 13 … of row i hold mode i's
#: constants in its configuration (:func:`_mode_constants`), which the bounds and the ledger of
#: every flight read.
(FC_STEADY, FC_A, FC_B, FC_AMP, FC_SIGMA, FC_WD, FC_WN2, FC_FAST2, FC_LEDGER, FC_K2MU, FC_K2S,
 FC_KPLUS, FC_KMINUS) = (13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 24, 25, 27)  # fmt: skip
FORM_COLS = 29

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


@compiled
def _mode_accel(pm, i, mass, t, x, v):
    """Mode i's q̈ᵢ (:func:`symimpact.forced.engine._rigid._accel` on row i of ``pm``)."""
    W, K, C = pm[i, P_W], pm[i, P_K], pm[i, P_C]
    th = W * t + pm[i, P_PHI]
    P = pm[i, P_F0] + K * pm[i, P_XB]
    Q = -C * W * pm[i, P_XB]
    return (P * math.cos(th) + Q * math.sin(th) - C * v - K * x) / mass


@compiled
def _mode_jerk(pm, i, mass, t, x, v):
    """Mode i's d³qᵢ/dt³ (:func:`symimpact.forced.engine._rigid._jerk` on row i of ``pm``)."""
    W, K, C = pm[i, P_W], pm[i, P_K], pm[i, P_C]
    th = W * t + pm[i, P_PHI]
    P = pm[i, P_F0] + K * pm[i, P_XB]
    Q = -C * W * pm[i, P_XB]
    a = _mode_accel(pm, i, mass, t, x, v)
    return (W * (Q * math.cos(th) - P * math.sin(th)) - C * a - K * v) / mass


@compiled
def _base_x(pm, xb, t):
    """x_b(t) = X_b·cos(Ωt + φ) [m], the supports' displacement (``xb``: X_b; 0 without base
    motion, then exactly 0)."""
    if xb == 0.0:
        return 0.0
    return xb * math.cos(pm[0, P_W] * t + pm[0, P_PHI])


@compiled
def _base_v(pm, xb, t):
    """ẋ_b(t) [m/s]."""
    if xb == 0.0:
        return 0.0
    return -xb * pm[0, P_W] * math.sin(pm[0, P_W] * t + pm[0, P_PHI])


@compiled
def _base_a(pm, xb, t):
    """ẍ_b(t) [m/s²]."""
    if xb == 0.0:
        return 0.0
    W = pm[0, P_W]
    return -xb * W * W * math.cos(W * t + pm[0, P_PHI])


@compiled
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


@compiled
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


@compiled
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


@compiled
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


@compiled
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


@compiled
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


@compiled
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


@compiled
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


@compiled
def _modes_of(cfg):
    """(Λ, V, V⁻¹, X̂) of a coupled configuration (views into its packed array)."""
    cplx, n2 = cfg[1], cfg[2]
    N2 = cplx.shape[0] - n2 - 2
    return cplx[N2 + n2 + 1, :n2], cplx[:N2, :n2], cplx[N2 : N2 + n2, :N2], cplx[N2 + n2, :N2]


@compiled
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


@compiled
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


@compiled
def _cmv(A, x):
    """A·x for a complex matrix of any shape (a held structure's may have no column)."""
    out = np.zeros(A.shape[0], dtype=np.complex128)
    for i in range(A.shape[0]):
        acc = 0.0j
        for j in range(A.shape[1]):
            acc += A[i, j] * x[j]
        out[i] = acc
    return out


@compiled
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


@compiled
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


@compiled
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


@compiled
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


@compiled
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


@compiled
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


@compiled
def _growth(lam, tau):
    """(Re, Im) of e^{λτ}: one term of the coupled flight's sum (:func:`_held_free`)."""
    ex = math.exp(lam.real * tau)
    return ex * math.cos(lam.imag * tau), ex * math.sin(lam.imag * tau)


@compiled
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


@compiled
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


@compiled
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


@compiled
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


@compiled
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


@compiled
def _stuck_acceleration(cfg, r, i):
    """q̈ᵢ of the coupled structure: row i of M_s⁻¹r, r its loads (:func:`_stuck_loads`,
    computed once for all i)."""
    Minv = cfg[0][0]
    g = 0.0
    for j in range(r.shape[0]):
        g += Minv[i, j] * r[j]
    return g


@compiled
def _free_point_accel(pm, Phi, row, t, q, v, xb):
    """ẍₐ = φᵀq̈ + ẍ_b at the point of row ``row`` of ``Phi`` while the modes are uncoupled: each
    mode's Eq. F1 (:func:`_point_accel`, without the configuration: see :func:`_free_states`)."""
    a = _base_a(pm, xb, t)
    for i in range(pm.shape[0]):
        a += Phi[row, i] * _mode_accel(pm, i, pm[i, P_M], t, q[i], v[i])
    return a


@compiled
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


@compiled
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


@compiled
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


@compiled
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


@compiled
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


@compiled
def _dot(Phi, row, v):
    out = 0.0
    for i in range(Phi.shape[1]):
        out += Phi[row, i] * v[i]
    return out
