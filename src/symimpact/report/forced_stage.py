"""Report stage "forced": beyond the paper, the forced response of the report's system.

The primary of the reading of Table 2 that the vibration stage chose (M, K, C) carries the impact
mass m of Table 2 and is driven by F0·cos(Ωt) over a band around its natural frequency ω_n.  The
paper's contact (the cubic fit with damping c1) is idealised as a rigid impact whose restitution
is that of the paper's linear fit k1 with the same c1 (Eq. 35's contact, Step 9):
e = ``closed_forms.linear_restitution(m, M, k1, c1)``; the stage states how long that contact
lasts against the forcing period, which is what the idealisation neglects.

- The frequency-response curve with and without the damper at three of Table 3's gaps (the six
  curves, rigid and compliant, on worker processes, one per core)
  (:func:`symimpact.forced.frequency_response`: branches continued with their stability, located
  bifurcations, brute-force sweeps up and down as a cross-check), and the located points;
- the same curves with that linear contact itself, integrated through each contact (a
  :class:`symimpact.forced.CompliantContact`), and their peaks beside the rigid idealisation's;
- the clearance design map (:func:`symimpact.maps.design.design_map`): the worst steady amplitude
  over the band against the clearance for three mass ratios, the best clearance of each.
"""

from __future__ import annotations

import math
import os
from pathlib import Path
from typing import Any

import numpy as np

from ..forced.contact_law import CompliantContact
from ..forced.forcing import Forcing
from ..forced.orbits.frf import frequency_response
from ..generated import closed_forms
from ..maps.design import best_clearances, design_map, design_row
from ..model.system import ImpactSystem
from ..model.units import si
from . import paper
from .document import Figure, Section, Table
from .figures import pyplot, save
from .plots import draw_frf, plot_design

#: Force amplitude [N]: the primary alone then peaks at F0/(C·ω_n).
F0 = 0.2
#: Three of Table 3's gaps [mm] for the response curves.
GAPS_MM = (9.0, 15.0, 25.0)
#: The band, in units of ω_n, and its number of frequencies for the curves and for the design
#: map (quick: fewer).
BAND = (0.5, 1.5)
N_BAND, N_BAND_QUICK = 201, 41
N_DESIGN_BAND, N_DESIGN_BAND_QUICK = 101, 31
#: The design map: clearances [mm] (quick: coarser), up to twice the primary alone's peak, and
#: mass ratios m/M.
DESIGN_GAPS_MM = (2.0, 41.0, 3.0)
DESIGN_GAPS_MM_QUICK = (5.0, 41.0, 9.0)
MASS_RATIOS = (0.1, 0.25, 0.5)
MASS_RATIOS_QUICK = (0.25,)


def _design_gaps(quick: bool) -> np.ndarray:
    """The design map's clearances [m]."""
    lo, hi, step = DESIGN_GAPS_MM_QUICK if quick else DESIGN_GAPS_MM
    return np.arange(lo, hi + step / 2, step) * 1e-3


def steps(quick: bool) -> int:
    """The stage's progress steps: the opening, two curves per gap, one per design of the map."""
    ratios = MASS_RATIOS_QUICK if quick else MASS_RATIOS
    return 1 + 2 * len(GAPS_MM) + len(_design_gaps(quick)) * len(ratios)


STEPS = steps(False)


def _system(earlier: Any) -> ImpactSystem:
    reading = next(s.facts["reading"] for s in earlier if "reading" in s.facts)
    return reading.system(GAPS_MM[0])


