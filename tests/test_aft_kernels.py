"""The harmonic balance's AFT residual emitted for importers (issue 83, item 4): in C, Octave,
Rust, Fortran and JAX, each target's R(U, ω), ∂R/∂U and ∂R/∂ω for every compliant law.

Checked against what they do not share: the runtime's balance
(:mod:`symimpact.forced.orbits.harmonic_balance`: NumPy matrices with Step 17's NumPy force
kernels, which equal the compiled engine's own laws, checked first) at random coefficients whose relative motion reaches both walls, to 1e-12 of the terms'
size (the same sums in another order: a few ULPs of the largest term times the 2H + 1 terms);
in C and JAX the Jacobian and ∂R/∂ω against central differences of the target's own residual
(step 1e-6 of the coefficients' scale: the truncation error, the third derivative times the step
squared, and the rounding, 1e-16 of the residual over the step, both below 1e-7 of the
Jacobian's size, where no sample lies within the step of an onset, which the points are chosen
to avoid), and in JAX against ``jax.jacfwd`` of its residual; and, where the runtime converges a
balance, the C residual vanishes there.
"""

from __future__ import annotations

import ctypes
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

from symimpact.forced.contact_law import CompliantContact
from symimpact.forced.forcing import Forcing
from symimpact.forced.orbits.harmonic_balance import _problem, hb_orbit
from symimpact.model.system import ImpactSystem
from tests.helpers import require_tool

ROOT = Path(__file__).resolve().parent.parent
GENERATED = ROOT / "generated"

BASE = {"M": 1.0, "K": 1000.0, "C": 0.5, "m": 0.05, "gap": 0.02}
#: Each law with its parameters as the kernels take them (after δ, δ̇) and the runtime's system.
LAWS = {
    "linear": (("k1", "c1"), {"k1": 2e4, "c1": 0.5}, None),
    "cubic": (("a", "b", "c1"), {"a": 1e9, "b": 1e4, "c1": 0.3}, None),
    "hertz": (("k_hz", "c1"), {"k_hz": 1e5, "c1": 0.5}, None),
    "hunt_crossley": (("k_hz", "chi"), {"k_hz": 1e5}, 0.4),
}
#: Harmonics and time samples of the cases, and the forcing (2 N at 33 rad/s, phase 0.3).
CASES = [(3, 16), (7, 29), (12, 48)]
FORCING = Forcing(F0=2.0, omega=33.0, phase=0.3)


def system_and_contact(law: str):
    _, values, chi = LAWS[law]
    system = ImpactSystem(**BASE, **values, contact="hertz" if chi else law)
    return system, CompliantContact(law.replace("_", "-"), chi)


def law_parameters(law: str) -> list[float]:
    names, values, chi = LAWS[law]
    return [chi if n == "chi" else values[n] for n in names]


def coefficients(H: int, N: int, seed: int) -> np.ndarray:
    """x and y of a motion whose relative motion z = y − x reaches both walls (amplitude about
    2.5 clearance halves), with smaller higher harmonics; redrawn until no sample lies within
    1e-5 m of an onset, where a difference step would switch a contact on or off."""
    rng = np.random.default_rng(seed)
    nh = 2 * H + 1
    while True:
        U = np.zeros(2 * nh)
        U[1], U[2] = 0.02 * rng.uniform(0.5, 1.0), 0.02 * rng.uniform(-0.5, 0.5)
        U[nh + 1], U[nh + 2] = -0.01 * rng.uniform(0.5, 1.0), 0.01 * rng.uniform(-0.5, 0.5)
        for k in range(2, H + 1):
            U[2 * k - 1 : 2 * k + 1] = rng.normal(0.0, 1e-3 / k**2, 2)
            U[nh + 2 * k - 1 : nh + 2 * k + 1] = rng.normal(0.0, 2e-3 / k**2, 2)
        U[0], U[nh] = rng.normal(0.0, 1e-3, 2)
        kt = np.outer(2 * np.pi * np.arange(N) / N, np.arange(1, H + 1))
        d = U[nh:] - U[:nh]
        z = d[0] + np.cos(kt) @ d[1::2] + np.sin(kt) @ d[2::2]
        if np.min(np.abs(np.abs(z) - BASE["gap"] / 2)) > 1e-5:
            return U


