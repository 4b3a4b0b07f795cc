r"""Step 4 — Lindstedt–Poincaré solution of the main-mass Duffing equation (paper Eq. 14–20).

$\ddot x + \omega_0^2 x + \varepsilon x^3 = 0$.  Stretch time, τ = ω t, so the unknown frequency
ω appears in the equation, $\omega^2 x'' + \omega_0^2 x + \varepsilon x^3 = 0$, and expand both
$x = \sum_k \varepsilon^k x_k(\tau)$ and $\omega = \sum_k \varepsilon^k \omega_k$ (ω₀ first).  At
every order $x_k'' + x_k$ = (known harmonics)/ω₀²; a cos τ term on the right would grow without
bound (secular), so its coefficient must vanish — that fixes $\omega_k$.  The remaining harmonics
give $x_k$.

The paper does order 1 (Eq. 16–19) and substitutes ε and ω₀ from Eq. 15 (Eq. 20).  Here any order
n is available: ``lindstedt_poincare(n)``, normalised at a turning point, x(0) = α, ẋ(0) = 0 (any
initial state reduces to this by a time shift; α from the exact energy, see ``amplitude``).  The
result is checked by substitution (the residual starts at εⁿ⁺¹) and against the series of the exact
frequency, π√(ω₀² + εα²)/(2K(m)) with m = εα²/(2(ω₀² + εα²)), a complete elliptic integral.
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from .board import Arg, Board

omega0, eps, alpha = sp.symbols("omega0 epsilon alpha", positive=True)
tau = sp.Symbol("tau", real=True)
KERNEL_ORDERS = (1, 2, 3)

Harmonics = dict[int, sp.Expr]  # {j: c_j} stands for Σ c_j cos(jτ)


def _sup(n: int) -> str:
    """``n`` in Unicode superscript digits (ε³ in plain text)."""
    return str(n).translate(str.maketrans("0123456789", "⁰¹²³⁴⁵⁶⁷⁸⁹"))


def _mul(p: Harmonics, q: Harmonics) -> Harmonics:
    out: Harmonics = {}
    for i, ci in p.items():
        for j, cj in q.items():
            for h in (i + j, abs(i - j)):
                out[h] = out.get(h, 0) + ci * cj / 2
    return out


def _add(*terms: Harmonics) -> Harmonics:
    out: Harmonics = {}
    for p in terms:
        for j, c in p.items():
            out[j] = out.get(j, 0) + c
    return out


def _scale(p: Harmonics, s: sp.Expr) -> Harmonics:
    return {j: s * c for j, c in p.items()}


def _dd(p: Harmonics) -> Harmonics:
    """Second τ-derivative."""
    return {j: -(j**2) * c for j, c in p.items()}


@cache
def lindstedt_poincare(n: int) -> tuple[tuple[sp.Expr, ...], tuple[Harmonics, ...]]:
    """Frequency terms (ω₀, ω₁, …, ω_n) and solution terms (x₀, …, x_n) as harmonic dicts."""
    x: list[Harmonics] = [{1: alpha}]
    w: list[sp.Expr] = [omega0]
    cubes: dict[int, Harmonics] = {}

    def cube(k: int) -> Harmonics:  # [x³]_k
        if k not in cubes:
            cubes[k] = _add(
                *(
                    _mul(_mul(x[i], x[j]), x[k - i - j])
                    for i in range(k + 1)
                    for j in range(k + 1 - i)
                )
            )
        return cubes[k]

    def w2(p: int, wk) -> sp.Expr:  # [ω²]_p with ω_p → wk
        ws = [*w, wk]
        return sum(ws[i] * ws[p - i] for i in range(p + 1))

    wk = sp.Symbol("w_k")
    for k in range(1, n + 1):
        rhs = _add(
            *(_scale(_dd(x[k - p]), -w2(p, wk)) for p in range(1, k + 1)),
            _scale(cube(k - 1), -1),
        )
        secular = sp.expand(rhs.get(1, 0))
        wk_value = sp.solve(secular, wk)[0]
        w.append(sp.factor(wk_value))
        xk: Harmonics = {}
        for j, c in rhs.items():
            c = sp.factor(sp.expand(c.subs(wk, wk_value)))
            if j != 1 and c != 0:
                xk[j] = c / (omega0**2 * (1 - j**2))
        xk[1] = -sum(xk.values())  # x_k(0) = 0; x_k'(0) = 0 holds for cosines
        x.append({j: sp.factor(c) for j, c in xk.items()})
    return tuple(w), tuple(x)


def frequency(n: int) -> sp.Expr:
    """ω to order εⁿ."""
    w, _ = lindstedt_poincare(n)
    return sum(eps**k * wk for k, wk in enumerate(w))


def solution(n: int, t: sp.Symbol) -> sp.Expr:
    """x(t) to order εⁿ (turning point at t = 0)."""
    _, xs = lindstedt_poincare(n)
    om = frequency(n)
    return sum(eps**k * c * sp.cos(j * om * t) for k, xk in enumerate(xs) for j, c in xk.items())


def residual_orders(n: int) -> tuple[list[sp.Expr], sp.Expr]:
    """Coefficients of ε⁰…εⁿ of the substituted equation (all must be 0) and that of εⁿ⁺¹.

    Independent of the harmonic algebra above: every cos(jτ) becomes the Chebyshev polynomial
    T_j(c) in c = cos τ, so the residual is a polynomial in (c, ε) expanded exactly.
    """
    w, xs = lindstedt_poincare(n)
    c = sp.Symbol("c")
    om = sum(eps**k * wk for k, wk in enumerate(w))
    x = sum(
        eps**k * coeff * sp.chebyshevt(j, c) for k, xk in enumerate(xs) for j, coeff in xk.items()
    )
    # d²/dτ² of T_j(cos τ) = −j² T_j(cos τ)
    xdd = sum(
        eps**k * (-(j**2)) * coeff * sp.chebyshevt(j, c)
        for k, xk in enumerate(xs)
        for j, coeff in xk.items()
    )
    res = sp.Poly(sp.expand(om**2 * xdd + omega0**2 * x + eps * x**3), eps)
    coeffs = [sp.simplify(res.coeff_monomial(eps**k)) for k in range(n + 2)]
    return coeffs[: n + 1], coeffs[n + 1]


def exact_frequency() -> sp.Expr:
    """Exact Duffing frequency for the turning-point amplitude α (hardening, ε > 0)."""
    mpar = eps * alpha**2 / (2 * (omega0**2 + eps * alpha**2))
    return sp.pi * sp.sqrt(omega0**2 + eps * alpha**2) / (2 * sp.elliptic_k(mpar))


def derive() -> Board:
    board = Board("lindstedt", "Lindstedt–Poincaré solution of the Duffing equation", "14–20")
    wr = board.write
    t = sp.Symbol("t", real=True)
    K, M, a, b = sp.symbols("K M a b", positive=True)
    om, om1 = sp.symbols("omega omega_1", positive=True)

    wr(
        "duffing",
        sp.Eq(
            sp.Function("x")(t).diff(t, 2)
            + omega0**2 * sp.Function("x")(t)
            + eps * sp.Function("x")(t) ** 3,
            0,
        ),
        "Undamped main-mass equation during contact (from step 3).",
        "14",
    )
    wr(
        "stretched",
        sp.Eq(
            om**2 * sp.Function("x")(tau).diff(tau, 2)
            + omega0**2 * sp.Function("x")(tau)
            + eps * sp.Function("x")(tau) ** 3,
            0,
        ),
        "With τ = ωt.",
        "16",
    )
    # Eq. 16 writes ω₀² = ω² − 2εω₀ω₁ − ε²ω₁²; with ω₀ = ω − εω₁ that is exactly (ω − εω₁)².
    printed16 = om**2 - 2 * eps * (om - eps * om1) * om1 - eps**2 * om1**2
    board.check(
        "expansion of ω₀² in Eq. 16", "16", sp.expand(printed16 - (om - eps * om1) ** 2) == 0
    )

    w, xs = lindstedt_poincare(3)
    for k in range(1, 4):
        wr(
            f"omega_{k}",
            w[k],
            rf"Secular condition at order $\varepsilon^{k}$.",
            "19" if k == 1 else None,
        )
        wr(
            f"x_{k}",
            sum(c * sp.cos(j * tau) for j, c in xs[k].items()),
            rf"Order-$\varepsilon^{k}$ correction of the solution (τ = ωt).",
            "18" if k == 1 else None,
        )
    board.check("ω₁ = 3α²/(8ω₀)", "19", sp.simplify(w[1] - 3 * alpha**2 / (8 * omega0)) == 0)

    for n in KERNEL_ORDERS:
        zero, first = residual_orders(n)
        board.check(
            f"order {n}: residual is O(ε{_sup(n + 1)})",
            "16–18",
            all(cf == 0 for cf in zero) and first != 0,
            f"ε{_sup(n + 1)} coefficient ≠ 0, lower ones vanish exactly",
        )
    nmax = max(KERNEL_ORDERS)
    exact = sp.series(exact_frequency(), eps, 0, nmax + 1).removeO()
    board.check(
        f"frequency series = exact elliptic-integral series to ε{_sup(nmax)}",
        "19–20",
        sp.simplify(sp.expand(exact - frequency(nmax))) == 0,
    )
    wr("frequency_series", frequency(nmax), rf"ω to order $\varepsilon^{nmax}$.", "19")

    # --- Eq. 17 amplitude and phase ---------------------------------------------------------------
    X0, Xd0 = sp.symbols("x0 xdot0", real=True)
    beta = sp.atan(-Xd0 / (om * X0))
    printed_alpha = X0 / sp.cos(beta)
    derived_alpha = sp.sqrt(X0**2 + (Xd0 / om) ** 2)
    board.erratum(
        key="eq17_amplitude_at_rest",
        equation="17",
        what="amplitude α = X₀/cos β",
        printed=printed_alpha,
        derived=derived_alpha,
        consequence="0/0 when the main mass starts at X₀ = 0, as in Table 2; "
        "α = √(X₀² + Ẋ₀²/ω²) is the same elsewhere (for X₀ > 0)",
        point={X0: 0, Xd0: sp.Rational(1, 200), om: 100},
    )
    board.check(
        "Eq. 17 α equals √(X₀² + (Ẋ₀/ω)²) for X₀ > 0",
        "17",
        sp.simplify((printed_alpha - derived_alpha).subs(X0, sp.Symbol("p", positive=True))) == 0,
        erratum=True,
    )
    energy = wr(
        "energy",
        Xd0**2 / 2 + omega0**2 * X0**2 / 2 + eps * X0**4 / 4,
        "Conserved energy of Eq. 14 per unit mass.",
        "14",
    )
    A2 = sp.Symbol("A2", positive=True)
    roots = sp.solve(omega0**2 * A2 / 2 + eps * A2**2 / 4 - energy, A2)
    a2 = next(r for r in roots if sp.N(r.subs({X0: 1, Xd0: 1, omega0: 1, eps: 1})) > 0)
    stable = 4 * energy / (omega0**2 + sp.sqrt(omega0**4 + 4 * eps * energy))
    board.check(
        "turning-point amplitude from energy", "14", sp.simplify(sp.radsimp(a2 - stable)) == 0
    )
    amplitude = wr(
        "amplitude",
        sp.sqrt(stable),
        "Exact turning-point amplitude α for any initial state (x(0), ẋ(0)).",
        "17",
    )

    # --- Eq. 20 -----------------------------------------------------------------------------------
    R = sp.Symbol("R")
    eps_15 = a / M * (1 - R) ** 3
    one_minus_R = sp.solve(sp.Eq(omega0**2, K / M + b / M * (1 - R)), R)[0]
    eq20 = wr(
        "eq20",
        (omega0 + eps * w[1]).subs(eps, eps_15).subs(R, one_minus_R),
        "First-order ω with ε and 1 − B/A from Eq. 15 expressed through ω₀.",
        "20",
    )
    printed20 = (
        omega0 + sp.Rational(3, 8) * a * alpha**2 / (M * b**3 * omega0) * (M * omega0**2 - K) ** 3
    )
    board.check("Eq. 20", "20", sp.simplify(eq20 - printed20) == 0)

    # --- kernels ------------------------------------------------------------------------------------
    aw0 = Arg(omega0, "rad/s", "Linear angular frequency ω₀", 1.0, 1e3, log=True)
    aeps = Arg(eps, "1/(m^2 s^2)", "Cubic coefficient ε", 1e-2, 1e6, log=True)
    aal = Arg(alpha, "m", "Turning-point amplitude α", 1e-5, 1e-2, log=True)
    at = Arg(t, "s", "Time since the turning point", 0.0, 0.1)
    for n in KERNEL_ORDERS:
        board.kernel(
            name=f"duffing_frequency_order{n}",
            args=(aw0, aeps, aal),
            expr=frequency(n),
            returns=f"Lindstedt–Poincaré angular frequency to order ε^{n}",
            unit="rad/s",
            equation="19" if n == 1 else "19 (higher order)",
            lhs=r"\omega",
        )
        board.kernel(
            name=f"duffing_response_order{n}",
            args=(at, aw0, aeps, aal),
            expr=solution(n, t),
            returns=f"Lindstedt–Poincaré displacement x(t) to order ε^{n}, x(0) = α",
            unit="m",
            magnitude=alpha,
            equation="17–18" if n == 1 else "17–18 (higher order)",
            lhs="x(t)",
        )
    board.kernel(
        name="duffing_amplitude",
        args=(
            Arg(X0, "m", "Initial displacement", -1e-2, 1e-2),
            Arg(Xd0, "m/s", "Initial velocity", -1.0, 1.0),
            aw0,
            aeps,
        ),
        expr=amplitude,
        returns="Exact turning-point amplitude α from the energy",
        unit="m",
        equation="17",
        lhs=r"\alpha",
        note="Replaces α = X₀/cos β of Eq. 17, which is 0/0 at X₀ = 0.",
    )
    board.kernel(
        name="frequency_eq20",
        args=(
            Arg(K, "N/m", "Main stiffness K", 10.0, 1e6, log=True),
            Arg(M, "kg", "Main mass M", 0.05, 50.0, log=True),
            Arg(a, "N/m^3", "Cubic coefficient a", 1e2, 1e9, log=True),
            Arg(b, "N/m", "Linear coefficient b", 1.0, 1e5, log=True),
            aw0,
            aal,
        ),
        expr=printed20,
        returns="First-order frequency ω in the paper's variables",
        unit="rad/s",
        equation="20",
        lhs=r"\omega",
    )
    return board
