"""Figures for the command line and the report (matplotlib, Agg backend, PNG)."""

from __future__ import annotations

import os
from typing import Any

from ..io import atomic_savefig


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


def plot_forced(result: Any, t: Any, state: Any, discard: int, path: str | os.PathLike) -> None:
    """Forced response (Eq. F1; rigid impacts, Eq. F2, or a compliant contact): x(t) with the
    impacts (contact onsets) marked, the kept (steady) window after ``discard`` periods shaded
    with ±amplitude dotted, and the relative displacement z = y − x between the walls ±d/2."""
    from ..model.display import display_unit, label, omega_text, shown

    plt = _pyplot()
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(9, 6), sharex=True)
    ax1.plot(t, shown("x", state[:, 0]), lw=0.8, label="main mass x")
    imp = result.impacts
    if len(imp):
        ax1.plot(imp, shown("x", result.impact_displacements), "k.", ms=2, label="impact")
    st = result.steady
    if st is not None:
        kept_from = discard * result.forcing.period
        ax1.axvspan(kept_from, t[-1], color="C3", alpha=0.08, lw=0, label="steady window")
        for sign in (-1, 1):
            ax1.axhline(sign * shown("x", st.amplitude), color="C3", lw=0.8, ls=":")
    ax1.set_ylabel(label("x"))
    ax1.legend(fontsize=8, ncol=3)
    ax2.plot(t, shown("z", state[:, 2]), lw=0.8, color="C2", label="z = y − x")
    for s in (-1, 1):
        ax2.axhline(s * shown("z", 0.5 * result.system.gap), color="grey", ls="--", lw=0.8)
    ax2.set_xlabel(label("t"))
    ax2.set_ylabel(label("z"))
    ax2.legend(fontsize=8)
    f = result.forcing
    fig.suptitle(
        f"Ω = {omega_text(f.omega, '.4g')}, "
        + (f"rigid, e = {result.e:g}" if result.contact == "rigid" else f"{result.contact} contact")
        + f": {len(imp)} impacts"
        + (
            ""
            if st is None
            else f", steady amplitude {shown('x', st.amplitude):.4g} {display_unit('x')}"
        )
    )
    fig.tight_layout()
    atomic_savefig(fig, path)
    plt.close(fig)


def legend_beside(ax: Any, *handles_labels: Any, **options: Any) -> Any:
    """The axes' legend outside it, to the right of its top corner, so that it covers no curve
    however the data fall (``tight_layout`` makes room for it); ``handles_labels`` and
    ``options`` as for ``Axes.legend``."""
    options = {"fontsize": 8, "loc": "upper left", "bbox_to_anchor": (1.01, 1.0),
               "borderaxespad": 0.0, **options}  # fmt: skip
    return ax.legend(*handles_labels, **options)


def verdict_run(a: Any, stable: Any, flag: bool) -> Any:
    """``a`` where the orbits' verdict ``stable`` is ``flag``, NaN elsewhere: each run of equal
    verdicts joined to its neighbour, so that the curve drawn in two styles stays unbroken."""
    import numpy as np

    joined = np.asarray(stable) == flag
    joined[1:] |= np.asarray(stable)[:-1] == flag
    return np.where(joined, a, np.nan)