@pytest.mark.parametrize("law", LAWS)
def test_the_derived_laws_are_the_engine_s(law):
    """Step 17's force and slopes (the NumPy bundle the runtime's balance evaluates) against the
    law the compiled engine integrates, written by hand (engine._compliant._force), at 200
    penetrations over six decades and rates of either sign: to 1e-13 of the force's terms (a
    power 1.5 as x·√x in one, x**1.5 in the other: a few ULPs)."""
    from symimpact.generated import multi_harmonic_balance as step17

    from symimpact.forced.engine import _compliant
    from symimpact.forced.simulation import _law_parameters

    system, contact = system_and_contact(law)
    rng = np.random.default_rng(83)
    delta = 10.0 ** rng.uniform(-8, -2, 200)
    ddelta = rng.uniform(-3.0, 3.0, 200)
    chi = 0.0 if contact.chi is None else contact.chi
    engine = _compliant.forces(_compliant.CODES[contact.law], _law_parameters(system, contact.law),
                               chi, delta, ddelta)  # fmt: skip
    derived = getattr(step17, f"force_{law}_and_derivatives")(delta, ddelta, *law_parameters(law))
    for name, a, b in zip(("F", "∂F/∂δ", "∂F/∂δ̇"), engine, derived, strict=True):
        b = np.broadcast_to(b, a.shape)
        terms = np.abs(a) + np.abs(b) + 1e-300
        assert np.all(np.abs(a - b) <= 1e-13 * terms), (law, name)


def runtime(law: str, H: int, N: int, U: np.ndarray, w: float):
    system, contact = system_and_contact(law)
    problem = _problem(system, FORCING, contact, H, N, 1)
    R, J, dR_dw, _ = problem.jacobian(U, w)
    return problem, R, J, dR_dw


def forcing_terms(problem) -> np.ndarray:
    return problem.F_ext.ravel()


def assert_close(got: np.ndarray, want: np.ndarray, scale: float, rtol: float, what: str):
    err = float(np.max(np.abs(got - want)))
    assert err <= rtol * scale, f"{what}: off by {err:.3g}, {err / scale:.3g} of {scale:.3g}"


def check_target(evaluate, law: str, H: int, N: int, seed: int) -> None:
    """``evaluate(law, H, N, ω, U, F_ext) -> (R, J, R_omega)`` against the runtime and against
    its own differences (module text)."""
    U = coefficients(H, N, seed)
    w = FORCING.omega * (1.0 + 0.05 * (seed % 3))
    problem, R0, J0, dw0 = runtime(law, H, N, U, w)
    F = forcing_terms(problem)
    R, J, dw = evaluate(law, H, N, w, U, F)
    size = float(np.max(np.abs(problem._linear(w) @ U)) + np.max(np.abs(F)) + np.max(np.abs(R0)))
    assert_close(R, R0, size, 1e-12, "R against the runtime")
    jscale = float(np.max(np.abs(J0)))
    assert_close(J, J0, jscale, 1e-12, "∂R/∂U against the runtime")
    assert_close(dw, dw0, float(np.max(np.abs(dw0))), 1e-12, "∂R/∂ω against the runtime")
    # the target's Jacobian against central differences of its own residual
    step = 1e-6 * float(np.max(np.abs(U)))
    fd = np.empty_like(J)
    for j in range(len(U)):
        d = np.zeros_like(U)
        d[j] = step
        fd[:, j] = (evaluate(law, H, N, w, U + d, F)[0] - evaluate(law, H, N, w, U - d, F)[0]) / (
            2 * step
        )
    assert_close(J, fd, jscale, 1e-7, "∂R/∂U against differences")
    hw = 1e-6 * w
    fdw = (evaluate(law, H, N, w + hw, U, F)[0] - evaluate(law, H, N, w - hw, U, F)[0]) / (2 * hw)
    assert_close(dw, fdw, float(np.max(np.abs(dw))), 1e-7, "∂R/∂ω against differences")


