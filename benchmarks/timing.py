"""Timing shared by the benchmarks: every figure is the median of at least five repeats, printed
with its spread (fastest–slowest), and the machine is named by its CPU model."""

from __future__ import annotations

import os
import platform
import statistics
import time
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

REPEATS = 5


@dataclass(frozen=True)
class Timing:
    """Median, fastest and slowest of ``n`` repeats [s], and the last repeat's return value."""

    median: float
    fastest: float
    slowest: float
    n: int
    out: Any = None

    def ms(self) -> str:
        """``1.234 ms (1.200–1.300)``."""
        return f"{self.median * 1e3:.3f} ms ({self.fastest * 1e3:.3f}–{self.slowest * 1e3:.3f})"

    def s(self) -> str:
        """``1.23 s (1.20–1.30)``."""
        return f"{self.median:.3f} s ({self.fastest:.3f}–{self.slowest:.3f})"

    def rate(self, count: float, unit: str) -> str:
        """``count`` per median second, with the spread: ``5.1e+06 ev/s (4.9e+06–5.2e+06)``."""
        return (
            f"{count / self.median:.4g} {unit} ({count / self.slowest:.4g}–"
            f"{count / self.fastest:.4g})"
        )


def timed(fn: Callable[[], Any], repeat: int = REPEATS, clock=time.perf_counter) -> Timing:
    """Run ``fn`` ``repeat`` times (at least five) and return the median and the spread."""
    repeat = max(repeat, REPEATS)
    times = []
    out = None
    for _ in range(repeat):
        t0 = clock()
        out = fn()
        times.append(clock() - t0)
    return Timing(statistics.median(times), min(times), max(times), repeat, out)


def cpu_model() -> str:
    """The CPU's model name (from /proc/cpuinfo on Linux), or what the platform module says."""
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or platform.machine()


def machine() -> str:
    """One line: CPU model, cores, OS, Python and the versions of the libraries timed."""
    import numba
    import numpy

    return (
        f"{cpu_model()}, {os.cpu_count()} cores, {platform.system()} {platform.release()}; "
        f"Python {platform.python_version()}, NumPy {numpy.__version__}, numba {numba.__version__}"
    )
