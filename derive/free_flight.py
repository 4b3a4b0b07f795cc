r"""Step 7 — free flight between impacts in closed form (paper Eq. 7).

While abs(y − x) < d/2 the masses do not touch: Mẍ + Cẋ + Kx = 0 and mÿ = 0.  The main mass is a
damped oscillator, $\omega_n = \sqrt{K/M}$, $\zeta = C/(2\sqrt{KM})$; for ζ < 1 (the beams of
interest are lightly damped) SymPy's ``dsolve`` gives the decaying cosine/sine pair, written here
with the damped frequency $\omega_d = \omega_n\sqrt{1 - \zeta^2}$.  The impact mass flies at
constant speed.
"""

from __future__ import annotations

import sympy as sp

from .board import Arg, Board


def free_decay(a, b, t, M, K, C):
    """Step 7's free decay of the primary from x = a, ẋ = b a time t later:
    e^(−σt)(a cos ω_d t + (b + σa)/ω_d · sin ω_d t), σ = C/(2M), ω_d = √(K/M − C²/(4M²)) (ζ < 1).
    The later steps correct an initial state with it."""
    sigma = C / (2 * M)
    wd = sp.sqrt(K / M - C**2 / (4 * M**2))
    return sp.exp(-sigma * t) * (a * sp.cos(wd * t) + (b + sigma * a) / wd * sp.sin(wd * t))


def derive() -> Board:
    board = Board("free_flight", "Free flight between impacts", "7")
    w = board.write
    t = sp.Symbol("t", nonnegative=True)
    M, K = sp.symbols("M K", positive=True)
    C = sp.Symbol("C", nonnegative=True)
    x0, xd0, y0, yd0 = sp.symbols("x0 xdot0 y0 ydot0", real=True)
    x, y = sp.Function("x"), sp.Function("y")

    eq_x = w(
        "main_mass_equation",
        sp.Eq(M * x(t).diff(t, 2) + C * x(t).diff(t) + K * x(t), 0),
        "Main mass between impacts.",
        "7",
    )
    eq_y = w("impact_mass_equation", sp.Eq(y(t).diff(t, 2), 0), "Impact mass between impacts.", "7")
    sigma = w("decay_rate", C / (2 * M), r"Decay rate $\sigma = \zeta\omega_n = C/(2M)$.", "7")
    wd = sp.Symbol("omega_d", positive=True)
    wd_value = w(
        "damped_frequency",
        sp.sqrt(K / M - C**2 / (4 * M**2)),
        r"Damped frequency $\omega_d$ (ζ < 1).",
        "7",
    )
    # dsolve with K written through ω_d keeps the underdamped branch explicit.
    K_of_wd = M * (wd**2 + sigma**2)
    sol = sp.dsolve(
        eq_x.lhs.subs(K, K_of_wd), x(t), ics={x(0): x0, x(t).diff(t).subs(t, 0): xd0}
    ).rhs
    x_t = w(
        "main_mass_displacement",
        sp.simplify(sp.expand_complex(sp.simplify(sol))),
        "Main-mass displacement; dsolve with the initial state (x₀, ẋ₀).",
        "7",
    )
    board.check(
        "x(t) solves Eq. 7 with its initial state",
        "7",
        sp.simplify(eq_x.lhs.subs(K, K_of_wd).subs(x(t), x_t).doit()) == 0
        and sp.simplify(x_t.subs(t, 0) - x0) == 0
        and sp.simplify(x_t.diff(t).subs(t, 0) - xd0) == 0,
    )
    reference = sp.exp(-sigma * t) * (
        x0 * sp.cos(wd * t) + (xd0 + sigma * x0) / wd * sp.sin(wd * t)
    )
    board.check("x(t) is the decaying cosine/sine pair", "7", sp.simplify(x_t - reference) == 0)
    x_t = reference.subs(wd, wd_value)
    xd_t = w("main_mass_velocity", sp.diff(reference, t).subs(wd, wd_value), "ẋ(t).", "7")
    y_t = w(
        "impact_mass_displacement",
        sp.dsolve(eq_y, y(t), ics={y(0): y0, y(t).diff(t).subs(t, 0): yd0}).rhs,
        "Impact mass: constant velocity.",
        "7",
    )
    board.check("y(t) = y₀ + ẏ₀t", "7", sp.expand(y_t - (y0 + yd0 * t)) == 0)

    at = Arg(t, "s", "Time since the last event", 0.0, 2.0)
    aM = Arg(M, "kg", "Main mass M", 0.05, 50.0, log=True)
    aK = Arg(K, "N/m", "Main stiffness K", 10.0, 1e6, log=True)
    aC = Arg(C, "N s/m", "Main damping C (underdamped: C < 2√(KM))", 0.0, 0.3)
    ax = Arg(x0, "m", "Main-mass displacement at t = 0", -1e-2, 1e-2)
    axd = Arg(xd0, "m/s", "Main-mass velocity at t = 0", -1.0, 1.0)
    args = (at, aM, aK, aC, ax, axd)
    amp = sp.sqrt(x0**2 + ((xd0 + sigma * x0) / wd_value) ** 2)
    board.kernel(
        name="main_mass_displacement",
        args=args,
        expr=x_t,
        returns="Main-mass displacement x(t) in free flight",
        unit="m",
        equation="7",
        lhs="x(t)",
        magnitude=amp * sp.exp(-sigma * t),
    )
    board.kernel(
        name="main_mass_velocity",
        args=args,
        expr=xd_t,
        returns="Main-mass velocity ẋ(t) in free flight",
        unit="m/s",
        equation="7",
        lhs=r"\dot{x}(t)",
        magnitude=amp * sp.sqrt(K / M) * sp.exp(-sigma * t),
    )
    board.kernel(
        name="impact_mass_velocity",
        args=(at, Arg(yd0, "m/s", "Impact-mass velocity", -1.0, 1.0)),
        expr=sp.diff(y_t, t) + 0 * t,
        returns="Impact-mass velocity ẏ(t) in free flight",
        unit="m/s",
        equation="7",
        lhs=r"\dot{y}(t)",
    )
    board.kernel(
        name="impact_mass_displacement",
        args=(
            at,
            Arg(y0, "m", "Impact-mass displacement at t = 0", -1e-2, 1e-2),
            Arg(yd0, "m/s", "Impact-mass velocity at t = 0", -1.0, 1.0),
        ),
        expr=y_t,
        returns="Impact-mass displacement y(t) in free flight",
        unit="m",
        equation="7",
        lhs="y(t)",
        magnitude=abs(y0) + abs(yd0) * t,
    )
    return board
