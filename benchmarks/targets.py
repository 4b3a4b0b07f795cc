"""The generated targets side by side (issue 38): evaluations per second of three representative
kernels at N = 10⁶ points, in each target, against the NumPy kernel in the same run; and the JAX
kernels' compile time.  One core.  Prints figures and ratios; asserts nothing.

Kernels: a contact duration (``closed_forms.hertz_contact_duration``, Eq. 34), the flight's
transition matrix (the bundle ``forced_flight.forced_transition``, Eq. F1: x, ẋ and the four
entries of ∂(x, ẋ)/∂(x0, ẋ0) in one call, six values a point) and a saltation entry
(``rigid_impact.saltation_main_velocity_z``, Step 9).  A bundle's evaluations are its points
(each gives all its parts); its results are compared as the sum of its parts.  Points: random over the physical ranges
the derivation declares (its constraints kept), the same points for every target.

- NumPy: the kernel on the arrays.
- C: ``generated/c/symimpact.c`` compiled with ``cc -O2`` as a shared library, the ``_batch``
  function called once through ctypes.
- JAX: the jit-compiled kernel on device arrays, ``block_until_ready``; its first call (trace and
  compile) timed apart.
- Rust: the exported crate as a path dependency of a small timing program (``cargo build
  --release --offline``), a loop over the points; Fortran: the module compiled with ``gfortran
  -O2``, the elemental function called on the arrays.  Both read the points from a binary file
  and time themselves (median of the same repeats); their sum of the results is compared with
  NumPy's.

Then the bundles (``forced_flight.forced_state`` and ``forced_transition``: the flight's state and
its transition matrix, their common subexpressions computed once) against their parts called one
by one, the same points: NumPy on the arrays, and the ``_scalar`` twins in a numba-compiled loop,
as the rigid simulation and the shooting chain call them.

Run from the checkout: python -m benchmarks.targets
"""

from __future__ import annotations

import ctypes
import os
import shutil
import statistics
import subprocess
import tempfile
import time
from pathlib import Path

import numpy as np
import sympy as sp

from derive import board
from symimpact.export import export_kernels

from .timing import REPEATS, timed

ROOT = Path(__file__).resolve().parent.parent
N = 10**6
KERNELS = (
    ("closed_forms", "hertz_contact_duration", "contact duration, Eq. 34"),
    ("forced_flight", "forced_transition", "the flight's transition matrix, a bundle, Eq. F1"),
    ("rigid_impact", "saltation_main_velocity_z", "saltation entry, Step 9"),
)


def declared():
    """{(module, kernel): the derivation's Kernel} of the three kernels (a bundle's first part,
    whose arguments and ranges it shares)."""
    out = {}
    for module, name, _ in KERNELS:
        b = board(module)
        bundle = next((bu for bu in b.bundles if bu.name == name), None)
        out[module, name] = bundle.parts[0] if bundle else next(k for k in b.kernels
                                                                if k.name == name)  # fmt: skip
    return out


def parts(module: str, name: str) -> int:
    """How many values the kernel gives a point (1, or a bundle's parts)."""
    from importlib import import_module

    return len(import_module(f"symimpact.generated.{module}").BUNDLES.get(name, (None,)))


def points(kernel, n, rng) -> list[np.ndarray]:
    """``n`` points (one array per argument) over the declared ranges, constraints kept."""
    cols = []
    m = 2 * n + 100
    for a in kernel.args:
        u = rng.random(m)
        lo, hi = a.low, a.high
        cols.append(np.exp(np.log(lo) + u * np.log(hi / lo)) if a.log else lo + u * (hi - lo))
    keep = np.ones(m, dtype=bool)
    symbols = [a.symbol for a in kernel.args]
    for c in kernel.constraints:
        keep &= np.asarray(sp.lambdify(symbols, c, "numpy")(*cols), dtype=bool)
    index = np.flatnonzero(keep)[:n]
    if index.size < n:
        raise SystemExit(f"{kernel.name}: not enough points within its constraints")
    return [np.ascontiguousarray(c[index]) for c in cols]


