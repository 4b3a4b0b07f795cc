"""Parameter maps: one simulation per point of a grid or of a list of parameter sets, run
serially, on local processes or on a Dask cluster, streamed to a resumable file.

A map point sets some swept inputs (system parameters such as ``gap``, ``m``, ``c1``, the
``mass_ratio`` m/M, or initial conditions such as ``x0``, ``xdot0``, ``t_end``) on a base
:class:`~symimpact.model.system.ImpactSystem` and runs :func:`~symimpact.free.simulation.simulate`.  Each
run gives one row of a tidy table:

``run`` (index of the point), the swept inputs [SI], ``n_impacts`` (N_tot), ``n_effective``
(N_eff, Eq. 37), ``effectiveness`` (Eq. 38), ``damping_inclination`` (DI [m], Eq. 36),
``zeta_eq`` (equivalent viscous damping ratio of the envelope of x,
:func:`~symimpact.free.simulation.equivalent_damping_ratio`), ``energy_initial``,
``energy_dissipated`` (by C and c₁), ``energy_dissipated_contact`` (by c₁ alone),
``energy_residual`` [J] and ``class`` (see :func:`symimpact.maps.gap_class`).  Undefined
values (effectiveness with no non-effective impact, DI with fewer than four maxima) are
missing (``<NA>``), never NaN.

Every row is computed by the same function in whichever process runs it, and rows are put back
in the order of the points, so the serial, process and Dask executors give identical tables.
"""

from __future__ import annotations

import math
import os
import time
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np

from ..errors import ParameterError
from ..model.system import ImpactSystem
from ..model.units import SI_UNITS, si_float
from .executors import EXECUTORS, _dask, _processes, _serial
from .points import MapPoints, as_points
from .runs import _Base, _check_points, _point_system, run_point
from .store import MapStore
from .table import tidy_table

#: Most points in one task by default: a chunk runs in one compiled loop (about 0.1–10 ms a
#: point), so a 10⁶-run map makes a few hundred chunk files and tasks, not tens of thousands.
MAX_CHUNK = 4096


def _chunks(todo: np.ndarray, size: int) -> list[np.ndarray]:
    return [todo[i : i + size] for i in range(0, todo.size, size)]


def _progress(progress: bool | Callable[[int, int], None], total: int, done: int, desc: str):
    if callable(progress):
        count = [done]

        def update(n: int | None) -> None:
            if n:
                count[0] += n
                progress(count[0], total)

        update.note = lambda text: None  # type: ignore[attr-defined]
        return update
    from tqdm import tqdm

    bar = tqdm(
        total=total,
        initial=done,
        unit="run",
        desc=desc,
        leave=True,  # the last line stays: runs done, time taken, rate
        disable=not progress,
        smoothing=0.05,
    )

    def update(n: int | None) -> None:
        if n is None:  # tqdm draws at most every 0.1 s: draw the final count before closing
            bar.refresh()
            bar.close()
        else:
            bar.update(n)

    last = [0.0]

    def note(text: str) -> None:
        """``text`` beside the count (what moves between two points), drawn at most twice a
        second."""
        bar.set_postfix_str(text, refresh=False)
        if time.monotonic() - last[0] >= 0.5:
            last[0] = time.monotonic()
            bar.refresh()

    update.note = note  # type: ignore[attr-defined]
    return update


def map_rows(
    system: ImpactSystem,
    points: MapPoints,
    *,
    x0: Any = 0.0,
    xdot0: Any = 0.0,
    y0: Any = 0.0,
    ydot0: Any = 0.0,
    t_end: Any = 1.0,
    contact: str | None = None,
    executor: str | None = None,
    workers: int | None = None,
    client: Any = None,
    scheduler: str | None = None,
    store: Any = None,
    chunk_size: int | None = None,
    progress: bool | Callable[[int, int], None] = True,
    desc: str = "map",
) -> list[dict[str, Any]]:
    """The rows of a map, in the order of ``points`` (the engine of :func:`parameter_map` and
    :func:`symimpact.maps.sweep`; see :func:`parameter_map` for the arguments)."""
    if not isinstance(system, ImpactSystem):
        raise ParameterError("system", "must be an ImpactSystem")
    initial = tuple(
        (n, si_float(n, v, SI_UNITS[n]))
        for n, v in (("x0", x0), ("xdot0", xdot0), ("y0", y0), ("ydot0", ydot0), ("t_end", t_end))
    )
    base = _Base(system, initial, contact)
    executor = _executor(executor, workers, client, scheduler)
    if chunk_size is not None and (not isinstance(chunk_size, int) or chunk_size < 1):
        raise ParameterError("chunk_size", "must be a positive integer")
    _validate(base, points)
    n = len(points)
    done: dict[int, dict[str, Any]] = {}
    if store is not None:
        done = {int(r["run"]): r for r in store.rows()}
    todo = np.array([i for i in range(n) if i not in done], dtype=int)
    workers = workers or os.cpu_count() or 1
    size = chunk_size or int(min(MAX_CHUNK, max(1, math.ceil(todo.size / (8 * workers)))))
    payloads = [(base, points.names, list(c), points.values[c]) for c in _chunks(todo, size)]
    if todo.size:
        # the first point runs here: a bad system fails before any worker starts (and numba
        # compiles or loads its cache once in this process)
        run_point(base, points.names, points.values[todo[0]])
        _check_points(base, points.names, points.values[todo])
    here = workers == 1 or len(payloads) < 2 or todo.size < 8
    results = _launch(payloads, executor, workers, client, scheduler, here)
    _gather(results, store, done, _progress(progress, n, len(done), desc))
    return [done[i] for i in range(n)]


