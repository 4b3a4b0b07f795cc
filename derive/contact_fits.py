r"""Step 2 — least-squares fits of the Hertz force by a cubic and by a line (paper Eq. 8–9, Fig. 2).

The Hertz force $K_{Hz}\,\delta^{3/2}$ on $[0, \delta_{\max}]$ is replaced by
$a\delta^3 + b\delta$ (Eq. 9) and by $k_1\delta$.  Two least-squares procedures are derived and
compared with the paper's a = 0.1553 N/cm³, b = 0.8360 N/cm and $k_1$ = 122.7 N/m
($K_{Hz}$ = 1000 N/m<sup>1.5</sup>, $\delta_{\max}$ = 2 cm):

* the *continuous* fit minimises
  $\int_0^{\delta_{\max}} (K_{Hz}\delta^{3/2} - a\delta^3 - b\delta)^2\,d\delta$ (closed form);
* the *discrete* fit minimises the sum of squares over n uniform samples
  $\delta_i = i\,\delta_{\max}/(n - 1)$, $i = 0 \dots n - 1$ — what MATLAB's curve-fitting
  toolbox does with sampled data.

Both scale exactly: $a = \hat a(n)\,K_{Hz}/\delta_{\max}^{3/2}$,
$b = \hat b(n)\,K_{Hz}\sqrt{\delta_{\max}}$, $k_1 = \hat k(n)\,K_{Hz}\sqrt{\delta_{\max}}$, with
pure numbers $\hat a$, $\hat b$, $\hat k$.  The discrete fit on n = 21 samples (a 1 mm step,
δ = 0 included) reproduces all three printed values; the continuous fit does not.  n = 21 is
therefore the default.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from .board import Arg, Board

#: Samples of the discrete fit that reproduce the paper's constants (found below, not assumed).
PAPER_SAMPLES = 21


def normal_equations(residual: sp.Expr, unknowns: tuple[sp.Symbol, ...], mean) -> dict:
    """Solve d/dp mean(residual²) = 0 for the unknowns; ``mean`` integrates or sums over δ."""
    objective = mean(sp.expand(residual**2))
    return sp.solve([sp.diff(objective, p) for p in unknowns], unknowns, dict=True)[0]


def derive() -> Board:
    board = Board("contact_fits", "Least-squares fits of the Hertz contact force", "8–9")
    w = board.write
    k_hz, d_max, delta = sp.symbols("k_hz delta_max delta", positive=True)
    a, b, k1 = sp.symbols("a b k1", real=True)
    n = sp.Symbol("n", integer=True, positive=True)
    i = sp.Symbol("i", integer=True, nonnegative=True)

    hertz = w("hertz_force", k_hz * delta ** sp.Rational(3, 2), "Hertz contact force.", "8")
    cubic = w("cubic_force", a * delta**3 + b * delta, "Cubic contact force.", "9")
    linear = w("linear_force", k1 * delta, "Linear contact force (Fig. 2).", "35")

    # --- continuous fit: integrals over [0, δ_max] ---------------------------------------------
    def integral(e):
        return sp.integrate(e, (delta, 0, d_max))

    cont_cubic = w(
        "continuous_cubic_fit",
        normal_equations(hertz - cubic, (a, b), integral),
        r"Continuous least squares: zero gradient of "
        r"$\int_0^{\delta_{\max}} (F_{Hz} - F_{cc})^2\,d\delta$ in (a, b).",
        "9",
    )
    cont_linear = w(
        "continuous_linear_fit",
        normal_equations(hertz - linear, (k1,), integral),
        "Continuous least squares for k₁.",
        "35",
    )

    # --- discrete fit on n uniform samples, in the dimensionless u = δ/δ_max ---------------------
    S = {p: sp.Symbol(f"S_{p}") for p in ("2", "4", "6", "5/2", "9/2")}
    w(
        "power_sum",
        sp.Sum((i / (n - 1)) ** sp.Symbol("p"), (i, 0, n - 1)),
        r"Power sums $S_p = \sum_i u_i^p$ over the samples $u_i = i/(n - 1)$.",
    )
    A_, B_, K_ = sp.symbols("ahat bhat khat")
    # Residual K_Hz δ_max^{3/2} (u^{3/2} − â u³ − b̂ u): the normal equations in terms of S_p.
    disc_cubic = w(
        "discrete_cubic_fit",
        sp.solve(
            [
                S["9/2"] - A_ * S["6"] - B_ * S["4"],  # ∂/∂â
                S["5/2"] - A_ * S["4"] - B_ * S["2"],  # ∂/∂b̂
            ],
            (A_, B_),
            dict=True,
        )[0],
        r"Discrete normal equations for $\hat a = a\sqrt{\delta_{\max}}/K_{Hz}$ and "
        r"$\hat b = b/(K_{Hz}\sqrt{\delta_{\max}})$.",
        "9",
    )
    disc_linear = w(
        "discrete_linear_fit",
        {K_: S["5/2"] / S["2"]},
        r"Discrete normal equation for $\hat k = k_1/(K_{Hz}\sqrt{\delta_{\max}})$.",
        "35",
    )

    def power_sums(n_samples: int) -> dict:
        us = [sp.Rational(j, n_samples - 1) for j in range(n_samples)]
        return {S[key]: sum(x ** sp.Rational(key) for x in us) for key in S}

    def discrete(n_samples: int) -> tuple[sp.Expr, sp.Expr, sp.Expr]:
        sums = power_sums(n_samples)
        return (
            sp.nsimplify(disc_cubic[A_].subs(sums)),
            sp.nsimplify(disc_cubic[B_].subs(sums)),
            disc_linear[K_].subs(sums),
        )

    ahat, bhat, khat = (
        w(f"{name}_n{PAPER_SAMPLES}", v, f"Exact {name} for n = {PAPER_SAMPLES}.")
        for name, v in zip(("ahat", "bhat", "khat"), discrete(PAPER_SAMPLES), strict=True)
    )
    # δ = δ_max·u turns the residual into K_Hz δ_max^{3/2} (u^{3/2} − â u³ − b̂ u), so:
    ahat_f, bhat_f, khat_f = (sp.Float(v.evalf(30), 30) for v in (ahat, bhat, khat))
    scale = {
        a: ahat_f * k_hz / d_max ** sp.Rational(3, 2),
        b: bhat_f * k_hz * sp.sqrt(d_max),
        k1: khat_f * k_hz * sp.sqrt(d_max),
    }

    # --- which procedure reproduces the paper? -------------------------------------------------
    paper = {k_hz: 1000, d_max: sp.Rational(2, 100)}
    printed = {"a": (0.1553e6, 1e2), "b": (83.60, 1e-2), "k1": (122.7, 1e-1)}  # SI, last digit

    def matches(values: dict) -> bool:
        return all(
            abs(float(values[key]) - v) <= 0.5 * ulp * 1.000001 for key, (v, ulp) in printed.items()
        )

    cont_vals = {
        "a": cont_cubic[a].subs(paper),
        "b": cont_cubic[b].subs(paper),
        "k1": cont_linear[k1].subs(paper),
    }
    disc_vals = {"a": scale[a].subs(paper), "b": scale[b].subs(paper), "k1": scale[k1].subs(paper)}
    w(
        "paper_values_continuous",
        {k: sp.N(v, 8) for k, v in cont_vals.items()},
        r"Continuous fit at $K_{Hz}$ = 1000 N/m<sup>1.5</sup>, $\delta_{\max}$ = 2 cm (SI).",
    )
    w(
        "paper_values_discrete",
        {k: sp.N(v, 8) for k, v in disc_vals.items()},
        f"Discrete fit, n = {PAPER_SAMPLES}, same inputs (SI).",
    )
    board.check(
        "continuous fit does not reproduce a, b, k1",
        "9, Fig. 2",
        not matches(cont_vals),
        ", ".join(f"{k}={float(v):.6g}" for k, v in cont_vals.items()),
    )
    board.check(
        f"discrete fit, n = {PAPER_SAMPLES}, reproduces a, b, k1",
        "9, Fig. 2",
        matches(disc_vals),
        ", ".join(f"{k}={float(v):.6g}" for k, v in disc_vals.items()),
    )
    # Uniqueness: scan n with floating-point least squares (independent of the algebra above).
    hits = []
    for n_samples in range(3, 401):
        x = np.linspace(0.0, 0.02, n_samples)
        f = 1000.0 * x**1.5
        (fa, fb), *_ = np.linalg.lstsq(np.c_[x**3, x], f, rcond=None)
        if matches({"a": fa, "b": fb, "k1": (x @ f) / (x @ x)}):
            hits.append(n_samples)
    w("matching_sample_counts", hits, "Sample counts n ≤ 400 that reproduce all three values.")
    board.check(
        f"n = {PAPER_SAMPLES} is the only n ≤ 400 that matches",
        "9, Fig. 2",
        hits == [PAPER_SAMPLES],
        f"matching n: {hits}",
    )

    # --- kernels --------------------------------------------------------------------------------
    args = (
        Arg(k_hz, "N/m^1.5", "Hertz contact stiffness K_Hz", 10.0, 1e10, log=True),
        Arg(d_max, "m", "Largest penetration δ_max of the fit interval", 1e-6, 0.1, log=True),
    )
    for name, sym, unit, eq, what in (
        ("cubic_fit_a", a, "N/m^3", "9", "Cubic coefficient a"),
        ("cubic_fit_b", b, "N/m", "9", "Linear coefficient b of the cubic law"),
        ("linear_fit_k1", k1, "N/m", "35", "Equivalent linear contact stiffness k₁"),
    ):
        board.kernel(
            name=name,
            args=args,
            expr=scale[sym],
            returns=f"{what}: least squares on {PAPER_SAMPLES} uniform samples of [0, δ_max]",
            unit=unit,
            equation=eq,
            lhs=sp.latex(sym),
            note="The procedure that reproduces the paper's a = 0.1553 N/cm³, b = 0.8360 N/cm, "
            "k₁ = 122.7 N/m (default).",
        )
        board.kernel(
            name=f"{name}_continuous",
            args=args,
            expr=(cont_linear if sym is k1 else cont_cubic)[sym],
            returns=f"{what}: continuous least squares over [0, δ_max]",
            unit=unit,
            equation=eq,
            lhs=sp.latex(sym),
        )
    return board
