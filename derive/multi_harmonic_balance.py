r"""Step 17 — the balance in H harmonics: the paper's one-term balance as the first of a scheme.

Beyond the paper.  Step 3 kept the cos ωt part of each residual (Eq. 11–12).  The tools engineers
use for nonlinear forced responses keep H harmonics and evaluate the contact force by the
alternating frequency–time scheme (AFT): the motion's coefficients → samples in time → the
force at each sample → its coefficients.  On the board:

1. The trial motion with H harmonics of θ = ωt, and the Galerkin projection of the linear terms
   M ẍ + C ẋ + K x: on harmonic k a 2 × 2 block, K − (kω)²M on its diagonal and ±kωC off it, the
   harmonics uncoupled.  With H = 1, C = c₁ = 0 and the cubic contact of Eq. 10 the projected
   residuals are Eq. 12 as printed: the paper's balance is the first member of the scheme.
2. AFT's samples: a force polynomial of degree p in the motion holds harmonics up to pH, and N
   samples fold harmonic j onto j mod N.  The projection is exact from N = (p + 1)H + 1 samples
   on, and N = (p + 1)H folds the top harmonic onto −H: checked for p = 1, 2, 3 and H = 1, 2, 3
   with every coefficient a symbol.
3. A contact with a clearance is not a polynomial: no N makes AFT exact, and the one-term
   balance needs the integral over the contact arcs.  For the linear contact k₁δ with walls at
   ±d/2 it is the describing function of a dead zone (Gelb and Vander Velde's table), derived
   here and emitted as a kernel with its derivatives, the H = 1 member against which an
   importer checks their own AFT.
4. Why the series converges slowly with a contact.  At an onset the penetration grows linearly,
   δ ≈ v₀s, so the force starts as $s_+^\nu$: ν = 1 for the linear and cubic laws, 3/2 for
   Hertz and Hunt–Crossley, 0 (a step) with a dashpot c₁δ̇.  The Laplace integral of
   $s^\nu e^{-ps}$ gives $\Gamma(\nu + 1)/p^{\nu+1}$: the force's harmonics fall as
   $k^{-(\nu+1)}$, the motion's as $k^{-(\nu+3)}$, and the motion's series truncated after H
   harmonics misses $O(H^{-(\nu+2)})$ — an algebraic rate, where a smooth force (Duffing's, no
   clearance) gives a spectral one.
"""

from __future__ import annotations

import sympy as sp

from .board import Arg, Board

#: The (degree p, harmonics H) pairs on which the aliasing rule is checked, every coefficient a
#: symbol.
ALIASING_CASES = tuple((p, H) for p in (1, 2, 3) for H in (1, 2, 3))


def laurent_power(coefficients: dict[int, sp.Expr], p: int) -> dict[int, sp.Expr]:
    """The coefficients of the p-th power of Σ cⱼ ζʲ by harmonic: a trigonometric polynomial
    raised to a power, written in ζ = exp(iθ) (harmonic j ↔ ζʲ)."""
    out = {0: sp.Integer(1)}
    for _ in range(p):
        step: dict[int, sp.Expr] = {}
        for i, a in out.items():
            for j, b in coefficients.items():
                step[i + j] = step.get(i + j, 0) + a * b
        out = step
    return {k: sp.expand(v) for k, v in out.items()}


def sampled_projection(power: dict[int, sp.Expr], n: int, H: int) -> dict[int, sp.Expr]:
    """What N samples give for harmonics −H … H: the discrete transform of samples at θ = 2πm/N
    sums every harmonic congruent to j mod N onto j."""
    return {j: sp.expand(sum(v for k, v in power.items() if (k - j) % n == 0))
            for j in range(-H, H + 1)}  # fmt: skip


