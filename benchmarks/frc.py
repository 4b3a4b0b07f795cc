"""A 200-frequency frequency-response curve with stability (``symimpact.forced.orbits.frf``: shooting,
pseudo-arclength continuation, Floquet multipliers and located bifurcations on every branch)
against the brute-force way of getting a response curve: a frequency sweep of the event-driven
simulation over the same 200 frequencies, each run started from the previous end state and run
until its transient has fallen to 1e-6 (exp(−ζω_n·t), as ``symimpact frf`` does for its overlay).

The curve here has no multi-start (``multistart=0``).  The baseline is run twice: settled to 1e-11, the accuracy of the continuation's points (Newton
stops at 1e-11 of the state's scale), which makes the ratio; and settled to 1e-6, what the frf
overlay uses.  A sweep finds only the stable motion it happens to follow (one per frequency, no
stability, no unstable orbit, no bifurcation); the curve finds every branch its starts reach.
Issue 21's target is the curve in ≤ 10 s on the 2-core machine.

Then the curve as ``symimpact frf`` computes it by default — branch switching, the multi-start
at 15 frequencies and the coverage it measures (issue 33's target: ≤ 15 s) — against the
multi-start brute force of the same band: the same four starts at every one of the 200
frequencies, each run settled to 1e-6 and its periodic motion shot (what it takes to list the
attractors frequency by frequency without continuation; target ratio ≥ 10).  The brute force
also measures the curve: the share of its periodic attractors that lie on a traced branch
(issue 33's target ≥ 99 %), those missed, and its highest stable motion beside the located peak.
The 200-frequency brute force finds the peak to 1 % only; matched to the curve's accuracy on the
peak (1e-6, issue 33's tolerance) it needs a frequency inside the peak's window on the branch,
whose width gives the frequencies it takes (checked by a run at that spacing around the peak)
and, at its measured cost a frequency, its time over the band (projected, not run);
then the same for the curve with folds (``frf --folds``: branches turned back at the grazings
where they end) and for the curve with the orbits embedded in the multi-start's chaotic motions
(``frf --embedded``) and for the curve with both, each with its cost against the default
curve's.

The same comparison follows with the contact compliant: the linear law (k1 1e6 N/m, c1 from
Step 9 for the same e), every contact integrated, the curve's shooting carrying the contact's
variational equations; its baseline is the compliant sweep settled to 1e-11.  Prints medians of
five with their spread and the ratios; asserts nothing.  Run from the checkout:
python -m benchmarks.frc
"""

from __future__ import annotations

import math

import numpy as np
from symimpact.generated import rigid_impact as ri

from symimpact.forced.contact_law import CompliantContact
from symimpact.forced.forcing import Forcing
from symimpact.forced.orbits.continuation import orbits_at
from symimpact.forced.orbits.coverage import attractors
from symimpact.forced.orbits.frf import MAX_SWITCH_PERIODS, _sweep, _traced, frequency_response
from symimpact.model.system import ImpactSystem

from .timing import timed

#: Issue 21's rigid system: M 1 kg, K 1000 N/m, C 0.5 N s/m, m 0.05 kg, d 20 mm, F0 2 N, e 0.6.
SYSTEM = ImpactSystem(M=1.0, K=1000.0, C=0.5, m=0.05, gap=0.02, contact="linear", k1=1e6)
FORCING = Forcing(F0=2.0, omega=30.0)
E = 0.6
BAND = np.linspace(25.0, 45.0, 200)  # rad/s; ω_n = 31.6 rad/s inside
#: The same system with the linear contact law, k1 1e6 N/m and c1 from Step 9 for e.
K1 = 1e6
COMPLIANT = SYSTEM.with_(k1=K1, c1=float(ri.linear_c1_for_restitution(SYSTEM.m, SYSTEM.M, K1, E)))


def _coverage_line(curve, shot) -> str:
    """The brute force's periodic attractors ``shot`` that lie on ``curve``'s branches, and the
    frequencies of those missed."""
    on = [_traced(curve.branches, SYSTEM, FORCING.at(a.omega), E, a.omega, a.amplitude,
                  a.period_multiple) for a in shot]  # fmt: skip
    missed = sorted({round(a.omega, 2) for a, t in zip(shot, on, strict=True) if not t})
    return (f"  the brute force's periodic attractors on its branches: {sum(on)} of {len(shot)} "
            f"({sum(on) / len(shot):.1%}); missed at Ω (rad/s): "
            f"{', '.join(f'{w:g}' for w in missed)}")  # fmt: skip


#: The accuracy of the located peak the brute force is matched to: issue 33's tolerance for an
#: attractor on a branch (amplitude within 1e-6 relative).
PEAK_ACCURACY = 1e-6