def draw_frf(ax: Any, frf: Any, sweeps: bool = True) -> None:
    """Draw a frequency-response curve on ``ax`` (see :func:`plot_frf`), with its one legend.

    The answer first (issue 80, item 6): the stable branches bold and on top in one colour, the
    unstable ones thin, dashed and pale beneath, the worst case the curve located marked (★),
    the sweeps' motions that do not repeat as a shaded envelope of their periods' largest abs(x)
    (:func:`_draw_envelope`), the other motions the multi-start landed on (not periodic,
    chattering: ×), the located
    bifurcations small and pale, the brute-force sweeps as faint dots, and the primary without
    the damper in grey."""
    import numpy as np

    from ..forced.responses import AXIS, QUANTITY, shown_response
    from ..model.display import display_unit, shown

    def W(v):  # Ω in its display unit (rad/s, or Hz when the band was given in Hz)
        return shown("omega", v)

    name = getattr(frf, "response", "displacement")  # what the amplitude fields hold
    quantity = QUANTITY[name]
    decibels = name == "transmissibility"  # drawn in dB, 20·log₁₀ T, as vibration tests read it

    def Y(v):  # the response in its display unit
        if decibels:
            with np.errstate(divide="ignore"):
                return 20.0 * np.log10(np.asarray(v, dtype=float))
        return shown_response(name, v)

    unit = "dB" if decibels else (None if quantity is None else display_unit(quantity))
    base = frf.baseline
    ax.plot(W(base[:, 0]), Y(base[:, 1]), color="0.55", lw=1.2, zorder=1,
            label="without the damper")  # fmt: skip
    for k, (lo, hi) in enumerate(getattr(frf, "no_impact", [])):
        inside = (base[:, 0] >= lo) & (base[:, 0] <= hi)
        ax.plot(W(base[inside, 0]), Y(base[inside, 1]), color="0.6", lw=4, alpha=0.45,
                solid_capstyle="butt", zorder=1,
                label=None if k else "no impact (mass at rest midway)")  # fmt: skip
    for g in getattr(frf, "no_impact_grazings", []):
        ax.axvline(W(g), color="0.6", lw=0.8, ls=":", zorder=0)
    if sweeps and frf.sweep_up is not None and len(frf.sweep_up):
        both = np.vstack([frf.sweep_up, frf.sweep_down])
        ax.plot(W(both[:, 0]), Y(both[:, 1]), ".", color="C1", ms=2.5, alpha=0.5, zorder=2,
                label="sweeps up and down (brute force)")  # fmt: skip
    for flag in (False, True):  # the unstable beneath, the stable drawn last, on top
        for b in frf.branches:
            w = W(np.array([p.omega for p in b.points]))
            a = Y(np.array([p.amplitude for p in b.points]))
            stable = np.array([p.stable for p in b.points])
            y = verdict_run(a, stable, flag)
            if flag:
                ax.plot(w, y, "-", color="C0", lw=2.2, zorder=4, solid_capstyle="round")
            else:
                ax.plot(w, y, "--", color="C0", lw=0.7, alpha=0.45, zorder=2)
    ax.plot([], [], "-", color="C0", lw=2.2, label="stable periodic orbits")
    ax.plot([], [], "--", color="C0", lw=0.7, alpha=0.45, label="unstable")
    if name == "displacement":  # (the envelope is of |x|: drawn on a displacement curve only)
        _draw_envelope(ax, frf, W, Y)
    cov = getattr(frf, "coverage", None)
    # the multi-start's amplitudes are displacements: drawn on a displacement curve only
    wild = [a for a in getattr(cov, "attractors", []) or [] if a.kind != "periodic"
            and a.kind != "no impact"] if name == "displacement" else []  # fmt: skip
    if wild:
        ax.plot(W(np.array([a.omega for a in wild])), Y(np.array([a.amplitude for a in wild])),
                "x", color="C3", ms=4, mew=1.0, zorder=5,
                label="other motions the multi-start landed on (not periodic, chatter)")  # fmt: skip
    markers = {"fold": "o", "branch-point": "s", "period-doubling": "D", "neimark-sacker": "*",
               "grazing": "x"}  # fmt: skip
    seen = set()
    for b in frf.branches:
        for f in b.bifurcations:
            ax.plot(W(f.omega), Y(f.amplitude), markers[f.kind], color="0.25", ms=3.5,
                    mfc="none", mew=0.6, alpha=0.7, zorder=3,
                    label=None if f.kind in seen else f.kind)  # fmt: skip
            seen.add(f.kind)
    peak = getattr(frf, "peak", None)
    if peak is not None:
        ax.plot(W(peak.omega), Y(peak.amplitude), "*", color="gold", mec="k", ms=14, zorder=6,
                label=f"worst case {Y(peak.amplitude):.4g}" + ("" if unit is None else f" {unit}")
                + f" at Ω {W(peak.omega):.4g} {display_unit('omega')}")  # fmt: skip
    ax.set_xlabel(f"Ω [{display_unit('omega')}]")
    ax.set_ylabel(AXIS[name] + ("" if unit is None else f" [{unit}]"))
    ax.set_xlim(W(frf.omegas[0]), W(frf.omegas[-1]))
    legend_beside(ax)


def _draw_envelope(ax: Any, frf: Any, W: Any, Y: Any) -> None:
    """The non-periodic bands of the sweeps (``frf.not_periodic``) shaded from the lowest to the
    highest of their kept periods' largest abs(x), each sweep's run of neighbouring frequencies one
    patch (a lone frequency a vertical bar): where a motion does not repeat, the primary's
    amplitude wanders between those bounds from period to period."""
    import numpy as np

    rows = getattr(frf, "not_periodic", None) or []
    grid = {float(w): i for i, w in enumerate(frf.omegas)}
    labelled = False
    for sweep in ("up", "down"):
        mine = sorted((grid.get(w, -2), w, lo, hi) for d, w, lo, hi in rows if d == sweep)
        runs: list[list] = []
        for row in mine:  # neighbours on the band's grid make one patch
            if runs and row[0] == runs[-1][-1][0] + 1 and row[0] >= 0:
                runs[-1].append(row)
            else:
                runs.append([row])
        for run in runs:
            w = W(np.array([r[1] for r in run]))
            lo, hi = Y(np.array([r[2] for r in run])), Y(np.array([r[3] for r in run]))
            label = None if labelled else ("motions that do not repeat (sweeps): the range of "
                                           "their periods' largest |x|")  # fmt: skip
            if len(run) == 1:
                ax.vlines(w, lo, hi, color="C3", lw=2.5, alpha=0.35, zorder=2, label=label)
            else:
                ax.fill_between(w, lo, hi, color="C3", alpha=0.22, lw=0, zorder=2, label=label)
            labelled = True


def plot_frf(frf: Any, path: str | os.PathLike, title: str = "") -> None:
    """The frequency-response curve (:func:`symimpact.forced.orbits.frf.frequency_response`),
    drawn by :func:`draw_frf`: the stable branches bold, the unstable thin and dashed, the worst
    case marked, the motions that do not repeat (the sweeps' as a shaded envelope, the
    multi-start's as marks), the located bifurcations, the brute-force sweeps and the primary
    without the damper."""
    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(9, 5.5))
    draw_frf(ax, frf)
    if title:
        ax.set_title(title, fontsize=10)
    fig.tight_layout()
    atomic_savefig(fig, path)
    plt.close(fig)


