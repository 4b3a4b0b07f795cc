"""Eq. 31 iterated to convergence: the compiled kernels of ``generated/fixed_points.py`` against
``sympy.lambdify`` of the same expressions (the derivation's own start and step), iterated on
NumPy arrays with the same stopping rule.  One core.  Prints figures and ratios; asserts nothing.

Points: random over the physical ranges the derivation declares for the kernel's arguments, kept
where Eq. 31's iteration converges in 100 steps (where it oscillates both would only run to the
cap), the same points for every method.  Run from the checkout: python -m benchmarks.contact_duration_kernel
"""

from __future__ import annotations

import sys

import numpy as np
import sympy as sp
from symimpact.generated import fixed_points

from derive import board

from .timing import REPEATS, timed

TOL, CAP = 1e-14, 100


def declared():
    fps = {f.name: f for f in board("multiple_scales").fixed_points}
    return fps["contact_duration"], fps["contact_duration_newton"]


def physical_points(fp, n, rng):
    """``n`` points (one array per argument) where the iteration of Eq. 31 converges."""
    cols = []
    for a in fp.args:
        u = rng.random(int(n * 1.15) + 10)
        lo, hi = a.low, a.high
        cols.append(np.exp(np.log(lo) + u * np.log(hi / lo)) if a.log else lo + u * (hi - lo))
    _, steps = fixed_points.contact_duration(*cols)
    keep = np.flatnonzero(steps < CAP)[:n]
    if keep.size < n:
        sys.exit("not enough converging points drawn")
    return [np.ascontiguousarray(c[keep]) for c in cols]


def lambdify_iteration(fp):
    """The baseline: lambdify(start), lambdify(step), then x ← step(x) on the still-moving
    elements until abs(Δ) ≤ tol·abs(x) everywhere (the best NumPy loop: no work on converged
    elements)."""
    symbols = [a.symbol for a in fp.args]
    start = sp.lambdify(symbols, fp.start, "numpy")
    step = sp.lambdify([fp.iterate, *symbols], fp.step, "numpy")

    def run(*args):
        x = np.asarray(start(*args), dtype=float)
        active = np.arange(x.size)
        sub = list(args)
        steps = np.zeros(x.size, dtype=np.int64)
        for _ in range(CAP):
            xa = x[active]
            new = step(xa, *sub)
            steps[active] += 1
            x[active] = new
            moving = np.abs(new - xa) > TOL * np.abs(new)
            active = active[moving]
            if active.size == 0:
                break
            sub = [s[moving] for s in sub]
        return x, steps

    return run


def main() -> None:
    rng = np.random.default_rng(20261122)
    plain_fp, newton_fp = declared()
    cases = (
        ("iteration of Eq. 31", plain_fp, fixed_points.contact_duration),
        ("Newton on h(T)", newton_fp, fixed_points.contact_duration_newton),
    )
    print(
        "contact-duration kernel: evaluations per second on one core, median of "
        f"{REPEATS} runs (slowest-fastest)"
    )
    for label, fp, kernel in cases:
        baseline = lambdify_iteration(fp)
        small = physical_points(plain_fp, 64, rng)
        kernel(*small)  # compile / load the cache (64 points: the 16-lane loop too)
        print(f"\n{label}")
        for n in (10**3, 10**5, 10**7):
            args = physical_points(plain_fp, n, rng)
            tk = timed(lambda a=args, f=kernel: f(*a))
            tb = timed(lambda a=args, f=baseline: f(*a))
            (value, steps), (ref, ref_steps) = tk.out, tb.out
            both = (steps < CAP) & (ref_steps < CAP)  # converged in both
            diff = np.max(np.abs(value - ref)[both] / np.abs(ref[both]))
            print(
                f"  N = {n:.0e}: kernel {tk.rate(n, 'ev/s')}; lambdify {tb.rate(n, 'ev/s')}; "
                f"ratio {tb.median / tk.median:.1f}x; mean steps {steps.mean():.2f}; max rel. "
                f"diff {diff:.1e}"
            )
    print("\ntargets: ratio >= 1.5x, kernel >= 1e7 evaluations/s")
    print("max rel. diff: over the points where both converged (Newton may stop at the cap on")
    print("a few points where the iteration converges)")


if __name__ == "__main__":
    main()
