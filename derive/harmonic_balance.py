"""Step 3 — single-harmonic balance of the undamped contact equations (paper Eq. 10–13, 15).

1. Newton for both masses during contact (Eq. 10): the contact force a·z³ + b·z + c₁·ż, with
   z = y − x, pushes the main mass M forward and the impact mass m back.
2. Undamped (C = c₁ = 0), try x = A cos ωt, y = B cos ωt (Eq. 11) and keep the cos ωt component
   of each residual (Galerkin projection over one period): Eq. 12.
3. Adding the two balances eliminates the contact terms: B/A = (K − Mω²)/(mω²) (Eq. 13).
4. With y = (B/A)·x the main-mass equation becomes Duffing's ẍ + ω₀²x + εx³ = 0 (Eq. 14–15).
5. With a = 0 the two balances are linear in (A, B) and their determinant gives the two linear
   modes of the coupled masses; the out-of-phase one (B/A < 0) is the impact mode.
"""

from __future__ import annotations

import sympy as sp

from .board import Arg, Board


def derive() -> Board:
    board = Board("harmonic_balance", "Harmonic balance of the contact phase", "10–15")
    w = board.write
    t = sp.Symbol("t", real=True)
    M, K, C, m, a, b, c1 = sp.symbols("M K C m a b c1", positive=True)
    omega = sp.Symbol("omega", positive=True)
    A, B = sp.symbols("A B", real=True)
    x, y = sp.Function("x")(t), sp.Function("y")(t)

    z = y - x
    force = a * z**3 + b * z + c1 * sp.diff(z, t)
    eq10_1 = w(
        "eq10_1",
        M * x.diff(t, 2) + C * x.diff(t) + K * x - force,
        "Main mass during contact: the contact force pushes it along +z.",
        "10.1",
    )
    eq10_2 = w(
        "eq10_2",
        m * y.diff(t, 2) + force,
        "Impact mass during contact: the same force, opposite sign.",
        "10.2",
    )

    undamped = {C: 0, c1: 0}
    trial = {x: A * sp.cos(omega * t), y: B * sp.cos(omega * t)}
    r1 = w(
        "eq11_1",
        sp.expand(eq10_1.subs(undamped).subs(trial).doit()),
        "Residual of Eq. 10.1 for the single-harmonic trial motion.",
        "11.1",
    )
    r2 = w(
        "eq11_2",
        sp.expand(eq10_2.subs(undamped).subs(trial).doit()),
        "Residual of Eq. 10.2 for the single-harmonic trial motion.",
        "11.2",
    )

    def cos_component(residual: sp.Expr) -> sp.Expr:
        # (ω/π)∫ R cos ωt dt over one period, written with θ = ωt.
        th = sp.Symbol("theta")
        integrand = (residual * sp.cos(omega * t)).subs(t, th / omega)
        return sp.expand(sp.integrate(sp.expand(integrand), (th, 0, 2 * sp.pi)) / sp.pi)

    bal1 = w("eq12_1", cos_component(r1), "cos ωt balance of Eq. 11.1.", "12")
    bal2 = w("eq12_2", cos_component(r2), "cos ωt balance of Eq. 11.2.", "12")

    printed12 = (
        -M * A * omega**2 + K * A + sp.Rational(3, 4) * a * (A - B) ** 3 + b * (A - B),
        -m * B * omega**2 - sp.Rational(3, 4) * a * (A - B) ** 3 - b * (A - B),
    )
    board.check(
        "harmonic balance",
        "12",
        sp.expand(bal1 - printed12[0]) == 0 and sp.expand(bal2 - printed12[1]) == 0,
    )
    # Eq. 11.2 as printed: + m ω² B cos ωt (the inertia term has the wrong sign; Eq. 12 is right).
    cwt = sp.cos(omega * t)
    printed11_2 = m * omega**2 * B * cwt - a * (A - B) ** 3 * cwt**3 - b * (A - B) * cwt
    board.erratum(
        key="eq11_2_inertia_sign",
        equation="11.2",
        what="sign of the inertia term m ω² B cos ωt",
        printed=printed11_2,
        derived=r2,
        consequence="none downstream: Eq. 12.2 has the right sign −mω²B",
        point={m: 1, omega: 2, A: sp.Rational(1, 3), B: 1, a: 1, b: 1, t: sp.Rational(1, 7)},
    )
    board.check(
        "Eq. 11.2 inertia sign",
        "11.2",
        sp.expand(printed11_2 - r2) != 0,
        "printed +mω²B, derived −mω²B",
        erratum=True,
    )

    ratio = w(
        "amplitude_ratio",
        sp.solve(sp.expand(bal1 + bal2), B)[0] / A,
        "Adding the balances cancels the contact terms: B/A.",
        "13",
    )
    board.check(
        "B/A = (K − Mω²)/(mω²)", "13", sp.simplify(ratio - (K - M * omega**2) / (m * omega**2)) == 0
    )

    # --- Duffing form of the main-mass equation --------------------------------------------------
    R = sp.Symbol("R", real=True)  # R = B/A
    xs = sp.Symbol("x_s", real=True)
    duffing_lhs = sp.expand(
        (eq10_1.subs(undamped).subs(y, R * x).doit() / M).subs(x.diff(t, 2), 0).subs(x, xs)
    )
    omega0_sq = w(
        "omega0_squared_in_R",
        duffing_lhs.coeff(xs, 1),
        "Coefficient of x after y = (B/A)·x, dividing by M.",
        "15",
    )
    eps = w("epsilon_in_R", duffing_lhs.coeff(xs, 3), "Coefficient of x³.", "15")
    board.check(
        "Duffing form (no other powers of x)",
        "14",
        sp.expand(duffing_lhs - omega0_sq * xs - eps * xs**3) == 0,
    )
    # factor() writes 1 − B/A as ((M + m)ω² − K)/(mω²): one subtraction instead of two.
    omega0_sq_w = w("omega0_squared", sp.factor(omega0_sq.subs(R, ratio)), "ω₀² with Eq. 13.", "15")
    eps_w = w("epsilon", sp.factor(eps.subs(R, ratio)), "ε with Eq. 13.", "15")
    printed15 = (
        K / M + b / M * (1 - (K - M * omega**2) / (m * omega**2)),
        a / M * (1 - (K - M * omega**2) / (m * omega**2)) ** 3,
    )
    board.check(
        "ω₀² and ε",
        "15",
        sp.simplify(omega0_sq_w - printed15[0]) == 0 and sp.simplify(eps_w - printed15[1]) == 0,
    )

    # --- linear limit: the two modes of the coupled masses ---------------------------------------
    lin = sp.Matrix([[sp.diff(e.subs(a, 0), v) for v in (A, B)] for e in (bal1, bal2)])
    W = sp.Symbol("W", positive=True)  # W = ω²
    char = w(
        "linear_characteristic",
        sp.factor(lin.det().subs(omega**2, W)),
        "a = 0: determinant of the balances, a quadratic in ω².",
        "12–13",
    )
    w_low, w_high = sorted(
        sp.solve(char, W), key=lambda e: sp.N(e.subs({K: 1000, M: 1, m: sp.Rational(1, 4), b: 84}))
    )
    # Vieta's product form of the lower root: no cancellation when K·m ≫ b·(M + m).
    w_low_stable = K * b / (M * m * w_high)
    board.check(
        "lower root equals its product form",
        "12–13",
        sp.simplify(sp.radsimp(w_low - w_low_stable)) == 0,
    )
    w_low = w("omega_squared_in_phase", w_low_stable, "Lower root: masses in phase (B/A > 0).")
    w("omega_squared_out_of_phase", w_high, "Upper root: masses in opposition (B/A < 0).")
    free_ratio = sp.simplify(sp.limit(ratio.subs(omega**2, w_high), K, 0))
    board.check(
        "free bodies (K → 0): B/A = −M/m",
        "13",
        sp.simplify(free_ratio + M / m) == 0,
        f"B/A → {free_ratio}",
    )

    # --- kernels --------------------------------------------------------------------------------
    aM = Arg(M, "kg", "Main mass M", 0.05, 50.0, log=True)
    aK = Arg(K, "N/m", "Main stiffness K", 10.0, 1e6, log=True)
    am = Arg(m, "kg", "Impact mass m", 0.005, 5.0, log=True)
    ab = Arg(b, "N/m", "Linear coefficient b of the cubic contact law", 1.0, 1e5, log=True)
    aa = Arg(a, "N/m^3", "Cubic coefficient a of the contact law", 1e2, 1e9, log=True)
    aw = Arg(omega, "rad/s", "Angular frequency ω of the common motion", 1.0, 1e3, log=True)
    board.kernel(
        name="amplitude_ratio",
        args=(aK, aM, am, aw),
        expr=ratio,
        returns="Amplitude ratio B/A of impact to main mass",
        unit="1",
        equation="13",
        lhs=r"\frac{B}{A}",
    )
    board.kernel(
        name="duffing_omega0_squared",
        args=(aK, aM, am, ab, aw),
        expr=omega0_sq_w,
        returns="Linear coefficient ω₀² of the main-mass Duffing equation",
        unit="rad^2/s^2",
        equation="15",
        lhs=r"\omega_0^2",
    )
    board.kernel(
        name="duffing_epsilon",
        args=(aK, aM, am, aa, aw),
        expr=eps_w,
        returns="Cubic coefficient ε of the main-mass Duffing equation",
        unit="1/(m^2 s^2)",
        equation="15",
        lhs=r"\varepsilon",
    )
    # On the linear modes either balance gives B/A; the impact-mass one, b/(b − mω²), has no
    # cancellation on the upper mode, Eq. 13 none on the lower one.
    ratio_12_2 = w(
        "amplitude_ratio_impact_balance",
        sp.solve(bal2.subs(a, 0), B)[0] / A,
        "a = 0: B/A from the impact-mass balance alone.",
        "12",
    )
    pt = {K: 566111, M: 3, m: 3, b: sp.Rational(11, 2)}
    board.check(
        "both balances give the same B/A on the linear modes",
        "12–13",
        all(
            abs(sp.N((ratio - ratio_12_2).subs(omega, sp.sqrt(root)).subs(pt), 30)) < 1e-25
            for root in (w_low, w_high)
        ),
    )
    forms = {"in_phase": ratio, "out_of_phase": ratio_12_2}
    for name, root, what in (
        ("in_phase", w_low, "in phase (B/A > 0)"),
        ("out_of_phase", w_high, "in opposition (B/A < 0), the impact mode"),
    ):
        board.kernel(
            name=f"linear_frequency_squared_{name}",
            args=(aK, aM, am, ab),
            expr=root,
            returns=f"ω² of the linear (a = 0) coupled mode with the masses {what}",
            unit="rad^2/s^2",
            equation="12–13",
            lhs=r"\omega^2",
        )
        board.kernel(
            name=f"linear_amplitude_ratio_{name}",
            args=(aK, aM, am, ab),
            expr=forms[name].subs(omega, sp.sqrt(root)),
            returns=f"B/A of the linear (a = 0) coupled mode with the masses {what}",
            unit="1",
            equation="13",
            lhs=r"\frac{B}{A}",
        )
    return board
