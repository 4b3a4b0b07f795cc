"""The C99 and Octave targets (issue 8), compiled or run for real and compared with NumPy.

- C: ``generated/c/symimpact.c`` is compiled with the system compiler (``$CC``, else ``cc``) at
  ``-std=c99 -Wall -Wextra -pedantic -Werror`` as a shared library and loaded with ctypes.
- Octave: one ``octave-cli`` run evaluates every ``generated/octave/*.m`` file.

Every kernel is evaluated at 200 random physical points (the ranges its derivation declares) and
compared with the NumPy kernel to 1e-13 relative (for oscillating results 1e-13·(abs(value) +
amplitude), as in tests/test_kernels_vs_mpmath.py).  At the few points where a formula's
cancellation makes rounding exceed that, both must lie within 1e-12 of a 50-digit mpmath value.  The Eq. 31 iterations are compared with the
numba loops: the value where both converged, and the step count to within one.  On a CI machine
(``CI`` set) a missing compiler or Octave fails the test; elsewhere it skips.
"""

from __future__ import annotations

import ctypes
import importlib
import os
import subprocess
from pathlib import Path

import mpmath as mp
import numpy as np
import pytest
import sympy as sp

from derive import STEPS
from derive.backend_c import c_name
from derive.backend_octave import octave_name
from tests.helpers import physical_points, require_tool

ROOT = Path(__file__).resolve().parent.parent
RTOL = 1e-13
N_POINTS = 200
SEED = 20261123


@pytest.fixture(scope="module")
def cases(boards):
    """(module, kernel, points, NumPy values, error scale) for every kernel, seeded; the C and
    the Octave tests share them."""
    rng = np.random.default_rng(SEED)
    out = []
    for step in STEPS:
        module = importlib.import_module(f"symimpact.generated.{step}")
        for k in boards[step].kernels:
            points = physical_points(k, rng, N_POINTS)
            expected = np.asarray(getattr(module, k.name)(*points.T), dtype=float)
            symbols = [a.symbol for a in k.args]
            magnitude = np.broadcast_to(
                np.abs(sp.lambdify(symbols, k.magnitude or 0, "numpy")(*points.T)), expected.shape
            )
            out.append((step, k, points, expected, np.abs(expected) + magnitude))
    return out


@pytest.fixture(scope="module")
def fixed_cases(boards):
    """(fixed point, points, numba values, numba step counts) for every Eq. 31 iteration."""
    from symimpact.generated import fixed_points

    rng = np.random.default_rng(SEED + 1)
    out = []
    for step in STEPS:
        for fp in boards[step].fixed_points:
            points = physical_points(fp, rng, N_POINTS)
            value, steps = getattr(fixed_points, fp.name)(*points.T, fp.tol, fp.max_iter)
            out.append((fp, points, value, steps))
    return out


def _assert_close(name, kernel, points, got, expected, scale):
    """Agreement to RTOL·scale; where a formula's cancellation amplifies rounding beyond that (at
    most 5 % of the points), both must instead lie within 1e-12·scale of a 50-digit mpmath
    evaluation: then they differ only by rounding, as tests/test_kernels_vs_mpmath.py bounds it."""
    both_nan = np.isnan(got) & np.isnan(expected)
    bad = ~both_nan & ~(np.abs(got - expected) <= RTOL * scale)
    if bad.any() and bad.sum() <= len(got) // 20:
        exact = sp.lambdify([a.symbol for a in kernel.args], kernel.expr, "mpmath", cse=True)
        with mp.workdps(50):
            for i in np.flatnonzero(bad):
                value = mp.re(exact(*(mp.mpf(float(v)) for v in points[i])))
                bad[i] = not (
                    abs(mp.mpf(float(got[i])) - value) <= 1e-12 * scale[i]
                    and abs(mp.mpf(float(expected[i])) - value) <= 1e-12 * scale[i]
                )
    assert not bad.any(), (
        f"{name}: {bad.sum()} of {len(got)} points differ, e.g. at {points[bad][0].tolist()}: "
        f"{got[bad][0]!r} against NumPy {expected[bad][0]!r}"
    )


def _assert_fixed_point(name, fp, got, got_steps, value, steps):
    assert np.all(np.abs(got_steps - steps) <= 1), name
    done = (steps < fp.max_iter) & (got_steps < fp.max_iter) & np.isfinite(value)
    assert done.sum() >= N_POINTS // 2, (name, done.sum())  # most points converge
    assert np.all(np.abs(got[done] - value[done]) <= RTOL * np.abs(value[done])), name