def section(folder: Path, quick: bool, tick: Any, earlier: Any = ()) -> Section:
    """Build the stage: write its figures into ``folder`` and return its section (``earlier``:
    the sections built before it; the vibration stage's chosen reading is taken from them)."""
    s = Section("forced", "Beyond the paper: forced response")
    base = _system(earlier)
    k1 = si("k1", paper.FIT["k1"] + " N/m")
    e = float(closed_forms.linear_restitution(base.m, base.M, k1, base.c1))
    duration = float(closed_forms.linear_contact_duration(base.m, base.M, k1, base.c1))
    wn = base.omega_n
    omegas = np.linspace(BAND[0] * wn, BAND[1] * wn, N_BAND_QUICK if quick else N_BAND)
    forcing = Forcing(F0=F0, omega=float(omegas[0]))
    s.blocks.append(
        f"The paper analyses free vibration only. Here its system is driven: the primary of the "
        f"chosen reading (M = {base.M:g} kg, K = {base.K:g} N/m, C = {base.C:g} N s/m, so "
        f"ω_n = {wn:.4g} rad/s and ζ = {base.zeta:.3g}) with the impact mass of Table 2 "
        f"(m = {base.m:g} kg), under F0·cos(Ωt), F0 = {F0:g} N, over Ω = {omegas[0]:.4g}–"
        f"{omegas[-1]:.4g} rad/s ({len(omegas)} frequencies). The contact is idealised as a "
        f"rigid impact with the restitution of the paper's linear contact law (k1 = "
        f"{k1:g} N/m, c1 = {base.c1:g} N s/m; Eq. 35's contact): e = {e:.4f}. That contact "
        f"lasts {duration * 1e3:.4g} ms, {duration / (2 * math.pi / wn) * 100:.3g} % of the "
        "forcing period at resonance, which the rigid law neglects. The curves below are first "
        "the rigid idealisation, then the compliant response with the linear contact itself, "
        "integrated through each contact."
    )
    tick()
    compliant = base.with_(contact="linear", k1=k1)
    jobs = [(gap_mm, law, system.with_(gap=gap_mm * 1e-3))
            for law, system in ((e, base), (CompliantContact("linear"), compliant))
            for gap_mm in GAPS_MM]  # fmt: skip
    curves = _computed_curves(jobs, forcing, omegas, tick)
    rigid_peaks = _curves(s, folder, curves[: len(GAPS_MM)])
    _compliant_curves(s, folder, curves[len(GAPS_MM) :], rigid_peaks)
    band = np.linspace(omegas[0], omegas[-1], N_DESIGN_BAND_QUICK if quick else N_DESIGN_BAND)
    _design(s, folder, base, forcing, e, band, quick, tick)
    return s


def _curve(job: tuple) -> tuple:
    """(frequency response, design row) of one curve: ``job`` = (system, forcing, contact,
    omegas).  Module level, so that worker processes can run it."""
    system, forcing, contact, omegas = job
    frf = frequency_response(system, forcing, contact, omegas)
    return frf, design_row(system, forcing, contact, omegas, curve=frf)


def _computed_curves(jobs: list, forcing: Forcing, omegas: np.ndarray, tick: Any) -> list:
    """(gap [mm], frequency response, design row) of each job (gap [mm], contact, system), in
    order: the curves are independent, so they run on the map engine's worker processes (one per
    core), the stage's bar moving as each ends."""
    from ..maps.executors import _processes

    payloads = [(system, forcing, law, omegas) for _, law, system in jobs]
    workers = min(os.cpu_count() or 1, len(payloads))
    results: list[Any] = [None] * len(jobs)
    if workers == 1:
        done = ((i, _curve(p)) for i, p in enumerate(payloads))
    else:
        done = _processes([(i, p) for i, p in enumerate(payloads)], workers, _numbered_curve)
    for i, (frf, row) in done:
        results[i] = (jobs[i][0], frf, row)
        tick()
    return results


def _numbered_curve(payload: tuple) -> tuple:
    """(index, (frequency response, design row)) of ``payload`` = (index, job)."""
    i, job = payload
    return i, _curve(job)


