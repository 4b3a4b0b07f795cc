"""``import symimpact`` time (a fresh interpreter each time; SymPy must not be imported), a warm
``symimpact simulate`` beside ``python -c pass`` (best of 5, numba's cache already filled), and
the time of ``python -m derive --check`` (every derivation re-run and the generated files
compared).  Prints figures and ratios to baselines measured in the same run; asserts nothing.
Run from the checkout: python -m benchmarks.startup
"""

from __future__ import annotations

import subprocess
import sys
import time

PROBE = (
    "import sys, time; t = time.perf_counter(); import {mod}; "
    "print(time.perf_counter() - t, 'sympy' in sys.modules, 'pandas' in sys.modules, "
    "'numba' in sys.modules)"
)


def import_time(mod: str, repeat: int = 7) -> tuple[float, list[str]]:
    best, flags = float("inf"), []
    for _ in range(repeat):
        out = subprocess.run(
            [sys.executable, "-c", PROBE.format(mod=mod)],
            capture_output=True,
            text=True,
            check=True,
        ).stdout.split()
        if float(out[0]) < best:
            best, flags = float(out[0]), out[1:]
    return best, flags


def command_time(args: list[str], repeat: int = 5) -> float:
    best = float("inf")
    for _ in range(repeat):
        t0 = time.perf_counter()
        subprocess.run(args, check=True, capture_output=True)
        best = min(best, time.perf_counter() - t0)
    return best


def main() -> None:
    base, _ = import_time("numpy")
    t, (sympy, pandas, numba) = import_time("symimpact")
    print(f"import numpy (baseline): {base:.3f} s")
    print(f"import symimpact:        {t:.3f} s  ({t / base:.1f}x numpy; target <= 0.6 s)")
    print(f"  imported sympy: {sympy}, pandas: {pandas}, numba: {numba} (sympy must be False)")
    simulate = [sys.executable, "-m", "symimpact.cli", "simulate"]
    subprocess.run(simulate, check=True, capture_output=True)  # fills numba's cache if empty
    empty = command_time([sys.executable, "-c", "pass"])
    warm = command_time(simulate)
    print(f"python -c pass (baseline): {empty:.3f} s")
    print(f"symimpact simulate, warm:  {warm:.3f} s  (target <= 0.8 s)")
    numba = command_time([sys.executable, "-c", "import numba"], repeat=3)
    print(f"  importing numba alone: {numba - empty:.3f} s beyond python -c pass")
    t0 = time.perf_counter()
    subprocess.run(
        [sys.executable, "-m", "derive", "--check", "--quiet"], check=True, capture_output=True
    )
    print(f"python -m derive --check: {time.perf_counter() - t0:.1f} s (all 7 steps re-derived)")


if __name__ == "__main__":
    main()
