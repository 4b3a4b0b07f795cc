"""The modal engine's energy ledger and its periods' maxima (:mod:`._modal`).

The work of the modal forces and the dissipation of the Cᵢ over a flight, in closed form while
the modes are uncoupled (:func:`_mode_ledger`), in the coupled flight's terms while masses stick
(:func:`_held_ledger`), or by Gauss–Legendre rules on a short flight (:func:`_flight_ledger`); and
the march of a flight that records each forcing period's largest displacement at the watched
points (:func:`_segment`).  The module docstring of :mod:`._modal` tells the whole engine.
"""

from __future__ import annotations

import math

import numpy as np

from ..._compiled import compiled
from ...free._stepper import secant_point
from ._modal_flight import (
    FC_A,
    FC_B,
    FC_K2MU,
    FC_K2S,
    FC_KMINUS,
    FC_KPLUS,
    FC_LEDGER,
    FC_SIGMA,
    FC_WD,
    FORM_COLS,
    _base_v,
    _base_x,
    _bounds,
    _dot,
    _free_states,
    _growth,
    _held_fill,
    _held_fresh,
    _held_rows,
    _mode_constants,
    _rows_at,
    _states,
)
from ._modal_search import (
    _INV_FACT,
    _INV_N,
    TAYLOR_MAX,
    _point_taylor,
)
from ._rigid import (
    _GL_W,
    _GL_X,
    P_C,
    P_F0,
    P_K,
    P_PHI,
    P_W,
    P_XB,
)

#: The 4-point Gauss–Legendre rule (the one-mode engine's is 8-point, _GL_X, _GL_W), for the
#: ledger's short steps (:func:`_segment`).
_GL4_X, _GL4_W = np.polynomial.legendre.leggauss(4)


@compiled
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


@compiled
def _expint(k, tau, ek):
    """∫₀^τ e^{κt} dt = (e^{κτ} − 1)/κ for a complex κ from ek = e^{κτ}, by its series where κτ is
    small (there the quotient would cancel, :func:`_expint_series`; a chatter's flights are
    short)."""
    z = k * tau
    if abs(z.real) + abs(z.imag) < 0.5:
        return _expint_series(z, tau)
    return (ek - 1.0) / k


@compiled
def _expint_by(kinv, z, tau, ek):
    """:func:`_expint` with z = κτ and 1/κ given (a mode's constants, :func:`_mode_constants`):
    a product where the quotient was."""
    if abs(z.real) + abs(z.imag) < 0.5:
        return _expint_series(z, tau)
    return (ek - 1.0) * kinv


@compiled
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


@compiled
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


@compiled
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


@compiled
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


@compiled
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


@compiled
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


@compiled
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
