"""Map stores that detect damage (issue 16, item 3).

A map is interrupted after it saved every chunk (its last step, writing the finished table, is
made to fail), the store is damaged in one way, and the same command is run again: the damage is
reported in one line (a MapStoreWarning naming the chunk) and the resumed table equals, bit for
bit, a map computed in one pass.  Before this, each case gave a traceback or a silently different
table.
"""

from __future__ import annotations

import json
import shutil
import warnings

import pandas as pd
import pytest

from symimpact.errors import ParameterError
from symimpact.maps import MapStore, MapStoreWarning, as_points, parameter_map
from symimpact.maps import store as mapfiles
from symimpact.model.system import ImpactSystem

BASE = ImpactSystem(M=1.0, K=100.0, C=1.0, m=0.25, gap=0.009, c1=5.0, k_hz=1000.0)
GRID = {"gap": "6 mm:18 mm:4 mm", "mass_ratio": [0.1, 0.25]}  # 8 runs, 4 chunks of 2
KW = {"xdot0": 0.5, "t_end": 6.0, "progress": False, "executor": "serial", "chunk_size": 2}


@pytest.fixture(scope="module")
def reference():
    return parameter_map(BASE, GRID, **KW)


def _interrupted_store(tmp_path, suffix=".csv"):
    out = tmp_path / f"map{suffix}"

    def fail(self, table):
        raise KeyboardInterrupt

    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(MapStore, "finish", fail)
        with pytest.raises(KeyboardInterrupt):
            parameter_map(BASE, GRID, out=out, **KW)
    partial = tmp_path / f".map{suffix}.partial"
    chunks = sorted(partial.glob("chunk-*"))
    assert len(chunks) == 4
    return out, partial, chunks


def _resume(out, **extra):
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        table = parameter_map(BASE, GRID, out=out, **KW, **extra)
    notes = [str(w.message) for w in caught if issubclass(w.category, MapStoreWarning)]
    return table, notes


def _truncate(p):
    data = p.read_bytes()
    p.write_bytes(data[: len(data) // 2 + 3])  # mid-row, most likely mid-number


def _random_bytes(p):
    p.write_bytes(bytes(range(256)) * 3)


def _text(p):
    p.write_text("hello, this is not a map chunk\n")


def _folder(p):
    p.unlink()
    p.mkdir()


def _lost_cells(p):
    lines = p.read_text().splitlines()
    lines[-1] = lines[-1][: len(lines[-1]) - 25]  # the last line loses its last cells
    p.write_text("\n".join(lines) + "\n")


def _edited_value(p):
    lines = p.read_text().splitlines()
    cells = lines[1].split(",")
    cells[1] = repr(float(cells[1]) * 1.000001)  # the gap of the first run, edited
    lines[1] = ",".join(cells)
    p.write_text("\n".join(lines) + "\n")


def _other_schema(p):
    df = pd.read_csv(p).rename(columns={"gap": "c1"})
    df.to_csv(p, index=False)


@pytest.mark.parametrize(
    "damage",
    [_truncate, _random_bytes, _text, _folder, _lost_cells, _edited_value, _other_schema],
    ids=lambda f: f.__name__[1:],
)
def test_a_damaged_chunk_is_reported_and_recomputed(tmp_path, reference, damage):
    out, _, chunks = _interrupted_store(tmp_path)
    damage(chunks[1])
    table, notes = _resume(out)
    pd.testing.assert_frame_equal(table, reference, check_exact=True)
    assert len(notes) == 1 and chunks[1].name in notes[0] and "\n" not in notes[0]


def test_a_damaged_parquet_chunk_is_reported_and_recomputed(tmp_path, reference):
    out, _, chunks = _interrupted_store(tmp_path, ".parquet")
    _truncate(chunks[2])
    table, notes = _resume(out)
    pd.testing.assert_frame_equal(table, reference, check_exact=True)
    assert len(notes) == 1 and chunks[2].name in notes[0]


def test_missing_and_duplicated_chunks_are_recomputed(tmp_path, reference):
    out, partial, chunks = _interrupted_store(tmp_path)
    chunks[0].unlink()
    manifest = json.loads((partial / "manifest.json").read_text())
    twin = "chunk-000000099.csv"  # a copy of chunk 3 under another name, listed as well
    shutil.copy(chunks[3], partial / twin)
    manifest["chunks"][twin] = manifest["chunks"][chunks[3].name]
    (partial / "manifest.json").write_text(json.dumps(manifest))
    table, notes = _resume(out)
    pd.testing.assert_frame_equal(table, reference, check_exact=True)
    assert any("missing" in n for n in notes) and any("repeats runs" in n for n in notes)


def test_a_damaged_spec_is_restored_and_the_verified_chunks_kept(tmp_path, reference):
    out, partial, _ = _interrupted_store(tmp_path)
    (partial / "spec.json").write_text("{not json")
    computed = []
    real = mapfiles.MapStore.write_chunk

    def counting(self, rows):
        computed.extend(r["run"] for r in rows)
        return real(self, rows)

    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(mapfiles.MapStore, "write_chunk", counting)
        table, notes = _resume(out)
    pd.testing.assert_frame_equal(table, reference, check_exact=True)
    assert computed == []  # every chunk verified: nothing computed again
    assert len(notes) == 1 and "restored from the manifest" in notes[0]


def test_a_partial_path_that_is_a_file_is_refused_or_replaced_with_force(tmp_path, reference):
    out = tmp_path / "map.csv"
    (tmp_path / ".map.csv.partial").write_text("x")
    with pytest.raises(ParameterError, match="not a folder"):
        parameter_map(BASE, GRID, out=out, **KW)
    table = parameter_map(BASE, GRID, out=out, force=True, **KW)
    pd.testing.assert_frame_equal(table, reference, check_exact=True)


def test_a_second_map_on_the_same_out_is_refused_while_the_first_runs(tmp_path):
    out = tmp_path / "map.csv"
    points = as_points(GRID, None)
    first = MapStore(out, system=BASE, points=points, settings={})
    try:
        with pytest.raises(ParameterError, match="another map is writing"):
            MapStore(out, system=BASE, points=points, settings={})
    finally:
        first.close()
    MapStore(out, system=BASE, points=points, settings={}).close()  # free again


def test_maps_package_imports_flow_one_way():
    """symimpact.maps: each module imports only the modules before it in the map's flow
    (points → runs → executors → table → store → engine → sweep → design → structure_curve →
    structure_design → ensemble), at the top or inside
    functions — no circle (maps, mapfiles and sweep used to import each other)."""
    import ast
    from pathlib import Path

    import symimpact.maps as pkg

    order = [
        "points",
        "runs",
        "executors",
        "table",
        "store",
        "engine",
        "sweep",
        "design",
        "structure_curve",
        "structure_design",
        "ensemble",
    ]
    folder = Path(pkg.__file__).parent
    assert sorted(p.stem for p in folder.glob("*.py") if p.stem != "__init__") == sorted(order)
    for k, name in enumerate(order):
        tree = ast.parse((folder / f"{name}.py").read_text(encoding="utf-8"))
        for node in ast.walk(tree):
            if isinstance(node, ast.ImportFrom) and node.level == 1:
                target = (node.module or "").split(".")[0]
                assert target in order[:k], f"{name} imports .{target}"
            if isinstance(node, ast.ImportFrom) and node.level >= 2 and node.module:
                assert not node.module.startswith(("maps", "cli", "report")), (name, node.module)