def plot_structure_run(period_max: Any, points: Any, period: float, discard: int,
                       path: str | os.PathLike, title: str = "") -> None:  # fmt: skip
    """A structure's forced run (``simulate --structure``,
    :func:`symimpact.forced.structure_response.simulate_structure`): one panel a named point, the
    largest abs(x) in each forcing period against time (``period`` [s] each, ``period_max`` of
    shape (periods, points) [m]), the periods before ``discard`` (the transient) pale, and the
    steady amplitude over the rest (the command's ``amplitudes``) as a dashed line."""
    import numpy as np

    from ..model.display import display_unit, shown

    plt = _pyplot()
    points = list(points)
    pm = np.asarray(period_max, dtype=float)
    t = (np.arange(len(pm)) + 0.5) * period  # each period's middle
    fig, axes = plt.subplots(len(points), 1, figsize=(9, 2.0 + 2.4 * len(points)), sharex=True,
                             squeeze=False)  # fmt: skip
    for j, (ax, point) in enumerate(zip(axes[:, 0], points, strict=True)):
        y = shown("x", pm[:, j])
        ax.plot(t[: discard + 1], y[: discard + 1], ".-", color="C0", alpha=0.35, ms=2, lw=0.6,
                label="transient (left out)")  # fmt: skip
        ax.plot(t[discard:], y[discard:], ".-", color="C0", ms=2.5, lw=0.9,
                label="largest |x| in each period")  # fmt: skip
        steady = float(np.max(y[discard:]))
        ax.axhline(steady, color="k", lw=0.8, ls="--",
                   label=f"steady amplitude {steady:.4g} {display_unit('x')}")  # fmt: skip
        ax.set_ylabel(f"max |x| at {point} [{display_unit('x')}]")
        ax.legend(fontsize=7, loc="lower right")
    axes[-1, 0].set_xlabel("t [s]")
    if title:
        axes[0, 0].set_title(title, fontsize=10)
    fig.tight_layout()
    atomic_savefig(fig, path)
    plt.close(fig)


def plot_structure_curve(branches: Any, points: Any, path: str | os.PathLike, title: str = "",
                         parameter: str = "omega", settled: Any = (),
                         bare: dict[str, Any] | None = None,
                         peaks: dict[str, Any] | None = None) -> None:  # fmt: skip
    """A structure's branches (``frf --structure``: in Ω,
    :func:`symimpact.forced.orbits.structure_branch.structure_curve`; ``branch --structure``: in a
    damper's gap, e or m or in F0, :func:`~symimpact.forced.orbits.structure_branch.parameter_branch`):
    one panel a named point of ``points``, the amplitude at that point against ``parameter`` —
    stable orbits bold, unstable ones thin and dashed, the ``settled`` runs from rest as dots,
    the bare structure (no damper, no stop) in grey and the located peak (★).  ``bare``:
    {point: (Ω [rad/s], amplitude [m])}; ``peaks``: {point: the peak's dict or None}, as the
    command's JSON holds them."""
    import numpy as np

    from ..model.display import display_unit, shown

    def X(v):  # the parameter in its display unit
        return shown(parameter, v)

    plt = _pyplot()
    points = list(points)
    fig, axes = plt.subplots(len(points), 1, figsize=(9, 2.0 + 2.6 * len(points)), sharex=True,
                             squeeze=False)  # fmt: skip
    for ax, point in zip(axes[:, 0], points, strict=True):
        if bare is not None:
            w, a = bare[point]
            ax.plot(X(w), shown("x", a), color="0.55", lw=1.2, zorder=1,
                    label="bare structure (no damper, no stop)")  # fmt: skip
        if len(settled):
            ax.plot(X(np.array([r["omega"] for r in settled])),
                    shown("x", np.array([r["amplitudes"][point] for r in settled])),
                    ".", color="C1", ms=3, alpha=0.6, zorder=2, label="runs from rest")  # fmt: skip
        for flag in (False, True):
            for b in branches:
                amp = shown("x", b.amplitudes(point))
                stable = np.array([o.stable for o in b.orbits])
                y = verdict_run(amp, stable, flag)
                if flag:
                    ax.plot(X(b.values), y, "-", color="C0", lw=2.2, zorder=4)
                else:
                    ax.plot(X(b.values), y, "--", color="C0", lw=0.7, alpha=0.45, zorder=3)
        ax.plot([], [], "-", color="C0", lw=2.2, label="stable periodic orbits")
        ax.plot([], [], "--", color="C0", lw=0.7, alpha=0.45, label="unstable")
        pk = (peaks or {}).get(point)
        if pk is not None:
            ax.plot(X(pk["omega"]), shown("x", pk["amplitude"]), "*", color="gold", mec="k",
                    ms=13, zorder=6,
                    label=f"peak {shown('x', pk['amplitude']):.4g} {display_unit('x')}")  # fmt: skip
        ax.set_ylabel(f"max |x| at {point} [{display_unit('x')}]")
        ax.legend(fontsize=7, loc="upper left")
    unit = display_unit(parameter)
    axes[-1, 0].set_xlabel(f"{'Ω' if parameter == 'omega' else parameter}"
                           + (f" [{unit}]" if unit else ""))  # fmt: skip
    if title:
        axes[0, 0].set_title(title, fontsize=10)
    fig.tight_layout()
    atomic_savefig(fig, path)
    plt.close(fig)


