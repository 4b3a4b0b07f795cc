"""Parameter maps: one simulation per point of a grid or of a list of parameter sets, run
serially, on local processes or on a Dask cluster, streamed to a resumable file.

A map point sets some swept inputs (system parameters such as ``gap``, ``m``, ``c1``, the
``mass_ratio`` m/M, or initial conditions such as ``x0``, ``xdot0``, ``t_end``) on a base
:class:`~symimpact.system.ImpactSystem` and runs :func:`~symimpact.simulation.simulate`.  Each
run gives one row of a tidy table:

``run`` (index of the point), the swept inputs [SI], ``n_impacts`` (N_tot), ``n_effective``
(N_eff, Eq. 37), ``effectiveness`` (Eq. 38), ``damping_inclination`` (DI [m], Eq. 36),
``zeta_eq`` (equivalent viscous damping ratio of the envelope of x,
:func:`~symimpact.simulation.equivalent_damping_ratio`), ``energy_initial``,
``energy_dissipated`` (by C and c₁), ``energy_dissipated_contact`` (by c₁ alone),
``energy_residual`` [J] and ``class`` (see :func:`symimpact.sweep.gap_class`).  Undefined
values (effectiveness with no non-effective impact, DI with fewer than four maxima) are
missing (``<NA>``), never NaN.

Every row is computed by the same function in whichever process runs it, and rows are put back
in the order of the points, so the serial, process and Dask executors give identical tables.
"""

from __future__ import annotations

import itertools
import math
import os
import sys
from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from .errors import ParameterError
from .system import ImpactSystem
from .units import SI_UNITS, si_float, split_quantity

INITIAL = ("x0", "xdot0", "y0", "ydot0", "t_end")
SYSTEM_PARAMETERS = ("M", "K", "C", "zeta", "m", "gap", "a", "b", "k_hz", "k1", "c1")
#: Every input a map can sweep: initial conditions, system parameters and the mass ratio m/M.
SWEEPABLE = INITIAL + SYSTEM_PARAMETERS + ("mass_ratio",)
#: Output columns of a map row, in table order (after ``run`` and the swept inputs).
OUTPUTS = (
    "n_impacts",
    "n_effective",
    "effectiveness",
    "damping_inclination",
    "zeta_eq",
    "energy_initial",
    "energy_dissipated",
    "energy_dissipated_contact",
    "energy_residual",
    "class",
)
EXECUTORS = ("serial", "processes", "dask")


@dataclass(frozen=True)
class MapPoints:
    """The points of a map: ``names`` of the swept inputs and ``values`` (n, len(names)) [SI]."""

    names: tuple[str, ...]
    values: np.ndarray

    def __len__(self) -> int:
        return self.values.shape[0]


def _check_names(names: Sequence[str]) -> tuple[str, ...]:
    names = tuple(names)
    if not names:
        raise ParameterError("grid", "sweep at least one input")
    for n in names:
        if not str(n).strip():
            raise ParameterError(
                "grid", f"an input name is empty; choose from {', '.join(SWEEPABLE)}"
            )
        if n not in SWEEPABLE:
            raise ParameterError(n, f"cannot be swept; choose from {', '.join(SWEEPABLE)}")
    if len(set(names)) != len(names):
        dup = next(n for n in names if names.count(n) > 1)
        raise ParameterError(dup, "is swept twice")
    if "m" in names and "mass_ratio" in names:
        raise ParameterError("mass_ratio", "sweep m or mass_ratio, not both")
    if "C" in names and "zeta" in names:
        raise ParameterError("zeta", "sweep C or zeta, not both")
    return names


def _si_values(name: str, values: Iterable[Any]) -> np.ndarray:
    if isinstance(values, str):
        from .sweep import parse_range

        arr = parse_range(name, values)
    else:
        arr = np.array(
            [si_float(name, v, SI_UNITS.get(name)) for v in np.ravel(np.asarray(values, object))]
        )
    if arr.size == 0:
        raise ParameterError(name, "has no values")
    if not np.all(np.isfinite(arr)):
        raise ParameterError(name, "every value must be finite")
    return arr


