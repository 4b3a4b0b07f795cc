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
Newton's law at τ) are linear in X, V, U, cos φ and sin φ: three of them give X, V, U at a fixed
phase, and the fourth becomes $a\cos\varphi + b\sin\varphi = c$, which has zero, one or two
solutions $\varphi = \operatorname{atan2}(b, a) \pm \arccos(c/\sqrt{a^2+b^2})$.
"""

from __future__ import annotations

import sympy as sp

from .board import Arg, Board


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
    sigma = C / (2 * M)
    wd = sp.sqrt(K / M - C**2 / (4 * M**2))

    def decay(a, b):
        return sp.exp(-sigma * t) * (a * sp.cos(wd * t) + (b + sigma * a) / wd * sp.sin(wd * t))

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
    F = sp.Matrix([[f11, f12], [f21, f22]])
    before = -sp.Matrix([xp0, vp0]) + F * sp.Matrix([X - xp0, V - vp0])
    x_before, v_before = before
    w("x_before_second_impact", x_before, r"$x(\tau^-)$.", "F3")
    w("v_before_second_impact", v_before, r"$\dot x(\tau^-)$.", "F3")

    conditions = [
        sp.Eq(x_before, -X),
        sp.Eq(X + d / 2 + U * tau, -X - d / 2),
        sp.Eq(M * v_before + m * U, M * (-V) + m * (-U)),
        sp.Eq(-U - (-V), -e * (U - v_before)),
    ]
    w(
        "conditions",
        conditions,
        "Antisymmetry of x; the impact mass crosses the clearance d at speed U in τ; momentum and "
        "Newton's law at the second impact (after it: −V and −U).",
        "F3",
    )
    at_phase = sp.solve(conditions[:3], [X, V, U], dict=True)[0]
    X_phi = w("impact_displacement", sp.factor(at_phase[X]), "X at a fixed phase.", "F3")
    V_phi = w("main_velocity_after", sp.factor(at_phase[V]), "V at a fixed phase.", "F3")
    U_phi = w("impact_mass_velocity_after", sp.factor(at_phase[U]), "U at a fixed phase.", "F3")
    last = sp.expand(sp.numer(sp.together((conditions[3].lhs - conditions[3].rhs).subs(at_phase))))
    a_coef, b_coef = last.coeff(cphi), last.coeff(sphi)
    c_coef = -sp.expand(last - a_coef * cphi - b_coef * sphi)
    board.check(
        "the last condition is a·cos φ + b·sin φ = c with a, b, c free of φ",
        "F3",
        sp.expand(a_coef * cphi + b_coef * sphi - c_coef - last) == 0
        and not ({cphi, sphi} & (a_coef.free_symbols | b_coef.free_symbols | c_coef.free_symbols)),
    )
    a_coef = w("phase_cos_coefficient", sp.factor(a_coef), "a.", "F3")
    b_coef = w("phase_sin_coefficient", sp.factor(b_coef), "b.", "F3")
    c_coef = w("phase_right_side", sp.factor(c_coef), "c.", "F3")
    # Check: at a phase solving the last condition, all four conditions hold.
    point = {
        f11: sp.Rational(3, 10), f12: sp.Rational(1, 70), f21: -sp.Rational(9, 2),
        f22: sp.Rational(1, 5), A: sp.Rational(1, 100), B: -sp.Rational(1, 300),
        M: 1, m: sp.Rational(1, 20), e: sp.Rational(3, 5), W: 30, d: sp.Rational(1, 50),
    }  # fmt: skip
    an, bn, cn = (sp.nsimplify(v.subs(point)) for v in (a_coef, b_coef, c_coef))
    phase = sp.atan2(bn, an) + sp.acos(cn / sp.sqrt(an**2 + bn**2))
    values = {cphi: sp.cos(phase), sphi: sp.sin(phase)}
    sol = {k: v.subs(point).subs(values) for k, v in at_phase.items()}
    board.check(
        "at a phase solving it, X, V, U satisfy all four conditions (exact rational point)",
        "F3",
        all(
            abs(sp.N((c.lhs - c.rhs).subs(point).subs(sol).subs(values), 40)) < 1e-35
            for c in conditions
        ),
    )

    # --- kernels: the coefficients with Φ and the steady solution written out -------------------
    P = F0 + K * Xb
    Q = -C * W * Xb
    D = (K - M * W**2) ** 2 + (C * W) ** 2
    closed = {
        A: ((K - M * W**2) * P - C * W * Q) / D,
        B: (C * W * P + (K - M * W**2) * Q) / D,
        f11: Phi[0, 0],
        f12: Phi[0, 1],
        f21: Phi[1, 0],
        f22: Phi[1, 1],
    }
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
        board.kernel(
            name=name,
            args=(*args, aphi),
            expr=expr.subs(on_phase).subs(closed),
            magnitude=_rounding_scale(expr).subs(on_phase).subs(closed),
            returns=what,
            unit=unit,
            equation="F3",
            lhs={"impact_displacement": "X", "main_velocity_after": "V"}.get(name, "U"),
        )
    return board
