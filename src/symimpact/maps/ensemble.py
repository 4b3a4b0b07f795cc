"""Ensembles of random-vibration realisations on the map engine: each realisation is one run of a
map (its index the run's only input), so an ensemble runs serially, on local processes or on a
Dask cluster, and resumes from its output file like any map (:class:`.store.MapStore`).

A realisation's record depends only on the ensemble's seed and its index
(:func:`symimpact.forced.loads.random_response.realisation_seed`): the same seed gives the same rows on
any executor and any number of workers.  A row holds the realisation's RMS values with the damper
and without it (the primary alone on the same record) and its number of impacts; the ensemble's
statistics (means, 95 % intervals, the paired reduction) are :func:`.random_response.combine` of
the rows.  The PSD is not kept per realisation (use
:func:`symimpact.forced.loads.random_response.random_statistics` for it).
"""

from __future__ import annotations

import os
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..errors import ParameterError
from ..forced.contact_law import contact_setting, restitution_or_law
from ..forced.loads.random_response import (
    KEYS,
    MAX_REALISATIONS,
    RandomStatistics,
    combine,
    default_settle,
    realisation,
)
from ..forced.simulation import CHATTER
from ..model import checks
from ..model.system import ImpactSystem
from ..model.units import positive_float
from .engine import _executor, _gather, _launch, _progress
from .points import MapPoints
from .runs import _first_point
from .store import MapStore

#: A row's output columns (after ``run`` and ``realisation``).
ENSEMBLE_OUTPUTS = (*(f"rms_{k}" for k in KEYS), *(f"baseline_rms_{k}" for k in KEYS), "impacts")


@dataclass(frozen=True)
class _EnsembleBase:
    system: ImpactSystem
    psd: Any  # a constant, a table (f, S) or a picklable callable (e.g. loads.KanaiTajimi)
    band: tuple[float, float]
    duration: float
    dt: float
    seed: int
    e: Any  # a restitution, or a CompliantContact
    settle: float
    kind: str
    chatter: float
    participation: float = 1.0


def _psd(base: _EnsembleBase) -> float | Callable[[np.ndarray], np.ndarray]:
    if callable(base.psd):
        return base.psd
    if isinstance(base.psd, tuple):
        f, s = (np.array(a) for a in base.psd)
        return lambda x: np.interp(x, f, s, left=0.0, right=0.0)
    return base.psd


def _ensemble_chunk(payload: tuple[_EnsembleBase, tuple[str, ...], list[int], np.ndarray]):
    """The rows of one chunk of an ensemble (what every executor runs)."""
    base, _, runs, _ = payload
    rows = []
    for run in runs:
        r = realisation(base.system, _psd(base), base.band, base.duration, base.dt, base.seed,
                        int(run), e=base.e, settle=base.settle, kind=base.kind, welch=False,
                        chatter=base.chatter, participation=base.participation)  # fmt: skip
        row: dict[str, Any] = {"run": int(run), "realisation": float(run)}
        row.update({f"rms_{k}": r["rms"][k] for k in KEYS})
        row.update({f"baseline_rms_{k}": r["baseline"][k] for k in KEYS})
        row["impacts"] = r["impacts"]
        rows.append(row)
    return rows


_ensemble_chunk.warm_payload = _first_point  # type: ignore[attr-defined]


def ensemble_table(rows: list[dict[str, Any]], names: Any = ("realisation",)) -> Any:
    """Ensemble rows as a DataFrame, in run order, with fixed columns and dtypes."""
    import pandas as pd

    df = pd.DataFrame.from_records(rows, columns=["run", "realisation", *ENSEMBLE_OUTPUTS])
    df["run"] = df["run"].astype("int64")
    df["impacts"] = df["impacts"].astype("int64")
    for c in ("realisation", *ENSEMBLE_OUTPUTS[:-1]):
        df[c] = df[c].astype("float64")
    return df.sort_values("run", kind="stable").reset_index(drop=True)