def _peak_window(curve, tau: float) -> tuple[float, float]:
    """The Ω interval around the curve's located peak where its branch's stable amplitude is
    within ``tau`` of the peak (each end by bisection on the branch's exact orbits,
    :func:`orbits_at`): a grid finds the peak to ``tau`` only with a frequency inside it."""
    pk = curve.peak
    b = curve.branches[pk.branch]
    target = (1.0 - tau) * pk.amplitude

    def held(w: float) -> bool:
        stable = [o.amplitude for o in orbits_at(b, SYSTEM, FORCING.at(w, b.phase), E, w)
                  if o.stable]  # fmt: skip
        return bool(stable) and min(stable, key=lambda a: abs(a - pk.amplitude)) >= target

    ends = []
    for sign in (-1.0, 1.0):
        inner, d = pk.omega, 1e-6
        while held(pk.omega + sign * d):
            inner, d = pk.omega + sign * d, 2.0 * d
        outer = pk.omega + sign * d
        for _ in range(50):
            m = 0.5 * (inner + outer)
            inner, outer = (m, outer) if held(m) else (inner, m)
        ends.append(inner)
    return ends[0], ends[1]


def _equal_accuracy(curve, per_frequency: float, curve_time: float) -> None:
    """The multi-start brute force matched to the curve's accuracy on the peak (PEAK_ACCURACY):
    the grid spacing it needs (the peak's window, :func:`_peak_window`), checked by a run of
    the brute force at that spacing around the peak, and its cost over the whole band at the
    200-frequency brute force's measured cost a frequency (projected, not run: ~18 minutes)."""
    lo, hi = _peak_window(curve, PEAK_ACCURACY)
    w = hi - lo
    n = math.ceil((BAND[-1] - BAND[0]) / w)
    pk = curve.peak
    local = attractors(SYSTEM, FORCING, E, (pk.omega - 3 * w, pk.omega + 3 * w), 5)
    top = max(a.amplitude for a in local if a.kind == "periodic" and a.stable)
    print(f"  the brute force matched to the located peak (to {PEAK_ACCURACY:g}): the peak's "
          f"window is {w:.3g} rad/s wide, so {n} frequencies; at that spacing around the peak "
          f"its highest stable motion is within {abs(top - pk.amplitude) / pk.amplitude:.1e} of "
          f"the located peak; at {per_frequency * 1e3:.1f} ms a frequency (measured above) the "
          f"band takes {n * per_frequency:.0f} s (projected): {n * per_frequency / curve_time:.0f} "
          "times the default curve, which also gives stability, unstable orbits and "
          "bifurcations")  # fmt: skip


