"""The clearance design map: the worst steady amplitude of the primary over a frequency band,
against the clearance d (and the mass ratio m/M), beside the primary without the damper.

For one design (a point of the map) the band is covered by the steady motions the package can
find:

- the **stable** periodic orbits of the frequency-response curve
  (:func:`symimpact.forced.frequency_response`: shooting and continuation of impacting orbits,
  Floquet multipliers);
- the **motion without impacts**: the impact mass at rest midway while the primary follows its
  linear response X(Ω) (Step 8's steady solution), a steady motion wherever X(Ω) < d/2 (the
  relative motion then stays inside the clearance);
- the **brute-force sweeps** up and down the band (chatter and sticking included), each point
  run from the previous end state until its transient is 1e-6 (exp(−ζω_n·t)): they show the
  motions no branch holds (not periodic, or where shooting does not converge), and motions
  coexisting with a traced branch that the curve's starts do not reach; a periodic swept motion
  with impacts, chatter and sticking included, starts a branch of its own.

The design's **peak** is the largest amplitude among them: the worst motion the machine may
settle on in the band, located on the branches and on the motion without impacts
(:mod:`symimpact.forced.orbits.peak`), and taken from a sweep only where a swept motion no branch
holds exceeds it.  Beside it: the peak of the primary without the damper, their ratio,
where the peak is and which motion gives it, and how many frequencies of the band only the
sweeps cover (``uncovered_frequencies``: no stable branch, no motion without impacts).  A motion
that neither the curve's starts nor the sweeps reach is not seen; a stable branch's largest
amplitude is located between its points (Brent's method on shot orbits), and the primary
alone's peak is located on its closed form.

:func:`refine_best` refines the best clearance of the grid by a one-dimensional search (Brent's
method, bounded by the grid's neighbours) on the peak, to a stated tolerance, then walks at that
tolerance until no clearance one to three steps away has a smaller peak: the peak against d is not
unimodal where the worst motion changes (a period-2 or non-periodic motion the sweeps carry beside
a located orbit), and Brent's method alone can stop on a shoulder.  The peak's sensitivity to the
restitution (e ± 0.1) is given beside it.

:func:`design_map` runs the points on the executors of a parameter map (serial, local
processes, Dask) and streams them to a resumable file (:class:`~symimpact.maps.store.MapStore`);
:func:`best_clearances` picks, for each mass ratio, the clearance of the smallest peak.
"""

from __future__ import annotations

import itertools
import math
import os
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from .. import _pool
from ..errors import ParameterError
from ..forced.contact_law import checked, is_constant, is_rigid
from ..forced.forcing import Forcing
from ..forced.orbits.coverage import FREQUENCIES
from ..forced.orbits.frf import SWEEP_ACCURACY, _sweep, _sweep_runs, frequency_response
from ..model import checks
from ..model.system import ImpactSystem
from .engine import _executor, _gather, _launch, _progress
from .points import MapPoints, as_points
from .store import MapStore

#: What a design map may sweep: the clearance, the impact mass or the mass ratio m/M.
DESIGN_SWEEPABLE = ("gap", "m", "mass_ratio")
#: Output columns of a design row, in table order (after ``run`` and the swept inputs).
DESIGN_OUTPUTS = (
    "peak_amplitude",
    "peak_omega",
    "peak_motion",
    "baseline_peak",
    "baseline_omega",
    "peak_ratio",
    "branches",
    "stable_frequencies",
    "linear_frequencies",
    "uncovered_frequencies",
)
#: The kinds of motion a peak can belong to (``peak_motion``).
MOTIONS = ("stable orbit", "no impact", "sweep up", "sweep down", "not periodic")


@dataclass(frozen=True)
class _DesignBase:
    system: ImpactSystem
    forcing: Forcing
    e: float
    omegas: tuple[float, ...]
    multistart: int = FREQUENCIES
    response: str = "displacement"
    #: processes for each curve's multi-start: the map's own where its clearances run here, one
    #: where they run on worker processes (which start no pool of their own)
    curve_workers: int | None = None


def _design_system(base: _DesignBase, names: Sequence[str], values: Sequence[float]):
    changes: dict[str, float] = {}
    for n, v in zip(names, values, strict=True):
        if n == "mass_ratio":
            if not v > 0:
                raise ParameterError("mass_ratio", f"must be positive, got {v:g}")
            changes["m"] = float(v) * base.system.M
        else:
            changes[n] = float(v)
    return base.system.with_(**changes) if changes else base.system


