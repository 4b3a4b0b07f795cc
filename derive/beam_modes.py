r"""Step 14 — a beam of several modes: the cantilever, the clamped–clamped and the simply supported
beam, their modes, their masses at a point, and how many modes a point needs.

Beyond the paper.  Step 1 reduces the cantilever to its first mode at the tip.  A real structure
carries its damper somewhere along a beam whose ends may be clamped, free or pinned, and its
response at that point is a sum over modes.  On the board:

1. The general solution of φ'''' = k⁴φ in ξ = r/L (k = βL), as in Step 1.
2. Each beam's end conditions (clamped: φ = φ' = 0; free: φ'' = φ''' = 0; pinned: φ = φ'' = 0)
   give a 4×4 determinant; its zeros are the frequency equation — cos k cosh k + 1 = 0
   (cantilever), cos k cosh k − 1 = 0 (clamped–clamped), sin k sinh k = 0 (simply supported).
   The mode shapes are written without the cancellation of cosh against sinh at large k.
3. Orthogonality shown, not assumed: for two solutions with k₁ ≠ k₂ an integration by parts gives
   (k₁⁴ − k₂⁴)∫φ₁φ₂ dξ = [φ₁'''φ₂ − φ₁''φ₂' + φ₁'φ₂'' − φ₁φ₂''']₀¹, and every end condition
   makes the bracket vanish.
4. The norm ∫φ² dξ from one more identity, d/dξ[ξ(k⁴φ² − 2φ'φ''' + φ''²) + 3φφ''' − φ'φ''] =
   4k⁴φ², so that at a root it is a boundary value; then the mass and stiffness of each mode
   referred to the damper's point ξ (the displacement there is the mode's coordinate):
   M/(ρAL) = ∫φ²dξ/φ(ξ)², K·L³/(EI) = k⁴·M/(ρAL).
5. The point's static flexibility from the beam's statics (EI w'''' = P δ(ξ − ξ₀), solved in two
   cubic pieces) against the modal sum Σ 1/Kᵢ: it converges as N⁻³, the measure of how many
   modes a point needs.
6. An impact at the point: each mode (referred to the point) takes the impulse P through its own
   modal mass, so the beam meets the impact mass as one effective mass, 1/m<sub>eff</sub> = Σ 1/Mᵢ; one
   mode gives Step 9's law.
"""

from __future__ import annotations

import itertools

import mpmath as mp
import sympy as sp

from .board import Arg, Board

N_MODES = 8
#: Modes summed for the static flexibility's convergence.
N_SUM = 64
DIGITS = 40

k, xi, x0 = sp.symbols("beta_L xi xi_0", positive=True)

#: Each beam: its two ends (at ξ = 0 and ξ = 1), its frequency equation's left side, and the
#: centre of its i-th root (a root lies within 0.5 of it).
BEAMS = {
    "cantilever": (("clamped", "free"), sp.cos(k) * sp.cosh(k) + 1, lambda i: (2 * i - 1) * mp.pi / 2),
    "clamped_clamped": (("clamped", "clamped"), sp.cos(k) * sp.cosh(k) - 1,
                        lambda i: (2 * i + 1) * mp.pi / 2),
    "simply_supported": (("pinned", "pinned"), sp.sin(k) * sp.sinh(k), lambda i: i * mp.pi),
}  # fmt: skip
#: The derivatives each end holds at zero.
ENDS = {"clamped": (0, 1), "free": (2, 3), "pinned": (0, 2)}
SUPERSCRIPT = {2: "²", 4: "⁴", 6: "⁶"}
NAMES = {"cantilever": "cantilever", "clamped_clamped": "clamped–clamped beam",
         "simply_supported": "simply supported beam"}  # fmt: skip