def plot_frf_beside(exact: Any, other: Any, path: str | os.PathLike, label: str,
                    title: str = "") -> None:  # fmt: skip
    """The exact curve (:func:`draw_frf`) with a second curve of the same schema drawn over it
    (``other``, e.g. the harmonic balance's of :mod:`symimpact.forced.orbits.hb_frf`): its
    stable orbits a thin red line through its points, its unstable ones dotted, its largest
    stable orbit a red star."""
    import numpy as np

    from ..model.display import shown

    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(9, 5.5))
    draw_frf(ax, exact)
    for flag in (False, True):
        for b in other.branches:
            w = shown("omega", np.array([p.omega for p in b.points]))
            a = shown("x", np.array([p.amplitude for p in b.points]))
            stable = np.array([p.stable for p in b.points])
            ax.plot(w, verdict_run(a, stable, flag), "-" if flag else ":", color="C3",
                    lw=1.0, marker="o" if flag else None, ms=2.5, zorder=7)  # fmt: skip
    ax.plot([], [], "-", color="C3", lw=1.0, marker="o", ms=2.5, label=f"{label}: stable (Hill)")
    ax.plot([], [], ":", color="C3", lw=1.0, label=f"{label}: unstable")
    if other.peak is not None:
        ax.plot(shown("omega", other.peak.omega), shown("x", other.peak.amplitude), "*",
                color="C3", mec="k", ms=10, zorder=8, label=f"{label}: largest stable")  # fmt: skip
    legend_beside(ax)  # again: draw_frf's legend with these entries
    if title:
        ax.set_title(title, fontsize=10)
    fig.tight_layout()
    atomic_savefig(fig, path)
    plt.close(fig)


def plot_branch(branch: Any, path: str | os.PathLike, title: str = "") -> None:
    """A branch continued in a parameter (:func:`symimpact.forced.trace_branch`): the amplitude
    against the parameter (d and X_b in mm), stable solid and unstable dashed, the located
    bifurcations marked by kind."""
    import numpy as np

    from ..model.display import display_unit, shown

    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(9, 5.5))
    name = branch.parameter
    length = name in ("gap", "X_b")

    def along(v):
        return shown("gap", v) if length else v

    x = along(np.array([p.value for p in branch.points]))
    a = shown("x", np.array([p.amplitude for p in branch.points]))
    stable = np.array([p.stable for p in branch.points])
    for flag, style in ((True, "-"), (False, "--")):
        ax.plot(x, verdict_run(a, stable, flag), style, color="C0", lw=1.4)
    markers = {"fold": "o", "branch-point": "s", "period-doubling": "D", "neimark-sacker": "*",
               "grazing": "x"}  # fmt: skip
    seen = set()
    for f in branch.bifurcations:
        ax.plot(along(f.value), shown("x", f.amplitude), markers[f.kind], color="k", ms=6,
                mfc="none", label=None if f.kind in seen else f.kind)  # fmt: skip
        seen.add(f.kind)
    ax.plot([], [], "-", color="C0", label="stable")
    ax.plot([], [], "--", color="C0", label="unstable")
    unit = display_unit("gap") if length else {"F0": "N", "e": ""}[name]
    ax.set_xlabel(f"{name} [{unit}]" if unit else name)
    ax.set_ylabel(f"amplitude max |x| [{display_unit('x')}]")
    ax.legend(fontsize=8)
    if title:
        ax.set_title(title, fontsize=10)
    fig.tight_layout()
    atomic_savefig(fig, path)
    plt.close(fig)


def plot_design(
    table: Any,
    path: str | os.PathLike,
    title: str = "",
    response: str = "displacement",
    best: list[dict[str, Any]] | None = None,
) -> None:
    """The clearance design map (:func:`symimpact.maps.design.design_map`): the peak amplitude
    (or the peak of ``response``, as the map was run) over the band against the clearance, one
    line per mass ratio, the best clearance of each marked, and the primary without the damper's
    peak (dashed).  ``best``: the refined best clearances (rows of
    :func:`symimpact.maps.design.refine_best`, SI, ``peak_amplitude`` the peak of ``response``),
    marked with their tolerance instead of the grid's best, so the figure shows the answer the
    command prints."""
    from ..forced.responses import shown_response
    from ..maps.design import best_clearances
    from ..model.display import display_unit, shown

    def Y(v):  # the response in its display unit
        return shown_response(response, v)

    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(8, 5))
    by = "mass_ratio" if "mass_ratio" in table.columns else ("m" if "m" in table.columns else None)
    groups = [(None, table)] if by is None else list(table.groupby(by, sort=True))
    for i, (key, g) in enumerate(groups):
        g = g.sort_values("gap")
        text = "" if key is None else (f"m/M = {key:g}" if by == "mass_ratio" else
                                       f"m = {key:g} kg")  # fmt: skip
        ax.plot(shown("gap", g["gap"]), Y(g["peak_amplitude"]), "o-", color=f"C{i % 10}",
                ms=3, lw=1.3, label=text or "with the damper")  # fmt: skip
    marks = best if best is not None else [r for _, r in best_clearances(table).iterrows()]
    for i, row in enumerate(marks):
        tol = row.get("tolerance") if best is not None else None
        label = None
        if i == 0:
            label = "best clearance" + (
                f" (refined, ± {shown('gap', tol):.2g} {display_unit('gap')})" if tol else ""
            )
        ax.errorbar(shown("gap", row["gap"]), Y(row["peak_amplitude"]),
                    xerr=None if not tol else shown("gap", tol), fmt="*", ms=13, capsize=4,
                    color=f"C{i % 10}", mec="k", label=label)  # fmt: skip
    _finish_design(plt, fig, ax, float(table["baseline_peak"].max()), path, title, response)


