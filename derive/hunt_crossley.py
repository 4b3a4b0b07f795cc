r"""Step 11 — the Hunt–Crossley contact: its exact coefficient of restitution.

Beyond the paper.  The paper's contact laws add a Kelvin–Voigt dashpot c1·δ̇ to the elastic force.
Hunt and Crossley (J. Appl. Mech. 1975) made the damping grow with the penetration instead,
$F = K\,\delta^{n}(1 + \chi\dot\delta)$, with n = 3/2 for Hertz's law.  Between two bodies of reduced
mass μ = mM/(m + M) (Step 6) that meet at the relative speed v₀, the contact is
$\mu\ddot\delta = -F$.  Because the damping carries the same power of δ as the spring, the motion
in the phase plane (δ̇ against δ) separates, and the whole impact can be solved: the speed at
separation gives the coefficient of restitution e exactly, as a function of the single number
z = χ·v₀, through Lambert's W.  Hunt–Crossley's own χ = 3(1 − e)/(2v₀) and Lankarani–Nikravesh's
χ = 3(1 − e²)/(4v₀) are the first terms of its expansion; we compute how far they are off.

The same phase plane gives the largest penetration, the force along the contact, the peak force
and the contact duration (as an integral, Hertz's $2.94\,\delta_{max}/v_0$ at χ = 0).  Finally we state where
the paper's Kelvin–Voigt law pulls the bodies together (a tensile contact force), which the
Hunt–Crossley law never does.
"""

from __future__ import annotations

import mpmath as mp
import sympy as sp
from sympy.codegen.cfunctions import log1p

from .board import Arg, Board

#: Below this value of z = χ·v₀ the kernels use the power series (12 terms: their truncation error
#: is below 1e-17 there); above it the logarithms, whose difference has lost at most eps/z.
SERIES_BELOW = sp.Rational(1, 20)
#: Above this z the restitution is (1 − exp(−R))/z to double precision (w < 1e-13, Newton's steps
#: would need 1 − ez, which rounds to zero).
LARGE_ABOVE = 30
ORDER = 12


def _series_coefficients(g, z, order: int) -> list[sp.Rational]:
    """e(z) = 1 + Σ a_k z^k from g(−e·z) = g(z), solved order by order."""
    a = sp.symbols(f"a1:{order + 1}")
    e_series = 1 + sum(a[i] * z ** (i + 1) for i in range(order))
    residual = sp.expand(sp.series(g(-e_series * z) - g(z), z, 0, order + 3).removeO())
    solved: dict[sp.Symbol, sp.Expr] = {}
    for k in range(order):
        coefficient = residual.coeff(z, k + 3).subs(solved)
        solved[a[k]] = sp.solve(coefficient, a[k])[0]
    return [solved[a[k]] for k in range(order)]