def derive() -> Board:
    board = Board("multi_harmonic_balance", "The balance in H harmonics", "F9–F12")
    w = board.write
    th = sp.Symbol("theta", real=True)
    t = sp.Symbol("t", real=True)
    k = sp.Symbol("k", integer=True, positive=True)
    M, K, C, m, a, b, c1, omega = sp.symbols("M K C m a b c1 omega", positive=True)
    ak, bk = sp.symbols("a_k b_k", real=True)

    # --- the trial motion and the linear terms, harmonic by harmonic ---------------------------
    xk = ak * sp.cos(k * omega * t) + bk * sp.sin(k * omega * t)
    linear = M * xk.diff(t, 2) + C * xk.diff(t) + K * xk

    def project(expr: sp.Expr, basis: sp.Expr) -> sp.Expr:
        # (1/π)∫ expr·basis dθ over one period, with θ = ωt
        integrand = sp.expand(expr.subs(t, th / omega) * basis.subs(t, th / omega))
        return sp.simplify(sp.integrate(integrand, (th, 0, 2 * sp.pi)) / sp.pi)

    block = w(
        "harmonic_block",
        sp.Matrix(
            [
                [project(linear, sp.cos(k * omega * t)).diff(v) for v in (ak, bk)],
                [project(linear, sp.sin(k * omega * t)).diff(v) for v in (ak, bk)],
            ]
        ),
        "Harmonic k of M ẍ + C ẋ + K x projected on cos kθ and sin kθ, acting on (aₖ, bₖ): "
        "each harmonic alone, the dynamic stiffness on the diagonal and the damping off it.",
        "F9",
    )
    board.check(
        "the linear terms' block of harmonic k",
        "F9",
        sp.simplify(
            block
            - sp.Matrix(
                [
                    [K - (k * omega) ** 2 * M, k * omega * C],
                    [-k * omega * C, K - (k * omega) ** 2 * M],
                ]
            )
        )
        == sp.zeros(2, 2),
    )
    j = sp.Symbol("j", integer=True, positive=True)
    cross = w(
        "harmonics_orthogonal",
        project(sp.cos(j * omega * t), sp.cos(k * omega * t)).subs(j, k + 1),
        "Two different harmonics (here k and k + 1) project to zero on each other: the linear "
        "terms couple no two harmonics; only the contact force does.",
        "F9",
    )
    board.check("different harmonics are orthogonal", "F9", cross == 0)

    # --- H = 1 with the cubic contact of Eq. 10: the paper's Eq. 12 ------------------------------
    A, B = sp.symbols("A B", real=True)
    x1, y1 = A * sp.cos(omega * t), B * sp.cos(omega * t)
    z1 = y1 - x1
    force = a * z1**3 + b * z1 + c1 * z1.diff(t)
    undamped = {C: 0, c1: 0}
    main = (M * x1.diff(t, 2) + C * x1.diff(t) + K * x1 - force).subs(undamped)
    impact = (m * y1.diff(t, 2) + force).subs(undamped)
    balance = (
        w(
            "one_term_balance_main",
            sp.expand(project(main, sp.cos(omega * t))),
            "H = 1, C = c₁ = 0: the main mass's residual of Eq. 10 projected on cos ωt.",
            "12",
        ),
        w(
            "one_term_balance_impact",
            sp.expand(project(impact, sp.cos(omega * t))),
            "The impact mass's residual, projected the same way.",
            "12",
        ),
    )
    printed12 = (
        -M * A * omega**2 + K * A + sp.Rational(3, 4) * a * (A - B) ** 3 + b * (A - B),
        -m * B * omega**2 - sp.Rational(3, 4) * a * (A - B) ** 3 - b * (A - B),
    )
    board.check(
        "H = 1 of the scheme is the paper's Eq. 12",
        "12",
        all(sp.expand(balance[i] - printed12[i]) == 0 for i in range(2)),
    )

    # --- AFT: how many samples a polynomial force needs -----------------------------------------
    def aliasing(p: int, H: int, n: int) -> bool:
        # True when N = n samples give every harmonic −H … H of z^p exactly
        c = {q: sp.Symbol(f"c_{q}") for q in range(-H, H + 1)}
        power = laurent_power(c, p)
        sampled = sampled_projection(power, n, H)
        return all(sp.expand(sampled[q] - power.get(q, 0)) == 0 for q in range(-H, H + 1))

    p_, H_ = sp.symbols("p H", integer=True, positive=True)
    rule = w(
        "fewest_samples",
        (p_ + 1) * H_ + 1,
        "The fewest samples N with which AFT projects a force of degree p in a motion of H "
        "harmonics exactly: harmonics up to pH, folded by N onto j mod N, must miss −H … H.",
        "F10",
    )
    exact = [aliasing(p, H, int(rule.subs({p_: p, H_: H}))) for p, H in ALIASING_CASES]
    folded = [not aliasing(p, H, int(rule.subs({p_: p, H_: H})) - 1) for p, H in ALIASING_CASES]
    board.check(
        "N = (p + 1)H + 1 samples are exact, one fewer folds (p, H ≤ 3)",
        "F10",
        all(exact) and all(folded),
        f"{len(ALIASING_CASES)} cases",
    )

    # --- a clearance: the describing function of the linear contact -----------------------------
    k1, gap, amp = sp.symbols("k1 gap A", positive=True)
    g = gap / 2
    arc = sp.acos(g / amp)
    first = w(
        "clearance_first_harmonic",
        sp.simplify(
            2 * sp.integrate(k1 * (amp * sp.cos(th) - g) * sp.cos(th), (th, -arc, arc)) / sp.pi
        ),
        "The cos θ part of the linear contact's force k₁δ for the relative motion z = A cos θ "
        "between walls at ±d/2 (A > d/2): (1/π)∫ f(A cos θ) cos θ dθ, two contact arcs of "
        "half-width arccos(d/2A).",
        "F11",
    )
    textbook = (
        k1 * amp * (1 - 2 / sp.pi * (sp.asin(g / amp) + g / amp * sp.sqrt(1 - (g / amp) ** 2)))
    )
    board.check(
        "the dead zone's describing function (Gelb and Vander Velde)",
        "F11",
        sp.simplify(sp.expand(first - textbook).rewrite(sp.acos)) == 0,
    )
    limits = (sp.limit(first / (k1 * amp), amp, sp.oo), sp.limit(first, amp, g, "+"))
    board.check(
        "far past the walls the spring k₁ itself, at the walls nothing",
        "F11",
        limits == (1, 0),
        f"F₁/(k₁A) → {limits[0]} as A → ∞, F₁ → {limits[1]} as A → d/2",
    )
    a_k1 = Arg(k1, "N/m", "Stiffness k₁ of the linear contact", 1.0, 1e9, log=True)
    a_gap = Arg(gap, "m", "Total clearance d (walls at ±d/2)", 1e-5, 0.1, log=True)
    a_amp = Arg(amp, "m", "Amplitude A of the relative motion z = A cos θ", 1e-5, 1.0, log=True)
    value = board.kernel(
        name="clearance_first_harmonic",
        args=(a_k1, a_gap, a_amp),
        expr=first,
        returns="Cos θ coefficient of the linear contact's force for z = A cos θ (H = 1 of AFT)",
        unit="N",
        equation="F11",
        lhs="F_1",
        constraints=(sp.StrictGreaterThan(amp, g),),
        # the two terms are each of the size k₁A and cancel as A → d/2
        magnitude=k1 * amp,
    )
    # the derivatives written without the 1/√(1 − r²) terms that cancel at the walls (r = d/2A)
    r = g / amp
    slopes = {"A": 2 * k1 / sp.pi * (sp.acos(r) + r * sp.sqrt(1 - r**2)),
              "gap": -2 * k1 / sp.pi * sp.sqrt(1 - r**2)}  # fmt: skip
    w(
        "clearance_slopes",
        sp.Matrix([slopes["A"], slopes["gap"]]),
        "∂F₁/∂A and ∂F₁/∂d, the terms in 1/√(1 − (d/2A)²) cancelled: the H = 1 Jacobian.",
        "F11",
    )
    board.check(
        "the slopes equal the derivatives of F₁",
        "F11",
        all(
            sp.simplify(sp.expand(sp.diff(first, v) - slopes[n]).rewrite(sp.acos)) == 0
            for n, v in (("A", amp), ("gap", gap))
        ),
    )
    board.bundle(
        "clearance_first_harmonic_and_derivatives",
        [value, *board.derivatives(value, ("k1", "gap", "A"), given=slopes)],
        "the force's cos θ coefficient and its derivatives in k₁, d and A",
    )

    # --- the onset's kink and the rate of convergence in H -------------------------------------
    s, p, nu = sp.symbols("s p nu", positive=True)
    laplace = w(
        "onset_transform",
        sp.integrate(s**nu * sp.exp(-p * s), (s, 0, sp.oo)),
        "A force starting as s₊ to the power ν at an onset (s the time after it): its transform, whose "
        "value at p = ikω gives harmonic k's part from the onset.",
        "F12",
    )
    board.check(
        "the transform is Γ(ν + 1) over p to the power ν + 1",
        "F12",
        sp.simplify(laplace - sp.gamma(nu + 1) / p ** (nu + 1)) == 0,
    )
    decay = w(
        "force_harmonic_decay",
        sp.simplify(sp.log(laplace.subs(p, k * omega)).diff(k) * k),
        "The slope of log Fₖ (its modulus) against log k, p's modulus kω (i to a real power has "
        "modulus 1): the force's "
        "harmonics fall as k to the power −(ν + 1).",
        "F12",
    )
    board.check(
        "the force's harmonics fall as k to the power −(ν + 1)",
        "F12",
        sp.simplify(decay + nu + 1) == 0,
    )
    q = sp.Symbol("q", positive=True)
    tail = w(
        "truncation_tail",
        sp.powsimp(sp.integrate(q ** (-(nu + 3)), (q, H_, sp.oo), conds="none")),
        "The motion's harmonics fall as k to the power −(ν + 3) (the force over the dynamic stiffness, "
        "k²ω²M for large k): the part after harmonic H, bounded by the integral of the tail.",
        "F12",
    )
    board.check(
        "the truncated tail is H to the power −(ν + 2), over ν + 2",
        "F12",
        sp.simplify(tail - H_ ** (-(nu + 2)) / (nu + 2)) == 0,
    )
    onsets = {"linear k₁δ or cubic aδ³ + bδ": 1, "Hertz or Hunt–Crossley k δ¹·⁵": sp.Rational(3, 2),
              "any dashpot c₁δ̇ (a step)": 0}  # fmt: skip
    w(
        "truncation_orders",
        {law: [str(v), str(v + 2)] for law, v in onsets.items()},
        "ν at an onset of penetration speed v₀ ≠ 0 and the order ν + 2 of the truncation error "
        "in H it gives, by contact law.",
        "F12",
    )
    return board
