"""Resumable map files: rows streamed as chunks finish, the finished table written atomically.

For an output ``DIR/name.parquet`` (or ``.csv``) the chunks go to the hidden folder
``DIR/.name.parquet.partial/``: one file per finished chunk, each written to a temporary name and
renamed, so a chunk file is either complete or absent, and ``spec.json``, the fingerprint of the
map (package version, base system, initial state, contact path and every point).  A restart with
the same inputs reads the chunks back and computes only the missing runs; a restart with other
inputs is refused instead of mixing two maps.  When every run is done the whole table is written
to ``name.parquet`` (temporary file + rename) and the folder is removed: a file under the output's
name is always a complete map.

CSV floats are written with 17 significant digits and read back exactly, so a resumed map equals
one computed in a single pass.
"""

from __future__ import annotations

import hashlib
import json
import os
import shutil
from pathlib import Path
from typing import Any

import numpy as np

from .errors import ParameterError
from .io import _temporary_beside

FORMATS = {".csv": "csv", ".parquet": "parquet", ".pq": "parquet"}


def _format(path: Path) -> str:
    fmt = FORMATS.get(path.suffix.lower())
    if fmt is None:
        raise ParameterError("out", f"{str(path)!r} must end in .csv or .parquet")
    return fmt


def fingerprint(system: Any, points: Any, settings: dict[str, Any]) -> dict[str, Any]:
    """What identifies a map: version, system, settings, swept names and a hash of the points."""
    from . import __version__

    digest = hashlib.sha256(np.ascontiguousarray(points.values, dtype="<f8").tobytes())
    return {
        "symimpact": __version__,
        "system": system.as_dict(),
        "settings": {
            k: (v if isinstance(v, int | float | None) else str(v)) for k, v in settings.items()
        },
        "names": list(points.names),
        "points": len(points),
        "points_sha256": digest.hexdigest(),
    }


class MapStore:
    """The output file of one map and its folder of finished chunks (see the module text)."""

    def __init__(
        self,
        out: str | os.PathLike,
        *,
        system: Any,
        points: Any,
        settings: dict[str, Any],
        force: bool = False,
    ) -> None:
        self.out = Path(out)
        self.format = _format(self.out)
        folder = self.out.parent if str(self.out.parent) else Path(".")
        if not folder.is_dir():
            raise ParameterError("out", f"folder {str(folder)!r} does not exist")
        if not os.access(folder, os.W_OK):
            raise ParameterError("out", f"cannot write in {str(folder)!r}")
        if self.out.is_dir():
            raise ParameterError("out", f"{str(self.out)!r} is a folder")
        self.partial = folder / f".{self.out.name}.partial"
        self.spec = fingerprint(system, points, settings)
        if self.out.exists() and not force:
            raise ParameterError(
                "out",
                f"{str(self.out)!r} exists (a finished map); use force (--force) to replace it",
            )
        spec_file = self.partial / "spec.json"
        if self.partial.exists():
            try:
                old = json.loads(spec_file.read_text())
            except (OSError, ValueError):
                old = None
            if old != self.spec:
                if not force:
                    raise ParameterError(
                        "out",
                        f"{str(self.partial)!r} holds an unfinished map with other inputs; "
                        "use force (--force) to discard it",
                    )
                shutil.rmtree(self.partial)
        if not self.partial.exists():
            self.partial.mkdir()
            self._write_text(spec_file, json.dumps(self.spec, indent=1, sort_keys=True))

    @property
    def suffix(self) -> str:
        return ".csv" if self.format == "csv" else ".parquet"

    def _write_text(self, path: Path, text: str) -> None:
        with _temporary_beside(path, "out", ".tmp") as tmp:
            Path(tmp).write_text(text)

    def rows(self) -> list[dict[str, Any]]:
        """The rows of every finished chunk (as dicts; missing values as None)."""
        rows: list[dict[str, Any]] = []
        for f in sorted(self.partial.glob(f"chunk-*{self.suffix}")):
            rows.extend(_read_rows(f, self.format))
        return rows

    def _write(self, df, path: Path) -> None:
        with _temporary_beside(path, "out", self.suffix) as tmp:
            if self.format == "csv":
                df.to_csv(tmp, index=False, float_format="%.17g", na_rep="")
            else:
                df.to_parquet(tmp, index=False)

    def write_chunk(self, rows: list[dict[str, Any]]) -> None:
        """Save one finished chunk (atomically)."""
        from .maps import tidy_table

        names = self.spec["names"]
        df = tidy_table(rows, names)
        first = int(df["run"].iloc[0])
        self._write(df, self.partial / f"chunk-{first:09d}{self.suffix}")

    def finish(self, table) -> Path:
        """Write the complete table to the output file and remove the chunk folder."""
        self._write(table, self.out)
        shutil.rmtree(self.partial, ignore_errors=True)
        return self.out


def read_map(path: str | os.PathLike):
    """A finished map file (``.csv`` or ``.parquet``) as the DataFrame :func:`parameter_map`
    returned (same dtypes, missing values as ``<NA>``)."""
    from .maps import OUTPUTS, tidy_table

    p = Path(path)
    fmt = _format(p)
    if not p.is_file():
        raise ParameterError("path", f"{str(p)!r} does not exist")
    rows = _read_rows(p, fmt)
    if not rows:
        raise ParameterError("path", f"{str(p)!r} holds no rows")
    names = [c for c in rows[0] if c not in ("run", *OUTPUTS)]
    return tidy_table(rows, names)


_INTEGERS = ("run", "n_impacts", "n_effective")


def _read_rows(path: Path, fmt: str) -> list[dict[str, Any]]:
    """Rows of a map file as dicts (CSV parsed with ``float``, which reads the 17 written digits
    back to the same double; empty cells and Parquet nulls are None)."""
    if fmt == "parquet":
        import pandas as pd

        from .maps import table_rows

        return table_rows(pd.read_parquet(path))
    import csv

    def cell(name: str, text: str) -> Any:
        if text == "":
            return None
        if name == "class":
            return text
        return int(text) if name in _INTEGERS else float(text)

    with open(path, newline="") as f:
        return [{k: cell(k, v) for k, v in r.items()} for r in csv.DictReader(f)]
