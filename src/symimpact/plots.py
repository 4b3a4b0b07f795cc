"""Figures for the command line and the report (matplotlib, Agg backend, PNG)."""

from __future__ import annotations

import os
from typing import Any

from .io import atomic_savefig


def _pyplot():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def plot_simulation(result: Any, path: str | os.PathLike) -> None:
    """x(t) and y(t) with the impacts marked (effective per Eq. 37 filled) and the four maxima
    used by the damping inclination (Eq. 36)."""
    plt = _pyplot()
    h = result.history
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(9, 6), sharex=True)
    ax1.plot(h["t"], h["x"] * 1e3, lw=1, label="main mass x")
    ax1.plot(h["t"], h["y"] * 1e3, lw=0.8, alpha=0.7, label="impact mass y")
    eff = [i for i in result.impacts if i.effective]
    non = [i for i in result.impacts if not i.effective]
    ax1.plot([i.t for i in eff], [i.x * 1e3 for i in eff], "ko", ms=3, label="effective impact")
    ax1.plot(
        [i.t for i in non],
        [i.x * 1e3 for i in non],
        "o",
        mfc="none",
        mec="k",
        ms=3,
        label="non-effective impact",
    )
    if len(result.peaks) >= 4:
        ax1.plot(result.peaks[:4, 0], result.peaks[:4, 1] * 1e3, "r^", ms=5, label="DI maxima")
    ax1.set_ylabel("displacement [mm]")
    ax1.legend(fontsize=8, ncol=2)
    ax2.plot(h["t"], (h["y"] - h["x"]) * 1e3, lw=1, color="C2", label="y − x")
    half = 0.5 * result.system.gap * 1e3
    for s in (-1, 1):
        ax2.axhline(s * half, color="grey", ls="--", lw=0.8)
    ax2.set_xlabel("t [s]")
    ax2.set_ylabel("relative [mm]")
    ax2.legend(fontsize=8)
    di = result.damping_inclination
    fig.suptitle(
        f"d = {result.system.gap * 1e3:g} mm: N_tot {result.n_impacts}, N_eff {result.n_effective}, "
        f"DI {'n/a' if di is None else f'{di * 1e6:.2f} µm'}"
    )
    fig.tight_layout()
    atomic_savefig(fig, path)
    plt.close(fig)


def plot_sweep(rows: list[dict[str, Any]], over: str, path: str | os.PathLike) -> None:
    """DI, N_eff and effectiveness against the swept parameter (as Fig. 7)."""
    plt = _pyplot()
    x = [r[over] for r in rows]
    fig, axes = plt.subplots(3, 1, figsize=(8, 7), sharex=True)
    series = (
        ("damping_inclination", "DI [m]"),
        ("n_effective", "N_eff"),
        ("effectiveness", "effectiveness"),
    )
    for ax, (key, label) in zip(axes, series, strict=True):
        ax.plot(x, [float("nan") if r[key] is None else r[key] for r in rows], "o-", ms=3)
        ax.set_ylabel(label)
    axes[-1].set_xlabel(over + " [SI]")
    fig.tight_layout()
    atomic_savefig(fig, path)
    plt.close(fig)
