"""Exercises of the derivation notebooks: per step, two or three changes of one assumption and
their effect, computed live.

Each exercise runs at the end of its step's notebook, where every name of the step's
``derive()`` (its symbols, intermediate results and helpers) is defined, because the notebook ran
the step's own statements.  Each prints or displays its result; the tests execute them.
"""

from __future__ import annotations

from dataclasses import dataclass

from .teach import ANSWER_RTOL


@dataclass(frozen=True)
class Exercise:
    """One exercise: ``text`` sets the scene, ``ask`` is the question, ``code`` the solution
    (hidden in the notebook), ``answer`` the expression, evaluated after the solution, that the
    reader's answer is checked against (:func:`derive.teach.check`); ``stated`` the same value as
    a textbook, the paper or an independent computation gives it (the digits it is stated to),
    with ``source``; the tests hold ``answer`` to it."""

    title: str
    text: str
    code: str
    ask: str = ""
    answer: str = ""
    stated: str | None = None
    source: str = ""
    #: How close the reader's answer must come to ``answer`` (:func:`derive.teach.check`): the
    #: default unless the solution itself is approximate (a grid's maximum).
    rtol: float = ANSWER_RTOL


EXERCISES: dict[str, tuple[Exercise, ...]] = {
    "ritz": (
        Exercise(
            "Put the damper at mid-span",
            "Refer the motion to ξ₀ = 1/2 instead of the tip: M and K change, their ratio — the "
            "frequency — does not.",
            """for where in (1, sp.Rational(1, 2)):
    Mc, Kc = fm(roots[0], where), fk(roots[0], where)
    print(f"xi0 = {where}: M/(rho A L) = {mp.nstr(Mc, 6)}, K L^3/(EI) = {mp.nstr(Kc, 6)}, "
          f"K/M = {mp.nstr(Kc / Mc, 8)}")
print("(beta_1 L)^4 =", mp.nstr(roots[0] ** 4, 8))""",
            ask="K/M with the damper at mid-span (ξ₀ = 1/2) divided by K/M at the tip.",
            answer="(fk(roots[0], sp.Rational(1, 2)) / fm(roots[0], sp.Rational(1, 2))) / (fk(roots[0], 1) / fm(roots[0], 1))",
            stated="1.000000000",
            source="the frequency does not depend on where the motion is referred to",
        ),
        Exercise(
            "The second mode",
            "The same reduction for mode 2: K·L³/(EI) at the tip is (β₂L)⁴/4.",
            """print("K L^3/(EI), mode 2:", mp.nstr(fk(roots[1], 1), 10))
print("(beta_2 L)^4 / 4:     ", mp.nstr(roots[1] ** 4 / 4, 10))""",
            ask="K·L³/(EI) of mode 2 referred to the tip.",
            answer="fk(roots[1], 1)",
            stated="121.3797046",
            source="(β₂L)⁴/4, β₂L the second root of cos βL·cosh βL = −1",
        ),
        Exercise(
            "Rayleigh with the static deflection shape",
            "Use the static tip-load shape ψ(ξ) = (3ξ² − ξ³)/2 instead of the mode: the classic "
            "K = 3EI/L³ and M = 33/140 ρAL, and a frequency a little above the exact one "
            "(Rayleigh's quotient bounds it from above).",
            """u_ = sp.Symbol("u")
psi = (3 * u_**2 - u_**3) / 2
M_psi = sp.integrate(psi**2, (u_, 0, 1))
K_psi = sp.integrate(sp.diff(psi, u_, 2) ** 2, (u_, 0, 1))
show_value(sp.Eq(sp.Symbol("M_psi"), M_psi))
show_value(sp.Eq(sp.Symbol("K_psi"), K_psi))
ratio = mp.sqrt(mp.mpf(str(K_psi / M_psi))) / roots[0] ** 2
print("omega_Rayleigh / omega_exact =", mp.nstr(ratio, 8))""",
            ask="ω_Rayleigh/ω_exact for the static tip-load shape.",
            answer="ratio",
            stated="1.014651549",
            source="√(3/(33/140))/(β₁L)², the classic 3EI/L³ and 33/140 ρAL",
        ),
    ),
    "contact_fits": (
        Exercise(
            "How many samples?",
            "The discrete fit depends on the number of samples; only n = 21 gives the paper's "
            "a = 0.1553 N/cm³ and b = 0.8360 N/cm.",
            """for ns in (6, 11, 21, 41):
    ah, bh, kh = discrete(ns)
    a_v = float(ah) * 1000 / 0.02**1.5  # N/m^3
    b_v = float(bh) * 1000 * 0.02**0.5  # N/m
    print(f"n = {ns:2d}: a = {a_v / 1e6:.4f} N/cm^3, b = {b_v / 100:.4f} N/cm")
print(f"continuous: a = {float(cont_vals['a']) / 1e6:.4f} N/cm^3, "
      f"b = {float(cont_vals['b']) / 100:.4f} N/cm")""",
            ask="a in N/cm³ from n = 21 samples.",
            answer="float(discrete(21)[0]) * 1000 / 0.02**1.5 / 1e6",
            stated="0.1553",
            source="the paper's printed a",
        ),
        Exercise(
            "Keep the full Hertz law",
            "How far is the cubic fit from the Hertz force it replaces, inside the fitted range "
            "and beyond it (a harder impact penetrates further)?",
            """F_hz = sp.lambdify(delta, hertz.subs(paper))
F_cc = sp.lambdify(delta, cubic.subs(scale).subs(paper))
for frac in (0.25, 0.5, 1.0, 1.5, 2.0):
    d = frac * 0.02
    print(f"delta = {frac:4.2f} delta_max: Hertz {F_hz(d):8.3f} N, cubic {F_cc(d):8.3f} N, "
          f"cubic/Hertz = {F_cc(d) / F_hz(d):.3f}")""",
            ask="The ratio cubic/Hertz of the two forces at twice the fitted range, δ = 2·δ_max.",
            answer="F_cc(0.04) / F_hz(0.04)",
            stated="1.66",
            source="a·δ³ + b·δ with the paper's a = 0.1553 N/cm³, b = 0.8360 N/cm, over 1000·δ^1.5",
        ),
        Exercise(
            "A shorter fit range",
            "Fit over δ_max = 1 cm: a grows as δ_max^(−3/2) and b shrinks as δ_max^(1/2).",
            """for dm in (sp.Rational(2, 100), sp.Rational(1, 100)):
    vals = {k_hz: 1000, d_max: dm}
    print(f"delta_max = {float(dm) * 100:.0f} cm: a = {float(scale[a].subs(vals)) / 1e6:.4f} "
          f"N/cm^3, b = {float(scale[b].subs(vals)) / 100:.4f} N/cm")""",
            ask="a(δ_max = 1 cm) divided by a(δ_max = 2 cm).",
            answer="scale[a].subs({k_hz: 1000, d_max: sp.Rational(1, 100)}) / scale[a].subs({k_hz: 1000, d_max: sp.Rational(2, 100)})",
            stated="2.828427125",
            source="2^(3/2), from a ∝ δ_max^(−3/2)",
        ),
    ),
    "harmonic_balance": (
        Exercise(
            "Keep the damping",
            "With C and c₁ kept, the residual of Eq. 10.1 has a sin ωt part as well: "
            "a single cosine cannot balance it, the response needs a phase.",
            """damped = sp.expand(eq10_1.subs(trial).doit())
theta = sp.Symbol("theta")
sin_part = sp.simplify(sp.integrate((damped * sp.sin(omega * t)).subs(t, theta / omega),
                                    (theta, 0, 2 * sp.pi)) / sp.pi)
show_value(sp.Eq(sp.Symbol("S_1"), sin_part))""",
            ask="S₁ for ω = 2 rad/s, A = 1 m, B = 3 m, C = 0.1 N s/m, c₁ = 0.5 N s/m.",
            answer="sin_part.subs({omega: 2, A: 1, B: 3, C: sp.Rational(1, 10), c1: sp.Rational(1, 2)})",
            stated="1.800000000",
            source="−ω(C·A + c₁(A − B)): the damping forces' sin ωt part",
        ),
        Exercise(
            "Linear contact, numbers",
            "With a = 0 the two balances are linear: the two natural frequencies of the masses "
            "coupled through b, for M = 1 kg, m = 0.25 kg, K = 100 N/m, b = 83.6 N/m.",
            """vals = {M: 1, m: sp.Rational(1, 4), K: 100, b: sp.Rational("83.6")}
for root in sorted(sp.solve(char.subs(vals), W)):
    f_hz = sp.sqrt(root) / (2 * sp.pi)
    print(f"omega^2 = {float(root):9.3f} rad^2/s^2, f = {float(f_hz):.3f} Hz")""",
            ask="The higher natural frequency in Hz.",
            answer="max(float(sp.sqrt(r) / (2 * sp.pi)) for r in sp.solve(char.subs(vals), W))",
            stated="3.34761087",
            source="scipy.linalg.eigh of the two-mass stiffness and mass matrices",
        ),
    ),
    "lindstedt": (
        Exercise(
            "How far does each order go?",
            "ω₀ = 1 rad/s, ε = 1: the Lindstedt series against the exact (elliptic-integral) "
            "frequency as the amplitude grows.",
            """for al in (0.5, 1.0, 2.0):
    vals = {omega0: 1, eps: 1, alpha: al}
    exact_w = float(exact_frequency().subs(vals).evalf())
    orders = ", ".join(f"order {n}: {float(frequency(n).subs(vals)):.6f}" for n in (1, 2, 3))
    print(f"alpha = {al}: {orders}; exact {exact_w:.6f}")""",
            ask="The order-3 frequency at α = 1 (ω₀ = 1 rad/s, ε = 1).",
            answer="frequency(3).subs({omega0: 1, eps: 1, alpha: 1})",
            stated="1.33251953125",
            source="1 + 3/8 − 21/256 + 81/2048, the series' published coefficients",
        ),
        Exercise(
            "A softening contact (ε < 0)",
            "The same series for ε = −0.2: the frequency now falls with amplitude.",
            """for al in (0.5, 1.0, 1.5):
    vals = {omega0: 1, eps: -sp.Rational(1, 5), alpha: al}
    print(f"alpha = {al}: order 1 {float(frequency(1).subs(vals)):.6f}, "
          f"order 3 {float(frequency(3).subs(vals)):.6f}, "
          f"exact {float(exact_frequency().subs(vals).evalf()):.6f}")""",
            ask="The order-1 frequency at α = 1.5 for ε = −0.2.",
            answer="frequency(1).subs({omega0: 1, eps: -sp.Rational(1, 5), alpha: sp.Rational(3, 2)})",
            stated="0.8312500000",
            source="1 + (3/8)·ε·α²",
        ),
    ),
    "multiple_scales": (
        Exercise(
            "Keep the contact damping",
            "Table 1's case with m = 0.25 kg and c₁ > 0: the fixed point of Eq. 31 moves.",
            """for c1_val in (0, sp.Rational(1, 20), sp.Rational(1, 2)):
    subs = {**table1_inputs("0.25"), c1: c1_val}
    step_map = sp.lambdify(T, T_map.subs(lam, lam_derived).subs(subs), "mpmath")
    Tk = mp.mpf(str(sp.N(T0.subs(lam, lam_derived).subs(subs), 30)))
    for _ in range(60):
        Tk = step_map(Tk)
    print(f"c1 = {float(c1_val):.2f} N s/m: T = {mp.nstr(Tk, 6)} s")""",
            ask="T at c₁ = 0.5 N s/m, in s.",
            answer="Tk",
            stated="0.1526983391",
            source="the generated kernel fixed_points.contact_duration (double precision, its own loop)",
        ),
        Exercise(
            "The printed factor for a heavier impact mass",
            "With the printed λ the linear start value T⁽⁰⁾ of the contact duration is too long "
            "by the factor 1 + m/M (M = 1 kg): the error grows with the mass ratio.",
            """for m_val in ("0.15", "0.25", "0.5"):
    subs = table1_inputs(m_val)
    t_p = sp.N(T0.subs(lam, lam_printed).subs(subs), 12)
    t_d = sp.N(T0.subs(lam, lam_derived).subs(subs), 12)
    print(f"m = {m_val} kg: printed/derived = {float(t_p / t_d):.5f}, "
          f"1 + m/M = {1 + float(m_val):.5f}")""",
            ask="printed/derived T⁽⁰⁾ for m = 0.5 kg.",
            answer="sp.N(T0.subs(lam, lam_printed).subs(table1_inputs('0.5')) / T0.subs(lam, lam_derived).subs(table1_inputs('0.5')), 15)",
            stated="1.500000000",
            source="1 + m/M",
        ),
    ),
    "closed_forms": (
        Exercise(
            "Another contact exponent",
            "For a force K·zⁿ the same steps give the constant "
            "2/(n+1)·B(1/(n+1), 1/2): π for the linear law (n = 1), 2.9433 for Hertz.",
            """n_ = sp.Symbol("n", positive=True)
const_n = 2 * sp.beta(1 / (n_ + 1), sp.Rational(1, 2)) / (n_ + 1)
for n_val in (1, sp.Rational(3, 2), 2, 3):
    print(f"n = {n_val}: constant = {float(sp.N(const_n.subs(n_, n_val), 15)):.6f}")
print("pi =", float(sp.pi))""",
            ask="The constant for n = 2.",
            answer="sp.N(const_n.subs(n_, 2), 15)",
            stated="2.804364211",
            source="mpmath's own beta function: (2/3)·B(1/3, 1/2)",
        ),
        Exercise(
            "Restitution of the linear law",
            "The coefficient of restitution exp(−c₁T/(2μ)) for M = 1 kg, m = 0.25 kg, "
            "k₁ = 122.7 N/m and a few contact dampings.",
            """for c1_val in (0, sp.Rational(1, 20), sp.Rational(1, 2), 2):
    vals = {m: sp.Rational(1, 4), M: 1, k1: sp.Rational("122.7"), c1: c1_val}
    print(f"c1 = {float(c1_val):.2f} N s/m: T = {float(T_lin.subs(vals)) * 1e3:.2f} ms, "
          f"e = {float(e_lin.subs(vals)):.4f}")""",
            ask="e for c₁ = 2 N s/m.",
            answer="e_lin.subs({m: sp.Rational(1, 4), M: 1, k1: sp.Rational('122.7'), c1: 2})",
            stated="0.5233471629",
            source="exp(−c₁T/(2μ)), T = π/ω_d, ω_d² = k₁/μ − (c₁/2μ)², μ = mM/(m + M)",
        ),
    ),
    "free_flight": (
        Exercise(
            "An overdamped beam",
            "ζ > 1 (M = 1 kg, K = 1 N/m, C = 3 N s/m): dsolve returns two decaying "
            "exponentials and no oscillation.",
            """over = sp.dsolve(eq_x.lhs.subs({M: 1, K: 1, C: 3}), x(t),
                 ics={x(0): x0, x(t).diff(t).subs(t, 0): xd0}).rhs
show_value(sp.Eq(sp.Symbol("x_over"), sp.simplify(over)))""",
            ask="The decay rate [1/s] of the slower exponential.",
            answer="min(-sp.re(r) for r in sp.solve(sp.Symbol('s') ** 2 + 3 * sp.Symbol('s') + 1))",
            stated="0.3819660113",
            source="(3 − √5)/2, the smaller root of s² + 3s + 1",
        ),
        Exercise(
            "The undamped limit",
            "C → 0 in the free-flight solution gives the undamped oscillator.",
            """show_value(sp.Eq(sp.Symbol("x_undamped"), sp.simplify(x_t.subs(C, 0))))""",
            ask="x_undamped at t = π/3 s for K = M = 1, x₀ = 1 m, ẋ₀ = 0.",
            answer="x_t.subs(C, 0).subs({K: 1, M: 1, x0: 1, xd0: 0}).subs(t, sp.pi / 3)",
            stated="0.5000000000",
            source="cos(π/3)",
        ),
    ),
    "forced_flight": (
        Exercise(
            "Base motion: the transmissibility",
            "With F0 = 0 the amplitude over X_b is the transmissibility √(K² + (CΩ)²)/√D; it "
            "passes through 1 at Ω = √2·ω_n whatever the damping.",
            """T2 = sp.simplify((amplitude**2).subs({P: P_value, Q: Q_value}).subs(F0, 0) / Xb**2)
show_value(sp.Eq(sp.Symbol("T_b") ** 2, T2))
print("at Omega = sqrt(2 K/M):", sp.simplify(T2.subs(W, sp.sqrt(2 * K / M))))""",
            ask="T_b² at Ω = √(2K/M).",
            answer="T2.subs(W, sp.sqrt(2 * K / M))",
            stated="1.000000000",
            source="the crossing of any damping",
        ),
        Exercise(
            "Beats below resonance, growth at it",
            "Undamped and from rest, the response beats at a detuned Ω and grows like t at Ω = ω_n.",
            """vals = {M: 1, K: 900, C: 0, F0: 1, Xb: 0, phi: 0, x0: 0, xd0: 0}
for Wv in (27, 29.5, 30):
    expr = resonant if Wv == 30 else general
    at_W = expr.subs(vals).subs(W, Wv)
    print(f"Omega = {Wv}:", [sp.N(at_W.subs(t, tt), 4) for tt in (1, 2, 4, 8)])""",
            ask="x [m] at t = 8 s for Ω = 30 rad/s.",
            answer="resonant.subs(vals).subs(W, 30).subs(t, 8)",
            stated="0.1260593540",
            source="F₀/(2Mω)·t·sin ωt",
        ),
    ),
    "rigid_impact": (
        Exercise(
            "How much a light damper takes",
            "With the primary at rest, the share of the impact mass's kinetic energy lost is "
            "(1 − e²)·M/(m + M): nearly all of (1 − e²) for a light damper.",
            """share = sp.simplify(loss_mu.subs(xm, 0) / (m * ym**2 / 2))
show_value(sp.Eq(sp.Symbol("share"), share))
for r in (sp.Rational(1, 100), sp.Rational(1, 10), 1):
    print(f"m/M = {r}, e = 0.6:", sp.N(share.subs({m: r * M, e: sp.Rational(3, 5)}), 6))""",
            ask="The share lost at m/M = 0.1, e = 0.6.",
            answer="share.subs({m: M / 10, e: sp.Rational(3, 5)})",
            stated="0.5818181818",
            source="(1 − e²)·M/(m + M)",
        ),
        Exercise(
            "The c1 for a wanted e",
            "The linear law's contact damping for e = 0.9, 0.6, 0.3 (m = 0.25 kg, M = 1 kg, "
            "k1 = 10⁵ N/m).",
            """for ev in (0.9, 0.6, 0.3):
    print(f"e = {ev}: c1 =", sp.N(c1_value.subs({m: 0.25, M: 1, k1: 1e5, e: ev}), 6), "N s/m")""",
            ask="c₁ [N s/m] for e = 0.6.",
            answer="c1_value.subs({m: 0.25, M: 1, k1: 1e5, e: 0.6})",
            stated="45.39428865",
            source="2ζ√(k₁μ), ζ = −ln e/√(π² + ln² e), μ = mM/(m + M)",
        ),
    ),
    "periodic_orbit": (
        Exercise(
            "Where the orbit exists",
            "Two phases solve a·cos φ + b·sin φ = c while abs(c) < √(a² + b²); the issue's system "
            "(M 1 kg, K 1000 N/m, C 0.5 N s/m, m 0.05 kg, d 20 mm, F0 2 N, e 0.6).",
            """import math
vals = {M: 1, K: 1000, C: sp.Rational(1, 2), m: sp.Rational(1, 20), e: sp.Rational(3, 5),
        d: sp.Rational(1, 50), F0: 2, Xb: 0}
fabc = sp.lambdify(W, [v.subs(closed).subs(vals) for v in (a_coef, b_coef, c_coef)], "math")
for Wv in (10, 20, 30, 38, 60):
    a_, b_, c_ = fabc(Wv)
    r_ = math.hypot(a_, b_)
    print(f"Omega = {Wv}: c/r = {c_ / r_:.4f}:", "two phases" if abs(c_) < r_ else "no orbit")""",
            ask="c/√(a² + b²) at Ω = 38 rad/s.",
            answer="(lambda a_, b_, c_: c_ / math.hypot(a_, b_))(*fabc(38))",
        ),
        Exercise(
            "Elastic impacts",
            "At e = 1 no energy is lost in the impacts; the right side c keeps its form.",
            """show_value(sp.Eq(sp.Symbol("c"), sp.factor(c_coef.subs(e, 1))))""",
            ask="c/√(a² + b²) at e = 1 for the issue's system at Ω = 30 rad/s (M 1 kg, K 1000 "
            "N/m, C 0.5 N s/m, m 0.05 kg, d 20 mm, F0 2 N): a, b and c share an arbitrary "
            "factor, their ratio does not.",
            answer="(lambda a_, b_, c_: sp.N(c_ / sp.sqrt(a_**2 + b_**2), 20))(*[v.subs(e, 1).subs(closed).subs({M: 1, K: 1000, C: sp.Rational(1, 2), m: sp.Rational(1, 20), d: sp.Rational(1, 50), F0: 2, Xb: 0, W: 30}) for v in (a_coef, b_coef, c_coef)])",
        ),
    ),
    "hunt_crossley": (
        Exercise(
            "Which χ for a wanted e",
            "Users set χ from a wanted e.  The e they actually get with Hunt–Crossley's "
            "χ = 3(1 − e)/(2v₀) and Lankarani–Nikravesh's χ = 3(1 − e²)/(4v₀), from the exact "
            "condition g(−e·z) = g(z) solved at 30 digits.",
            """def exact_e(zv):
    return mp.findroot(lambda ev: (-ev * zv - mp.log1p(-ev * zv)) - (zv - mp.log1p(zv)),
                       (mp.mpf("1e-9"), 1 - mp.mpf("1e-30")), solver="anderson")
with mp.workdps(30):
    for wanted in (0.95, 0.8, 0.6, 0.4):
        z_hc, z_ln = 1.5 * (1 - wanted), 0.75 * (1 - wanted**2)
        print(f"wanted e = {wanted}: HC gives {mp.nstr(exact_e(mp.mpf(z_hc)), 6)}, "
              f"LN gives {mp.nstr(exact_e(mp.mpf(z_ln)), 6)}")""",
            ask="The e Hunt–Crossley's χ gives for a wanted e = 0.6.",
            answer="exact_e(mp.mpf(1.5 * (1 - 0.6)))",
            stated="0.7119501796",
            source="scipy's brentq on g(−e·z) = g(z), g(u) = u − ln(1 + u), z = 3(1 − e)/2",
        ),
        Exercise(
            "How long the Kelvin–Voigt law pulls",
            "The share of the contact time during which the paper's linear law k₁δ + c₁δ̇ is "
            "tensile, for c₁ set from e (Step 9): 2·atan(−ln e/π)/π.",
            """for ev in (0.9, 0.6, 0.3, 0.1):
    share = 2 * sp.atan(-sp.log(sp.Float(ev)) / sp.pi) / sp.pi
    print(f"e = {ev}: pulls during {sp.N(100 * share, 4)} % of the contact")""",
            ask="The tensile share [%] at e = 0.6.",
            answer="100 * 2 * sp.atan(-sp.log(sp.Float(0.6)) / sp.pi) / sp.pi",
            stated="10.26168396",
            source="2·atan(−ln e/π)/π",
        ),
    ),
    "slow_flow": (
        Exercise(
            "How hard the walls must be hit",
            "The activation threshold ξ_a = ρ/√(1 + ρ²): the primary's amplitude, in half "
            "clearances, below which the impact mass cannot reach both walls each period.",
            """for ev in (1, 0.9, 0.6, 0.3, 0):
    rv = rho_value.subs(e, ev)
    print(f"e = {ev}: rho = {sp.N(rv, 4)}, threshold = {sp.N(threshold.subs(rho, rv), 4)}")""",
            ask="ξ_a at e = 0.6.",
            answer="threshold.subs(rho, rho_value.subs(e, sp.Rational(3, 5)))",
            stated="0.1571767255",
            source="ρ/√(1 + ρ²), ρ = 2(1 − e)/(π(1 + e))",
        ),
        Exercise(
            "The best clearance",
            "Along the backbone, the clearance d_b(ξ) rises and falls: its largest value is the "
            "best clearance.  The issue's system (M 1 kg, K 1000 N/m, C 0.5 N s/m, m 0.05 kg, "
            "F0 2 N, e 0.6), scanned over ξ.",
            """import numpy as np
vals = {M: 1, K: 1000, C: sp.Rational(1, 2), m: sp.Rational(1, 20), F0: 2, Xb: 0,
        rho: rho_value.subs(e, sp.Rational(3, 5))}
f = sp.lambdify(xi, backbone_clear.subs(Theta, Theta_of_xi).subs(vals), "numpy")
grid = np.geomspace(float(threshold.subs(vals)) * 1.0001, 50, 4000)
best = grid[np.argmax(f(grid))]
print(f"best clearance about {1e3 * f(best):.3f} mm at xi = {best:.3f}: "
      f"primary peak {1e3 * best * f(best) / 2:.3f} mm")""",
            ask="The best clearance in mm.",
            answer="1e3 * f(best)",
            rtol=1e-5,  # the solution's grid of 4000 points finds the maximum to ~5e-7
        ),
    ),
    "hertz_contact": (
        Exercise(
            "A steel ball against a steel flat",
            "The paper's K_Hz = 1000 N/m^1.5 beside a 20 mm steel sphere on a steel flat "
            "(E = 210 GPa, ν = 0.3): the same law, ten million times stiffer.",
            """steel = {E1: 210e9, E2: 210e9, nu1: sp.Rational(3, 10), nu2: sp.Rational(3, 10)}
Es_v = E_star.subs(steel)
R_v = radius.subs({R1: sp.Rational(1, 100), kappa2: 0})
K_v = k_hz.subs({Es: Es_v, R: R_v})
print(f"E* = {sp.N(Es_v / 1e9, 5)} GPa, R = {sp.N(R_v * 1e3, 4)} mm, "
      f"K_Hz = {sp.N(K_v, 4)} N/m^1.5 = {sp.N(K_v / 1000, 3)} x the paper's")""",
            ask="K_Hz [N/m^1.5] of the 20 mm steel sphere on the steel flat.",
            answer="k_hz.subs({Es: E_star.subs(steel), R: radius.subs({R1: sp.Rational(1, 100), kappa2: 0})})",
            stated="1.538461538e10",
            source="(4/3)·E*·√R, E* = E/(2(1 − ν²)) (Johnson, Contact Mechanics, §4.2)",
        ),
        Exercise(
            "Where yield starts, for other Poisson ratios",
            "The depth of the largest σ_r − σ_z on the axis and the peak pressure p₀/Y at which it "
            "reaches the yield strength.",
            """for nv in ("0.2", "0.3", "0.4", "0.5"):
    f = sp.lambdify(zeta, difference.subs(nu, sp.Rational(nv)), "mpmath")
    zs = mp.findroot(lambda t: mp.diff(f, t), mp.mpf("0.5"))
    print(f"nu = {nv}: depth {mp.nstr(zs, 4)} a, p0 = {mp.nstr(1 / f(zs), 4)} Y")""",
            ask="p₀/Y at ν = 0.3.",
            answer="(lambda f: 1 / f(mp.findroot(lambda t: mp.diff(f, t), mp.mpf('0.5'))))(sp.lambdify(zeta, difference.subs(nu, sp.Rational(3, 10)), 'mpmath'))",
            stated="1.61",
            source="Johnson, Contact Mechanics, §3.4: the largest τ₁ = 0.31·p₀, at z = 0.48a (ν = 0.3); Tresca, τ₁ = Y/2",
        ),
        Exercise(
            "Restitution against impact speed",
            "Thornton's e against v₀/v_y, beside the power law v₀^(−1/4) it tends to at high "
            "speed.",
            """f = sp.lambdify(ratio_v, printed, "mpmath")
for k in (1, 2, 5, 10, 100, 1000):
    ev = f(mp.mpf(1) / k)
    print(f"v0/vy = {k:5d}: e = {mp.nstr(ev, 5)}, e * (v0/vy)^(1/4) = {mp.nstr(ev * k**0.25, 5)}")""",
            ask="e·(v₀/v_y)^(1/4) at v₀/v_y = 1000.",
            answer="f(mp.mpf(1) / 1000) * 1000**0.25",
            stated="1.185",
            source="Thornton (1997), e = √(6√3/5)·√(1 − r²/6)·(r/(r + 2√(6/5 − r²/5)))^(1/4), r = v_y/v₀",
        ),
    ),
    "beam_modes": (
        Exercise(
            "A damper a quarter along a simply supported beam",
            "The first mode's mass referred to ξ = 1/4 instead of the midspan: the point moves "
            "less, so the mode looks heavier there.",
            """fM = sp.lambdify((k, xi), mass["simply_supported"], "mpmath")
for where in (sp.Rational(1, 2), sp.Rational(1, 4)):
    print(f"xi = {where}: M/(rho A L) = {mp.nstr(fM(found['simply_supported'][0], where), 10)}")""",
            ask="M/(ρAL) of the simply supported beam's first mode referred to ξ = 1/4.",
            answer="sp.lambdify((k, xi), mass['simply_supported'], 'mpmath')(found['simply_supported'][0], sp.Rational(1, 4))",
            stated="1.000000000",
            source="∫₀¹sin²(πξ)dξ / sin²(π/4) = (1/2)/(1/2)",
        ),
        Exercise(
            "One mode for a static load",
            "The cantilever's tip under a static force, from its first mode alone: 1/K₁ in units "
            "of L³/(EI), against the exact 1/3.",
            """one = (1 / stiff["cantilever"]).subs(xi, 1)
v = sp.lambdify(k, one, "mpmath")(found["cantilever"][0])
print(f"first mode: {mp.nstr(v, 10)}, exact 1/3: {mp.nstr(mp.mpf(1) / 3, 10)}, "
      f"short by {mp.nstr((1 - 3 * v) * 100, 4)} %")""",
            ask="1/K₁ of the cantilever at its tip, in units of L³/(EI).",
            answer="sp.lambdify(k, (1 / stiff['cantilever']).subs(xi, 1), 'mpmath')(found['cantilever'][0])",
            stated="0.3235627",
            source="4/(β₁L)⁴ with β₁L = 1.87510407 (Blevins, Table 8-1)",
        ),
        Exercise(
            "The third root of the clamped–clamped beam",
            "The roots of cos k·cosh k = 1 approach (2i + 1)π/2 as cosh grows.",
            """for i, r in enumerate(found["clamped_clamped"][:4], start=1):
    print(f"mode {i}: beta L = {mp.nstr(r, 12)}, (2i + 1) pi / 2 = {mp.nstr((2 * i + 1) * mp.pi / 2, 12)}")""",
            ask="β₃L of the clamped–clamped beam.",
            answer="found['clamped_clamped'][2]",
            stated="10.9956078",
            source="Blevins, Formulas for Natural Frequency and Mode Shape, Table 8-1",
        ),
    ),
    "modal_structure": (
        Exercise(
            "Rayleigh damping between its two frequencies",
            "C = αM + βK set to ζ = 0.02 at ω₁ = 10 and ω₂ = 100 rad/s: in between, at the "
            "geometric mean √(ω₁ω₂), a mode is damped less.",
            """given = {z_: sp.Rational(2, 100), wa: 10, wb: 100}
a_, b_ = alpha_v.subs(given), beta_v.subs(given)
middle = sp.sqrt(10 * 100)
print(f"alpha = {sp.N(a_, 8)} 1/s, beta = {sp.N(b_, 8)} s")
print(f"zeta at sqrt(w1 w2) = {sp.N(zeta_i.subs({al: a_, be: b_, wi: middle}), 10)}")""",
            ask="ζ of a mode at √(ω₁ω₂) ≈ 31.62 rad/s.",
            answer="zeta_i.subs({al: alpha_v.subs({z_: sp.Rational(2, 100), wa: 10, wb: 100}), be: beta_v.subs({z_: sp.Rational(2, 100), wa: 10, wb: 100}), wi: sp.sqrt(1000)})",
            stated="0.01149919",
            source="2ζ√(ω₁ω₂)/(ω₁ + ω₂), the Rayleigh ratio at the geometric mean",
        ),
        Exercise(
            "The cantilever's second mode at the tip under base motion",
            "Referred to the tip, the second mode is driven by the base with Γ₂, of the "
            "opposite sign to Γ₁: it moves the tip against the first.",
            """gamma = sp.lambdify(k, participation["cantilever"].subs(xi, 1), "mpmath")
for i, r in enumerate(roots("cantilever", 3), start=1):
    print(f"mode {i}: Gamma at the tip = {mp.nstr(gamma(r), 10)}")""",
            ask="Γ₂ of the cantilever referred to its tip.",
            answer="sp.lambdify(k, participation['cantilever'].subs(xi, 1), 'mpmath')(roots('cantilever', 2)[1])",
            stated="-0.8678718",
            source="φ₂(1)∫φ₂dξ/∫φ₂²dξ by mpmath quadrature of the shape",
        ),
    ),
    "sampled_load": (
        Exercise(
            "A load applied suddenly",
            "A constant load p₀ switched on at τ = 0 on the undamped primary at rest: the "
            "response overshoots the static deflection p₀/K and swings about it.",
            """sudden = x_t.subs({C: 0, x0: 0, xd0: 0, pd: 0})
for where in (sp.pi / (2 * wn), sp.pi / wn):
    print(f"tau = {where}: x K / p0 = {sp.simplify(sudden.subs(t, where) * K / p0)}")""",
            ask="The largest x·K/p₀ of the suddenly applied load (at τ = π/ωₙ).",
            answer="sp.simplify(x_t.subs({C: 0, x0: 0, xd0: 0, pd: 0}).subs(t, sp.pi / wn) * K / p0)",
            stated="2.000000000",
            source="the dynamic load factor of a step load, 2 (Chopra, Dynamics of Structures, §4.3)",
        ),
        Exercise(
            "How far a damped primary lags a ramp",
            "Under a slowly rising load p = ṗτ the decay dies out and x follows the static "
            "deflection ṗτ/K late by a fixed time: the offset −Cṗ/K² is ṗ/K times −C/K.",
            """given = {M: 1, K: 1000, C: sp.Rational(1, 2)}
lag = -particular.subs({p0: 0, t: 0}) / (pd / K)
print("lag C/K =", lag.subs(given), "s; 2 zeta / omega_n =",
      sp.N((2 * (C / (2 * sp.sqrt(K * M))) / wn).subs(given), 10), "s")""",
            ask="The lag (s) behind a ramp of M 1 kg, K 1000 N/m, C 0.5 N s/m.",
            answer="(-particular.subs({p0: 0, t: 0}) / (pd / K)).subs({M: 1, K: 1000, C: sp.Rational(1, 2)})",
            stated="0.0005000000000",
            source="2ζ/ωₙ, the steady lag of a damped oscillator behind a ramp load",
        ),
    ),
    "multi_harmonic_balance": (
        Exercise(
            "Samples for a quadratic force",
            "A force quadratic in the motion (p = 2) of H = 5 harmonics holds harmonics up to 10. "
            "Count the samples AFT needs, and watch one fewer fold harmonic 10 onto −5.",
            """n = rule.subs({p_: 2, H_: 5})
print("N =", n, "exact:", aliasing(2, 5, int(n)), "| N - 1 exact:", aliasing(2, 5, int(n) - 1))""",
            ask="The fewest time samples N for a force of degree p = 2 in a motion of H = 5 "
            "harmonics.",
            answer="rule.subs({p_: 2, H_: 5})",
            stated="16",
            source="Krack and Gross, Harmonic Balance for Nonlinear Vibration Problems (2019): "
            "AFT is exact for a polynomial force of degree p from N = (p + 1)H + 1 samples",
        ),
        Exercise(
            "The clearance at A = d",
            "A relative motion of amplitude A equal to the clearance d spends a third of each "
            "period against the walls: the equivalent stiffness F₁/A is a fraction of k₁.",
            """ratio = sp.simplify((first / (k1 * amp)).subs(amp, gap))
print("F1/(k1 A) at A = d:", ratio, "=", sp.N(ratio, 12))""",
            ask="F₁/(k₁A), the linear contact's equivalent stiffness over k₁, at A = d.",
            answer="(first / (k1 * amp)).subs(amp, gap)",
            stated="0.3910022190",
            source="mpmath's quadrature of (1/πA)∫ f(A cos θ) cos θ dθ over one period, f the "
            "dead zone of half-width d/2 (2/3 − √3/(2π) in Gelb and Vander Velde's closed form)",
        ),
        Exercise(
            "A Hertz onset",
            "At an onset the Hertz force starts as (v₀s)^(3/2): read the rate at which its "
            "harmonics fall, and the order of the balance's truncation in H.",
            """print("d log|F_k|/d log k:", decay.subs(nu, sp.Rational(3, 2)))
print("truncation order nu + 2:", sp.Rational(3, 2) + 2)""",
            ask="d log|F_k| / d log k for a force starting as s₊^(3/2).",
            answer="decay.subs(nu, sp.Rational(3, 2))",
            stated="-2.5",
            source="Lighthill, Fourier Analysis and Generalised Functions (1958): a singularity "
            "s₊^ν gives Fourier coefficients of order k^−(ν+1)",
        ),
    ),
}