def random_ensemble(
    system: ImpactSystem,
    psd: Any,
    band: tuple[Any, Any],
    duration: Any,
    dt: Any,
    *,
    e: Any,
    realisations: Any,
    seed: Any = 0,
    settle: Any = None,
    kind: str = "force",
    chatter: Any = CHATTER,
    participation: Any = 1.0,
    executor: str | None = None,
    workers: int | None = None,
    client: Any = None,
    scheduler: str | None = None,
    out: str | os.PathLike | None = None,
    force: bool = False,
    progress: bool | Callable[[int, int], None] = False,
) -> tuple[RandomStatistics, Any]:
    """(statistics, table of rows) of ``realisations`` random-vibration runs as a map (module
    text); ``psd`` a constant one-sided PSD [N²/Hz or (m/s²)²/Hz], a table (frequencies [Hz],
    values) or a picklable function of frequency (:class:`~symimpact.forced.loads.records.KanaiTajimi`),
    the other arguments as :func:`symimpact.forced.loads.random_response.random_statistics`;
    ``executor``, ``workers``, ``client``, ``scheduler``, ``out`` and ``force`` as for
    :func:`symimpact.maps.parameter_map` (``out``: a resumable CSV or Parquet file)."""
    checks.instance("system", system, ImpactSystem, "an ImpactSystem")
    n = checks.whole_number("realisations", realisations, 1, MAX_REALISATIONS)
    seed = checks.whole_number("seed", seed, 0, 2**63 - 1)
    e = restitution_or_law(e)
    T = positive_float("duration", duration, "s")
    dt = positive_float("dt", dt, "s")
    settle = (
        default_settle(system)
        if settle is None
        else checks.bounded("settle", settle, 0.0, unit="s")
    )
    lo, hi = checks.bounds("band", band, "Hz")
    if isinstance(psd, tuple | list) and len(psd) == 2:
        f, s = (tuple(float(v) for v in checks.numbers("psd", a)) for a in psd)
        if len(f) != len(s) or len(f) < 2 or np.any(np.diff(f) <= 0) or min(s) < 0:
            raise ParameterError("psd", "a table needs increasing frequencies and values ≥ 0")
        table_psd: Any = (f, s)
    elif callable(psd):
        table_psd = psd  # run in the workers as it is: it must pickle (a module-level class)
    else:
        table_psd = checks.bounded("psd", psd, 0.0)
    base = _EnsembleBase(system, table_psd, (lo, hi), T, dt, seed, e, settle, kind,
                         checks.bounded("chatter", chatter, 0.0),
                         checks.bounded("participation", participation))  # fmt: skip
    # the first realisation here: bad input fails in one line before any worker starts
    first = _ensemble_chunk((base, ("realisation",), [0], np.zeros((1, 1))))
    points = MapPoints(("realisation",), np.arange(n, dtype=float).reshape(-1, 1))
    executor = _executor(executor, workers, client, scheduler)
    store = None
    if out is not None:
        settings = {"psd": str(table_psd), "band": f"{lo!r}:{hi!r}", "duration": T, "dt": dt,
                    "seed": seed, "e": contact_setting(e), "settle": settle, "kind": kind,
                    "chatter": base.chatter}  # fmt: skip
        if base.participation != 1.0:  # (absent at 1: files written before it still resume)
            settings["participation"] = base.participation
        store = MapStore(out, system=system, points=points, settings=settings, force=force,
                         outputs=ENSEMBLE_OUTPUTS, table=ensemble_table)  # fmt: skip
    try:
        done: dict[int, dict[str, Any]] = {}
        if store is not None:
            done = {int(r["run"]): r for r in store.rows()}
        if 0 not in done:
            if store is not None:
                store.write_chunk(first)
            done[0] = first[0]
        todo = [i for i in range(n) if i not in done]
        workers = workers or os.cpu_count() or 1
        size = max(1, min(64, len(todo) // (8 * workers) or 1))
        chunks = [todo[i : i + size] for i in range(0, len(todo), size)]
        payloads = [(base, points.names, c, points.values[c]) for c in chunks]
        results = _launch(payloads, executor, workers, client, scheduler,
                          workers == 1 or len(payloads) < 2, _ensemble_chunk)  # fmt: skip
        _gather(results, store, done, _progress(progress, n, len(done), "realisations"))
        table = ensemble_table([done[i] for i in range(n)])
        if store is not None:
            store.finish(table)
    finally:
        if store is not None:
            store.close()
    runs = [
        {"rms": {k: r[f"rms_{k}"] for k in KEYS},
         "baseline": {k: r[f"baseline_rms_{k}"] for k in KEYS}, "impacts": r["impacts"]}
        for r in table.to_dict("records")
    ]  # fmt: skip
    return combine(runs, seed=seed, settle=settle, duration=T), table
