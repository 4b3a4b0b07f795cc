"""Sweeps over a parameter (gap by default) and the gap classification of Sect. 4 (Fig. 5).

Classification (method stated because the paper does not give one): a gap is **in range** when
the simulation from the given initial state has at least as many effective impacts (Eq. 37) as
non-effective ones, i.e. effectiveness (Eq. 38) ≥ 1 or every impact effective; otherwise it is
**out of range** (and **no impact** when the masses never touch).  This criterion gives the class
printed for every one of the nine gaps of Table 3 from the effectiveness printed beside it.
The classes change on fine scales (thin strips of either class, down to 0.01 mm and below), so
they are reported as intervals of a stated grid with the share of in-range gaps per mm, and d_min,
d_max by stated criteria: a robust envelope of a fine sweep (:func:`envelope_limits`) and the
paper's Fig. 5 criterion, the effective-contact condition at the first contact the impact mass
reaches by its own motion (:func:`fig5_limits`), whose sign changes are true boundaries.  No
class boundary is placed by bisection between two grid points.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Sequence
from typing import Any

import numpy as np

from ..errors import ParameterError
from ..model.system import ImpactSystem
from ..model.units import si_float
from .engine import map_rows
from .points import SWEEPABLE, MapPoints, _si_values


def sweep(
    system: ImpactSystem,
    values: Iterable[Any],
    parameter: str = "gap",
    *,
    x0: Any = 0.0,
    xdot0: Any = 0.0,
    y0: Any = 0.0,
    ydot0: Any = 0.0,
    t_end: Any = 1.0,
    contact: str | None = None,
    workers: int | None = None,
    executor: str | None = None,
    client: Any = None,
    progress: bool | Callable[[int, int], None] = True,
) -> list[dict[str, Any]]:
    """One simulation per value of ``parameter``: rows with N_tot, N_eff, effectiveness (Eq. 38),
    DI (Eq. 36), ζ_eq, energies [J] and class, in the order of ``values``.

    ``parameter`` is a system parameter (``gap``, ``m``, ``c1``, ...), ``mass_ratio`` or an
    initial condition (``x0``, ``xdot0``, ``y0``, ``ydot0``, ``t_end``).  Runs on the
    ``executor`` of :func:`symimpact.maps.parameter_map` (default ``workers`` local processes,
    all cores) with a progress bar on standard error unless ``progress`` is False.  For several
    swept inputs, files and resuming, use :func:`symimpact.maps.parameter_map`.
    """

    if parameter not in SWEEPABLE:
        raise ParameterError(
            "parameter", f"cannot sweep {parameter!r}; choose one of {', '.join(SWEEPABLE)}"
        )
    vals = _si_values(parameter, values)  # ranges, lists or quantities → SI, finite, non-empty
    rows = map_rows(
        system,
        MapPoints((parameter,), vals.reshape(-1, 1)),
        x0=x0,
        xdot0=xdot0,
        y0=y0,
        ydot0=ydot0,
        t_end=t_end,
        contact=contact,
        executor=executor,
        workers=workers,
        client=client,
        progress=progress,
        desc="sweep",
    )
    for r in rows:
        del r["run"]
    return rows


def gap_intervals(rows: Sequence[dict[str, Any]]) -> list[dict[str, Any]]:
    """Runs of consecutive gaps with the same class, from sweep rows sorted by gap.

    Each interval is ``{"class", "from", "to", "n"}`` [m]: the first and last grid gap of the run
    and how many grid gaps it holds.  A boundary is known to the grid step, no better: between the
    last gap of one interval and the first of the next.
    """
    out: list[dict[str, Any]] = []
    for r in sorted(rows, key=lambda r: r["gap"]):
        if out and out[-1]["class"] == r["class"]:
            out[-1]["to"] = r["gap"]
            out[-1]["n"] += 1
        else:
            out.append({"class": r["class"], "from": r["gap"], "to": r["gap"], "n": 1})
    return out


def in_range_share(rows: Sequence[dict[str, Any]], bin_width: float = 1e-3) -> list[dict[str, Any]]:
    """Share of in-range gaps in consecutive bins of ``bin_width`` [m] (default 1 mm):
    ``[{"from", "to", "n", "share"}]``, bins aligned to multiples of ``bin_width``; the fine
    structure of the classes, whatever the grid step."""
    bins: dict[int, list[bool]] = {}
    for r in rows:
        k = int(np.floor(r["gap"] / bin_width + 1e-9))
        bins.setdefault(k, []).append(r["class"] == "in range")
    return [
        {
            "from": k * bin_width,
            "to": (k + 1) * bin_width,
            "n": len(v),
            "share": sum(v) / len(v),
        }
        for k, v in sorted(bins.items())
    ]


def envelope_limits(
    rows: Sequence[dict[str, Any]], share: float = 0.9, window: float = 1e-3
) -> tuple[float | None, float | None]:
    """Robust d_min and d_max [m] of a fine gap sweep.

    d_min is the smallest grid gap d such that at least ``share`` of the grid gaps in
    [d, d + window] are in range; d_max the largest d such that at least ``share`` of those in
    [d − window, d] are.  A single in-range gap among out-of-range ones (or the reverse), a strip
    narrower than the window, moves neither limit; each limit is known to the grid step.
    (None, None) when no window qualifies.
    """
    if not 0.0 < share <= 1.0:
        raise ParameterError("share", "must be in (0, 1]")
    if not window > 0.0:
        raise ParameterError("window", "must be positive")
    pts = sorted((r["gap"], r["class"] == "in range") for r in rows)
    gaps = np.array([g for g, _ in pts])
    inside = np.array([i for _, i in pts], dtype=float)
    tol = 1e-9 * window

    def ok(lo: float, hi: float) -> bool:
        sel = (gaps >= lo - tol) & (gaps <= hi + tol)
        return bool(sel.any()) and inside[sel].mean() >= share

    lows = [g for g in gaps if ok(g, g + window)]
    highs = [g for g in gaps if ok(g - window, g)]
    return (float(lows[0]) if lows else None, float(highs[-1]) if highs else None)


def arrival_condition(system: ImpactSystem, gap: float, **kwargs: Any) -> float:
    """ẋ·ẏ [m²/s²] at the onset of the first contact the impact mass reaches by its own motion.

    The effective-contact condition of Eq. 37 on the relative motion (Sect. 4, Fig. 5): that
    contact is effective when this is negative.  "By its own motion": the first contact whose
    onset finds ẏ ≠ 0; with the paper's initial state (Y0 = Ẏ0 = 0) the main mass meets the
    resting impact mass first, so it is the second contact, the end of the first flight of the
    impact mass across the clearance.  It depends continuously on the gap while that contact
    stays the same event, so its sign changes are boundaries that root-finding can place.
    NaN when no such contact happens before ``t_end``.  Keywords: those of
    :func:`symimpact.free.simulation.simulate` (initial state, t_end, contact).
    """
    from ..free.simulation import simulate

    res = simulate(system.with_(gap=gap), **kwargs)
    for imp in res.impacts:
        if imp.ydot != 0.0:
            return imp.xdot * imp.ydot
    return float("nan")


def fig5_limits(
    system: ImpactSystem, gaps: Sequence[Any], *, xtol: float = 1e-9, **kwargs: Any
) -> dict[str, Any]:
    """d_min and d_max [m] by the paper's Fig. 5 criterion: the effective-contact condition
    (ẋ·ẏ < 0, Eq. 37) at the first contact the impact mass reaches by its own motion
    (:func:`arrival_condition`).

    The condition is evaluated on the grid ``gaps``; every sign change is placed by Brent's
    method to ``xtol`` [m].  A boundary where the condition jumps instead of crossing zero (that
    contact becomes another event, e.g. a grazing one appears) is kept with ``kind="jump"``.
    d_min is the first boundary entering an acceptable stretch, d_max the last one leaving it;
    None where the grid's end is reached inside one (then no limit lies within the grid).
    Returns ``{"d_min", "d_max", "boundaries", "method"}``.
    """
    from scipy.optimize import brentq

    grid = np.sort(np.array([si_float("gaps", g) for g in gaps]))

    def g(d: float) -> float:
        return arrival_condition(system, float(d), **kwargs)

    vals = np.array([g(d) for d in grid])
    boundaries = []
    for a, b, ga, gb in zip(grid[:-1], grid[1:], vals[:-1], vals[1:], strict=True):
        if not (np.isfinite(ga) and np.isfinite(gb)) or (ga < 0) == (gb < 0):
            continue
        root = brentq(g, a, b, xtol=xtol)
        near = max(abs(g(root - 2 * xtol)), abs(g(root + 2 * xtol)))
        scale = max(abs(ga), abs(gb))
        boundaries.append(
            {
                "gap": float(root),
                "enters": bool(gb < 0),  # acceptable above the boundary
                "kind": "zero" if near <= 1e-3 * scale else "jump",
            }
        )
    d_min = next((b["gap"] for b in boundaries if b["enters"]), None)
    d_max = next((b["gap"] for b in reversed(boundaries) if not b["enters"]), None)
    return {
        "d_min": d_min,
        "d_max": d_max,
        "boundaries": boundaries,
        "method": "Fig. 5 criterion: ẋ·ẏ < 0 (Eq. 37) at the first contact the impact mass "
        f"reaches by its own motion, sign changes placed by Brent's method to {xtol:g} m",
    }


def gap_range(
    system: ImpactSystem,
    gaps: Sequence[Any],
    *,
    share: float = 0.9,
    window: float = 1e-3,
    **kwargs: Any,
) -> dict[str, Any]:
    """Gap classes of a fine sweep as intervals, their share per mm, and robust d_min, d_max.

    Runs :func:`sweep` over ``gaps`` (keywords: those of :func:`sweep`) and returns
    ``{"d_min", "d_max", "resolution", "intervals", "shares", "method", "rows"}``: the intervals
    of :func:`gap_intervals`, the per-mm shares of :func:`in_range_share` and the envelope limits
    of :func:`envelope_limits` (``share``, ``window``), None where it finds none or where it is
    the grid's first or last gap (the range goes on beyond the grid).  The limits are stated at
    the grid's resolution (its largest step); no boundary is refined between two grid points,
    because the classes change on scales far below any grid (thin strips of either class).
    """
    rows = sweep(system, gaps, "gap", **kwargs)
    grid = np.sort([r["gap"] for r in rows])
    d_min, d_max = envelope_limits(rows, share, window)
    # a limit at the grid's end only says that the grid ends inside the range
    d_min = None if d_min == grid[0] else d_min
    d_max = None if d_max == grid[-1] else d_max
    return {
        "d_min": d_min,
        "d_max": d_max,
        "resolution": float(np.max(np.diff(grid))) if len(grid) > 1 else None,
        "intervals": gap_intervals(rows),
        "shares": in_range_share(rows, window),
        "method": f"envelope: the extreme gaps from which at least {share:.0%} of the gaps in "
        f"the next (d_min) or previous (d_max) {window * 1e3:g} mm are in range; in range ⇔ "
        "N_eff ≥ N_tot − N_eff (Eq. 37–38)",
        "rows": rows,
    }
