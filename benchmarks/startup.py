"""``import symimpact`` time (a fresh interpreter each time; SymPy must not be imported), a warm
``symimpact simulate`` beside ``python -c pass`` (median of 5, numba's cache already filled), and
the time of ``python -m derive --check`` (every derivation re-run and the generated files
compared).  Prints figures and ratios to baselines measured in the same run; asserts nothing.
Run from the checkout: python -m benchmarks.startup
"""

from __future__ import annotations

import subprocess
import sys

from .timing import Timing, timed

PROBE = (
    "import sys, time; t = time.perf_counter(); import {mod}; "
    "print(time.perf_counter() - t, 'sympy' in sys.modules, 'pandas' in sys.modules, "
    "'numba' in sys.modules)"
)


def import_time(mod: str) -> tuple[Timing, list[str]]:
    """Time of ``import mod`` in a fresh interpreter (median of 7), and whether SymPy, pandas and
    numba were imported with it."""
    flags: list[str] = []

    def once() -> float:
        out = subprocess.run(
            [sys.executable, "-c", PROBE.format(mod=mod)],
            capture_output=True,
            text=True,
            check=True,
        ).stdout.split()
        flags[:] = out[1:]
        return float(out[0])

    times = sorted(once() for _ in range(7))
    return Timing(times[3], times[0], times[-1], 7), flags


def command_time(args: list[str]) -> Timing:
    return timed(lambda: subprocess.run(args, check=True, capture_output=True))


def main() -> None:
    base, _ = import_time("numpy")
    t, (sympy, pandas, numba) = import_time("symimpact")
    print(f"import numpy (baseline): {base.s()}")
    print(
        f"import symimpact:        {t.s()}  ({t.median / base.median:.1f}x numpy; target <= 0.6 s)"
    )
    print(f"  imported sympy: {sympy}, pandas: {pandas}, numba: {numba} (sympy must be False)")
    simulate = [sys.executable, "-m", "symimpact.cli", "simulate"]
    subprocess.run(simulate, check=True, capture_output=True)  # fills numba's cache if empty
    empty = command_time([sys.executable, "-c", "pass"])
    warm = command_time(simulate)
    print(f"python -c pass (baseline): {empty.s()}")
    print(f"symimpact simulate, warm:  {warm.s()}  (target <= 0.8 s)")
    numba = command_time([sys.executable, "-c", "import numba"])
    print(f"  importing numba alone: {numba.median - empty.median:.3f} s beyond python -c pass")
    check = timed(
        lambda: subprocess.run(
            [sys.executable, "-m", "derive", "--check", "--quiet"], check=True, capture_output=True
        )
    )
    import derive

    print(f"python -m derive --check: {check.s()} (all {len(derive.STEPS)} steps re-derived)")


if __name__ == "__main__":
    main()
