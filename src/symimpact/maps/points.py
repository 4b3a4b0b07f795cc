"""The points of a map: which inputs are swept and their values, from a grid, a range text or a
CSV file of parameter sets, each value read as SI (units accepted).  The first stage of a map:
points → runs → executors → table → store → engine."""

from __future__ import annotations

import itertools
import math
import os
import sys
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import ParameterError
from ..model.names import SWEEPABLE
from ..model.units import SI_UNITS, si_float, split_quantity, units_alike


def parse_range(name: str, text: str) -> np.ndarray:
    """``"6 mm:35 mm:1 mm"`` (start:stop:step, stop included) or ``"7 mm,9 mm,15 mm"`` → SI."""
    if ":" in text:
        parts = text.split(":")
        if len(parts) != 3:
            raise ParameterError(name, f"range {text!r} must be start:stop:step")
        units_alike(name, text, parts)
        units = {split_quantity(name, p.strip())[1] for p in parts}
        if len(units) == 1 and "" not in units:
            # one unit for all three: the grid is made in the numbers typed and each value then
            # converted, so "4 Hz:6 Hz:0.5 Hz" gives 2π·4.5 to the last bit, not 2π·4 + 2π·0.5
            unit = units.pop()
            typed = parse_range(name, ":".join(str(split_quantity(name, p.strip())[0])
                                               for p in parts))  # fmt: skip
            return np.array([si_float(name, f"{float(v)!r} {unit}") for v in typed])
        start, stop, step = (si_float(name, p.strip()) for p in parts)
        if step <= 0:
            raise ParameterError(name, f"range step must be positive, got {step:g}")
        if stop < start:
            raise ParameterError(name, f"range stop {stop:g} is below its start {start:g}")
        with np.errstate(all="ignore"):
            steps = (stop - start) / step * (1 + 1e-12) + 1e-9
        if not steps < 1_000_000:  # also an overflow to inf
            raise ParameterError(name, f"range {text!r} has more than 1e6 values")
        n = int(np.floor(steps)) + 1
        # 12 significant digits: "6 mm:35 mm:1 mm" gives 0.009, not 0.009000000000000001
        return np.array([float(f"{start + step * k:.12g}") for k in range(n)])
    return np.array([si_float(name, p.strip()) for p in text.split(",") if p.strip()])


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
    ``"start:stop:step"`` / ``"v1,v2,..."`` (see :func:`parse_range`).
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
    (:func:`symimpact.model.units.split_quantity`).  A byte-order mark is ignored.  ``progress``: a
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
