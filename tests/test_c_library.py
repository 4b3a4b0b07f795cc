"""The C target as a library (issue 38, item 2), built the way a C user builds it.

The C target as ``symimpact export --target c`` writes it (``generated/c/``, its
``CMakeLists.txt`` included) is configured and built with the system's CMake and C compiler
(warnings as errors), its own check program is run under ctest (every kernel and iteration at
the recorded points of ``derive/checkpoints.py``, against 50-digit mpmath values), the tree is
installed to a prefix, and two programs outside it link the installed library: one through
pkg-config (shared library, from a prefix moved after installing) and one through CMake's
``find_package(symimpact)`` (static library).  Both compare a kernel with NumPy's.  The check
program itself is shown to fail when one kernel is off by 1e-9 relative (its bound is 1e-12 of
the error scale).  On a CI machine (``CI`` set) a missing tool fails the test; elsewhere it skips.
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
from pathlib import Path

import pytest
from symimpact.generated import closed_forms

from symimpact.export import export_kernels
from tests.helpers import require_tool

ROOT = Path(__file__).resolve().parent.parent
C = ROOT / "generated" / "c"
#: The NumPy kernel and a C program agree to a few roundings (tests/test_targets.py uses 1e-13).
RTOL = 1e-13
CONSUMER = r"""
#include <stdio.h>
#include "symimpact.h"

