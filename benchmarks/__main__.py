"""Run every benchmark in turn: ``python -m benchmarks`` from the checkout (a few minutes).

Each prints its figures, the baseline measured in the same run and the ratio; none asserts a
time.  The figures of one run, with the machine, are kept in ``benchmarks/RESULTS.md``.
"""

from __future__ import annotations

import os
import platform
import sys
import time

from . import contact_duration_kernel, map_throughput, simulation_speed, startup

SUITE = (
    ("1. simulation: fast path vs solve_ivp", simulation_speed.main),
    ("2. contact-duration kernel (Eq. 31) vs sympy.lambdify", contact_duration_kernel.main),
    ("3. map throughput and Dask scaling", map_throughput.main),
    ("4. start-up: import symimpact, python -m derive", startup.main),
)


def main() -> None:
    import numba
    import numpy

    print(
        f"machine: {platform.machine()} {platform.processor() or platform.platform()}, "
        f"{os.cpu_count()} cores; Python {sys.version.split()[0]}, NumPy {numpy.__version__}, "
        f"numba {numba.__version__}"
    )
    for title, run in SUITE:
        print(f"\n=== {title} ===")
        t0 = time.perf_counter()
        run()
        print(f"({time.perf_counter() - t0:.0f} s)")


if __name__ == "__main__":
    main()
