"""The package's stepper against what a user would write instead, each tuned to the same accuracy.

Peers: a hand-written numba DOP853 with events (:mod:`benchmarks.handwritten_dop853`), and
``solve_ivp`` (DOP853 and LSODA, through :func:`symimpact.free.reference.reference_impacts`).  For each
system, the reference is the package's stepper at rtol 1e-14 (checked against solve_ivp DOP853
at rtol 1e-13, printed).  Each method is tuned: of its settings (rtol; for the peers also the
step cap in free flight, which they need so as not to step over a grazing impact), the cheapest
whose impact list has every impact of the reference, each within 1e-9 s, is kept.  Its CPU time
is the median of 5 runs (the spread printed).  Prints figures and ratios; asserts nothing.
Run from the checkout: python -m benchmarks.stepper_peers
"""

from __future__ import annotations

import statistics
import time

import numpy as np

from symimpact.free.reference import reference_impacts
from symimpact.free.simulation import simulate
from symimpact.model.system import table2_system

from . import handwritten_dop853

ACCURACY = 1e-9  # [s] impact-time accuracy every method is tuned to
RTOLS = (1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12)
CAPS = (10, 25, 50, 100, 200, 400)  # free-flight steps per natural period (the peers)
REPEATS = 5


def _grazing_speed(system, t_end):
    """ẋ0 at which the first approach just reaches the wall (bisection on the impact count),
    times (1 + 1e-6): an impact 1e-6 of the speed past grazing."""
    lo, hi = 0.0, 1.0
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if simulate(system, 0, mid, 0, 0, t_end, rtol=1e-14).n_impacts:
            hi = mid
        else:
            lo = mid
    return hi * (1 + 1e-6)


def systems():
    """(label, system, initial state, t_end): the four systems of the issue's table and one with
    a grazing first impact."""
    t2 = table2_system("9 mm", C=0.5, c1="5 N s/m")
    soft = table2_system("9 mm", C=0.5, c1="1 N s/m")
    light = table2_system("9 mm", C=0.02, c1="1 N s/m")
    period = 2 * np.pi / t2.omega_n
    graze = _grazing_speed(t2, 0.5 * period)
    return [
        ("Table 2, d = 9 mm, 0.1 s", t2, (0.0, 0.5, 0.0, 0.0), 0.1),
        ("Table 2, d = 9 mm, 2 s", t2, (0.0, 0.5, 0.0, 0.0), 2.0),
        ("c1 = 1 N s/m, 20 s", soft, (0.0, 0.5, 0.0, 0.0), 20.0),
        ("C = 0.02 N s/m, c1 = 1 N s/m, 20 s", light, (0.0, 0.5, 0.0, 0.0), 20.0),
        ("grazing first impact, 2 s", t2, (0.0, graze, 0.0, 0.0), 2.0),
    ]


def _cpu(fn):
    t0 = time.process_time()
    out = fn()
    return time.process_time() - t0, out


def _median(fn):
    times = [_cpu(fn)[0] for _ in range(REPEATS)]
    return statistics.median(times), min(times), max(times)


def _error(times, ref):
    """Largest impact-time error [s], or None when the impact lists differ in length."""
    times = np.asarray(times, float)
    return float(np.max(np.abs(times - ref), initial=0.0)) if times.size == ref.size else None


def _tune(run, settings, ref):
    """The cheapest setting whose impacts all match the reference within ACCURACY:
    (setting, error, CPU s of one run); None if none does.  ``settings`` lists groups (a step cap
    each) of rtols from loose to tight: in each group the loosest that matches is a candidate."""
    best = None
    for group in settings:
        for setting in group:
            cost, times = _cpu(lambda s=setting: run(s))
            err = _error(times, ref)
            if err is not None and err <= ACCURACY:
                if best is None or cost < best[2]:
                    best = (setting, err, cost)
                break
    return best


def main() -> dict:
    results = {}
    print(
        f"impact times within {ACCURACY:g} s of the reference, every impact found; CPU time, "
        f"median of {REPEATS} runs (min-max)"
    )
    for label, s, state, t_end in systems():
        ref = np.array([i.t for i in simulate(s, *state, t_end, rtol=1e-14).impacts])
        check = reference_impacts(s, *state, t_end, rtol=1e-13, atol=1e-16)
        agree = _error([r["t"] for r in check], ref)
        print(
            f"\n{label}: {ref.size} impacts; reference (stepper, rtol 1e-14) and solve_ivp "
            f"DOP853 (rtol 1e-13) agree to {agree:.1e} s"
            if agree is not None
            else f"\n{label}: {ref.size} impacts; solve_ivp DOP853 found {len(check)}"
        )

        def ours(rtol, s=s, state=state, t_end=t_end):
            return [i.t for i in simulate(s, *state, t_end, rtol=rtol).impacts]

        def hand(setting, s=s, state=state, t_end=t_end):
            cap, rtol = setting
            return handwritten_dop853.impact_times(s, state, t_end, rtol, cap_per_period=cap)

        def ivp(setting, method, s=s, state=state, t_end=t_end):
            cap, rtol = setting
            scale = max(0.5 * s.gap, 1e-3)
            return [
                r["t"]
                for r in reference_impacts(
                    s,
                    *state,
                    t_end,
                    method=method,
                    rtol=rtol,
                    atol=rtol * 1e-3 * scale,
                    steps_per_period=cap,
                )
            ]

        hand((CAPS[-1], 1e-12))  # compile / load the cache of the hand-written stepper
        rows = {}
        methods = {
            "symimpact": (ours, [RTOLS]),
            "hand-written numba DOP853": (hand, [[(c, r) for r in RTOLS] for c in CAPS]),
            "solve_ivp DOP853": (
                lambda st: ivp(st, "DOP853"),
                [[(c, r) for r in RTOLS[::2]] for c in CAPS[::2]],
            ),
            "solve_ivp LSODA": (
                lambda st: ivp(st, "LSODA"),
                [[(c, r) for r in RTOLS[::2]] for c in CAPS[::2]],
            ),
        }
        for name, (run, settings) in methods.items():
            tuned = _tune(run, settings, ref)
            if tuned is None:
                print(f"  {name:27} no setting found every impact within {ACCURACY:g} s")
                rows[name] = None
                continue
            setting, err, _ = tuned
            med, lo, hi = _median(lambda r=run, st=setting: r(st))
            rows[name] = {"ms": med * 1e3, "min": lo * 1e3, "max": hi * 1e3, "setting": setting}
            print(
                f"  {name:27} {med * 1e3:10.3f} ms  ({lo * 1e3:.3f}-{hi * 1e3:.3f})  setting "
                f"{setting}, worst impact-time error {err:.1e} s"
            )
        ours_ms = rows["symimpact"]["ms"] if rows["symimpact"] else float("nan")
        for name, row in rows.items():
            if name != "symimpact" and row:
                print(f"  ratio {name} / symimpact: {row['ms'] / ours_ms:8.1f}x")
        results[label] = {"impacts": int(ref.size), **rows}
    print(
        "\ntargets: >= 2x the hand-written numba and >= 300x the tuned solve_ivp on every "
        "system, no impact missed"
    )
    return results


if __name__ == "__main__":
    main()