int main(void)
{
    printf("%.17g\n", symimpact_closed_forms_hertz_contact_duration(0.25, 1.0, 1000.0, 0.075));
    return 0;
}
"""
EXPECTED = float(closed_forms.hertz_contact_duration(0.25, 1.0, 1000.0, 0.075))


def _run(*args, **kwargs) -> subprocess.CompletedProcess:
    run = subprocess.run([str(a) for a in args], capture_output=True, text=True, timeout=600,
                         **kwargs)  # fmt: skip
    assert run.returncode == 0, f"{' '.join(map(str, args))}\n{run.stdout}\n{run.stderr}"
    return run


@pytest.fixture(scope="module")
def built(tmp_path_factory):
    """(build folder, install prefix) of the library: configured, built, installed."""
    cmake = require_tool("cmake")
    require_tool(os.environ.get("CC", "cc"))
    base = tmp_path_factory.mktemp("clib")
    source, build, prefix = base / "source", base / "build", base / "prefix"
    export_kernels("c", source)  # what `symimpact export --target c` gives a C user
    _run(cmake, "-S", source, "-B", build, "-DCMAKE_BUILD_TYPE=Release", "-DCMAKE_C_FLAGS=-Werror")
    _run(cmake, "--build", build, "--parallel", "2")
    _run(cmake, "--install", build, "--prefix", prefix)
    return build, prefix


def _counts() -> tuple[int, int, int, int]:
    """(kernels, iterations, bundles, the bundles' parts) the header declares."""
    header = (C / "symimpact.h").read_text(encoding="utf-8")
    singles = re.findall(r"^double (symimpact_\w+)\(", header, flags=re.M)
    iterations = [b for b in singles if b.startswith("symimpact_fixed_points_")]
    bundles = re.findall(r"^void (symimpact_\w+)\(double", header, flags=re.M)
    parts = re.findall(r"^ \*   \[\d+\] symimpact_\w+$", header, flags=re.M)
    return len(singles) - len(iterations), len(iterations), len(bundles), len(parts)


def test_ctest_runs_the_check_program_on_both_libraries_and_every_kernel_passes(built):
    build, _ = built
    run = _run(require_tool("ctest"), "--test-dir", build, "--output-on-failure")
    assert "100% tests passed, 0 tests failed out of 2" in run.stdout
    kernels, iterations, bundles, parts = _counts()
    assert bundles >= 7 and parts > 2 * bundles
    out = _run(build / "check_kernels_static").stdout
    # three points a kernel, and a bundle's part, each through the function and its _batch
    # twin; an iteration's value and step count twice over
    checks = 3 * (2 * kernels + 4 * iterations + 2 * parts)
    assert out.strip() == (f"symimpact: {checks} checks of {kernels} kernels, {bundles} bundles "
                           f"and {iterations} iterations, 0 failed")  # fmt: skip


def test_install_tree_holds_both_libraries_the_header_and_both_package_files(built):
    _, prefix = built
    lib = next(p for p in (prefix / "lib", prefix / "lib64") if p.exists())
    names = {p.name for p in lib.iterdir()}
    assert {"libsymimpact.a", "libsymimpact.so", "libsymimpact.so.0"} <= names
    assert (prefix / "include" / "symimpact.h").read_bytes() == (C / "symimpact.h").read_bytes()
    assert (lib / "pkgconfig" / "symimpact.pc").exists()
    assert {"symimpactConfig.cmake", "symimpactConfigVersion.cmake", "symimpactTargets.cmake"} <= {
        p.name for p in (lib / "cmake" / "symimpact").iterdir()
    }


def _no_library_path() -> dict[str, str]:
    """The environment without LD_LIBRARY_PATH: a program linked through pkg-config finds the
    shared library by the run path its Libs set (issue 80, item 7: it had needed the variable)."""
    return {k: v for k, v in os.environ.items() if k != "LD_LIBRARY_PATH"}


def test_a_program_links_the_shared_library_through_pkg_config_from_a_moved_prefix(built, tmp_path):
    _, prefix = built
    moved = tmp_path / "elsewhere"
    shutil.copytree(prefix, moved, symlinks=True)  # the installed tree, moved
    lib = next(p for p in (moved / "lib", moved / "lib64") if p.exists())
    env = {**os.environ, "PKG_CONFIG_PATH": str(lib / "pkgconfig")}
    flags = _run(require_tool("pkg-config"), "--cflags", "--libs", "symimpact", env=env).stdout
    assert str(prefix) not in flags  # found from where the .pc file lies
    src = tmp_path / "consumer.c"
    src.write_text(CONSUMER, encoding="utf-8")
    exe = tmp_path / "consumer"
    cc = os.environ.get("CC", "cc")
    _run(cc, "-std=c99", "-Wall", "-Wextra", "-pedantic", "-Werror", src, *flags.split(),
         "-o", exe)  # fmt: skip
    out = _run(exe, env=_no_library_path()).stdout  # the run path pkg-config set finds it
    assert float(out) == pytest.approx(EXPECTED, rel=RTOL)


def test_a_cmake_project_finds_the_installed_package_and_links_the_static_library(built, tmp_path):
    _, prefix = built
    project = tmp_path / "consumer"
    project.mkdir()
    (project / "consumer.c").write_text(CONSUMER, encoding="utf-8")
    (project / "CMakeLists.txt").write_text(
        "cmake_minimum_required(VERSION 3.16)\nproject(consumer LANGUAGES C)\n"
        "find_package(symimpact 0.1 REQUIRED)\nadd_executable(consumer consumer.c)\n"
        "target_link_libraries(consumer PRIVATE symimpact::static)\n",
        encoding="utf-8",
    )
    cmake = require_tool("cmake")
    build = tmp_path / "build"
    _run(cmake, "-S", project, "-B", build, f"-DCMAKE_PREFIX_PATH={prefix}")
    _run(cmake, "--build", build)
    exe = build / "consumer"
    assert "libsymimpact.so" not in _run(require_tool("ldd"), exe).stdout  # linked statically
    assert float(_run(exe).stdout) == pytest.approx(EXPECTED, rel=RTOL)


def test_the_check_program_fails_on_a_kernel_off_by_1e_9(tmp_path):
    cc = require_tool(os.environ.get("CC", "cc"))
    source = (C / "symimpact.c").read_text(encoding="utf-8")
    name = "symimpact_closed_forms_hertz_contact_duration"
    start = source.index(f"double {name}(")
    ret = source.index("    return ", start)
    end = source.index(";\n", ret)
    body = source[ret + len("    return ") : end]
    wrong = source[:ret] + f"    return ({body})*(1.0 + 1e-9)" + source[end:]
    (tmp_path / "symimpact.c").write_text(wrong, encoding="utf-8")
    for f in ("symimpact.h", "check_kernels.c"):
        shutil.copy(C / f, tmp_path / f)
    exe = tmp_path / "check"
    _run(cc, "-std=c99", "-O2", tmp_path / "check_kernels.c", tmp_path / "symimpact.c", "-o", exe,
         "-lm")  # fmt: skip
    run = subprocess.run([str(exe)], capture_output=True, text=True, timeout=60)
    assert run.returncode == 1
    failed = {line.split(",")[0] for line in run.stderr.splitlines()}
    assert failed == {name, f"{name}_batch"}  # that kernel, and only it, at every point
    assert run.stdout.strip().endswith(", 6 failed")


def test_the_readme_call_example_compiles_against_the_installed_library_and_runs(built, tmp_path):
    """The ```c block of generated/c/README.md, its statements put in a main, linked through
    pkg-config: it compiles warning-free and the batch call gives the single calls' values."""
    _, prefix = built
    text = (C / "README.md").read_text(encoding="utf-8")
    (block,) = re.findall(r"```c\n(.*?)```", text, flags=re.S)
    includes = [line for line in block.splitlines() if line.startswith("#include")]
    body = [line for line in block.splitlines() if not line.startswith("#include")]
    check = ('printf("%.17g %.17g %.17g %ld\\n", T, durations[1], T31, steps);\n'
             "return !(durations[1] == T);")  # fmt: skip
    src = tmp_path / "readme.c"
    src.write_text("\n".join(["#include <stdio.h>", *includes, "int main(void)", "{", *body,
                              check, "}", ""]), encoding="utf-8")  # fmt: skip
    lib = next(p for p in (prefix / "lib", prefix / "lib64") if p.exists())
    env = {**os.environ, "PKG_CONFIG_PATH": str(lib / "pkgconfig")}
    flags = _run(require_tool("pkg-config"), "--cflags", "--libs", "symimpact", env=env).stdout
    exe = tmp_path / "readme"
    _run(os.environ.get("CC", "cc"), "-std=c99", "-Wall", "-Wextra", "-pedantic", "-Werror", src,
         *flags.split(), "-o", exe)  # fmt: skip
    T, batch, T31, steps = _run(exe, env=_no_library_path()).stdout.split()
    assert float(T) == pytest.approx(EXPECTED, rel=RTOL) and float(batch) == float(T)
    assert 0 < int(steps) < 100 and 0 < float(T31) < 1
