"""Map throughput: simulations per second of one parameter map run serially (the baseline), on
all local cores (process executor), and on a Dask LocalCluster with 1 and then 2 single-threaded
worker processes (the scaling ratio).  Every executor must give the same table; the benchmark
checks that and prints figures and ratios; it asserts nothing about time.
Run from the checkout: python -m benchmarks.map_throughput
"""

from __future__ import annotations

import os
import time

import pandas as pd

from symimpact.maps import parameter_map
from symimpact.system import ImpactSystem

BASE = ImpactSystem(M=1.0, K=100.0, C=1.0, m=0.25, gap=0.009, c1=5.0, k_hz=1000.0)
GRID = {"gap": "4 mm:50 mm:2 mm", "mass_ratio": "0.02:0.6:0.02", "c1": "1,5"}
KW = {"xdot0": 0.5, "t_end": 20.0, "progress": False}


def timed(**kw):
    t0 = time.perf_counter()
    table = parameter_map(BASE, GRID, **KW, **kw)
    return time.perf_counter() - t0, table


def main() -> None:
    from distributed import Client, LocalCluster

    parameter_map(BASE, {"gap": [0.009]}, executor="serial", **KW)  # compile / load the cache
    t_serial, ref = timed(executor="serial")
    n = len(ref)
    cores = os.cpu_count() or 1
    print(
        f"map: {n} simulations (gap x mass ratio x c1), t_end 20 s, {ref['n_impacts'].sum()} "
        f"impacts in all; {cores} cores"
    )
    print(f"serial (baseline):          {n / t_serial:8.1f} simulations/s")
    t_proc, table = timed(executor="processes")
    pd.testing.assert_frame_equal(table, ref, check_exact=True)
    print(
        f"processes ({cores} workers):      {n / t_proc:8.1f} simulations/s  "
        f"({t_serial / t_proc:.2f}x serial)"
    )
    rates = {}
    for workers in (1, 2):
        with (
            LocalCluster(
                n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None
            ) as cluster,
            Client(cluster) as client,
        ):
            parameter_map(BASE, {"gap": [0.009, 0.01]}, client=client, **KW)  # warm the workers
            t, table = timed(client=client)
        pd.testing.assert_frame_equal(table, ref, check_exact=True)
        rates[workers] = n / t
        print(f"dask, {workers} worker(s):           {n / t:8.1f} simulations/s")
    print(f"dask scaling 1 -> 2 workers: {rates[2] / rates[1]:.2f}x (target >= 1.7x on 2 cores)")
    print("tables identical (exact) for serial, processes and dask")


if __name__ == "__main__":
    main()