def _stable_spans(branches) -> list[tuple[float, float]]:
    """The Ω intervals spanned by two consecutive stable points of a branch."""
    spans = []
    for b in branches:
        for p, q in itertools.pairwise(b.points):
            if p.stable and q.stable:
                spans.append(tuple(sorted((p.omega, q.omega))))
    return spans


def design_row(
    system: ImpactSystem, forcing: Forcing, e: float, omegas: Any, curve: Any = None,
    multistart: int = FREQUENCIES, response: str = "displacement", workers: int | None = None,
    progress: Any = None,
) -> dict[str, Any]:  # fmt: skip
    """The design map's figures for one system over the band ``omegas`` [rad/s] (module text):
    ``peak_amplitude`` [m] and ``peak_omega`` [rad/s] of the worst steady motion, ``peak_motion``
    (one of :data:`MOTIONS`), ``baseline_peak`` [m] and ``baseline_omega`` [rad/s] of the primary
    without the damper (Step 8, Eq. F1), ``peak_ratio`` = peak/baseline, the number of
    ``branches`` of the curve and how many frequencies of the band each kind of motion covers.
    ``curve``: the system's frequency response over ``omegas`` if already computed (its sweeps
    are run and stored in it if it has none); ``multistart``: frequencies of the curve's
    multi-start (:mod:`symimpact.forced.orbits.coverage`; 0: none).  ``response``
    (:data:`symimpact.forced.responses.RESPONSES`): what the peaks measure [its SI unit] —
    the curve in that response (:func:`symimpact.forced.orbits.response_curve.response_curve`), the
    primary alone's closed form, and the sweeps measured in it over their kept periods.
    ``workers``: processes for the curve's multi-start (None: one per core); ``progress``: the
    curve's (:func:`~symimpact.forced.orbits.frf.frequency_response`)."""
    w = np.asarray(omegas, dtype=float)
    if curve is None:
        curve = frequency_response(system, forcing, e, w, multistart=multistart, workers=workers,
                                   progress=progress)  # fmt: skip
    if response != "displacement":
        return _response_row(system, forcing, e, w, curve, response)
    if curve.sweep_up is None or not len(curve.sweep_up):
        curve.sweep_up = _sweep(system, forcing, e, w)
        curve.sweep_down = _sweep(system, forcing, e, w[::-1])[::-1]
    return _row(system, w, curve, curve, curve.sweep_up, curve.sweep_down)


def _response_row(system, forcing, e, w, curve, response: str) -> dict[str, Any]:
    """:func:`design_row` in a response other than the displacement."""
    from ..forced.orbits.response_curve import response_curve

    shown = response_curve(curve, response, system, forcing, e)
    up = _sweep_runs(system, forcing, e, w, response=response)
    down = _sweep_runs(system, forcing, e, w[::-1], response=response)[::-1]
    return _row(system, w, curve, shown,
                np.array([(p.omega, p.response) for p in up]),
                np.array([(p.omega, p.response) for p in down]))  # fmt: skip


def _row(system, w, curve, shown, sweep_up, sweep_down) -> dict[str, Any]:
    """A design row: ``curve`` (the displacement's: where the motion is stable or without
    impacts), ``shown`` (the same curve in the measured response: its located peaks) and the
    sweeps ((Ω, response) rows, up and down)."""
    linear = curve.baseline[:, 1]  # the primary alone (Step 8), computed with the curve
    spans = _stable_spans(curve.branches)
    stable = np.array([any(lo <= x <= hi for lo, hi in spans) for x in w], dtype=bool)
    free = linear < system.gap / 2.0
    located = shown.peak
    if located is None:
        peak, peak_omega, motion = 0.0, math.nan, ""
    else:
        peak, peak_omega = located.amplitude, located.omega
        # a stable orbit, the motion without impacts, or a steady motion no branch holds (the
        # multi-start's or the worst case's: chatter, chaos, a motion that does not repeat)
        motion = {"periodic": MOTIONS[0], "no impact": MOTIONS[1]}.get(located.motion, MOTIONS[4])
    swept = [(float(a), float(x), motion)
             for motion, sweep in ((MOTIONS[2], sweep_up), (MOTIONS[3], sweep_down))
             for x, a in sweep]  # fmt: skip
    top = max(swept)
    # a swept amplitude carries its transient (≤ SWEEP_ACCURACY): it names the peak only where
    # it exceeds every traced motion by more than that (a motion no branch holds)
    if top[0] > peak * (1.0 + SWEEP_ACCURACY):
        peak, peak_omega, motion = top
    base = shown.baseline_peak
    return {
        "peak_amplitude": peak,
        "peak_omega": peak_omega,
        "peak_motion": motion,
        "baseline_peak": base.amplitude,
        "baseline_omega": base.omega,
        "peak_ratio": peak / base.amplitude,
        "branches": len(curve.branches),
        "stable_frequencies": int(stable.sum()),
        "linear_frequencies": int(free.sum()),
        "uncovered_frequencies": int((~stable & ~free).sum()),
    }