# --- C99 ----------------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def libsymimpact(tmp_path_factory):
    cc = require_tool(os.environ.get("CC", "cc"))
    out = tmp_path_factory.mktemp("c") / "libsymimpact.so"
    flags = ["-std=c99", "-Wall", "-Wextra", "-pedantic", "-Werror", "-O2", "-shared", "-fPIC"]
    run = subprocess.run(
        [cc, *flags, str(ROOT / "generated" / "c" / "symimpact.c"), "-o", str(out), "-lm"],
        capture_output=True,
        text=True,
    )
    assert run.returncode == 0, run.stderr
    assert run.stderr == "", run.stderr  # no warning at all
    return ctypes.CDLL(str(out))


def _pointer(array: np.ndarray, ctype=ctypes.c_double):
    return array.ctypes.data_as(ctypes.POINTER(ctype))


def test_header_declares_every_definition():
    header = (ROOT / "generated" / "c" / "symimpact.h").read_text()
    source = (ROOT / "generated" / "c" / "symimpact.c").read_text()
    assert "malloc" not in source and "restrict" in header
    for line in source.splitlines():
        if line.startswith(("double symimpact_", "void symimpact_")):
            assert line + ";" in header, line


def test_every_c_kernel_matches_numpy(boards, cases, libsymimpact):
    assert len(cases) == sum(len(boards[s].kernels) for s in STEPS)
    for step, k, points, expected, scale in cases:
        name = c_name(step, k.name)
        batch = getattr(libsymimpact, f"{name}_batch")
        columns = [np.ascontiguousarray(c) for c in points.T]
        got = np.empty(N_POINTS)
        batch(ctypes.c_size_t(N_POINTS), *(_pointer(c) for c in columns), _pointer(got))
        _assert_close(name, k, points, got, expected, scale)
        one = getattr(libsymimpact, name)
        one.restype = ctypes.c_double
        for p, g in zip(points[:5], got[:5], strict=True):  # the scalar entry point is the same
            assert one(*(ctypes.c_double(v) for v in p)) == g or np.isnan(g)


def test_every_c_iteration_matches_numba(fixed_cases, libsymimpact):
    for fp, points, value, steps in fixed_cases:
        name = c_name("fixed_points", fp.name)
        columns = [np.ascontiguousarray(c) for c in points.T]
        got = np.empty(N_POINTS)
        got_steps = np.empty(N_POINTS, dtype=np.int64)
        assert ctypes.sizeof(ctypes.c_long) == 8  # the C long of the entry point is 64 bits here
        getattr(libsymimpact, f"{name}_batch")(
            ctypes.c_size_t(N_POINTS),
            *(_pointer(c) for c in columns),
            ctypes.c_double(fp.tol),
            ctypes.c_long(fp.max_iter),
            _pointer(got),
            _pointer(got_steps, ctypes.c_long),
        )
        _assert_fixed_point(name, fp, got, got_steps, value, steps)
        one = getattr(libsymimpact, name)
        one.restype = ctypes.c_double
        taken = ctypes.c_long(-1)
        args = [ctypes.c_double(v) for v in points[0]]
        first = one(*args, ctypes.c_double(fp.tol), ctypes.c_long(fp.max_iter), ctypes.byref(taken))
        assert (first == got[0] or np.isnan(got[0])) and taken.value == got_steps[0]
        assert one(*args, ctypes.c_double(fp.tol), ctypes.c_long(fp.max_iter), None) == first