def main() -> None:
    # numba compiles on the first call: one small curve before timing
    frequency_response(SYSTEM, FORCING, E, np.linspace(34.0, 36.0, 3), starts=1, sweeps=False,
                       multistart=1)  # fmt: skip
    frc = timed(lambda: frequency_response(SYSTEM, FORCING, E, BAND, sweeps=False, multistart=0))
    r = frc.out
    points = sum(len(b.points) for b in r.branches)
    kinds: dict[str, int] = {}
    for b in r.branches:
        for bif in b.bifurcations:
            kinds[bif.kind] = kinds.get(bif.kind, 0) + 1
    fair = timed(lambda: _sweep(SYSTEM, FORCING, E, BAND, settled=1e-11))
    loose = timed(lambda: _sweep(SYSTEM, FORCING, E, BAND, settled=1e-6))
    print(f"band: {len(BAND)} frequencies, {BAND[0]:g}–{BAND[-1]:g} rad/s; system of issue 21, "
          f"e {E}")  # fmt: skip
    print(f"frequency-response curve with stability: {frc.s()}  (target <= 10 s)")
    print(f"  {len(r.branches)} branches, {points} continuation points, located: "
          + ", ".join(f"{n} {k}" for k, n in sorted(kinds.items())))  # fmt: skip
    print(f"brute-force sweep up, transient 1e-11 (baseline): {fair.s()}")
    print(f"brute-force sweep up, transient 1e-6:             {loose.s()}")
    print("  a sweep: one amplitude per frequency, the stable motion it follows, no stability")
    print(f"ratio sweep (1e-11) / curve: {fair.median / frc.median:.2f}; "
          f"sweep (1e-6) / curve: {loose.median / frc.median:.2f}")  # fmt: skip
    full = timed(lambda: frequency_response(SYSTEM, FORCING, E, BAND, sweeps=False))
    r = full.out
    cov = r.coverage
    brute = timed(lambda: attractors(SYSTEM, FORCING, E, (BAND[0], BAND[-1]), len(BAND)))
    found = brute.out
    periodic = [a for a in found if a.kind == "periodic"]
    print(f"the curve with switching and coverage (symimpact frf's default): {full.s()}  "
          "(target <= 15 s)")  # fmt: skip
    print(f"  {len(r.branches)} branches; multi-start at 15 frequencies, refined: {len(cov.attractors)} "
          f"attractors, {sum(cov.traced)} of {len(cov.traced)} periodic ones on a traced branch; "
          f"peak {r.peak.amplitude * 1e3:.4g} mm ({r.peak.motion})")  # fmt: skip
    print(f"multi-start brute force at all {len(BAND)} frequencies (baseline): {brute.s()}  "
          f"({len(found)} attractors, {len(periodic)} periodic)")  # fmt: skip
    print(f"ratio multi-start brute force / curve: {brute.median / full.median:.2f}  "
          "(target >= 10)")  # fmt: skip
    # the curve's coverage measured against the dense brute force rather than its own 15
    # frequencies: its periodic attractors (of the periods the curve traces) on a traced branch
    shot = [a for a in periodic if a.period_multiple <= MAX_SWITCH_PERIODS]
    on = [_traced(r.branches, SYSTEM, FORCING.at(a.omega), E, a.omega, a.amplitude,
                  a.period_multiple) for a in shot]  # fmt: skip
    top = max((a for a in shot if a.stable), key=lambda a: a.amplitude)
    print(f"  the brute force's periodic attractors on the curve's branches: {sum(on)} of "
          f"{len(shot)} ({sum(on) / len(shot):.1%}; target >= 99 %); its highest stable one "
          f"{top.amplitude * 1e3:.4g} mm at {top.omega:.4g} rad/s, the located peak "
          f"{r.peak.amplitude * 1e3:.4g} mm at {r.peak.omega:.4g} rad/s")  # fmt: skip
    missed = sorted({round(a.omega, 2) for a, t in zip(shot, on, strict=True) if not t})
    print(f"  missed at Ω (rad/s): {', '.join(f'{w:g}' for w in missed)}")
    _equal_accuracy(r, brute.median / len(BAND), full.median)
    folded = timed(lambda: frequency_response(SYSTEM, FORCING, E, BAND, sweeps=False, folds=True))
    rf = folded.out
    turned = sum(b.origin.startswith("turned back") for b in rf.branches)
    print(f"the curve with folds (symimpact frf --folds): {folded.s()}  ({len(rf.branches)} "
          f"branches, {turned} of them turned back at a grazing); ratio to the default curve "
          f"{folded.median / full.median:.2f}")  # fmt: skip
    print(_coverage_line(rf, shot))
    embedded = timed(lambda: frequency_response(SYSTEM, FORCING, E, BAND, sweeps=False,
                                                embedded=True))  # fmt: skip
    curve = embedded.out
    found_in = sum(" motion at Ω = " in b.origin for b in curve.branches)
    print(f"the curve with embedded orbits (symimpact frf --embedded): {embedded.s()}  "
          f"({len(curve.branches)} branches, {found_in} of them from orbits embedded in a chaotic "
          f"motion); ratio to the default curve {embedded.median / full.median:.2f}")  # fmt: skip
    print(_coverage_line(curve, shot))
    both = timed(lambda: frequency_response(SYSTEM, FORCING, E, BAND, sweeps=False, folds=True,
                                            embedded=True))  # fmt: skip
    print(f"the curve with both (symimpact frf --folds --embedded): {both.s()}  "
          f"({len(both.out.branches)} branches); ratio to the default curve "
          f"{both.median / full.median:.2f}")  # fmt: skip
    print(_coverage_line(both.out, shot))
    law = CompliantContact("linear")
    soft = timed(lambda: frequency_response(COMPLIANT, FORCING, law, BAND, sweeps=False,
                                            multistart=0))  # fmt: skip
    r = soft.out
    points = sum(len(b.points) for b in r.branches)
    base = timed(lambda: _sweep(COMPLIANT, FORCING, law, BAND, settled=1e-11))
    print(f"linear contact (k1 {K1:.0e} N/m, c1 {COMPLIANT.c1:.4g} N s/m for e {E}), every "
          "contact integrated:")  # fmt: skip
    print(f"frequency-response curve with stability: {soft.s()}  ({len(r.branches)} branches, "
          f"{points} continuation points)")  # fmt: skip
    print(f"brute-force sweep up, transient 1e-11 (baseline): {base.s()}")
    print(f"ratio sweep (1e-11) / curve: {base.median / soft.median:.2f}")


if __name__ == "__main__":
    main()