def _design_chunk(payload: tuple[_DesignBase, tuple[str, ...], list[int], np.ndarray]):
    """The rows of one chunk of a design map (what every executor runs)."""
    base, names, runs, values = payload
    rows = []
    for run, v in zip(runs, values, strict=True):
        system = _design_system(base, names, v)
        row: dict[str, Any] = {"run": int(run)}
        row.update(zip(names, (float(x) for x in v), strict=True))
        # each run of the curve counted where the map's progress reads it (_pool.CurveRuns)
        row.update(design_row(system, base.forcing, base.e, np.array(base.omegas),
                              multistart=base.multistart, response=base.response,
                              workers=base.curve_workers, progress=_pool.CurveRuns()))  # fmt: skip
        rows.append(row)
    return rows


def design_table(rows: list[dict[str, Any]], names: Sequence[str]):
    """Design rows as a DataFrame, in run order, with fixed columns and dtypes."""
    import pandas as pd

    df = pd.DataFrame.from_records(rows, columns=["run", *names, *DESIGN_OUTPUTS])
    df["run"] = df["run"].astype("int64")
    for c in (*names, "peak_amplitude", "peak_omega", "baseline_peak", "baseline_omega",
              "peak_ratio"):  # fmt: skip
        df[c] = df[c].astype("float64")
    for c in DESIGN_OUTPUTS[-4:]:
        df[c] = df[c].astype("int64")
    df["peak_motion"] = df["peak_motion"].astype("string")
    return df.sort_values("run", kind="stable").reset_index(drop=True)


