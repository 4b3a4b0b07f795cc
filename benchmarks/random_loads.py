"""Random vibration with the impact damper: realisations per second on the report's system
(M 1 kg, K 100 N/m, C 1 N s/m, m 0.25 kg, d 9 mm, rigid impacts with the linear contact's
e = 0.1594) under band-limited white noise on the base (0.1–10 Hz, 0.01 (m/s²)²/Hz, 100 s kept
after the 13.8 s the primary needs to forget its start, 200 samples a second), each realisation
run with the damper and without it.

First one realisation against a baseline measured in the same run: the primary alone on the same
record (Eq. F8's recurrence with no impact to look for; both exact, so the ratio is what the
certified impact search, the impacts, chatter and sticking cost).  An event-driven integrator
(DOP853 with impacts as terminal events) is no baseline here: at e = 0.16 the impact mass chatters
against a wall, and the integrator, stopping at every impact of a sequence that accumulates, did
not finish one record in ten minutes.  Then ensembles: serially, on
two local processes, and on Dask LocalClusters of 1 and 2 single-threaded workers (the scaling),
each checked to give the same rows; and the time 10 000 realisations would take.  Medians of
repeats with their spread; prints figures and ratios, asserts nothing.
Run from the checkout: python -m benchmarks.random_loads
"""

from __future__ import annotations

import pandas as pd

from symimpact.forced.loads.record_flight import primary_response
from symimpact.forced.loads.record_response import damper_response
from symimpact.forced.loads.records import random_record
from symimpact.maps.ensemble import random_ensemble
from symimpact.model.system import ImpactSystem

from .timing import timed

SYSTEM = ImpactSystem(M=1.0, K=100.0, C=1.0, m=0.25, gap=0.009, contact="linear", k1=122.7)
E = 0.1594
ARGS = (SYSTEM, 0.01, (0.1, 10.0), 100.0, 0.005)
KW = {"e": E, "seed": 2026, "kind": "base-acceleration"}
N = 400  # realisations an ensemble is timed on


def main() -> None:
    from distributed import Client, LocalCluster

    record = random_record(0.01, (0.1, 10.0), 113.8, 0.005, 7, "base-acceleration")
    exact = damper_response(SYSTEM, record, e=E)
    ours = timed(lambda: damper_response(SYSTEM, record, e=E))
    print(f"one record of {record.duration:g} s ({len(record.values)} samples, "
          f"{len(exact.impact_times)} impacts):")  # fmt: skip
    print(f"  exact flight (Eq. F8) and impacts: {ours.ms()}")
    alone = timed(lambda: primary_response(SYSTEM, record))
    print(f"  the primary alone (baseline): {alone.ms()}; with the damper "
          f"{ours.median / alone.median:.1f}x its time")  # fmt: skip
    reference = random_ensemble(*ARGS, realisations=N, executor="serial", **KW)[1]
    print(f"\nensembles of {N} realisations (100 s kept each, with and without the damper):")
    rates = {}
    for name, kw in (("serial", {"executor": "serial"}),
                     ("2 processes", {"executor": "processes", "workers": 2})):  # fmt: skip
        t = timed(lambda kw=kw: random_ensemble(*ARGS, realisations=N, **kw, **KW)[1], repeat=3)
        pd.testing.assert_frame_equal(t.out, reference, check_exact=True)
        rates[name] = N / t.median
        print(f"  {name:13} {t.rate(N, 'realisations/s')}")
    for workers in (1, 2):
        with (
            LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                         dashboard_address=None) as cluster,
            Client(cluster) as client,
        ):  # fmt: skip
            random_ensemble(*ARGS, realisations=4, client=client, **KW)  # workers compile/load
            t = timed(lambda c=client: random_ensemble(*ARGS, realisations=N, client=c, **KW)[1],
                      repeat=3)  # fmt: skip
        pd.testing.assert_frame_equal(t.out, reference, check_exact=True)
        rates[f"dask {workers}"] = N / t.median
        print(
            f"  Dask, {workers} worker{'s' if workers > 1 else ' '} {t.rate(N, 'realisations/s')}"
        )
    print(f"  Dask scaling 1 -> 2 workers: {rates['dask 2'] / rates['dask 1']:.2f}x (target 1.8x)")
    best = max(rates.values())
    print(f"  10 000 realisations at the best rate ({best:.0f}/s): {10_000 / best / 60:.1f} min "
          "(target 10 min on 2 cores)")  # fmt: skip


if __name__ == "__main__":
    main()
