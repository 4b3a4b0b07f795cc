"""The continuation's ∂P/∂p carried along the monodromy's chain (the generated derivative kernels,
issue 38 item 1) against central differences of the map (two more simulations per evaluation,
what the continuation did before): the same branches traced both ways, their largest relative
difference in parameter and amplitude, and the time of each (median of five, spread).

Branches of issue 21's rigid system (M 1 kg, K 1000 N/m, C 0.5 N s/m, m 0.05 kg, d 20 mm,
F0 2 N, e 0.6) in Ω, d and e from the orbit at 36 rad/s, and of issue 33's 12 Hz primary
(M 40 kg, ζ 0.01, m 2 kg, d 10 mm, F0 50 N, e 0.6) in Ω both ways from 12 Hz.  Prints figures
and ratios; asserts nothing.  Run from the checkout: python -m benchmarks.parameter_derivative
"""

from __future__ import annotations

import math

import numpy as np

from symimpact.forced.forcing import Forcing
from symimpact.forced.orbits import continuation as cont
from symimpact.forced.orbits.shooting import shoot_from_rest
from symimpact.model.system import ImpactSystem

from .timing import timed


def cases():
    """(label, system, forcing, start state, bounds, parameter, direction)."""
    small = ImpactSystem(M=1.0, K=1000.0, C=0.5, m=0.05, gap=0.02, contact="hertz", k_hz=1000.0)
    f = Forcing(F0=2.0, omega=36.0)
    s0 = shoot_from_rest(small, f, 0.6).state
    k12 = 40.0 * (2 * math.pi * 12.0) ** 2
    big = ImpactSystem(M=40.0, K=k12, zeta=0.01, m=2.0, gap=0.01, contact="hertz", k_hz=1000.0)
    f12 = Forcing(F0=50.0, omega=2 * math.pi * 12.0)
    s12 = shoot_from_rest(big, f12, 0.6, start=(0.0, 0.0, 0.0, 0.3)).state
    band = (2 * math.pi * 8.0, 2 * math.pi * 16.0)
    return [
        ("issue 21, Ω down from 36 rad/s", small, f, s0, (25.0, 40.0), "omega", -1),
        ("issue 21, d from 20 mm", small, f, s0, (0.005, 0.04), "gap", 1),
        ("issue 21, e from 0.6", small, f, s0, (0.3, 0.9), "e", 1),
        ("12 Hz primary, Ω down from 12 Hz", big, f12, s12, band, "omega", -1),
        ("12 Hz primary, Ω up from 12 Hz", big, f12, s12, band, "omega", 1),
    ]


def main() -> None:
    print("continuation: ∂P/∂p along the chain (generated derivative kernels) against central "
          "differences of the map; median of 5 (fastest–slowest)")  # fmt: skip
    for label, system, f, s0, bounds, parameter, direction in cases():

        def trace(system=system, f=f, s0=s0, bounds=bounds, p=parameter, d=direction):
            return cont.continue_orbit(system, f, 0.6, s0, bounds, parameter=p, direction=d)

        tc = timed(trace)
        cont._Problem.carried = False  # ∂P/∂p by central differences of the map
        try:
            td = timed(trace)
        finally:
            cont._Problem.carried = True
        a = np.array([(p.value, p.amplitude) for p in tc.out.points])
        b = np.array([(p.value, p.amplitude) for p in td.out.points])
        same = a.shape == b.shape
        rel = float(np.max(np.abs(a - b) / np.abs(b))) if same else float("nan")
        print(f"\n{label}: {len(a)} points (differences: {len(b)}), "
              f"largest relative difference {rel:.1e}; ends: {tc.out.stopped}")  # fmt: skip
        print(f"  chain        {tc.s()}")
        print(f"  differences  {td.s()}; ratio {td.median / tc.median:.2f}x")
    print("\ntarget: the same branches (1e-8); time: figures")


if __name__ == "__main__":
    main()