def _curves(s: Section, folder: Path, curves: list) -> dict[float, float]:
    """The rigid idealisation's curves (``curves``: (gap [mm], frequency response, design row)
    each); returns each gap's peak (gap [mm] → peak [mm])."""
    plt = pyplot()
    fig, axes = plt.subplots(len(GAPS_MM), 1, figsize=(9, 4.2 * len(GAPS_MM)), sharex=True)
    located: list[list[Any]] = []
    peaks: list[list[Any]] = []
    for ax, (gap_mm, frf, row) in zip(axes, curves, strict=True):
        draw_frf(ax, frf)
        ax.set_title(f"d = {gap_mm:g} mm", fontsize=10)
        for i, b in enumerate(frf.branches):
            for f in b.bifurcations:
                located.append([gap_mm, i, f.kind, f.omega, f.amplitude * 1e3])
        swept = max(float(np.max(frf.sweep_up[:, 1])), float(np.max(frf.sweep_down[:, 1])))
        cov = frf.coverage
        peaks.append([gap_mm, len(frf.branches), row["peak_amplitude"] * 1e3, row["peak_omega"],
                      row["peak_motion"], swept * 1e3, row["baseline_peak"] * 1e3,
                      row["peak_ratio"], f"{sum(cov.traced)} of {len(cov.traced)}",
                      len(cov.missed), _checked(cov)])  # fmt: skip
    save(fig, folder, "forced_frc")
    s.blocks.append(
        Figure(
            "forced_frc",
            "Frequency-response curves at three gaps",
            "Largest primary displacement max |x| over a period against Ω: branches of periodic "
            "orbits continued in Ω (stable solid, unstable dashed, one colour per branch), the "
            "located bifurcations by kind, the primary without the damper (grey; thick where "
            "it is also the motion without impacts, the impact mass at rest midway, which ends "
            "where it grazes a wall: dotted lines) and brute-force sweeps up (▲) and down (▼), "
            "each point run from the previous end state until its transient is 1e-6. The "
            "branches are continued through chatter and sticking too (an accumulation of "
            "impacts, then the masses moving together); a run from each stable end of a branch "
            "and each loss of stability, just beyond it, starts a branch where it lands on a "
            "periodic motion no branch holds, as a periodic swept motion does, and so do the "
            "multi-start's initial states run at every branch end; a motion shown "
            "by sweep markers alone is one no branch holds "
            "(the table below counts the multi-start's attractors the branches hold and those "
            "they do not).",
        )
    )
    s.blocks.append(
        Table(
            "forced_peaks",
            "Peak amplitude over the band at three gaps",
            [
                "d [mm]",
                "branches",
                "peak with the damper [mm]",
                "at Ω [rad/s]",
                "motion",
                "largest swept [mm]",
                "without the damper [mm]",
                "ratio",
                "periodic attractors traced",
                "not traced",
                "random check traced",
            ],
            peaks,
            [".3g", None, ".4g", ".4g", None, ".4g", ".4g", ".3f", None, None, None],
            note="The peak is located on the stable branches (their maxima, and the bifurcations "
            "and grazings that end their stable stretches) and on the motion without impacts "
            "(the impact mass at rest midway, where the primary alone stays inside the "
            "clearance), beside the primary alone's located resonance (symimpact.forced.orbits.peak); "
            "a chattering or non-periodic motion found by the multi-start (15 frequencies, 4 "
            "starts each, refined where a start's landings differ) or a swept amplitude names "
            "the peak where it exceeds them "
            "(symimpact.maps.design). The last two columns: how many of the multi-start's "
            "periodic attractors lie on a traced branch, and how many attractors no branch can "
            "hold (not periodic, or periodic where shooting does not converge) or misses "
            "(symimpact.forced.orbits.coverage); the last: the same count at a second, independent set "
            "of 5 frequencies drawn at random in the band (seeded), whose landings start no "
            "branch (the curve's coverage is the lower of the two shares).",
        )
    )
    s.blocks.append(
        Table(
            "forced_bifurcations",
            "Located bifurcations",
            ["d [mm]", "branch", "kind", "Ω [rad/s]", "amplitude [mm]"],
            located,
            [".3g", None, None, ".6g", ".5g"],
            note="Folds from the tangent's Ω component, branch points (a multiplier through +1 "
            "without a turn), period doublings (through −1), Neimark–Sacker points (a complex "
            "pair through the unit circle) and grazings (an impact with zero relative speed, "
            "where the impact count changes), each located on its branch.",
        )
    )
    return {row[0]: row[2] for row in peaks}


