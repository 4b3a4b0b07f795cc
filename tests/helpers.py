"""Helpers shared by test modules: random physical points for a kernel (the tests against
mpmath, the C and Octave targets), and the external tools a test needs (a C compiler, Octave)."""

from __future__ import annotations

import os
import shutil

import numpy as np
import pytest
import sympy as sp


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