def plot_robust_design(
    result: dict[str, Any], path: str | os.PathLike, title: str = "",
    response: str = "displacement",
) -> None:  # fmt: skip
    """A design robust to the restitution (:func:`symimpact.maps.design.robust_design`): the
    band of the peak (of ``response``, as the design was run) over the range of e against the
    clearance, the nominal e's curve, the worst case, both best clearances marked, and the
    primary without the damper (dashed)."""
    from ..forced.responses import shown_response
    from ..model.display import shown

    def Y(v):  # the response in its display unit
        return shown_response(response, v)

    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(8, 5))
    rows = result["rows"]
    d = [shown("gap", r["gap"]) for r in rows]
    low = [Y(min(r["peaks"])) for r in rows]
    worst = [Y(r["worst_peak"]) for r in rows]
    es = result["e"]
    ax.fill_between(d, low, worst, color="C0", alpha=0.25,
                    label=f"peak over e {es[0]:.3g}–{es[-1]:.3g}")  # fmt: skip
    ax.plot(d, [Y(r["nominal_peak"]) for r in rows], "o-", color="C0", ms=3, lw=1.3,
            label=f"nominal e {es[len(es) // 2]:.3g}")  # fmt: skip
    ax.plot(d, worst, "s--", color="C3", ms=3, lw=1.0, label="worst case over e")
    nb, rb = result["nominal_best"], result["robust_best"]
    ax.plot(shown("gap", nb["gap"]), Y(nb["nominal_peak"]), "*", ms=13, color="C0",
            mec="k", label="best at the nominal e")  # fmt: skip
    ax.plot(shown("gap", rb["gap"]), Y(rb["worst_peak"]), "*", ms=13, color="C3",
            mec="k", label="robust (smallest worst case)")  # fmt: skip
    _finish_design(plt, fig, ax, rows[0]["baseline_peak"], path, title, response)


def _finish_design(plt: Any, fig: Any, ax: Any, baseline: float, path: Any, title: str,
                   response: str = "displacement") -> None:  # fmt: skip
    """A design figure's common end: the primary alone's peak (dashed), the axes (the peak of
    ``response``), the legend, the title, and the file written."""
    from ..forced.responses import AXIS, QUANTITY, shown_response
    from ..model.display import display_unit

    quantity = QUANTITY[response]
    ax.axhline(shown_response(response, baseline), ls="--", color="0.5", lw=1.0,
               label="without the damper")  # fmt: skip
    ax.set_xlabel(f"clearance d [{display_unit('gap')}]")
    unit = "" if quantity is None else f" [{display_unit(quantity)}]"
    what = "peak amplitude" if response == "displacement" else f"peak of {AXIS[response]}"
    ax.set_ylabel(f"{what} over the band{unit}")
    ax.set_ylim(bottom=0)
    ax.legend(fontsize=8)
    if title:
        ax.set_title(title, fontsize=10)
    fig.tight_layout()
    atomic_savefig(fig, path)
    plt.close(fig)


def plot_sweep(rows: list[dict[str, Any]], over: str, path: str | os.PathLike) -> None:
    """DI, N_eff and effectiveness against the swept parameter (as Fig. 7)."""
    from ..model.display import label, shown

    plt = _pyplot()
    x = [shown(over, r[over]) for r in rows]
    fig, axes = plt.subplots(3, 1, figsize=(8, 7), sharex=True)
    series = (
        ("damping_inclination", label("damping_inclination").replace("damping_inclination", "DI")),
        ("n_effective", "N_eff"),
        ("effectiveness", "effectiveness"),
    )
    for ax, (key, text) in zip(axes, series, strict=True):
        ys = [float("nan") if r[key] is None else shown(key, r[key]) for r in rows]
        ax.plot(x, ys, "o-", ms=3)
        ax.set_ylabel(text)
        ax.ticklabel_format(axis="y", useOffset=False)
    axes[-1].set_xlabel(label(over))
    fig.tight_layout()
    atomic_savefig(fig, path)
    plt.close(fig)


def _edges(centres):
    import numpy as np

    c = np.asarray(centres, dtype=float)
    if c.size == 1:
        return np.array([c[0] - 0.5, c[0] + 0.5]) if c[0] == 0 else c[0] * np.array([0.95, 1.05])
    mid = 0.5 * (c[1:] + c[:-1])
    return np.concatenate([[c[0] - (mid[0] - c[0])], mid, [c[-1] + (c[-1] - mid[-1])]])