# --- C ------------------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def c_library(tmp_path_factory):
    cc = require_tool(os.environ.get("CC", "cc"))
    out = tmp_path_factory.mktemp("aft_c") / "libsymimpact_aft.so"
    subprocess.run([cc, "-std=c99", "-Wall", "-Wextra", "-pedantic", "-Werror", "-O2", "-fPIC",
                    "-shared", "-o", str(out), str(GENERATED / "c" / "symimpact.c"), "-lm"],
                   check=True, capture_output=True, timeout=600)  # fmt: skip
    return ctypes.CDLL(str(out))


def c_evaluate(lib):
    def evaluate(law, H, N, w, U, F):
        f = getattr(lib, f"symimpact_multi_harmonic_balance_aft_residual_{law}")
        args = arguments(law)
        n = len(U)
        R, J, dw = np.empty(n), np.empty(n * n), np.empty(n)
        p = ctypes.POINTER(ctypes.c_double)
        f.restype = None
        f.argtypes = [ctypes.c_int, ctypes.c_int, ctypes.c_double, p, p,
                      *[ctypes.c_double] * len(args), p, p, p]  # fmt: skip
        U, F = np.ascontiguousarray(U), np.ascontiguousarray(F)
        f(H, N, w, *(a.ctypes.data_as(p) for a in (U, F)),
          *args, *(a.ctypes.data_as(p) for a in (R, J, dw)))  # fmt: skip
        return R, J.reshape(n, n), dw

    return evaluate


@pytest.mark.parametrize("law", LAWS)
@pytest.mark.parametrize(("H", "N"), CASES)
def test_the_c_residual_matches_the_runtime_and_its_own_differences(c_library, law, H, N):
    check_target(c_evaluate(c_library), law, H, N, seed=H * 31 + N)


def test_the_c_residual_vanishes_at_the_runtime_s_balance(c_library):
    """The runtime's Newton converges the Hertz balance at 34 rad/s (H 10, N 40); the C
    residual at its coefficients is zero to the runtime's own tolerance (a correction below 1e-10
    of the clearance's half: the residual below that times the Jacobian's size)."""
    system, contact = system_and_contact("hertz")
    forcing = Forcing(F0=2.0, omega=34.0)
    orbit = hb_orbit(system, forcing, contact, harmonics=10, time_samples=40)
    U = np.concatenate([orbit.x, orbit.y])
    problem = _problem(system, forcing, contact, 10, 40, 1)
    R, J, _ = c_evaluate(c_library)("hertz", 10, 40, 34.0, U, problem.F_ext.ravel())
    assert np.max(np.abs(R)) <= 1e-9 * np.max(np.abs(J)) * system.gap / 2


# --- JAX, in a child process ---------------------------------------------------------------------

#: The child's script: each case's (R, ∂R/∂U, ∂R/∂ω) and jax.jacfwd of R in U and in ω.  JAX
#: runs in a child process, as in tests/test_jax_kernels.py: it starts threads, and a later test
#: in this worker that forks a process pool would meet its warning (or a deadlock).
JAX_CHILD = """
import sys
import numpy as np
import jax
from symimpact.generated.jax import multi_harmonic_balance as mhb

cases = np.load(sys.argv[1], allow_pickle=True)["cases"]
out = []
for law, H, N, w, U, F, rest in cases:
    f = getattr(mhb, "aft_residual_" + law)
    R, J, dw = f(H, N, w, U, F, *rest)
    J_ad = jax.jacfwd(lambda u: f(H, N, w, u, F, *rest)[0])(U)
    dw_ad = jax.jacfwd(lambda v: f(H, N, v, U, F, *rest)[0])(w)
    out.append([np.asarray(a) for a in (R, J, dw, J_ad, dw_ad)])
np.save(sys.argv[2], np.array(out, dtype=object), allow_pickle=True)
"""


