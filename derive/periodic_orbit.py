r"""Step 10 — the symmetric periodic motion with two impacts per forcing period.

Beyond the paper: the classical solution of Masri & Caughey (J. Appl. Mech. 1966), see also
Bapat & Sankar (J. Sound Vib. 1985), for the rigid impact law of Step 9.  The primary is forced by
$P\cos(\Omega t+\varphi) + Q\sin(\Omega t+\varphi)$ (Step 8: $P = F_0 + KX_b$, $Q = -C\Omega X_b$).
The impact mass hits the wall $y - x = +d/2$ at t = 0 and the wall $y - x = -d/2$ half a period
later, τ = π/Ω; the state after the second impact is the negative of the state after the first,
and the forcing has changed sign too, so the next half period repeats the first one negated.

Between impacts the primary follows Step 8: the steady solution $x_p$ plus the free decay of its
deviation Δ from it, and the steady solution changes sign over half a period.  With the fundamental
matrix Φ of the free decay over τ:

$$\begin{pmatrix}x(\tau^-)\\ \dot x(\tau^-)\end{pmatrix} =
-\begin{pmatrix}x_p(0)\\ \dot x_p(0)\end{pmatrix} + \Phi\,\Delta_0, \qquad
\Delta_0 = \begin{pmatrix}X - x_p(0)\\ V - \dot x_p(0)\end{pmatrix}.$$

The unknowns are X = x(0), V = ẋ(0⁺), U = ẏ(0⁺) and the forcing phase φ.  The four conditions
(x is continuous and antisymmetric; the impact mass crosses the clearance at speed U; momentum;
Newton's law at τ) are linear in X, V, U, cos φ and sin φ.  Any three of them give X, V, U at a
fixed phase, but a triple's determinant can vanish: the first three's at the undamped resonance
(Φ = −I there, so the first condition loses X and V) and at frequencies next to a damped one,
the last three's at others.  So
all four are kept: the signed 3×3 minors of their matrix form a left null vector ℓ, and ℓ applied
to the right side leaves $a\cos\varphi + b\sin\varphi = c$, which has zero, one or two solutions
$\varphi = \operatorname{atan2}(b, a) \pm \arccos(c/\sqrt{a^2+b^2})$; X, V, U follow from the four
triples' Cramer solutions weighted by their determinants squared, so no determinant divides
alone.

The steady solution does not exist for an undamped primary at Ω = ωₙ, but the response to the
forcing from rest over half a period, Γ, does: written with sinc it is finite there, and the
closed form holds at and next to the resonance (Masri and Caughey's own setting).
"""

from __future__ import annotations

import sympy as sp

from .board import Arg, Board
from .free_flight import free_decay


def _rounding_scale(expr: sp.Expr) -> sp.Expr:
    """The size of the terms that cancel in ``expr``: the absolute values of its numerator's
    expanded terms summed, over the absolute denominator.  The kernels' rounding is judged
    against it (near the orbit's existence boundary a, b, c are small differences)."""
    num, den = sp.fraction(sp.together(expr))
    return sum(sp.Abs(term) for term in sp.Add.make_args(sp.expand(num))) / sp.Abs(den)