def grid_points(grid: Mapping[str, Any]) -> MapPoints:
    """The Cartesian product of the swept values (first input varies slowest).

    ``grid`` maps input names to values: a sequence of numbers or quantities, or a range string
    ``"start:stop:step"`` / ``"v1,v2,..."`` (see :func:`symimpact.sweep.parse_range`).
    """
    names = _check_names(list(grid))
    axes = [_si_values(n, grid[n]) for n in names]
    n = math.prod(a.size for a in axes)
    if n > 10_000_000:
        raise ParameterError("grid", f"has {n} points; at most 1e7 per map")
    values = np.array(list(itertools.product(*axes)), dtype=float).reshape(n, len(names))
    return MapPoints(names, values)


def _header_name(cell: str) -> tuple[str, str | None]:
    cell = cell.strip()
    if cell.endswith("]") and "[" in cell:
        name, unit = cell[:-1].split("[", 1)
        return name.strip(), unit.strip()
    return cell, None


def read_sets(path: str | os.PathLike, progress: bool = False) -> MapPoints:
    """Parameter sets from a CSV file: one column per swept input, one row per run.

    A header cell is an input name, optionally with a unit (``gap [mm]``); a cell is a number
    (in the header's unit, else SI) or a quantity with units (``9 mm``), read strictly
    (:func:`symimpact.units.split_quantity`).  A byte-order mark is ignored.  ``progress``: a
    progress bar on standard error for files of more than 10 000 sets (about 30 µs a cell).
    """
    import csv

    p = Path(path)
    try:
        text = p.read_text(encoding="utf-8-sig")  # a byte-order mark (Excel's CSV) is not a cell
    except OSError as exc:
        raise ParameterError("sets", f"cannot read {str(p)!r}: {exc.strerror}") from None
    except UnicodeDecodeError:
        raise ParameterError("sets", f"{str(p)!r} is not a text (CSV) file") from None
    rows = [r for r in csv.reader(text.splitlines()) if any(c.strip() for c in r)]
    if len(rows) < 2:
        raise ParameterError("sets", f"{str(p)!r} needs a header row and at least one set")
    header = [_header_name(c) for c in rows[0]]
    names = _check_names([n for n, _ in header])
    values = np.empty((len(rows) - 1, len(names)))
    lines: Iterable = enumerate(rows[1:], start=2)
    if progress and len(rows) > 10_001:
        from tqdm import tqdm

        lines = tqdm(lines, total=len(rows) - 1, desc="reading sets", unit="set", file=sys.stderr)
    for i, row in lines:
        if len(row) != len(names):
            raise ParameterError("sets", f"line {i} has {len(row)} cells, the header {len(names)}")
        for j, ((name, unit), cell) in enumerate(zip(header, row, strict=True)):
            cell = cell.strip()
            try:
                # read strictly (units.split_quantity); a cell without a unit takes the header's
                _, own_unit = split_quantity(name, cell)
                q: Any = cell if own_unit or not unit else f"{cell} {unit}"
                values[i - 2, j] = si_float(name, q, SI_UNITS.get(name))
            except ParameterError as exc:
                raise ParameterError(name, f"line {i} of {str(p)!r}: {exc.reason}") from None
    if not np.all(np.isfinite(values)):
        raise ParameterError("sets", "every value must be finite")
    return MapPoints(names, values)


def as_points(grid: Any = None, sets: Any = None) -> MapPoints:
    """Map points from a grid (mapping of swept values), or from parameter sets (a CSV path, a
    sequence of mappings, or :class:`MapPoints`)."""
    if (grid is None) == (sets is None):
        raise ParameterError("grid", "give either a grid of swept values or parameter sets")
    if grid is not None:
        return grid_points(grid)
    if isinstance(sets, MapPoints):
        _check_names(sets.names)
        return sets
    if isinstance(sets, str | os.PathLike):
        return read_sets(sets)
    sets = list(sets)
    if not sets:
        raise ParameterError("sets", "has no parameter sets")
    names = _check_names(list(sets[0]))
    for i, s in enumerate(sets):
        if set(s) != set(names):
            raise ParameterError("sets", f"set {i} has inputs {sorted(s)}, set 0 {sorted(names)}")
    values = np.array([[si_float(n, s[n], SI_UNITS.get(n)) for n in names] for s in sets])
    if not np.all(np.isfinite(values)):
        raise ParameterError("sets", "every value must be finite")
    return MapPoints(names, values)


# --- one run ---------------------------------------------------------------------------------------
@dataclass(frozen=True)
class _Base:
    system: ImpactSystem
    initial: tuple[tuple[str, float], ...]
    contact: str | None


