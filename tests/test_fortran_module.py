"""The Fortran 2008 target (issue 38, item 3): the module ``symimpact export --target fortran``
writes is compiled with the system's gfortran at ``-std=f2008 -pedantic`` with warnings as errors
(less the two notes its README names: an argument a kernel ignores, and the exact comparisons of
its case distinctions), and its check program calls every kernel once on the array of its
recorded points (the functions are elemental) against 50-digit mpmath values (1e-12 of the error
scale), and every iteration.  The program must fail when one kernel is off by 1e-9 relative.
On a CI machine (``CI`` set) a missing gfortran fails the test; elsewhere it skips.
"""

from __future__ import annotations

import re
import subprocess
from pathlib import Path

from symimpact.export import export_kernels
from tests.helpers import require_tool

ROOT = Path(__file__).resolve().parent.parent
FLAGS = ["-std=f2008", "-pedantic", "-Wall", "-Wextra", "-Wno-unused-dummy-argument",
         "-Wno-compare-reals", "-Werror", "-O2"]  # fmt: skip


def _build(folder: Path) -> subprocess.CompletedProcess:
    """Compile the module and the check program in ``folder``; run the program."""
    fc = require_tool("gfortran")
    for args in (["-c", "symimpact.f90"], ["check_kernels.f90", "symimpact.o", "-o", "check"]):
        run = subprocess.run([fc, *FLAGS, *args], cwd=folder, capture_output=True, text=True,
                             timeout=600)  # fmt: skip
        assert run.returncode == 0 and run.stderr == "", run.stderr
    return subprocess.run([str(folder / "check")], capture_output=True, text=True, timeout=60)


def test_the_module_compiles_cleanly_and_every_recorded_point_passes(tmp_path):
    export_kernels("fortran", tmp_path)
    run = _build(tmp_path)
    assert run.returncode == 0, run.stdout + run.stderr
    source = (ROOT / "generated" / "fortran" / "symimpact.f90").read_text(encoding="utf-8")
    kernels = len(re.findall(r"^    pure elemental function (?!symimpact_log1p)", source, re.M))
    iterations = len(re.findall(r"^    pure elemental subroutine ", source, re.M))
    # the harmonic balance's residuals are tested by tests/test_aft_kernels.py
    bundles = len(re.findall(r"^    pure subroutine (?!\w+_aft_residual_)", source, re.M))
    parts = len(re.findall(r"^    !   \(\d+\) \w+$", source, re.M))
    assert kernels > 90 and iterations == 5 and bundles >= 7 and parts > 2 * bundles
    # an iteration: its value and its step count; a bundle: each part at its three points
    checks = 3 * kernels + 6 * iterations + 3 * parts
    assert run.stdout.strip() == (f"symimpact: {checks} checks of {kernels} kernels, {bundles} "
                                  f"bundles and {iterations} iterations, 0 failed")  # fmt: skip


def test_the_check_program_fails_on_a_kernel_off_by_1e_9(tmp_path):
    export_kernels("fortran", tmp_path)
    module = tmp_path / "symimpact.f90"
    text = module.read_text(encoding="utf-8")
    name = "closed_forms_hertz_contact_duration"
    end = text.index(f"    end function {name}\n")
    module.write_text(text[:end] + "        f_result = f_result*(1.0_dp + 1e-9_dp)\n" + text[end:],
                      encoding="utf-8")  # fmt: skip
    run = _build(tmp_path)
    assert run.returncode == 1
    failed = {line.split(",")[0] for line in run.stdout.splitlines() if ", point " in line}
    assert failed == {name}
    assert run.stdout.strip().endswith(", 3 failed")
