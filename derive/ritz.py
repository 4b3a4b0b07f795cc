r"""Step 1 — Ritz reduction of the cantilever to one mass and one spring (paper Eq. 1–6).

On the board:

1. Separate x(r, t) = q(t) φ(r) in $\rho A\,x_{tt} + EI\,x_{rrrr} = 0$ (Eq. 1–2): φ'''' = β⁴ φ.
2. Impose the cantilever's boundary conditions (clamped at r = 0, free at r = L) on the general
   solution; a non-trivial φ needs a zero determinant, which simplifies to the frequency equation
   cos βL cosh βL + 1 = 0 (quoted before Eq. 4).  Its null vector is the mode shape of Eq. 3.
3. Solve the frequency equation to 40 digits with mpmath for the first modes.
4. Ritz / virtual work with the displacement referred to the damper's position r₀ (the tip in the
   paper): q is the beam deflection at r₀, x = q φ(r)/φ(r₀), so the kinetic and strain energies
   give M = ρA ∫φ² dr / φ(r₀)² and K = EI ∫φ''² dr / φ(r₀)².  At the tip and for every mode
   M = ρAL/4 and $K = (\beta_i L)^4 EI/(4L^3)$; for mode 1 K = 3.0906 EI/L³ (Eq. 6).
"""

from __future__ import annotations

import mpmath as mp
import sympy as sp

from .board import Arg, Board

N_MODES = 8
DIGITS = 60  # working precision; cosh(β₈L) ≈ 1e10 costs ~20 digits in the energies


def beta_l_roots(n: int = N_MODES, dps: int = DIGITS) -> list[mp.mpf]:
    """The first ``n`` positive roots of cos(x)·cosh(x) + 1 = 0 to ``dps`` digits.

    Root i lies within 0.5 of (2i − 1)π/2 (where cos vanishes and the cosh factor is huge), so
    a bracketing solver started on that interval finds each root once and in order.
    """
    with mp.workdps(dps + 10):
        roots = []
        for i in range(1, n + 1):
            centre = (2 * i - 1) * mp.pi / 2
            root = mp.findroot(
                lambda x: mp.cos(x) * mp.cosh(x) + 1,
                (centre - mp.mpf("0.5"), centre + mp.mpf("0.5")),
                solver="anderson",
            )
            roots.append(root)
    return roots


def _by_powers(expr: sp.Expr, s: sp.Symbol) -> sp.Expr:
    """``expr`` as a polynomial in ``s``, each coefficient trigsimp-ed (the board's form)."""
    poly = sp.Poly(sp.expand(expr), s)
    return sum((sp.trigsimp(c) * s**k for (k,), c in poly.terms()), start=sp.Integer(0))


