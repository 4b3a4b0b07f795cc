"""Helpers shared by test modules: random physical points for a kernel (the tests against
mpmath, the C and Octave targets), the external tools a test needs (a C compiler, Octave), and
an integration of the forced impact pair independent of symimpact."""

from __future__ import annotations

import math
import os
import shutil

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp


def require_tool(name: str) -> str:
    """Path of the program ``name``; a missing one fails on CI (``CI`` set), else skips."""
    path = shutil.which(name)
    if path is None:
        if os.environ.get("CI"):
            pytest.fail(f"{name} is not installed (.ci/run installs it)")
        pytest.skip(f"{name} is not installed")
    return path


def physical_points(kernel, rng: np.random.Generator, n: int) -> np.ndarray:
    """(n, number of arguments) points for ``kernel`` (a Kernel or a FixedPoint): each argument
    uniform or log-uniform on the range its derivation declares, points that violate the
    kernel's constraints redrawn."""
    constraints = getattr(kernel, "constraints", ())
    checks = [sp.lambdify([a.symbol for a in kernel.args], c, "mpmath") for c in constraints]
    points = []
    while len(points) < n:
        p = []
        for a in kernel.args:
            u = rng.random()
            p.append(
                float(np.exp(np.log(a.low) + u * (np.log(a.high) - np.log(a.low))))
                if a.log
                else float(a.low + u * (a.high - a.low))
            )
        if all(c(*p) for c in checks):
            points.append(p)
    return np.array(points)


# --- rounding-error bounds -----------------------------------------------------------------------
#: Unit roundoff of float64 (half an ULP of 1).
UNIT_ROUNDOFF = 2.0**-53
#: Error of one elementary function (exp, sin, cos, log, pow, ...) in units of the roundoff:
#: glibc documents at most 1–2 ULP for them, NumPy's SIMD float64 loops (SVML-derived, used on
#: AVX-512 machines) at most 4 ULP; 4 ULP = 8 roundoffs covers both.
ELEMENTARY_ROUNDOFFS = 8


def rounding_bound(expr: sp.Expr, symbols, point, dps: int = 40) -> float:
    """First-order bound on the float64 rounding error of evaluating ``expr`` at ``point``.

    Running error analysis over the expression tree (evaluated in mpmath at ``dps`` digits): every
    node's result carries a relative error of at most u (arithmetic, correctly rounded square
    root), (k − 1)·u for a k-term sum or product, or 8u for an elementary function (see
    ``ELEMENTARY_ROUNDOFFS``); it reaches the result multiplied by |∂f/∂node|.  The bound is
    Σ |∂f/∂node|·|node|·u_node, i.e. the conditioning of the formula at that point, which is what
    any two faithful float64 evaluations of it (NumPy's vectorised loops, its scalar loops, C,
    Octave) can differ by, whatever the CPU.
    """
    import mpmath as mp

    env = dict(zip(symbols, point, strict=True))
    u = mp.mpf(UNIT_ROUNDOFF)
    with mp.workdps(dps):
        values: dict[int, mp.mpf] = {}

        def value(node) -> mp.mpf:
            key = id(node)
            if key not in values:
                if node.is_Symbol:
                    v = mp.mpf(float(env[node]))
                elif not node.free_symbols:
                    v = mp.mpf(sp.N(node, dps + 5))
                elif node.is_Add:
                    v = mp.fsum(value(a) for a in node.args)
                elif node.is_Mul:
                    v = mp.fprod(value(a) for a in node.args)
                elif node.is_Pow:
                    v = value(node.args[0]) ** value(node.args[1])
                else:
                    v = getattr(mp, node.func.__name__)(*(value(a) for a in node.args))
                values[key] = mp.re(v) if mp.im(v) == 0 else v
            return values[key]

        total = mp.mpf(0)

        def visit(node, adj) -> None:
            nonlocal total
            if not node.free_symbols or node.is_Symbol or adj == 0:
                return  # inputs are exact; constants are the same float in every evaluation
            args = node.args
            val = value(node)
            if node.is_Add:
                total += abs(adj) * (len(args) - 1) * u * sum(abs(value(a)) for a in args)
                for a in args:
                    visit(a, adj)
            elif node.is_Mul:
                total += abs(adj) * (len(args) - 1) * u * abs(val)
                for i, a in enumerate(args):
                    visit(a, adj * mp.fprod(value(b) for j, b in enumerate(args) if j != i))
            elif node.is_Pow:
                base, ex = args
                exact = ex in (sp.Integer(2), sp.Integer(-1), sp.Rational(1, 2), sp.Rational(-1, 2))
                total += abs(adj) * abs(val) * u * (1 if exact else ELEMENTARY_ROUNDOFFS)
                vb, ve = value(base), value(ex)
                visit(base, adj * ve * vb ** (ve - 1))
                if ex.free_symbols:
                    visit(ex, adj * val * mp.log(vb))
            else:
                total += abs(adj) * abs(val) * u * ELEMENTARY_ROUNDOFFS
                (arg,) = args
                x = sp.Dummy()
                slope = sp.diff(node.func(x), x)
                visit(arg, adj * mp.mpf(sp.N(slope.subs(x, sp.Float(value(arg), dps)), dps)))

        tree = sp.sympify(expr)  # held, so that the ids keying ``values`` stay unique
        visit(tree, mp.mpf(1))
        return float(abs(total))


