"""Random physical points for a kernel: each argument uniform or log-uniform on the range its
derivation declares, points that violate the kernel's constraints redrawn (shared by the tests
that check kernels against mpmath and the C and Octave targets against NumPy)."""

from __future__ import annotations

import numpy as np
import sympy as sp


def physical_points(kernel, rng: np.random.Generator, n: int) -> np.ndarray:
    """(n, number of arguments) points for ``kernel`` (a Kernel or a FixedPoint)."""
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