def derive() -> Board:
    board = Board("ritz", "Ritz reduction of the cantilever beam", "1–6")
    w = board.write
    r, L, t = sp.symbols("r L t", positive=True)
    beta, E, I, rho, A = sp.symbols("beta E I rho A", positive=True)
    k, xi = sp.symbols("beta_L xi", positive=True)  # k = βL, ξ = r/L

    # --- 1. separation of variables ------------------------------------------------------------
    phi = sp.Function("phi")
    q = sp.Function("q")
    pde = w(
        "pde",
        sp.Eq(rho * A * sp.diff(q(t) * phi(r), t, 2) + E * I * sp.diff(q(t) * phi(r), r, 4), 0),
        "Free transverse vibration of the uniform Euler–Bernoulli beam, x = q(t)·φ(r).",
        "1–2",
    )
    C = sp.symbols("C1:5")
    general = w(
        "general_solution",
        C[0] * sp.sin(beta * r)
        + C[1] * sp.cos(beta * r)
        + C[2] * sp.sinh(beta * r)
        + C[3] * sp.cosh(beta * r),
        "General solution of φ'''' = β⁴ φ with β⁴ = ρAω²/(EI).",
    )
    # Put x = cos(ωt)·(general solution) into Eq. 1 with β⁴ = ρAω²/(EI): the residual vanishes.
    om = sp.Symbol("omega", positive=True)
    separated = (
        pde.lhs.subs({q(t): sp.cos(om * t), phi(r): general})
        .doit()
        .subs(beta, (rho * A * om**2 / (E * I)) ** sp.Rational(1, 4))
    )
    board.check("separated solution satisfies Eq. 1", "1", sp.simplify(separated) == 0)

    # --- 2. boundary conditions → frequency equation and mode shape ----------------------------
    bcs = [
        general.subs(r, 0),  # clamped: no deflection
        sp.diff(general, r).subs(r, 0),  # clamped: no slope
        sp.diff(general, r, 2).subs(r, L),  # free: no bending moment
        sp.diff(general, r, 3).subs(r, L),  # free: no shear force
    ]
    matrix = sp.Matrix([[sp.diff(bc, c) for c in C] for bc in bcs])
    det = w(
        "boundary_determinant",
        sp.simplify(sp.trigsimp(matrix.det() / beta**6)),
        "Determinant of the boundary conditions (clamped at r = 0, free at r = L), divided by β⁶.",
    )
    frequency_equation = w(
        "frequency_equation",
        sp.Eq(sp.cos(k) * sp.cosh(k) + 1, 0),
        "A non-trivial mode needs a zero determinant: the cantilever frequency equation.",
        "4 (text)",
    )
    det_in_k = sp.simplify(det.subs(beta, k / L))
    ratio = sp.simplify(det_in_k / (frequency_equation.lhs))
    board.check(
        "frequency equation from boundary conditions",
        "4 (text)",
        ratio.is_number and ratio != 0,
        f"det/β⁶ = {ratio}·(cos βL cosh βL + 1)",
    )

    sigma = (sp.sin(k) + sp.sinh(k)) / (sp.cos(k) + sp.cosh(k))
    mode = w(
        "mode_shape",
        sp.sin(k * xi) - sp.sinh(k * xi) - sigma * (sp.cos(k * xi) - sp.cosh(k * xi)),
        "Mode shape of Eq. 3 in ξ = r/L (the null vector of the boundary matrix).",
        "3",
    )
    # Eq. 3 satisfies the two clamped conditions identically and the two free ones at the roots.
    mode_r = mode.subs({k: beta * L, xi: r / L})
    clamped = [sp.simplify(mode_r.subs(r, 0)), sp.simplify(sp.diff(mode_r, r).subs(r, 0))]
    roots = beta_l_roots()
    free_at_root = []
    with mp.workdps(DIGITS):
        for root in roots[:4]:
            for order in (2, 3):
                f = sp.lambdify((k, xi), sp.diff(mode, xi, order), "mpmath")
                free_at_root.append(abs(f(root, 1)) / root**order)
    board.check(
        "Eq. 3 meets the cantilever boundary conditions",
        "3",
        clamped == [0, 0] and max(free_at_root) < mp.mpf(10) ** (-DIGITS + 8),
        f"free-end moment/shear at the first 4 roots ≤ {mp.nstr(max(free_at_root), 3)}",
    )

    # --- 3. the roots ---------------------------------------------------------------------------
    w(
        "beta_L_roots",
        [sp.Float(mp.nstr(x, DIGITS), DIGITS) for x in roots],
        f"First {N_MODES} roots of the frequency equation to {DIGITS} digits.",
        "4 (text)",
    )
    board.check(
        "β₁L = 1.875104",
        "4 (text)",
        abs(roots[0] - mp.mpf("1.875104")) < 5e-7,
        f"β₁L = {mp.nstr(roots[0], 20)}; printed 1.875104 (rounded to 7 digits)",
    )
    board.constant(
        name="BETA_L",
        values=tuple(repr(float(x)) for x in roots),
        digits=tuple(mp.nstr(x, 25) for x in roots),
        doc=f"Roots β_i·L of cos(βL)·cosh(βL) + 1 = 0, modes 1..{N_MODES} (mpmath, {DIGITS} digits).",
    )

    # --- 4. Ritz: energies referred to the damper position ξ -----------------------------------
    s = sp.Symbol("sigma")
    mode_s = sp.sin(k * xi) - sp.sinh(k * xi) - s * (sp.cos(k * xi) - sp.cosh(k * xi))
    u = sp.Symbol("u", positive=True)
    # On the board the integrals are written as polynomials in σ (how they were computed), with
    # σ named; the values carry σ substituted, for the checks and kernels below.
    sig = {s: sigma}
    mass_in_s = sp.integrate(sp.expand(mode_s.subs(xi, u) ** 2), (u, 0, 1))
    strain_in_s = sp.integrate(sp.expand(sp.diff(mode_s, xi, 2).subs(xi, u) ** 2), (u, 0, 1))
    mass_integral = w(
        "mass_integral",
        mass_in_s.subs(s, sigma),
        r"$\int_0^1 \varphi(\xi)^2\,d\xi$: the kinetic energy of $x = q\,\varphi(\xi)/"
        r"\varphi(\xi_0)$ is $\tfrac12\rho A L\,\dot q^2\int_0^1\varphi^2 d\xi/"
        r"\varphi(\xi_0)^2$.",
        "4–5",
        shown=(mass_shown := _by_powers(mass_in_s, s)),
        names=sig,
    )
    strain_integral = w(
        "strain_integral",
        strain_in_s.subs(s, sigma),
        r"$\int_0^1 \varphi''(\xi)^2\,d\xi$: the strain energy is "
        r"$\tfrac12 (EI/L^3)\, q^2 \int_0^1 \varphi''^2 d\xi / \varphi(\xi_0)^2$.",
        "5",
        shown=(strain_shown := _by_powers(strain_in_s, s)),
        names=sig,
    )
    mass_coefficient = w(
        "mass_coefficient",
        mass_integral / mode**2,
        "Generalised mass referred to the damper at $\\xi = r_0/L$, in units of $\\rho A L$.",
        "5–6",
        shown=sp.Symbol("I_M") / sp.Symbol("varphi") ** 2,
        names={sp.Symbol("I_M"): mass_shown, sp.Symbol("varphi"): mode_s, **sig},
    )
    stiffness_coefficient = w(
        "stiffness_coefficient",
        strain_integral / mode**2,
        "Generalised stiffness referred to the damper at $\\xi = r_0/L$, in units of $EI/L^3$.",
        "5–6",
        shown=sp.Symbol("I_K") / sp.Symbol("varphi") ** 2,
        names={sp.Symbol("I_K"): strain_shown, sp.Symbol("varphi"): mode_s, **sig},
    )
    fm = sp.lambdify((k, xi), mass_coefficient, "mpmath")
    fk = sp.lambdify((k, xi), stiffness_coefficient, "mpmath")
    with mp.workdps(DIGITS):
        tip_mass = [fm(x, 1) for x in roots]
        tip_stiff = [fk(x, 1) for x in roots]
        mass_err = max(abs(v - mp.mpf(1) / 4) for v in tip_mass)
        stiff_err = max(abs(v / (x**4 / 4) - 1) for v, x in zip(tip_stiff, roots, strict=True))
    w(
        "tip_mass_coefficients",
        [sp.Float(mp.nstr(v, 20), 20) for v in tip_mass],
        "M/(ρAL) at the tip for each mode: 1/4 for every mode.",
    )
    w(
        "tip_stiffness_coefficients",
        [sp.Float(mp.nstr(v, 20), 20) for v in tip_stiff],
        r"K·L³/(EI) at the tip for each mode: $(\beta_i L)^4/4$.",
    )
    board.check(
        "M = 0.25 ρAL at the tip, every mode",
        "6",
        mass_err < mp.mpf(10) ** (-DIGITS + 25),
        f"max |M/(ρAL) − 1/4| over {N_MODES} modes = {mp.nstr(mass_err, 2)}",
    )
    board.check(
        "K = (β_iL)⁴/4 · EI/L³ at the tip, every mode",
        "6",
        stiff_err < mp.mpf(10) ** (-DIGITS + 25),
        f"strain-energy K vs β⁴-form: max rel. diff {mp.nstr(stiff_err, 2)}",
    )
    k_tip = tip_stiff[0]
    board.check(
        "K = 3.0906 EI/L³ (mode 1)",
        "6",
        abs(k_tip - mp.mpf("3.0906")) < 5e-5,
        f"K·L³/EI = {mp.nstr(k_tip, 15)}",
    )
    # --- a form for floating point --------------------------------------------------------------
    # For large βL the terms of Eq. 3 are of size cosh βL and cancel.  With σ = 1 + δσ,
    # δσ = (sin βL − cos βL − e^{−βL})/(cos βL + cosh βL), and cosh − sinh = e^{−x}, no term exceeds 2.
    dsigma = (sp.sin(k) - sp.cos(k) - sp.exp(-k)) / (sp.cos(k) + sp.cosh(k))
    mode_stable = w(
        "mode_shape_stable",
        sp.sin(k * xi) - (1 + dsigma) * sp.cos(k * xi) + sp.exp(-k * xi) + dsigma * sp.cosh(k * xi),
        "Eq. 3 rearranged without cancellation (for the kernels).",
        "3",
    )
    board.check(
        "cancellation-free form equals Eq. 3",
        "3",
        sp.simplify((mode_stable - mode).rewrite(sp.exp)) == 0,
    )
    # At a root, ∫₀¹φ² dξ = φ(1)²/4 (checked above for 8 modes, and below at interior points).
    mass_at_root = w(
        "mass_coefficient_at_root",
        (mode_stable.subs(xi, 1) / mode_stable) ** 2 / 4,
        "At a root ∫₀¹φ²dξ = φ(1)²/4, so M/(ρAL) = φ(1)²/(4φ(ξ)²): the form the kernels use.",
        "5–6",
    )
    stiff_at_root = w(
        "stiffness_coefficient_at_root",
        k**4 * mass_at_root,
        "At a root ∫₀¹φ''²dξ = (βL)⁴∫₀¹φ²dξ, so K·L³/(EI) = (βL)⁴·M/(ρAL).",
        "5–6",
    )
    fm_root = sp.lambdify((k, xi), mass_at_root, "mpmath")
    fk_root = sp.lambdify((k, xi), stiff_at_root, "mpmath")
    with mp.workdps(DIGITS):
        worst = max(
            max(abs(fm_root(x, p) / fm(x, p) - 1), abs(fk_root(x, p) / fk(x, p) - 1))
            for x in roots
            for p in (mp.mpf("0.3"), mp.mpf("0.55"), mp.mpf("0.9"), 1)
        )
    board.check(
        "root forms equal the energy integrals (8 modes, ξ = 0.3…1)",
        "5–6",
        worst < mp.mpf(10) ** (-DIGITS + 25),
        f"max rel. diff {mp.nstr(worst, 2)}",
    )

    # Orthogonality of Eq. 4 (numerical quadrature at the roots).
    with mp.workdps(30):
        f_mode = sp.lambdify((k, xi), mode, "mpmath")
        off = max(
            abs(mp.quad(lambda z, a=a, b=b: f_mode(a, z) * f_mode(b, z), [0, 1]))
            for i, a in enumerate(roots[:4])
            for b in roots[i + 1 : 4]
        )
    board.check("modes orthogonal", "4", off < 1e-20, f"max |∫φᵢφⱼ dξ| = {mp.nstr(off, 2)}")

    # --- errata ---------------------------------------------------------------------------------
    k1_exact = sp.Float(mp.nstr(roots[0] ** 4, 30), 30)
    eq6 = sp.Rational("12.362361")
    board.erratum(
        key="eq6_constant",
        equation="6",
        what="stiffness constant (β₁L)⁴",
        printed=eq6 * E * I / (4 * L**3),
        derived=k1_exact * E * I / (4 * L**3),
        consequence=(
            f"(β₁L)⁴ = {mp.nstr(roots[0] ** 4, 12)}, not 12.362361 (relative "
            f"{mp.nstr(abs(eq6 - k1_exact) / k1_exact, 2)}); the rounded K = 3.0906 EI/L³ is right"
        ),
        point={E: 1, I: 1, L: 1},
    )
    f0, k1_sym = sp.symbols("f_0 beta_1L")
    board.erratum(
        key="eq5_load_projection",
        equation="5",
        what="load projected on φ₁(L) instead of φ₁(r)",
        printed=f0 * L * mode.subs(xi, 1).subs(k, k1_sym),
        derived=f0 * L * sp.integrate(mode, (xi, 0, 1)).subs(k, k1_sym),
        consequence=(
            "notation only: ∫f(r,t)φ₁(r)dr is the generalised force; for the damper's point force "
            "at the tip it equals F·φ₁(L), which is what Eq. 6 uses. Shown for a uniform load f₀"
        ),
        point={f0: 1, L: 1, k1_sym: sp.Float(mp.nstr(roots[0], 30), 30)},
    )
    board.check("Eq. 6 constant 12.362361", "6", True, "differs from (β₁L)⁴", erratum=True)

    # --- kernels --------------------------------------------------------------------------------
    arg_k = Arg(k, "1", "Root β·L of the frequency equation (e.g. BETA_L[i])", 1.2, 8.0)
    arg_xi = Arg(xi, "1", "Damper position r₀/L along the beam (1 = tip)", 0.25, 1.0)
    board.kernel(
        name="mode_shape",
        args=(arg_k, arg_xi),
        expr=mode_stable,
        returns="Mode shape φ(ξ) of Eq. 3 at ξ = r/L",
        unit="1",
        equation="3",
        lhs=r"\phi(\xi)",
    )
    board.kernel(
        name="mass_coefficient",
        args=(arg_k, arg_xi),
        expr=mass_at_root,
        returns="Generalised mass M/(ρAL) referred to the damper position ξ",
        unit="1",
        equation="5–6",
        lhs=r"\frac{M}{\rho A L}",
        note="beta_L must be a root of the frequency equation (BETA_L). Equals 1/4 at the tip "
        "(ξ = 1) for every mode.",
    )
    board.kernel(
        name="stiffness_coefficient",
        args=(arg_k, arg_xi),
        expr=stiff_at_root,
        returns="Generalised stiffness K·L³/(EI) referred to the damper position ξ",
        unit="1",
        equation="5–6",
        lhs=r"\frac{K L^3}{E I}",
        note="beta_L must be a root of the frequency equation (BETA_L). Equals (βL)⁴/4 at the "
        "tip (ξ = 1); 3.0906 for mode 1.",
    )
    args_beam = (
        Arg(E, "Pa", "Young's modulus E", 1e9, 4e11, log=True),
        Arg(I, "m^4", "Second moment of area I", 1e-12, 1e-6, log=True),
        Arg(L, "m", "Beam length L", 0.05, 5.0, log=True),
    )
    board.kernel(
        name="tip_stiffness",
        args=args_beam,
        expr=k1_exact * E * I / (4 * L**3),
        returns="Tip-referred stiffness K of mode 1",
        unit="N/m",
        equation="6",
        lhs="K",
    )
    board.kernel(
        name="tip_stiffness_printed",
        args=args_beam,
        expr=eq6 * E * I / (4 * L**3),
        returns="Tip-referred stiffness K of mode 1 with the printed constant 12.362361",
        unit="N/m",
        equation="6",
        lhs="K",
        printed=True,
    )
    board.kernel(
        name="tip_mass",
        args=(
            Arg(rho, "kg/m^3", "Density ρ", 500.0, 20000.0, log=True),
            Arg(A, "m^2", "Cross-section area A", 1e-6, 1e-2, log=True),
            Arg(L, "m", "Beam length L", 0.05, 5.0, log=True),
        ),
        expr=rho * A * L / 4,
        returns="Tip-referred mass M of mode 1",
        unit="kg",
        equation="6",
        lhs="M",
    )
    return board