#: The best cell of a heat map is *isolated* where its best neighbour falls short of it by more
#: than this share of the map's range of values: a lone outlier among its neighbours (a
#: motion that settled differently), not a design the neighbourhood confirms.
ISOLATED = 0.25


def best_cell_neighbourhood(z: Any, i0: int, j0: int, best: str) -> tuple[float | None, bool]:
    """The best value among the (up to eight) neighbours of cell (i0, j0) of the grid ``z``
    (None where none is defined), and whether the cell is isolated: it beats that neighbour by
    more than :data:`ISOLATED` of the range of the grid's defined values."""
    import numpy as np

    block = z[max(i0 - 1, 0) : i0 + 2, max(j0 - 1, 0) : j0 + 2].astype(float).copy()
    block[min(i0, 1), min(j0, 1)] = np.nan  # the cell itself
    if not np.any(np.isfinite(block)):
        return None, False
    near = float(np.nanmax(block) if best == "max" else np.nanmin(block))
    span = float(np.nanmax(z) - np.nanmin(z))
    return near, abs(float(z[i0, j0]) - near) > ISOLATED * span


def plot_map(
    table: Any,
    x: str,
    y: str,
    value: str = "damping_inclination",
    path: str | os.PathLike = "map.png",
    best: str = "max",
) -> dict[str, Any]:
    """Heat map of the map output ``value`` over the swept inputs ``x`` and ``y``, with the
    optimum marked: for each ``y`` the ``x`` that gives the best ``value`` (white dots) and the
    best cell of the map (star; hollow where it is isolated, see :func:`best_cell_neighbourhood`).
    ``best`` is ``"max"`` or ``"min"``.

    With more than two swept inputs, each cell shows the best ``value`` over the others (said in
    the title).  Cells where ``value`` is undefined are left blank.  Returns the optimum:
    ``{x, y, value}``, the per-``y`` optima ``{"rows": [(y, x, value), ...]}``, its best
    neighbour's value ``"neighbour_best"`` and whether it is ``"isolated"``.
    """
    import numpy as np

    from ..errors import ParameterError
    from ..maps import OUTPUTS

    for name, role in ((x, "x"), (y, "y")):
        if name not in table.columns or name in OUTPUTS or name == "run":
            raise ParameterError(role, f"{name!r} is not a swept input of this map")
    if x == y:
        raise ParameterError("y", "must differ from x")
    if value not in OUTPUTS or value == "class":
        raise ParameterError("value", f"must be a numeric output: {', '.join(OUTPUTS[:-1])}")
    if best not in ("max", "min"):
        raise ParameterError("best", "must be 'max' or 'min'")
    others = [c for c in table.columns if c not in ("run", x, y, *OUTPUTS)]
    v = table[value].astype("float64")  # <NA> → NaN for the reduction only
    frame = table[[x, y]].assign(_v=v)
    grouped = frame.groupby([y, x], sort=True)["_v"]
    cells = grouped.max() if best == "max" else grouped.min()
    grid = cells.unstack(x)
    xs, ys = grid.columns.to_numpy(float), grid.index.to_numpy(float)
    z = grid.to_numpy(float)
    if not np.any(np.isfinite(z)):
        raise ParameterError("value", f"{value} is undefined everywhere in this map")
    pick = np.nanargmax if best == "max" else np.nanargmin
    rows = []
    for i, yv in enumerate(ys):
        if np.any(np.isfinite(z[i])):
            j = int(pick(z[i]))
            rows.append((float(yv), float(xs[j]), float(z[i, j])))
    flat = int(pick(z))
    i0, j0 = divmod(flat, z.shape[1])
    near, isolated = best_cell_neighbourhood(z, i0, j0, best)
    optimum = {x: float(xs[j0]), y: float(ys[i0]), value: float(z[i0, j0]), "rows": rows,
               "neighbour_best": near, "isolated": isolated}  # fmt: skip

    from ..model.display import label, shown

    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(8, 6))
    sx, sy = shown(x, xs), shown(y, ys)  # axes and colours in display units
    mesh = ax.pcolormesh(_edges(sx), _edges(sy), np.ma.masked_invalid(shown(value, z)),
                         cmap="viridis")  # fmt: skip
    fig.colorbar(mesh, ax=ax, label=label(value))
    ax.plot(
        [shown(x, r[1]) for r in rows],
        [shown(y, r[0]) for r in rows],
        "o",
        mfc="white",
        mec="black",
        ms=4,
        label=f"{best} of {value} for each {y}",
    )
    star = f"{best} of the map" + (" (isolated: its neighbours do not confirm it)" if isolated
                                    else "")  # fmt: skip
    ax.plot(sx[j0], sy[i0], "*", ms=16, mfc="none" if isolated else "red",
            mec="red" if isolated else "white", label=star)  # fmt: skip
    ax.set_xlabel(label(x))
    ax.set_ylabel(label(y))
    title = (
        f"{label(value)}: {best} {shown(value, z[i0, j0]):.4g} at {x} = {sx[j0]:.4g}, "
        f"{y} = {sy[i0]:.4g}"
    )
    if others:
        title += f"\n({best} over {', '.join(others)})"
    ax.set_title(title, fontsize=10)
    ax.legend(fontsize=8, loc="best")
    fig.tight_layout()
    atomic_savefig(fig, path)
    plt.close(fig)
    return optimum


