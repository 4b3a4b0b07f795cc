"""The JAX target (issue 38, item 3): ``symimpact.generated.jax``, generated from the same
expressions as every other target, checked against mpmath and JAX's own transformations.

- Every kernel, called once on the arrays of its recorded points (``derive/checkpoints.py``, as
  the C, Rust and Fortran tests), against the 50-digit mpmath values to 1e-12 of the error scale;
  every iteration mapped with ``jax.vmap`` over its points, value and steps (within one).
- ``jax.vmap`` of each kernel equals its single calls to 1e-13 of the scale (the same formula;
  XLA may fuse a batch differently, which moves the last bits).
- ``jax.jacfwd`` of each kernel, with respect to every argument, at its first recorded point
  against mpmath's differentiation (``mpmath.diff``, 50 digits) of the derivation's expression
  where the argument has no derivative kernel, and against the JAX derivative
  kernels (``<kernel>_d_<argument>``, themselves checked against mpmath) there, to 1e-9 of the derivative's scale |∂f/∂xᵢ| + scale/|xᵢ|: differentiation through
  the generated code multiplies rounding by the formula's conditioning, which 1e-9 leaves a
  factor 10⁶ above double rounding for.

JAX runs in a child process: JAX starts threads, and a later test that forks a process pool
(the map executors) could deadlock in a process that has imported it.  On a CI machine (``CI``
set) a missing JAX fails the test; elsewhere it skips.
"""

from __future__ import annotations

import importlib.util
import json
import os
import subprocess
import sys

import mpmath as mp
import numpy as np
import pytest
import sympy as sp

from derive import checkpoints

if importlib.util.find_spec("jax") is None:  # pragma: no cover - the test extra installs it
    if os.environ.get("CI"):
        raise ImportError("jax is not installed (the test extra installs it)")
    pytest.skip("jax is not installed", allow_module_level=True)

#: In the slow set, which CI runs second: JAX's start and compilation of 146 kernels take about
#: a minute, which the README's test command (within about twelve minutes) cannot spare.
pytestmark = pytest.mark.slow

RTOL = checkpoints.RTOL
VMAP_RTOL = 1e-13
GRAD_RTOL = 1e-9

#: What the child process runs: the JAX kernels on the points it is given.
CHILD = r"""
import importlib, json, sys
import jax, numpy as np
payload = json.load(open(sys.argv[1]))
out = {"x64": None, "kernels": [], "iterations": [], "jacobians": []}
for module, name, columns in payload["kernels"]:
    f = getattr(importlib.import_module("symimpact.generated.jax." + module), name)
    cols = [np.array(c) for c in columns]
    values = np.asarray(f(*cols), dtype=float) + 0.0 * cols[0] if cols else f()
    mapped = np.asarray(jax.vmap(f)(*cols), dtype=float) if cols else values
    single = [float(f(*(float(c[i]) for c in cols))) for i in range(len(cols[0]))] if cols else []
    out["kernels"].append([np.broadcast_to(values, (len(cols[0]),)).tolist(), mapped.tolist(),
                           single])
out["x64"] = bool(jax.config.jax_enable_x64)
for module, name, columns, tol, max_iter in payload["iterations"]:
    f = getattr(importlib.import_module("symimpact.generated.jax." + module), name)
    axes = (0,) * len(columns) + (None, None)
    value, steps = jax.vmap(f, in_axes=axes)(*(np.array(c) for c in columns), tol, max_iter)
    out["iterations"].append([np.asarray(value).tolist(), np.asarray(steps).tolist()])
for module, name, point in payload["jacobians"]:
    f = getattr(importlib.import_module("symimpact.generated.jax." + module), name)
    jac = jax.jacfwd(f, argnums=tuple(range(len(point))))(*point)
    out["jacobians"].append([float(j) for j in jac])
json.dump(out, open(sys.argv[2], "w"))
"""


def _columns(points) -> list[list[float]]:
    return [[float(p.args[i]) for p in points] for i in range(len(points[0].args))]


def _along(value, args: list, i: int):
    """x ↦ Re value(args with its i-th replaced by x): the expression along one argument."""
    return lambda x: mp.re(value(*args[:i], x, *args[i + 1 :]))


def _in_jax(payload: dict, tmp_path) -> dict:
    src, dst = tmp_path / "payload.json", tmp_path / "result.json"
    src.write_text(json.dumps(payload), encoding="utf-8")
    run = subprocess.run([sys.executable, "-c", CHILD, str(src), str(dst)], capture_output=True,
                         text=True, timeout=1200)  # fmt: skip
    assert run.returncode == 0, run.stderr[-3000:]
    return json.loads(dst.read_text(encoding="utf-8"))


@pytest.fixture(scope="module")
def recorded(boards):
    return checkpoints.recorded(list(boards.values()))