def _point_system(base: _Base, names: tuple[str, ...], values: Sequence[float]):
    initial = dict(base.initial)
    changes: dict[str, float] = {}
    ratio = None
    for n, v in zip(names, values, strict=True):
        if n in INITIAL:
            initial[n] = float(v)
        elif n == "mass_ratio":
            ratio = float(v)
        else:
            changes[n] = float(v)
    if ratio is not None:
        if not ratio > 0:
            raise ParameterError("mass_ratio", f"must be positive, got {ratio:g}")
        changes["m"] = ratio * changes.get("M", base.system.M)
    system = base.system.with_(**changes) if changes else base.system
    return system, initial


def run_point(base: _Base, names: tuple[str, ...], values: Sequence[float]) -> dict[str, Any]:
    """The table row (without ``run``) of one map point."""
    from .simulation import simulate
    from .sweep import gap_class

    system, initial = _point_system(base, names, values)
    res = simulate(system, contact=base.contact, **initial)
    e = res.energy
    row: dict[str, Any] = dict(zip(names, (float(v) for v in values), strict=True))
    row.update(
        n_impacts=res.n_impacts,
        n_effective=res.n_effective,
        effectiveness=res.effectiveness,
        damping_inclination=res.damping_inclination,
        zeta_eq=res.zeta_eq,
        energy_initial=e["initial"],
        energy_dissipated=e["dissipated_C"] + e["dissipated_c1"],
        energy_dissipated_contact=e["dissipated_c1"],
        energy_residual=e["residual"],
    )
    row["class"] = gap_class(res.n_impacts, res.n_effective)
    return row


def _run_chunk(payload: tuple[_Base, tuple[str, ...], list[int], np.ndarray]):
    base, names, runs, values = payload
    rows = []
    for run, vals in zip(runs, values, strict=True):
        row = {"run": int(run)}
        row.update(run_point(base, names, vals))
        rows.append(row)
    return rows


# --- executors -------------------------------------------------------------------------------------
def _serial(payloads: list) -> Iterator[list[dict[str, Any]]]:
    for p in payloads:
        yield _run_chunk(p)


def _worker_init(parent: int) -> None:
    """Pool workers end with the map that started them: on Linux the kernel sends SIGTERM when
    the parent dies (prctl PR_SET_PDEATHSIG), whatever killed it; Ctrl-C is left to the parent,
    which then ends the pool."""
    import signal

    signal.signal(signal.SIGINT, signal.SIG_IGN)
    for sig in (signal.SIGTERM, signal.SIGHUP):  # not the handlers a forked worker inherits
        signal.signal(sig, signal.SIG_DFL)
    if sys.platform.startswith("linux"):
        import ctypes

        ctypes.CDLL(None, use_errno=True).prctl(1, int(signal.SIGTERM))  # PR_SET_PDEATHSIG
    if os.getppid() != parent:  # the parent died before the line above took effect
        os._exit(1)


def _processes(payloads: list, workers: int) -> Iterator[list[dict[str, Any]]]:
    from concurrent.futures import ProcessPoolExecutor, as_completed

    pool = ProcessPoolExecutor(
        max_workers=workers, initializer=_worker_init, initargs=(os.getpid(),)
    )
    finished = False
    try:
        futures = [pool.submit(_run_chunk, p) for p in payloads]
        for f in as_completed(futures):
            yield f.result()
        finished = True
    finally:
        if not finished:  # interrupted, terminated or failed: do not wait for running chunks
            for proc in list((getattr(pool, "_processes", None) or {}).values()):
                proc.terminate()
        pool.shutdown(wait=True, cancel_futures=True)


#: How long a Dask map waits with no worker before it gives up (all workers lost), and how
#: long it waits to connect to a scheduler.
DASK_NO_WORKER_TIMEOUT = 60.0
DASK_CONNECT_TIMEOUT = 10.0


def _scheduler_address(scheduler: str) -> tuple[str, str, int]:
    """(protocol, host, port) of ``tcp://HOST:PORT`` or ``tls://HOST:PORT`` (``HOST:PORT`` is
    taken as tcp); anything else is refused naming ``scheduler``."""
    import re

    m = re.fullmatch(r"(?:(tcp|tls)://)?(\[[0-9A-Fa-f:.]+\]|[A-Za-z0-9_.-]+):(\d{1,5})", scheduler)
    if m is None or not 0 < int(m[3]) < 65536:
        raise ParameterError(
            "scheduler", f"{scheduler!r} is not a scheduler address like tcp://10.0.0.5:8786"
        )
    return m[1] or "tcp", m[2].strip("[]"), int(m[3])