def design_map(
    system: ImpactSystem,
    forcing: Forcing,
    e: Any,
    omegas: Any,
    grid: Mapping[str, Any],
    *,
    executor: str | None = None,
    workers: int | None = None,
    client: Any = None,
    scheduler: str | None = None,
    out: str | os.PathLike | None = None,
    force: bool = False,
    progress: bool | Callable[[int, int], None] = False,
    multistart: int = FREQUENCIES,
    response: str = "displacement",
    runs: Callable[[int], None] | None = None,
):
    """The clearance design map (module text): one row per point of ``grid`` (``{name:
    values}`` over :data:`DESIGN_SWEEPABLE`, values in SI or with units) for the contact ``e``
    (Newton's restitution of rigid impacts, or a :class:`~symimpact.forced.CompliantContact`)
    under ``forcing`` over the band ``omegas`` [rad/s].  ``executor``,
    ``workers``, ``client``, ``scheduler``, ``out`` and ``force`` as for
    :func:`symimpact.maps.parameter_map`: the same executors, and a resumable ``out`` file;
    ``multistart``: frequencies of each curve's multi-start (0: none); ``response``: what the
    peaks measure (:func:`design_row`).  The progress bar counts clearances and notes beside
    them the runs their curves have made (on the workers too, through shared memory), so that it
    moves while a clearance's curve runs; ``runs(n)`` is told that number as it grows."""
    from ..forced.responses import checked_response

    system, forcing, e = checked(system, forcing, e)
    response = checked_response(response, forcing, rigid=is_rigid(e))
    if not isinstance(grid, Mapping) or not grid:
        raise ParameterError("grid", "give the clearance (gap) and/or mass_ratio values")
    bad = [n for n in grid if n not in DESIGN_SWEEPABLE]
    if bad:
        raise ParameterError(bad[0], f"a design map sweeps {', '.join(DESIGN_SWEEPABLE)}")
    points: MapPoints = as_points(dict(grid))
    w = checks.numbers("omegas", omegas)
    if w.ndim != 1 or len(w) < 2 or not np.all(np.isfinite(w)) or np.any(np.diff(w) <= 0):
        raise ParameterError("omega", "the band needs at least two increasing frequencies")
    if not np.all(w > 0):
        raise ParameterError("omega", "the band's frequencies must be positive")
    if forcing.F0 == 0.0 and forcing.X_b == 0.0:
        raise ParameterError(
            "force",
            "a design needs a driving amplitude (F0 or X_b not zero): undriven, the primary "
            "stays at rest and every peak ratio is 0/0",
        )
    multistart = checks.whole_number("multistart", multistart, 0, 1000)
    base = _DesignBase(system, forcing, e, tuple(float(x) for x in w), multistart, response)
    for row in points.values:  # a bad point fails here, in one line, before any run
        _design_system(base, points.names, row)
    executor = _executor(executor, workers, client, scheduler)
    store = None
    if out is not None:
        contact = e.as_dict() if not is_constant(e) else {"e": e}
        motion = {k: v for k, v in forcing.as_dict().items() if k in ("V_b", "A_b", "inertia")}
        settings = {"F0": forcing.F0, "X_b": forcing.X_b, "phase": forcing.phase, **motion,
                    **contact,
                    "omegas": ",".join(f"{x:.17g}" for x in w)}  # fmt: skip
        if multistart != FREQUENCIES:  # (files written with the defaults carry no entry)
            settings["multistart"] = multistart
        if response != "displacement":
            settings["response"] = response
        store = MapStore(out, system=system, points=points, settings=settings, force=force,
                         outputs=DESIGN_OUTPUTS, table=design_table)  # fmt: skip
    try:
        done: dict[int, dict[str, Any]] = {}
        if store is not None:
            done = {int(r["run"]): r for r in store.rows()}
        todo = [i for i in range(len(points)) if i not in done]
        payloads = [(base, points.names, [i], points.values[[i]]) for i in todo]
        workers = workers or os.cpu_count() or 1
        here = executor == "serial" or (executor == "processes" and (workers == 1 or len(todo) < 2))
        payloads = [(replace(base, curve_workers=workers if here else 1), *p[1:])
                    for p in payloads]  # fmt: skip
        bar = _progress(progress, len(points), len(done), "design map")
        counts = _pool.shared_counts() if executor == "processes" else None
        start = _pool.ended_here(_pool.CURVE_RUNS)
        told = [0]

        def curve_runs() -> None:
            """The runs of the map's curves so far, here and on the workers, told."""
            n = _pool.ended_here(_pool.CURVE_RUNS) - start
            n += counts[_pool.CURVE_RUNS] if counts is not None else 0
            if n != told[0]:
                told[0] = n
                bar.note(f"{n} runs of the clearances' curves")
                if runs is not None:
                    runs(n)

        results = _launch(payloads, executor, workers, client, scheduler,
                          workers == 1 or len(todo) < 2, _design_chunk, counts,
                          curve_runs)  # fmt: skip
        with _pool.watching(curve_runs):  # the runs made here (serial, or the first clearance)
            _gather(results, store, done, bar)
        table = design_table([done[i] for i in range(len(points))], points.names)
        if store is not None:
            store.finish(table)
    finally:
        if store is not None:
            store.close()
    return table


def best_clearances(table) -> Any:
    """For each mass ratio (or impact mass) of a design map, the row of the smallest peak: the
    best clearance in the band."""
    by = [c for c in ("mass_ratio", "m") if c in table.columns]
    if not by:
        return table.loc[[table["peak_amplitude"].idxmin()]].reset_index(drop=True)
    idx = table.groupby(by, sort=True)["peak_amplitude"].idxmin()
    return table.loc[idx.to_numpy()].reset_index(drop=True)


#: The best clearance is refined to this [m] by default: 0.01 mm.
TOLERANCE = 1e-5
#: The walk after Brent's method looks these many tolerance steps either side of the clearance.
WALK_STEPS = (1, 2, 3)
#: At most this many moves of the walk (each a step of at most two tolerances).
MAX_WALK = 50