def test_the_jax_residual_matches_the_runtime_and_jax_s_own_derivatives(tmp_path):
    """JAX's residual against the runtime (1e-12), and its Jacobian and ∂R/∂ω against
    forward-mode differentiation of its residual (JAX's own chain rule through the samples, the
    law evaluated only where δ > 0; 1e-12)."""
    import importlib.util
    import sys

    if importlib.util.find_spec("jax") is None:
        if os.environ.get("CI"):
            pytest.fail("jax is not installed (the test extra installs it)")
        pytest.skip("jax is not installed")
    cases, wanted = [], []
    for law in LAWS:
        for H, N, w, U, F in _points(law):
            cases.append((law, H, N, w, U, F, arguments(law)))
            wanted.append((law, H, N, w, U, F))
    src, dst = tmp_path / "cases.npz", tmp_path / "out.npy"
    np.savez(src, cases=np.array(cases, dtype=object))
    run = subprocess.run([sys.executable, "-c", JAX_CHILD, str(src), str(dst)],
                         capture_output=True, text=True, timeout=900)  # fmt: skip
    assert run.returncode == 0, run.stderr[-3000:]
    for (law, H, N, w, U, F), (R, J, dw, J_ad, dw_ad) in zip(
        wanted, np.load(dst, allow_pickle=True), strict=True
    ):
        _check_against_runtime(law, H, N, w, U, F, R, J, dw)
        assert_close(J, J_ad, float(np.max(np.abs(J))), 1e-12, f"{law} ∂R/∂U, AD")
        assert_close(dw, dw_ad, float(np.max(np.abs(dw))), 1e-12, f"{law} ∂R/∂ω, AD")


# --- Rust, Fortran and Octave: a program prints R, J, ∂R/∂ω at the cases' points ----------


def _points(law: str) -> list[tuple[int, int, float, np.ndarray, np.ndarray]]:
    out = []
    for H, N in CASES[:2]:
        U = coefficients(H, N, H * 31 + N)
        w = FORCING.omega * 1.05
        out.append((H, N, w, U, forcing_terms(runtime(law, H, N, U, w)[0])))
    return out


def _check_against_runtime(law, H, N, w, U, F, R, J, dw) -> None:
    problem, R0, J0, dw0 = runtime(law, H, N, U, w)
    size = float(np.max(np.abs(problem._linear(w) @ U)) + np.max(np.abs(F)))
    assert_close(R, R0, size, 1e-12, f"{law} R")
    assert_close(J, J0, float(np.max(np.abs(J0))), 1e-12, f"{law} ∂R/∂U")
    assert_close(dw, dw0, float(np.max(np.abs(dw0))), 1e-12, f"{law} ∂R/∂ω")


def _check_printed(stdout: str) -> None:
    """A program's lines, one per point of :func:`_points` for each law in turn: R, then J row
    by row, then ∂R/∂ω, against the runtime (as :func:`check_target` does, without the
    differences: those test the scheme, which the C and JAX tests cover, and would cost a build
    per difference)."""
    rows = [np.array([float(v) for v in line.split()]) for line in stdout.strip().splitlines()]
    points = [(law, *point) for law in LAWS for point in _points(law)]
    for (law, H, N, w, U, F), row in zip(points, rows, strict=True):
        n = len(U)
        _check_against_runtime(law, H, N, w, U, F, row[:n], row[n : n + n * n].reshape(n, n),
                               row[n + n * n :])  # fmt: skip


def arguments(law: str) -> list[float]:
    """M, C, K, m, gap and the law's parameters, as every target takes them."""
    return [BASE[k] for k in ("M", "C", "K", "m", "gap")] + law_parameters(law)


def _numbers(values) -> str:
    return ", ".join(repr(float(v)) for v in values)


