"""Run every benchmark in turn: ``python -m benchmarks`` from the checkout (about 20 minutes on
2 cores); ``python -m benchmarks --write benchmarks/RESULTS.md`` also writes what the run printed
into that file, under a header naming the date and the machine; with ``--only N`` (repeatable)
it replaces those sections of the file, each stamped with its own run, and keeps the others.

Each benchmark prints its figures (medians of at least five repeats with their spread), the
baseline measured in the same run and the ratio; none asserts a time.  RESULTS.md is only ever
written this way, from a run's output, never by hand.
"""

from __future__ import annotations

import argparse
import contextlib
import datetime
import io
import re
import sys
import time

from . import (
    contact_duration_kernel,
    coverage,
    design_map,
    estimates,
    first_run,
    frc,
    harmonic_balance,
    identification,
    map_throughput,
    million_map,
    one_mode_engine,
    parameter_derivative,
    random_loads,
    startup,
    stepper_peers,
    structure,
    targets,
)
from .timing import machine

SUITE = (
    ("1. the stepper against its peers, each tuned to 1e-9 s impact times", stepper_peers.main),
    ("2. contact-duration kernel (Eq. 31) against sympy.lambdify", contact_duration_kernel.main),
    ("3. map throughput: compiled chunks against the per-point path; Dask", map_throughput.main),
    ("4. a map of 10^6 runs", million_map.main),
    ("5. start-up: import symimpact, symimpact simulate, python -m derive --check", startup.main),
    ("6. a 200-frequency response curve with stability against brute-force sweeps", frc.main),
    ("7. the generated targets (C, JAX, Rust, Fortran) against NumPy at 10^6 points", targets.main),
    (
        "8. the continuation's ∂P/∂p: the chain's derivative kernels against differences",
        parameter_derivative.main,
    ),
    (
        "9. random vibration with the damper: realisations per second, Dask scaling",
        random_loads.main,
    ),
    (
        "10. a structure of several modes with impact dampers: cost against N, against DOP853, its curve",
        structure.main,
    ),
    (
        "11. the one-mode system through the engine of several modes against the engine it replaced",
        one_mode_engine.main,
    ),
    ("12. a clearance design map of 20 clearances, refined to 0.01 mm", design_map.main),
    (
        "13. the curves' coverage of the brute force's motions on the 12 Hz and report systems",
        coverage.main,
    ),
    (
        "14. the sampled loads' estimates, printed before they run, against their runs",
        estimates.main,
    ),
    ("15. the first run after an install: each engine's compilation, then warm", first_run.main),
    (
        "16. a 10 s free decay at 5 kHz identified: e, ζ, d with their intervals",
        identification.main,
    ),
    (
        "17. a 200-frequency curve by harmonic balance (H = 15) beside the exact one",
        harmonic_balance.main,
    ),
)


class _Tee(io.TextIOBase):
    def __init__(self, *streams):
        self.streams = streams

    def write(self, text: str) -> int:
        for s in self.streams:
            s.write(text)
            s.flush()
        return len(text)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m benchmarks", description=__doc__)
    parser.add_argument("--write", metavar="FILE", help="also write the run's output to FILE")
    parser.add_argument(
        "--only", metavar="N", type=int, action="append", help="run benchmark N only (repeatable)"
    )
    ns = parser.parse_args(argv)
    captured = io.StringIO()
    started = datetime.datetime.now(datetime.UTC)
    with contextlib.redirect_stdout(_Tee(sys.stdout, captured)):
        print(f"machine: {machine()}")
        for k, (title, run) in enumerate(SUITE, start=1):
            if ns.only and k not in ns.only:
                continue
            print(f"\n=== {title} ===")
            t0 = time.perf_counter()
            run()
            print(f"({time.perf_counter() - t0:.0f} s)")
    if ns.write:
        text = captured.getvalue().strip()
        if ns.only:
            text = _merged(ns.write, text, started)
        with open(ns.write, "w") as f:
            f.write(
                "# Benchmark figures\n\n"
                f"Written by `python -m benchmarks --write {ns.write}` (with `--only N`: the "
                "sections that run replaced, each under its own run's header) from the runs' "
                "output; not edited by hand. Each figure is the median of at least five repeats "
                "with the spread (fastest–slowest), unless the line says otherwise; every "
                "baseline was measured in the same run as what it is compared with.\n\n"
                "```text\n" + text + "\n```\n"
            )
    return 0


def _sections(text: str) -> tuple[list[str], dict[int, str]]:
    """The machine lines before the first section and each section's text, by number."""
    head, sections, number = [], {}, None
    for line in text.splitlines():
        if line.startswith("=== "):
            number = int(line[4:].split(".")[0])
            sections[number] = line
        elif number is None:
            head.append(line)
        else:
            sections[number] += "\n" + line
    return head, sections


def _merged(path: str, text: str, started: datetime.datetime) -> str:
    """The figures already in ``path`` with the sections of this run (``text``) put in their
    place, each section led by the machine and start time of the run that printed it."""
    try:
        with open(path) as f:
            whole = f.read()
        old = whole.split("```text\n", 1)[1].rsplit("\n```", 1)[0]
    except (OSError, IndexError):
        whole, old = "", ""
    head_old, kept = _sections(old)
    when = re.search(r"run started (\d{4}-\d\d-\d\d \d\d:\d\d) UTC;", whole)
    if head_old and when and not head_old[0].startswith("("):
        head_old[0] = f"(the sections without a stamp: run started {when[1]} UTC) {head_old[0]}"
    head_new, fresh = _sections(text)
    stamp = f"(run started {started:%Y-%m-%d %H:%M} UTC; {' '.join(head_new).strip()})"
    for number, body in fresh.items():
        title, _, rest = body.partition("\n")
        kept[number] = f"{title}\n{stamp}\n{rest}".rstrip()
    # each section without its trailing blank lines: a kept one is joined again as it was
    return (
        "\n".join(head_old).strip() + "\n\n" + "\n\n".join(kept[k].rstrip() for k in sorted(kept))
    )


if __name__ == "__main__":
    sys.exit(main())
