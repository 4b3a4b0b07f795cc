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

from ..errors import ParameterError
from ..io import _temporary_beside
from .runs import OUTPUTS
from .table import table_rows, tidy_table

FORMATS = {".csv": "csv", ".parquet": "parquet", ".pq": "parquet"}


def _format(path: Path) -> str:
    fmt = FORMATS.get(path.suffix.lower())
    if fmt is None:
        raise ParameterError("out", f"{str(path)!r} must end in .csv or .parquet")
    return fmt


def fingerprint(system: Any, points: Any, settings: dict[str, Any]) -> dict[str, Any]:
    """What identifies a map: version, system, settings, swept names and a hash of the points."""
    from .. import __version__

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


class MapStoreWarning(UserWarning):
    """A map store was found damaged on resume; what was damaged is recomputed."""


def _sha256(path: Path) -> str:
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


class MapStore:
    """The output file of one map and its folder of finished chunks (see the module text).

    The folder holds ``spec.json`` (the map's fingerprint), one file per finished chunk and
    ``manifest.json``: for every chunk, its run indices (as spans of consecutive runs) and the SHA-256 of its bytes, written
    (atomically, synced to disk) after the chunk itself.  On resume every chunk is verified
    against the manifest; one that is missing, truncated, unreadable, of another schema,
    duplicated or altered is reported (a :class:`MapStoreWarning`, one line) and its runs are
    computed again, so a resumed table never silently differs.  A damaged ``spec.json`` is
    restored from the manifest's copy when that still matches the inputs.  A lock file beside the
    output keeps a second map from writing the same ``out`` at the same time.  ``outputs`` and
    ``table`` are the row's output columns and the function that makes rows a table (a
    parameter map's by default; the design map of :mod:`.design` passes its own).
    """

    def __init__(
        self,
        out: str | os.PathLike,
        *,
        system: Any,
        points: Any,
        settings: dict[str, Any],
        force: bool = False,
        outputs: tuple[str, ...] = OUTPUTS,
        table: Any = tidy_table,
    ) -> None:
        from ..io import output_target

        self.outputs, self.table = outputs, table
        self.format = _format(Path(out))
        # the resolved path: a link and its target share one lock and one partial file
        self.out = output_target(out, "out")
        folder = self.out.parent
        self.partial = folder / f".{self.out.name}.partial"
        self.spec = fingerprint(system, points, settings)
        self._lock(folder)
        try:
            self._open(force)
        except BaseException:
            self.close()
            raise

    def _lock(self, folder: Path) -> None:
        import fcntl

        self._lock_path = folder / f".{self.out.name}.lock"
        try:
            self._lock_file: Any = open(self._lock_path, "a+")  # held until close()
        except OSError as exc:
            raise ParameterError(
                "out", f"cannot write in {str(folder)!r}: {exc.strerror}"
            ) from None
        try:
            fcntl.flock(self._lock_file, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError:
            self._lock_file.close()
            self._lock_file = None
            raise ParameterError(
                "out",
                f"another map is writing {str(self.out)!r} now (lock {str(self._lock_path)!r}); "
                "wait for it to finish or choose another --out",
            ) from None

    def close(self) -> None:
        """Release the lock (the store can no longer be written)."""
        if getattr(self, "_lock_file", None) is not None:
            self._lock_file.close()
            self._lock_file = None

    def _warn(self, message: str) -> None:
        import warnings

        warnings.warn(f"{str(self.out)!r}: {message}", MapStoreWarning, stacklevel=3)

    def _open(self, force: bool) -> None:
        if self.out.exists() and not force:
            raise ParameterError(
                "out",
                f"{str(self.out)!r} exists (a finished map); use force (--force) to replace it",
            )
        if self.partial.exists() and not self.partial.is_dir():
            if not force:
                raise ParameterError(
                    "out",
                    f"{str(self.partial)!r} is not a folder; use force (--force) to remove it",
                )
            self.partial.unlink()
        spec_file = self.partial / "spec.json"
        if self.partial.exists():
            old = _read_json(spec_file)
            manifest = _read_json(self.partial / "manifest.json")
            vouched = isinstance(manifest, dict) and manifest.get("spec") == self.spec
            if old is None and vouched:
                self._warn(
                    "spec.json of the unfinished map was damaged; restored from the manifest"
                )
                self._write_text(spec_file, json.dumps(self.spec, indent=1, sort_keys=True))
            elif old is None:
                self._warn(
                    "spec.json of the unfinished map is damaged and no manifest vouches for its "
                    "chunks; every run is computed again"
                )
                shutil.rmtree(self.partial)
            elif old != self.spec:
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
        manifest = _read_json(self.partial / "manifest.json")
        if not (isinstance(manifest, dict) and isinstance(manifest.get("chunks"), dict)):
            if (self.partial / "manifest.json").exists():
                self._warn("manifest.json was damaged; the chunks it listed are computed again")
            manifest = {"spec": self.spec, "chunks": {}}
        self.manifest = manifest

    @property
    def suffix(self) -> str:
        return ".csv" if self.format == "csv" else ".parquet"

    def _write_text(self, path: Path, text: str) -> None:
        with _temporary_beside(path, "out", ".tmp", sync=True) as tmp:
            Path(tmp).write_text(text)

    def _save_manifest(self) -> None:
        self._write_text(
            self.partial / "manifest.json", json.dumps(self.manifest, indent=1, sort_keys=True)
        )

    def _verify(self, name: str, entry: Any, seen: set[int]) -> list[dict[str, Any]] | str:
        """The rows of chunk ``name`` if it verifies against its manifest entry, else why not."""

        path = self.partial / name
        if not isinstance(entry, dict) or not {"sha256", "runs"} <= set(entry):
            return "its manifest entry is damaged"
        if not path.is_file():
            return "it is missing"
        if _sha256(path) != entry["sha256"]:
            return "its bytes differ from the checksum recorded when it was written (truncated "
            "or altered)"
        try:
            rows = _read_rows(path, self.format)
        except Exception as exc:  # any parse failure of a damaged file
            return f"it cannot be read ({type(exc).__name__})"
        expected = {"run", *self.spec["names"], *self.outputs}
        if not rows or set(rows[0]) != expected:
            return "its columns are not this map's"
        runs = [r["run"] for r in rows]
        if _spans(runs) != entry["runs"]:
            return "its run indices are not the ones recorded"
        if seen.intersection(runs) or len(set(runs)) != len(runs):
            return "it repeats runs of another chunk"
        if not all(isinstance(i, int) and 0 <= i < self.spec["points"] for i in runs):
            return "its run indices are out of range"
        return rows

    def rows(self) -> list[dict[str, Any]]:
        """The rows of every finished chunk that verifies (as dicts; missing values as None).

        A chunk that does not verify, or a file in the folder the manifest does not list, is
        reported in one line and removed; its runs are then computed again."""
        rows: list[dict[str, Any]] = []
        seen: set[int] = set()
        chunks = self.manifest["chunks"]
        changed = False
        for name in sorted(chunks):
            got = self._verify(name, chunks[name], seen)
            if isinstance(got, str):
                n = _count(chunks[name].get("runs")) if isinstance(chunks[name], dict) else 0
                self._warn(f"chunk {name}: {got}; its {n} runs are computed again")
                _remove(self.partial / name)
                del chunks[name]
                changed = True
                continue
            seen.update(r["run"] for r in got)
            rows.extend(got)
        for path in sorted(self.partial.glob(".*.tmp")) + sorted(self.partial.glob(".chunk-*")):
            _remove(path)  # temporary files of a run that was ended while writing
        for path in sorted(self.partial.glob("chunk-*")):
            if path.name not in chunks:
                if not path.name.endswith(".tmp") and not path.name.startswith("."):
                    self._warn(
                        f"chunk {path.name}: not in the manifest (the map stopped while writing "
                        "it?); its runs are computed again"
                    )
                _remove(path)
        if changed:
            self._save_manifest()
        return rows

    def _write(self, df, path: Path) -> None:
        with _temporary_beside(path, "out", self.suffix, sync=True) as tmp:
            if self.format == "csv":
                df.to_csv(tmp, index=False, float_format="%.17g", na_rep="")
            else:
                df.to_parquet(tmp, index=False)

    def write_chunk(self, rows: list[dict[str, Any]]) -> None:
        """Save one finished chunk (atomically, synced), then record it in the manifest."""

        names = self.spec["names"]
        df = self.table(rows, names)
        first = int(df["run"].iloc[0])
        name = f"chunk-{first:09d}{self.suffix}"
        self._write(df, self.partial / name)
        self.manifest["chunks"][name] = {
            "runs": _spans(int(r) for r in df["run"]),
            "sha256": _sha256(self.partial / name),
        }
        self._save_manifest()

    def finish(self, table) -> Path:
        """Write the complete table to the output file and remove the chunk folder."""
        self._write(table, self.out)
        shutil.rmtree(self.partial, ignore_errors=True)
        self._lock_path.unlink(missing_ok=True)
        self.close()
        return self.out


def _spans(runs) -> list[list[int]]:
    """Run indices as [first, last + 1] spans of consecutive runs (a chunk is one span unless
    a resumed map skips runs already done): the manifest stays small for a 10⁶-run map."""
    spans: list[list[int]] = []
    for r in runs:
        if spans and r == spans[-1][1]:
            spans[-1][1] = r + 1
        else:
            spans.append([r, r + 1])
    return spans


def _count(spans: Any) -> int:
    """How many runs ``spans`` (as written by :func:`_spans`) hold; 0 if it is not such a list."""
    try:
        return sum(int(b) - int(a) for a, b in spans)
    except (TypeError, ValueError):
        return 0


def _read_json(path: Path) -> Any:
    try:
        return json.loads(path.read_text())
    except (OSError, ValueError):
        return None


def _remove(path: Path) -> None:
    if path.is_dir() and not path.is_symlink():
        shutil.rmtree(path, ignore_errors=True)
    else:
        path.unlink(missing_ok=True)


def read_map(path: str | os.PathLike):
    """A finished map file (``.csv`` or ``.parquet``) as the DataFrame :func:`parameter_map`
    returned (same dtypes, missing values as ``<NA>``)."""

    p = Path(path)
    fmt = _format(p)
    if not p.is_file():
        raise ParameterError("path", f"{str(p)!r} does not exist")
    rows = _read_rows(p, fmt)
    if not rows:
        raise ParameterError("path", f"{str(p)!r} holds no rows")
    names = [c for c in rows[0] if c not in ("run", *OUTPUTS)]
    return tidy_table(rows, names)


#: Columns read back as whole numbers and as text (a parameter map's, then the design map's of
#: :mod:`.design`); every other column is a float.
_INTEGERS = ("run", "n_impacts", "n_effective", "branches", "stable_frequencies",
             "linear_frequencies", "uncovered_frequencies")  # fmt: skip
_STRINGS = ("class", "peak_motion")


def _read_rows(path: Path, fmt: str) -> list[dict[str, Any]]:
    """Rows of a map file as dicts (CSV parsed with ``float``, which reads the 17 written digits
    back to the same double; empty cells and Parquet nulls are None)."""
    if fmt == "parquet":
        import pandas as pd

        return table_rows(pd.read_parquet(path))
    import csv

    def cell(name: str, text: str) -> Any:
        if text == "":
            return None
        if name in _STRINGS:
            return text
        return int(text) if name in _INTEGERS else float(text)

    with open(path, newline="") as f:
        return [{k: cell(k, v) for k, v in r.items()} for r in csv.DictReader(f)]