def test_the_rust_residual_matches_the_runtime(tmp_path):
    cargo = require_tool("cargo")
    crate = tmp_path / "aft"
    (crate / "src").mkdir(parents=True)
    (crate / "Cargo.toml").write_text(
        '[package]\nname = "aft"\nversion = "0.1.0"\nedition = "2021"\n\n[dependencies]\n'
        f'symimpact = {{ path = "{GENERATED / "rust"}" }}\n'
    )
    body = []
    for law in LAWS:
        for H, N, w, U, F in _points(law):
            args = ", ".join(repr(v) for v in arguments(law))
            body.append(
                f"    let (r, j, w) = symimpact::multi_harmonic_balance::aft_residual_{law}("
                f"{H}, {N}, {w!r}, &[{_numbers(U)}], &[{_numbers(F)}], {args});\n"
                "    let all: Vec<String> = r.iter().chain(j.iter()).chain(w.iter())"
                '.map(|v| format!("{:e}", v)).collect();\n'
                '    println!("{}", all.join(" "));\n'
            )
    (crate / "src" / "main.rs").write_text("fn main() {\n" + "".join(body) + "}\n")
    run = subprocess.run([cargo, "run", "--quiet", "--offline", "--release"], cwd=crate,
                         capture_output=True, text=True, timeout=900,
                         env={**os.environ, "CARGO_TARGET_DIR": str(tmp_path / "target")})  # fmt: skip
    assert run.returncode == 0, run.stderr[-3000:]
    _check_printed(run.stdout)


def test_the_fortran_residual_matches_the_runtime(tmp_path):
    fc = require_tool("gfortran")
    calls = []
    for law in LAWS:
        for H, N, w, U, F in _points(law):
            n = len(U)
            args = ", ".join(f"{v!r}_dp" for v in arguments(law))
            values = "".join(f"        U({i + 1}) = {float(v)!r}_dp\n        F({i + 1}) = {float(f)!r}_dp\n"
                             for i, (v, f) in enumerate(zip(U, F, strict=True)))  # fmt: skip
            calls.append(
                f"    block\n        real(dp) :: U({n}), F({n}), R({n}), J({n}, {n}), W({n})\n"
                + values
                + f"        call multi_harmonic_balance_aft_residual_{law}({H}, {N}, {w!r}_dp, U, "
                f"F, {args}, R, J, W)\n"
                "        write (*, '(*(es25.17e3, 1x))') R, transpose(J), W\n    end block\n"
            )
    program = (
        "program aft\n    use symimpact\n    implicit none\n" + "".join(calls) + "end program aft\n"
    )
    (tmp_path / "aft.f90").write_text(program)
    build = subprocess.run([fc, "-std=f2008", "-O1", "-ffree-line-length-none",
                            str(GENERATED / "fortran" / "symimpact.f90"), "aft.f90", "-o", "aft"],
                           cwd=tmp_path, capture_output=True, text=True, timeout=900)  # fmt: skip
    assert build.returncode == 0, build.stderr[-3000:]
    run = subprocess.run(["./aft"], cwd=tmp_path, capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    _check_printed(run.stdout)


def test_the_octave_residual_matches_the_runtime(tmp_path):
    octave = require_tool("octave-cli")
    lines = []
    for law in LAWS:
        for H, N, w, U, F in _points(law):
            rest = ", ".join(repr(v) for v in arguments(law))
            lines.append(
                f"[R, J, W] = multi_harmonic_balance_aft_residual_{law}({H}, {N}, {w!r}, "
                f"[{_numbers(U)}], [{_numbers(F)}], {rest});\n"
                "printf('%.17g ', [R; reshape(J', [], 1); W]); printf('\\n');\n"
            )
    script = tmp_path / "aft.m"
    script.write_text("".join(lines))
    run = subprocess.run([octave, "--no-gui", "--quiet", "--norc", "--path",
                          str(GENERATED / "octave"), str(script)],
                         capture_output=True, text=True, timeout=600)  # fmt: skip
    assert run.returncode == 0, run.stderr[-3000:]
    _check_printed(run.stdout)
