"""A map of 10⁶ runs (gap 100 x mass ratio 100 x c1 100, t_end 2 s) on all local cores, streamed
to a resumable Parquet file; then the same map interrupted after its first chunks and resumed.
One map of minutes is not repeated five times: the figure is its wall time, with the median and
spread of its chunks' rates.  Prints figures; asserts nothing.
Run from the checkout: python -m benchmarks.million_map
"""

from __future__ import annotations

import json
import os
import statistics
import tempfile
import time
from pathlib import Path

import numpy as np

from symimpact.maps import parameter_map, read_map
from symimpact.model.system import ImpactSystem

BASE = ImpactSystem(M=1.0, K=100.0, C=1.0, m=0.25, gap=0.009, c1=5.0, k_hz=1000.0)
GRID = {
    "gap": "4 mm:53.5 mm:0.5 mm",
    "mass_ratio": "0.01:1:0.01",
    "c1": list(np.geomspace(0.1, 1000.0, 100)),
}
KW = {"xdot0": 0.5, "t_end": 2.0}


class _Interrupt(Exception):
    pass


def main() -> dict:
    cores = os.cpu_count() or 1
    parameter_map(BASE, {"gap": [0.009]}, executor="serial", progress=False, **KW)  # warm
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "million.parquet"
        stamps: list[tuple[float, int]] = []

        def progress(done: int, total: int) -> None:
            stamps.append((time.perf_counter(), done))

        t0 = time.perf_counter()
        table = parameter_map(BASE, GRID, out=out, progress=progress, **KW)
        wall = time.perf_counter() - t0
        n = len(table)
        times = [t0] + [t for t, _ in stamps]
        counts = [0] + [d for _, d in stamps]
        chunk_rates = [
            (counts[i + 1] - counts[i]) / (times[i + 1] - times[i])
            for i in range(len(stamps))
            if times[i + 1] > times[i]
        ]
        print(
            f"{n} runs, {int(table['n_impacts'].sum())} impacts, on {cores} cores: {wall:.1f} s "
            f"wall ({n / wall:.0f} runs/s; target <= 600 s); {len(stamps)} chunks, their rates "
            f"median {statistics.median(chunk_rates):.0f} runs/s "
            f"({min(chunk_rates):.0f}-{max(chunk_rates):.0f})"
        )
        assert read_map(out).equals(table)

        # interrupted after a tenth of its runs, then resumed: only the missing runs are run
        out.unlink()
        seen = {"done": 0}

        def stop_early(done: int, total: int) -> None:
            seen["done"] = done
            if done >= total // 10:
                raise _Interrupt

        try:
            parameter_map(BASE, GRID, out=out, progress=stop_early, **KW)
        except _Interrupt:
            pass
        manifest = json.loads((out.parent / f".{out.name}.partial" / "manifest.json").read_text())
        kept = sum(b - a for entry in manifest["chunks"].values() for a, b in entry["runs"])
        t0 = time.perf_counter()
        again = parameter_map(BASE, GRID, out=out, progress=False, **KW)
        print(
            f"interrupted after {seen['done']} runs ({kept} saved in finished chunks); resumed, "
            f"the map ran the other {n - kept} in {time.perf_counter() - t0:.1f} s; tables "
            f"identical: {again.equals(table)}"
        )
    return {"runs": n, "wall": wall}


if __name__ == "__main__":
    main()
