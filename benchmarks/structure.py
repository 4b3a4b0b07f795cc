"""A structure of several modes carrying rigid impact dampers (issue 36): the compiled modal engine
(:func:`symimpact.forced.structure_response.simulate_structure`) by the number of modes, a
10-mode cantilever with two dampers, and against SciPy's DOP853 with event location on the same
model at the same impact-time accuracy.

1. Cost per event against N: the steel cantilever of the tests (1 m of 40 mm × 10 mm, ζ 0.02)
   reduced to its first N Ritz modes (N = 1 … 8, the beams' kernels), dampers of 50 g (10 mm) at
   the tip and of 30 g (3 mm) at mid-span, e 0.6, 2 N at 8 Hz at the tip, 20 periods.  Each
   mode's flight costs the same; the energy ledger is closed form per flight, and the search
   steps as its bound allows, which the high modes an impact excites (ωₙ ∝ n² on a beam) make
   finer near the walls.  The exponent printed is the slope of log(cost per event) against
   log N.
2. The issue's case: a 10-mode cantilever (a Hermite finite-element model of 20 elements, written
   here, reduced by :func:`symimpact.model.structure.fe_structure`) with the same two dampers:
   the issue's 400-period run itself, timed (target ≤ 1 s; its tenth mode is near 2 kHz; both
   dampers chatter and stick, about 300 events a period, and the first periods have fewer, so
   no shorter run stands for it).  Its motion is sensitive to its start: forces one unit in the
   last place apart give runs with very different numbers of events, so one run times one
   trajectory.  The run is timed at ULP_RUNS forces 1 ulp apart from 2 N, and the median and
   range of the times, of the events and of the cost per event are printed, with its energy
   ledger (the default) and without it (``energy=False``: the same motion to the bit; the
   riding mass's flights are coupled, and their ledger by Gauss–Legendre rules at the tenth
   mode's rate is most of the cost).
3. The baseline: DOP853 (rtol 1e-13, events at every wall) on the two-mode system of the tests'
   comparison (ζ 0.05, one 50 g damper of 10 mm, e 0.5, 2 N at 8 Hz, 60 periods): both computed
   in this run, the impact times' largest relative difference printed beside the ratio (target
   ≥ 100).
4. The issue's curve: the 10-mode cantilever of item 2 over 0.85–1.15 of its first natural
   frequency at 200 frequencies (:func:`symimpact.maps.structure_curve.structure_curve_map`: a
   run from rest at each, without its energy ledger, as long as the slowest mode's transient
   takes to fall to 1e-6 and 40 periods more, on as many processes as the machine has cores, then branches continued from
   the band's ends; target ≤ 60 s on two cores), timed once (it takes minutes), beside one of
   its runs from rest at the first mode.
5. Through sticking: the plastic damper (e 0, 50 g in 10 mm) at the tip of the two-mode
   cantilever of the tests (ζ 0.02, 2 N at the tip), whose mass chatters, sticks and is released
   twice a period: its branch from 7.5 to 7.75 Hz (:func:`symimpact.forced.orbits.structure_branch.
   structure_branch`, step 0.1 rad/s) with the monodromy carried through the accumulations, the
   sticking phases and the releases, against the same branch with the map's central differences
   in their place (2(2N + 2K) = 12 more runs a Newton step: what the shooting did before the
   chain was carried through sticking), both in this run; the largest relative difference of
   their orbits' amplitudes is printed beside the ratio.

Medians of five with their spread (item 4: one run); asserts nothing.  Run from the checkout:
python -m benchmarks.structure
"""

from __future__ import annotations

import math
import os
import time

import numpy as np
from scipy.integrate import solve_ivp

from symimpact.forced.orbits.structure_branch import (
    KEPT,
    curve_peak,
    settling_periods,
    structure_branch,
)
from symimpact.forced.structure_response import simulate_structure
from symimpact.maps.structure_curve import structure_curve_map
from symimpact.model.dampers import dampers
from symimpact.model.structure import beam_structure, fe_structure

from .timing import timed

BEAM = {"support": "cantilever", "E": 210e9, "I": 0.04 * 0.01**3 / 12, "rho": 7850.0,
        "A": 4e-4, "L": 1.0}  # fmt: skip
TWO = [{"name": "tip", "at": "tip", "m": 0.05, "gap": "10 mm", "e": 0.6},
       {"name": "mid", "at": "mid", "m": 0.03, "gap": "3 mm", "e": 0.6}]  # fmt: skip
OMEGA = 2 * math.pi * 8.0
#: Item 2's forces, 2 N and the next ULP_RUNS − 1 doubles above it.
ULP_RUNS = 8


