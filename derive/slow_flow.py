r"""Step 12 — the 1:1 slow flow of a vibro-impact absorber.

Beyond the paper.  Steps 8–10 solve the rigid-impact motion exactly; a designer first wants the
rougher picture that the vibro-impact absorber literature draws, and that the open MATLAB tool CC
(tobiaswdm/CC) codes by hand: near the primary's resonance, with a light impact mass, the primary
moves harmonically and the impact mass bounces between the walls twice per period at a constant
speed, so its displacement is a triangle wave.  Two impact conditions then tie the triangle's
amplitude Θ·d/2 and phase lag Δ to the primary's amplitude ξ·d/2; the triangle's first harmonic
is the force the absorber puts on the primary; and a single complex equation gives the
frequency-response surface, its backbone and the clearance that makes the primary's resonance
peak smallest.

Assumptions, stated where they are used: the impact mass is light (m ≪ M: an impact does not
change the primary's velocity), and the primary's motion is one harmonic (light damping and
forcing near its resonance filter the triangle's higher harmonics).  Tests measure the slow
flow against Step 10's exact orbit as m/M grows.
"""

from __future__ import annotations

import sympy as sp

from .board import Arg, Board
from .periodic_orbit import _rounding_scale


def derive() -> Board:
    board = Board("slow_flow", "The 1:1 slow flow of a vibro-impact absorber", "F5")
    w = board.write
    M, K, m, W, d = sp.symbols("M K m Omega d", positive=True)
    C, e = sp.symbols("C e", nonnegative=True)
    F0, Xb = sp.symbols("F0 X_b", real=True)
    xi, Theta = sp.symbols("xi Theta", positive=True)
    Delta, tau, t = sp.symbols("Delta tau t", real=True)
    k = sp.Symbol("k", positive=True, integer=True)
    h = d / 2

    # --- the triangle wave and its Fourier series ------------------------------------------
    tri = w(
        "triangle_wave",
        sp.Piecewise((1 + 2 * tau / sp.pi, tau < 0), (1 - 2 * tau / sp.pi, True)),
        r"A triangle wave of unit amplitude, peak at τ = 0, on −π ≤ τ ≤ π (period 2π): the "
        "impact mass at constant speed between two walls.",
        "F5",
    )
    # even in τ: the cosine coefficients are twice the integral over the half 0..π
    coefficient = sp.simplify(
        2 / sp.pi * sp.integrate((1 - 2 * tau / sp.pi) * sp.cos(k * tau), (tau, 0, sp.pi))
    )
    coefficient = w(
        "triangle_cosine_coefficient",
        sp.simplify(coefficient.rewrite(sp.cos)),
        "Its cosine coefficients (it is even, so it has no sine terms).",
        "F5",
    )
    a1 = sp.simplify(coefficient.subs(k, 1))
    board.check(
        "coefficients 8/(π²k²) for odd k, none for even k; the first is 8/π²",
        "F5",
        all(
            sp.simplify(coefficient.subs(k, kk) - (8 / (sp.pi**2 * kk**2) if kk % 2 else 0)) == 0
            for kk in range(1, 8)
        )
        and sp.simplify(a1 - 8 / sp.pi**2) == 0
        and sp.integrate(1 - 2 * tau / sp.pi, (tau, 0, sp.pi)) == 0,
    )
    j = sp.Symbol("j", integer=True, nonnegative=True)
    board.check(
        "the series adds up to the peak: Σ 8/(π²(2j + 1)²) = 1",
        "F5",
        sp.simplify(sp.summation(8 / (sp.pi**2 * (2 * j + 1) ** 2), (j, 0, sp.oo)) - 1) == 0,
    )
    w("first_harmonic", a1, "The first harmonic's share of the triangle's amplitude.", "F5")

    # --- the ansatz and the impact conditions ----------------------------------------------
    x = xi * h * sp.cos(W * t)
    rising = Theta * h * (1 + 2 * (W * t - Delta) / sp.pi)  # just before the impact at Ωt = Δ
    falling = Theta * h * (1 - 2 * (W * t - Delta) / sp.pi)  # just after it
    w(
        "ansatz",
        [sp.Eq(sp.Symbol("x"), x), sp.Eq(sp.Symbol("y"), Theta * h * tri.subs(tau, W * t - Delta))],
        r"The primary moves harmonically with amplitude ξ·d/2; the impact mass is a triangle wave "
        r"of amplitude Θ·d/2 whose peaks lag the primary's by Δ.  Both change sign over half a "
        r"period, so the second impact (on the other wall) repeats the first one negated.",
        "F5",
    )
    t_i = Delta / W
    v = sp.diff(rising, t)
    board.check(
        "between impacts the impact mass moves at the speed 2Θ(d/2)Ω/π, reversed at each impact",
        "F5",
        sp.simplify(v - 2 * Theta * h * W / sp.pi) == 0
        and sp.simplify(sp.diff(falling, t) + v) == 0,
    )
    cD, sD = sp.symbols("c_Delta s_Delta", real=True)
    on_trig = {sp.cos(Delta): cD, sp.sin(Delta): sD}
    geometric = sp.Eq((rising - x).subs(t, t_i).subs(on_trig), h)
    # m ≪ M: the primary's velocity is the same before and after the impact
    newton = sp.Eq(
        (sp.diff(falling, t) - sp.diff(x, t)).subs(t, t_i),
        -e * (sp.diff(rising, t) - sp.diff(x, t)).subs(t, t_i),
    ).subs(on_trig)
    w(
        "impact_conditions",
        [geometric, newton],
        r"At Ωt = Δ the impact mass reaches the wall y − x = d/2, and Newton's law (Step 9) "
        r"reverses its relative velocity; with m ≪ M the primary's velocity is unchanged.",
        "F5",
    )
    trig = sp.solve([geometric, newton], [cD, sD], dict=True)[0]
    rho = sp.Symbol("rho", nonnegative=True)
    rho_value = w(
        "rho",
        sp.factor(sp.simplify(trig[sD] * xi / Theta)),
        r"ρ: the conditions give ξ·cos Δ = Θ − 1 and ξ·sin Δ = ρ·Θ with this ρ.",
        "F5",
    )
    board.check(
        "ξ·cos Δ = Θ − 1, ξ·sin Δ = ρΘ with ρ = (2/π)(1 − e)/(1 + e)",
        "F5",
        sp.simplify(trig[cD] * xi - (Theta - 1)) == 0
        and sp.simplify(rho_value - 2 * (1 - e) / (sp.pi * (1 + e))) == 0,
    )
    circle = sp.expand((Theta - 1) ** 2 + rho**2 * Theta**2 - xi**2)
    w(
        "amplitude_relation",
        sp.Eq(xi**2, (Theta - 1) ** 2 + rho**2 * Theta**2),
        "cos²Δ + sin²Δ = 1 eliminates the phase lag.",
        "F5",
    )
    roots = sp.solve(circle, Theta)
    upper = max(roots, key=lambda r: r.subs({xi: 2, rho: sp.Rational(1, 3)}))
    Theta_of_xi = w(
        "absorber_amplitude_ratio",
        upper,
        r"Θ(ξ), the larger root (the other one, smaller than 1/(1 + ρ²), is the branch the "
        r"literature and CC discard; the runtime checks both against the walls).",
        "F5",
    )
    threshold = w(
        "activation_amplitude_ratio",
        rho / sp.sqrt(1 + rho**2),
        r"The roots are real only above this ξ: below it the primary moves too little for the "
        r"impact mass to reach the walls twice per period.",
        "F5",
    )
    board.check(
        "at the threshold the roots meet at Θ = 1/(1 + ρ²); at e = 1 (ρ = 0) Θ = 1 + ξ",
        "F5",
        all(sp.simplify(r.subs(xi, threshold) - 1 / (1 + rho**2)) == 0 for r in roots)
        and sp.simplify(Theta_of_xi.subs(rho, 0) - (1 + xi)) == 0,
    )

    # --- harmonic balance on the primary ---------------------------------------------------
    P = F0 + K * Xb
    Q = -C * W * Xb
    # M ẍ + m ÿ + C ẋ + K x = P cos(Ωt + ψ) + Q sin(Ωt + ψ): the momentum of the pair (the
    # contact force is internal); in complex amplitudes (e^{iΩt}), ŷ = a1·Θ·(d/2)·e^{−iΔ}
    e_minus = (Theta - 1) / xi - sp.I * rho * Theta / xi
    residual = (K - M * W**2 + sp.I * C * W) * xi * h - m * W**2 * a1 * Theta * h * e_minus
    re_part, im_part = (sp.expand(v_) for v_ in residual.as_real_imag())
    w(
        "harmonic_balance",
        sp.Eq(re_part**2 + im_part**2, P**2 + Q**2),
        r"First harmonics of M ẍ + m ÿ + C ẋ + K x = P cos(Ωt + ψ) + Q sin(Ωt + ψ) (the "
        r"contact force is internal); the forcing phase ψ drops out of the moduli.  The "
        r"triangle's higher harmonics are dropped: the primary is assumed harmonic.",
        "F5",
    )
    # the same parts times ξ/(d/2), kept factored: expanded, (K − MΩ²)² would cancel near
    # the resonance
    re_s = (K - M * W**2) * xi**2 - m * W**2 * a1 * Theta * (Theta - 1)
    im_s = C * W * xi**2 + m * W**2 * a1 * rho * Theta**2
    board.check(
        "the balance's parts times ξ/(d/2): (K − MΩ²)ξ² − (8/π²)mΩ²Θ(Θ − 1) and "
        "CΩξ² + (8/π²)mΩ²ρΘ²",
        "F5",
        sp.simplify(re_part * xi / h - re_s) == 0 and sp.simplify(im_part * xi / h - im_s) == 0,
    )
    clearance = w(
        "clearance_for_response",
        2 * xi * sp.sqrt(P**2 + Q**2) / sp.sqrt(re_s**2 + im_s**2),
        r"The frequency-response surface: the clearance d for which the primary's amplitude is "
        r"ξ·d/2 at the frequency Ω.",
        "F5",
    )
    board.check(
        "without the impact mass (m = 0) it is the linear response: ξ·d/2 = √(P² + Q²)/|K − MΩ² "
        "+ iCΩ|",
        "F5",
        sp.simplify(
            (xi * clearance / 2).subs(m, 0)
            - sp.sqrt(P**2 + Q**2) / sp.sqrt((K - M * W**2) ** 2 + (C * W) ** 2)
        )
        == 0,
    )
    # at a fixed clearance: a quartic in Θ (multiply by ξ², then ξ² = (Θ−1)² + ρ²Θ²)
    xi2 = (Theta - 1) ** 2 + rho**2 * Theta**2
    quartic_expr = sp.expand((h * re_s) ** 2 + (h * im_s) ** 2 - (P**2 + Q**2) * xi**2)
    quartic_expr = sp.expand(quartic_expr.subs(xi**2, xi2).subs(xi**4, xi2**2))
    quartic = sp.Poly(quartic_expr, Theta)
    board.check(
        "at a fixed clearance the balance is a quartic in Θ (all responses at once)",
        "F5",
        quartic.degree() == 4 and xi not in quartic_expr.free_symbols,
    )
    # its coefficients from the two parts as quadratics in Θ, with K − MΩ² and CΩ kept whole
    # (expanded, K² − 2KMΩ² + M²Ω⁴ would cancel near the resonance)
    Ar, Bi, c8 = sp.symbols("A_r B_i c_8", real=True)
    whole = {Ar: K - M * W**2, Bi: C * W, c8: m * W**2 * a1}
    re_q = sp.Poly(sp.expand(Ar * xi2 - c8 * Theta * (Theta - 1)), Theta).all_coeffs()
    im_q = sp.Poly(sp.expand(Bi * xi2 + c8 * rho * Theta**2), Theta).all_coeffs()
    F2 = P**2 + Q**2
    coefficients = [
        h**2 * (re_q[0] ** 2 + im_q[0] ** 2),
        h**2 * 2 * (re_q[0] * re_q[1] + im_q[0] * im_q[1]),
        h**2 * (re_q[1] ** 2 + 2 * re_q[0] * re_q[2] + im_q[1] ** 2 + 2 * im_q[0] * im_q[2])
        - F2 * (1 + rho**2),
        h**2 * 2 * (re_q[1] * re_q[2] + im_q[1] * im_q[2]) + 2 * F2,
        h**2 * (re_q[2] ** 2 + im_q[2] ** 2) - F2,
    ]
    board.check(
        "written from the parts as quadratics in Θ, the coefficients are the quartic's",
        "F5",
        all(
            sp.expand(c_.subs(whole) - q_) == 0
            for c_, q_ in zip(coefficients, quartic.all_coeffs(), strict=True)
        ),
    )
    w(
        "response_quartic",
        sp.Eq(sum(sp.factor(c_) * Theta ** (4 - i) for i, c_ in enumerate(coefficients)), 0),
        r"Its roots Θ (real, with the ξ they give through the amplitude relation) are the "
        r"slow flow's responses at Ω.",
        "F5",
    )
    # --- the backbone and the best clearance -------------------------------------------------
    Wb2 = sp.solve(sp.Eq(re_s, 0), W**2)
    (backbone_sq,) = [sp.simplify(s_) for s_ in Wb2 if s_ != 0]
    backbone_sq = w(
        "backbone_frequency_squared",
        sp.factor(backbone_sq),
        r"The backbone: the frequency where the balance's real part vanishes (the primary's "
        r"stiffness against the inertia of both masses).",
        "F5",
    )
    board.check(
        "without the impact mass the backbone is the primary's natural frequency K/M",
        "F5",
        sp.simplify(backbone_sq.subs(m, 0) - K / M) == 0,
    )
    Wb = sp.sqrt(backbone_sq)
    backbone_clear = 2 * xi * sp.sqrt(P**2 + Q**2) / im_s
    backbone_clear = w(
        "backbone_clearance",
        backbone_clear.subs(W, Wb),
        r"On the backbone only the imaginary part is left: the clearance for which the "
        r"primary's amplitude at the peak is ξ·d/2.  Its largest value over ξ is the best "
        r"clearance: a larger one leaves the absorber inactive at the resonance.",
        "F5",
    )

    # --- kernels --------------------------------------------------------------------------------
    on_rho = {rho: rho_value}
    aM = Arg(M, "kg", "Main mass M", 0.2, 20.0, log=True)
    aK = Arg(K, "N/m", "Main stiffness K", 100.0, 1e5, log=True)
    aC = Arg(C, "N s/m", "Main damping C (underdamped)", 0.0, 0.5)
    am = Arg(m, "kg", "Impact mass m", 1e-3, 0.2, log=True)
    ae = Arg(e, "1", "Coefficient of restitution e", 0.0, 1.0)
    ad = Arg(d, "m", "Total clearance d", 1e-4, 5e-2, log=True)
    aF = Arg(F0, "N", "Force amplitude F0 on the main mass", -10.0, 10.0)
    aXb = Arg(Xb, "m", "Base-motion amplitude X_b", -1e-2, 1e-2)
    aW = Arg(W, "rad/s", "Forcing frequency Ω", 1.0, 300.0, log=True)
    axi = Arg(xi, "1", "Primary amplitude over half the clearance ξ", 0.05, 100.0, log=True)
    above = (sp.StrictGreaterThan(xi, threshold.subs(on_rho)),)
    board.kernel(
        name="rho",
        args=(ae,),
        expr=rho_value,
        returns="The slow flow's dissipation number ρ = (2/π)(1 − e)/(1 + e)",
        unit="1",
        equation="F5",
        lhs=r"\rho",
    )
    board.kernel(
        name="activation_amplitude_ratio",
        args=(ae,),
        expr=threshold.subs(on_rho),
        returns="Smallest primary amplitude, over half the clearance, that keeps two impacts "
        "per period",
        unit="1",
        equation="F5",
        lhs=r"\xi_a",
    )
    board.kernel(
        name="absorber_amplitude_ratio",
        args=(ae, axi),
        expr=Theta_of_xi.subs(on_rho),
        returns="Impact-mass amplitude over half the clearance Θ at the primary's ξ",
        unit="1",
        equation="F5",
        lhs=r"\Theta",
        constraints=above,
    )
    board.kernel(
        name="absorber_phase_lag",
        args=(ae, axi),
        expr=sp.atan2(rho * Theta_of_xi, Theta_of_xi - 1).subs(on_rho),
        returns="Phase lag Δ of the impact mass's triangle wave behind the primary",
        unit="rad",
        equation="F5",
        lhs=r"\Delta",
        constraints=above,
    )
    on_theta = {Theta: Theta_of_xi}
    surface = board.kernel(
        name="clearance_for_response",
        args=(aM, aK, aC, am, ae, aF, aXb, aW, axi),
        expr=clearance.subs(on_theta).subs(on_rho),
        returns="Clearance d at which the primary's amplitude is ξ·d/2 at Ω (the response surface)",
        unit="m",
        equation="F5",
        lhs="d",
        constraints=above,
    )
    # the response surface's slopes in every argument (sympy.diff)
    board.bundle(
        "clearance_for_response_and_derivatives",
        [surface, *board.derivatives(surface, tuple(a.name for a in surface.args))],
        "The clearance on the response surface and its slopes in every argument",
    )
    for i, c_ in enumerate(coefficients):
        c_ = c_.subs(whole)
        board.kernel(
            name=f"response_quartic_{4 - i}",
            args=(aM, aK, aC, am, ae, ad, aF, aXb, aW),
            expr=c_.subs(on_rho),
            magnitude=_rounding_scale(sp.expand(c_)).subs(on_rho),
            returns=f"Coefficient of Θ to the power {4 - i} in the response quartic at a fixed "
            "clearance",
            unit="N^2",
            equation="F5",
            lhs=f"q_{4 - i}",
        )
    board.kernel(
        name="backbone_frequency",
        args=(aM, aK, am, ae, axi),
        expr=Wb.subs(on_theta).subs(on_rho),
        returns="Backbone frequency at the primary's ξ",
        unit="rad/s",
        equation="F5",
        lhs=r"\Omega_b",
        constraints=above,
    )
    board.kernel(
        name="backbone_clearance",
        args=(aM, aK, aC, am, ae, aF, aXb, axi),
        expr=backbone_clear.subs(on_theta).subs(on_rho),
        returns="Clearance whose resonance peak (on the backbone) is ξ·d/2",
        unit="m",
        equation="F5",
        lhs=r"d_b",
        constraints=above,
    )
    return board