def plot_random(
    stats: Any, path: str | os.PathLike, band: tuple[float, float] | None = None
) -> None:
    """The displacement's PSD with and without the damper (Welch, averaged over realisations;
    symimpact.forced.loads.random_response) on log–log axes, as a test engineer reads a PSD: over
    the load's ``band`` [Hz] (shaded) and an octave either side, where the impacts' broadband
    shows; the RMS values and the reduction in the title."""
    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(8, 4.5))
    f = stats.psd_frequency
    keep = f > 0
    if band is not None:
        keep &= (f >= band[0] / 2.0) & (f <= band[1] * 2.0)
        ax.axvspan(band[0], band[1], color="0.93", zorder=0, label=f"the load's band "
                   f"{band[0]:g}–{band[1]:g} Hz")  # fmt: skip
    ax.loglog(f[keep], stats.baseline_psd[keep] * 1e6, lw=1, color="grey", label="primary alone")
    ax.loglog(f[keep], stats.psd[keep] * 1e6, lw=1.2, color="C0", label="with the impact damper")
    top = max(stats.psd[keep].max(), stats.baseline_psd[keep].max()) * 1e6
    ax.set_ylim(top * 1e-10, top * 3)  # ten decades: the band and the impacts' broadband
    ax.set_xlabel("frequency [Hz]")
    ax.set_ylabel("displacement PSD [mm²/Hz]")
    lo, hi = stats.reduction_ci95["displacement"]
    ax.set_title(
        f"RMS {stats.rms['displacement'] * 1e3:.3g} mm (alone {stats.baseline_rms['displacement'] * 1e3:.3g}"
        f" mm): reduction {100 * stats.reduction['displacement']:.0f} % "
        f"(95 %: {100 * lo:.0f}–{100 * hi:.0f} %), {stats.realisations} realisations; "
        f"resolution {stats.psd_resolution:.2g} Hz",
        fontsize=9,
    )
    ax.legend(fontsize=8)
    fig.tight_layout()
    atomic_savefig(fig, path)
    plt.close(fig)


def plot_shock(shock: Any, path: str | os.PathLike) -> None:
    """The shock-response spectrum of the main mass's motion with and without the damper
    (symimpact.forced.loads.shock_response), in g, log-log."""
    plt = _pyplot()
    g = 9.80665
    fig, ax = plt.subplots(figsize=(8, 4.5))
    ax.loglog(shock.frequency, shock.baseline_srs / g, color="grey", label="primary alone")
    ax.loglog(shock.frequency, shock.srs / g, color="C0", label="with the impact damper")
    ax.set_xlabel("natural frequency of the equipment [Hz]")
    ax.set_ylabel(f"SRS, maximax absolute acceleration [g] (ζ = {shock.zeta:g})")
    ax.set_title(
        f"peak displacement {shock.peak * 1e3:.3g} mm (alone {shock.baseline_peak * 1e3:.3g} mm), "
        f"{shock.impacts} impacts",
        fontsize=9,
    )
    ax.legend(fontsize=8)
    ax.grid(True, which="both", lw=0.3)
    fig.tight_layout()
    atomic_savefig(fig, path)
    plt.close(fig)


def plot_sine_sweep(sweep: Any, path: str | os.PathLike) -> None:
    """The displacement's envelope against the instantaneous frequency, up and down, with and
    without the damper (symimpact.forced.loads.sweep_response), and, when the run computed it, the
    steady curve of ``frf`` at the same amplitude beside them: the stable orbits of each
    continued branch (black), the motion without impacts (thick grey) and the primary alone's
    steady response (dotted)."""
    import numpy as np

    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(9, 4.8))
    for d, name, ls in ((sweep.up, "up", "-"), (sweep.down, "down", "--")):
        ax.plot(d["frequency"], d["baseline"] * 1e3, ls, color="grey", lw=0.9,
                label=f"primary alone, sweep {name}")  # fmt: skip
        ax.plot(d["frequency"], d["envelope"] * 1e3, ls, color="C0", lw=1.2,
                label=f"with the impact damper, sweep {name}")  # fmt: skip
    c = getattr(sweep, "steady", None)
    if c is not None:
        ax.plot(c.linear[:, 0], c.linear[:, 1] * 1e3, ":", color="0.3", lw=1.0,
                label="primary alone, steady")  # fmt: skip
        if len(c.no_impact):
            ax.plot(c.no_impact[:, 0], c.no_impact[:, 1] * 1e3, color="0.6", lw=4, alpha=0.45,
                    solid_capstyle="butt", label="steady, no impact")  # fmt: skip
        for k, b in enumerate(np.unique(c.stable[:, 2])):
            rows = c.stable[c.stable[:, 2] == b]
            ax.plot(rows[:, 0], rows[:, 1] * 1e3, ".", color="k", ms=3,
                    label=None if k else "steady stable orbits (frf)")  # fmt: skip
    ax.set_xlabel("instantaneous frequency [Hz]")
    ax.set_ylabel("largest |x| over each period [mm]")
    legend_beside(ax)
    fig.tight_layout()
    atomic_savefig(fig, path)
    plt.close(fig)