def _c_library(folder: Path):
    cc = shutil.which(os.environ.get("CC", "cc"))
    if cc is None:
        return None
    lib = folder / "libsymimpact.so"
    subprocess.run([cc, "-std=c99", "-O2", "-shared", "-fPIC", str(ROOT / "generated" / "c" /
                    "symimpact.c"), "-o", str(lib), "-lm"], check=True)  # fmt: skip
    return ctypes.CDLL(str(lib))


def _c_call(lib, module, name, cols):
    f = getattr(lib, f"symimpact_{module}_{name}_batch")
    k = parts(module, name)
    out = np.empty(cols[0].size) if k == 1 else np.empty((cols[0].size, k))
    ptr = ctypes.POINTER(ctypes.c_double)
    args = [c.ctypes.data_as(ptr) for c in cols]

    def run():
        f(ctypes.c_size_t(cols[0].size), *args, out.ctypes.data_as(ptr))
        return out if k == 1 else out.T  # a bundle: one row of its parts per point

    return run


RUST_MAIN = """use std::io::Read;
use std::time::Instant;

fn read(path: &str, n: usize, k: usize) -> Vec<Vec<f64>> {{
    let mut bytes = Vec::new();
    std::fs::File::open(path).unwrap().read_to_end(&mut bytes).unwrap();
    let all: Vec<f64> = bytes.chunks_exact(8)
        .map(|b| f64::from_le_bytes(b.try_into().unwrap())).collect();
    (0..k).map(|j| all[j * n..(j + 1) * n].to_vec()).collect()
}}

fn main() {{
    let n: usize = {n};
{body}
}}
"""
RUST_CASE = """    {{
        let a = read("{path}", n, {k});
        let mut out = vec![0.0_f64; n];
        let mut times = Vec::new();
        for _ in 0..{repeats} {{
            let t0 = Instant::now();
            for i in 0..n {{
                out[i] = symimpact::{module}::{name}({args}){total};
            }}
            times.push(t0.elapsed().as_secs_f64());
        }}
        let sum: f64 = out.iter().sum();
        println!("{module}.{name} {{}} {{:e}}", times.iter().map(|t| format!("{{:e}}", t))
            .collect::<Vec<_>>().join(","), sum);
    }}"""


def _rust(folder: Path, cases) -> dict[str, tuple[list[float], float]] | None:
    cargo = shutil.which("cargo")
    if cargo is None:
        return None
    export_kernels("rust", folder / "crate")
    bench = folder / "bench"
    (bench / "src").mkdir(parents=True)
    (bench / "Cargo.toml").write_text(
        '[package]\nname = "bench"\nversion = "0.0.0"\nedition = "2021"\n\n[dependencies]\n'
        'symimpact = { path = "../crate" }\n\n[profile.release]\nopt-level = 3\n'
    )
    body = "\n".join(RUST_CASE.format(path=path, k=len(cols), repeats=REPEATS, module=module,
                                      name=name, args=", ".join(f"a[{j}][i]" for j in
                                                                range(len(cols))),
                                      total="" if parts(module, name) == 1
                                      else ".iter().sum::<f64>()")
                     for module, name, cols, path in cases)  # fmt: skip
    (bench / "src" / "main.rs").write_text(RUST_MAIN.format(n=N, body=body))
    env = {**os.environ, "CARGO_TARGET_DIR": str(folder / "target")}
    subprocess.run([cargo, "build", "--release", "--offline", "-q"], cwd=bench, env=env,
                   check=True)  # fmt: skip
    run = subprocess.run([str(folder / "target" / "release" / "bench")], capture_output=True,
                         text=True, check=True)  # fmt: skip
    return _parse(run.stdout)


FORTRAN_CASE = """    allocate(a({n}, {k}))
    open(newunit=u, file="{path}", access="stream", form="unformatted", status="old")
    read(u) a
    close(u)
    do r = 1, {repeats}
        call system_clock(c0, rate)
{call}
        call system_clock(c1)
        times(r) = real(c1 - c0, dp) / real(rate, dp)
    end do
    write(*, '(a, 1x, *(es24.16, :, ","))', advance="no") "{module}.{name}", times
    write(*, '(1x, es24.16)') sum(out)
    deallocate(a)
"""


