"""The tip response of a 3-mode steel cantilever strip around its first mode, bare and with one
and with two rigid impact dampers (the figure of issue 36's note): the bare curve is the modal
receptance, each damped curve is :func:`symimpact.forced.orbits.structure_branch.structure_curve`'s —
periodic orbits continued in Ω with their stability (solid: stable, dashed: unstable) and a run
from rest at every frequency of the grid (dots), which holds the motions no branch follows
(chatter, sticking, motions that are not periodic) — and each curve's peak is located
(:func:`symimpact.forced.orbits.structure_branch.curve_peak`, beside the bare structure's
:func:`symimpact.forced.orbits.structure_branch.bare_peak`).  It prints the time each curve took: the
issue's target is a 200-frequency ``frf`` with stability within 60 s (``--points 200``).

Run: ``PYTHONPATH=. python benchmarks/structure_frc.py [--out FIGURE.png] [--points N]``.
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from symimpact.forced.orbits.structure_branch import bare_peak, curve_peak, structure_curve
from symimpact.model.dampers import damper
from symimpact.model.structure import beam_structure

# a steel strip 25 mm × 10 mm, 0.5 m long
E, RHO, B, H, L = 210e9, 7850.0, 0.025, 0.010, 0.5
A, I = B * H, B * H**3 / 12.0
F0 = 1.0  # N at the tip


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default="structure_frc.png")
    ap.add_argument("--points", type=int, default=61, help="frequencies of the band's grid")
    ap.add_argument("--warmup", type=int, default=300, help="periods of each run from rest")
    ns = ap.parse_args()
    s = beam_structure("cantilever", E, I, RHO, A, L, {"tip": L, "mid": L / 2}, 3, 0.01)
    f1 = s.modes[0].frequency
    w_lo, w_hi = 2 * np.pi * 0.85 * f1, 2 * np.pi * 1.15 * f1
    step = (w_hi - w_lo) / (ns.points - 1)
    tip = damper(s, "tip", "tip", 0.02, 0.004, 0.6)
    mid = damper(s, "mid", "mid", 0.02, 0.001, 0.6)
    configs = {"one damper (tip)": (tip,), "two dampers (tip, mid)": (tip, mid)}
    bare = bare_peak(s, "tip", F0, "tip", w_lo, w_hi)
    print(f"3-mode cantilever ({', '.join(f'{m.frequency:.1f}' for m in s.modes)} Hz), "
          f"{F0:g} N at the tip, {ns.points} frequencies {w_lo / 2 / np.pi:.2f}-"
          f"{w_hi / 2 / np.pi:.2f} Hz, {ns.warmup} periods from rest at each")  # fmt: skip
    print(f"  no damper: peak {bare.amplitude * 1e3:.4f} mm at {bare.omega / 2 / np.pi:.4f} Hz "
          "(receptance)")  # fmt: skip
    curves = {}
    for name, ds in configs.items():
        t0 = time.perf_counter()
        c = structure_curve(s, ds, "tip", F0, w_lo, w_hi, step, warmup=ns.warmup)
        peak = curve_peak(s, ds, "tip", F0, c, "tip")
        secs = time.perf_counter() - t0
        first = " (compiling included)" if not curves else ""
        curves[name] = c
        orbits = sum(len(b.orbits) for b in c.branches)
        print(f"  {name}: {secs:.1f} s{first}, {len(c.branches)} "
              f"branches, {orbits} orbits, "
              f"{sum(len(b.bifurcations) for b in c.branches)} bifurcations; peak "
              f"{peak.amplitude * 1e3:.4f} mm at {peak.omega / 2 / np.pi:.4f} Hz ({peak.kind}), "
              f"{100 * (1 - peak.amplitude / bare.amplitude):.1f} % below the bare peak")  # fmt: skip
        for note in c.notes:
            print(f"    note: {note}")
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    grid = np.linspace(w_lo, w_hi, 400)
    ax.plot(grid / 2 / np.pi, [abs(s.receptance("tip", "tip", w)) * F0 * 1e3 for w in grid],
            color="0.4", lw=1, label="no damper")  # fmt: skip
    for (name, c), color in zip(curves.items(), ("C0", "C3"), strict=True):
        for j, b in enumerate(c.branches):
            f = b.omegas / 2 / np.pi
            a = b.amplitudes("tip") * 1e3
            st = np.array([o.stable for o in b.orbits])
            ax.plot(f, np.where(st, a, np.nan), color=color, lw=1.6,
                    label=f"{name}: stable orbits" if j == 0 else None)  # fmt: skip
            ax.plot(f, np.where(st, np.nan, a), color=color, lw=1, ls="--",
                    label=f"{name}: unstable" if j == 0 else None)  # fmt: skip
        ax.plot([r["omega"] / 2 / np.pi for r in c.settled],
                [r["amplitudes"]["tip"] * 1e3 for r in c.settled], ".", color=color, ms=3,
                label=f"{name}: run from rest")  # fmt: skip
    ax.set_xlabel("forcing frequency [Hz]")
    ax.set_ylabel("tip amplitude [mm]")
    ax.set_title(f"3-mode steel cantilever, {F0:g} N at the tip\ndampers 20 g, e 0.6, clearance "
                 "4 mm (tip), 1 mm (mid)", fontsize=9)  # fmt: skip
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(ns.out, dpi=120)
    print(f"figure: {ns.out}")


if __name__ == "__main__":
    main()