def refine_best(
    table: Any,
    system: ImpactSystem,
    forcing: Forcing,
    e: Any,
    omegas: Any,
    *,
    tolerance: float = TOLERANCE,
    multistart: int = FREQUENCIES,
    response: str = "displacement",
    progress: bool = False,
) -> list[dict[str, Any]]:
    """For each mass ratio (or impact mass) of a design ``table`` (from :func:`design_map` over
    the clearance), the best clearance refined: Brent's bounded method on the peak of
    :func:`design_row` against d, between the grid's neighbours of the grid's best (the grid's
    end where the best lies there), stopped at ``tolerance`` [m] on d.  Each row: the design
    row at the refined d, with ``tolerance``, ``grid_gap`` (the grid's best), ``evaluations``,
    ``walk_moves`` (the moves of the walk after Brent's method, module text) and, for rigid impacts, ``peak_e_minus`` / ``peak_e_plus``: the peak at e − 0.1 and e + 0.1
    (within 0–1) for the refined d; ``multistart`` and ``response`` as for :func:`design_row`.
    With ``progress``, a bar on stderr counts the designs as they are computed, with the time
    taken and the rate (their number is Brent's, not known ahead)."""
    from scipy.optimize import minimize_scalar
    from tqdm import tqdm

    system, forcing, e = checked(system, forcing, e)
    tolerance = checks.bounded("tolerance", tolerance, 0.0, math.inf, open_low=True)
    w = np.asarray(omegas, dtype=float)
    if "gap" not in table.columns:
        raise ParameterError("grid", "refining needs a design map over the clearance (gap)")
    by = [c for c in ("mass_ratio", "m") if c in table.columns]
    groups = [table] if not by else [g for _, g in table.groupby(by, sort=True)]
    out = []
    bar = tqdm(desc="refining the best clearance", unit=" curves", disable=not progress,
               leave=True)  # fmt: skip
    start = _pool.ended_here(_pool.CURVE_RUNS)
    shown = [start]

    def curve_runs() -> None:
        """Each curve's runs beside the count of curves, so that the bar moves within one."""
        now = _pool.ended_here(_pool.CURVE_RUNS)
        if now - shown[0] >= 10:
            shown[0] = now
            bar.set_postfix_str(f"{now - start} runs", refresh=True)

    # the runs of every curve, counted here (_pool.CurveRuns), noted beside the bar
    with _pool.watching(curve_runs if progress else None):
        for g in groups:
            g = g.sort_values("gap")
            gaps = g["gap"].to_numpy(dtype=float)
            i = int(np.argmin(g["peak_amplitude"].to_numpy(dtype=float)))
            first = g.iloc[0]
            base = _design_system(_DesignBase(system, forcing, e, tuple(w)), by,
                                  [float(first[c]) for c in by])  # fmt: skip
            cache: dict[float, dict[str, Any]] = {}

            def row(d: float, sys_=base, cache=cache) -> dict[str, Any]:
                if d not in cache:
                    cache[d] = design_row(sys_.with_(gap=d), forcing, e, w, multistart=multistart,
                                          response=response, progress=_pool.CurveRuns())  # fmt: skip
                    bar.update(1)
                return cache[d]

            lo, hi = gaps[max(i - 1, 0)], gaps[min(i + 1, len(gaps) - 1)]
            best_d = float(gaps[i])
            if hi > lo:
                r = minimize_scalar(lambda d: row(float(d))["peak_amplitude"], bounds=(lo, hi),
                                    method="bounded", options={"xatol": tolerance})  # fmt: skip
                if row(float(r.x))["peak_amplitude"] <= float(g.iloc[i]["peak_amplitude"]):
                    best_d = float(r.x)
            best_d, walked = _walk_down(best_d, tolerance, lambda d: row(d)["peak_amplitude"])
            result = {**{c: float(first[c]) for c in by}, "gap": best_d, **row(best_d)}
            result.update(tolerance=tolerance, grid_gap=float(gaps[i]), evaluations=len(cache),
                          walk_moves=walked)  # fmt: skip
            if is_constant(e):  # (the materials' e has no single value to move)
                for key, de in (("peak_e_minus", -0.1), ("peak_e_plus", 0.1)):
                    ee = min(max(float(e) + de, 0.0), 1.0)
                    result[key] = design_row(base.with_(gap=best_d), forcing, ee, w,
                                             multistart=multistart,
                                             response=response)["peak_amplitude"]  # fmt: skip
                    bar.update(1)
            out.append(result)
    bar.close()
    return out


def _walk_down(d: float, step: float, peak: Callable[[float], float]) -> tuple[float, int]:
    """(d, moves): from the clearance ``d`` [m], move to the clearance of smallest ``peak``
    among those :data:`WALK_STEPS` steps of ``step`` [m] either side (positive ones only) while
    it is smaller than the peak at ``d``; at most :data:`MAX_WALK` moves.  The clearances lie on
    the lattice d + n·step (n whole), so a clearance met again is the same number."""
    n, here = 0, peak(d)
    for moves in range(MAX_WALK):
        near = [n + s * k for k in WALK_STEPS for s in (-1, 1) if d + (n + s * k) * step > 0]
        best = min(near, key=lambda j: peak(d + j * step))
        if peak(d + best * step) >= here:
            return d + n * step, moves
        n, here = best, peak(d + best * step)
    return d + n * step, MAX_WALK


