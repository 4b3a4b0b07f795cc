r"""Step 9 — the rigid impact law: Newton's restitution coefficient.

Beyond the paper.  When the contact is much stiffer than the primary and much shorter than its
period, the contact phase can be replaced by an instantaneous impact.  Two laws fix the velocities
after it: the momentum of the pair is conserved (the contact force is internal, and finite forces
do no impulse in zero time), and the relative velocity is reversed and multiplied by Newton's
coefficient of restitution e ∈ [0, 1].  The energy lost follows, through the reduced mass
μ = mM/(m + M) of Step 6.  For the linear contact law of the paper (k1, c1) Step 6 gave
$e = \exp(-c_1 T/(2\mu))$ with $T = \pi/\omega_d$; solving it for c1 tells a user which contact damping to put in
the compliant model to get a wanted e.

The stability of motions through impacts needs one more object: the **saltation matrix** S, which
carries a small perturbation of the state (x, ẋ, z = y − x, ẏ) from just before an impact to just
after it.  A perturbed motion reaches the wall a little earlier or later, and in that time it
moves with the flight's vector field f⁻ before the impact and f⁺ after it; S is the jump map's
Jacobian plus that correction, $S = DR + (f^+ - DR\,f^-)\,\nabla g^T/(\nabla g\cdot f^-)$ with the
wall $g = s z - d/2$.  The board derives it from the impact law above and checks it against a
perturbed impact worked out to first order.
"""

from __future__ import annotations

import sympy as sp

from .board import Arg, Board