def _connect(scheduler: str) -> Any:
    """A ``distributed.Client`` of the scheduler at ``scheduler``, or one line saying why not."""
    import socket

    from distributed import Client

    protocol, host, port = _scheduler_address(scheduler)
    try:  # say "refused" at once rather than a time-out 20 s later
        socket.create_connection((host, port), timeout=DASK_CONNECT_TIMEOUT).close()
    except ConnectionRefusedError:
        raise ParameterError(
            "scheduler", f"nothing listens at {host}:{port} (connection refused)"
        ) from None
    except TimeoutError:
        raise ParameterError(
            "scheduler", f"{host}:{port} did not answer within {DASK_CONNECT_TIMEOUT:g} s"
        ) from None
    except OSError as exc:
        raise ParameterError(
            "scheduler", f"cannot reach {host}:{port}: {exc.strerror or exc}"
        ) from None
    try:
        return Client(f"{protocol}://{host}:{port}", timeout=f"{DASK_CONNECT_TIMEOUT:g}s")
    except Exception as exc:  # distributed raises assorted types (OSError, TimeoutError, ...)
        raise ParameterError(
            "scheduler",
            f"{scheduler!r} is not a Dask scheduler that answers ({type(exc).__name__})",
        ) from None


class DaskLost(OSError):
    """The Dask scheduler or every worker was lost during a map (a fault, not bad input)."""


def _dask(payloads: list, client: Any, scheduler: str | None) -> Iterator[list[dict[str, Any]]]:
    import time

    try:
        from distributed import Client, LocalCluster, as_completed
    except ImportError:  # pragma: no cover - distributed is a dependency
        raise ParameterError("executor", "dask needs the 'distributed' package") from None
    cluster = None
    own = client is None
    if own and scheduler is None:
        # a local cluster: on the loopback interface only, no dashboard
        cluster = LocalCluster(
            host="127.0.0.1", dashboard_address=None, threads_per_worker=1, processes=True
        )
        client = Client(cluster)
    elif own:
        client = _connect(scheduler)
    try:
        futures = client.map(_run_chunk, payloads, pure=False)
        pending = as_completed(futures)
        alone_since = None
        try:
            while not pending.is_empty():
                batch = pending.next_batch(block=False)
                for f in batch:
                    try:
                        yield f.result()
                    except ParameterError:
                        raise
                    except Exception as exc:
                        raise DaskLost(
                            f"the Dask map failed: {type(exc).__name__}: {exc}"
                        ) from None
                if batch:
                    continue
                if client.status != "running":
                    raise DaskLost("the Dask scheduler was lost during the map")
                try:
                    workers = len(client.scheduler_info()["workers"])
                except Exception:
                    raise DaskLost("the Dask scheduler was lost during the map") from None
                now = time.monotonic()
                alone_since = None if workers else (alone_since or now)
                if alone_since is not None and now - alone_since > DASK_NO_WORKER_TIMEOUT:
                    raise DaskLost(
                        f"no Dask worker for {DASK_NO_WORKER_TIMEOUT:g} s: every worker was lost"
                    )
                time.sleep(0.05)
        finally:
            try:
                client.cancel(futures)
            except Exception:  # a lost scheduler: nothing left to cancel
                pass
    finally:
        if own:
            try:
                client.close()
            finally:
                if cluster is not None:
                    cluster.close()


def _chunks(todo: np.ndarray, size: int) -> list[np.ndarray]:
    return [todo[i : i + size] for i in range(0, todo.size, size)]


