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

from .board import Arg, Board, rounding_scale

#: The compliant laws as a sentence names them.
NAMES = {"linear": "linear", "cubic": "cubic", "hertz": "Hertz", "hunt_crossley": "Hunt–Crossley"}

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

    # --- the force at a time sample: each compliant law and its two slopes -----------------------
    # AFT evaluates the contact where it is known, in time: at each sample the penetration
    # δ = s·z − d/2 on the wall s = ±1 and its rate δ̇ = s·ż, the law's force F(δ, δ̇) while
    # δ > 0, and for the Jacobian ∂F/∂δ and ∂F/∂δ̇ (the chain rule through z = y − x does the rest:
    # the force on m is −s·F, on M its opposite).
    delta, ddelta = sp.symbols("delta ddelta", real=True)
    la, lb, khz, chi = sp.symbols("a b k_hz chi", positive=True)
    a_delta = Arg(delta, "m", "Penetration δ = s·z − d/2 into the wall s = ±1 (δ > 0)", 1e-8,
                  1e-2, log=True)  # fmt: skip
    a_ddelta = Arg(ddelta, "m/s", "Rate of penetration δ̇ = s·ż", -3.0, 3.0)
    a_c1 = Arg(c1, "N s/m", "Contact damping c₁", 0.0, 50.0)
    laws = {
        "linear": (k1 * delta + c1 * ddelta, (Arg(k1, "N/m", "Stiffness k₁ of the linear contact",
                                                  1.0, 1e9, log=True), a_c1), "35"),
        "cubic": (la * delta**3 + lb * delta + c1 * ddelta,
                  (Arg(la, "N/m^3", "Cubic stiffness a", 1e3, 1e16, log=True),
                   Arg(lb, "N/m", "Linear stiffness b", 1.0, 1e9, log=True), a_c1), "8"),
        "hertz": (khz * delta ** sp.Rational(3, 2) + c1 * ddelta,
                  (Arg(khz, "N/m^1.5", "Hertz contact stiffness K_Hz", 10.0, 1e10, log=True),
                   a_c1), "9"),
        "hunt_crossley": (khz * delta ** sp.Rational(3, 2) * (1 + chi * ddelta),
                          (Arg(khz, "N/m^1.5", "Hertz contact stiffness K_Hz", 10.0, 1e10,
                               log=True),
                           Arg(chi, "s/m", "Hunt–Crossley damping χ", 1e-4, 10.0, log=True)),
                          "F4"),
    }  # fmt: skip
    board.check(
        "Hunt–Crossley's law with χ = 0 is Hertz's with c₁ = 0",
        "F4",
        sp.simplify(laws["hunt_crossley"][0].subs(chi, 0) - laws["hertz"][0].subs(c1, 0)) == 0,
    )
    forces = {}
    for law, (expr, params, eq) in laws.items():
        value = board.kernel(
            name=f"force_{law}",
            args=(a_delta, a_ddelta, *params),
            expr=expr,
            returns=f"Force of the {NAMES[law]} contact at penetration δ and "
            "rate δ̇ (δ > 0: in contact), what AFT evaluates at each time sample",
            unit="N",
            equation=eq,
            lhs="F",
            constraints=(sp.StrictGreaterThan(delta, 0),),
            magnitude=rounding_scale(expr),
        )
        forces[law] = board.bundle(
            f"force_{law}_and_derivatives",
            [value, *board.derivatives(value, ("delta", "ddelta"))],
            "the force with its slopes ∂F/∂δ and ∂F/∂δ̇, AFT's Jacobian at a sample",
        )
        board.balance(
            name=f"aft_residual_{law}",
            law=NAMES[law],
            force=forces[law],
            params=params,
            equation="F9–F10",
        )
    # the force at a sample on (M, m) and its slopes in (x, y) and (ẋ, ẏ): the chain rule through
    # δ = s(y − x) − d/2 and δ̇ = s(ẏ − ẋ), with s² = 1 on either wall
    x_, y_, xd_, yd_ = sp.symbols("x y xdot ydot", real=True)
    s_, h_ = sp.symbols("s h", real=True)
    law = sp.Function("F")
    d_, dd_ = sp.symbols("delta ddelta", real=True)
    at = {d_: s_ * (y_ - x_) - h_, dd_: s_ * (yd_ - xd_)}
    Fs = law(d_, dd_)
    on_pair = sp.Matrix([s_ * Fs, -s_ * Fs]).subs(at)
    Fd, Fdd = sp.symbols("F_delta F_ddelta", real=True)
    slope_of = {sp.Derivative(Fs, d_): Fd, sp.Derivative(Fs, dd_): Fdd}
    plain = w(
        "aft_sample_slopes",
        sp.Matrix.hstack(on_pair.jacobian([x_, y_]), on_pair.jacobian([xd_, yd_]))
        .subs(s_**2, 1)
        .subs({v: k for k, v in at.items()})
        .applyfunc(lambda e: e.doit().xreplace(slope_of)),
        "At a sample in contact the force on (M, m) is (s·F, −s·F), δ = s(y − x) − d/2 and "
        "δ̇ = s(ẏ − ẋ): its slopes in (x, y), then in (ẋ, ẏ), s² = 1. These are the blocks the "
        "emitted residual subtracts from L(ω), P·diag(∂f/∂q)·E + ω·P·diag(∂f/∂q̇)·E_θ (Eq. F10).",
        "F10",
    )
    board.check(
        "the force's slopes at a sample are (−F_δ, F_δ; F_δ, −F_δ) on either wall",
        "F10",
        plain == sp.Matrix([[-Fd, Fd, -Fdd, Fdd], [Fd, -Fd, Fdd, -Fdd]]),
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
    # ν read off the laws' own forces at an onset, δ = v₀s and δ̇ = v₀: the exponent of the
    # leading power of s, s·F_s/F as s → 0⁺
    v0 = sp.Symbol("v_0", positive=True)

    def onset(expr: sp.Expr, damped: bool) -> sp.Expr:
        f = expr.subs({delta: v0 * s, ddelta: v0}).subs({} if damped else {c1: 0})
        return sp.limit(sp.simplify(s * sp.diff(f, s) / f), s, 0, "+")

    read = [onset(laws[n][0], False) for n in ("linear", "cubic", "hertz", "hunt_crossley")]
    read += [onset(laws[n][0], True) for n in ("linear", "cubic", "hertz")]
    board.check(
        "ν of each law read off its force at an onset",
        "F12",
        read == [1, 1, sp.Rational(3, 2), sp.Rational(3, 2), 0, 0, 0]
        and list(onsets.values()) == [1, sp.Rational(3, 2), 0],
        "linear, cubic 1; Hertz, Hunt–Crossley 3/2; with c₁ > 0 every law 0",
    )
    w(
        "truncation_orders",
        {law: [str(v), str(v + 2)] for law, v in onsets.items()},
        "ν at an onset of penetration speed v₀ ≠ 0 and the order ν + 2 of the truncation error "
        "in H it gives, by contact law.",
        "F12",
    )
    return board
