r"""Step 9 — the rigid impact law: Newton's restitution coefficient.

Beyond the paper.  When the contact is much stiffer than the primary and much shorter than its
period, the contact phase can be replaced by an instantaneous impact.  Two laws fix the velocities
after it: the momentum of the pair is conserved (the contact force is internal, and finite forces
do no impulse in zero time), and the relative velocity is reversed and multiplied by Newton's
coefficient of restitution e ∈ [0, 1].  The energy lost follows, through the reduced mass
μ = mM/(m + M) of Step 6.  For the linear contact law of the paper (k1, c1) Step 6 gave
$e = \exp(-c_1 T/(2\mu))$ with $T = \pi/\omega_d$; solving it for c1 tells a user which contact damping to put in
the compliant model to get a wanted e.
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

    am = Arg(m, "kg", "Impact mass m", 1e-3, 1.0, log=True)
    aM = Arg(M, "kg", "Main mass M", 0.05, 50.0, log=True)
    ae = Arg(e, "1", "Coefficient of restitution e", 0.0, 1.0)
    axm = Arg(xm, "m/s", "Main-mass velocity before the impact", -1.0, 1.0)
    aym = Arg(ym, "m/s", "Impact-mass velocity before the impact", -1.0, 1.0)
    args = (am, aM, ae, axm, aym)
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
    return board