def _compliant_curves(s: Section, folder: Path, curves: list,
                      rigid_peaks: dict[float, float]) -> None:  # fmt: skip
    """The curves with the linear contact law integrated through each contact (``curves`` as
    for :func:`_curves`), and each gap's peak beside the rigid idealisation's (``rigid_peaks``:
    gap [mm] → peak [mm])."""
    plt = pyplot()
    fig, axes = plt.subplots(len(GAPS_MM), 1, figsize=(9, 4.2 * len(GAPS_MM)), sharex=True)
    rows = []
    for ax, (gap_mm, frf, row) in zip(axes, curves, strict=True):
        draw_frf(ax, frf)
        ax.set_title(f"d = {gap_mm:g} mm, linear contact", fontsize=10)
        peak = row["peak_amplitude"] * 1e3
        rows.append([gap_mm, len(frf.branches), peak, row["peak_omega"], row["peak_motion"],
                     rigid_peaks[gap_mm], peak / rigid_peaks[gap_mm]])  # fmt: skip
    save(fig, folder, "forced_frc_compliant")
    s.blocks.append(
        Figure(
            "forced_frc_compliant",
            "Frequency-response curves with the linear contact",
            "As above, with the paper's linear contact law (k1, c1) integrated through every "
            "contact instead of a rigid impact: shooting carries the contact's variational "
            "equations and the located onsets and exits, so the branches, their stability and "
            "bifurcations are those of the compliant system.",
        )
    )
    s.blocks.append(
        Table(
            "forced_compliant_peaks",
            "Peak amplitude with the linear contact against the rigid idealisation",
            [
                "d [mm]",
                "branches",
                "peak, linear contact [mm]",
                "at Ω [rad/s]",
                "motion",
                "peak, rigid [mm]",
                "linear / rigid",
            ],
            rows,
            [".3g", None, ".4g", ".4g", None, ".4g", ".3f"],
            note="Both peaks as in the table above (stable branches, the motion without impacts "
            "and both sweeps); a ratio far from 1 is what the rigid idealisation of a contact "
            "this long misses.",
        )
    )


def _design(s: Section, folder: Path, base: ImpactSystem, forcing: Forcing, e: float,
            omegas: np.ndarray, quick: bool, tick: Any) -> None:  # fmt: skip
    gaps = _design_gaps(quick)
    ratios = MASS_RATIOS_QUICK if quick else MASS_RATIOS
    ticked = [0]

    def designs_done(done: int, total: int) -> None:  # the stage's bar moves with each design
        tick(done - ticked[0])
        ticked[0] = done

    table = design_map(base, forcing, e, omegas, {"gap": gaps, "mass_ratio": list(ratios)},
                       progress=designs_done)  # fmt: skip
    plot_design(table, folder / "forced_design_map.png",
                title=f"F0 = {F0:g} N, e = {e:.3f}, Ω {omegas[0]:.3g}–{omegas[-1]:.3g} rad/s")  # fmt: skip
    s.blocks.append(
        Figure(
            "forced_design_map",
            "Clearance design map",
            "The worst steady amplitude of the primary over the band against the clearance, one "
            "line per mass ratio m/M, the best clearance of each marked (★), and the peak of the "
            "primary without the damper (dashed).",
        )
    )
    rows = []
    for _, r in best_clearances(table).iterrows():
        rows.append([r["mass_ratio"], r["gap"] * 1e3, r["peak_amplitude"] * 1e3, r["peak_omega"],
                     r["peak_motion"], r["baseline_peak"] * 1e3, r["peak_ratio"]])  # fmt: skip
    s.blocks.append(
        Table(
            "forced_best_clearance",
            "Best clearance for each mass ratio",
            [
                "m/M",
                "d [mm]",
                "peak [mm]",
                "at Ω [rad/s]",
                "motion",
                "without the damper [mm]",
                "ratio",
            ],
            rows,
            [".3g", ".3g", ".4g", ".4g", None, ".4g", ".3f"],
            note=f"Over {len(gaps)} clearances {gaps[0] * 1e3:g}–{gaps[-1] * 1e3:g} mm, each "
            f"design's band sampled at {len(omegas)} frequencies; the full map is "
            "forced_design_map.csv.",
        )
    )
    full = []
    for _, r in table.iterrows():
        full.append([r["mass_ratio"], r["gap"] * 1e3, r["peak_amplitude"] * 1e3, r["peak_omega"],
                     r["peak_motion"], r["peak_ratio"], r["branches"],
                     r["uncovered_frequencies"]])  # fmt: skip
    s.blocks.append(
        Table(
            "forced_design_map",
            "Design map",
            [
                "m/M",
                "d [mm]",
                "peak [mm]",
                "at Ω [rad/s]",
                "motion",
                "ratio",
                "branches",
                "frequencies only the sweeps cover",
            ],
            full,
            [".3g", ".3g", ".4g", ".4g", None, ".3f", None, None],
            note="Every design of the map, its peak and how it was found.",
            link_only=True,
        )
    )


__all__ = ["section"]


def _checked(cov) -> str:
    """The coverage check's periodic landings on a traced branch, "k of n" ("—": not run)."""
    if cov.check is None:
        return "—"
    return f"{sum(cov.check.traced)} of {len(cov.check.traced)}"
