"""Step 5 — two-variable expansion of the relative motion and the contact duration (Eq. 21–33).

1. During contact the motion is assumed to keep the shape y = (B/A)·x, so y = B/(B − A)·z with
   z = y − x.  Put into Eq. 10.2: m·B/(B − A)·z̈ + c₁ż + az³ + bz = 0, i.e.
   z̈ + λ(c₁ż + az³ + bz)/m = 0 with **λ = (B − A)/B = 1 − A/B** (Eq. 21).  The paper prints
   λ = B/(B − A), the reciprocal; every later equation (22, 29–33) inherits it.  Both are kept.
2. Bookkeeping parameter μ (Eq. 22), fast time ξ = Ωt and slow time η = μt (Eq. 23–24), the
   expansion z = z₀ + μz₁, κ₃ = Ω² + μΩ₁ (Eq. 25) and the order equations (Eq. 26).
3. z₀ = N(η) sin ξ; removing the secular sin ξ and cos ξ terms gives Eq. 27–28, then z₁ and Eq. 32.
4. Ω² = κ₃ − μΩ₁ (Eq. 29); half a period of the contact oscillation is the contact duration,
   T = π/Ω, a fixed point (Eq. 30) solved by iteration (Eq. 31) from the linear value
   T⁽⁰⁾ = π√(m/(λb)) (the paper prints 2π: a whole period).
"""

from __future__ import annotations

import mpmath as mp
import sympy as sp

from .board import Arg, Board


