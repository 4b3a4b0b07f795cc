r"""Step 8 — forced free flight: the primary between impacts under harmonic forcing.

Beyond the paper.  Impact dampers exist to fight forced vibration, so the primary is now driven,
either by a force $F_0\cos(\Omega t + \varphi)$ on the main mass or by base motion
$x_b = X_b\cos(\Omega t + \varphi)$ (the primary's spring and damper attach to the moving base):

$$M\ddot x + C(\dot x - \dot x_b) + K(x - x_b) = F_0\cos(\Omega t + \varphi).$$

Moving the base terms to the right gives one harmonic right-hand side
$P\cos(\Omega t + \varphi) + Q\sin(\Omega t + \varphi)$ with $P = F_0 + KX_b$ and
$Q = -C\Omega X_b$, so both kinds of forcing share one solution.  It is the steady (particular)
solution found by undetermined coefficients plus the free decay of Step 7 that corrects the
initial state.  At the undamped resonance (C = 0, $\Omega = \omega_n$) the undetermined coefficients have no
solution; the particular solution grows like t there, and the kernel takes that branch instead of
dividing by zero.  The impact mass still flies at constant speed (Step 7).
"""

from __future__ import annotations

import sympy as sp

from .board import Arg, Board
from .free_flight import free_decay


def derive() -> Board:
    board = Board("forced_flight", "Forced free flight between impacts", "F1")
    w = board.write
    t = sp.Symbol("t", nonnegative=True)
    M, K, W = sp.symbols("M K Omega", positive=True)
    C = sp.Symbol("C", nonnegative=True)
    F0, Xb, phi, x0, xd0 = sp.symbols("F0 X_b phi x0 xdot0", real=True)
    P, Q, A, B = sp.symbols("P Q A B", real=True)
    x = sp.Function("x")
    theta = W * t + phi

    base = Xb * sp.cos(theta)
    eq_x = w(
        "forced_equation",
        sp.Eq(
            M * x(t).diff(t, 2) + C * (x(t).diff(t) - base.diff(t)) + K * (x(t) - base),
            F0 * sp.cos(theta),
        ),
        r"Main mass between impacts, forced by $F_0\cos(\Omega t+\varphi)$ and by base motion "
        r"$X_b\cos(\Omega t+\varphi)$.",
    )
    lhs_free = M * x(t).diff(t, 2) + C * x(t).diff(t) + K * x(t)
    rhs = sp.expand(eq_x.rhs - (eq_x.lhs - lhs_free))
    P_value = w("P", rhs.coeff(sp.cos(theta)), r"Cosine part of the right-hand side, $P$.")
    Q_value = w("Q", rhs.coeff(sp.sin(theta)), r"Sine part of the right-hand side, $Q$.")
    board.check(
        "base motion and force become P cos + Q sin",
        "F1",
        sp.simplify(rhs - (P_value * sp.cos(theta) + Q_value * sp.sin(theta))) == 0
        and sp.simplify(P_value - (F0 + K * Xb)) == 0
        and sp.simplify(Q_value + C * W * Xb) == 0,
    )

    # --- the steady solution by undetermined coefficients -------------------------------------
    trial = A * sp.cos(theta) + B * sp.sin(theta)
    residual = sp.expand(lhs_free.subs(x(t), trial).doit() - P * sp.cos(theta) - Q * sp.sin(theta))
    coefficients = sp.solve(
        [residual.coeff(sp.cos(theta)), residual.coeff(sp.sin(theta))], [A, B], dict=True
    )[0]
    D = (K - M * W**2) ** 2 + (C * W) ** 2
    # Written over the unexpanded denominator: expanded, K² − 2KMΩ² + M²Ω⁴ would cancel near
    # resonance and lose the digits this form keeps.
    A_value = w(
        "steady_cosine",
        ((K - M * W**2) * P - C * W * Q) / D,
        r"Coefficient $A$ of $\cos(\Omega t+\varphi)$ in the steady solution.",
    )
    B_value = w(
        "steady_sine",
        (C * W * P + (K - M * W**2) * Q) / D,
        r"Coefficient $B$ of $\sin(\Omega t+\varphi)$ in the steady solution.",
    )
    board.check(
        "undetermined coefficients: A and B over (K − MΩ²)² + (CΩ)², zero only at C = 0, Ω = ωₙ",
        "F1",
        sp.simplify(A_value - coefficients[A]) == 0 and sp.simplify(B_value - coefficients[B]) == 0,
    )
    steady = (A_value * sp.cos(theta) + B_value * sp.sin(theta)).subs({P: P_value, Q: Q_value})
    board.check(
        "the steady solution solves the forced equation",
        "F1",
        sp.simplify((eq_x.lhs - eq_x.rhs).subs(x(t), steady).doit()) == 0,
    )
    amplitude = w(
        "steady_amplitude",
        sp.sqrt(P**2 + Q**2) / sp.sqrt(D),
        r"Its amplitude $\sqrt{A^2+B^2} = \sqrt{P^2+Q^2}/\sqrt{(K-M\Omega^2)^2+(C\Omega)^2}$: the "
        "linear frequency response of the primary without the damper.",
    )
    board.check(
        "amplitude² = A² + B²",
        "F1",
        sp.simplify(amplitude**2 - (A_value**2 + B_value**2)) == 0,
    )

    # --- the free decay that corrects the initial state (Step 7's solution) --------------------
    sigma = C / (2 * M)
    wd = sp.sqrt(K / M - C**2 / (4 * M**2))

    def decay(a, b):
        """Free decay from x = a, ẋ = b (Step 7)."""
        return free_decay(a, b, t, M, K, C)

    xs0, vs0 = steady.subs(t, 0), steady.diff(t).subs(t, 0)
    general = w(
        "forced_displacement_general",
        steady + decay(x0 - xs0, xd0 - vs0),
        r"$x(t)$ = steady solution + free decay of the difference between the initial state and "
        "the steady solution's.",
    )
    board.check(
        "x(t) solves the forced equation with its initial state",
        "F1",
        sp.simplify((eq_x.lhs - eq_x.rhs).subs(x(t), general).doit()) == 0
        and sp.simplify(general.subs(t, 0) - x0) == 0
        and sp.simplify(general.diff(t).subs(t, 0) - xd0) == 0,
    )

    # --- the undamped resonance ----------------------------------------------------------------
    resonant_eq = sp.Eq(
        M * x(t).diff(t, 2) + M * W**2 * x(t), F0 * sp.cos(theta) + M * W**2 * Xb * sp.cos(theta)
    )
    resonant = w(
        "forced_displacement_resonant",
        sp.simplify(sp.dsolve(resonant_eq, x(t), ics={x(0): x0, x(t).diff(t).subs(t, 0): xd0}).rhs),
        r"At C = 0 and $\Omega = \omega_n = \sqrt{K/M}$ (K = MΩ²) dsolve gives a response that "
        "grows like t.",
    )
    resonant_limit = sp.limit(
        general.subs(C, 0).subs(K, M * sp.Symbol("w", positive=True) ** 2),
        sp.Symbol("w", positive=True),
        W,
    )
    board.check(
        "the resonant response is the limit Ω → ωₙ of the undamped general one",
        "F1",
        sp.simplify(sp.expand_trig(resonant_limit - resonant)) == 0,
    )
    at_resonance = sp.And(sp.Eq(C, 0), sp.Eq(K, M * W**2))
    x_t = sp.Piecewise((resonant.subs(M * W**2, K), at_resonance), (general, True))
    board.check(
        "the resonant branch solves its equation",
        "F1",
        sp.simplify((resonant_eq.lhs - resonant_eq.rhs).subs(x(t), resonant).doit()) == 0,
    )
    xd_t = sp.Piecewise(
        (sp.diff(resonant, t).subs(M * W**2, K), at_resonance), (sp.diff(general, t), True)
    )

    at = Arg(t, "s", "Time since the last event", 0.0, 2.0)
    aM = Arg(M, "kg", "Main mass M", 0.05, 50.0, log=True)
    aK = Arg(K, "N/m", "Main stiffness K", 10.0, 1e6, log=True)
    aC = Arg(C, "N s/m", "Main damping C (underdamped: C < 2√(KM))", 0.0, 0.3)
    aF = Arg(F0, "N", "Force amplitude F0 on the main mass", -10.0, 10.0)
    aXb = Arg(Xb, "m", "Base-motion amplitude X_b", -1e-2, 1e-2)
    aW = Arg(W, "rad/s", "Forcing frequency Ω", 1.0, 1000.0, log=True)
    aphi = Arg(phi, "rad", "Forcing phase at t = 0, φ", -3.15, 3.15)
    ax = Arg(x0, "m", "Main-mass displacement at t = 0", -1e-2, 1e-2)
    axd = Arg(xd0, "m/s", "Main-mass velocity at t = 0", -1.0, 1.0)
    args = (at, aM, aK, aC, aF, aXb, aW, aphi, ax, axd)
    # Rounding scale: the steady amplitude and the free decay's, which cancel near resonance.
    amp_s = amplitude.subs({P: P_value, Q: Q_value})
    amp_d = sp.sqrt((x0 - xs0) ** 2 + ((xd0 - vs0 + sigma * (x0 - xs0)) / wd) ** 2)
    x_kernel = board.kernel(
        name="forced_displacement",
        args=args,
        expr=x_t,
        returns="Main-mass displacement x(t) in forced free flight",
        unit="m",
        equation="F1",
        lhs="x(t)",
        magnitude=amp_s + amp_d * sp.exp(-sigma * t),
    )
    v_kernel = board.kernel(
        name="forced_velocity",
        args=args,
        expr=xd_t,
        returns="Main-mass velocity ẋ(t) in forced free flight",
        unit="m/s",
        equation="F1",
        lhs=r"\dot{x}(t)",
        magnitude=(amp_s * W + amp_d * sp.sqrt(K / M) * sp.exp(-sigma * t)),
    )
    # The flight's transition matrix ∂(x, ẋ)/∂(x0, ẋ0), its vector field ∂/∂t and its
    # derivatives in the forcing (F0, X_b, φ): sympy.diff of the two kernels.  Not in M, K, Ω:
    # they decide the resonant case, where differentiating case by case would be wrong.
    slopes = {k.name: board.derivatives(k, ("t", "x0", "xdot0", "F0", "X_b", "phi"))
              for k in (x_kernel, v_kernel)}  # fmt: skip
    by_arg = {k.name: {d.derivative_of[1]: d for d in ds} for k, ds in
              ((x_kernel, slopes[x_kernel.name]), (v_kernel, slopes[v_kernel.name]))}  # fmt: skip
    board.bundle("forced_state", [x_kernel, v_kernel],
                 "The primary's displacement and velocity a time t into a flight (x, ẋ)")  # fmt: skip
    board.bundle(
        "forced_transition",
        [x_kernel, v_kernel, *(by_arg[k.name][a] for k in (x_kernel, v_kernel)
                               for a in ("x0", "xdot0"))],
        "The state after a flight and its transition matrix: x, ẋ, ∂x/∂x0, ∂x/∂ẋ0, ∂ẋ/∂x0, "
        "∂ẋ/∂ẋ0",
    )  # fmt: skip
    # ∂/∂Ω, which the continuation in Ω needs: case by case off the resonant set; on it (C = 0,
    # K = MΩ²) the limit of the undamped general derivative as the natural frequency tends to Ω,
    # as the value's own resonant case is the limit of the general response.
    wn = sp.Symbol("w", positive=True)
    for k, g, what in (
        (x_kernel, general, "displacement"),
        (v_kernel, general.diff(t), "velocity"),
    ):
        lim = w(
            f"{k.name}_d_Omega_resonant",
            sp.simplify(sp.limit(g.subs(C, 0).diff(W).subs(K, M * wn**2), wn, W)),
            f"∂/∂Ω of the flight's {what} at resonance: the limit ωₙ → Ω of the undamped general "
            "derivative.",
            "F1",
        )
        near = {M: sp.Rational(13, 10), W: 27, t: sp.Rational(7, 10), C: 0, F0: 2,
                Xb: sp.Rational(1, 1000), phi: sp.Rational(3, 10), x0: sp.Rational(1, 100),
                xd0: sp.Rational(1, 5)}  # fmt: skip
        # the general derivative a relative 1e-30 off resonance, at 80 digits
        off = sp.N(
            g.diff(W).subs({**near, K: near[M] * near[W] ** 2 * (1 + sp.Rational(1, 10**30))}), 80
        )
        on = sp.N(lim.subs(near), 80)
        board.check(
            f"the {what}'s ∂/∂Ω at resonance is the limit of the general derivative",
            "F1",
            abs(off - on) <= sp.Float(1e-20) * abs(on),
            f"{sp.N(on, 12)} at the resonance, {sp.N(off, 12)} a relative 1e-30 off it",
        )
        d = sp.Piecewise((lim, at_resonance), (g.diff(W), True))
        board.derivatives(k, ("Omega",), given={"Omega": d})
    # --- the flight in its own time: its coefficients once, its values at many t -------------
    # An event-driven run evaluates one flight at many times (an impact search's steps, their
    # refinement, the periods' maxima), and a structure's modes are all driven at one Ω.  In the
    # five functions of t that Eq. F1 is made of,
    #   x(t) = a·cos Ωt + b·sin Ωt + e^(−σt)·(c·cos ω_d t + s·sin ω_d t),
    # and ẋ(t) in the same five with its own a, b, c, s, every coefficient is a constant of the
    # flight: a run computes them once a flight and then, at each t, two cosines, two sines
    # and an exponential (cos Ωt and sin Ωt shared by the modes) instead of Eq. F1's ten.
    cW, sW, cD, sD, eD = sp.symbols("cW sW cD sD eD", real=True)
    five = {sp.cos(W * t): cW, sp.sin(W * t): sW, sp.cos(wd * t): cD, sp.sin(wd * t): sD,
            sp.exp(-sigma * t): eD}  # fmt: skip
    a_, b_, c_, s_ = sp.symbols("a b c s", real=True)
    sig_, wd_ = sp.symbols("sigma omega_d", positive=True)
    w(
        "flight_form",
        sp.Eq(
            x(t),
            a_ * sp.cos(W * t)
            + b_ * sp.sin(W * t)
            + sp.exp(-sig_ * t) * (c_ * sp.cos(wd_ * t) + s_ * sp.sin(wd_ * t)),
        ),
        r"The same flight in its own time: $\cos(\Omega t+\varphi)$ and $\sin(\Omega t+\varphi)$ "
        r"split by the angle-sum formulas leave five functions of t, and a, b, c, s (and ẋ's own "
        r"four) are constants of the flight, computed once by the kernel ``flight_form``.",
        "F1",
    )
    form_args = (aM, aK, aC, aF, aXb, aW, aphi, ax, axd)
    form_parts = []
    for what, expr, lhs, unit, size in (
        ("displacement", general, "x", "m", (amp_s, amp_d)),
        ("velocity", general.diff(t), r"\dot{x}", "m/s", (amp_s * W, amp_d * sp.sqrt(K / M))),
    ):
        # cos(Ωt + φ) and sin(Ωt + φ) split by the angle-sum formulas; then no t is left
        in_five = sp.expand_trig(expr).subs(five)
        coefficients = {
            "a": in_five.diff(cW).subs({cW: 0, sW: 0, eD: 0}),
            "b": in_five.diff(sW).subs({cW: 0, sW: 0, eD: 0}),
            "c": in_five.diff(eD).diff(cD).subs({cD: 0, sD: 0}),
            "s": in_five.diff(eD).diff(sD).subs({cD: 0, sD: 0}),
        }
        rebuilt = (coefficients["a"] * cW + coefficients["b"] * sW
                   + eD * (coefficients["c"] * cD + coefficients["s"] * sD))  # fmt: skip
        sample = {M: sp.Rational(13, 10), K: 900, C: sp.Rational(3, 10), F0: 2,
                  Xb: sp.Rational(1, 1000), W: 27, phi: sp.Rational(3, 10),
                  x0: sp.Rational(1, 100), xd0: sp.Rational(1, 5), t: sp.Rational(7, 10)}  # fmt: skip
        back = rebuilt.subs({cW: sp.cos(W * t), sW: sp.sin(W * t), cD: sp.cos(wd * t),
                             sD: sp.sin(wd * t), eD: sp.exp(-sigma * t)})  # fmt: skip
        board.check(
            f"the flight's {what} in its own time: four coefficients free of t, of cos Ωt, "
            "sin Ωt and the decaying cosine and sine",
            "F1",
            not in_five.has(t)
            and all(not v.has(t, cW, sW, cD, sD, eD) for v in coefficients.values())
            and abs(sp.N((back - expr).subs(sample), 60)) < sp.Float(1e-50),
        )
        for part, value in coefficients.items():
            steady = part in "ab"
            form_parts.append(board.kernel(
                name=f"flight_{what}_{part}",
                args=form_args,
                expr=value,
                returns=(f"Coefficient {part} of the flight's {what} "
                         + ("(of cos Ωt" if part == "a" else "(of sin Ωt" if part == "b"
                            else "(of the decaying cosine" if part == "c"
                            else "(of the decaying sine")
                         + ", t since the flight began; off the undamped resonance)"),
                unit=unit,
                equation="F1",
                lhs=f"{part}_{{{lhs}}}",
                magnitude=size[0] if steady else size[1],
            ))  # fmt: skip
    for name, value, what, unit in ((
            "flight_decay_rate", sigma, "Decay rate σ = C/(2M) of the flight's free part", "1/s"), (
            "flight_damped_frequency", wd, "Damped frequency of the flight's free part",
            "rad/s")):  # fmt: skip
        form_parts.append(board.kernel(name=name, args=form_args, expr=value, returns=what,
                                       unit=unit, equation="F1",
                                       lhs=r"\sigma" if "decay" in name else r"\omega_d"))  # fmt: skip
    board.bundle("flight_form", form_parts,
                 "The flight's coefficients in its own time: a, b, c, s of x, then of ẋ, then σ "
                 "and the damped frequency")  # fmt: skip
    for name, coefficient, which in (
        ("steady_cosine", A_value, "cos"),
        ("steady_sine", B_value, "sin"),
    ):
        board.kernel(
            name=name,
            args=(aM, aK, aC, aF, aXb, aW),
            expr=coefficient.subs({P: P_value, Q: Q_value}),
            returns=f"Coefficient of {which}(Ωt + φ) in the steady solution of the primary",
            unit="m",
            equation="F1",
            lhs="A" if which == "cos" else "B",
            magnitude=amp_s,
        )
    board.kernel(
        name="linear_amplitude",
        args=(aM, aK, aC, aF, aXb, aW),
        expr=amp_s,
        returns="Steady amplitude of the primary without the damper (linear frequency response)",
        unit="m",
        equation="F1",
        lhs=r"\hat{x}",
    )
    return board