# --- Octave -------------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def octave_results(cases, fixed_cases, tmp_path_factory):
    """Run every .m file on the sampled points in one Octave session; read back its output."""
    octave = require_tool("octave-cli")
    work = tmp_path_factory.mktemp("octave")
    fixed = fixed_cases
    lines = [f"addpath('{ROOT / 'generated' / 'octave'}');"]

    def call(name, points, outputs, extra, fmt):
        """Script lines: read the points, call ``name``, write ``outputs`` in ``fmt``."""
        np.savetxt(work / f"{name}.in", points, fmt="%.17g", delimiter=",")
        args = ", ".join([*(f"P(:, {i + 1})" for i in range(points.shape[1])), *extra])
        return [
            f"P = dlmread('{work / name}.in', ',');",
            f"[{', '.join(outputs)}] = {name}({args});",
            f"f = fopen('{work / name}.out', 'w'); "
            f"fprintf(f, '{fmt}\\n', [{', '.join(outputs)}]'); fclose(f);",
        ]

    for step, k, points, *_ in cases:
        lines += call(octave_name(step, k.name), points, ["r"], [], "%.17g")
    # a bundle at the points of its first part, every output written
    first = {(step, k.name): points for step, k, points, *_ in cases}
    for step in STEPS:
        module = importlib.import_module(f"symimpact.generated.{step}")
        for name, parts in module.BUNDLES.items():
            outs = [f"r{j + 1}" for j in range(len(parts))]
            lines += call(octave_name(step, name), first[step, parts[0]], outs, [],
                          " ".join(["%.17g"] * len(parts)))  # fmt: skip
    for fp, points, *_ in fixed:
        extra = [repr(fp.tol), str(fp.max_iter)]
        lines += call(octave_name("fixed_points", fp.name), points, ["r", "s"], extra, "%.17g %d")
    (work / "run_all.m").write_text("\n".join(lines) + "\n")
    run = subprocess.run(
        [octave, "--no-gui", "--norc", "--quiet", str(work / "run_all.m")],
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert run.returncode == 0, run.stderr[-2000:]
    assert "warning" not in run.stderr.lower(), run.stderr[-2000:]
    return work, cases, fixed


def _read(path: Path) -> np.ndarray:
    return np.array([[float(v) for v in line.split()] for line in path.read_text().splitlines()])


def test_every_octave_kernel_matches_numpy(octave_results, boards):
    work, cases, _ = octave_results
    files = {p.stem for p in (ROOT / "generated" / "octave").glob("*.m")}
    for step, k, points, expected, scale in cases:
        name = octave_name(step, k.name)
        files.discard(name)
        got = _read(work / f"{name}.out")[:, 0]
        _assert_close(name, k, points, got, expected, scale)
    for fp in octave_results[2]:
        files.discard(octave_name("fixed_points", fp[0].name))
    # each output of a bundle against its part's case, whose points the bundle was run at
    by_name = {(step, k.name): (k, points, expected, scale)
               for step, k, points, expected, scale in cases}  # fmt: skip
    for step in STEPS:
        module = importlib.import_module(f"symimpact.generated.{step}")
        for name, parts in module.BUNDLES.items():
            files.discard(octave_name(step, name))
            got = _read(work / f"{octave_name(step, name)}.out")
            first = by_name[step, parts[0]][1]
            for j, part in enumerate(parts):
                k, points, _, _ = by_name[step, part]
                expected = np.asarray(getattr(module, part)(*first.T), dtype=float)
                symbols = [a.symbol for a in k.args]
                magnitude = np.abs(sp.lambdify(symbols, k.magnitude or 0, "numpy")(*first.T))
                scale = np.abs(expected) + np.broadcast_to(magnitude, expected.shape)
                _assert_close(f"{octave_name(step, name)}[{j}]", k, first, got[:, j], expected,
                              scale)  # fmt: skip
    constants = {"ritz_BETA_L", *(f"beam_modes_BETA_L_{b}" for b in
                 ("CANTILEVER", "CLAMPED_CLAMPED", "SIMPLY_SUPPORTED"))}  # fmt: skip
    # the harmonic balance's residuals are run by tests/test_aft_kernels.py
    files -= {octave_name(s, x.name) for s in STEPS for x in boards[s].balances}
    assert files == constants, files  # every other file was run (a constant is not sampled)


def test_every_octave_iteration_matches_numba(octave_results):
    work, _, fixed = octave_results
    for fp, _points, value, steps in fixed:
        name = octave_name("fixed_points", fp.name)
        out = _read(work / f"{name}.out")
        _assert_fixed_point(name, fp, out[:, 0], out[:, 1], value, steps)


@pytest.mark.parametrize(
    ("module", "name"),
    [("ritz", "BETA_L"), *(("beam_modes", f"BETA_L_{b}") for b in
                          ("CANTILEVER", "CLAMPED_CLAMPED", "SIMPLY_SUPPORTED"))],
)  # fmt: skip
def test_octave_constant_is_the_python_constant(module, name):
    import importlib

    python = getattr(importlib.import_module(f"symimpact.generated.{module}"), name)
    octave = require_tool("octave-cli")
    folder = ROOT / "generated" / "octave"
    run = subprocess.run(
        [
            octave,
            "--no-gui",
            "--norc",
            "--quiet",
            "--eval",
            f"addpath('{folder}'); fprintf('%.17g\\n', {module}_{name}())",
        ],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert [float(v) for v in run.stdout.split()] == list(python)


EDGE_PROGRAM = r"""
#include <math.h>
#include <stdio.h>
#include "symimpact.h"

/* Table 1's m = 0.15 kg case with the paper's B/A = -M/m: the iteration converges. */
#define ARGS 0.15, 155300.0, 83.6, 0.0, 0.075, -1.0 / 0.15
int main(void)
{
    double m[3] = {0.15, 0.2, 0.25}, a[3] = {155300.0, 155300.0, 155300.0};
    double b[3] = {83.6, 83.6, 83.6}, c1[3] = {0.0, 0.0, 0.0}, v[3] = {0.075, 0.075, 0.075};
    double ba[3] = {-1.0 / 0.15, -1.0 / 0.2, -1.0 / 0.25}, out[3];
    long steps = 99;
    double T;
    /* the batch entry points with steps_taken == NULL, as the header allows */
    symimpact_fixed_points_contact_duration_batch(3, m, a, b, c1, v, ba, 1e-14, 100, out, NULL);
    symimpact_fixed_points_contact_duration_newton_batch(3, m, a, b, c1, v, ba, 1e-14, 100, out, NULL);
    symimpact_fixed_points_contact_duration_printed_batch(3, m, a, b, c1, v, ba, 1e-14, 100, out, NULL);
    printf("batch %.6f %.6f %.6f\n", out[0], out[1], out[2]);
    T = symimpact_fixed_points_contact_duration(ARGS, 1e-14, 100, &steps);
    printf("ok %.6f %ld\n", T, steps);
    T = symimpact_fixed_points_contact_duration(ARGS, NAN, 100, &steps);
    printf("nan_tol %d %ld\n", isnan(T) ? 1 : 0, steps);
    T = symimpact_fixed_points_contact_duration_newton(ARGS, -1.0, 100, &steps);
    printf("negative_tol %d %ld\n", isnan(T) ? 1 : 0, steps);
    T = symimpact_fixed_points_contact_duration_printed(ARGS, 1e-14, 0, &steps);
    printf("zero_max_iter %d %ld\n", isnan(T) ? 1 : 0, steps);
    return 0;
}
"""


def test_c_iterations_are_honest_at_their_edges_under_sanitizers(tmp_path):
    """Issue 16, item 6: the batch entry points accept a NULL steps_taken (they wrote through it:
    a segfault for n ≥ 2); a NaN or negative tol or max_iter ≤ 0 gives NaN and steps_taken = −1
    (it returned the start with 0 steps, which looks converged).  Compiled with AddressSanitizer
    and UndefinedBehaviorSanitizer, any report aborting the run."""
    cc = require_tool(os.environ.get("CC", "cc"))
    src = tmp_path / "edges.c"
    src.write_text(EDGE_PROGRAM, encoding="utf-8")
    exe = tmp_path / "edges"
    flags = ["-std=c99", "-Wall", "-Wextra", "-pedantic", "-Werror", "-g",
             "-fsanitize=address,undefined", "-fno-sanitize-recover=all"]  # fmt: skip
    subprocess.run(
        [cc, *flags, "-I", str(ROOT / "generated" / "c"), str(src),
         str(ROOT / "generated" / "c" / "symimpact.c"), "-o", str(exe), "-lm"],
        check=True, capture_output=True, text=True,
    )  # fmt: skip
    run = subprocess.run([str(exe)], capture_output=True, text=True, timeout=60)
    assert run.returncode == 0, run.stderr
    assert run.stderr == ""
    lines = dict(line.split(" ", 1) for line in run.stdout.splitlines())
    assert lines["nan_tol"] == "1 -1"
    assert lines["negative_tol"] == "1 -1"
    assert lines["zero_max_iter"] == "1 -1"
    value, steps = lines["ok"].split()
    assert 0 < int(steps) < 100 and 0.05 < float(value) < 0.5
    assert all(0.05 < float(x) < 0.5 for x in lines["batch"].split())