def integrate_whole_system(force, system, forcing, state, t_end):
    """The forced pair of Eq. F1 with a compliant contact, integrated as a whole by SciPy's DOP853
    (rtol 1e-13), independently of symimpact: no closed-form flight and no onset search, flight
    and contact each integrated and switched where δ = s·(y − x) − d/2 crosses 0 (located events).
    ``force(δ, δ̇)`` [N] is the contact law; ``state`` = (x, ẋ, y, ẏ) at t = 0, in flight.
    Returns (the state at ``t_end``, the number of contact onsets)."""
    M, K, C, m, h = system.M, system.K, system.C, system.m, system.gap / 2
    F0, W, phase = forcing.F0, forcing.omega, forcing.phase

    def rhs(t, u):
        x, v, y, w = u
        side = 1.0 if y - x > 0 else -1.0
        delta = side * (y - x) - h
        F = force(delta, side * (w - v)) if delta > 0 else 0.0
        fx = F0 * math.cos(W * t + phase) - K * x - C * v + side * F
        return [v, fx / M, w, -side * F / m]

    def wall(side, direction):
        def g(t, u):
            return side * (u[2] - u[0]) - h

        g.terminal, g.direction = True, direction
        return g

    t, u, side, contacts = 0.0, np.array(state, dtype=float), 0, 0
    while t < t_end:
        events = [wall(1, 1), wall(-1, 1)] if side == 0 else [wall(side, -1)]
        sol = solve_ivp(rhs, (t, t_end), u, method="DOP853", rtol=1e-13, atol=1e-16,
                        events=events)  # fmt: skip
        t, u = sol.t[-1], sol.y[:, -1]
        if sol.status == 1 and side == 0:
            side, contacts = (1 if len(sol.t_events[0]) else -1), contacts + 1
        elif sol.status == 1:
            side = 0
    return u, contacts


# --- a beam in Hermite elements, for the beam steps' independent checks -------------------------
#: a steel strip 1 m long, 50 mm × 10 mm
E, RHO, L = 210e9, 7850.0, 1.0
B, H = 0.05, 0.01
I, A = B * H**3 / 12, B * H
#: the supports' constrained (w, θ) degrees of freedom at the two ends
#: ("free": none, the whole model, as the supports' own rows are needed for base motion)
ENDS = {"cantilever": ((0, 1), ()), "clamped-clamped": ((0, 1), (0, 1)),
        "simply-supported": ((0,), (0,)), "free": ((), ())}  # fmt: skip
N_EL = 200


def hermite_beam_whole(n_el: int = N_EL):
    """(K, M) of the strip in ``n_el`` Hermite cubic elements with consistent mass, DOFs (w, θ)
    per node, no support: an independent model of the beams of Steps 1, 14 and 15 that shares
    no formula with their derivations."""
    h = L / n_el
    k = (
        E
        * I
        / h**3
        * np.array(
            [
                [12, 6 * h, -12, 6 * h],
                [6 * h, 4 * h * h, -6 * h, 2 * h * h],
                [-12, -6 * h, 12, -6 * h],
                [6 * h, 2 * h * h, -6 * h, 4 * h * h],
            ]
        )
    )
    m = RHO * A * h / 420 * np.array([[156, 22 * h, 54, -13 * h], [22 * h, 4 * h * h, 13 * h, -3 * h * h],
                                      [54, 13 * h, 156, -22 * h], [-13 * h, -3 * h * h, -22 * h, 4 * h * h]])  # fmt: skip
    n = 2 * (n_el + 1)
    K, M = np.zeros((n, n)), np.zeros((n, n))
    for e in range(n_el):
        s = slice(2 * e, 2 * e + 4)
        K[s, s] += k
        M[s, s] += m
    return K, M


def supported_dofs(support: str, n_el: int = N_EL) -> list[int]:
    """The DOFs of the whole model :func:`hermite_beam_whole` the ``support`` keeps."""
    n = 2 * (n_el + 1)
    left, right = ENDS[support]
    fixed = [d for d in left] + [n - 2 + d for d in right]
    return [d for d in range(n) if d not in fixed]


def hermite_beam(support: str, n_el: int = N_EL):
    """(K, M, kept DOFs) of :func:`hermite_beam_whole` with the ``support``'s end DOFs removed."""
    K, M = hermite_beam_whole(n_el)
    kept = supported_dofs(support, n_el)
    return K[np.ix_(kept, kept)], M[np.ix_(kept, kept)], kept


def flights_with_impacts(rhs, s, t, t_end, h, e, M, m, marks=()):
    """Brute force of a primary M with an impact mass m in a clearance 2h under ``rhs(t, w)``
    (w = x, ẋ, y, ẏ; any frame both share): DOP853 (rtol 1e-12) from ``s`` at ``t`` to ``t_end``,
    each impact (abs(y − x) = h) a terminal event with Newton's law (Eq. F2, restitution ``e``,
    or ``e(approach speed)`` if callable) applied there.  Returns (the state at t_end, the
    impact times, the states at ``marks``, an increasing sequence of times in [t, t_end], from
    the dense output)."""
    mu = M * m / (M + m)

    def upper(_, w):
        return w[2] - w[0] - h

    def lower(_, w):
        return w[2] - w[0] + h

    upper.terminal = lower.terminal = True
    upper.direction, lower.direction = 1, -1
    s, hits, out, marks = np.array(s, dtype=float), [], [], list(marks)
    while t < t_end:
        sol = solve_ivp(rhs, (t, t_end), s, method="DOP853", rtol=1e-12, atol=1e-16,
                        events=(upper, lower), dense_output=bool(marks))  # fmt: skip
        while marks and marks[0] <= sol.t[-1]:
            out.append(sol.sol(marks.pop(0)))
        s, t = sol.y[:, -1].copy(), sol.t[-1]
        if sol.status == 1:
            hits.append(t)
            v, u = s[1], s[3]
            r = e(abs(u - v)) if callable(e) else e  # e(v) of the approach speed, or one e
            s[1] = v + (1 + r) * mu / M * (u - v)
            s[3] = u - (1 + r) * mu / m * (u - v)
    return s, hits, np.array(out)