def derive() -> Board:
    board = Board("periodic_orbit", "The symmetric two-impact periodic motion", "F3")
    w = board.write
    t = sp.Symbol("t", nonnegative=True)
    M, K, m, W, d = sp.symbols("M K m Omega d", positive=True)
    C, e = sp.symbols("C e", nonnegative=True)
    F0, Xb = sp.symbols("F0 X_b", real=True)
    X, V, U, cphi, sphi = sp.symbols("X V U c_varphi s_varphi", real=True)
    A, B = sp.symbols("A B", real=True)
    f11, f12, f21, f22 = sp.symbols("Phi_11 Phi_12 Phi_21 Phi_22", real=True)

    tau = w("half_period", sp.pi / W, r"Half the forcing period, τ = π/Ω.", "F3")

    # --- the free decay over τ: its fundamental matrix -----------------------------------------
    def decay(a, b):
        return free_decay(a, b, t, M, K, C)

    Phi = sp.Matrix(
        [
            [decay(1, 0), decay(0, 1)],
            [sp.diff(decay(1, 0), t), sp.diff(decay(0, 1), t)],
        ]
    ).subs(t, tau)
    for (i, j), name in zip(
        ((0, 0), (0, 1), (1, 0), (1, 1)), ("11", "12", "21", "22"), strict=True
    ):
        w(
            f"Phi_{name}",
            Phi[i, j],
            rf"$\Phi_{{{name}}}$: the free decay (Step 7) over τ; first column from a unit "
            "displacement, second from a unit velocity (rows: x, ẋ).",
            "F3",
        )
    xp0 = A * cphi + B * sphi
    vp0 = W * (B * cphi - A * sphi)
    board.check(
        "the steady solution (Step 8) changes sign over half a period",
        "F3",
        sp.simplify(
            (A * sp.cos(W * t + sp.Symbol("phi")) + B * sp.sin(W * t + sp.Symbol("phi"))).subs(
                t, tau
            )
            + (A * sp.cos(sp.Symbol("phi")) + B * sp.sin(sp.Symbol("phi")))
        )
        == 0,
    )
    # --- the forced half period from rest: Γ ----------------------------------------------------
    # x(τ⁻) = Φ·(X, V) + Γ·(cos φ, sin φ): the free decay of the state after the impact plus the
    # response to the forcing from rest.  With the steady solution, that response is
    # x_p(τ) − Φ·x_p(0) = −(I + Φ)·x_p(0), and x_p(0) = Ψ·(cos φ, sin φ).
    F = sp.Matrix([[f11, f12], [f21, f22]])
    G = sp.Matrix(2, 2, sp.symbols("Gamma_11 Gamma_12 Gamma_21 Gamma_22", real=True))
    Psi = sp.Matrix([[A, B], [W * B, -W * A]])
    w(
        "forced_half_period_from_rest",
        sp.Eq(G, -(sp.eye(2) + F) * Psi),
        r"Γ: the primary's state a half period after starting at rest, per unit cos φ and sin φ "
        r"of the forcing phase (columns); the steady solution's coefficients A, B give "
        r"Γ = −(I + Φ)Ψ.",
        "F3",
    )
    before = F * sp.Matrix([X, V]) + G * sp.Matrix([cphi, sphi])
    x_before, v_before = before
    board.check(
        "Φ·(X, V) + Γ·(cos φ, sin φ) is the steady solution plus the free decay of the difference",
        "F3",
        sp.expand(
            (before - (-sp.Matrix([xp0, vp0]) + F * sp.Matrix([X - xp0, V - vp0]))).subs(
                dict(zip(G, -(sp.eye(2) + F) * Psi, strict=True))
            )
        )
        == sp.zeros(2, 1),
    )
    w("x_before_second_impact", x_before, r"$x(\tau^-)$.", "F3")
    w("v_before_second_impact", v_before, r"$\dot x(\tau^-)$.", "F3")

    conditions = [
        sp.Eq(x_before, -X),
        sp.Eq(X + d / 2 + U * tau, -X - d / 2),
        sp.Eq(M * v_before + m * U, M * (-V) + m * (-U)),
        sp.Eq(-U - (-V), -e * (U - v_before)),
    ]
    for name, condition, text in zip(
        ("antisymmetry", "crossing", "momentum", "restitution"),
        conditions,
        (
            "Antisymmetry: x after half a period is −X.",
            "The impact mass crosses the clearance d at speed U in τ.",
            "Momentum at the second impact (after it: −V and −U).",
            "Newton's law at the second impact.  The four conditions are linear in X, V, U: "
            "four equations for three unknowns, solvable when the right side (linear in cos φ "
            "and sin φ) lies in the span of the columns.",
        ),
        strict=True,
    ):
        w(f"condition_{name}", condition, text, "F3")
    unknowns = [X, V, U]
    # rows as lengths (the last two divided by MΩ and Ω), so that their minors share one unit
    lengths = [1, 1, 1 / (M * W), 1 / W]
    L, y = sp.linear_eq_to_matrix(
        [(c.lhs - c.rhs) * s for c, s in zip(conditions, lengths, strict=True)], unknowns
    )

    # Each three of the four conditions give X, V, U at a fixed phase by Cramer's rule, unless
    # their determinant vanishes — and each of them does somewhere: three of them at the undamped
    # resonance, where Φ = −I and Γ stays finite, others next to the damped resonance.  All four
    # together never fail where L has rank 3.
    def without(i):
        return [r for r in range(4) if r != i]

    minors = [L.extract(without(i), [0, 1, 2]).det() for i in range(4)]
    left = sp.Matrix([[(-1) ** i * minors[i] for i in range(4)]])
    board.check(
        "the signed 3×3 minors of L form its left null vector ℓ (Laplace expansion of a 4×4 "
        "determinant with a repeated column)",
        "F3",
        sp.expand(left * L) == sp.zeros(1, 3),
    )
    last = sp.expand((left * y)[0])
    a_coef, b_coef = last.coeff(cphi), last.coeff(sphi)
    c_coef = -sp.expand(last - a_coef * cphi - b_coef * sphi)
    board.check(
        "ℓ·(right side) = 0 is a·cos φ + b·sin φ = c with a, b, c free of φ",
        "F3",
        sp.expand(a_coef * cphi + b_coef * sphi - c_coef - last) == 0
        and not ({cphi, sphi} & (a_coef.free_symbols | b_coef.free_symbols | c_coef.free_symbols)),
    )
    a_coef = w("phase_cos_coefficient", a_coef, "a.", "F3")
    b_coef = w("phase_sin_coefficient", b_coef, "b.", "F3")
    c_coef = w("phase_right_side", c_coef, "c.", "F3")
    # At such a phase the four conditions agree; the solutions of the four triples, weighted by
    # their determinants squared, give X, V, U wherever any triple can.
    weight = sum(mi**2 for mi in minors)
    at_phase_sum = sp.zeros(3, 1)
    for i in range(4):
        rows = without(i)
        at_phase_sum += minors[i] * L.extract(rows, [0, 1, 2]).adjugate() * y.extract(rows, [0])
    at_phase = {u: at_phase_sum[k] / weight for k, u in enumerate(unknowns)}
    w(
        "weighted_cramer",
        sp.Eq(
            sp.Matrix(unknowns),
            sp.Symbol(r"\sum_i D_i\,\mathrm{adj}(L_{\hat i})\,y_{\hat i} / \sum_i D_i^2"),
        ),
        r"$D_i$: the determinant of the conditions without the i-th; $L_{\hat i}$, $y_{\hat i}$: "
        "their rows.  Each term is Cramer's rule times $D_i^2$, so no determinant divides alone.",
        "F3",
    )
    X_phi = w("impact_displacement", at_phase[X], "X at a fixed phase.", "F3")
    V_phi = w("main_velocity_after", at_phase[V], "V at a fixed phase.", "F3")
    U_phi = w("impact_mass_velocity_after", at_phase[U], "U at a fixed phase.", "F3")
    # Check: at a phase solving the last condition, all four conditions hold.
    point = {
        f11: sp.Rational(3, 10), f12: sp.Rational(1, 70), f21: -sp.Rational(9, 2),
        f22: sp.Rational(1, 5), G[0, 0]: sp.Rational(1, 100), G[0, 1]: -sp.Rational(1, 300),
        G[1, 0]: sp.Rational(1, 7), G[1, 1]: sp.Rational(2, 9),
        M: 1, m: sp.Rational(1, 20), e: sp.Rational(3, 5), W: 30, d: sp.Rational(1, 50),
    }  # fmt: skip
    resonant_point = dict(point) | {f11: -1, f12: 0, f21: 0, f22: -1}
    checks_ok = []
    for pt in (point, resonant_point):
        an, bn, cn = (sp.nsimplify(v.subs(pt)) for v in (a_coef, b_coef, c_coef))
        phase = sp.atan2(bn, an) + sp.acos(cn / sp.sqrt(an**2 + bn**2))
        values = {cphi: sp.cos(phase), sphi: sp.sin(phase)}
        sol = {k: v.subs(pt).subs(values) for k, v in at_phase.items()}
        checks_ok.append(
            all(
                abs(sp.N((c.lhs - c.rhs).subs(pt).subs(sol).subs(values), 40)) < 1e-35
                for c in conditions
            )
        )
    board.check(
        "at a phase solving it, X, V, U satisfy all four conditions (exact rational points, one "
        "with Φ = −I as at the undamped resonance)",
        "F3",
        all(checks_ok),
    )

    # --- Γ written out; for an undamped primary, in a form that stays finite at Ω = ωₙ --------
    P = F0 + K * Xb
    Q = -C * W * Xb
    D = (K - M * W**2) ** 2 + (C * W) ** 2
    steady = {A: ((K - M * W**2) * P - C * W * Q) / D, B: (C * W * P + (K - M * W**2) * Q) / D}
    Gamma_damped = (-(sp.eye(2) + Phi) * Psi).subs(steady)
    wn = sp.sqrt(K / M)
    u = sp.Symbol("u", real=True)
    rotation = sp.Matrix([[sp.sin(u), sp.cos(u) / wn], [-wn * sp.cos(u), sp.sin(u)]])
    Gamma_undamped = (
        sp.pi * sp.sinc(u) / (M * W * (wn + W)) * rotation * sp.Matrix([[P, Q], [W * Q, -W * P]])
    )
    w(
        "undamped_half_period_from_rest",
        sp.Eq(sp.Symbol(r"\Gamma_{C=0}"), Gamma_undamped),
        r"With C = 0, $u = \pi(\Omega - \omega_n)/(2\Omega)$: $1 + \cos\omega_n\tau = "
        r"2\sin^2 u$ and $\sin\omega_n\tau = 2\sin u\cos u$, so the factor sin u of I + Φ "
        r"cancels the resonant denominator $\omega_n - \Omega = -2\Omega u/\pi$: "
        r"sinc u = sin(u)/u is 1 at the resonance.",
        "F3",
    )
    u_value = sp.pi * (W - wn) / (2 * W)
    sample = {M: sp.Rational(3, 2), K: 700, W: sp.Rational(41, 2), F0: sp.Rational(7, 5),
              Xb: sp.Rational(1, 300)}  # fmt: skip
    diff = (Gamma_undamped.subs(u, u_value) - Gamma_damped).subs(C, 0).subs(sample)
    board.check(
        "for C = 0 it equals −(I + Φ)Ψ (50 digits at a rational point)",
        "F3",
        max(abs(sp.N(v, 50)) for v in diff) < 1e-45,
    )
    # At Ω = ωₙ: the response from rest, solved afresh (dsolve) for the resonant equation.
    xr = sp.Function("x")
    rhs = (P * sp.cos(W * t + sp.Symbol("phi")) + Q * sp.sin(W * t + sp.Symbol("phi"))).subs(C, 0)
    resonant = sp.dsolve(
        sp.Eq(M * xr(t).diff(t, 2) + M * W**2 * xr(t), rhs),
        xr(t),
        ics={xr(0): 0, xr(t).diff(t).subs(t, 0): 0},
    ).rhs
    at_tau = sp.Matrix([resonant, resonant.diff(t)]).subs(t, tau)
    phi_s = sp.Symbol("phi")
    by_gamma = Gamma_undamped.subs(u, 0).subs(K, M * W**2).subs(C, 0) * sp.Matrix(
        [sp.cos(phi_s), sp.sin(phi_s)]
    )
    board.check(
        "at Ω = ωₙ (u = 0) it is the resonant response from rest, x ∝ t·sin(Ωt + φ) (dsolve)",
        "F3",
        sp.simplify(sp.expand_trig(at_tau.subs(K, M * W**2) - by_gamma)) == sp.zeros(2, 1),
    )
    Gamma_value = sp.Matrix(
        2,
        2,
        lambda i, j: sp.Piecewise(
            (Gamma_undamped[i, j].subs(u, u_value), sp.Eq(C, 0)), (Gamma_damped[i, j], True)
        ),
    )

    # --- kernels: the coefficients with Φ and Γ written out -------------------------------------
    closed = {f11: Phi[0, 0], f12: Phi[0, 1], f21: Phi[1, 0], f22: Phi[1, 1]}
    closed |= {G[i, j]: Gamma_value[i, j] for i in range(2) for j in range(2)}
    aM = Arg(M, "kg", "Main mass M", 0.2, 20.0, log=True)
    aK = Arg(K, "N/m", "Main stiffness K", 100.0, 1e5, log=True)
    aC = Arg(C, "N s/m", "Main damping C (underdamped)", 0.0, 0.5)
    am = Arg(m, "kg", "Impact mass m", 1e-3, 0.2, log=True)
    ae = Arg(e, "1", "Coefficient of restitution e", 0.0, 1.0)
    ad = Arg(d, "m", "Total clearance d", 1e-4, 5e-2, log=True)
    aF = Arg(F0, "N", "Force amplitude F0 on the main mass", -10.0, 10.0)
    aXb = Arg(Xb, "m", "Base-motion amplitude X_b", -1e-2, 1e-2)
    aW = Arg(W, "rad/s", "Forcing frequency Ω", 1.0, 300.0, log=True)
    args = (aM, aK, aC, am, ae, ad, aF, aXb, aW)
    for name, expr, what, unit in (
        (
            "phase_cos_coefficient",
            a_coef,
            "Coefficient a of cos φ in a·cos φ + b·sin φ = c",
            "kg m/s",
        ),
        (
            "phase_sin_coefficient",
            b_coef,
            "Coefficient b of sin φ in a·cos φ + b·sin φ = c",
            "kg m/s",
        ),
        ("phase_right_side", c_coef, "Right side c of a·cos φ + b·sin φ = c", "kg m/s"),
    ):
        board.kernel(
            name=name,
            args=args,
            expr=expr.subs(closed),
            magnitude=_rounding_scale(expr).subs(closed),
            returns=what,
            unit=unit,
            equation="F3",
            lhs=name[0] if name != "phase_right_side" else "c",
        )
    aphi = Arg(
        sp.Symbol("phi", real=True), "rad", "Forcing phase at the first impact φ", -3.15, 3.15
    )
    on_phase = {cphi: sp.cos(aphi.symbol), sphi: sp.sin(aphi.symbol)}
    at_phase_kernels = []
    for name, expr, what, unit in (
        ("impact_displacement", X_phi, "Main-mass displacement X at the first impact", "m"),
        ("main_velocity_after", V_phi, "Main-mass velocity V after the first impact", "m/s"),
        (
            "impact_mass_velocity_after",
            U_phi,
            "Impact-mass velocity U after the first impact",
            "m/s",
        ),
    ):
        k = board.kernel(
            name=name,
            args=(*args, aphi),
            expr=expr.subs(on_phase).subs(closed),
            magnitude=_rounding_scale(expr).subs(on_phase).subs(closed),
            returns=what,
            unit=unit,
            equation="F3",
            lhs={"impact_displacement": "X", "main_velocity_after": "V"}.get(name, "U"),
        )
        at_phase_kernels.append(k)
    # --- the residual of the phase condition, and the orbit's slopes ----------------------------
    # r(φ) = a·cos φ + b·sin φ − c vanishes on the orbit.  Its slopes in φ and in a parameter p
    # give the phase's, dφ/dp = −(∂r/∂p)/(∂r/∂φ), and with ∂X/∂p + ∂X/∂φ·dφ/dp the state's: the
    # orbit's sensitivity to the damper (m, e, d) and to the forcing (F0, X_b) without
    # differencing.  Not in M, K, C, Ω: they enter through Φ and Γ, where C = 0 is a case and the
    # resonant sinc's derivative cancels catastrophically next to ωₙ.
    residual = board.kernel(
        name="phase_residual",
        args=(*args, aphi),
        expr=(a_coef * cphi + b_coef * sphi - c_coef).subs(on_phase).subs(closed),
        magnitude=(
            _rounding_scale(a_coef) * sp.Abs(cphi)
            + _rounding_scale(b_coef) * sp.Abs(sphi)
            + _rounding_scale(c_coef)
        )
        .subs(on_phase)
        .subs(closed),
        returns="Residual r = a·cos φ + b·sin φ − c of the orbit's phase condition",
        unit="kg m/s",
        equation="F3",
        lhs="r",
    )
    board.bundle(
        "phase_residual_and_derivatives",
        [residual, *board.derivatives(residual, ("phi", "e", "d", "m", "F0", "X_b"))],
        "The phase condition's residual and its derivatives in φ, e, d, m, F0, X_b",
    )
    for k in at_phase_kernels:
        board.derivatives(k, ("phi", "e", "d"))
    return board
