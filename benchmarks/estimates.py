"""The estimates the sampled-load commands print before they run, against the time the run then
takes (:mod:`symimpact.forced.loads.record_cost`): a primary of 5.03 Hz (M 1 kg, K 1000 N/m,
C 0.5 N s/m) with a 50 g impact mass in a 20 mm clearance, rigid impacts (e 0.6) or a Hertz
contact (1e6 N/m^1.5), under a random force (2 N²/Hz over 1–20 Hz, 8 realisations of 500 s)
and a sine sweep (2 N, 1–20 Hz at 0.003 Hz/s, up and down, without the steady curve).  Each row
is one estimate and one run of the API call the command makes (the estimate is itself timed,
so repeats would give other estimates); the ratios say how far the printed "about" was off (a
sweep's estimate is a span: from the rate of its first piece to that of the piece where it
crosses the primary's natural frequency).
Run from the checkout: python -m benchmarks.estimates
"""

from __future__ import annotations

import time

from symimpact.forced.contact_law import CompliantContact
from symimpact.forced.loads.random_response import ensemble_estimate, random_statistics
from symimpact.forced.loads.record_cost import duration_text
from symimpact.forced.loads.sweep_response import sweep_estimate, sweep_response
from symimpact.model.system import ImpactSystem

RIGID = ImpactSystem(M=1.0, K=1000.0, C=0.5, m=0.05, gap=0.02, contact="linear", k1=1e5)
HERTZ = ImpactSystem(M=1.0, K=1000.0, C=0.5, m=0.05, gap=0.02, contact="hertz", k_hz=1e6, c1=0.0)
CASES = {
    "rigid e 0.6": (RIGID, 0.6),
    "Hertz 1e6 N/m^1.5": (HERTZ, CompliantContact("hertz")),
}
DT = 1.0 / 400.0  # the commands' default at a 20 Hz top: 20 samples a period


def _row(name: str, estimate, run, *args, **kwargs) -> None:
    start = time.perf_counter()
    run(*args, **kwargs)
    took = time.perf_counter() - start
    print(f"  {name:<30} estimate {duration_text(estimate.seconds):>6} to "
          f"{duration_text(estimate.high):>6}, took {duration_text(took):>6}: ratios "
          f"{estimate.seconds / took:.2f} to {estimate.high / took:.2f}")  # fmt: skip


def main() -> None:
    for label, (system, e) in CASES.items():
        args = (system, 2.0, (1.0, 20.0), 500.0, DT)
        estimate = ensemble_estimate(*args, e=e, realisations=8)
        _row(f"random, {label}", estimate, random_statistics, *args, e=e, realisations=8)
        sweep = (system, 2.0, 1.0, 20.0, 0.003, DT)
        estimate = sweep_estimate(*sweep, e=e)
        _row(f"sweep-sine, {label}", estimate, sweep_response, *sweep, e=e)


if __name__ == "__main__":
    main()
