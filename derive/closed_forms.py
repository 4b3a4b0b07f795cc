r"""Step 6 — closed-form contact durations for comparison: Hertz (Eq. 34) and linear (Eq. 35).

Both treat the contact as two free bodies, i.e. one body of reduced mass μ = mM/(m + M)
(K* = 1/μ in the paper) on the relative coordinate z, starting at z = 0 with ż = Ż₀.

* Hertz: $\mu\ddot z + K_{Hz} z^{3/2} = 0$.  Energy gives
  $\dot z^2 = \dot Z_0^2 - \frac{4K_{Hz}}{5\mu} z^{5/2}$; the contact lasts twice the time to the
  largest penetration $z_m = (5\mu\dot Z_0^2/(4K_{Hz}))^{2/5}$:
  $T = 2\frac{z_m}{\dot Z_0}\int_0^1 (1 - u^{5/2})^{-1/2}\,du
  = \frac45 B(\tfrac25, \tfrac12)\,\frac{z_m}{\dot Z_0}$.  The constant
  $\frac45 B(\tfrac25, \tfrac12) = 4\sqrt\pi\,\Gamma(\tfrac25)/(5\Gamma(\tfrac{9}{10}))$
  = 2.943275…; the paper prints 2.9432 (truncated).
* Linear: $\mu\ddot z + c_1\dot z + k_1 z = 0$ gives
  $z = (\dot Z_0/\omega_d)\,e^{-c_1 t/(2\mu)} \sin\omega_d t$; z returns to zero at
  $T = \pi/\omega_d$, which is Eq. 35.  The restitution coefficient is
  $-\dot z(T)/\dot Z_0 = \exp(-c_1 T/(2\mu))$.
"""

from __future__ import annotations

import mpmath as mp
import sympy as sp

from .board import Arg, Board


