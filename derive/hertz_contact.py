r"""Step 13 — the contact from materials and geometry: Hertz's stiffness, the impact it gives, the
onset of yield and the restitution of an elastic–plastic impact.

Beyond the paper.  The paper takes $K_{Hz}$ = 1000 N/m<sup>1.5</sup> as given: a resilient,
rubber-like contact.  A designer knows the ball and the cavity instead — their materials (E, ν,
yield strength Y) and radii.  Hertz's theory turns these into the contact law.

*The board.*  Two smooth bodies touch at a point; near it their gap is $r^2/(2R)$, with
$1/R = 1/R_1 + 1/R_2$ (a concave surface, the inside of a spherical cavity, has a negative radius;
a flat has $1/R_2 = 0$).  Hertz's pressure $p = p_0\sqrt{1 - r^2/a^2}$ on a circle of radius a
displaces the surface of an elastic half-space by
$u(r) = \frac{1-\nu^2}{E}\frac{\pi p_0}{4a}(2a^2 - r^2)$ inside the circle (the Boussinesq
integral of this pressure: typed in from Johnson, *Contact Mechanics* (1985), Eq. 3.41, and
checked below by integrating Boussinesq's point-load solution).  Both bodies displace; the sum must
close the gap to the approach δ everywhere on the circle.  Matching the constant and the $r^2$
terms gives a, $p_0$ and the force, and with them $K_{Hz} = \tfrac43 E^*\sqrt R$.

The impact of two bodies of reduced mass μ at speed $v_0$ follows from energy (largest penetration,
peak force) and one integral (duration; Hertz's 2.94 δ<sub>max</sub>/v₀); the penetration and the
duration are the paper's Eq. 34 (Step 6's kernels, which the runtime uses), re-derived here to show
where Hertz's constants come from.  The stresses on the axis
under the Hertz pressure (Johnson Eq. 3.45, checked by integrating the point-load stresses) give
where yield starts: von Mises' $\sigma_r - \sigma_z$ peaks below the surface, at $p_0 = 1.60\,Y$ for
ν = 0.3.  Past that speed, Thornton's elastic–perfectly-plastic contact (J. Appl. Mech. 64, 1997)
caps the pressure at $p_y$: the force grows linearly, and the unloading is Hertzian about a flatter
radius.  Its energy balance gives the coefficient of restitution as a function of $v_0/v_y$ alone;
we derive it and compare it with Thornton's printed closed form.
"""

from __future__ import annotations

import mpmath as mp
import sympy as sp

from .board import Arg, Board


def _boussinesq_displacement(nu, p0, a, r):
    """u(r) of the half-space (E = 1) under p₀√(1 − s²/a²), by quadrature of the point-load
    solution (1 − ν²)/(π E ρ) in polar coordinates about the field point (no singularity left)."""

    def inner(theta):
        # distance from (r, 0) along direction theta to the circle's edge
        c = r * mp.cos(theta)
        rho_max = -c + mp.sqrt(c**2 - (r**2 - a**2))
        return mp.quad(
            lambda rho: (
                p0
                * mp.sqrt(
                    max(
                        mp.mpf(0),
                        1 - (r**2 + rho**2 + 2 * r * rho * mp.cos(theta)) / a**2,
                    )
                )
            ),
            [0, rho_max],
        )

    return (1 - nu**2) / mp.pi * mp.quad(inner, [0, mp.pi, 2 * mp.pi])


