"""Sweeps over a parameter (gap by default) and the gap classification of Sect. 4 (Fig. 5).

Classification (method stated because the paper does not give one): a gap is **in range** when
the simulation from the given initial state has at least as many effective impacts (Eq. 37) as
non-effective ones, i.e. effectiveness (Eq. 38) ≥ 1 or every impact effective; otherwise it is
**out of range** (and **no impact** when the masses never touch).  This criterion gives the class
printed for every one of the nine gaps of Table 3 from the effectiveness printed beside it.
d_min and d_max are the smallest and largest in-range gaps of a grid, each refined by bisection
against its out-of-range neighbour.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Sequence
from typing import Any

import numpy as np

from .errors import ParameterError
from .system import ImpactSystem
from .units import si_float


def gap_class(n_impacts: int, n_effective: int) -> str:
    """``in range``, ``out of range`` or ``no impact`` by the criterion of this module."""
    if n_impacts == 0:
        return "no impact"
    return "in range" if n_effective >= n_impacts - n_effective else "out of range"


def parse_range(name: str, text: str) -> np.ndarray:
    """``"6 mm:35 mm:1 mm"`` (start:stop:step, stop included) or ``"7 mm,9 mm,15 mm"`` → SI."""
    if ":" in text:
        parts = text.split(":")
        if len(parts) != 3:
            raise ParameterError(name, f"range {text!r} must be start:stop:step")
        start, stop, step = (si_float(name, p.strip()) for p in parts)
        if step <= 0:
            raise ParameterError(name, f"range step must be positive, got {step:g}")
        if stop < start:
            raise ParameterError(name, f"range stop {stop:g} is below its start {start:g}")
        n = int(np.floor((stop - start) / step * (1 + 1e-12) + 1e-9)) + 1
        if n > 1_000_000:
            raise ParameterError(name, f"range has {n} values; at most 1e6")
        # 12 significant digits: "6 mm:35 mm:1 mm" gives 0.009, not 0.009000000000000001
        return np.array([float(f"{start + step * k:.12g}") for k in range(n)])
    return np.array([si_float(name, p.strip()) for p in text.split(",") if p.strip()])


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
    from .maps import SWEEPABLE, MapPoints, _si_values, map_rows

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


def gap_range(
    system: ImpactSystem,
    gaps: Sequence[Any],
    *,
    refine: bool = True,
    tol: float = 1e-5,
    **kwargs: Any,
) -> dict[str, Any]:
    """d_min and d_max [m]: the extreme in-range gaps of the grid ``gaps`` (see the module text),
    each refined by bisection to ``tol`` [m] against its out-of-range neighbour.

    Keywords are those of :func:`sweep` (initial state, t_end, contact, workers, progress).
    Returns ``{"d_min", "d_max", "method", "rows"}``; d_min/d_max are None if no gap is in range.
    """
    rows = sweep(system, gaps, "gap", **kwargs)
    grid = [r["gap"] for r in rows]
    inside = [i for i, r in enumerate(rows) if r["class"] == "in range"]
    out: dict[str, Any] = {
        "d_min": None,
        "d_max": None,
        "method": "in range ⇔ N_eff ≥ N_tot − N_eff (Eq. 37–38); extreme in-range grid gaps "
        + ("refined by bisection" if refine else "of the grid"),
        "rows": rows,
    }
    if not inside:
        return out
    from .maps import INITIAL, _Base, run_point

    initial = tuple((n, si_float(n, kwargs.get(n, 1.0 if n == "t_end" else 0.0))) for n in INITIAL)
    base = _Base(system, initial, kwargs.get("contact"))

    def is_in(gap):
        return run_point(base, ("gap",), (gap,))["class"] == "in range"

    def bisect(lo_in, hi_out):
        a, b = lo_in, hi_out
        while abs(b - a) > tol:
            mid = 0.5 * (a + b)
            if is_in(mid):
                a = mid
            else:
                b = mid
        return a

    lo, hi = inside[0], inside[-1]
    out["d_min"] = grid[lo] if not (refine and lo > 0) else bisect(grid[lo], grid[lo - 1])
    out["d_max"] = (
        grid[hi] if not (refine and hi < len(grid) - 1) else bisect(grid[hi], grid[hi + 1])
    )
    return out