def _executor(executor: str | None, workers: Any, client: Any, scheduler: str | None) -> str:
    """The executor a map runs on (a client or scheduler means Dask; default local processes),
    after the checks every map shares, each refusal one line."""
    if executor is not None and not isinstance(executor, str):
        raise ParameterError("executor", f"must be one of {', '.join(EXECUTORS)}")
    if client is not None or scheduler is not None:
        if executor not in (None, "dask"):
            raise ParameterError("executor", f"{executor!r} cannot use a Dask client or scheduler")
        executor = "dask"
    executor = executor or "processes"
    if executor not in EXECUTORS:
        raise ParameterError("executor", f"must be one of {', '.join(EXECUTORS)}")
    if workers is not None and (not isinstance(workers, int) or workers < 1):
        raise ParameterError("workers", "must be a positive integer")
    return executor


def _launch(payloads: list, executor: str, workers: int, client: Any, scheduler: str | None,
            here: bool, chunk: Callable | None = None, counts: Any = None,
            on_wait: Callable[[], None] | None = None):  # fmt: skip
    """The chunks' rows as they finish, from ``executor`` (``here``: too little work for a
    process pool, run in this process); ``chunk`` turns a payload into rows (default a map's);
    on local processes, ``counts`` and ``on_wait`` as for :func:`symimpact._pool.spread`."""
    if executor == "serial" or (executor == "processes" and here):
        return _serial(payloads, chunk)
    if executor == "processes":
        return _processes(payloads, min(workers, len(payloads)), chunk, counts, on_wait)
    return _dask(payloads, client, scheduler, chunk)


def _gather(results, store: Any, done: dict[int, dict[str, Any]], bar) -> None:
    """Each finished chunk's rows into ``done`` by run (and into ``store``), the bar advanced."""
    try:
        for rows in results:
            if store is not None:
                store.write_chunk(rows)
            for r in rows:
                done[r["run"]] = r
            bar(len(rows))
    finally:
        bar(None)


def _validate(base: _Base, points: MapPoints) -> None:
    """Every swept value on its own against the base system (names the bad input early)."""
    for j, name in enumerate(points.names):
        for v in np.unique(points.values[:, j]):
            _point_system(base, (name,), (v,))
            if name == "t_end" and not v > 0:
                raise ParameterError("t_end", f"must be positive, got {v:g}")


def parameter_map(
    system: ImpactSystem,
    grid: Mapping[str, Any] | None = None,
    *,
    sets: Any = None,
    x0: Any = 0.0,
    xdot0: Any = 0.0,
    y0: Any = 0.0,
    ydot0: Any = 0.0,
    t_end: Any = 1.0,
    contact: str | None = None,
    executor: str | None = None,
    workers: int | None = None,
    client: Any = None,
    scheduler: str | None = None,
    out: str | os.PathLike | None = None,
    force: bool = False,
    chunk_size: int | None = None,
    progress: bool | Callable[[int, int], None] = True,
):
    """A tidy table (pandas DataFrame) with one row per map point: inputs, N_tot, N_eff,
    effectiveness (Eq. 38), DI (Eq. 36), ζ_eq, energies [J] and class (module text).

    Parameters
    ----------
    system : the base :class:`~symimpact.model.system.ImpactSystem`; each point changes the inputs it
        sweeps.
    grid : ``{name: values}``: the Cartesian product is run (first input varies slowest); values
        are sequences of numbers or quantities, or range strings ``"6 mm:35 mm:1 mm"``.
    sets : instead of ``grid``: explicit parameter sets, a CSV path (:func:`read_sets`) or a
        sequence of ``{name: value}``.
    x0, xdot0, y0, ydot0 : initial state [m, m/s]; t_end : end time [s] (unless swept).
    contact : contact path of :func:`~symimpact.free.simulation.simulate` (default the system's law).
    executor : ``"serial"``, ``"processes"`` (default: ``workers`` local processes, all cores)
        or ``"dask"`` (with ``client``, a ``distributed.Client``, or ``scheduler``, the address
        of a running Dask scheduler such as ``"tcp://10.0.0.5:8786"``).
    out : stream the rows to this ``.csv`` or ``.parquet`` file.  Chunks are saved as they finish
        in the hidden folder ``.<name>.partial`` beside it; the table is written to ``out``
        (atomically) when the map is complete.  Calling again with the same inputs after an
        interruption computes only the missing points.  An existing ``out`` is replaced only
        with ``force``.
    chunk_size : points per task (default: about eight tasks per worker, at most 4096 points).
    progress : a progress bar with rate and ETA on standard error (False: none; a callable
        ``f(done, total)`` is called instead).

    Every executor returns the same rows, the same numbers, in the same order.
    """
    points = as_points(grid, sets)
    store = None
    if out is not None:
        store = MapStore(
            out,
            system=system,
            points=points,
            settings={
                "x0": x0,
                "xdot0": xdot0,
                "y0": y0,
                "ydot0": ydot0,
                "t_end": t_end,
                "contact": contact,
            },
            force=force,
        )
    try:
        rows = map_rows(
            system,
            points,
            x0=x0,
            xdot0=xdot0,
            y0=y0,
            ydot0=ydot0,
            t_end=t_end,
            contact=contact,
            executor=executor,
            workers=workers,
            client=client,
            scheduler=scheduler,
            store=store,
            chunk_size=chunk_size,
            progress=progress,
        )
        table = tidy_table(rows, points.names)
        if store is not None:
            store.finish(table)
    finally:
        if store is not None:
            store.close()
    return table
