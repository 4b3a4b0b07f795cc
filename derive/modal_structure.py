r"""Step 15 — a structure of several modes: its modal equations under force and base motion,
modal damping, how much of its mass each mode moves, and an impact in modal coordinates.

Beyond the paper.  Step 14 gives a beam's modes; a finite-element model gives others.  Whatever
their source, the modes turn the structure into uncoupled oscillators, each of which flies between
impacts by Step 8's solution.  On the board:

1. A structure M ẍ + C(ẋ − r ẋ<sub>b</sub>) + K(x − r x<sub>b</sub>) = f, r the displacement of
   every degree of freedom when the base moves by one unit, written on its modes x = Σ φᵢqᵢ.
   With Kφᵢ = ωᵢ²Mφᵢ and K symmetric, φᵢᵀKr = Kᵢ·Γᵢ (Γᵢ = φᵢᵀMr/Mᵢ, the participation
   factor), and with proportional damping φᵢᵀCr = Cᵢ·Γᵢ: each mode obeys Step 8's equation with
   its own Mᵢ, Kᵢ, Cᵢ, the force F₀·φᵢ(a) at the driven point a and the base amplitude Γᵢ·X<sub>b</sub>.
   Shown on a two-degree-of-freedom chain, checked on a three-degree-of-freedom chain against its
   complex frequency response.
2. Proportional (Rayleigh) damping C = αM + βK gives ζᵢ = α/(2ωᵢ) + βωᵢ/2; the α, β that give a
   ratio ζ at two frequencies.
3. The effective modal masses MᵢΓᵢ² sum to the mass the base carries, rᵀMr (from
   Φ diag(1/Mᵢ) Φᵀ = M⁻¹); for the three beams of Step 14, Γᵢ and the share of the beam's mass
   each mode moves from ∫φ dξ in closed form.
4. An impact at a point a where the modes have the values φᵢ(a): the impulse enters each mode
   through φᵢ(a), the effective mass is 1/m<sub>eff</sub> = Σ φᵢ(a)²/Mᵢ, and the saltation matrix
   in modal coordinates, checked by a perturbed impact; one mode with φ = 1 gives Step 9's.
5. Sticking at a: the impact mass rides with the point, and the structure carries it — the modal
   mass matrix gains m·φφᵀ, inverted in closed form (Sherman–Morrison); the point's acceleration
   that decides the release; the stuck structure's frequencies from a secular equation (the
   matrix determinant lemma), interlacing the free ones; one mode gives Step 9's sticking phase,
   one mass M + m.
"""

from __future__ import annotations

import mpmath as mp
import sympy as sp

from .beam_modes import BEAMS, NAMES, _mode_shapes, norm_at_root, roots
from .board import Arg, Board, rounding_scale
from .forced_flight import derive as forced_flight_step

#: Modes summed for the effective-mass sum rule of the beams.
N_SUM = 64


def _chain(masses, springs):
    """Mass and stiffness matrices of a chain grounded at its first spring."""
    n = len(masses)
    M = sp.diag(*masses)
    K = sp.zeros(n, n)
    for i, k in enumerate(springs):
        K[i, i] += k
        if i > 0:
            K[i - 1, i - 1] += k
            K[i - 1, i] -= k
            K[i, i - 1] -= k
    return M, K


