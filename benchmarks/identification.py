"""Identification from a free decay (issue 82's speed case): a 10 s record at 5 kHz of the
README's primary (M 1 kg, K 1000 N/m, ζ 1 %) with a 50 g ball in 10 mm, e 0.6, tapped to
0.3 m/s, with 1 % noise (of the tap's amplitude), fitted for e, ζ, d and the tap's x₀, ẋ₀.

The record is the package's own engine's (the benchmark times the fit, not its accuracy, which
tests/test_identify_decay.py checks against DOP853).  The baseline, measured in the same run, is
one simulation of the whole record: the fit's time over it is how many whole-record runs the fit
costs (its windows, its differences, its profiles).  The fit itself is timed once (it takes
minutes); the baseline is a median of five.  Prints figures, asserts nothing.
Run from the checkout: python -m benchmarks.identification
"""

from __future__ import annotations

import time

import numpy as np

from symimpact.identify.decay import Decay, fit_decay, simulated_decay
from symimpact.model.system import ImpactSystem

from .timing import timed

RIG = ImpactSystem(M=1.0, K=1000.0, m=0.05, gap=0.010, zeta=0.01, k_hz=1000.0)
TOLD = ImpactSystem(M=1.0, K=1000.0, m=0.05, gap=0.03, zeta=0.05, k_hz=1000.0)


def main(duration: float = 10.0, rate: float = 5000.0) -> None:
    dt = 1.0 / rate
    n = round(duration * rate) + 1
    truth = simulated_decay(RIG, 0.6, n, dt, 0.0, 0.3)
    clean, n_true = truth.displacement, truth.impact_times.size
    amplitude = 0.3 / RIG.omega_n
    data = Decay(clean + np.random.default_rng(82).normal(0.0, 0.01 * amplitude, n), dt,
                 "displacement")  # fmt: skip
    one = timed(lambda: simulated_decay(RIG, 0.6, n, dt, 0.0, 0.3))
    print(f"a decay of {duration:g} s at {rate:g} Hz ({n} samples), 1 % noise")
    print(f"  one run of the whole record (baseline): {one.ms()}")
    t0 = time.perf_counter()
    result, response = fit_decay(TOLD, data)
    took = time.perf_counter() - t0
    print(f"  the fit of e, zeta, gap, x0, xdot0 with 95 % profiles: {took:.1f} s, "
          f"{took / one.median:.0f} whole-record runs' time (target: 30 s)")  # fmt: skip
    for p in result.parameters.values():
        print(f"    {p.name} = {p.value:.6g} ± {p.stderr or float('nan'):.2g} {p.unit}")
    print(f"  {response.impact_times.size} impacts (the record's own: {n_true})")
    for w in result.warnings:
        print(f"  warning: {w}")


if __name__ == "__main__":
    main()
