"""The Rust target (issue 38, item 3): the crate ``symimpact export --target rust`` writes is built
and tested offline with the system's cargo (``cargo test --offline``, no dependency): every
kernel and iteration at the recorded points of ``derive/checkpoints.py`` against 50-digit mpmath
values (1e-12 of the error scale), and the crate documentation's example.  The build must be
free of warnings, and the test must fail when one kernel is off by 1e-9 relative.  On a CI
machine (``CI`` set) a missing cargo fails the test; elsewhere it skips.
"""

from __future__ import annotations

import os
import re
import subprocess
from pathlib import Path

import pytest

from symimpact.export import export_kernels
from tests.helpers import require_tool

ROOT = Path(__file__).resolve().parent.parent


def _cargo(crate: Path, target: Path, *args: str) -> subprocess.CompletedProcess:
    env = {**os.environ, "CARGO_TARGET_DIR": str(target), "CARGO_TERM_COLOR": "never"}
    return subprocess.run([require_tool("cargo"), *args, "--offline"], cwd=crate, env=env,
                          capture_output=True, text=True, timeout=900)  # fmt: skip


@pytest.fixture(scope="module")
def crate(tmp_path_factory):
    """(crate folder, shared target folder): the exported crate."""
    base = tmp_path_factory.mktemp("rust")
    export_kernels("rust", base / "crate")
    return base / "crate", base / "target"


def _counts() -> tuple[int, int, int]:
    """(kernels, iterations, the bundles' parts) the crate defines (the harmonic balance's
    residuals, which return vectors, are tested by tests/test_aft_kernels.py)."""
    text = (ROOT / "generated" / "rust" / "src" / "lib.rs").read_text(encoding="utf-8")
    fixed = text[text.index("pub mod fixed_points") :]
    parts = [int(n) for n in re.findall(r"^    pub fn \w+\([^)]*\) -> \[f64; (\d+)\]", text, re.M)]
    balances = len(re.findall(r"^    pub fn aft_residual_\w+\(", text, re.M))
    kernels = text.count("    pub fn ") - fixed.count("    pub fn ") - len(parts) - balances
    return kernels, fixed.count("    pub fn "), sum(parts)


def test_the_crate_builds_without_a_warning_and_every_recorded_point_passes(crate):
    folder, target = crate
    build = _cargo(folder, target, "build", "--all-targets")
    assert build.returncode == 0, build.stderr
    assert "warning" not in build.stderr, build.stderr
    run = _cargo(folder, target, "test")
    assert run.returncode == 0, run.stdout + run.stderr
    kernels, iterations, parts = _counts()
    assert kernels > 90 and iterations == 5 and parts > 16
    results = re.findall(r"test result: ok\. (\d+) passed; 0 failed", run.stdout)
    # the unit tests (none), the integration test (a test per kernel, iteration and part of a
    # bundle), the doctest
    assert [int(n) for n in results] == [0, kernels + iterations + parts, 1], run.stdout


def test_the_crate_test_fails_on_a_kernel_off_by_1e_9(crate, tmp_path):
    _, target = crate
    wrong = tmp_path / "crate"
    export_kernels("rust", wrong)
    lib = wrong / "src" / "lib.rs"
    text = lib.read_text(encoding="utf-8")
    start = text.index("pub fn hertz_contact_duration(")
    end = text.index("\n    }\n", start)
    last = text.rindex("\n", start, end) + 1  # the function's result: its last line
    body = text[last:end].strip()
    lib.write_text(text[:last] + f"        ({body}) * (1.0 + 1e-9)" + text[end:], encoding="utf-8")
    run = _cargo(wrong, target, "test", "--test", "check_kernels")
    assert run.returncode != 0
    failed = re.findall(r"^test (\w+) \.\.\. FAILED", run.stdout, flags=re.M)
    assert failed == ["closed_forms_hertz_contact_duration"], run.stdout
