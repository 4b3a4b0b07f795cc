"""A structure's response curve with its runs from rest spread over local processes or a Dask
cluster (:func:`structure_curve_map`).

Nearly all of a curve's time is its runs from rest, one at each frequency of the band
(:func:`symimpact.forced.orbits.structure_branch.settled_run`), and they are independent: they run on
the map engine's executors, and the branches are then continued from the band's ends in this
process (:func:`symimpact.forced.orbits.structure_branch.structure_curve`), as without the map.  Each
run is the same computation wherever it runs, so the curve is the same to the bit."""

from __future__ import annotations

import os
from typing import Any

from .._progress import Stages
from ..forced.orbits.structure_branch import (
    StructureCurve,
    curve_grid,
    settled_run,
    structure_curve,
)
from ..model.checks import whole_number
from .engine import _executor, _launch


def _settled_chunk(payload: tuple) -> list[tuple[dict[str, Any], Any]]:
    """The runs from rest of one chunk of frequencies (module level, so that a worker process or
    a Dask worker can unpickle it)."""
    args, stops, warmup, base, omegas = payload
    return [settled_run(*args, float(w), stops, warmup, base) for w in omegas]


def structure_curve_map(structure: Any, dampers: Any, force_at: Any, F0: Any, omega_low: float,
                        omega_high: float, step: float, stops: Any = (), warmup: Any = None,
                        base: Any = 0.0, *, executor: str | None = None, workers: Any = None,
                        client: Any = None, scheduler: str | None = None,
                        progress: Any = None) -> StructureCurve:  # fmt: skip
    """:func:`symimpact.forced.orbits.structure_branch.structure_curve` (the same arguments, SI) with
    its runs from rest on ``executor``: "serial", "processes" (the default, ``workers`` of
    them, default the machine's CPUs) or "dask" (``client``, ``scheduler``, or a local
    cluster).  Neighbouring frequencies cost alike (a chattering band is slow), so each chunk
    takes every n-th frequency of the grid.  ``progress`` (:class:`symimpact._progress.Stages`:
    True a bar on stderr, or a callable): the runs from rest counted as their chunks end, then
    the continuation of the branches as one stage."""
    executor = _executor(executor, workers, client, scheduler)
    workers = workers or os.cpu_count() or 1
    grid = curve_grid(omega_low, omega_high, step)
    if warmup is not None:
        warmup = whole_number("warmup", warmup, 0)
    args = (structure, dampers, force_at, F0)
    n_chunks = min(len(grid), 4 * workers)
    payloads = [(args, stops, warmup, base, grid[i::n_chunks]) for i in range(n_chunks)]
    here = workers == 1 or len(grid) < 2
    done: dict[float, tuple] = {}
    with Stages(progress, "frf") as stages:
        stages.stage("runs from rest", len(grid), unit="Ω")
        for rows in _launch(payloads, executor, workers, client, scheduler, here, _settled_chunk):
            for entry, final in rows:
                done[entry["omega"]] = (entry, final)
            stages.advance(len(rows))
        runs = [done[float(w)] for w in grid]
        stages.stage("branches", None, unit="branch")
        curve = structure_curve(structure, dampers, force_at, F0, omega_low, omega_high, step,
                                stops, warmup, base, runs=runs)  # fmt: skip
        stages.advance(len(curve.branches))  # (counted when the continuation has ended)
        return curve
