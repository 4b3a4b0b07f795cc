"""The on-disk table of pint's unit factors (symimpact.model.units._FactorFile): a warm command reads
its units without importing pint, and a damaged, stale or unwritable table only costs time —
the numbers are pint's either way."""

from __future__ import annotations

import json
import os
import subprocess
import sys

import pytest

PROBE = (
    "import sys; from symimpact.model.units import si; "
    "print(repr(si('gap', '9 mm')), repr(si('a', '0.1553 N/cm^3')), 'pint' in sys.modules)"
)


def _run(cache_home) -> list[str]:
    env = dict(os.environ, XDG_CACHE_HOME=str(cache_home))
    out = subprocess.run(
        [sys.executable, "-c", PROBE], env=env, capture_output=True, text=True, check=True
    )
    return out.stdout.split()


def test_second_run_reads_factors_without_pint(tmp_path):
    first = _run(tmp_path)
    assert first == ["0.009", "155300.0", "True"]  # the first run asks pint
    stored = json.loads((tmp_path / "symimpact" / "unit-factors.json").read_text())
    assert stored["factors"]["mm\x00m"] == ["ok", "0.001"]
    assert _run(tmp_path) == ["0.009", "155300.0", "False"]  # same numbers, pint not imported


@pytest.mark.parametrize(
    "content",
    [
        "{not json",
        json.dumps({"pint": "another pint", "factors": {"mm\x00m": ["ok", "7"]}}),
        json.dumps({"pint": None, "factors": []}),
    ],
)
def test_damaged_or_stale_table_falls_back_to_pint(tmp_path, content):
    folder = tmp_path / "symimpact"
    folder.mkdir()
    (folder / "unit-factors.json").write_text(content)
    assert _run(tmp_path) == ["0.009", "155300.0", "True"]  # a stale "7" is never used
    assert _run(tmp_path)[:2] == ["0.009", "155300.0"]


def test_unwritable_cache_folder_still_reads_units(tmp_path):
    blocker = tmp_path / "file"
    blocker.write_text("")  # a file where the cache folder's parent should be
    assert _run(blocker) == ["0.009", "155300.0", "True"]


def test_refusals_are_kept_as_refusals(tmp_path):
    probe = (
        "from symimpact.model.units import si\n"
        "for v in ('3 kg', '3 blorbs'):\n"
        "    try: si('gap', v)\n"
        "    except Exception as e: print(e)\n"
    )
    env = dict(os.environ, XDG_CACHE_HOME=str(tmp_path))
    runs = [
        subprocess.run([sys.executable, "-c", probe], env=env, capture_output=True, text=True)
        for _ in range(2)
    ]
    assert runs[0].stdout == runs[1].stdout  # the cached refusal reads exactly as pint's
    assert "expected units of m" in runs[0].stdout and "blorbs" in runs[0].stdout