def _axis_stresses_by_quadrature(nu, zeta):
    """(σ_r, σ_z)/p₀ on the axis at depth ζ = z/a, from Boussinesq's point-load stresses summed
    over the Hertz pressure (a = p₀ = 1): on the axis σ_r = σ_θ = ½ of the point loads' σ_r + σ_θ
    about each load."""

    def pressure(s):
        return mp.sqrt(1 - s**2)

    def sz(s):
        rho = mp.sqrt(s**2 + zeta**2)
        return -3 * zeta**3 / (2 * mp.pi * rho**5)

    def sr_plus_st(s):
        rho = mp.sqrt(s**2 + zeta**2)
        return (-3 * zeta * s**2 / rho**5 + (1 - 2 * nu) * zeta / rho**3) / (2 * mp.pi)

    sigma_z = mp.quad(lambda s: pressure(s) * sz(s) * 2 * mp.pi * s, [0, 1])
    sigma_r = mp.quad(lambda s: pressure(s) * sr_plus_st(s) * 2 * mp.pi * s, [0, 1]) / 2
    return sigma_r, sigma_z


def derive() -> Board:
    board = Board("hertz_contact", "The contact from materials and geometry", "F5")
    w = board.write
    E1, E2, Es, R, R1, a, p0, delta = sp.symbols("E_1 E_2 E_star R R_1 a p_0 delta", positive=True)
    nu1, nu2, nu = sp.symbols("nu_1 nu_2 nu", real=True)
    kappa2 = sp.Symbol("kappa_2", real=True)
    r, s, x = sp.symbols("r s x", nonnegative=True)
    m, M, mu, v0, K = sp.symbols("m M mu v0 K_Hz", positive=True)

    # --- two half-spaces under Hertz's pressure ----------------------------------------------------
    def u(E, n):
        return (1 - n**2) / E * sp.pi * p0 / (4 * a) * (2 * a**2 - r**2)

    u_half = w(
        "half_space_displacement",
        u(sp.Symbol("E", positive=True), nu),
        r"Displacement of a half-space under $p_0\sqrt{1-r^2/a^2}$ (Johnson Eq. 3.41).",
        "F5",
    )
    with mp.workdps(20):
        errs = []
        for rv in ("0", "0.3", "0.7"):
            brute = _boussinesq_displacement(mp.mpf("0.3"), 1, 1, mp.mpf(rv))
            closed = (1 - mp.mpf("0.3") ** 2) * mp.pi / 4 * (2 - mp.mpf(rv) ** 2)
            errs.append(abs(brute - closed) / closed)
    board.check(
        "the typed displacement equals the Boussinesq integral of the pressure at r/a = 0, 0.3, 0.7",
        "F5",
        max(errs) < 1e-10,
        detail=f"largest relative difference {mp.nstr(max(errs), 3)} (quadrature, 20 digits)",
    )
    E_star = w(
        "effective_modulus",
        1 / ((1 - nu1**2) / E1 + (1 - nu2**2) / E2),
        r"Both surfaces displace: $u_1 + u_2$ has the factor $1/E^* = (1-\nu_1^2)/E_1 + "
        r"(1-\nu_2^2)/E_2$.",
        "F5",
    )
    total = sp.expand(u(E1, nu1) + u(E2, nu2))
    board.check(
        "u₁ + u₂ is one half-space of modulus E*",
        "F5",
        sp.simplify(total - u_half.subs({sp.Symbol("E", positive=True): E_star, nu: 0})) == 0,
    )
    radius = w(
        "effective_radius",
        1 / (1 / R1 + kappa2),
        r"The gap between the surfaces is $r^2/(2R)$, $1/R = 1/R_1 + \kappa_2$ ($\kappa_2 = 1/R_2$: "
        r"0 on a flat, negative in a concave cavity).",
        "F5",
    )
    # contact: u_total(r) = δ − r²/(2R) for r ≤ a, with u_total = π p₀ (2a² − r²)/(4 a E*)
    closure = sp.expand(sp.pi * p0 / (4 * a * Es) * (2 * a**2 - r**2) - (delta - r**2 / (2 * R)))
    sol = sp.solve([closure.coeff(r, 0), closure.coeff(r, 2)], [p0, delta], dict=True)[0]
    p0_a = w("peak_pressure_of_radius", sol[p0], r"The $r^2$ terms: $p_0 = 2E^*a/(\pi R)$.", "F5")
    delta_a = w("approach_of_radius", sol[delta], r"The constant terms: $\delta = a^2/R$.", "F5")
    force_a = w(
        "force_of_radius",
        sp.integrate(p0_a * sp.sqrt(1 - s**2 / a**2) * 2 * sp.pi * s, (s, 0, a)),
        r"The force is the pressure's integral over the circle.",
        "F5",
    )
    a_delta = sp.sqrt(R * delta)
    force = w(
        "hertz_force",
        sp.simplify(force_a.subs(a, a_delta)),
        r"With $a = \sqrt{R\delta}$: Hertz's law $F = \tfrac43 E^*\sqrt R\,\delta^{3/2}$.",
        "F5",
    )
    k_hz = w("hertz_stiffness", sp.Rational(4, 3) * Es * sp.sqrt(R), r"So $K_{Hz}$.", "F5")
    board.check(
        "the force is K_Hz δ^{3/2} with K_Hz = 4/3 E* √R",
        "F5",
        sp.simplify(force - k_hz * delta ** sp.Rational(3, 2)) == 0
        and sp.simplify(delta_a - a**2 / R) == 0,
    )
    p0_delta = sp.simplify(p0_a.subs(a, a_delta))

    # --- the elastic impact ------------------------------------------------------------------------
    d_max = sp.Symbol("delta_max", positive=True)
    energy = sp.integrate(K * x ** sp.Rational(3, 2), (x, 0, d_max))
    u5 = sp.Symbol("u", positive=True)  # δ_max^{5/2}
    (u_root,) = sp.solve(sp.Eq(energy.subs(d_max ** sp.Rational(5, 2), u5), mu * v0**2 / 2), u5)
    dm = w(
        "impact_max_penetration",
        u_root ** sp.Rational(2, 5),
        r"All of $\tfrac12\mu v_0^2$ is stored at the deepest point: $\tfrac25 K_{Hz}\delta_{max}^{5/2}$.",
        "F5",
    )
    # duration: 2 ∫₀^δmax dδ / v(δ), v² = v₀² (1 − (δ/δmax)^{5/2}); the integral of
    # (1 − x^{5/2})^{−1/2} over (0, 1) is (2/5) B(2/5, 1/2) (x = u^{2/5})
    beta_form = (
        sp.Rational(2, 5)
        * sp.gamma(sp.Rational(2, 5))
        * sp.sqrt(sp.pi)
        / sp.gamma(sp.Rational(9, 10))
    )
    duration_factor = w(
        "duration_factor",
        2 * beta_form,
        r"$t_c = 2\int_0^{\delta_{max}} d\delta/\dot\delta = c\,\delta_{max}/v_0$ with "
        r"$c = 2\int_0^1 (1-x^{5/2})^{-1/2}dx = \tfrac45 B(\tfrac25, \tfrac12)$.",
        "F5",
    )
    with mp.workdps(30):
        quad = 2 * mp.quad(lambda t: 1 / mp.sqrt(1 - t**2.5), [0, 1])
        factor = sp.N(duration_factor, 30)
    board.check(
        "the duration factor is the integral (quadrature) and rounds to Hertz's 2.94",
        "F5",
        abs(quad - mp.mpf(str(factor))) < mp.mpf(10) ** -15 and round(float(factor), 2) == 2.94,
        detail=f"c = {sp.N(duration_factor, 12)}; quadrature differs by "
        f"{mp.nstr(abs(quad - mp.mpf(str(factor))), 2)} (the square-root singularity at x = 1 "
        "limits tanh-sinh to about 17 digits)",
    )
    mu_mM = m * M / (m + M)
    k_of = k_hz
    board.check(
        "t_c = 2.87 (μ²/(R E*² v₀))^{1/5} (Johnson Eq. 11.24) to its three digits",
        "F5",
        round(
            float(
                sp.N(
                    sp.simplify(
                        duration_factor
                        * dm.subs(K, k_of)
                        / v0
                        / (mu**2 / (R * Es**2 * v0)) ** sp.Rational(1, 5)
                    )
                )
            ),
            2,
        )
        == 2.87,
    )

    # --- the onset of yield ------------------------------------------------------------------------
    zeta = sp.Symbol("zeta", nonnegative=True)
    sigma_z = w("axis_sigma_z", -1 / (1 + zeta**2), r"$\sigma_z/p_0$ on the axis, ζ = z/a.", "F5")
    sigma_r = w(
        "axis_sigma_r",
        -(1 + nu) * (1 - zeta * sp.atan(1 / zeta)) + 1 / (2 * (1 + zeta**2)),
        r"$\sigma_r/p_0 = \sigma_\theta/p_0$ on the axis (Johnson Eq. 3.45).",
        "F5",
    )
    with mp.workdps(20):
        errs = []
        for zv in ("0.2", "0.48", "1.5"):
            br, bz = _axis_stresses_by_quadrature(mp.mpf("0.3"), mp.mpf(zv))
            cr = sp.N(sigma_r.subs({nu: sp.Rational(3, 10), zeta: sp.Rational(zv)}), 20)
            cz = sp.N(sigma_z.subs(zeta, sp.Rational(zv)), 20)
            errs += [abs(br - mp.mpf(str(cr))), abs(bz - mp.mpf(str(cz)))]
    board.check(
        "the axis stresses equal the point-load stresses summed over the pressure (ζ = 0.2, 0.48, 1.5)",
        "F5",
        max(errs) < 1e-12,
        detail=f"largest difference {mp.nstr(max(errs), 3)} p₀",
    )
    difference = w(
        "axis_stress_difference",
        sp.simplify(sigma_r - sigma_z),
        r"Von Mises on the axis ($\sigma_r = \sigma_\theta$): $\sigma_r - \sigma_z$; yield where "
        r"its largest value reaches Y.",
        "F5",
    )
    f_diff = sp.lambdify(zeta, difference.subs(nu, sp.Rational(3, 10)), "mpmath")
    with mp.workdps(20):
        z_star = mp.findroot(lambda t: mp.diff(f_diff, t), mp.mpf("0.5"))
        ratio = 1 / f_diff(z_star)
    board.check(
        "for ν = 0.3 the largest shear τ₁ = 0.31 p₀ lies at depth 0.48a (Johnson §4.2: p₀ ≈ 1.60 Y)",
        "F5",
        round(float(z_star), 2) == 0.48 and round(float(1 / (2 * ratio)), 2) == 0.31,
        detail=f"ζ* = {mp.nstr(z_star, 6)}, p₀/Y = {mp.nstr(ratio, 6)}",
    )
    p_y = sp.Symbol("p_y", positive=True)
    (delta_y,) = sp.solve(sp.Eq(p0_delta, p_y), delta)  # p₀ ∝ √δ: one root
    delta_y = w("yield_approach", delta_y, r"The approach at which $p_0$ reaches $p_y$.", "F5")
    (v_y,) = sp.solve(sp.Eq(energy.subs(d_max, delta_y).subs(K, k_hz), mu * v0**2 / 2), v0)
    v_y = w("yield_speed", v_y, r"The impact speed that reaches it: $v_y$.", "F5")
    (v_reach,) = sp.solve(sp.Eq(energy.subs(d_max, delta), mu * v0**2 / 2), v0)
    v_reach = w(
        "speed_for_approach",
        v_reach,
        r"For any contact with the force $K_{Hz}\delta^{3/2}$ (an elliptical one too), the impact "
        r"speed whose deepest approach is δ: the energy balance read backwards.",
        "F5",
    )
    board.check(
        "the speed for the yield approach is the yield speed",
        "F5",
        sp.simplify(v_reach.subs(delta, delta_y).subs(K, k_hz) - v_y) == 0,
    )
    rho, Y = sp.symbols("rho Y", positive=True)
    johnson = sp.simplify(
        (rho * v_y**2 / Y)
        .subs(mu, sp.Rational(4, 3) * sp.pi * R**3 * rho)
        .subs(p_y, sp.Rational(8, 5) * Y)
        / (Y / Es) ** 4
    )
    board.check(
        "a sphere on a massive flat: ρv_y²/Y = 26 (Y/E*)⁴ (Johnson Eq. 11.26) to its two digits",
        "F5",
        round(float(johnson)) == 26,
        detail=f"coefficient {sp.N(johnson, 6)} (Johnson rounds to 26)",
    )

    # --- Thornton's elastic–perfectly-plastic impact -----------------------------------------------
    dy, xp = sp.symbols("delta_y x_p", positive=True)
    Fy = k_hz * dy ** sp.Rational(3, 2)
    py_of = p0_delta.subs(delta, dy)
    plastic_force = w(
        "plastic_loading_force",
        Fy + sp.pi * R * py_of * xp,
        r"Past $\delta_y$ the pressure is capped at $p_y$: the force grows by $\pi R p_y$ per unit of "
        r"the further approach $x_p = \delta - \delta_y$ (its slope continues Hertz's).",
        "F5",
    )
    board.check(
        "the plastic slope πRp_y equals Hertz's slope at δ_y",
        "F5",
        sp.simplify(
            sp.diff(plastic_force, xp)
            - sp.diff(k_hz * delta ** sp.Rational(3, 2), delta).subs(delta, dy)
        )
        == 0,
    )
    W_in = sp.Rational(2, 5) * k_hz * dy ** sp.Rational(5, 2) + sp.integrate(
        plastic_force, (xp, 0, xp)
    )
    Fm = plastic_force
    am = sp.sqrt(R * (dy + xp))
    # unloading: Hertz about a radius R_p with the same contact radius a_m and force F_m;
    # F = 4E*a³/(3R_p), δ − δ_r = a²/R_p, so the energy returned is (2/5) F_m a_m²/R_p
    Rp = 4 * Es * am**3 / (3 * Fm)
    W_out = w(
        "unloading_energy",
        sp.Rational(2, 5) * Fm * am**2 / Rp,
        r"Unloading is Hertzian about a flatter radius $R_p = 4E^*a_m^3/(3F_m)$ (same contact radius "
        r"$a_m$ and force $F_m$ at the deepest point): it returns $\tfrac25 F_m a_m^2/R_p$.",
        "F5",
    )
    # in units of δ_y: x_p = q δ_y; the ratio W_out/W_in depends on q alone; and v²/v_y² = W_in/W_y
    q, ratio_v = sp.symbols("q r_v", positive=True)
    W_y = sp.Rational(2, 5) * k_hz * dy ** sp.Rational(5, 2)
    e2 = sp.simplify((W_out / W_in).subs(xp, q * dy))
    v2 = sp.simplify((W_in / W_y).subs(xp, q * dy))
    board.check(
        "restitution and speed depend on x_p/δ_y alone (not on E*, R or p_y apart)",
        "F5",
        e2.free_symbols == {q} and v2.free_symbols == {q},
    )
    # v_y/v = r_v: solve v2(q) = 1/r_v² for q (a quadratic in q)
    q_sols = [
        qs
        for qs in sp.solve(sp.Eq(v2, 1 / ratio_v**2), q)
        if qs.subs(ratio_v, sp.Rational(1, 2)).is_positive
    ]
    (q_of_r,) = q_sols
    e_thornton = w(
        "thornton_restitution_derived",
        sp.sqrt(sp.simplify(e2.subs(q, q_of_r))),
        r"$e^2 = W_{out}/W_{in}$ with the plastic approach from $\tfrac12\mu v_0^2 = W_{in}$, "
        r"$r_v = v_y/v_0 \le 1$.",
        "F5",
    )
    printed = (
        sp.sqrt(6 * sp.sqrt(3) / 5)
        * sp.sqrt(1 - ratio_v**2 / 6)
        * (ratio_v / (ratio_v + 2 * sp.sqrt(sp.Rational(6, 5) - ratio_v**2 / 5)))
        ** sp.Rational(1, 4)
    )
    w(
        "thornton_restitution_printed",
        printed,
        r"Thornton's printed closed form (J. Appl. Mech. 64, 1997, Eq. 33).",
        "F5",
    )
    with mp.workdps(30):
        f_d = sp.lambdify(ratio_v, e_thornton, "mpmath")
        f_p = sp.lambdify(ratio_v, printed, "mpmath")
        diffs = [abs(f_d(mp.mpf(t)) - f_p(mp.mpf(t))) for t in ("0.01", "0.1", "0.5", "0.9", "1")]
    board.check(
        "the derived restitution equals Thornton's printed form at v_y/v₀ = 0.01, 0.1, 0.5, 0.9, 1",
        "F5",
        max(diffs) < mp.mpf(10) ** -25 and abs(f_d(mp.mpf(1)) - 1) < mp.mpf(10) ** -25,
        detail=f"largest difference {mp.nstr(max(diffs), 3)}; e = 1 at v₀ = v_y",
    )

    # --- the impact law's slope when e follows the speed (Step 9's saltation) ------------------
    # A rigid impact at approach speed w leaves at the separation speed e(w)·w.  Where e is
    # constant the velocity jumps are linear in w, and Step 9's saltation matrix holds e; where
    # e follows the speed (e = T(v_y/w) above yield) their slope in w is d(e·w)/dw = e + w·e'(w),
    # which takes e's place in the saltation's velocity entries.  With r = v_y/w,
    # w·de/dw = −r·dT/dr.
    wsp, vy = sp.symbols("w v_y", positive=True)
    slope = w(
        "thornton_separation_slope",
        sp.simplify(printed - ratio_v * sp.diff(printed, ratio_v)),
        r"$\hat e = d(e\,w)/dw = T(r_v) - r_v\,T'(r_v)$: the separation speed's slope in the "
        r"approach speed, in place of e in Step 9's saltation entries.",
        "F5",
    )
    board.check(
        "ê = d(e·w)/dw with e = T(v_y/w), written in r = v_y/w",
        "F5",
        sp.simplify(
            sp.diff(wsp * printed.subs(ratio_v, vy / wsp), wsp) - slope.subs(ratio_v, vy / wsp)
        )
        == 0,
    )
    with mp.workdps(30):
        f_s = sp.lambdify(ratio_v, slope, "mpmath")
        slopes = [f_s(mp.mpf(t)) for t in ("0.001", "0.01", "0.1", "0.5", "0.9", "1")]
    board.check(
        "ê lies in (0, 1] over 1e-3 ≤ v_y/w ≤ 1 (the separation speed grows with the approach "
        "speed, more slowly than it)",
        "F5",
        all(0 < x <= 1 for x in slopes),
        detail="ê at v_y/w = 1e-3, 0.01, 0.1, 0.5, 0.9, 1: "
        + ", ".join(mp.nstr(x, 4) for x in slopes),
    )

    # --- kernels -----------------------------------------------------------------------------------
    aE1 = Arg(E1, "Pa", "Young's modulus of body 1", 1e6, 5e11, log=True)
    anu1 = Arg(nu1, "1", "Poisson's ratio of body 1", 0.0, 0.5)
    aE2 = Arg(E2, "Pa", "Young's modulus of body 2", 1e6, 5e11, log=True)
    anu2 = Arg(nu2, "1", "Poisson's ratio of body 2", 0.0, 0.5)
    aEs = Arg(Es, "Pa", "Effective modulus E*", 1e6, 3e11, log=True)
    aR = Arg(R, "m", "Effective radius R", 1e-4, 1.0, log=True)
    aR1 = Arg(R1, "m", "Radius of the impacting sphere R₁", 1e-4, 0.2, log=True)
    akappa = Arg(
        kappa2, "1/m", "Curvature of the other surface 1/R₂ (0 flat, < 0 concave)", -4.0, 100.0
    )
    adelta = Arg(delta, "m", "Approach (penetration) δ", 1e-9, 1e-2, log=True)
    am_ = Arg(m, "kg", "Impact (ball) mass m", 1e-3, 10.0, log=True)
    aM = Arg(M, "kg", "Main mass M (the cavity's body)", 1e-2, 1e3, log=True)
    akhz = Arg(K, "N/m^1.5", "Hertz stiffness K_Hz", 1e2, 1e11, log=True)
    av0 = Arg(v0, "m/s", "Relative impact speed v₀", 1e-3, 10.0, log=True)
    apy = Arg(p_y, "Pa", "Peak pressure at first yield p_y (≈ 1.6 Y)", 1e6, 5e9, log=True)
    azeta = Arg(zeta, "1", "Depth below the surface over the contact radius, z/a", 0.01, 3.0)
    anu = Arg(nu, "1", "Poisson's ratio of the body", 0.0, 0.5)
    ar = Arg(ratio_v, "1", "Yield speed over impact speed v_y/v₀ (≤ 1)", 1e-4, 1.0, log=True)
    kernels = (
        ("effective_modulus", (aE1, anu1, aE2, anu2), E_star, "Effective modulus E*", "Pa", "E^*"),
        ("effective_radius", (aR1, akappa), radius, "Effective radius of curvature R", "m", "R"),
        (
            "hertz_stiffness",
            (aEs, aR),
            k_hz,
            "Hertz stiffness K_Hz = 4/3 E*√R",
            "N/m^1.5",
            "K_{Hz}",
        ),
        ("contact_radius", (aR, adelta), a_delta, "Contact radius a = √(Rδ)", "m", "a"),
        ("peak_pressure", (aEs, aR, adelta), p0_delta, "Peak (central) pressure p₀", "Pa", "p_0"),
        (
            "impact_peak_force",
            (am_, aM, akhz, av0),
            K * dm.subs(mu, mu_mM) ** sp.Rational(3, 2),
            "Peak force of an elastic Hertz impact",
            "N",
            "F_{max}",
        ),
        (
            "axis_stress_difference",
            (azeta, anu),
            difference,
            "(σ_r − σ_z)/p₀ on the axis under the Hertz pressure (von Mises there)",
            "1",
            r"(\sigma_r-\sigma_z)/p_0",
        ),
        (
            "yield_speed",
            (am_, aM, aEs, aR, apy),
            v_y.subs(mu, mu_mM),
            "Impact speed at which the peak pressure reaches p_y (first yield)",
            "m/s",
            "v_y",
        ),
        (
            "yield_approach",
            (aEs, aR, apy),
            delta_y,
            "Approach at which the peak pressure of a circular contact reaches p_y",
            "m",
            r"\delta_y",
        ),
        (
            "speed_for_approach",
            (am_, aM, akhz, adelta),
            v_reach.subs(mu, mu_mM),
            "Impact speed whose deepest approach is δ (any K_Hz·δ^1.5 contact)",
            "m/s",
            "v",
        ),
        (
            "thornton_restitution",
            (ar,),
            printed,
            "Coefficient of restitution of an elastic–perfectly-plastic impact (v₀ ≥ v_y)",
            "1",
            "e",
        ),
        (
            "thornton_separation_slope",
            (ar,),
            slope,
            "Slope ê = e + w·de/dw of the separation speed in the approach speed w (v₀ ≥ v_y)",
            "1",
            r"\hat{e}",
        ),
    )
    for name, args, expr, returns, unit, lhs in kernels:
        board.kernel(
            name=name, args=args, expr=expr, returns=returns, unit=unit, equation="F5", lhs=lhs
        )
    return board