def derive() -> Board:
    board = Board("multiple_scales", "Two-variable expansion and contact duration", "21–33")
    w = board.write
    t = sp.Symbol("t", nonnegative=True)
    m, a, b, c1, mu, Om = sp.symbols("m a b c1 mu Omega", positive=True)
    Zd0 = sp.Symbol("zdot0", positive=True)
    A, B, R = sp.symbols("A B ba", real=True)  # ba = B/A
    z = sp.Function("z")(t)

    # --- Eq. 21: the relative-motion equation -----------------------------------------------------
    y_of_z = B / (B - A) * z
    eq10_2 = m * sp.diff(y_of_z, t, 2) + c1 * z.diff(t) + a * z**3 + b * z
    lam_derived = w(
        "lambda",
        sp.simplify(sp.expand(eq10_2 / m).coeff(z.diff(t, 2)) ** -1),
        "Eq. 10.2 with y = B/(B − A)·z, divided by the coefficient of z̈: "
        "z̈ + λ(c₁ż + az³ + bz)/m = 0.",
        "21",
    )
    lam_derived = sp.simplify(lam_derived.subs(B, R * A))
    lam_printed = R / (R - 1)  # B/(B − A) as printed
    board.check(
        "Eq. 21 factor (B − A)/B",
        "21",
        sp.simplify(lam_derived - (R - 1) / R) == 0,
        "derived λ = 1 − A/B; printed B/(B − A)",
        erratum=True,
    )
    M_ = sp.Symbol("M", positive=True)
    board.check(
        "free bodies (B/A = −M/m): λ b/m = b/(reduced mass)",
        "21",
        sp.simplify(lam_derived.subs(R, -M_ / m) * b / m - b * (m + M_) / (m * M_)) == 0,
    )
    board.erratum(
        key="eq21_factor",
        equation="21 (and 22, 29–33)",
        what="factor of the contact terms",
        printed=lam_printed,
        derived=lam_derived,
        consequence="contact frequency √(λb/m) with the printed λ is too low: for two free "
        "bodies (B/A = −M/m) it gives √(bM/(m(m+M))) instead of √(b/μ), μ = mM/(m+M); "
        "the printed contact durations are longer by the factor (1 + m/M)",
        point={R: -4},
    )

    # --- Eq. 22–26 with a generic λ ----------------------------------------------------------------
    lam = sp.Symbol("lambda", positive=True)
    # κ₁ = λc₁/(μm), κ₂ = λa/(μm) are O(1) symbols during the expansion; μ marks smallness.
    k1_, k2_ = sp.symbols("kappa_1 kappa_2", positive=True)
    k3 = lam * b / m
    physical = {k1_: lam * c1 / (mu * m), k2_: lam * a / (mu * m)}
    w(
        "kappa",
        (physical[k1_], physical[k2_], k3),
        "κ₁, κ₂, κ₃ with the bookkeeping μ (small damping and cubic).",
        "22",
    )
    xi, eta = sp.symbols("xi eta", real=True)
    Om1 = sp.Function("Omega_1")(eta)
    Z0, Z1 = sp.Function("z_0")(xi, eta), sp.Function("z_1")(xi, eta)
    Z = Z0 + mu * Z1

    def ddt(f):  # chain rule, Eq. 23
        return Om * sp.diff(f, xi) + mu * sp.diff(f, eta)

    eq24 = w(
        "eq24",
        sp.expand(ddt(ddt(Z)) + mu * (k1_ * ddt(Z) + k2_ * Z**3) + (Om**2 + mu * Om1) * Z),
        "Eq. 22 in (ξ, η) with κ₃ = Ω² + μΩ₁ (Eq. 23–25).",
        "24–25",
    )
    order0 = w("order0", eq24.coeff(mu, 0), "Order μ⁰.", "26.1")
    order1 = w("order1", sp.expand(eq24.coeff(mu, 1)), "Order μ¹.", "26.2")
    board.check("Eq. 26.1", "26.1", sp.simplify(order0 / Om**2 - (Z0.diff(xi, 2) + Z0)) == 0)
    printed26_2 = (
        Z1.diff(xi, 2)
        + Z1
        + 2 / Om * Z0.diff(xi, eta)
        + k1_ / Om * Z0.diff(xi)
        + Om1 / Om**2 * Z0
        + k2_ / Om**2 * Z0**3
    )
    board.check("Eq. 26.2", "26.2", sp.simplify(order1 / Om**2 - printed26_2) == 0)

    # --- secular terms ------------------------------------------------------------------------------
    N = sp.Function("N")(eta)
    forcing = w(
        "forcing",
        sp.expand(
            -(order1 - Om**2 * (Z1.diff(xi, 2) + Z1)).subs(Z0, N * sp.sin(xi)).doit() / Om**2
        ),
        "Right side of Eq. 26.2 with z₀ = N(η) sin ξ.",
        "26.2",
    )
    sec_cos = w(
        "secular_cos",
        sp.simplify(sp.integrate(forcing * sp.cos(xi), (xi, 0, 2 * sp.pi)) / sp.pi),
        "cos ξ component.",
        "27.1",
    )
    sec_sin = w(
        "secular_sin",
        sp.simplify(sp.integrate(forcing * sp.sin(xi), (xi, 0, 2 * sp.pi)) / sp.pi),
        "sin ξ component.",
        "27.2",
    )
    board.check("Eq. 27.1", "27.1", sp.simplify(sec_cos + (2 * N.diff(eta) + k1_ * N) / Om) == 0)
    board.check(
        "Eq. 27.2",
        "27.2",
        sp.simplify(sec_sin + N**3 / Om**2 * (Om1 / N**2 + sp.Rational(3, 4) * k2_)) == 0,
    )
    N_sol = w(
        "N",
        sp.dsolve(sec_cos, N, ics={N.subs(eta, 0): Zd0 / Om}).rhs,
        "Slowly decaying amplitude; N(0) = Ż₀/Ω from ż(0) = Ω ∂z₀/∂ξ.",
        "28.1",
    )
    Om1_sol = w("Omega_1", sp.solve(sec_sin, Om1)[0], "Frequency correction.", "28.2")
    board.check(
        "Eq. 28",
        "28",
        sp.simplify(N_sol - Zd0 / Om * sp.exp(-k1_ * eta / 2)) == 0
        and sp.simplify(Om1_sol + sp.Rational(3, 4) * k2_ * N**2) == 0,
    )

    # --- z₁ -------------------------------------------------------------------------------------------
    nonsecular = sp.expand(
        sp.expand_trig(forcing)
        .subs(N.diff(eta), sp.solve(sec_cos, N.diff(eta))[0])
        .subs(Om1, Om1_sol)
    )
    nonsecular = sp.simplify(sp.fu(nonsecular))
    u = sp.Function("u")
    z1_sol = sp.dsolve(
        u(xi).diff(xi, 2) + u(xi) - nonsecular.subs(Z1, 0),
        u(xi),
        ics={u(0): 0, u(xi).diff(xi).subs(xi, 0): 0},
    ).rhs
    z1_sol = w(
        "z_1", sp.simplify(z1_sol), "Non-secular part solved with z₁(0) = ∂z₁/∂ξ(0) = 0.", "26.2"
    )
    z_sol = w("z", N * sp.sin(xi) + mu * z1_sol, "z = z₀ + μ z₁.", "32")
    printed32 = N * sp.sin(xi) - mu * k2_ * N**3 / (32 * Om**2) * (sp.sin(3 * xi) - 3 * sp.sin(xi))
    board.check("Eq. 32 (with λ)", "32", sp.simplify(sp.expand_trig(z_sol - printed32)) == 0)

    # Substitute back into Eq. 24: orders μ⁰ and μ¹ vanish, μ² does not.
    back = sp.expand(
        (
            ddt(ddt(z_sol))
            + mu * (k1_ * ddt(z_sol) + k2_ * z_sol**3)
            + (Om**2 + mu * Om1_sol) * z_sol
        )
        .subs(N, N_sol)
        .doit()
    )
    back = sp.expand(sp.expand_trig(back))
    res = [sp.simplify(back.coeff(mu, k)) for k in range(3)]
    board.check(
        "z₀ + μz₁ leaves an O(μ²) residual in Eq. 24",
        "24–32",
        res[0] == 0 and res[1] == 0 and res[2] != 0,
    )

    # --- Eq. 29–31: frequency and contact duration ---------------------------------------------------
    Om_sq = w(
        "Omega_squared",
        sp.expand((k3 - mu * Om1_sol).subs(N, N_sol).subs(eta, mu * t).subs(physical)),
        "Ω² = κ₃ − μΩ₁ at time t.",
        "29",
    )
    printed29 = lam * (b / m + 3 * a / (4 * m) * Zd0**2 / Om**2 * sp.exp(-lam * c1 / m * t))
    board.check("Eq. 29 (with λ)", "29", sp.simplify(Om_sq - printed29) == 0)
    T = sp.Symbol("T", positive=True)
    T_map = w(
        "contact_duration_map",
        sp.pi / sp.sqrt(Om_sq.subs(Om, sp.pi / T).subs(t, T)),
        "T = π/Ω with Ω = π/T inside and t = T: the fixed-point map.",
        "30–31",
    )
    T0 = w(
        "contact_duration_start",
        sp.pi * sp.sqrt(m / (lam * b)),
        "Linear (a = 0, c₁ = 0) half period: the starting value.",
        "31",
    )
    T0_printed = 2 * sp.pi * sp.sqrt(m / (lam * b))
    board.erratum(
        key="eq31_start_full_period",
        equation="31 (T⁽⁰⁾)",
        what="starting value is a full period",
        printed=T0_printed.subs(lam, lam_printed),
        derived=T0.subs(lam, lam_printed),
        consequence="2π for π: the first iterate starts twice too long; the fixed point "
        "is the same, but the iteration history (Fig. 3b) differs",
        point={m: sp.Rational(1, 4), b: 84, R: -4},
    )
    board.check("T⁽⁰⁾: π (half period), not 2π", "31", True, "printed 2π", erratum=True)

    # --- the fixed point on Table 1's inputs ------------------------------------------------------
    # M = 1 kg, Ż₀ = 7.5 cm/s, c₁ = 0, the paper's a and b; B/A = −M/m (free bodies, which the
    # closed forms of Eq. 34–35 also assume).  Iterated in mpmath until it stops moving.
    def table1_inputs(m_val):
        return {
            m: sp.Rational(m_val),
            a: sp.Rational("155300"),
            b: sp.Rational("83.60"),
            c1: 0,
            Zd0: sp.Rational("0.075"),
            R: -1 / sp.Rational(m_val),
        }

    table1 = {}
    for m_val in ("0.15", "0.20", "0.25"):
        for name, lam_v, start in (
            ("derived", lam_derived, T0),
            ("printed", lam_printed, T0_printed),
        ):
            subs = table1_inputs(m_val)
            step_map = sp.lambdify(T, T_map.subs(lam, lam_v).subs(subs), "mpmath")
            with mp.workdps(30):
                history = [mp.mpf(str(sp.N(start.subs(lam, lam_v).subs(subs), 30)))]
                for _ in range(60):
                    history.append(step_map(history[-1]))
            table1[(m_val, name)] = history
    w(
        "table1_iterations",
        {f"m={k[0]} ({k[1]})": [mp.nstr(v, 6) for v in h[:6]] for k, h in table1.items()},
        "Contact-duration iterates T⁽⁰⁾…T⁽⁵⁾ [s] on Table 1's inputs (B/A = −M/m, c₁ = 0).",
        "31",
    )
    converged = all(abs(h[-1] - h[-2]) < 1e-20 for h in table1.values())
    board.check(
        "fixed point converges on Table 1 inputs",
        "30–31, Table 1",
        converged,
        "; ".join(f"m={k[0]} {k[1]} {mp.nstr(h[-1], 4)} s" for k, h in table1.items()),
    )

    # --- the same fixed point as a root (for a fast kernel) ----------------------------------------
    # T = π/√D(T) with D > 0 holds exactly when h(T) = T²·D(T) − π² = 0 (T > 0).  With c₁ = 0,
    # h is a quadratic in T², so the fixed point is in closed form; with c₁ > 0 Newton's method on
    # h started there converges in a few steps, also where the iteration of Eq. 31 does not.
    D_T = Om_sq.subs(Om, sp.pi / T).subs(t, T)
    h = w(
        "contact_duration_residual",
        sp.expand(T**2 * D_T - sp.pi**2),
        "h(T) = T²·D(T) − π²: zero exactly at the fixed point of Eq. 31 (T = π/√D(T)).",
        "30–31",
    )
    u = sp.Symbol("u", positive=True)
    quad = sp.Poly(sp.expand(h.subs(c1, 0)).subs(T, sp.sqrt(u)), u)
    kq, beta, const = quad.all_coeffs()
    root_stable = 2 * sp.pi**2 / (beta + sp.sqrt(beta**2 - 4 * kq * const))
    T_c0 = w(
        "contact_duration_undamped",
        sp.sqrt(root_stable),
        "With c₁ = 0, h = k·T⁴ + β·T² − π² (quadratic in T²): the fixed point in closed form, "
        "written without cancellation for small k: T² = 2π²/(β + √(β² + 4kπ²)).",
        "31 (c₁ = 0)",
    )
    board.check(
        "c₁ = 0: closed form solves h = 0",
        "31",
        sp.simplify(quad.as_expr().subs(u, root_stable)) == 0
        and sp.simplify(const + sp.pi**2) == 0,
    )
    newton_step = w(
        "contact_duration_newton_step",
        sp.Max(T - h / sp.diff(h, T), T / 2),
        "Newton's step on h: T ← T − h(T)/h′(T), never below T/2.  The cut matters: for T < 0 "
        "the factor exp(−λc₁T/m) grows, so h has a spurious negative root that a full step "
        "from the c₁ = 0 value can jump to.",
        "31",
    )
    closed = []
    for m_val in ("0.15", "0.20", "0.25"):
        subs = {**table1_inputs(m_val), lam: lam_derived}
        with mp.workdps(30):
            exact = mp.mpf(str(sp.N(T_c0.subs(lam, lam_derived).subs(subs), 30)))
            closed.append(abs(exact - table1[(m_val, "derived")][-1]) < 1e-25)
    with mp.workdps(30):  # c₁ > 0: Newton's limit is the iteration's limit
        subs = {m: sp.Rational(1, 4), a: 155300, b: sp.Rational("83.6"), c1: 5}
        subs.update({Zd0: sp.Rational(3, 10), R: -4, lam: lam_derived})
        it_map = sp.lambdify(T, T_map.subs(lam, lam_derived).subs(subs), "mpmath")
        nt_map = sp.lambdify(T, newton_step.subs(lam, lam_derived).subs(subs), "mpmath")
        x_it = x_nt = mp.mpf(str(sp.N(T0.subs(lam, lam_derived).subs(subs), 30)))
        for _ in range(200):
            x_it = it_map(x_it)
        x_nt = mp.mpf(str(sp.N(T_c0.subs(lam, lam_derived).subs(subs), 30)))
        for _ in range(30):
            x_nt = nt_map(x_nt)
        closed.append(abs(x_it - x_nt) < 1e-25)
    board.check(
        "closed form (c₁ = 0) and Newton (c₁ = 5) equal the iteration's limit",
        "31",
        all(closed),
        "Table 1 inputs; and m = 0.25, c₁ = 5 N s/m, Ż₀ = 0.3 m/s, B/A = −4 (30 digits)",
    )

    # --- kernels ------------------------------------------------------------------------------------
    aT = Arg(T, "s", "Current contact-duration iterate T⁽ⁱ⁻¹⁾", 1e-3, 1.0, log=True)
    am = Arg(m, "kg", "Impact mass m", 0.05, 5.0, log=True)
    aa = Arg(a, "N/m^3", "Cubic coefficient a", 1e2, 1e9, log=True)
    ab = Arg(b, "N/m", "Linear coefficient b", 1.0, 1e5, log=True)
    ac = Arg(c1, "N s/m", "Contact damping c₁", 0.0, 5.0)
    az = Arg(Zd0, "m/s", "Relative approach speed Ż₀ at contact onset", 1e-3, 1.0, log=True)
    # The impact mode is the root of Eq. 12 with the larger |B/A|: out of phase (B/A < 0; −M/m
    # for two free bodies) when the contact is stiffer than the main spring, in phase (B/A > 1,
    # since its ω² < K/M) when it is softer. The check points sample the out-of-phase side.
    aR = Arg(R, "1", "Amplitude ratio B/A (Eq. 13) of the impact mode: < 0 out of phase, > 1 in "
             "phase", -20.0, -0.1)  # fmt: skip
    at = Arg(t, "s", "Time since contact onset", 0.0, 0.5)
    aO = Arg(Om, "rad/s", "Contact angular frequency Ω (= π/T_CD)", 1.0, 1e3, log=True)
    # Back to physical time and coefficients: η = μt, μκ₁ = λc₁/m, μκ₂ = λa/m.
    z_t = sp.expand(z_sol.subs(N, N_sol).subs({xi: Om * t, eta: mu * t}).subs(physical))
    board.check("μ cancels from z(t)", "32", mu not in z_t.free_symbols)
    for suffix, lam_v, printed in (("", lam_derived, False), ("_printed", lam_printed, True)):
        s = {lam: lam_v}
        board.kernel(
            name=f"contact_duration_map{suffix}",
            args=(aT, am, aa, ab, ac, az, aR),
            expr=T_map.subs(s),
            returns="Next contact-duration iterate T⁽ⁱ⁾",
            unit="s",
            equation="31",
            lhs=r"T_{CD}^{(i)}",
            printed=printed,
        )
        board.kernel(
            name=f"contact_duration_start{suffix}",
            args=(am, ab, aR),
            expr=(T0_printed if printed else T0).subs(s),
            returns="Starting contact duration T⁽⁰⁾",
            unit="s",
            equation="31",
            lhs=r"T_{CD}^{(0)}",
            printed=printed,
        )
        board.fixed_point(
            name=f"contact_duration{suffix}",
            args=(am, aa, ab, ac, az, aR),
            iterate=T,
            start=(T0_printed if printed else T0).subs(s),
            step=T_map.subs(s),
            returns="Contact duration T_CD, Eq. 31 iterated from T⁽⁰⁾ to convergence",
            unit="s",
            equation="31",
            lhs=r"T_{CD}",
            note="The fixed point of the map `contact_duration_map"
            + suffix
            + "` started at `contact_duration_start"
            + suffix
            + "`.",
            printed=printed,
        )
        if not printed:
            board.fixed_point(
                name="contact_duration_newton",
                args=(am, aa, ab, ac, az, aR),
                iterate=T,
                start=T_c0.subs(s),
                step=newton_step.subs(s),
                returns="Contact duration T_CD, the fixed point of Eq. 31 by Newton's method",
                unit="s",
                equation="31",
                lhs=r"T_{CD}",
                note="A fixed point of Eq. 31, found as the root of h(T) = T²·D(T) − π² by "
                "Newton's method from the closed form with c₁ = 0: a few steps instead of tens, "
                "and it converges also where the iteration of Eq. 31 oscillates (strong "
                "nonlinearity).  Where Eq. 31 has two positive fixed points (a strong cubic term "
                "with strong contact damping) it finds the shorter one, and `contact_duration` "
                "may find the other: the documentation's kernel page says where.",
            )
        board.kernel(
            name=f"relative_displacement{suffix}",
            args=(at, aO, am, aa, ac, az, aR),
            expr=z_t.subs(s),
            returns="Relative displacement z = y − x during contact",
            unit="m",
            magnitude=Zd0 / Om * (1 + a * Zd0**2 / (m * Om**4) * abs(R)),
            equation="32",
            lhs="z(t)",
            printed=printed,
        )
        board.kernel(
            name=f"relative_velocity{suffix}",
            args=(at, aO, am, aa, ac, az, aR),
            expr=sp.diff(z_t, t).subs(s),
            returns="Relative velocity ż = ẏ − ẋ during contact (time derivative of Eq. 32)",
            unit="m/s",
            magnitude=(Zd0 + c1 * Zd0 / (m * Om) * abs(R - 1) / abs(R))
            * (1 + a * Zd0**2 / (m * Om**4) * abs(R)),
            equation="32",
            lhs=r"\dot{z}(t)",
            printed=printed,
        )
        board.kernel(
            name=f"main_mass_displacement_contact{suffix}",
            args=(at, aO, am, aa, ac, az, aR),
            expr=(z_t / (R - 1)).subs(s),
            returns="Main-mass displacement x = z/(B/A − 1) during contact",
            unit="m",
            magnitude=Zd0 / Om * (1 + a * Zd0**2 / (m * Om**4) * abs(R)) / abs(R - 1),
            equation="33",
            lhs="x(t)",
            printed=printed,
        )
    return board
