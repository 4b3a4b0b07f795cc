r"""Step 16 — the flight under a sampled load: the primary between impacts when the force is a
record, not a sine.

Beyond the paper.  Machines and buildings see random vibration, shocks and run-ups through
resonance.  Such a load is known as samples p₀, p₁, … every Δt (a measured record, or one drawn
from a spectrum); joined by straight lines, it is linear on each interval, and on each interval the
primary's flight is again closed form — the piecewise-exact method of structural dynamics, exact
for the record as sampled.  On the board:

1. M ẍ + C ẋ + K x = p₀ + ṗ·τ on one interval (τ the time into it, ṗ the record's slope there).
   A base-acceleration record ẍ<sub>b</sub> enters the same way: the displacement relative to the
   base, u = x − x<sub>b</sub>, obeys M ü + C u̇ + K u = F − M ẍ<sub>b</sub>.
2. The particular solution by undetermined coefficients, a straight line (p₀ + ṗτ)/K − Cṗ/K²;
   the free decay of Step 7 corrects the initial state.
3. Checked three ways: it solves the equation with its initial state; it equals Duhamel's
   integral of the impulse response over the load (SymPy integrates it); and at C = 0 from rest it
   is the textbook step response p₀/K·(1 − cos ωₙτ) and ramp response (ṗ/K)(τ − sin(ωₙτ)/ωₙ).
4. The interval's update x(Δt) = A x₀ + B ẋ₀ + C′ p₀ + D′ p₁ (p₁ the next sample), whose A and B
   are the free vibration's.
"""

from __future__ import annotations

import sympy as sp

from .board import Arg, Board
from .free_flight import free_decay