def _fortran(folder: Path, cases) -> dict[str, tuple[list[float], float]] | None:
    fc = shutil.which("gfortran")
    if fc is None:
        return None
    export_kernels("fortran", folder / "f90")

    def call(module, name, cols) -> str:
        """The elemental function on the arrays, or a bundle's subroutine in a loop, the sum
        of its parts kept per point."""
        if parts(module, name) == 1:
            args = ", ".join(f"a(:, {j + 1})" for j in range(len(cols)))
            return f"        out = {module}_{name}({args})"
        args = ", ".join(f"a(i, {j + 1})" for j in range(len(cols)))
        return (
            f"        do i = 1, {N}\n            call {module}_{name}({args}, row)\n"
            f"            out(i) = sum(row(1:{parts(module, name)}))\n        end do"
        )

    body = "".join(FORTRAN_CASE.format(n=N, k=len(cols), path=path, repeats=REPEATS,
                                       module=module, name=name, call=call(module, name, cols))
                   for module, name, cols, path in cases)  # fmt: skip
    program = (f"program bench\n    use symimpact\n    implicit none\n"
               f"    real(dp), allocatable :: a(:, :)\n    real(dp) :: out({N}), times({REPEATS}), row(16)\n"
               f"    integer :: u, r, i\n    integer(8) :: c0, c1, rate\n{body}end program bench\n")  # fmt: skip
    (folder / "f90" / "bench.f90").write_text(program)
    for args in (["-c", "symimpact.f90"], ["bench.f90", "symimpact.o", "-o", "bench"]):
        subprocess.run([fc, "-O2", "-ffree-line-length-none", *args], cwd=folder / "f90",
                       check=True)  # fmt: skip
    run = subprocess.run([str(folder / "f90" / "bench")], capture_output=True, text=True,
                         check=True)  # fmt: skip
    return _parse(run.stdout)


def _parse(text: str) -> dict[str, tuple[list[float], float]]:
    out = {}
    for line in text.splitlines():
        key, *times, total = line.replace(",", " ").split()
        out[key] = ([float(t) for t in times], float(total))
    return out


def _rate(times: list[float]) -> str:
    med = statistics.median(times)
    return f"{N / med:.4g} ev/s ({N / max(times):.4g}–{N / min(times):.4g})"


def main() -> None:
    rng = np.random.default_rng(20261125)
    kernels = declared()
    print(f"generated targets: evaluations per second at N = {N:.0e}, one core, median of "
          f"{REPEATS} runs (slowest–fastest); ratio = NumPy's time / the target's")  # fmt: skip
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        lib = _c_library(folder)
        cases, data = [], {}
        for module, name, _ in KERNELS:
            cols = points(kernels[module, name], N, rng)
            path = folder / f"{module}.{name}.bin"
            np.concatenate(cols).astype("<f8").tofile(path)
            cases.append((module, name, cols, str(path)))
            data[module, name] = cols
        rust = _rust(folder, cases)
        fortran = _fortran(folder, cases)
        try:
            import jax
            import jax.numpy as jnp
            from symimpact.generated import jax as jax_kernels
        except ImportError:
            jax_kernels = None
        for module, name, label in KERNELS:
            cols = data[module, name]
            numpy_kernel = getattr(__import__(f"symimpact.generated.{module}",
                                              fromlist=[name]), name)  # fmt: skip
            tn = timed(lambda f=numpy_kernel, c=cols: f(*c))
            ref = np.asarray(tn.out)  # a bundle: (parts, points)
            print(f"\n{module}.{name} ({label}, {len(cols)} arguments)")
            print(f"  NumPy    {tn.rate(N, 'ev/s')}")
            if lib is not None:
                tc = timed(_c_call(lib, module, name, cols))
                diff = np.max(np.abs(tc.out - ref)) / np.max(np.abs(ref))
                print(f"  C        {tc.rate(N, 'ev/s')}; ratio {tn.median / tc.median:.1f}x; "
                      f"max |diff| from NumPy {diff:.1e} of max |value|")  # fmt: skip
            if jax_kernels is not None:
                f = getattr(getattr(jax_kernels, module), name)
                dev = [jnp.asarray(c) for c in cols]
                t0 = time.perf_counter()
                jax.block_until_ready(f(*dev))  # traced and compiled here
                first = time.perf_counter() - t0
                tj = timed(lambda f=f, dev=dev: jax.block_until_ready(f(*dev)))
                compile_s = first - tj.median
                diff = np.max(np.abs(np.asarray(tj.out) - ref)) / np.max(np.abs(ref))
                print(f"  JAX      {tj.rate(N, 'ev/s')}; ratio {tn.median / tj.median:.1f}x; "
                      f"max |diff| from NumPy {diff:.1e} of max |value|; first call (trace and compile) "
                      f"{compile_s:.2f} s more; jax {jax.__version__}")  # fmt: skip
            for target, found in (("Rust", rust), ("Fortran", fortran)):
                if found is None:
                    print(f"  {target:<8} not built (its compiler is not installed)")
                    continue
                times, total = found[f"{module}.{name}"]
                rel = abs(total - float(np.sum(ref))) / abs(float(np.sum(ref)))
                print(f"  {target:<8} {_rate(times)}; ratio "
                      f"{tn.median / statistics.median(times):.1f}x; sum of the results "
                      f"{rel:.1e} from NumPy's")  # fmt: skip
    print("\ntarget: none (figures); C, Rust and Fortran at -O2/opt-level 3 without -march")
    bundles(rng)