def derive() -> Board:
    board = Board("hunt_crossley", "The Hunt–Crossley contact: exact restitution", "F4")
    w = board.write
    mu, K, chi, v0, n = sp.symbols("mu K_Hz chi v0 n", positive=True)
    delta = sp.Symbol("delta", nonnegative=True)
    v, vv = sp.symbols("v vv", real=True)
    z, e = sp.symbols("z e", positive=True)
    s = sp.Symbol("s", real=True)  # the rate of penetration over v₀: from 1 down to −e

    w(
        "hunt_crossley_force",
        sp.Eq(sp.Symbol("F"), K * delta**n * (1 + chi * v)),
        r"The Hunt–Crossley law, with $v = \dot\delta$ the rate of penetration.",
        "F4",
    )
    # --- the phase plane: μ v dv/dδ = −K δⁿ (1 + χv) separates ------------------------------------
    w(
        "phase_plane",
        sp.Eq(v / (1 + chi * v) * sp.Symbol("dv"), -K / mu * delta**n * sp.Symbol("ddelta")),
        r"$\mu\ddot\delta = \mu v\,dv/d\delta = -F$, divided by $\mu(1 + \chi v)$.",
        "F4",
    )
    left = sp.integrate(vv / (1 + chi * vv), (vv, v0, v))
    right = sp.integrate(-K / mu * sp.Symbol("dd") ** n, (sp.Symbol("dd"), 0, delta))
    orbit = w(
        "phase_orbit",
        sp.Eq(sp.simplify(left), right),
        r"Integrated from the touch-down (δ = 0, v = v₀) to a point of the contact.",
        "F4",
    )
    g = lambda p: p - sp.log(1 + p)  # noqa: E731
    board.check(
        "the left side is (g(χv) − g(χv₀))/χ² with g(p) = p − ln(1 + p)",
        "F4",
        sp.simplify(orbit.lhs - (g(chi * v) - g(chi * v0)) / chi**2) == 0,
    )
    # --- separation: δ = 0 again at v = −e·v₀ -------------------------------------------------
    exit_condition = w(
        "restitution_condition",
        sp.Eq(g(-e * z), g(z)),
        r"At separation δ = 0 again, so the left side vanishes at v = −e·v₀; with z = χv₀.",
        "F4",
    )
    board.check(
        "the restitution depends on z = χv₀ alone: not on K, μ, the exponent n or v₀ apart",
        "F4",
        sp.simplify(orbit.lhs.subs(v, -e * v0) * chi**2 - (g(-e * z) - g(z)).subs(z, chi * v0)) == 0
        and exit_condition.free_symbols == {e, z},
    )
    W_, R = sp.symbols("w R", positive=True)
    (w_root,) = sp.solve(sp.Eq(W_ - sp.log(W_), R), W_)
    w(
        "restitution_in_w",
        sp.Eq(W_ - sp.log(W_), 1 + z - sp.log(1 + z)),
        r"With w = 1 − e·z ∈ (0, 1) the condition reads w − ln w = R, R = 1 + z − ln(1 + z).",
        "F4",
    )
    closed = w(
        "restitution_lambert_w",
        (1 + sp.LambertW(-(1 + z) * sp.exp(-(1 + z)))) / z,
        r"So $w e^{-w} = e^{-R}$, $w = -W_0(-e^{-R})$: Lambert's W on its principal branch "
        r"(the other branch gives w = 1 + z, the touch-down itself).",
        "F4",
    )
    board.check(
        "sympy's root of w − ln w = R is −W(−exp(−R)), and −exp(−R) = −(1 + z)·exp(−(1 + z))",
        "F4",
        sp.simplify(w_root + sp.LambertW(-sp.exp(-R))) == 0
        and sp.simplify(sp.exp(-(1 + z - sp.log(1 + z))) - (1 + z) * sp.exp(-(1 + z))) == 0,
    )
    points = ("1/1000", "1/10", "1/2", "1", "3", "10", "30")
    closed_e = sp.lambdify(z, closed, "mpmath")  # mpmath's lambertw: the principal branch
    with mp.workdps(50):
        residuals, in_range = [], True
        for text in points:
            zv = mp.mpf(sp.Rational(text).p) / sp.Rational(text).q
            ev = mp.re(closed_e(zv))
            gz = lambda p: p - mp.log1p(p)  # noqa: E731
            residuals.append(abs(gz(-ev * zv) - gz(zv)) / gz(zv))
            in_range &= bool(0 < ev < 1 and 0 < 1 - ev * zv < 1)
    board.check(
        "the Lambert-W form satisfies the condition at z = " + ", ".join(points) + " (50 digits)",
        "F4",
        max(residuals) < mp.mpf(10) ** -40 and in_range,
        detail=f"largest relative residual {mp.nstr(max(residuals), 3)} (50 digits, of which "
        "g ≈ z²/2 cancels 7 at z = 1/1000); 0 < e < 1 and 0 < w < 1",
    )
    # --- the expansion in z, and the published approximations -------------------------------------
    coefficients = _series_coefficients(g, z, ORDER)
    series = w(
        "restitution_series",
        1 + sum(c * z ** (k + 1) for k, c in enumerate(coefficients)),
        r"The condition solved order by order for e = 1 + a₁z + a₂z² + … (12 terms).",
        "F4",
    )
    with mp.workdps(50):
        zs = mp.mpf(SERIES_BELOW.p) / SERIES_BELOW.q
        exact = (1 + mp.lambertw(-(1 + zs) * mp.exp(-(1 + zs)), 0).real) / zs
        truncation = abs(sp.lambdify(z, series, "mpmath")(zs) - exact) / exact
    board.check(
        f"the 12-term series equals the Lambert-W form to 1e-17 for z ≤ {SERIES_BELOW}",
        "F4",
        truncation < mp.mpf(10) ** -17,
        detail=f"relative difference {mp.nstr(truncation, 3)} at z = {SERIES_BELOW}",
    )
    e_hc = w(
        "hunt_crossley_approximation",
        1 - sp.Rational(2, 3) * z,
        r"Hunt–Crossley's χ = 3(1 − e)/(2v₀), solved for e.",
        "F4",
    )
    e_ln = w(
        "lankarani_nikravesh_approximation",
        sp.sqrt(1 - sp.Rational(4, 3) * z),
        r"Lankarani–Nikravesh's χ = 3(1 − e²)/(4v₀), solved for e.",
        "F4",
    )
    hc_error = w(
        "hunt_crossley_error",
        sp.series(series - e_hc, z, 0, 3).removeO(),
        r"The exact e minus Hunt–Crossley's: it is the series cut after its first term.",
        "F4",
    )
    ln_error = w(
        "lankarani_nikravesh_error",
        sp.series(series - e_ln, z, 0, 3).removeO(),
        r"The exact e minus Lankarani–Nikravesh's: their first terms agree too.",
        "F4",
    )
    board.check(
        "both approximations are exact to first order in z; the errors start at 4z²/9 (HC) "
        "and 2z²/3 (LN): Hunt–Crossley's own χ is the closer of the two",
        "F4",
        sp.simplify(hc_error - sp.Rational(4, 9) * z**2) == 0
        and sp.simplify(ln_error - sp.Rational(2, 3) * z**2) == 0,
    )
    # --- never tensile ------------------------------------------------------------------------
    board.check(
        "the force K δⁿ(1 + χv) ≥ 0 throughout: v ≥ −e·v₀ during the contact, so "
        "1 + χv ≥ 1 − e·z = w > 0 (the principal branch of W lies in (−1, 0))",
        "F4",
        in_range,
    )
    # --- Kelvin–Voigt: where the paper's damping pulls ----------------------------------------
    k1, c1, t = sp.symbols("k1 c1 t", positive=True)
    wd = sp.sqrt(k1 / mu - c1**2 / (4 * mu**2))
    d_lin = v0 / wd * sp.exp(-c1 * t / (2 * mu)) * sp.sin(wd * t)
    board.check(
        "δ = (v₀/ωd)·exp(−c₁t/(2μ))·sin(ωd·t) solves μδ̈ + c₁δ̇ + k₁δ = 0 from δ = 0, δ̇ = v₀",
        "35",
        sp.simplify(mu * d_lin.diff(t, 2) + c1 * d_lin.diff(t) + k1 * d_lin) == 0
        and d_lin.subs(t, 0) == 0
        and sp.simplify(d_lin.diff(t).subs(t, 0) - v0) == 0,
    )
    force_lin = sp.simplify((k1 * d_lin + c1 * d_lin.diff(t)) * wd / v0 * sp.exp(c1 * t / (2 * mu)))
    w(
        "kelvin_voigt_force",
        force_lin,
        r"The force k₁δ + c₁δ̇ of the linear law (Step 6), times the positive factor "
        r"$(\omega_d/v_0)e^{c_1t/(2\mu)}$: it turns negative (tensile) before δ returns to zero.",
        "35",
    )
    w(
        "kelvin_voigt_tensile_fraction",
        sp.atan2(c1 * wd, k1 - c1**2 / (2 * mu)) / sp.pi,
        r"The share of the contact time ($T = \pi/\omega_d$) during which it pulls: from "
        r"$\tan\omega_d t = -c_1\omega_d/(k_1 - c_1^2/(2\mu))$.",
        "35",
    )
    L = sp.Symbol("L", positive=True)  # L = −ln e
    c1_of_e = 2 * L * sp.sqrt(k1 * mu) / sp.sqrt(sp.pi**2 + L**2)  # Step 9
    tan_fraction = sp.simplify((c1 * wd / (k1 - c1**2 / (2 * mu))).subs(c1, c1_of_e))
    w(
        "kelvin_voigt_tensile_fraction_of_e",
        2 * sp.atan(-sp.log(e) / sp.pi) / sp.pi,
        r"With c₁ set for a restitution e (Step 9) the share depends on e alone.",
        "35",
    )
    board.check(
        "with Step 9's c₁: tan(π·share) = 2Lπ/(π² − L²) = tan(2·atan(L/π)), L = −ln e",
        "35",
        sp.simplify(tan_fraction - 2 * L * sp.pi / (sp.pi**2 - L**2)) == 0
        and sp.simplify(
            sp.expand_trig(sp.tan(2 * sp.atan(L / sp.pi))) - 2 * L * sp.pi / (sp.pi**2 - L**2)
        )
        == 0,
    )
    board.check(
        "the paper's Kelvin–Voigt laws (any elastic part f(δ) with f(0) = 0, plus c₁δ̇) end "
        "every contact pulling: at separation the force is c₁·(−e·v₀) < 0",
        "10",
        sp.simplify(force_lin.subs(t, sp.pi / wd) + c1 * wd) == 0,
    )
    # --- the Hertz exponent: penetration, force, peak, duration -----------------------------------
    h = sp.Function("h")
    w(
        "h_function",
        sp.Eq(h(z), g(z) / z**2),
        r"With n = 3/2 we scale the phase orbit by v₀²: $h(p) = g(p)/p^2$, h(0) = 1/2.",
        "F4",
    )
    D = sp.Symbol("D")  # δ^{5/2}
    penetration_orbit = sp.solve(
        sp.Eq(orbit.lhs.subs(v, s * v0), orbit.rhs.subs(n, sp.Rational(3, 2))).subs(
            delta, D ** sp.Rational(2, 5)
        ),
        D,
    )[0]
    h_of = lambda p: g(p) / p**2  # noqa: E731
    penetration = w(
        "penetration_at_speed",
        (sp.Rational(5, 2) * mu * v0**2 / K * (h_of(z) - s**2 * h_of(z * s))) ** sp.Rational(2, 5),
        r"δ when the rate of penetration is v = s·v₀ (s from 1 down to −e).",
        "F4",
    )
    board.check(
        "δ²·√δ from the phase orbit equals (5μv₀²/(2K))·(h(z) − s²·h(zs))",
        "F4",
        sp.simplify(
            penetration_orbit.subs(chi, z / v0)
            - sp.Rational(5, 2) * mu * v0**2 / K * (h_of(z) - s**2 * h_of(z * s))
        )
        == 0,
    )
    hertz_max = (sp.Rational(5, 4) * mu * v0**2 / K) ** sp.Rational(2, 5)
    board.check(
        "at χ = 0 the largest penetration (s = 0) is Hertz's: the 2/5 power of 5μv₀²/(4K) (Step 6)",
        "34",
        sp.simplify(sp.limit(penetration.subs(s, 0), z, 0) - hertz_max) == 0,
    )
    force_s = w(
        "force_at_speed",
        K * penetration ** sp.Rational(3, 2) * (1 + z * s),
        r"The contact force at the same point.",
        "F4",
    )
    peak = w(
        "peak_force_condition",
        sp.Eq(5 * z * (h_of(z) - s**2 * h_of(z * s)), 3 * s),
        r"dF/ds = 0: the force peaks during the compression (s > 0), earlier than at the "
        r"largest penetration (s = 0); at χ = 0 the two coincide.",
        "F4",
    )
    log_slope = sp.diff(sp.log(force_s), s)
    board.check(
        "d(ln F)/ds = (z − 3s/(5(h(z) − s²h(zs))))/(1 + zs): zero exactly on the peak condition",
        "F4",
        sp.simplify(
            sp.expand_log(log_slope, force=True) * 5 * (1 + z * s) * (h_of(z) - s**2 * h_of(z * s))
            - (peak.lhs - peak.rhs)
        )
        == 0,
    )
    w(
        "contact_duration_integral",
        sp.Integral(mu * v0 / force_s, (s, -e, 1)),
        r"dt = dv/δ̈ = −μ·dv/F with dv = v₀·ds: the contact lasts this long; the integrand "
        r"is singular like $(1-s)^{-3/5}$ and $(s+e)^{-3/5}$ at the ends, which integrate.",
        "F4",
    )
    hertz_constant = sp.Rational(4, 5) * sp.beta(sp.Rational(1, 2), sp.Rational(2, 5))
    board.check(
        "at χ = 0 it is (4/5)·B(1/2, 2/5)·δmax/v₀ = 2.9432·δmax/v₀, Hertz's duration (Step 6)",
        "34",
        abs(
            float(sp.Integral((1 / (1 - s**2) ** sp.Rational(3, 5)), (s, -1, 1)).evalf(30)) * 4 / 5
            - float(hertz_constant.evalf(30))
        )
        < 1e-12
        and abs(float(hertz_constant.evalf(30)) - 2.9432) < 1e-4,
        detail=f"(4/5)·B(1/2, 2/5) = {float(hertz_constant.evalf(20)):.10f}",
    )

    # --- kernels -------------------------------------------------------------------------------
    def h_kernel(p):
        """h(p) = (p − log1p(p))/p², by its series where the difference would cancel."""
        h_series = sum((-1) ** k * p ** (k - 2) / k for k in range(2, ORDER + 3))
        # the formula's p² is floored at the threshold²: equal on its branch, and finite (not
        # 0/0) where compiled code evaluates both branches before choosing
        return sp.Piecewise(
            (h_series, sp.Abs(p) < SERIES_BELOW),
            ((p - log1p(p)) / sp.Max(p**2, SERIES_BELOW**2), True),
        )

    m, M = sp.symbols("m M", positive=True)
    mu_mM = m * M / (m + M)
    am = Arg(m, "kg", "Impact mass m", 1e-3, 1.0, log=True)
    aM = Arg(M, "kg", "Main mass M", 0.05, 50.0, log=True)
    aK = Arg(K, "N/m^1.5", "Hertz stiffness", 1e3, 1e10, log=True)
    achi = Arg(chi, "s/m", "Hunt–Crossley damping χ", 1e-4, 10.0, log=True)
    av0 = Arg(v0, "m/s", "Approach speed v₀", 1e-3, 3.0, log=True)
    as_ = Arg(s, "1", "Rate of penetration as a fraction s of v₀ (−e ≤ s ≤ 1)", -0.9, 1.0)
    zz = chi * v0
    g_emit = lambda p: p - log1p(p)  # noqa: E731
    e_it = sp.Symbol("e", positive=True)
    series_e = series.subs(z, zz)
    large_e = (1 - sp.exp(-(1 + g_emit(zz)))) / sp.Max(zz, SERIES_BELOW)  # = zz on its branch
    newton = e_it - (g_emit(-e_it * zz) - g_emit(zz)) * (1 - e_it * zz) / (e_it * zz**2)
    board.fixed_point(
        name="hunt_crossley_restitution",
        args=(achi, av0),
        iterate=e_it,
        start=sp.Piecewise((series_e, zz < SERIES_BELOW), (large_e, True)),
        step=sp.Piecewise(
            (series_e, zz < SERIES_BELOW), (large_e, zz > LARGE_ABOVE), (newton, True)
        ),
        returns="Coefficient of restitution of the Hunt–Crossley contact (exact, any exponent n)",
        unit="1",
        equation="F4",
        lhs="e",
        tol=1e-12,
        max_iter=60,
        note="The root of g(−e·z) = g(z), z = χv₀ (the closed form is Lambert's W): the 12-term "
        f"series below z = {SERIES_BELOW}, (1 − exp(−R))/z above z = {LARGE_ABOVE}, Newton's "
        "method from that upper bound in between (monotone: g(−ez) is convex in e).",
    )
    h_z = h_kernel(zz)
    board.kernel(
        name="max_penetration",
        args=(am, aM, aK, achi, av0),
        expr=(sp.Rational(5, 2) * mu_mM * v0**2 / K * h_z) ** sp.Rational(2, 5),
        returns="Largest penetration of the Hunt–Crossley contact (n = 3/2)",
        unit="m",
        equation="F4",
        lhs=r"\delta_{max}",
    )
    pen = (sp.Rational(5, 2) * mu_mM * v0**2 / K * (h_z - s**2 * h_kernel(zz * s))) ** sp.Rational(
        2, 5
    )
    board.kernel(
        name="penetration_at_speed",
        args=(as_, am, aM, aK, achi, av0),
        expr=pen,
        returns="Penetration δ when the rate of penetration is s·v₀ (n = 3/2)",
        unit="m",
        equation="F4",
        lhs=r"\delta(s)",
        # z < 1 and s above −(1 − 2z/3), which lies below −e (the exact e exceeds Hunt–Crossley's
        # 1 − 2z/3 there: the error series starts at +4z²/9)
        constraints=(sp.StrictLessThan(zz, 1), sp.StrictGreaterThan(s, -1 + 2 * zz / 3)),
    )
    board.kernel(
        name="force_at_speed",
        args=(as_, am, aM, aK, achi, av0),
        expr=K * pen ** sp.Rational(3, 2) * (1 + zz * s),
        returns="Contact force when the rate of penetration is s·v₀ (n = 3/2)",
        unit="N",
        equation="F4",
        lhs="F(s)",
        # z < 1 and s above −(1 − 2z/3), which lies below −e (the exact e exceeds Hunt–Crossley's
        # 1 − 2z/3 there: the error series starts at +4z²/9)
        constraints=(sp.StrictLessThan(zz, 1), sp.StrictGreaterThan(s, -1 + 2 * zz / 3)),
    )
    # --- the duration's integrand, free of cancellation at both ends ---------------------------
    # P(s) = h(z) − s²h(zs) vanishes at s = 1 and s = −e; written from each end it needs no
    # difference of nearly equal numbers: from the touch-down, r = (1 − s)/(1 + zs) and
    # P = r²h(zr) + r·s; from the separation, ρ = (s + e)/(1 − ez) and P = ρe − ρ²h(zρ).
    r_top = (1 - s) / (1 + z * s)
    rho = (s + e) / (1 - e * z)
    P_exact = h_of(z) - s**2 * h_of(z * s)
    P_top = r_top**2 * h_of(z * r_top) + r_top * s
    P_bottom = rho * e - rho**2 * h_of(z * rho)
    on_exit = {s: -e}
    with mp.workdps(40):
        worst = mp.mpf(0)
        for zv, sv in ((sp.Rational(1, 5), sp.Rational(-1, 3)), (1, sp.Rational(1, 2)),
                       (3, sp.Rational(-1, 10))):  # fmt: skip
            e_v = mp.re(closed_e(mp.mpf(zv)))
            vals = {z: zv, s: sv}
            ref = sp.lambdify(e, P_exact.subs(vals), "mpmath")(e_v)
            for form in (P_top, P_bottom):
                got = sp.lambdify(e, form.subs(vals), "mpmath")(e_v)
                worst = max(worst, abs(got - ref) / abs(ref))
    board.check(
        "written from the touch-down and from the separation, P(s) is the same function "
        "(z = 1/5, 1, 3 at 40 digits, e the root of the restitution condition)",
        "F4",
        worst < mp.mpf(10) ** -30
        and sp.simplify(P_top.subs(s, 1)) == 0
        and sp.simplify(P_bottom.subs(on_exit)) == 0,
        detail=f"largest relative difference {mp.nstr(worst, 3)}",
    )
    w(
        "duration_integrand_regular_part",
        sp.Piecewise(
            (1 / ((1 + z * s) * (s + e)) * (r_top * h(z * r_top) + s), s >= 0),
            ((e - rho * h(z * rho)) / ((1 - e * z) * (1 - s)), True),
        ),
        r"P(s)/((1 − s)(s + e)): finite at both ends (1/((1 + z)(1 + e)) and e/((1 − ez)(1 + e))), "
        r"so the duration is a weight $((1-s)(s+e))^{-3/5}$ times a smooth function.",
        "F4",
    )
    ratio_top = (r_top * h_kernel(zz * r_top.subs(z, zz)) + s) / ((1 + zz * s) * (s + e))
    ratio_bottom = (e - rho.subs(z, zz) * h_kernel(zz * rho.subs(z, zz))) / ((1 - e * zz) * (1 - s))
    ratio = sp.Piecewise((ratio_top.subs(z, zz), s >= 0), (ratio_bottom, True))
    board.kernel(
        name="duration_density",
        args=(
            as_,
            Arg(e, "1", "Coefficient of restitution e (from hunt_crossley_restitution)", 0.1, 1.0),
            am,
            aM,
            aK,
            achi,
            av0,
        ),
        expr=mu_mM
        * v0
        / (K * (sp.Rational(5, 2) * mu_mM * v0**2 / K) ** sp.Rational(3, 5))
        / (ratio ** sp.Rational(3, 5) * (1 + zz * s)),
        returns="μv₀/F(s) times the 3/5 power of (1 − s)(s + e): the contact duration is its "
        "integral over s ∈ [−e, 1] against the weight ((1 − s)(s + e)) to the power −3/5",
        unit="s",
        equation="F4",
        lhs=r"\tau(s)",
        # z < 1, s above −(1 − 2z/3) and e above Hunt–Crossley's 1 − 2z/3: a point of a contact
        constraints=(
            sp.StrictLessThan(zz, 1),
            sp.StrictGreaterThan(s, -1 + 2 * zz / 3),
            sp.StrictGreaterThan(e, 1 - 2 * zz / 3),
        ),
    )
    s_it = sp.Symbol("s", real=True)
    peak_residual = 5 * zz * (h_z - s_it**2 * h_kernel(zz * s_it)) - 3 * s_it
    peak_slope = -5 * zz * s_it / (1 + zz * s_it) - 3
    board.fixed_point(
        name="hunt_crossley_peak_speed_ratio",
        args=(achi, av0),
        iterate=s_it,
        start=5 * zz * h_z / 3,
        step=s_it - peak_residual / peak_slope,
        returns="Rate of penetration, as a fraction of v₀, at which the contact force peaks",
        unit="1",
        equation="F4",
        lhs="s^*",
        tol=1e-13,
        max_iter=60,
        note="Newton's method on 5z(h(z) − s²h(zs)) = 3s from s = 5z·h(z)/3, above the root "
        "(the residual is concave and decreasing in s, so the steps fall monotonically).",
    )
    board.kernel(
        name="kelvin_voigt_tensile_fraction",
        args=(Arg(e, "1", "Coefficient of restitution e of the linear law", 0.01, 1.0),),
        expr=2 * sp.atan(-sp.log(e) / sp.pi) / sp.pi,
        returns="Share of the contact time during which the linear Kelvin–Voigt law pulls",
        unit="1",
        equation="F4",
        lhs=r"t_{tensile}/T",
    )
    return board
