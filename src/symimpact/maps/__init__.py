"""Parameter maps and sweeps, in the order a map flows (each module imports only the ones before
it):

- :mod:`.points` — what is swept: a grid, range texts or a CSV of parameter sets, read as SI;
- :mod:`.runs` — one run: the point's system simulated, its row and gap class;
- :mod:`.executors` — where chunks of runs execute: this process, local processes or Dask;
- :mod:`.table` — rows as a tidy table;
- :mod:`.store` — the resumable map file (chunks, manifest, lock);
- :mod:`.engine` — :func:`parameter_map`: points → executor → store → table;
- :mod:`.sweep` — sweeps over one input and the gap classification of Sect. 4 (Fig. 5);
- :mod:`.design` — the clearance design map of the forced response: the worst steady amplitude
  over a frequency band against the clearance and the mass ratio, on the same executors and store.
"""

from .engine import map_rows, parameter_map
from .executors import EXECUTORS, DaskLost
from .points import SWEEPABLE, MapPoints, as_points, grid_points, parse_range, read_sets
from .runs import OUTPUTS, gap_class, run_point
from .store import MapStore, MapStoreWarning, read_map
from .sweep import sweep
from .table import table_rows, tidy_table

__all__ = [
    "EXECUTORS",
    "OUTPUTS",
    "SWEEPABLE",
    "DaskLost",
    "MapPoints",
    "MapStore",
    "MapStoreWarning",
    "as_points",
    "best_clearances",
    "design_map",
    "design_row",
    "gap_class",
    "grid_points",
    "map_rows",
    "parameter_map",
    "parse_range",
    "read_map",
    "read_sets",
    "run_point",
    "sweep",
    "table_rows",
    "tidy_table",
]


def __getattr__(name: str):
    """The design map's functions, imported on first use: :mod:`.design` needs the forced
    response (SciPy's optimisers among it), which a parameter map or a simulation does not."""
    if name in ("best_clearances", "design_map", "design_row"):
        from . import design

        return getattr(design, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