def derive() -> Board:
    board = Board("closed_forms", "Hertz and linear contact durations", "34–35")
    w = board.write
    t = sp.Symbol("t", nonnegative=True)
    m, M, k_hz, k1, v = sp.symbols("m M k_hz k1 zdot0", positive=True)
    c1 = sp.Symbol("c1", nonnegative=True)
    mu = w("reduced_mass", m * M / (m + M), "Reduced mass μ = 1/K*.", "34")
    z, zm, u = sp.symbols("z z_m u", positive=True)

    # --- Hertz ----------------------------------------------------------------------------------
    energy = w(
        "hertz_energy",
        sp.Eq(
            mu * v**2 / 2,
            mu * sp.Symbol("zdot") ** 2 / 2
            + sp.integrate(k_hz * z ** sp.Rational(3, 2), (z, 0, z)),
        ),
        "Energy conservation during the Hertz contact.",
        "34",
    )
    z_max = w(
        "hertz_max_penetration",
        sp.solve(energy.subs(sp.Symbol("zdot"), 0).subs(z, zm), zm)[0],
        "Largest penetration (ż = 0).",
        "34",
    )
    shape_integral = w(
        "shape_integral",
        sp.Integral((1 - u ** sp.Rational(5, 2)) ** sp.Rational(-1, 2), (u, 0, 1)),
        r"Time to $z_m$ is $(z_m/\dot Z_0)\int_0^1 (1 - u^{5/2})^{-1/2}\,du$, $u = z/z_m$.",
    )
    s = sp.Symbol("s", positive=True)
    # u = s^{2/5}: du = (2/5) s^{-3/5} ds turns it into Euler's Beta integral B(2/5, 1/2).
    u_of_s = s ** sp.Rational(2, 5)
    substituted = w(
        "beta_integrand",
        sp.powsimp(shape_integral.function.subs(u, u_of_s) * sp.diff(u_of_s, s), force=True),
        r"Integrand after $u = s^{2/5}$: $\frac25 s^{2/5 - 1}(1 - s)^{1/2 - 1}$.",
    )
    board.check(
        "substitution gives Euler's Beta integrand",
        "34",
        sp.simplify(
            substituted
            - sp.Rational(2, 5) * s ** sp.Rational(-3, 5) * (1 - s) ** sp.Rational(-1, 2)
        )
        == 0,
    )
    constant = w(
        "hertz_constant",
        sp.gammasimp(
            2 * sp.Rational(2, 5) * sp.beta(sp.Rational(2, 5), sp.Rational(1, 2)).rewrite(sp.gamma)
        ),
        r"$2\int_0^1 (1 - u^{5/2})^{-1/2}\,du = \frac45 B(\tfrac25, \tfrac12)$ in Gamma functions.",
        "34",
    )
    with mp.workdps(30):
        quad = 2 * mp.quad(lambda x: (1 - x ** mp.mpf(2.5)) ** -0.5, [0, mp.mpf(1) / 2, 1])
    board.check(
        "Hertz constant = (4/5)B(2/5,1/2) (quadrature)",
        "34",
        float(abs(sp.N(constant, 30) - sp.Float(mp.nstr(quad, 30), 30))) < 1e-15,
        f"{sp.N(constant, 20)} (quadrature {mp.nstr(quad, 20)})",
    )
    T_hertz = w("hertz_contact_duration", constant * z_max / v, "Hertz contact duration.", "34")
    Kstar = (m + M) / (m * M)
    printed34 = (
        sp.Rational("2.9432")
        / v ** sp.Rational(1, 5)
        * (sp.Rational(5, 4) / (Kstar * k_hz)) ** sp.Rational(2, 5)
    )
    ratio = sp.simplify(T_hertz / printed34)
    board.check(
        "Eq. 34 form (up to the constant)",
        "34",
        ratio.is_number,
        f"derived/printed = {sp.N(ratio, 10)}",
    )
    board.erratum(
        key="eq34_constant",
        equation="34",
        what="Hertz constant truncated",
        printed=sp.Rational("2.9432"),
        derived=constant,
        consequence=f"2.9432 is {sp.N(constant, 12)} truncated (rounding gives 2.9433): "
        f"Hertz durations {sp.N((constant / sp.Rational('2.9432') - 1) * 1e6, 3)} ppm short",
    )
    board.check("Eq. 34 constant 2.9432", "34", True, "truncated", erratum=True)

    # --- linear ---------------------------------------------------------------------------------
    zf = sp.Function("z")
    sol = sp.dsolve(
        mu * zf(t).diff(t, 2) + c1 * zf(t).diff(t) + k1 * zf(t),
        zf(t),
        ics={zf(0): 0, zf(t).diff(t).subs(t, 0): v},
    ).rhs
    wd = sp.Symbol("omega_d", positive=True)
    wd_value = w(
        "linear_damped_frequency",
        sp.sqrt(k1 / mu - c1**2 / (4 * mu**2)),
        "Damped frequency of the linear contact.",
        "35",
    )
    z_lin = w(
        "linear_contact_motion",
        v / wd * sp.exp(-c1 * t / (2 * mu)) * sp.sin(wd * t),
        "Relative motion during a linear contact.",
        "35",
    )
    diffs = [
        sp.N(
            (sol - z_lin.subs(wd, wd_value)).subs(
                {t: sp.Rational(tt, 100), m: sp.Rational(1, 4), M: 1, k1: 120, c1: cc, v: 1}
            ),
            30,
        )
        for tt in (3, 7, 19)
        for cc in (0, sp.Rational(1, 2), 2)
    ]
    board.check(
        "dsolve agrees with the damped-sine form",
        "35",
        max(abs(sp.re(d)) + abs(sp.im(d)) for d in diffs) < 1e-25,
    )
    T_lin = w(
        "linear_contact_duration",
        sp.pi / wd_value,
        r"First return of z to 0: $\omega_d T = \pi$.",
        "35",
    )
    printed35 = 2 * m * M * sp.pi / (sp.sqrt(m + M) * sp.sqrt(4 * m * M * k1 - c1**2 * (m + M)))
    board.check("Eq. 35", "35", sp.simplify(T_lin - printed35) == 0)
    e_lin = w(
        "linear_restitution",
        sp.simplify(-(sp.diff(z_lin, t).subs(t, sp.pi / wd)) / v),
        "Coefficient of restitution −ż(T)/Ż₀.",
        "35",
    )
    e_lin = e_lin.subs(wd, wd_value)

    # --- kernels ----------------------------------------------------------------------------------
    am = Arg(m, "kg", "Impact mass m", 0.01, 5.0, log=True)
    aM = Arg(M, "kg", "Main mass M", 0.05, 50.0, log=True)
    av = Arg(v, "m/s", "Relative approach speed Ż₀", 1e-3, 10.0, log=True)
    ahz = Arg(k_hz, "N/m^1.5", "Hertz contact stiffness K_Hz", 10.0, 1e10, log=True)
    ak1 = Arg(k1, "N/m", "Linear contact stiffness k₁", 10.0, 1e7, log=True)
    ac1 = Arg(c1, "N s/m", "Contact damping c₁ (below critical)", 0.0, 0.5)
    underdamped = 4 * m * M * k1 - c1**2 * (m + M) > 0
    hertz = board.kernel(
        name="hertz_contact_duration",
        args=(am, aM, ahz, av),
        expr=T_hertz,
        returns="Hertz contact duration",
        unit="s",
        equation="34",
        lhs=r"T_{CD}^{(Hertz)}",
    )
    board.kernel(
        name="hertz_contact_duration_printed",
        args=(am, aM, ahz, av),
        expr=printed34,
        returns="Hertz contact duration with the printed constant 2.9432",
        unit="s",
        equation="34",
        lhs=r"T_{CD}^{(Hertz)}",
        printed=True,
    )
    board.kernel(
        name="hertz_max_penetration",
        args=(am, aM, ahz, av),
        expr=z_max,
        returns="Largest Hertz penetration",
        unit="m",
        equation="34",
        lhs="z_m",
    )
    linear = board.kernel(
        name="linear_contact_duration",
        args=(am, aM, ak1, ac1),
        expr=T_lin,
        returns="Linear damped contact duration",
        unit="s",
        equation="35",
        lhs=r"T_{CD}^{(Linear)}",
        constraints=(underdamped,),
    )
    board.kernel(
        name="linear_restitution",
        args=(am, aM, ak1, ac1),
        expr=e_lin,
        returns="Coefficient of restitution of the linear damped contact",
        unit="1",
        equation="35",
        lhs="e",
        constraints=(underdamped,),
    )
    # The durations' sensitivities to every argument (sympy.diff).
    for k, wrt in ((hertz, ("m", "M", "k_hz", hertz.args[3].name)),
                   (linear, ("m", "M", "k1", "c1"))):  # fmt: skip
        board.bundle(f"{k.name}_and_derivatives", [k, *board.derivatives(k, wrt)],
                     f"{k.returns} and its derivatives in {', '.join(wrt)}")  # fmt: skip
    return board