@pytest.fixture(scope="module")
def evaluated(recorded, tmp_path_factory):
    """What the child process computed on every kernel's and iteration's recorded points."""
    payload = {
        "kernels": [(m, k.name, _columns(pts)) for m, k, pts in recorded["kernels"]],
        "iterations": [
            (m, fp.name, _columns(pts), fp.tol, fp.max_iter)
            for m, fp, pts in recorded["iterations"]
        ],
        "jacobians": [],
    }
    return _in_jax(payload, tmp_path_factory.mktemp("jax"))


def test_every_kernel_and_iteration_agrees_with_mpmath_at_the_recorded_points(recorded, evaluated):
    assert evaluated["x64"]  # importing the package turned on float64
    for (module, k, points), (values, _, _) in zip(
        recorded["kernels"], evaluated["kernels"], strict=True
    ):
        expected = np.array([float(p.value) for p in points])
        scale = np.array([float(p.scale) for p in points])
        got = np.array(values)
        assert np.all(np.abs(got - expected) <= RTOL * scale), (module, k.name, got, expected)
    for (_, fp, points), (value, steps) in zip(
        recorded["iterations"], evaluated["iterations"], strict=True
    ):
        expected = np.array([float(p.value) for p in points])
        assert np.all(np.abs(np.array(value) - expected) <= RTOL * np.abs(expected)), fp.name
        assert np.all(np.abs(np.array(steps) - [p.steps for p in points]) <= 1), fp.name


def test_vmap_equals_single_calls(recorded, evaluated):
    for (module, k, points), (_, mapped, single) in zip(
        recorded["kernels"], evaluated["kernels"], strict=True
    ):
        scale = np.array([float(p.scale) for p in points])
        diff = np.abs(np.array(mapped) - np.array(single))
        assert np.all(diff <= VMAP_RTOL * scale), (module, k.name)


def test_jacfwd_agrees_with_the_derivative_of_the_expression(recorded, evaluated, tmp_path):
    """jax.jacfwd of every value kernel against mpmath's derivative of its expression (50 digits),
    and every generated derivative kernel against jacfwd of its value kernel. The
    derivative kernels' own jacfwd (second derivatives of the closed-form orbit's 100-kB
    expressions: eight of the slow set's minutes on 2 cores) is not asked: what they are, first
    derivatives, is checked here and against complex steps and mpmath elsewhere."""
    cases = [(m, k, pts[0]) for m, k, pts in recorded["kernels"]
             if k.args and k.derivative_of is None]  # fmt: skip
    jacobians = [(m, k.name, [float(a) for a in p.args]) for m, k, p in cases]
    payload = {"kernels": [], "iterations": [], "jacobians": jacobians}
    jacobians = _in_jax(payload, tmp_path)["jacobians"]
    # a derivative that has its own generated kernel is compared with it below, and that kernel
    # with mpmath's differentiation of the value at its recorded points in
    # tests/test_derivative_kernels.py: mpmath differentiates the value here for the others only.
    # mpmath.diff of the expression, evaluated once per kernel at 50 digits, not sympy.diff:
    # SymPy's derivatives of the closed-form orbit's 100-kB expressions, each lambdified, took
    # 78 s of one core against 12 s (they agree to 1e-31 of the scale below on every case but
    # the orbit's, where the exact ones were the cost)
    first = {(m, k.name): pts[0] for m, k, pts in recorded["kernels"]}
    covered = {(m, k.derivative_of[0], k.derivative_of[1]) for m, k, pts in recorded["kernels"]
               if k.derivative_of is not None
               and first[m, k.derivative_of[0]].args == pts[0].args}  # fmt: skip
    for (module, k, p), jac in zip(cases, jacobians, strict=True):
        symbols = [a.symbol for a in k.args]
        wanted = [i for i, a in enumerate(k.args) if (module, k.name, a.name) not in covered]
        if not wanted:
            continue
        with mp.workdps(checkpoints.DIGITS):
            args = [mp.mpf(float(v)) for v in p.args]
            value = sp.lambdify(symbols, k.expr, "mpmath", cse=True)
            for i in wanted:
                exact = mp.diff(_along(value, args, i), args[i])
                bound = GRAD_RTOL * (abs(exact) + mp.mpf(p.scale) / abs(args[i]))
                assert abs(mp.mpf(jac[i]) - exact) <= bound, (
                    module, k.name, symbols[i], jac[i], float(exact))  # fmt: skip
    # the derivative kernels (sympy.diff, issue 38 item 1) equal jacfwd of their value kernels
    by_name = {(m, k.name): (k, p, jac) for (m, k, p), jac in zip(cases, jacobians, strict=True)}
    compared = 0
    for (module, k, points), (values, _, _) in zip(
        recorded["kernels"], evaluated["kernels"], strict=True
    ):
        if k.derivative_of is None:
            continue
        value_kernel, p, jac = by_name[module, k.derivative_of[0]]
        if p.args != points[0].args:  # the first recorded points differ: nothing to compare
            continue
        i = [a.name for a in value_kernel.args].index(k.derivative_of[1])
        assert abs(values[0] - jac[i]) <= GRAD_RTOL * float(points[0].scale), (module, k.name)
        compared += 1
    assert compared >= 30