def plot_restitution_fit(data: Any, results: dict[str, Any], law: str,
                         path: str | os.PathLike) -> None:  # fmt: skip
    """The restitution identified from single impacts (symimpact.identify.impacts): measured e
    against the approach speed with the fitted ``law`` (solid) and the other laws (dashed); the
    residuals of the rebound speed; the profile of each fitted parameter (RSS over its least,
    the 95 % threshold dotted)."""
    import numpy as np

    from ..identify.impacts import restitution

    plt = _pyplot()
    result = results[law]
    n = len(result.parameters)
    fig, axes = plt.subplots(1, 2 + n, figsize=(4.2 * (2 + n), 4.0))
    ax = axes[0]
    w = np.geomspace(data.v_in.min(), data.v_in.max(), 300)
    ax.plot(data.v_in, data.v_out / data.v_in, "o", color="k", ms=3, label="measured")
    for k, r in results.items():
        ax.plot(
            w,
            restitution(k, list(r.values().values()), w),
            "-" if k == law else "--",
            lw=1.6 if k == law else 0.9,
            label=f"{k} (rms {r.residual_rms * 1e3:.3g} mm/s)",
        )
    ax.set_xscale("log")
    ax.set_xlabel("approach speed [m/s]")
    ax.set_ylabel("coefficient of restitution e [1]")
    ax.legend(fontsize=8)
    ax = axes[1]
    ax.axhline(0.0, color="grey", lw=0.8)
    ax.plot(data.v_in, result.residuals * 1e3, "o", color="C0", ms=3)
    ax.set_xscale("log")
    ax.set_xlabel("approach speed [m/s]")
    ax.set_ylabel(f"rebound speed, measured − {law} [mm/s]")
    for ax, (name, p) in zip(axes[2:], result.parameters.items(), strict=True):
        prof = result.profiles[name]
        ax.plot(prof[:, 0], prof[:, 1] / result.rss if result.rss > 0 else prof[:, 1], ".-",
                color="C0", ms=4)  # fmt: skip
        if result.rss > 0:
            ax.axhline(result.threshold / result.rss, color="k", ls=":", lw=1,
                       label="95 % threshold")  # fmt: skip
        ax.axvline(p.value, color="grey", lw=0.8)
        ax.xaxis.set_major_locator(plt.MaxNLocator(4))
        ax.set_xlabel(f"{name} [{p.unit}]")
        ax.set_ylabel("profile RSS / least RSS")
        ax.legend(fontsize=8)
    fig.tight_layout()
    atomic_savefig(fig, path)
    plt.close(fig)


def plot_decay_fit(data: Any, result: Any, response: Any, path: str | os.PathLike) -> None:
    """A free decay and the model fitted to it (symimpact.identify.decay): the record and the
    fitted motion with its impacts marked, the residuals below, and each fitted parameter's
    profile (RSS over its least, the 95 % threshold dotted)."""
    plt = _pyplot()
    scale, unit = {"displacement": (1e3, "mm"), "velocity": (1e3, "mm/s"),
                   "acceleration": (1.0, "m/s²")}[data.quantity]  # fmt: skip
    names = [k for k in result.parameters if k not in ("x0", "xdot0")]
    fig = plt.figure(figsize=(11, 7))
    grid = fig.add_gridspec(3, max(len(names), 1))
    ax1 = fig.add_subplot(grid[0, :])
    t = data.times
    ax1.plot(t, data.values * scale, color="0.6", lw=2.2, label="measured")
    ax1.plot(t, (data.values - result.residuals) * scale, color="C0", lw=0.9, label="fitted")
    for k, ti in enumerate(response.impact_times):
        ax1.axvline(ti, color="C3", lw=0.5, alpha=0.5, label=None if k else "impacts (fitted)")
    ax1.set_ylabel(f"{data.quantity} [{unit}]")
    ax1.legend(fontsize=8, ncol=3)
    ax2 = fig.add_subplot(grid[1, :], sharex=ax1)
    ax2.plot(t, result.residuals * scale, color="C0", lw=0.7)
    ax2.axhline(0.0, color="grey", lw=0.8)
    ax2.set_xlabel("t [s]")
    ax2.set_ylabel(f"measured − fitted [{unit}]")
    for k, name in enumerate(names):
        ax = fig.add_subplot(grid[2, k])
        p, prof = result.parameters[name], result.profiles[name]
        ax.plot(prof[:, 0], prof[:, 1] / result.rss if result.rss > 0 else prof[:, 1], ".",
                color="C0", ms=3)  # fmt: skip
        if result.rss > 0:
            ax.axhline(result.threshold / result.rss, color="k", ls=":", lw=1)
        ax.axvline(p.value, color="grey", lw=0.8)
        ax.xaxis.set_major_locator(plt.MaxNLocator(3))
        ax.set_xlabel(f"{name} [{p.unit}]")
        if k == 0:
            ax.set_ylabel("profile RSS / least")
    fig.tight_layout()
    atomic_savefig(fig, path)
    plt.close(fig)
