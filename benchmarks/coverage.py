"""How many of the stable motions a brute force finds lie on the curve's branches, on issue 33's
other target systems (the README's band is benchmark 6): the 12 Hz system of the issue (M 40 kg,
K 227 396 N/m, ζ 0.01, m 2 kg, d 10 mm, F0 50 N, rigid e 0.6, 8–16 Hz) and the report's three
rigid curves (the chosen reading of the paper's beam, F0 0.2 N, 0.5–1.5 ω_n, e of the paper's
linear contact, d 9, 15 and 25 mm).

Each system's multi-start brute force (four initial states at each of 200 frequencies, each
periodic motion shot; :func:`symimpact.forced.orbits.coverage.attractors`) lists its periodic
attractors of at most four periods, and each curve (``symimpact frf --no-sweeps``, by default
with ``--embedded`` and with ``--folds --embedded``) is measured against them: the share on a traced branch (amplitude
within 1e-7 relative, :func:`symimpact.forced.orbits.frf._traced`) and the frequencies of those missed.
These are coverage figures, not speed targets: each curve and brute force runs once, and its
time is that one run's.  Run from the checkout: python -m benchmarks.coverage
"""

from __future__ import annotations

import math
import time

import numpy as np
from symimpact.generated import closed_forms

from symimpact.forced.forcing import Forcing
from symimpact.forced.orbits.coverage import attractors
from symimpact.forced.orbits.frf import MAX_SWITCH_PERIODS, _traced, frequency_response
from symimpact.model.system import ImpactSystem
from symimpact.model.units import si
from symimpact.report import forced_stage, paper
from symimpact.report.vibration_stage import STATED, _choose_reading, _table3_runs

#: Multi-start brute force: frequencies over the band (as benchmark 6).
BRUTE = 200


def twelve_hertz() -> tuple[str, ImpactSystem, Forcing, float, np.ndarray]:
    """The issue's 12 Hz system: ζ 0.01 gives C = 2ζ·sqrt(K·M).  Its impacts are rigid (e 0.6);
    the system's compliant law (linear, k1 1e6 N/m, as benchmark 6's) is not used."""
    M, K = 40.0, 227_396.0
    system = ImpactSystem(M=M, K=K, C=2 * 0.01 * math.sqrt(K * M), m=2.0, gap=0.01,
                          contact="linear", k1=1e6)  # fmt: skip
    band = 2 * math.pi * np.linspace(8.0, 16.0, 161)  # the 0.05 Hz step
    return "12 Hz system, d 10 mm, e 0.6", system, Forcing(F0=50.0, omega=band[0]), 0.6, band


def report_curves() -> list[tuple[str, ImpactSystem, Forcing, float, np.ndarray]]:
    """The report's rigid curves, built as its forced stage builds them."""
    base = _choose_reading(_table3_runs(STATED))[0].system(forced_stage.GAPS_MM[0])
    k1 = si("k1", paper.FIT["k1"] + " N/m")
    e = float(closed_forms.linear_restitution(base.m, base.M, k1, base.c1))
    lo, hi = forced_stage.BAND
    band = np.linspace(lo * base.omega_n, hi * base.omega_n, forced_stage.N_BAND)
    forcing = Forcing(F0=forced_stage.F0, omega=float(band[0]))
    return [(f"report's curve, d {d:g} mm, e {e:.4f}", base.with_(gap=d * 1e-3), forcing, e, band)
            for d in forced_stage.GAPS_MM]  # fmt: skip


def main() -> None:
    cases = [twelve_hertz(), *report_curves()]
    # numba compiles on the first call: one small curve before timing
    frequency_response(*cases[0][1:4], cases[0][4][:3], starts=1, sweeps=False, multistart=1)
    modes = {"frf (default)": {}, "frf --embedded": {"embedded": True},
             "frf --folds --embedded": {"folds": True, "embedded": True}}  # fmt: skip
    totals = {mode: [0, 0] for mode in modes}
    for name, system, forcing, e, band in cases:
        t0 = time.perf_counter()
        found = attractors(system, forcing, e, (band[0], band[-1]), BRUTE)
        brute = time.perf_counter() - t0
        shot = [
            a for a in found if a.kind == "periodic" and a.period_multiple <= MAX_SWITCH_PERIODS
        ]
        print(f"{name}, Ω {band[0]:.4g}–{band[-1]:.4g} rad/s ({len(band)} frequencies): "
              f"multi-start brute force at {BRUTE} frequencies {brute:.1f} s (one run), "
              f"{len(found)} attractors, {len(shot)} periodic of at most "
              f"{MAX_SWITCH_PERIODS} periods")  # fmt: skip
        for mode, options in modes.items():
            t0 = time.perf_counter()
            r = frequency_response(system, forcing, e, band, sweeps=False, **options)
            took = time.perf_counter() - t0
            on = [_traced(r.branches, system, forcing.at(a.omega), e, a.omega, a.amplitude,
                          a.period_multiple) for a in shot]  # fmt: skip
            totals[mode][0] += sum(on)
            totals[mode][1] += len(shot)
            missed = sorted({round(a.omega, 2) for a, t in zip(shot, on, strict=True) if not t})
            share = f"{sum(on) / len(shot):.1%}" if shot else "none to find"
            print(f"  {mode:>22}: {took:.1f} s "
                  f"(one run), {len(r.branches)} branches, {sum(on)} of {len(shot)} on them "
                  f"({share}); missed at Ω (rad/s): {', '.join(f'{w:g}' for w in missed) or '-'}; "
                  f"located peak {r.peak.amplitude * 1e3:.4g} mm ({r.peak.motion})")  # fmt: skip
    for mode, (on, n) in totals.items():
        print(f"all four: {mode} {on} of {n} ({on / n:.1%}; target >= 99 %)")


if __name__ == "__main__":
    main()