def _hermite_cantilever(n_el: int = 20):
    """(M, K) of the cantilever in Hermite cubic elements (consistent mass), clamped at x = 0,
    DOFs (w, θ) per free node: the tip's deflection is DOF 2·n_el − 2, mid-span's n_el − 2."""
    E, I, rho, A, L = (BEAM[k] for k in ("E", "I", "rho", "A", "L"))
    h = L / n_el
    k = E * I / h**3 * np.array([[12, 6 * h, -12, 6 * h], [6 * h, 4 * h * h, -6 * h, 2 * h * h],
                                 [-12, -6 * h, 12, -6 * h], [6 * h, 2 * h * h, -6 * h, 4 * h * h]])  # fmt: skip
    m = rho * A * h / 420 * np.array([[156, 22 * h, 54, -13 * h], [22 * h, 4 * h * h, 13 * h, -3 * h * h],
                                      [54, 13 * h, 156, -22 * h], [-13 * h, -3 * h * h, -22 * h, 4 * h * h]])  # fmt: skip
    n = 2 * (n_el + 1)
    K, M = np.zeros((n, n)), np.zeros((n, n))
    for e in range(n_el):
        s = slice(2 * e, 2 * e + 4)
        K[s, s] += k
        M[s, s] += m
    return M[2:, 2:], K[2:, 2:]


def _dop853_impacts(s, ds, F0, omega, t_end):
    """Impact times by DOP853 with event location on the modal equations (the tests' reference,
    restated: rtol 1e-13, the impact as an impulse reversing the relative velocity by e)."""
    modes = s.modes
    N, K = len(modes), len(ds)
    M = np.array([m.mass for m in modes])
    w = np.array([m.omega for m in modes])
    z = np.array([m.zeta for m in modes])
    F = F0 * np.array([m.shape["tip"] for m in modes])
    Phi = s.shapes([d.at for d in ds])
    h = np.array([d.gap / 2 for d in ds])

    def rhs(t, y):
        a = F * math.cos(omega * t) / M - 2 * z * w * y[N : 2 * N] - w * w * y[:N]
        return np.concatenate([y[N : 2 * N], a, y[2 * N + K :], np.zeros(K)])

    events = []
    for k in range(K):
        for side in (1.0, -1.0):

            def ev(t, y, k=k, side=side):
                return side * (y[2 * N + k] - Phi[k] @ y[:N]) - h[k]

            ev.terminal, ev.direction = True, 1.0
            events.append((k, ev))
    y, t, times = np.zeros(2 * N + 2 * K), 0.0, []
    while t < t_end:
        sol = solve_ivp(rhs, (t, t_end), y, method="DOP853", rtol=1e-13, atol=1e-16,
                        events=[e[1] for e in events])  # fmt: skip
        hit = [(te[0], i) for i, te in enumerate(sol.t_events) if len(te)]
        if not hit:
            break
        t, i = min(hit)
        k = events[i][0]
        y = sol.y_events[i][0].copy()
        P = (
            (1 + ds[k].e)
            * (y[2 * N + K + k] - Phi[k] @ y[N : 2 * N])
            / (1 / ds[k].m + np.sum(Phi[k] ** 2 / M))
        )
        y[N : 2 * N] += Phi[k] * P / M
        y[2 * N + K + k] -= P / ds[k].m
        times.append(t)
    return np.array(times)