def derive() -> Board:
    board = Board("modal_structure", "A structure of several modes", "F7")
    w = board.write

    # --- 1. the modal equations -----------------------------------------------------------------
    m1, m2, k1, k2 = sp.symbols("m_1 m_2 k_1 k_2", positive=True)
    M2, K2 = _chain((m1, m2), (k1, k2))
    w(
        "chain_mass_matrix",
        M2,
        "A chain of two masses on two springs, the first to the base: M.",
    )
    w("chain_stiffness_matrix", K2, "Its stiffness matrix K; the base moves both masses "
      "rigidly, r = (1, 1), and K·r = (k₁, 0) is the force the base's motion puts in.")  # fmt: skip
    lam = sp.Symbol("lambda", positive=True)
    char = w("chain_characteristic", sp.factor((K2 - lam * M2).det()),
             "det(K − λM), λ = ω²: its two roots are the chain's ωᵢ².")  # fmt: skip
    lams = sp.solve(char, lam)
    r = sp.Matrix([1, 1])
    phis = []
    for li in lams:
        # (K − λM)φ = 0 from its first row: φ = (k₂, k₁ + k₂ − λm₁)
        phis.append(sp.Matrix([k2, k1 + k2 - li * m1]))
    ortho_m = sp.simplify((phis[0].T * M2 * phis[1])[0])
    ortho_k = sp.simplify((phis[0].T * K2 * phis[1])[0])
    board.check(
        "the chain's two modes are M- and K-orthogonal",
        "F7",
        ortho_m == 0 and ortho_k == 0,
    )
    base_k = [
        sp.simplify((p.T * K2 * r)[0] - li * (p.T * M2 * r)[0])
        for p, li in zip(phis, lams, strict=True)
    ]
    board.check(
        "φᵢᵀKr = ωᵢ²φᵢᵀMr = KᵢΓᵢ: the base enters mode i through Γᵢ = φᵢᵀMr/Mᵢ (chain of two)",
        "F7",
        all(b == 0 for b in base_k),
        "(Kφᵢ)ᵀr = ωᵢ²(Mφᵢ)ᵀr as K is symmetric",
    )
    Mi, Ki, Ci, Gi, phia = sp.symbols("M_i K_i C_i Gamma_i varphi_i(a)", real=True)
    t = sp.Symbol("t", real=True)
    F0, Xb, W, ph = sp.symbols("F0 X_b Omega phi", real=True)
    q = sp.Function("q_i")(t)
    xb = Xb * sp.cos(W * t + ph)
    w(
        "modal_equation",
        sp.Eq(Mi * q.diff(t, 2) + Ci * (q.diff(t) - Gi * xb.diff(t)) + Ki * (q - Gi * xb),
              phia * F0 * sp.cos(W * t + ph)),
        "Mode i of the structure: φᵢᵀ(M ẍ + C(ẋ − r ẋ<sub>b</sub>) + K(x − r x<sub>b</sub>) − f) "
        "= 0 with x = Σφⱼqⱼ, the other modes dropping out by orthogonality.  It is Step 8's "
        "equation (F1) with M → Mᵢ, K → Kᵢ, C → Cᵢ, F₀ → φᵢ(a)F₀ and X<sub>b</sub> → ΓᵢX<sub>b</sub>.",
        "F7",
    )  # fmt: skip

    # the check: a three-degree-of-freedom chain's steady response at its top, by modes with Step
    # 8's steady coefficients, against the complex frequency response of the full equations
    b8 = forced_flight_step()
    A8, B8 = b8.values["steady_cosine"], b8.values["steady_sine"]
    P8, Q8 = b8.values["P"], b8.values["Q"]
    sym8 = {
        s.name: s for s in (A8.free_symbols | B8.free_symbols | P8.free_symbols | Q8.free_symbols)
    }
    with mp.workdps(40):
        ms = [mp.mpf(1), mp.mpf("1.5"), mp.mpf("0.7")]
        ks = [mp.mpf(2000), mp.mpf(1500), mp.mpf(900)]
        Mn, Kn = _chain(ms, ks)
        Mm, Km = mp.matrix(Mn.tolist()), mp.matrix(Kn.tolist())
        alpha, beta = mp.mpf("0.8"), mp.mpf("2e-4")
        Cm = alpha * Mm + beta * Km
        rr = mp.matrix([1, 1, 1])
        fa = mp.matrix([0, 0, 1])
        F0n, Xbn, Wn = mp.mpf(3), mp.mpf("0.002"), mp.mpf(31)
        # full: (K − Ω²M + iΩC) X = F0·fa + (K + iΩC) r X_b, x(t) = Re(X e^{iΩt})
        Z = Km - Wn**2 * Mm + 1j * Wn * Cm
        X = mp.lu_solve(Z, F0n * fa + (Km + 1j * Wn * Cm) * rr * Xbn)
        top_full = X[2]
        # modes: L = cholesky(M), symmetric eigenproblem of L⁻¹KL⁻ᵀ
        L = mp.cholesky(Mm)
        Li = L**-1
        _, vecs = mp.eigsy(Li * Km * Li.T)
        top_modal = mp.mpc(0)
        for i in range(3):
            phi = Li.T * vecs[:, i]
            Mi_n = (phi.T * Mm * phi)[0]
            Ki_n = (phi.T * Km * phi)[0]
            Ci_n = (phi.T * Cm * phi)[0]
            G = (phi.T * Mm * rr)[0] / Mi_n
            vals = {
                sym8["M"]: Mi_n,
                sym8["K"]: Ki_n,
                sym8["C"]: Ci_n,
                sym8["Omega"]: Wn,
            }
            P = P8.subs({sym8["F0"]: F0n * phi[2], sym8["X_b"]: G * Xbn, sym8["K"]: Ki_n})
            Q = Q8.subs({sym8["X_b"]: G * Xbn, sym8["C"]: Ci_n, sym8["Omega"]: Wn})
            a = sp.N(A8.subs({sym8["P"]: P, sym8["Q"]: Q}).subs(vals), 40)
            b = sp.N(B8.subs({sym8["P"]: P, sym8["Q"]: Q}).subs(vals), 40)
            # A cos θ + B sin θ = Re((A − iB) e^{iθ})
            top_modal += phi[2] * (mp.mpf(str(a)) - 1j * mp.mpf(str(b)))
        err = abs(top_modal - top_full) / abs(top_full)
    board.check(
        "three masses, force at the top and base motion: the modal sum of Step 8's steady "
        "solutions equals the full complex frequency response",
        "F7",
        err < mp.mpf(10) ** -30,
        f"relative difference {mp.nstr(err, 2)} (40 digits)",
    )

    # --- 2. proportional damping ------------------------------------------------------------------
    al, be, wi, z_, wa, wb = sp.symbols("alpha beta omega_i zeta omega_1 omega_2", positive=True)
    Mi_p = sp.Symbol("M_i", positive=True)
    zeta_i = w("rayleigh_ratio", sp.simplify((al * Mi_p + be * Mi_p * wi**2) / (2 * Mi_p * wi)),
               "C = αM + βK gives Cᵢ = φᵢᵀCφᵢ = αMᵢ + βKᵢ = 2ζᵢωᵢMᵢ: the ratio of mode i.",
               "F7")  # fmt: skip
    sol = sp.solve([zeta_i.subs(wi, wa) - z_, zeta_i.subs(wi, wb) - z_], [al, be], dict=True)[0]
    alpha_v = w("rayleigh_alpha", sp.factor(sol[al]), "α for the ratio ζ at ω₁ and ω₂.", "F7")
    beta_v = w("rayleigh_beta", sp.factor(sol[be]), "β for the ratio ζ at ω₁ and ω₂.", "F7")
    board.check(
        "α = 2ζω₁ω₂/(ω₁ + ω₂), β = 2ζ/(ω₁ + ω₂) (Chopra, Dynamics of Structures, Eq. 11.4.9)",
        "F7",
        sp.simplify(alpha_v - 2 * z_ * wa * wb / (wa + wb)) == 0
        and sp.simplify(beta_v - 2 * z_ / (wa + wb)) == 0,
    )

    # --- 3. effective modal masses ----------------------------------------------------------------
    eff = [sp.simplify((p.T * M2 * r)[0] ** 2 / (p.T * M2 * p)[0]) for p in phis]
    board.check(
        "the effective masses MᵢΓᵢ² = (φᵢᵀMr)²/Mᵢ of the chain of two sum to m₁ + m₂ = rᵀMr",
        "F7",
        sp.simplify(sum(eff) - (m1 + m2)) == 0,
        "Σ MᵢΓᵢ² = rᵀM Φ diag(1/Mᵢ) Φᵀ Mr = rᵀMr, since Φ diag(1/Mᵢ) Φᵀ = M⁻¹",
    )
    k, xi = sp.symbols("beta_L xi", positive=True)
    shapes = _mode_shapes()
    fractions = {}
    participation = {}
    sums = {}
    for beam in BEAMS:
        phi = shapes[beam]
        area = w(f"shape_integral_{beam}", sp.simplify(sp.integrate(phi, (xi, 0, 1))),
                 f"The {NAMES[beam]}: ∫₀¹φ dξ, the mode's share of a rigid motion.", "F7")  # fmt: skip
        norm = norm_at_root(beam, phi)  # Step 14's boundary form of ∫φ²dξ
        fractions[beam] = w(
            f"effective_mass_fraction_{beam}",
            area**2 / norm,
            f"The {NAMES[beam]}: the share MᵢΓᵢ²/(ρAL) = I²/N of the beam's mass that the mode "
            "moves when the supports move (base excitation), I = ∫φ dξ and N = ∫φ² dξ.",
            "F7",
        )
        participation[beam] = w(
            f"base_participation_{beam}",
            phi * area / norm,
            f"The {NAMES[beam]}: Γᵢ of the mode referred to the point ξ (qᵢ the displacement "
            "there): Γᵢ = φ(ξ)·I/N.",
            "F7",
        )
        with mp.workdps(30):
            frac = sp.lambdify(k, fractions[beam], "mpmath")
            sums[beam] = [frac(rt) for rt in roots(beam, N_SUM, 30)]
    first = {b: [mp.nstr(v, 4) for v in sv[:3]] for b, sv in sums.items()}
    with mp.workdps(30):
        board.check(
            "cantilever: 61.3 %, 18.8 %, 6.5 % of the mass in modes 1–3; simply supported: "
            "8/π², 0, 8/(9π²) (Chopra, Dynamics of Structures, Ch. 16; the sine series)",
            "F7",
            all(abs(a - b) < 5e-4 for a, b in zip(sums["cantilever"][:3], (0.6131, 0.1883, 0.0647),
                                                  strict=True))
            and abs(sums["simply_supported"][0] - 8 / mp.pi**2) < 1e-25
            and abs(sums["simply_supported"][1]) < 1e-25
            and abs(sums["simply_supported"][2] - 8 / (9 * mp.pi**2)) < 1e-25,
            "; ".join(f"{NAMES[b]} {', '.join(v)}" for b, v in first.items()),
        )  # fmt: skip
        missing = {b: (1 - mp.fsum(sv[: N_SUM // 2]), 1 - mp.fsum(sv)) for b, sv in sums.items()}
        # the sine series: Σ over odd i of 8/(iπ)² is exactly 1, so what 64 modes leave is its tail
        tail = 8 / mp.pi**2 * mp.nsum(lambda j: 1 / (2 * j + 1) ** 2, [N_SUM // 2, mp.inf])
        board.check(
            f"the shares sum to the whole beam: what the first N modes leave falls as 1/N (halved "
            f"from {N_SUM // 2} to {N_SUM} modes); for the simply supported beam it is the tail "
            "of Σ 8/(iπ)² over odd i, whose sum is 1",
            "F7",
            all(1.9 < a / b < 2.1 for a, b in missing.values())
            and abs(missing["simply_supported"][1] - tail) < 1e-25,
            ", ".join(f"{NAMES[bm]}: 1 − Σ = {mp.nstr(a, 3)}, {mp.nstr(b, 3)}"
                      for bm, (a, b) in missing.items()),
        )  # fmt: skip
    w(
        "effective_mass_shares",
        {NAMES[b]: [sp.Float(mp.nstr(v, 4), 4) for v in sv[:4]] for b, sv in sums.items()},
        "The share of each beam's mass moved by its modes 1–4 under base excitation.",
        "F7",
    )

    # --- 4. an impact in modal coordinates --------------------------------------------------------
    e = sp.Symbol("e", nonnegative=True)
    m = sp.Symbol("m", positive=True)
    n = 2
    Ms = sp.symbols(f"M_1:{n + 1}", positive=True)
    Cs = sp.symbols(f"C_1:{n + 1}", nonnegative=True)
    ps = sp.symbols(f"varphi_1:{n + 1}", real=True)  # the shapes' values at the point
    qs = sp.symbols(f"q_1:{n + 1}", real=True)
    vs = sp.symbols(f"qdot_1:{n + 1}", real=True)
    acc = sp.symbols(f"a_1:{n + 1}", real=True)  # each mode's acceleration before the impact
    z, u, s = sp.symbols("z ydot s", real=True)
    P = sp.Symbol("P", real=True)
    xdot = sum(p * v for p, v in zip(ps, vs, strict=True))
    newton = sp.Eq((u - P / m) - sum(p * (v + p * P / Mi_) for p, v, Mi_ in zip(ps, vs, Ms, strict=True)),
                   -e * (u - xdot))  # fmt: skip
    impulse = sp.factor(sp.solve(newton, P)[0])
    m_eff = 1 / sum(p**2 / Mi_ for p, Mi_ in zip(ps, Ms, strict=True))
    mu = m * m_eff / (m + m_eff)
    board.check(
        "P = (1 + e)·μ·ż⁻, μ the reduced mass of m and the effective mass (Σφᵢ(a)²/Mᵢ)⁻¹; each q̇ᵢ "
        "jumps by φᵢ(a)P/Mᵢ",
        "F7",
        sp.simplify(impulse - (1 + e) * mu * (u - xdot)) == 0,
    )
    state = sp.Matrix([*qs, *vs, z, u])

    def jump(X):
        vv = X[n : 2 * n]
        Pv = impulse.subs(dict(zip(vs, vv, strict=True))).subs(u, X[2 * n + 1])
        return sp.Matrix([*X[:n], *(vv[i] + ps[i] * Pv / Ms[i] for i in range(n)), X[2 * n],
                          X[2 * n + 1] - Pv / m])  # fmt: skip

    DR = jump(state).jacobian(state)
    after = jump(state)
    zrate = u - xdot
    f_minus = sp.Matrix([*vs, *acc, zrate, 0])
    v_plus = after[n : 2 * n]
    a_plus = [acc[i] - Cs[i] * (v_plus[i] - vs[i]) / Ms[i] for i in range(n)]
    f_plus = sp.Matrix(
        [
            *v_plus,
            *a_plus,
            after[2 * n + 1] - sum(p * v for p, v in zip(ps, v_plus, strict=True)),
            0,
        ]
    )
    grad = sp.Matrix([[0] * (2 * n) + [s, 0]])
    S = DR + (f_plus - DR * f_minus) * grad / (grad * f_minus)[0]
    S = S.applyfunc(sp.simplify)
    # first-order check as in Step 9: fly with f⁻ to the shifted wall, jump, fly back with f⁺
    eps, dt_ = sp.symbols("epsilon Delta_t", real=True)
    delta = sp.Matrix(sp.symbols(f"d1:{2 * n + 3}", real=True))
    start = state + eps * delta
    sub = dict(zip(state, start, strict=True))
    shift = sp.solve(
        s * (start[2 * n] + f_minus[2 * n].subs(sub, simultaneous=True) * dt_) - s * z,
        dt_,
    )[0]
    arrived = start + f_minus.subs(sub, simultaneous=True) * shift
    back = jump(arrived) - f_plus.subs(sub, simultaneous=True) * shift
    first_order = sp.Matrix([sp.diff(c, eps).subs(eps, 0) for c in back])
    board.check(
        "two modes: S·δ is the first-order change of the state after a perturbed impact",
        "F7",
        all(sp.simplify(c) == 0 for c in (first_order - S * delta)),
    )
    gains = [(1 + e) * mu * p / Mi_ for p, Mi_ in zip(ps, Ms, strict=True)]
    k_m = (1 + e) * mu / m
    expected = {}
    for i in range(n):
        expected[(i, 2 * n)] = gains[i]
        for j in range(n):
            expected[(n + i, n + j)] = int(i == j) - gains[i] * ps[j]
        expected[(n + i, 2 * n)] = gains[i] * (
            sum(p * a for p, a in zip(ps, acc, strict=True)) / zrate - Cs[i] / Ms[i]
        )
        expected[(n + i, 2 * n + 1)] = gains[i]
    for j in range(n):
        expected[(2 * n + 1, n + j)] = k_m * ps[j]
    expected[(2 * n + 1, 2 * n + 1)] = 1 - k_m
    expected[(2 * n, 2 * n)] = -e
    expected[(2 * n + 1, 2 * n)] = -k_m * sum(p * a for p, a in zip(ps, acc, strict=True)) / zrate
    board.check(
        "S in modal coordinates: rows qᵢ, column z: kᵢ; rows q̇ᵢ: δᵢⱼ − kᵢφⱼ, kᵢ(Σφⱼaⱼ/ż − Cᵢ/Mᵢ), "
        "kᵢ; row z: −e; row ẏ: kₘφⱼ, −kₘΣφⱼaⱼ/ż, 1 − kₘ; kᵢ = (1 + e)μφᵢ/Mᵢ, kₘ = (1 + e)μ/m",
        "F7",
        all(
            sp.simplify(S[i, j] - expected.get((i, j), int(i == j) if j < n or i < n else 0)) == 0
            for i in range(2 * n + 2)
            for j in range(2 * n + 2)
        ),
    )
    # the entries that carry the impact's move in time, written as a teacher would: k₁, kₘ and
    # the point's acceleration A = Σφⱼaⱼ named
    k1s, kms, A_s, zs = sp.symbols("k_1 k_m A zdot")
    point_acc = sum(p * a for p, a in zip(ps, acc, strict=True))
    w(
        "modal_saltation_velocity_z",
        S[n, 2 * n],
        "Row q̇₁, column z of the saltation matrix of an impact at a point of a two-mode structure "
        "(state q₁, q₂, q̇₁, q̇₂, z = y − Σφᵢqᵢ, ẏ): a perturbation of z moves the impact in time, "
        "and mode 1's velocity after it by this much per metre; A = Σφⱼaⱼ is the point's "
        "acceleration before the impact, k₁ = (1 + e)μφ₁/M₁ the mode's gain.",
        "F7",
        shown=k1s * (A_s / zs - Cs[0] / Ms[0]),
        names={k1s: gains[0], A_s: point_acc, zs: zrate},
    )
    w("modal_saltation_impact_velocity_z", S[2 * n + 1, 2 * n],
      "Row ẏ, column z, the same for the impact mass (kₘ = (1 + e)μ/m); any number of modes "
      "follows the pattern of the check above.", "F7",
      shown=-kms * A_s / zs, names={kms: k_m, A_s: point_acc, zs: zrate})  # fmt: skip
    # one mode with φ = 1: Step 9's matrix
    M_, C_, am_ = sp.symbols("M C a_minus", real=True)
    one = S.subs({ps[1]: 0}).subs({ps[0]: 1, Ms[0]: M_, Cs[0]: C_, acc[0]: am_})
    keep = [0, 2, 4, 5]
    S1 = one.extract(keep, keep)
    kM = (1 + e) * (m * M_ / (m + M_)) / M_
    km = (1 + e) * (m * M_ / (m + M_)) / m
    wz = u - vs[0]
    step9_S = sp.Matrix([
        [1, 0, kM, 0],
        [0, 1 - kM, kM * (am_ / wz - C_ / M_), kM],
        [0, 0, -e, 0],
        [0, km, -km * am_ / wz, 1 - km],
    ])  # fmt: skip
    board.check("one mode with φ = 1 gives Step 9's saltation matrix (F2)", "F7",
                all(sp.simplify(c) == 0 for c in (S1 - step9_S)))  # fmt: skip

    # --- 5. sticking at a point: the structure carries the impact mass -----------------------------
    # When chatter has accumulated (Step 9) the impact mass rides with the point a: the structure
    # then moves as one with the mass m added at a.  In modal coordinates the mass matrix gains
    # the rank-one term m·φφᵀ, φ = (φᵢ(a)).
    n3 = 3
    M3s = sp.symbols(f"M_1:{n3 + 1}", positive=True)
    p3 = sp.symbols(f"varphi_1:{n3 + 1}", real=True)
    g3 = sp.symbols(f"g_1:{n3 + 1}", real=True)  # each mode's load Qᵢ − Cᵢq̇ᵢ − Kᵢqᵢ
    phi = sp.Matrix(p3)
    Md = sp.diag(*M3s)
    stuck_mass = Md + m * phi * phi.T
    w("stuck_mass_matrix", stuck_mass,
      "Three modes sticking at a: the modal mass matrix diag(Mᵢ) + m·φφᵀ, φ the shapes' values "
      "at a (the impact mass's kinetic energy ½m(Σφᵢq̇ᵢ)² added to the modes').", "F7")  # fmt: skip
    inv_d = sp.diag(*[1 / Mi_ for Mi_ in M3s])
    r = 1 + m * sum(p**2 / Mi_ for p, Mi_ in zip(p3, M3s, strict=True))
    sherman = inv_d - m * (inv_d * phi) * (inv_d * phi).T / r
    board.check(
        "its inverse is Sherman–Morrison's: diag(1/Mᵢ) − m·(φᵢ/Mᵢ)(φⱼ/Mⱼ)/(1 + mΣφₖ²/Mₖ), no "
        "matrix to invert at run time",
        "F7",
        all(sp.simplify(c) == 0 for c in (sherman * stuck_mass - sp.eye(n3))),
    )
    g = sp.Matrix(g3)
    q_acc = sherman * g
    point_acc = sp.simplify((phi.T * q_acc)[0])
    gsum = sum(p * gi / Mi_ for p, gi, Mi_ in zip(p3, g3, M3s, strict=True))
    board.check(
        "the point's acceleration while stuck: ẍₐ = (Σφᵢgᵢ/Mᵢ)/(1 + m/m_eff), gᵢ = Qᵢ − Cᵢq̇ᵢ − "
        "Kᵢqᵢ; each mode then moves by q̈ᵢ = (gᵢ − m·ẍₐ·φᵢ)/Mᵢ, pushed by the mass's inertia at a",
        "F7",
        sp.simplify(point_acc - gsum / r) == 0
        and all(
            sp.simplify(q_acc[i] - (g3[i] - m * point_acc * p3[i]) / M3s[i]) == 0 for i in range(n3)
        ),
    )
    w("stuck_point_acceleration", gsum / r,
      "The acceleration of the point a and of the mass riding on it during sticking; the wall "
      "pushes the mass with the force m·ẍₐ, compressive while s·ẍₐ ≤ 0 on the wall s = ±1, and "
      "the mass is released where s·ẍₐ turns positive (Step 9's rule, with the structure's ẍₐ).",
      "F7")  # fmt: skip
    # one mode with φ = 1: Step 9's sticking phase, one mass M + m under the same load
    M_1, g_1 = sp.symbols("M g", real=True)
    one_mode = (gsum / r).subs({p3[1]: 0, p3[2]: 0}).subs({p3[0]: 1, M3s[0]: M_1, g3[0]: g_1})
    board.check("one mode with φ = 1: ẍ = g/(M + m), Step 9's sticking phase (F2)", "F7",
                sp.simplify(one_mode - g_1 / (M_1 + m)) == 0)  # fmt: skip
    # the stuck structure is linear: its own frequencies, by the matrix determinant lemma
    lam = sp.Symbol("lambda", positive=True)
    om = sp.symbols(f"omega_1:{n3 + 1}", positive=True)
    Kd = sp.diag(*[Mi_ * o**2 for Mi_, o in zip(M3s, om, strict=True)])
    secular = 1 - m * lam * sum(
        p**2 / (Mi_ * (o**2 - lam)) for p, Mi_, o in zip(p3, M3s, om, strict=True)
    )
    det_ratio = (Kd - lam * stuck_mass).det() / (Kd - lam * Md).det()
    board.check(
        "det(K − λ(M + mφφᵀ)) = det(K − λM)·(1 − mλΣφᵢ²/(Mᵢ(ωᵢ² − λ))): the stuck structure's "
        "ω² are the roots of this secular equation",
        "F7",
        sp.simplify(det_ratio - secular) == 0,
    )
    # an example: M (2, 1, 3) kg, ω (10, 25, 60) rad/s, φ(a) (1, −0.7, 0.3), m 0.5 kg
    example = {M3s[0]: 2, M3s[1]: 1, M3s[2]: 3, om[0]: 10, om[1]: 25, om[2]: 60,
               m: sp.Rational(1, 2), p3[0]: 1, p3[1]: sp.Rational(-7, 10),
               p3[2]: sp.Rational(3, 10)}  # fmt: skip
    stuck_roots = sorted(float(r) for r in sp.Poly(
        sp.expand((Kd - lam * stuck_mass).det().subs(example)), lam).nroots())  # fmt: skip
    free_roots = [100.0, 625.0, 3600.0]
    board.check(
        "the added mass lowers every frequency and the stuck ω² interlace the free ones, "
        "λ'₁ < ω₁² < λ'₂ < ω₂² < λ'₃ < ω₃² (an example: M 2, 1, 3 kg, ω 10, 25, 60 rad/s, "
        f"φ(a) 1, −0.7, 0.3, m 0.5 kg: λ' = {', '.join(f'{r:.5g}' for r in stuck_roots)})",
        "F7",
        stuck_roots[0]
        < free_roots[0]
        < stuck_roots[1]
        < free_roots[1]
        < stuck_roots[2]
        < free_roots[2],
    )
    w("stuck_secular_equation", sp.Eq(secular, 0),
      "The natural frequencies λ = ω² of the structure carrying the mass m at a (sticking), "
      "written with the free structure's ωᵢ, Mᵢ and φᵢ(a).", "F7")  # fmt: skip
    one_root = sp.solve(secular.subs({p3[1]: 0, p3[2]: 0}).subs({p3[0]: 1}), lam)
    board.check("one mode with φ = 1: ω² = Mω₁²/(M + m) = K/(M + m), Step 9's stuck primary",
                "F7", len(one_root) == 1
                and sp.simplify(one_root[0] - M3s[0] * om[0] ** 2 / (M3s[0] + m)) == 0)  # fmt: skip

    # --- kernels -----------------------------------------------------------------------------------
    arg_k = Arg(
        k,
        "1",
        "Root βL of the beam's frequency equation (its BETA_L_… constant)",
        3.0,
        12.0,
    )
    arg_xi = Arg(xi, "1", "Point ξ = r/L along the beam (0 < ξ < 1)", 0.2, 0.8)
    for beam in BEAMS:
        board.kernel(
            name=f"mass_share_{beam}",
            args=(arg_k,),
            expr=fractions[beam],
            returns=f"Share MᵢΓᵢ²/(ρAL) of the {NAMES[beam]}'s mass that a mode moves under base "
            "excitation",
            unit="1",
            equation="F7",
            lhs=r"\frac{M_i \Gamma_i^2}{\rho A L}",
            # away from a root the boundary form of ∫φ² cancels: rounding judged against its terms
            magnitude=rounding_scale(fractions[beam]),
            note="beta_L must be a root of the frequency equation.",
        )
        board.kernel(
            name=f"participation_{beam}",
            args=(arg_k, arg_xi),
            expr=participation[beam],
            returns=f"Participation factor Γᵢ of a mode of the {NAMES[beam]} referred to the "
            "point ξ (its base-motion amplitude is Γᵢ·X_b)",
            unit="1",
            equation="F7",
            lhs=r"\Gamma_i",
            magnitude=rounding_scale(participation[beam]),
            note="beta_L must be a root of the frequency equation.",
        )
    return board