def derive() -> Board:
    board = Board("sampled_load", "The flight under a sampled load", "F8")
    w = board.write
    t, s = sp.symbols("t s", nonnegative=True)
    M, K = sp.symbols("M K", positive=True)
    C = sp.Symbol("C", nonnegative=True)
    p0, pd, x0, xd0 = sp.symbols("p0 pdot x0 xdot0", real=True)
    a, b = sp.symbols("a b", real=True)
    x = sp.Function("x")

    load = p0 + pd * t
    eq_x = w(
        "sampled_load_equation",
        sp.Eq(M * x(t).diff(t, 2) + C * x(t).diff(t) + K * x(t), load),
        "The primary on one interval of a record joined by straight lines: the load p₀ at the "
        "interval's start, its slope ṗ = (p₁ − p₀)/Δt.  A base-acceleration record gives "
        "p = F − M·ẍ<sub>b</sub> for the displacement relative to the base.",
        "F8",
    )

    # --- the particular solution: a straight line ---------------------------------------------
    trial = a + b * t
    residual = sp.expand(eq_x.lhs.subs(x(t), trial).doit() - load)
    coefficients = sp.solve([residual.coeff(t, 0), residual.coeff(t, 1)], [a, b], dict=True)[0]
    particular = w(
        "sampled_load_particular",
        sp.expand(trial.subs(coefficients)),
        "Undetermined coefficients: a straight line a + bτ solves the equation with b = ṗ/K and "
        "a = p₀/K − Cṗ/K² (the damper's force Cb lowers the offset).",
        "F8",
    )
    board.check(
        "the particular solution is (p₀ + ṗτ)/K − Cṗ/K²",
        "F8",
        sp.simplify(particular - ((p0 + pd * t) / K - C * pd / K**2)) == 0,
    )

    # --- the general solution: Step 7's free decay corrects the initial state --------------------
    sigma = C / (2 * M)
    wd = sp.sqrt(K / M - C**2 / (4 * M**2))

    def decay(x_start, v_start, time=t):
        """Free decay from x = x_start, ẋ = v_start (Step 7)."""
        return free_decay(x_start, v_start, time, M, K, C)

    xp0, vp0 = particular.subs(t, 0), particular.diff(t).subs(t, 0)
    x_t = w(
        "sampled_load_displacement",
        particular + decay(x0 - xp0, xd0 - vp0),
        "x(τ) = the straight line + the free decay of the difference between the initial state "
        "and the line's.",
        "F8",
    )
    board.check(
        "x(τ) solves the equation with its initial state",
        "F8",
        sp.simplify((eq_x.lhs - eq_x.rhs).subs(x(t), x_t).doit()) == 0
        and sp.simplify(x_t.subs(t, 0) - x0) == 0
        and sp.simplify(x_t.diff(t).subs(t, 0) - xd0) == 0,
    )
    # Duhamel: the free response plus the load convolved with the impulse response h(τ), the
    # free decay from x = 0, ẋ = 1/M (a unit impulse); SymPy integrates it.  Checked at
    # underdamped numbers (the symbolic integral over general C is slow to simplify).
    h = decay(0, 1 / M, t - s)
    numbers = {M: sp.Rational(3, 2), K: 600, C: sp.Rational(9, 10), p0: sp.Rational(7, 3),
               pd: -11, x0: sp.Rational(1, 50), xd0: sp.Rational(-3, 10)}  # fmt: skip
    duhamel = decay(x0, xd0).subs(numbers) + sp.integrate(
        sp.expand((h * load.subs(t, s)).subs(numbers)), (s, 0, t)
    )
    tau = sp.Rational(37, 100)
    gap = sp.N((duhamel - x_t.subs(numbers)).subs(t, tau), 40)
    board.check(
        "x(τ) equals Duhamel's integral of the impulse response over the load",
        "F8",
        abs(gap) < sp.Float(1e-30),
        f"difference {float(gap):.1e} at τ = 0.37 s (M 1.5 kg, K 600 N/m, C 0.9 N s/m), 40 digits",
    )
    wn = sp.sqrt(K / M)
    undamped = x_t.subs(C, 0)
    board.check(
        "at C = 0 from rest: the textbook step response p₀/K·(1 − cos ωₙτ) and ramp response "
        "(ṗ/K)(τ − sin(ωₙτ)/ωₙ)",
        "F8",
        sp.simplify(undamped.subs({x0: 0, xd0: 0, pd: 0}) - p0 / K * (1 - sp.cos(wn * t))) == 0
        and sp.simplify(undamped.subs({x0: 0, xd0: 0, p0: 0}) - pd / K * (t - sp.sin(wn * t) / wn))
        == 0,
    )
    xd_t = w("sampled_load_velocity", sp.diff(x_t, t), "ẋ(τ).", "F8")

    # --- the interval's update: a recurrence over the record ----------------------------------
    dt, p1 = sp.symbols("Delta_t p1", positive=True)
    update = sp.expand(x_t.subs(pd, (p1 - p0) / dt).subs(t, dt))
    names = {x0: "A", xd0: "B", p0: "C′", p1: "D′"}
    parts = {v: sp.simplify(update.coeff(v)) for v in names}
    w(
        "sampled_load_update",
        sp.Add(*(sp.Symbol(names[v]) * v for v in names)),
        "Over a whole interval Δt: x(Δt) = A x₀ + B ẋ₀ + C′ p₀ + D′ p₁, p₁ the next sample; the "
        "four coefficients depend on M, K, C and Δt only, so a record of any length is one "
        "recurrence.",
        "F8",
    )
    board.check(
        "the update's coefficients rebuild x(Δt), and A, B are the free vibration's",
        "F8",
        sp.simplify(sum(parts[v] * v for v in names) - update) == 0
        and sp.simplify(parts[x0] - decay(1, 0).subs(t, dt)) == 0
        and sp.simplify(parts[xd0] - decay(0, 1).subs(t, dt)) == 0,
    )

    at = Arg(t, "s", "Time into the interval", 0.0, 0.1)
    aM = Arg(M, "kg", "Main mass M", 0.05, 50.0, log=True)
    aK = Arg(K, "N/m", "Main stiffness K", 10.0, 1e6, log=True)
    aC = Arg(C, "N s/m", "Main damping C (underdamped: C < 2√(KM))", 0.0, 0.3)
    ap = Arg(p0, "N", "Load at the interval's start p₀", -10.0, 10.0)
    apd = Arg(pd, "N/s", "The load's slope over the interval ṗ", -1e3, 1e3)
    ax = Arg(x0, "m", "Main-mass displacement at the interval's start", -1e-2, 1e-2)
    axd = Arg(xd0, "m/s", "Main-mass velocity at the interval's start", -1.0, 1.0)
    args = (at, aM, aK, aC, ap, apd, ax, axd)
    # rounding scale: the line's size and the decay's, which cancel as the flight settles
    line = (abs(p0) + abs(pd) * t + C * abs(pd) / K) / K
    start = abs(x0 - xp0) + abs((xd0 - vp0) / wd) + abs(sigma * (x0 - xp0) / wd)
    x_kernel = board.kernel(
        name="ramp_displacement",
        args=args,
        expr=x_t,
        returns="Main-mass displacement x(τ) under a load linear in τ",
        unit="m",
        equation="F8",
        lhs="x(τ)",
        magnitude=line + start * sp.exp(-sigma * t),
    )
    v_kernel = board.kernel(
        name="ramp_velocity",
        args=args,
        expr=xd_t,
        returns="Main-mass velocity ẋ(τ) under a load linear in τ",
        unit="m/s",
        equation="F8",
        lhs=r"\dot{x}(τ)",
        magnitude=abs(pd) / K + start * wn * sp.exp(-sigma * t),
    )
    board.bundle("ramp_state", [x_kernel, v_kernel],
                 "The primary's displacement and velocity τ into an interval of a sampled load "
                 "(x, ẋ)")  # fmt: skip
    return board
