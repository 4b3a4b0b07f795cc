"""The clearance design map of issue 33's speed target, "a design map of 20 clearances ≤ 2 min on
the 2-core machine": the issue's 12 Hz system (M 40 kg, K 227 396 N/m, ζ 0.01, m 2 kg, F0 50 N,
rigid e 0.6) over 8–16 Hz at 0.05 Hz (161 frequencies), 20 clearances 6–25 mm, each row a whole
frequency-response curve as ``symimpact design`` computes it by default (branches with switching,
the refined multi-start at 15 frequencies, the sweeps, the located peak;
:func:`symimpact.maps.design.design_map`), on 2 processes; then the best clearance refined to
0.01 mm (:func:`symimpact.maps.design.refine_best`: Brent's method, the walk, the peak at
e ± 0.1).  The baseline, measured in the same run: the same map on one process.

Each map is timed once (a map is minutes: five repeats would be most of an hour); the line says
so.  Asserts nothing.  Run from the checkout: ``python -m benchmarks --only 12``.
"""

from __future__ import annotations

import math
import time

import numpy as np

from symimpact.forced.forcing import Forcing
from symimpact.maps.design import design_map, refine_best
from symimpact.model.system import ImpactSystem

#: The 12 Hz system of issue 33 (the contact law is unused: the impacts are rigid, e 0.6).
SYSTEM = ImpactSystem(M=40.0, K=227396.0, zeta=0.01, m=2.0, gap=0.010, contact="linear", k1=1e6)
FORCING = Forcing(F0=50.0, omega=2 * math.pi * 12.0)
E = 0.6
BAND = 2 * math.pi * np.arange(8.0, 16.0001, 0.05)  # rad/s
GAPS = np.arange(6.0, 25.001, 1.0) * 1e-3  # m: 20 clearances
TARGET = 120.0  # s


def main() -> None:
    # numba compiles on the first call: one small map first, untimed
    design_map(SYSTEM, FORCING, E, BAND[:5], {"gap": GAPS[:1]}, workers=1)
    grid = {"gap": GAPS}
    t0 = time.perf_counter()
    table = design_map(SYSTEM, FORCING, E, BAND, grid, executor="processes", workers=2)
    parallel = time.perf_counter() - t0
    t0 = time.perf_counter()
    (best,) = refine_best(table, SYSTEM, FORCING, E, BAND)
    refined = time.perf_counter() - t0
    t0 = time.perf_counter()
    serial_table = design_map(SYSTEM, FORCING, E, BAND, grid, workers=1)
    serial = time.perf_counter() - t0
    same = np.array_equal(
        table["peak_amplitude"].to_numpy(), serial_table["peak_amplitude"].to_numpy()
    )
    grid_best = table.loc[table["peak_amplitude"].idxmin()]
    print(f"the 12 Hz system of issue 33, e {E}, {len(BAND)} frequencies 8-16 Hz, "
          f"{len(GAPS)} clearances {GAPS[0] * 1e3:g}-{GAPS[-1] * 1e3:g} mm; each map timed once")  # fmt: skip
    print(f"design map on 2 processes: {parallel:.1f} s (target <= {TARGET:.0f} s), "
          f"{parallel / len(GAPS):.1f} s a clearance")  # fmt: skip
    print(f"  the same map on one process (baseline): {serial:.1f} s; ratio {serial / parallel:.2f}; "
          f"peaks identical: {same}")  # fmt: skip
    print(f"  grid's best: d {grid_best['gap'] * 1e3:g} mm, peak "
          f"{grid_best['peak_amplitude'] * 1e3:.4f} mm (baseline peak "
          f"{grid_best['baseline_peak'] * 1e3:.4f} mm)")  # fmt: skip
    print(f"refined to {best['tolerance'] * 1e3:g} mm: {refined:.1f} s, {best['evaluations']} "
          f"curves; d {best['gap'] * 1e3:.4f} mm, peak {best['peak_amplitude'] * 1e3:.4f} mm "
          f"(e - 0.1: {best['peak_e_minus'] * 1e3:.4f} mm, e + 0.1: "
          f"{best['peak_e_plus'] * 1e3:.4f} mm)")  # fmt: skip
    print(f"map and refinement together: {parallel + refined:.1f} s")


if __name__ == "__main__":
    main()