def _progress(progress: bool | Callable[[int, int], None], total: int, done: int, desc: str):
    if callable(progress):
        count = [done]

        def update(n: int | None) -> None:
            if n:
                count[0] += n
                progress(count[0], total)

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
    :func:`symimpact.sweep.sweep`; see :func:`parameter_map` for the arguments)."""
    if not isinstance(system, ImpactSystem):
        raise ParameterError("system", "must be an ImpactSystem")
    initial = tuple(
        (n, si_float(n, v, SI_UNITS[n]))
        for n, v in (("x0", x0), ("xdot0", xdot0), ("y0", y0), ("ydot0", ydot0), ("t_end", t_end))
    )
    base = _Base(system, initial, contact)
    if client is not None or scheduler is not None:
        if executor not in (None, "dask"):
            raise ParameterError("executor", f"{executor!r} cannot use a Dask client or scheduler")
        executor = "dask"
    executor = executor or "processes"
    if executor not in EXECUTORS:
        raise ParameterError("executor", f"must be one of {', '.join(EXECUTORS)}")
    if workers is not None and (not isinstance(workers, int) or workers < 1):
        raise ParameterError("workers", "must be a positive integer")
    if chunk_size is not None and (not isinstance(chunk_size, int) or chunk_size < 1):
        raise ParameterError("chunk_size", "must be a positive integer")
    _validate(base, points)
    n = len(points)
    done: dict[int, dict[str, Any]] = {}
    if store is not None:
        done = {int(r["run"]): r for r in store.rows()}
    todo = np.array([i for i in range(n) if i not in done], dtype=int)
    workers = workers or os.cpu_count() or 1
    size = chunk_size or int(min(256, max(1, math.ceil(todo.size / (8 * workers)))))
    payloads = [(base, points.names, list(c), points.values[c]) for c in _chunks(todo, size)]
    if todo.size:
        # the first point runs here: a bad system fails before any worker starts (and numba
        # compiles or loads its cache once in this process)
        run_point(base, points.names, points.values[todo[0]])
    if executor == "serial" or (
        executor == "processes" and (workers == 1 or len(payloads) < 2 or todo.size < 8)
    ):
        results = _serial(payloads)
    elif executor == "processes":
        results = _processes(payloads, min(workers, len(payloads)))
    else:
        results = _dask(payloads, client, scheduler)
    bar = _progress(progress, n, len(done), desc)
    try:
        for rows in results:
            if store is not None:
                store.write_chunk(rows)
            for r in rows:
                done[r["run"]] = r
            bar(len(rows))
    finally:
        bar(None)
    return [done[i] for i in range(n)]


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
    system : the base :class:`~symimpact.system.ImpactSystem`; each point changes the inputs it
        sweeps.
    grid : ``{name: values}``: the Cartesian product is run (first input varies slowest); values
        are sequences of numbers or quantities, or range strings ``"6 mm:35 mm:1 mm"``.
    sets : instead of ``grid``: explicit parameter sets, a CSV path (:func:`read_sets`) or a
        sequence of ``{name: value}``.
    x0, xdot0, y0, ydot0 : initial state [m, m/s]; t_end : end time [s] (unless swept).
    contact : contact path of :func:`~symimpact.simulation.simulate` (default the system's law).
    executor : ``"serial"``, ``"processes"`` (default: ``workers`` local processes, all cores)
        or ``"dask"`` (with ``client``, a ``distributed.Client``, or ``scheduler``, the address
        of a running Dask scheduler such as ``"tcp://10.0.0.5:8786"``).
    out : stream the rows to this ``.csv`` or ``.parquet`` file.  Chunks are saved as they finish
        in the hidden folder ``.<name>.partial`` beside it; the table is written to ``out``
        (atomically) when the map is complete.  Calling again with the same inputs after an
        interruption computes only the missing points.  An existing ``out`` is replaced only
        with ``force``.
    chunk_size : points per task (default: about eight tasks per worker, at most 256 points).
    progress : a progress bar with rate and ETA on standard error (False: none; a callable
        ``f(done, total)`` is called instead).

    Every executor returns the same rows, the same numbers, in the same order.
    """
    points = as_points(grid, sets)
    store = None
    if out is not None:
        from .mapfiles import MapStore

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


def table_rows(table) -> list[dict[str, Any]]:
    """A map table (or any DataFrame) as a list of row dicts, missing values as None."""
    import pandas as pd

    return table.astype(object).where(pd.notna(table), None).to_dict("records")


def tidy_table(rows: list[dict[str, Any]], names: Sequence[str]):
    """Rows as a DataFrame with fixed column order and dtypes (missing values as ``<NA>``)."""
    import pandas as pd

    columns = ["run", *names, *OUTPUTS]
    df = pd.DataFrame.from_records(rows, columns=columns)
    df["run"] = df["run"].astype("int64")
    for n in names:
        df[n] = df[n].astype("float64")
    for c in ("n_impacts", "n_effective"):
        df[c] = df[c].astype("int64")
    for c in OUTPUTS[2:-1]:
        df[c] = pd.array(
            [None if v is None or (isinstance(v, float) and math.isnan(v)) else v for v in df[c]],
            dtype="Float64",
        )
    df["class"] = df["class"].astype("string")
    return df.sort_values("run", kind="stable").reset_index(drop=True)
