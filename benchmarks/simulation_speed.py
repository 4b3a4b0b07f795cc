"""Simulation fast path (numba stepper) against the best solve_ivp reference, same system and
accuracy (both at rtol 1e-12; the impact times they find are compared and the largest difference
printed).  Prints figures and the ratio; asserts nothing.
Run from the checkout: python -m benchmarks.simulation_speed
"""

from __future__ import annotations

import time

from symimpact.reference import reference_impacts
from symimpact.simulation import simulate
from symimpact.system import table2_system


def best_of(fn, repeat):
    best = float("inf")
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t0)
    return best


def main() -> None:
    s = table2_system("9 mm", C=0.5, c1="5 N s/m")
    args = (0.0, 0.5, 0.0, 0.0, 2.0)
    simulate(s, *args)  # compile / load the cache
    fast = best_of(lambda: simulate(s, *args, rtol=1e-12), 20)
    fast_res = simulate(s, *args, rtol=1e-12)
    n = fast_res.n_impacts
    print(f"system: Table 2 masses, d = 9 mm, C = 0.5 N s/m, c1 = 5 N s/m, 2 s, {n} impacts")
    print(f"fast path (numba, rtol 1e-12): {fast * 1e3:9.3f} ms")
    results = {}
    for method in ("DOP853", "RK45", "LSODA"):  # Radau: 17 s here, never the best
        try:
            ref = reference_impacts(s, *args, method=method, rtol=1e-12, atol=1e-15)
        except Exception as exc:  # a method may fail at this tolerance; report and go on
            print(f"solve_ivp {method:6}: failed ({exc})")
            continue
        if len(ref) != n:
            print(f"solve_ivp {method:6}: {len(ref)} impacts (not {n}); not comparable")
            continue
        t = best_of(
            lambda m=method: reference_impacts(s, *args, method=m, rtol=1e-12, atol=1e-15), 3
        )
        results[method] = t
        dt = max(abs(r["t"] - i.t) for r, i in zip(ref, fast_res.impacts, strict=True))
        print(
            f"solve_ivp {method:6} (rtol 1e-12): {t * 1e3:9.3f} ms  (impact times agree to "
            f"{dt:.1e} s)"
        )
    best = min(results, key=results.get)
    print(
        f"best reference: {best}; ratio reference/fast = {results[best] / fast:.0f}x (target 100x)"
    )


if __name__ == "__main__":
    main()