def main() -> None:
    print("1. cost per event against the number of modes (cantilever, dampers at tip and "
          "mid-span, 2 N at 8 Hz, 20 periods)")  # fmt: skip
    costs = []
    for n in (1, 2, 3, 4, 6, 8):
        s = beam_structure(**BEAM, points={"tip": 1.0, "mid": 0.5}, modes=n, zeta=0.02)
        ds = dampers(s, TWO)
        simulate_structure(s, ds, "tip", 2.0, OMEGA, periods=2)  # compiled before timing
        run = timed(lambda s=s, ds=ds: simulate_structure(s, ds, "tip", 2.0, OMEGA, periods=20))
        events = len(run.out.events)
        per = run.median / max(events, 1)
        costs.append((n, per))
        print(f"  N = {n}: {run.s()}, {events} events, {per * 1e6:.1f} µs an event "
              f"(× {per / costs[0][1]:.1f} of N = 1)")  # fmt: skip
    ns, cs = np.log([c[0] for c in costs]), np.log([c[1] for c in costs])
    print(f"  growth: cost per event ∝ N^{np.polyfit(ns, cs, 1)[0]:.2f} over N = 1 … 8")
    M, K = _hermite_cantilever()
    s = fe_structure(M, K, {"tip": M.shape[0] - 2, "mid": M.shape[0] // 2 - 1}, modes=10,
                     zeta=0.02)  # fmt: skip
    ds = dampers(s, TWO)
    ten, ten_dampers = s, ds  # item 4's structure
    simulate_structure(s, ds, "tip", 2.0, OMEGA, periods=2)
    print(f"2. a 10-mode cantilever (20 Hermite elements, modes up to "
          f"{s.modes[-1].frequency:.0f} Hz), 2 rigid dampers, the 400-period run, {ULP_RUNS} "
          "forces 1 ulp apart from 2 N (target <= 1 s):")  # fmt: skip
    for energy in (True, False):
        times, events = [], []
        F = 2.0
        for _ in range(ULP_RUNS):
            t = time.perf_counter()
            out = simulate_structure(s, ds, "tip", F, OMEGA, periods=400, energy=energy)
            times.append(time.perf_counter() - t)
            events.append(len(out.events))
            F = float(np.nextafter(F, 3.0))
        times, events = np.array(times), np.array(events)
        per = times / events * 1e6
        print(f"  {'with its energy ledger (the default)' if energy else 'without it (energy=False)'}"
              f": median {np.median(times):.3f} s ({times.min():.3f}–{times.max():.3f}), events "
              f"median {np.median(events):.0f} ({events.min()}–{events.max()}, "
              f"{np.median(events) / 400:.0f} a period), {np.median(per):.1f} µs an event "
              f"({per.min():.1f}–{per.max():.1f})")  # fmt: skip
    s = beam_structure(**BEAM, points={"tip": 1.0, "mid": 0.5}, modes=2, zeta=0.05)
    ds = dampers(s, [{"name": "tip", "at": "tip", "m": 0.05, "gap": "10 mm", "e": 0.5}])
    engine = timed(lambda: simulate_structure(s, ds, "tip", 2.0, OMEGA, periods=60))
    ref = timed(lambda: _dop853_impacts(s, ds, 2.0, OMEGA, engine.out.t_end))
    got = engine.out.impacts("tip")
    diff = np.max(np.abs(got - ref.out) / ref.out) if len(got) == len(ref.out) else math.nan
    print(f"3. two modes, one damper, 60 periods ({len(got)} impacts): engine {engine.s()}; "
          f"DOP853 with events (rtol 1e-13) {ref.s()}; impact times agree to {diff:.1e}")  # fmt: skip
    print(f"  ratio DOP853 / engine: {ref.median / engine.median:.0f}  (target >= 100)")
    _ten_mode_curve(ten, ten_dampers)
    _through_sticking()


def _ten_mode_curve(s, ds, points: int = 200) -> None:
    """Item 4 (module text): the 200-frequency curve of item 2's structure ``s`` with its dampers
    ``ds``, timed once."""
    f1 = s.modes[0].frequency
    lo, hi = 2 * math.pi * 0.85 * f1, 2 * math.pi * 1.15 * f1
    n = settling_periods(s, 2 * math.pi * f1) + KEPT  # what the curve runs there
    t = time.perf_counter()
    one = simulate_structure(s, ds, "tip", 2.0, 2 * math.pi * f1, periods=n, energy=False)
    t_one = time.perf_counter() - t
    t = time.perf_counter()
    c = structure_curve_map(s, ds, "tip", 2.0, lo, hi, (hi - lo) / (points - 1))
    secs = time.perf_counter() - t
    peak = curve_peak(s, ds, "tip", 2.0, c, "tip")
    orbits = sum(len(b.orbits) for b in c.branches)
    print(f"4. its curve, {points} frequencies {lo / 2 / math.pi:.3f}-{hi / 2 / math.pi:.3f} Hz, "
          f"one run on {os.cpu_count()} processes: {secs:.1f} s (target <= 60 s on 2); "
          f"{len(c.branches)} branches, {orbits} orbits, "
          f"{len(c.notes)} notes; peak {peak.amplitude * 1e3:.4f} mm at "
          f"{peak.omega / 2 / math.pi:.4f} Hz ({peak.kind})")  # fmt: skip
    print(f"  one of its runs from rest, at the first mode ({f1:.3f} Hz, {n} periods): {t_one:.2f} s, "
          f"{len(one.events)} events ({t_one / len(one.events) * 1e6:.0f} µs an event)")  # fmt: skip


def _through_sticking() -> None:
    """Item 5 (module text): the plastic damper's branch, carried against differenced."""
    from unittest import mock

    from symimpact.forced.orbits import structure_orbits

    s = beam_structure(**BEAM, points={"p": 1.0}, modes=2, zeta=0.02)
    ds = dampers(s, [{"name": "p", "at": "p", "m": 0.05, "gap": "10 mm", "e": 0.0}])
    w0, w1 = 2 * math.pi * 7.5, 2 * math.pi * 7.75
    start = simulate_structure(s, ds, "p", 2.0, w0, periods=300).final_state[1:7]
    strobe = structure_orbits.stroboscopic_map

    def differenced(*args, **kwargs):  # the map, its carried chain replaced by NaN
        image, G, res = strobe(*args, **kwargs)
        return image, np.full_like(G, np.nan), res

    def branch():
        return structure_branch(s, ds, "p", 2.0, w0, w1, start, step=0.1)

    carried = timed(branch)
    with mock.patch.object(structure_orbits, "stroboscopic_map", differenced):
        diff = timed(branch)
    a = np.array([o.amplitudes["p"] for o in carried.out.orbits])
    b = np.array([o.amplitudes["p"] for o in diff.out.orbits])
    gap = np.max(np.abs(a - b) / np.abs(b)) if len(a) == len(b) else math.nan
    print(f"5. through sticking: the plastic damper's branch 7.5-7.75 Hz on two modes "
          f"({len(a)} orbits, {carried.out.orbits[0].jacobian}): carried {carried.s()}; "
          f"differenced ({len(b)} orbits, {diff.out.orbits[0].jacobian}) {diff.s()}; ratio "
          f"{diff.median / carried.median:.1f}; amplitudes agree to {gap:.1e}")  # fmt: skip


if __name__ == "__main__":
    main()