def derive() -> Board:
    board = Board("rigid_impact", "The rigid impact law", "F2")
    w = board.write
    m, M, k1 = sp.symbols("m M k1", positive=True)
    e = sp.Symbol("e", nonnegative=True)
    xm, ym, xp, yp = sp.symbols("xdot_minus ydot_minus xdot_plus ydot_plus", real=True)

    momentum = w(
        "momentum",
        sp.Eq(M * xp + m * yp, M * xm + m * ym),
        "Momentum of the pair is conserved through the impact.",
        "F2",
    )
    newton = w(
        "newton_restitution",
        sp.Eq(yp - xp, -e * (ym - xm)),
        "Newton's law: the relative velocity is reversed and multiplied by e.",
        "F2",
    )
    after = sp.solve([momentum, newton], [xp, yp], dict=True)[0]
    x_after = w(
        "main_velocity_after",
        sp.collect(sp.factor(after[xp] - xm), e) + xm,
        r"Main-mass velocity after the impact.",
        "F2",
    )
    y_after = w(
        "impact_velocity_after",
        sp.collect(sp.factor(after[yp] - ym), e) + ym,
        r"Impact-mass velocity after the impact.",
        "F2",
    )
    mu = m * M / (m + M)
    board.check(
        "the velocity jumps are ±(1 + e)·μ·(relative velocity)/mass",
        "F2",
        sp.simplify(x_after - (xm + (1 + e) * mu / M * (ym - xm))) == 0
        and sp.simplify(y_after - (ym - (1 + e) * mu / m * (ym - xm))) == 0,
    )
    kinetic = lambda a, b: M * a**2 / 2 + m * b**2 / 2  # noqa: E731
    loss = w(
        "energy_lost",
        sp.factor(kinetic(xm, ym) - kinetic(x_after, y_after)),
        "Kinetic energy lost in the impact.",
        "F2",
    )
    loss_mu = (1 - e**2) * mu * (ym - xm) ** 2 / 2
    board.check(
        "energy lost = ½·μ·(1 − e²)·v² (v the approach speed): none at e = 1, the most at e = 0",
        "F2",
        sp.simplify(loss - loss_mu) == 0,
    )

    # --- the linear law's c1 for a wanted e (inverting Step 6) -----------------------------------
    c1 = sp.Symbol("c1", positive=True)
    wd = sp.sqrt(k1 / mu - c1**2 / (4 * mu**2))
    restitution = w(
        "linear_restitution",
        sp.exp(-c1 * (sp.pi / wd) / (2 * mu)),
        r"Step 6: $e = \exp(-c_1 T/(2\mu))$, $T = \pi/\omega_d$.",
        "35",
    )
    L = sp.Symbol("L", positive=True)  # L = −ln e > 0 for 0 < e < 1
    solutions = sp.solve(sp.Eq(c1 * sp.pi / (2 * mu * wd), L), c1)
    (c1_of_L,) = [s for s in solutions if s.is_positive is not False]
    c1_value = w(
        "linear_c1_for_restitution",
        sp.simplify(c1_of_L.subs(L, -sp.log(e))),
        r"Solving $-\ln e = c_1\pi/(2\mu\omega_d)$ for $c_1$.",
        "F2",
    )
    board.check(
        "c1 = −2 ln(e)·√(k1 μ)/√(π² + ln² e) gives back e through Step 6",
        "F2",
        sp.simplify(
            c1_value - (-2 * sp.log(e) * sp.sqrt(k1 * mu) / sp.sqrt(sp.pi**2 + sp.log(e) ** 2))
        )
        == 0
        and sp.simplify((-c1 * sp.pi / (2 * mu * wd)).subs(c1, c1_value).subs(sp.log(e), -L) + L)
        == 0
        and restitution.args[0] == -c1 * sp.pi / (2 * mu * wd),
    )
    board.check(
        "c1²/(4 k1 μ) = ln²e/(π² + ln²e) < 1: never critical damping; c1 = 0 at e = 1",
        "F2",
        sp.simplify((c1_value**2 / (4 * k1 * mu)).subs(sp.log(e), -L) - L**2 / (sp.pi**2 + L**2))
        == 0
        and sp.simplify(c1_value.subs(e, 1)) == 0,
    )

    # --- the saltation matrix: perturbations through an impact ------------------------------
    C = sp.Symbol("C", nonnegative=True)
    x, v, z, u, am_ = sp.symbols("x xdot z ydot a_minus", real=True)
    s_ = sp.Symbol("s", real=True)
    q = sp.Matrix([x, v, z, u])

    def jump(state):  # R: positions kept, velocities by the impact law
        return sp.Matrix([
            state[0],
            x_after.subs({xm: state[1], ym: state[3]}),
            state[2],
            y_after.subs({xm: state[1], ym: state[3]}),
        ])  # fmt: skip

    DR = jump(q).jacobian(q)
    w_rel = u - v  # ż, the relative velocity at the wall
    v_plus, u_plus = x_after.subs({xm: v, ym: u}), y_after.subs({xm: v, ym: u})
    # the primary's acceleration is linear in its velocity with slope −C/M (Eq. F1), so across
    # the impact it changes by −C·Δẋ/M whatever the forcing
    a_plus = am_ - C * (v_plus - v) / M
    f_minus = sp.Matrix([v, am_, w_rel, 0])
    f_plus = sp.Matrix([v_plus, a_plus, u_plus - v_plus, 0])
    grad_g = sp.Matrix([[0, 0, s_, 0]])
    # S = DR + (f⁺ − DR f⁻) ∇gᵀ / (∇g · f⁻); its entries are written below, one by one
    S = (DR + (f_plus - DR * f_minus) * grad_g / (grad_g * f_minus)[0]).applyfunc(sp.simplify)
    board.check(
        "the wall's side s cancels: S is the same on both walls",
        "F2",
        all(not S[i, j].has(s_) for i in range(4) for j in range(4)),
    )
    # first-order check: perturb the state by ε·δ, fly with f⁻ to the (shifted) wall, jump, and
    # fly back with f⁺ to the unperturbed impact time; d/dε at 0 must be S·δ
    eps, dt_ = sp.symbols("epsilon Delta_t", real=True)
    delta = sp.Matrix(sp.symbols("d1:5", real=True))
    start = q + eps * delta
    shift = sp.solve(s_ * (start[2] + f_minus[2].subs(dict(zip(q, start, strict=True))) * dt_)
                     - s_ * z, dt_)[0]  # fmt: skip
    # (the wall is where the unperturbed state is: s·z = d/2 at ε = 0)
    arrived = start + f_minus.subs(dict(zip(q, start, strict=True))) * shift
    after = jump(arrived) - f_plus.subs(dict(zip(q, start, strict=True))) * shift
    first_order = sp.Matrix([sp.diff(c, eps).subs(eps, 0) for c in after])
    board.check(
        "S·δ is the first-order change of the state after a perturbed impact (flight with f⁻ to "
        "the wall, the jump, flight back with f⁺)",
        "F2",
        all(sp.simplify(c) == 0 for c in (first_order - S * delta)),
    )
    k_main = (1 + e) * m / (m + M)  # the velocity jumps' gains, (1 + e)·μ/M and (1 + e)·μ/m
    k_imp = (1 + e) * M / (m + M)
    board.check(
        "S = [[1, 0, k_M, 0], [0, 1 − k_M, k_M(a⁻/ż − C/M), k_M], [0, 0, −e, 0], "
        "[0, k_m, −k_m a⁻/ż, 1 − k_m]], k_M = (1 + e)μ/M, k_m = (1 + e)μ/m",
        "F2",
        all(
            sp.simplify(S[i, j] - ref) == 0
            for (i, j), ref in {
                (0, 2): k_main,
                (1, 1): 1 - k_main,
                (1, 2): k_main * (am_ / w_rel - C / M),
                (1, 3): k_main,
                (2, 2): -e,
                (3, 1): k_imp,
                (3, 2): -k_imp * am_ / w_rel,
                (3, 3): 1 - k_imp,
                (0, 0): 1,
                (2, 0): 0,
                (0, 1): 0,
                (3, 0): 0,
            }.items()
        ),
    )

    zd = sp.Symbol("zdot_minus", real=True)  # ż⁻ = ẏ − ẋ, the kernels' argument

    def on_zd(entry):
        return sp.factor(sp.simplify(entry.subs(u, zd + v)))

    w(
        "saltation_main_gain",
        sp.factor(S[0, 2]),
        r"The gain $k_M = (1+e)\mu/M$ of the main mass's velocity jump: S's row x, column z and "
        r"row ẋ, column ẏ.",
        "F2",
    )
    w(
        "saltation_impact_gain",
        sp.factor(S[3, 1]),
        r"The gain $k_m = (1+e)\mu/m$ of the impact mass's velocity jump: S's row ẏ, column ẋ.",
        "F2",
    )
    w(
        "saltation_main_velocity_z",
        on_zd(S[1, 2]),
        r"Row ẋ, column z of S: a perturbation of z moves the impact in time, and the main "
        r"mass's velocity after it by this much per metre.",
        "F2",
    )
    w(
        "saltation_impact_velocity_z",
        on_zd(S[3, 2]),
        r"Row ẏ, column z of S, the same for the impact mass; row z, column z is $-e$.",
        "F2",
    )

    am = Arg(m, "kg", "Impact mass m", 1e-3, 1.0, log=True)
    aM = Arg(M, "kg", "Main mass M", 0.05, 50.0, log=True)
    ae = Arg(e, "1", "Coefficient of restitution e", 0.0, 1.0)
    axm = Arg(xm, "m/s", "Main-mass velocity before the impact", -1.0, 1.0)
    aym = Arg(ym, "m/s", "Impact-mass velocity before the impact", -1.0, 1.0)
    args = (am, aM, ae, axm, aym)
    after = [
        board.kernel(
            name="main_velocity_after",
            args=args,
            expr=x_after,
            returns="Main-mass velocity after a rigid impact",
            unit="m/s",
            equation="F2",
            lhs=r"\dot{x}^+",
            magnitude=abs(xm) + abs(ym),
        )
    ]
    after.append(
        board.kernel(
            name="impact_velocity_after",
            args=args,
            expr=y_after,
            returns="Impact-mass velocity after a rigid impact",
            unit="m/s",
            equation="F2",
            lhs=r"\dot{y}^+",
            magnitude=abs(xm) + abs(ym),
        )
    )
    # The impact map's Jacobian in the velocities before it and in e (sympy.diff).
    slopes = [board.derivatives(k, ("e", "xdot_minus", "ydot_minus")) for k in after]
    board.bundle(
        "velocities_after_and_derivatives",
        [*after, *slopes[0], *slopes[1]],
        "Both velocities after a rigid impact and their derivatives in e, ẋ⁻, ẏ⁻ (the impact "
        "map's Jacobian)",
    )
    board.kernel(
        name="energy_lost",
        args=args,
        expr=loss_mu,
        returns="Kinetic energy lost in a rigid impact",
        unit="J",
        equation="F2",
        lhs=r"\Delta E",
    )
    board.kernel(
        name="linear_c1_for_restitution",
        args=(
            am,
            aM,
            Arg(k1, "N/m", "Linear contact stiffness k1", 1e3, 1e9, log=True),
            Arg(e, "1", "Wanted coefficient of restitution e (0 < e ≤ 1)", 0.01, 1.0),
        ),
        expr=c1_value,
        returns="Contact damping c1 of the linear law that gives the restitution e",
        unit="N s/m",
        equation="F2",
        lhs="c_1",
    )
    aw = Arg(zd, "m/s", "Relative velocity ż = ẏ − ẋ just before the impact (≠ 0)", 0.01, 2.0,
             log=True)  # fmt: skip
    aa = Arg(am_, "m/s^2", "Main-mass acceleration just before the impact", -100.0, 100.0)
    aC = Arg(C, "N s/m", "Main damping C", 0.0, 10.0)
    board.kernel(
        name="saltation_main_gain",
        args=(am, aM, ae),
        expr=k_main,
        returns="Gain k_M = (1 + e)μ/M of the main mass's velocity jump (saltation entries)",
        unit="1",
        equation="F2",
        lhs="k_M",
    )
    board.kernel(
        name="saltation_impact_gain",
        args=(am, aM, ae),
        expr=k_imp,
        returns="Gain k_m = (1 + e)μ/m of the impact mass's velocity jump (saltation entries)",
        unit="1",
        equation="F2",
        lhs="k_m",
    )
    board.kernel(
        name="saltation_main_velocity_z",
        args=(am, aM, ae, aC, aw, aa),
        expr=on_zd(S[1, 2]),
        returns="Saltation entry ∂ẋ⁺/∂z⁻: the main mass's velocity after the impact per unit "
        "of relative displacement before it",
        unit="1/s",
        equation="F2",
        lhs=r"S_{\dot{x} z}",
        magnitude=k_main * (sp.Abs(am_ / zd) + C / M),
    )
    board.kernel(
        name="saltation_impact_velocity_z",
        args=(am, aM, ae, aw, aa),
        expr=on_zd(S[3, 2]),
        returns="Saltation entry ∂ẏ⁺/∂z⁻: the impact mass's velocity after the impact per unit "
        "of relative displacement before it",
        unit="1/s",
        equation="F2",
        lhs=r"S_{\dot{y} z}",
    )
    return board
