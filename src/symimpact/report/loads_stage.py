"""Report stage "Beyond the paper: random and shock loads": the forced stage's system (the chosen
reading's primary, Table 2's impact mass, d = 9 mm, rigid impacts with the restitution of the
paper's linear contact) under band-limited white noise on the base and under a half-sine base
shock, each with the damper and without it (symimpact.forced.loads.random_response,
symimpact.forced.loads.shock_response; the flight Step 16's Eq. F8, exact for the sampled record)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from ..forced.loads.random_response import KEYS, random_statistics
from ..forced.loads.records import shock_record
from ..forced.loads.shock_response import shock_response
from ..generated import closed_forms
from ..model.units import si
from . import paper
from .document import Figure, Section, Table
from .figures import pyplot, save
from .forced_stage import _system

#: White noise on the base: one-sided PSD [(m/s²)²/Hz] over the band [Hz], sampled every DT [s].
PSD, BAND, DT = 0.01, (0.1, 10.0), 0.005
#: Seconds kept per realisation, and the realisations (quick: fewer).
DURATION, REALISATIONS, REALISATIONS_QUICK = 100.0, 32, 8
SEED = 2026
#: The shock: a half-sine of the base, height [m/s²] and duration [s], the run [s], its samples.
SHOCK_PEAK, SHOCK_PULSE, SHOCK_RUN, SHOCK_DT = 2.0 * 9.80665, 0.011, 10.0, 5e-5
G = 9.80665
STEPS = 2


def section(folder: Path, quick: bool, tick: Any, earlier: Any = ()) -> Section:
    """Build the stage: its figures into ``folder``, its section returned."""
    s = Section("loads", "Beyond the paper: random and shock loads")
    system = _system(earlier)
    k1 = si("k1", paper.FIT["k1"] + " N/m")
    e = float(closed_forms.linear_restitution(system.m, system.M, k1, system.c1))
    duration = float(closed_forms.linear_contact_duration(system.m, system.M, k1, system.c1))
    n = REALISATIONS_QUICK if quick else REALISATIONS
    st = random_statistics(system, PSD, BAND, DURATION, DT, e=e, realisations=n, seed=SEED,
                           kind="base-acceleration", segment=DURATION / 4)  # fmt: skip
    tick()
    fn = system.omega_n / (2 * np.pi)
    s.blocks.append(
        f"Machines, vehicles and buildings shake their structures randomly and by shocks more "
        f"often than by a steady sine. Here the forced stage's system (M = {system.M:g} kg, "
        f"K = {system.K:g} N/m, C = {system.C:g} N s/m: f_n = {fn:.4g} Hz, ζ = "
        f"{system.zeta:.3g}; m = {system.m:g} kg in d = {system.gap * 1e3:g} mm, rigid impacts "
        f"with e = {e:.4f}) stands on a base whose acceleration is band-limited white noise, "
        f"one-sided PSD {PSD:g} (m/s²)²/Hz from {BAND[0]:g} to {BAND[1]:g} Hz, sampled every "
        f"{DT * 1e3:g} ms; {st.realisations} independent realisations (seed {SEED}), each "
        f"{DURATION:g} s kept after {st.settle:.3g} s in which the primary forgets its start. "
        "Between samples the load is a straight line and the flight is exact (Eq. F8); each "
        "realisation runs with the damper and without it on the same record."
    )
    names = {"displacement": ("relative displacement", 1e3, "mm"),
             "velocity": ("relative velocity", 1e3, "mm/s"),
             "acceleration": ("absolute acceleration", 1 / G, "g"),
             "base_force": ("force into the base", 1.0, "N")}  # fmt: skip
    rows = []
    for key in KEYS:
        label, k, unit = names[key]
        lo, hi = st.rms_ci95[key]
        rlo, rhi = st.reduction_ci95[key]
        rows.append([f"{label} [{unit}]", st.baseline_rms[key] * k, st.rms[key] * k, lo * k,
                     hi * k, 100 * st.reduction[key], 100 * rlo, 100 * rhi])  # fmt: skip
    s.blocks.append(
        Table(
            "loads_random_rms",
            "RMS under base noise, with the damper and without it",
            [
                "response",
                "alone",
                "with the damper",
                "95 % low",
                "95 % high",
                "reduction [%]",
                "reduction 95 % low",
                "reduction 95 % high",
            ],
            rows,
            [None, ".4g", ".4g", ".4g", ".4g", ".1f", ".1f", ".1f"],
            note=f"Means over the realisations, 95 % intervals from Student's t on their "
            "logarithms (the spread of the simulated records' mean); the reduction "
            "1 − RMS/RMS alone is taken per realisation (paired on its record). "
            f"{st.impacts_per_second:.3g} impacts a second on average. The acceleration is "
            "between impacts (their impulses are instants).",
        )
    )
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(8, 4.5))
    f = st.psd_frequency
    keep = (f > 0) & (f <= 3 * BAND[1])
    ax.semilogy(f[keep], st.baseline_psd[keep] * 1e6, color="grey", lw=1, label="primary alone")
    ax.semilogy(f[keep], st.psd[keep] * 1e6, color="C0", lw=1.2, label="with the impact damper")
    top = st.baseline_psd[keep].max() * 1e6
    ax.set_ylim(top * 1e-8, top * 3)
    ax.set_xlabel("frequency [Hz]")
    ax.set_ylabel("relative displacement PSD [mm²/Hz]")
    ax.legend(fontsize=8)
    save(fig, folder, "loads_random_psd")
    s.blocks.append(
        Figure(
            "loads_random_psd",
            "The relative displacement's PSD under base noise",
            f"Welch's method, Hann segments of {DURATION / 4:g} s with half overlap (resolution "
            f"{st.psd_resolution:.3g} Hz), averaged over the realisations. Above the band the "
            "primary alone has almost nothing; the impacts put broadband motion there.",
        )
    )
    record = shock_record("half-sine", SHOCK_PEAK, SHOCK_PULSE, SHOCK_RUN, SHOCK_DT,
                          "base-acceleration")  # fmt: skip
    freqs = np.geomspace(0.1 * fn, 100 * fn, 40)
    shock = shock_response(system, record, e=e, frequencies=freqs)
    tick()
    fig, ax = plt.subplots(figsize=(8, 4.5))
    ax.loglog(freqs, shock.baseline_srs / G, color="grey", label="primary alone")
    ax.loglog(freqs, shock.srs / G, color="C0", label="with the impact damper")
    ax.set_xlabel("natural frequency of an equipment on the main mass [Hz]")
    ax.set_ylabel("SRS, maximax absolute acceleration [g]")
    ax.grid(True, which="both", lw=0.3)
    ax.legend(fontsize=8)
    save(fig, folder, "loads_shock_srs")
    i = int(np.argmin(np.abs(freqs - fn)))
    s.blocks.append(
        Figure(
            "loads_shock_srs",
            "Shock-response spectrum of the main mass's motion",
            f"A half-sine of the base, {SHOCK_PEAK / G:g} g for {SHOCK_PULSE * 1e3:g} ms, and "
            f"{SHOCK_RUN:g} s after it (the residual response). Oscillators of damping ratio "
            f"{shock.zeta:g} on the main mass, driven by its displacement and velocity (which "
            "hold no impulses; its acceleration does). Peak relative displacement "
            f"{shock.peak * 1e3:.4g} mm with the damper ({shock.impacts} impacts), "
            f"{shock.baseline_peak * 1e3:.4g} mm alone; at the primary's frequency the SRS is "
            f"{shock.srs[i] / G:.3g} g with the damper and {shock.baseline_srs[i] / G:.3g} g alone. "
            "A rigid impact is a jump of the main mass's velocity, and the SRS of a jump Δv grows "
            "like 2πf·Δv: the rise at high frequency is the rigid idealisation's. The paper's "
            f"linear contact lasts {duration * 1e3:.4g} ms (Eq. 35), so above about "
            f"{1 / duration:.2g} Hz the contact's own duration, which the rigid law neglects, "
            "would cut it down.",
        )
    )
    return s
