"""Map throughput: simulations per second of one parameter map, the compiled chunk loop against
the per-point path it replaced (each point's ImpactSystem, then ``simulate``; kept in the package
as ``symimpact.maps.runs._run_chunk_per_point``), serially and on all local cores; then Dask
LocalClusters of 1 and 2 single-threaded workers (the scaling ratio).  Every path and executor
must give the same table (checked exactly).  Each figure is the median of 5 maps with the
spread; prints figures and ratios, asserts nothing.
Run from the checkout: python -m benchmarks.map_throughput
"""

from __future__ import annotations

import os

import pandas as pd

import symimpact.maps.executors as executors
import symimpact.maps.runs as runs
from symimpact.maps import parameter_map
from symimpact.model.system import ImpactSystem

from .timing import REPEATS, timed

BASE = ImpactSystem(M=1.0, K=100.0, C=1.0, m=0.25, gap=0.009, c1=5.0, k_hz=1000.0)
GRID = {"gap": "4 mm:50 mm:2 mm", "mass_ratio": "0.02:0.6:0.02", "c1": "1,5"}
DASK_GRID = {**GRID, "c1": "1,2,5,10,20"}
KW = {"xdot0": 0.5, "t_end": 20.0, "progress": False}
PATHS = {"per-point (baseline)": runs._run_chunk_per_point, "compiled": runs._run_chunk}


def _map(grid=GRID, **kw):
    return parameter_map(BASE, grid, **KW, **kw)


def main() -> dict:
    from distributed import Client, LocalCluster

    cores = os.cpu_count() or 1
    _map({"gap": [0.009]}, executor="serial")  # compile / load the cache
    reference = _map(executor="serial")
    n = len(reference)
    print(
        f"map: {n} simulations (gap x mass ratio x c1), t_end 20 s, "
        f"{reference['n_impacts'].sum()} impacts in all; {cores} cores; median of {REPEATS} maps "
        "(slowest-fastest)"
    )
    rates: dict[str, float] = {}
    try:
        for executor in ("serial", "processes"):
            for path, task in PATHS.items():
                executors._run_chunk = task  # every executor runs the chunks through this name
                t = timed(lambda e=executor: _map(executor=e))
                pd.testing.assert_frame_equal(t.out, reference, check_exact=True)
                rates[f"{executor}, {path}"] = n / t.median
                print(f"  {executor:9} {path:21} {t.rate(n, 'sim/s')}")
    finally:
        executors._run_chunk = runs._run_chunk
    for executor in ("serial", "processes"):
        ratio = rates[f"{executor}, compiled"] / rates[f"{executor}, per-point (baseline)"]
        print(f"  {executor}: compiled / per-point = {ratio:.2f}x")
    best = rates["processes, compiled"] / rates["serial, per-point (baseline)"]
    print(f"  compiled on {cores} cores / per-point serial = {best:.2f}x")

    dask_ref = _map(DASK_GRID, executor="processes")
    m = len(dask_ref)
    print(f"\ndask: {m} simulations (c1 x 5 values), compiled chunks")
    dask_rates = {}
    for workers in (1, 2):
        with (
            LocalCluster(
                n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None
            ) as cluster,
            Client(cluster) as client,
        ):
            _map({"gap": [0.009, 0.01]}, client=client)  # warm the workers
            t = timed(lambda c=client: _map(DASK_GRID, client=c))
        pd.testing.assert_frame_equal(t.out, dask_ref, check_exact=True)
        dask_rates[workers] = m / t.median
        print(f"  {workers} worker(s): {t.rate(m, 'sim/s')}")
    print(
        f"  dask scaling 1 -> 2 workers: {dask_rates[2] / dask_rates[1]:.2f}x "
        "(target >= 1.8x on 2 cores)"
    )
    print("tables identical (exact) for both paths and every executor")
    return {"rates": rates, "dask": dask_rates}


if __name__ == "__main__":
    main()