def roots(beam: str, n: int = N_MODES, dps: int = DIGITS) -> list[mp.mpf]:
    """The first ``n`` positive roots k = βL of ``beam``'s frequency equation to ``dps`` digits
    (bracketed within 0.5 of their centres, where cos vanishes and cosh is large)."""
    _, equation, centre = BEAMS[beam]
    f = sp.lambdify(k, equation / sp.cosh(k), "mpmath")  # ÷ cosh: the same zeros, bounded
    with mp.workdps(dps + 10):
        return [mp.findroot(f, (centre(i) - mp.mpf("0.5"), centre(i) + mp.mpf("0.5")),
                            solver="anderson") for i in range(1, n + 1)]  # fmt: skip


#: φ and its derivatives φ⁽ⁿ⁾ on the board: f0 … f4
F = sp.symbols("f0:5")
#: N, with dN/dξ = 4k⁴φ² (section 4 of the module text)
NORM_BRACKET = xi * (k**4 * F[0] ** 2 - 2 * F[1] * F[3] + F[2] ** 2) + 3 * F[0] * F[3] - F[1] * F[2]


def norm_boundary(beam: str) -> sp.Expr:
    """[N]₀¹ for ``beam``, the terms its end conditions zero removed (4k⁴∫φ²dξ at a root)."""
    (left, right), _, _ = BEAMS[beam]
    one = NORM_BRACKET.subs(xi, 1).subs({F[i]: 0 for i in ENDS[right]})
    return sp.expand(one - NORM_BRACKET.subs(xi, 0).subs({F[i]: 0 for i in ENDS[left]}))


def norm_at_root(beam: str, shape: sp.Expr) -> sp.Expr:
    """∫₀¹φ²dξ of ``shape`` (``beam``'s mode shape in k and ξ), valid where k is a root."""
    values = {F[n]: sp.diff(shape, xi, n).subs(xi, 1) for n in range(4)}
    return norm_boundary(beam).subs(values) / (4 * k**4)


def _mode_shapes() -> dict[str, sp.Expr]:
    """Each beam's mode shape without cancellation at large k (checked against the textbook
    forms on the board)."""
    d_cl = (sp.sin(k) - sp.cos(k) - sp.exp(-k)) / (sp.cos(k) + sp.cosh(k))
    d_cc = (sp.cos(k) - sp.sin(k) - sp.exp(-k)) / (sp.sinh(k) - sp.sin(k))
    return {
        "cantilever": sp.sin(k * xi)
        - (1 + d_cl) * sp.cos(k * xi)
        + sp.exp(-k * xi)
        + d_cl * sp.cosh(k * xi),
        "clamped_clamped": sp.exp(-k * xi)
        + d_cc * sp.sinh(k * xi)
        - sp.cos(k * xi)
        + (1 - d_cc) * sp.sin(k * xi),
        "simply_supported": sp.sin(k * xi),
    }