def _numba_loop(f, outputs: int):
    """A compiled loop over the points (columns of a 10-row array) calling the scalar kernel
    ``f`` and summing its ``outputs`` values (so that nothing is optimised away)."""
    from numba import njit

    g = njit(cache=False)(f)

    @njit(cache=False)
    def one(a):
        total = 0.0
        for i in range(a.shape[1]):
            total += g(a[0, i], a[1, i], a[2, i], a[3, i], a[4, i], a[5, i], a[6, i], a[7, i],
                       a[8, i], a[9, i])  # fmt: skip
        return total

    @njit(cache=False)
    def many(a):
        total = 0.0
        for i in range(a.shape[1]):
            for v in g(a[0, i], a[1, i], a[2, i], a[3, i], a[4, i], a[5, i], a[6, i], a[7, i],
                       a[8, i], a[9, i]):  # fmt: skip
                total += v
        return total

    return one if outputs == 1 else many


def bundles(rng) -> None:
    """The flight's bundles against their parts one by one (module text)."""
    from symimpact.generated import forced_flight as ff

    x = next(k for k in board("forced_flight").kernels if k.name == "forced_displacement")
    cols = points(x, N, rng)
    stack = np.ascontiguousarray(np.vstack(cols))
    print("\nbundles against their parts, the same points (forced flight, Eq. F1), one core")
    for name, parts in (
        ("forced_state", ("forced_displacement", "forced_velocity")),
        ("forced_transition", ("forced_displacement", "forced_velocity",
                               "forced_displacement_d_x0", "forced_displacement_d_xdot0",
                               "forced_velocity_d_x0", "forced_velocity_d_xdot0")),
    ):  # fmt: skip
        whole = getattr(ff, name)
        tb = timed(lambda c=cols, f=whole: f(*c))
        tp = timed(lambda c=cols, ps=parts: [getattr(ff, p)(*c) for p in ps])
        diff = max(float(np.max(np.abs(a - b)) / np.max(np.abs(b)))
                   for a, b in zip(tb.out, tp.out, strict=True))  # fmt: skip
        # the bundle in one loop; its parts one by one, a loop each, as separate calls would be
        whole_loop = _numba_loop(getattr(ff, f"{name}_scalar"), len(parts))
        part_loops = [_numba_loop(getattr(ff, f"{p}_scalar"), 1) for p in parts]
        for f in (whole_loop, *part_loops):
            f(stack[:, :10])  # compiled here
        nb = timed(lambda f=whole_loop: f(stack))
        np_ = timed(lambda fs=part_loops: [f(stack) for f in fs])
        print(f"{name} ({len(parts)} parts)")
        print(f"  NumPy: bundle {tb.rate(N, 'ev/s')}; parts {tp.rate(N, 'ev/s')}; ratio "
              f"{tp.median / tb.median:.2f}x; max |diff| {diff:.1e} of max |value|")  # fmt: skip
        print(f"  numba scalar twins: bundle {nb.rate(N, 'ev/s')}; parts {np_.rate(N, 'ev/s')}; "
              f"ratio {np_.median / nb.median:.2f}x")  # fmt: skip


if __name__ == "__main__":
    main()