#: Restitution samples of a robust design (ends, middle and the quarters of the range).
E_SAMPLES = 5
#: Tolerance [1] of the worst-case restitution located between samples (Brent's method).
E_TOLERANCE = 0.01


def worst_over(
    es: Any, peaks: Any, peak_at: Callable[[float], float], tolerance: float = E_TOLERANCE
) -> tuple[float, float]:
    """(e, peak) of the largest peak over the range of the samples ``es`` (increasing) with their
    ``peaks``: the largest sample, then Brent's bounded method on ``peak_at`` between its
    neighbours (one side at an end of the range: a peak may rise past the last sample and fall
    before the end), to ``tolerance`` in e; what Brent finds is kept only if larger."""
    from scipy.optimize import minimize_scalar

    es, peaks = np.asarray(es, dtype=float), np.asarray(peaks, dtype=float)
    i = int(np.argmax(peaks))
    best_e, best = float(es[i]), float(peaks[i])
    if len(es) > 1:
        cache: dict[float, float] = {}

        def value(e: float) -> float:
            if e not in cache:
                cache[e] = float(peak_at(e))
            return cache[e]

        bounds = (es[max(i - 1, 0)], es[min(i + 1, len(es) - 1)])
        r = minimize_scalar(lambda e: -value(float(e)), bounds=bounds,
                            method="bounded", options={"xatol": tolerance})  # fmt: skip
        if value(float(r.x)) > best:
            best_e, best = float(r.x), value(float(r.x))
    return best_e, best


def robust_design(
    system: ImpactSystem,
    forcing: Forcing,
    e_range: tuple[float, float],
    omegas: Any,
    gaps: Any,
    *,
    samples: int = E_SAMPLES,
    multistart: int = FREQUENCIES,
    response: str = "displacement",
    **map_options: Any,
) -> dict[str, Any]:
    """A clearance design robust to an uncertain restitution e ∈ ``e_range`` (rigid impacts).

    The design map over ``gaps`` [m] (:func:`design_map`, with ``map_options``: executor,
    workers, …) is run at ``samples`` restitutions spread evenly over the range (its ends and
    middle among them).  Per clearance, the worst case is the largest peak over the range: the
    largest sample, refined between its neighbours by Brent's bounded method (to
    :data:`E_TOLERANCE`; :func:`worst_over`).  Returns ``{"rows": per clearance
    {gap, peaks (one per sample), worst_peak, worst_e, nominal_peak (the middle e),
    baseline_peak}, "e": the samples, "nominal_best": the row of the smallest nominal peak,
    "robust_best": the row of the smallest worst case}`` (SI; best clearances on the grid);
    ``response``: what the peaks measure (:func:`design_row`)."""
    lo, hi = (float(v) for v in e_range)
    if not 0.0 <= lo < hi <= 1.0:
        raise ParameterError("e", f"a range needs 0 ≤ low < high ≤ 1, got {lo:g}:{hi:g}")
    samples = checks.whole_number("samples", samples, 3, 101)
    if samples % 2 == 0:
        raise ParameterError(
            "samples", f"must be odd (the middle of the range is one), got {samples}"
        )
    es = np.linspace(lo, hi, samples)
    es[samples // 2] = 0.5 * (lo + hi)
    w = np.asarray(omegas, dtype=float)
    tables = [design_map(system, forcing, float(e), w, {"gap": gaps}, multistart=multistart,
                         response=response, **map_options) for e in es]  # fmt: skip
    rows = []
    for k in range(len(tables[0])):
        d = float(tables[0]["gap"].iloc[k])
        peaks = np.array([float(t["peak_amplitude"].iloc[k]) for t in tables])
        sys_d = system.with_(gap=d)

        def peak_at(e: float, sys_d=sys_d) -> float:
            return design_row(sys_d, forcing, e, w, multistart=multistart,
                              response=response)["peak_amplitude"]  # fmt: skip

        worst_e, worst = worst_over(es, peaks, peak_at)
        rows.append({
            "gap": d,
            "peaks": [float(p) for p in peaks],
            "worst_peak": worst,
            "worst_e": worst_e,
            "nominal_peak": float(peaks[samples // 2]),
            "baseline_peak": float(tables[0]["baseline_peak"].iloc[k]),
        })  # fmt: skip
    return {
        "e": [float(e) for e in es],
        "rows": rows,
        "nominal_best": min(rows, key=lambda r: r["nominal_peak"]),
        "robust_best": min(rows, key=lambda r: r["worst_peak"]),
    }