def derive() -> Board:
    board = Board("beam_modes", "A beam of several modes", "F6")
    w = board.write
    C = sp.symbols("C1:5")
    general = w(
        "general_solution",
        C[0] * sp.sin(k * xi) + C[1] * sp.cos(k * xi) + C[2] * sp.sinh(k * xi)
        + C[3] * sp.cosh(k * xi),
        "General solution of φ'''' = k⁴φ in ξ = r/L, k = βL, β⁴ = ρAω²/(EI) (Step 1).",
    )  # fmt: skip
    shapes = _mode_shapes()
    textbook = {
        "cantilever": sp.sin(k * xi) - sp.sinh(k * xi)
        - (sp.sin(k) + sp.sinh(k)) / (sp.cos(k) + sp.cosh(k)) * (sp.cos(k * xi) - sp.cosh(k * xi)),
        "clamped_clamped": sp.cosh(k * xi) - sp.cos(k * xi)
        - (sp.cosh(k) - sp.cos(k)) / (sp.sinh(k) - sp.sin(k)) * (sp.sinh(k * xi) - sp.sin(k * xi)),
        "simply_supported": sp.sin(k * xi),
    }  # fmt: skip
    found: dict[str, list[mp.mpf]] = {}
    for beam, ((left, right), equation, _) in BEAMS.items():
        name = NAMES[beam]
        conditions = [sp.diff(general, xi, d).subs(xi, 0) for d in ENDS[left]]
        conditions += [sp.diff(general, xi, d).subs(xi, 1) for d in ENDS[right]]
        matrix = sp.Matrix([[sp.diff(c, ci) for ci in C] for c in conditions])
        power = sum(ENDS[left]) + sum(ENDS[right])  # each derivative brings a factor k
        det = w(f"determinant_{beam}", sp.simplify(matrix.det() / k**power),
                f"The {name}: the determinant of its end conditions ({left} at ξ = 0, {right} "
                f"at ξ = 1), divided by k{SUPERSCRIPT[power]}.")  # fmt: skip
        freq = w(f"frequency_equation_{beam}", sp.Eq(equation, 0),
                 f"A mode needs a zero determinant: the {name}'s frequency equation.")  # fmt: skip
        ratio = sp.simplify(det / freq.lhs)
        board.check(f"{name}: frequency equation from the end conditions", "F6",
                    bool(ratio.is_number and ratio != 0), f"determinant = {ratio}·k{SUPERSCRIPT[power]}·(equation)")  # fmt: skip
        mode = w(f"mode_shape_{beam}", shapes[beam],
                 f"The {name}'s mode shape, written so that no term exceeds 2 at large k.")  # fmt: skip
        same = sp.simplify((mode - textbook[beam]).rewrite(sp.exp)) == 0
        board.check(f"{name}: the cancellation-free shape is the textbook one", "F6", same)
        rs = roots(beam)
        found[beam] = rs
        at_zero = [sp.simplify(sp.diff(mode, xi, d).subs(xi, 0)) for d in ENDS[left]]
        with mp.workdps(DIGITS):
            worst = max(abs(sp.lambdify(k, sp.diff(mode, xi, d).subs(xi, 1), "mpmath")(r))
                        / r**d for r in rs for d in ENDS[right])  # fmt: skip
        board.check(f"{name}: the shape meets both ends' conditions", "F6",
                    at_zero == [0, 0] and worst < mp.mpf(10) ** (-DIGITS + 5),
                    f"at ξ = 0 exactly; at ξ = 1, at the first {N_MODES} roots ≤ "
                    f"{mp.nstr(worst, 2)}")  # fmt: skip
        w(f"beta_L_{beam}", [sp.Float(mp.nstr(r, 30), 30) for r in rs],
          f"The {name}: the first {N_MODES} roots k = βL ({DIGITS} digits, 30 shown).")  # fmt: skip
        board.constant(
            name=f"BETA_L_{beam.upper()}",
            values=tuple(repr(float(r)) for r in rs),
            digits=tuple(mp.nstr(r, 25) for r in rs),
            doc=f"Roots βL of the {name}'s frequency equation, modes 1..{N_MODES} (mpmath).",
        )
    textbook_roots = {"cantilever": "1.875104", "clamped_clamped": "4.730041",
                      "simply_supported": "3.141593"}  # fmt: skip
    board.check(
        "β₁L = 1.875104, 4.730041, π (Blevins, Formulas for Natural Frequency, Table 8-1)",
        "F6",
        all(abs(found[b][0] - mp.mpf(v)) < 5e-7 for b, v in textbook_roots.items()),
        ", ".join(mp.nstr(found[b][0], 10) for b in BEAMS),
    )

    # --- orthogonality, shown --------------------------------------------------------------------
    f = sp.symbols("f0:5")  # φ₁ and its derivatives
    g = sp.symbols("g0:5")  # φ₂ and its derivatives
    bracket = w(
        "orthogonality_bracket",
        f[3] * g[0] - f[2] * g[1] + f[1] * g[2] - f[0] * g[3],
        "B = φ₁'''φ₂ − φ₁''φ₂' + φ₁'φ₂'' − φ₁φ₂''' (fₙ, gₙ: the n-th derivatives of φ₁, φ₂).",
    )
    # d/dξ B: each symbol's derivative is the next one
    d = sp.expand(sum(sp.diff(bracket, s) * nxt for s, nxt in itertools.pairwise(f))
                  + sum(sp.diff(bracket, s) * nxt for s, nxt in itertools.pairwise(g)))  # fmt: skip
    k1, k2 = sp.symbols("k_1 k_2", positive=True)
    telescoped = sp.expand(d.subs({f[4]: k1**4 * f[0], g[4]: k2**4 * g[0]}))
    w("orthogonality_identity", sp.Eq(sp.Symbol("dB/dxi"), sp.factor(telescoped)),
      "Differentiating B, the middle terms cancel in pairs: dB/dξ = φ₁''''φ₂ − φ₁φ₂'''' = "
      "(k₁⁴ − k₂⁴)φ₁φ₂, so (k₁⁴ − k₂⁴)∫₀¹φ₁φ₂dξ = [B]₀¹.")  # fmt: skip
    ends_kill = all(
        bracket.subs({**{f[i]: 0 for i in ENDS[e]}, **{g[i]: 0 for i in ENDS[e]}}) == 0
        for e in ENDS
    )
    board.check(
        "every end condition makes B vanish: modes of different k are orthogonal",
        "F6",
        sp.simplify(telescoped - (k1**4 - k2**4) * f[0] * g[0]) == 0 and ends_kill,
        "clamped, free and pinned ends each zero one factor of every term of B",
    )
    with mp.workdps(25):
        off = mp.mpf(0)
        for beam in BEAMS:
            phi = sp.lambdify((k, xi), shapes[beam], "mpmath")
            for i, a in enumerate(found[beam][:4]):
                for b in found[beam][i + 1 : 4]:
                    off = max(off, abs(mp.quad(lambda z, a=a, b=b, p=phi: p(a, z) * p(b, z),
                                               [0, 1])))  # fmt: skip
    board.check("orthogonal by quadrature (4 modes of each beam)", "F6", off < 1e-18,
                f"max |∫φᵢφⱼ dξ| = {mp.nstr(off, 2)}")  # fmt: skip

    # --- the norm at a root -------------------------------------------------------------------
    norm_bracket = w("norm_bracket", NORM_BRACKET, "N = ξ(k⁴φ² − 2φ'φ''' + φ''²) + 3φφ''' − φ'φ''.")
    dn = sp.diff(norm_bracket, xi) + sum(
        sp.diff(norm_bracket, s) * nxt for s, nxt in itertools.pairwise(f)
    )
    dn = sp.expand(dn.subs(f[4], k**4 * f[0]))
    board.check("dN/dξ = 4k⁴φ², so 4k⁴∫₀¹φ²dξ = [N]₀¹", "F6",
                sp.simplify(dn - 4 * k**4 * f[0] ** 2) == 0, f"dN/dξ = {sp.factor(dn)}")  # fmt: skip
    norms = {}
    for beam in BEAMS:
        boundary = norm_boundary(beam)
        values = {f[n]: sp.diff(shapes[beam], xi, n).subs(xi, 1) for n in range(4)}
        at_end = {f[n]: sp.Symbol(f"varphi^({n})(1)") for n in range(4)}  # φ⁽ⁿ⁾(1) on the board
        norms[beam] = w(
            f"norm_{beam}",
            boundary.subs(values) / (4 * k**4),
            f"The {NAMES[beam]}: ∫₀¹φ²dξ = [N]₀¹/(4k⁴), the terms at ξ = 0 vanishing by its "
            "conditions (valid at a root).",
            shown=boundary.subs(at_end) / (4 * k**4),
            names={at_end[n]: values[n] for n in values},
        )
    with mp.workdps(30):
        worst = mp.mpf(0)
        for beam in BEAMS:
            norm = sp.lambdify(k, norms[beam], "mpmath")
            phi = sp.lambdify((k, xi), shapes[beam], "mpmath")
            for r in found[beam][:4]:
                quad = mp.quad(lambda z, r=r, p=phi: p(r, z) ** 2, [0, 1])
                worst = max(worst, abs(norm(r) / quad - 1))
    board.check("the boundary norms equal ∫φ² by quadrature (4 modes of each beam)", "F6",
                worst < 1e-20, f"max rel. diff {mp.nstr(worst, 2)}")  # fmt: skip

    # --- mass and stiffness at the damper's point ---------------------------------------------
    mass = {b: norms[b] / shapes[b] ** 2 for b in BEAMS}
    stiff = {b: k**4 * mass[b] for b in BEAMS}
    for beam in BEAMS:
        w(f"mass_coefficient_{beam}", mass[beam],
          f"The {NAMES[beam]}: M/(ρAL) of a mode referred to the point ξ, ∫φ²dξ/φ(ξ)².")  # fmt: skip
        w(f"stiffness_coefficient_{beam}", stiff[beam],
          f"The {NAMES[beam]}: K·L³/(EI) = k⁴·M/(ρAL), so that K/M = ω².")  # fmt: skip
    with mp.workdps(30):
        mid_ss = sp.lambdify((k, xi), mass["simply_supported"], "mpmath")(found["simply_supported"][0],
                                                                          mp.mpf("0.5"))  # fmt: skip
        mid_cc = sp.lambdify((k, xi), mass["clamped_clamped"], "mpmath")(found["clamped_clamped"][0],
                                                                         mp.mpf("0.5"))  # fmt: skip
        tip = sp.lambdify((k, xi), mass["cantilever"], "mpmath")(found["cantilever"][0], 1)
    board.check(
        "mode 1: M = ρAL/4 at the cantilever's tip, ρAL/2 at a simply supported midspan, "
        "0.3965 ρAL at a clamped–clamped one",
        "F6",
        abs(tip - mp.mpf(1) / 4) < 1e-25 and abs(mid_ss - mp.mpf(1) / 2) < 1e-25
        and abs(mid_cc - mp.mpf("0.3965")) < 5e-5,
        f"{mp.nstr(tip, 10)}, {mp.nstr(mid_ss, 10)}, {mp.nstr(mid_cc, 10)}",
    )  # fmt: skip

    # --- how many modes: the static flexibility ------------------------------------------------
    s = sp.Symbol("s", positive=True)  # position along the beam, in units of L
    a = sp.symbols("a0:4")
    b = sp.symbols("b0:4")
    left_piece = sum(a[i] * s**i for i in range(4))
    right_piece = sum(b[i] * s**i for i in range(4))
    flex = {}
    for beam, ((le, ri), _, _) in BEAMS.items():
        # EI w'''' = P δ(s − ξ₀), in units EI = P = L = 1: w, w', w'' continuous, w''' jumps by +1
        eqs = [sp.diff(left_piece, s, n).subs(s, 0) for n in ENDS[le]]
        eqs += [sp.diff(right_piece, s, n).subs(s, 1) for n in ENDS[ri]]
        eqs += [sp.diff(left_piece - right_piece, s, n).subs(s, x0) for n in range(3)]
        eqs.append(sp.diff(right_piece - left_piece, s, 3).subs(s, x0) - 1)
        sol = sp.solve(eqs, [*a, *b], dict=True)[0]
        flex[beam] = w(
            f"static_flexibility_{beam}",
            sp.factor(left_piece.subs(sol).subs(s, x0)),
            f"The {NAMES[beam]}'s deflection under a unit static force at ξ₀, in units of "
            "L³/(EI): EI w'''' = P δ(ξ − ξ₀) solved as two cubics joined at ξ₀ (w, w', w'' "
            "continuous, the shear jumping by P).",
        )
    textbook = {"cantilever": (1, sp.Rational(1, 3)), "simply_supported": (sp.Rational(1, 2),
                sp.Rational(1, 48)), "clamped_clamped": (sp.Rational(1, 2), sp.Rational(1, 192))}  # fmt: skip
    board.check(
        "L³/(3EI) at the cantilever's tip, L³/(48EI) and L³/(192EI) at the midspans",
        "F6",
        all(sp.simplify(flex[bm].subs(x0, p) - v) == 0 for bm, (p, v) in textbook.items()),
    )
    sums = {}
    with mp.workdps(30):
        for beam, (p, _) in textbook.items():
            rs = roots(beam, N_SUM, 30)
            fk = sp.lambdify((k, xi), 1 / stiff[beam], "mpmath")
            terms = [fk(r, mp.mpf(p)) for r in rs]
            exact = flex[beam].subs(x0, p)
            sums[beam] = [abs(1 - mp.fsum(terms[:n]) / exact) for n in (1, 2, 4, 8, 16, 32, 64)]
    w(
        "modal_sum_errors",
        {NAMES[bm]: [sp.Float(mp.nstr(e, 3), 3) for e in errs] for bm, errs in sums.items()},
        "Relative error of the modal sum Σᵢ₌₁ᴺ 1/Kᵢ against the static flexibility at the "
        "points above, for N = 1, 2, 4, 8, 16, 32, 64 (modes with a node at the point add "
        "nothing): each doubling of N divides it by about 8.",
    )
    rates = [errs[-2] / errs[-1] for errs in sums.values()]
    board.check("the modal sum converges as N⁻³", "F6",
                all(6 < r < 10 for r in rates) and all(e[-1] < 1e-5 for e in sums.values()),
                "error(32)/error(64) = " + ", ".join(mp.nstr(r, 4) for r in rates))  # fmt: skip

    # --- an impact at the point of an N-mode beam ---------------------------------------------
    # Each modal coordinate qᵢ is referred to the point (its displacement there, so φᵢ = 1 at the
    # point and x = Σqᵢ): an impulse P at the point changes each q̇ᵢ by P/Mᵢ, the impact mass's
    # velocity by −P/m.  Written for three modes; the pattern holds for any number.
    n_modes = 3
    Ms = sp.symbols(f"M_1:{n_modes + 1}", positive=True)
    vs = sp.symbols(f"qdot_1:{n_modes + 1}", real=True)
    m, e = sp.symbols("m", positive=True), sp.Symbol("e", nonnegative=True)
    u, P = sp.symbols("ydot_minus P", real=True)
    xdot = sum(vs)
    after = [v + P / Mi for v, Mi in zip(vs, Ms, strict=True)]
    newton = sp.Eq((u - P / m) - sum(after), -e * (u - xdot))
    impulse = w(
        "point_impulse",
        sp.factor(sp.solve(newton, P)[0]),
        "The impulse at the point of a beam of three modes (modal masses Mᵢ referred to the "
        "point): Newton's law on the point's relative velocity, each modal velocity jumping by "
        "P/Mᵢ and the impact mass's by −P/m.",
    )
    m_eff, zdot = sp.symbols("m_eff zdot_minus", positive=True)
    mu_eff = m * m_eff / (m + m_eff)
    general = w(
        "point_impulse_effective_mass",
        (1 + e) * mu_eff * zdot,
        "P = (1 + e)·μ·ż⁻ with μ = m·m<sub>eff</sub>/(m + m<sub>eff</sub>) and the effective "
        "mass at the point 1/m<sub>eff</sub> = Σᵢ 1/Mᵢ (ż⁻ = ẏ⁻ − ẋ⁻, ẋ = Σq̇ᵢ): the beam meets "
        "the impact mass as one mass.",
    )
    sum_inverse = sum(1 / Mi for Mi in Ms)
    board.check(
        "the impulse is (1 + e)·μ·ż⁻, μ the reduced mass of m and the effective mass (Σ 1/Mᵢ)⁻¹",
        "F6",
        sp.simplify(impulse - general.subs({m_eff: 1 / sum_inverse, zdot: u - xdot})) == 0,
    )
    energy = sum(Mi * v**2 for Mi, v in zip(Ms, vs, strict=True)) / 2 + m * u**2 / 2
    energy_after = (sum(Mi * a**2 for Mi, a in zip(Ms, after, strict=True)) / 2
                    + m * (u - P / m) ** 2 / 2)  # fmt: skip
    lost = sp.simplify((energy - energy_after).subs(P, impulse))
    board.check(
        "energy lost = ½·μ·(1 − e²)·ż⁻², as for two masses (Step 9)",
        "F6",
        sp.simplify(lost - (1 - e**2) * mu_eff.subs(m_eff, 1 / sum_inverse) * (u - xdot) ** 2 / 2)
        == 0,
    )
    # one mode: Step 9's law, ẋ⁺ = ẋ⁻ + (1 + e)·μ/M·(ẏ⁻ − ẋ⁻) with μ = mM/(m + M)
    Mo, xm = sp.symbols("M xdot_minus")
    one = (xm + general / Mo).subs({m_eff: Mo, zdot: u - xm})
    step9 = xm + (1 + e) * (m * Mo / (m + Mo)) / Mo * (u - xm)
    board.check("one mode gives Step 9's impact law", "F6", sp.simplify(one - step9) == 0)

    # --- kernels -----------------------------------------------------------------------------
    arg_k = Arg(
        k, "1", "Root βL of the beam's frequency equation (its BETA_L_… constant)", 3.0, 12.0
    )
    arg_xi = Arg(xi, "1", "Point ξ = r/L along the beam (0 < ξ < 1)", 0.2, 0.8)
    for beam in ("clamped_clamped", "simply_supported"):
        name = NAMES[beam]
        board.kernel(name=f"mode_shape_{beam}", args=(arg_k, arg_xi), expr=shapes[beam],
                     returns=f"Mode shape φ(ξ) of the {name}", unit="1", equation="F6",
                     lhs=r"\phi(\xi)")  # fmt: skip
        board.kernel(name=f"mass_coefficient_{beam}", args=(arg_k, arg_xi), expr=mass[beam],
                     returns=f"Mass M/(ρAL) of a mode of the {name} referred to the point ξ",
                     unit="1", equation="F6", lhs=r"\frac{M}{\rho A L}",
                     note="beta_L must be a root of the frequency equation.")  # fmt: skip
        board.kernel(name=f"stiffness_coefficient_{beam}", args=(arg_k, arg_xi),
                     expr=stiff[beam],
                     returns=f"Stiffness K·L³/(EI) of a mode of the {name} referred to the point ξ",
                     unit="1", equation="F6", lhs=r"\frac{K L^3}{E I}",
                     note="beta_L must be a root of the frequency equation.")  # fmt: skip
    board.kernel(
        name="point_impulse",
        args=(
            Arg(m, "kg", "Impact mass m", 0.01, 2.0, log=True),
            Arg(m_eff, "kg", "Effective mass of the beam at the point, 1/Σ(1/Mᵢ)", 0.1, 50.0,
                log=True),
            Arg(e, "1", "Coefficient of restitution e", 0.0, 1.0),
            Arg(zdot, "m/s", "Relative approach velocity ż⁻ = ẏ⁻ − ẋ⁻ at the point", 0.01, 2.0),
        ),
        expr=general,
        returns="Impulse P at the point of an N-mode beam; each modal velocity (mode referred to "
        "the point) jumps by P/Mᵢ, the impact mass's by −P/m",
        unit="N s",
        equation="F6",
        lhs="P",
    )  # fmt: skip
    arg_x0 = Arg(x0, "1", "Point ξ₀ = r₀/L of the static force (0 < ξ₀ ≤ 1)", 0.2, 0.9)
    for beam in BEAMS:
        board.kernel(name=f"static_flexibility_{beam}", args=(arg_x0,), expr=flex[beam],
                     returns=f"Static deflection of the {NAMES[beam]} at ξ₀ under a unit force "
                     "there, in units of L³/(EI)", unit="1", equation="F6",
                     lhs=r"\frac{w(\xi_0) E I}{P L^3}")  # fmt: skip
    return board
